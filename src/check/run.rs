//! Running a suite: load each scene file once, draw every shot, verify it.
//! Files load in parallel and shots run in parallel (rayon); results keep
//! the suite's order, and each picture is the same as a serial run's
//! because rendering never depends on threads.

use super::report::{Report, ShotResult};
use super::suite::Suite;
use super::{verify, Options, Status};
use crate::error::Result;
use crate::scene::Scene;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

/// Draws and verifies every shot of `suite`. Problems with one case (its
/// scene does not load, its viewpoint does not exist) are that case's
/// `Error` result, not an early stop, so one run shows everything.
pub fn run(suite: &Suite, options: &Options) -> Report {
    let start = Instant::now();
    let files: Vec<PathBuf> = suite
        .cases
        .iter()
        .map(|c| c.file.clone())
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    let scenes: BTreeMap<PathBuf, Result<Scene>> = files
        .into_par_iter()
        .map(|f| {
            let scene = crate::front::load(&f);
            (f, scene)
        })
        .collect();
    let results: Vec<ShotResult> = suite
        .shots()
        .into_par_iter()
        .map(|shot| {
            let t0 = Instant::now();
            let case = &suite.cases[shot.case];
            let mut result = ShotResult {
                name: shot.name.clone(),
                case: case.name.clone(),
                file: case.file.clone(),
                golden: shot.golden.clone(),
                time: shot.at,
                status: Status::Error,
                comparison: None,
                actual_png: None,
                diff_png: None,
                error: None,
                seconds: 0.0,
            };
            let outcome = match &scenes[&case.file] {
                Err(e) => Err(e.clone()),
                Ok(scene) => {
                    let time = if shot.frame {
                        shot.at / scene.settings.fps.max(1e-6)
                    } else {
                        shot.at
                    };
                    result.time = time;
                    let spec = case.spec.clone().at(time);
                    crate::front::render(scene, &spec).and_then(|img| {
                        verify(&img, &shot.golden, &shot.name, &case.tolerance, options)
                    })
                }
            };
            match outcome {
                Ok(v) => {
                    result.status = v.status;
                    result.comparison = v.comparison;
                    result.actual_png = v.actual_png;
                    result.diff_png = v.diff_png;
                }
                Err(e) => result.error = Some(e.to_string()),
            }
            result.seconds = t0.elapsed().as_secs_f64();
            result
        })
        .collect();
    Report {
        suite: suite.path.clone(),
        results,
        seconds: start.elapsed().as_secs_f64(),
    }
}
