//! TimeSensors that wait for an event do not play at load.
//!
//! A TimeSensor whose `startTime` is the destination of a ROUTE (from a
//! TouchSensor's `touchTime`, a Script, another sensor) is started by that
//! event (ISO/IEC 14772-1 §6.50: active from `startTime`, which the event
//! sets; unless it loops with `stopTime` ≤ `startTime`, which runs
//! forever): before it, at load, the fields the sensor drives keep their
//! values from the file. A viewer that cannot click shows that still pose,
//! as Coin does. Such a sensor's tracks become a clip of their own, named
//! after the sensor (`--animation NAME` or the viewer's clip key plays
//! it); the tracks of every other sensor stay in the clip that plays at
//! load, named `at load`.

use super::animation::resolve;
use super::build::Builder;
use crate::anim::Animation;
use crate::format::syntax::{AstNode, NodeRef, Route};
use crate::scene::Clip;
use std::collections::{HashMap, HashSet};
use std::rc::Rc;

/// Name of the clip that plays at load when some sensors wait for events.
pub const AT_LOAD: &str = "at load";

/// The TimeSensors whose `startTime` some ROUTE sets (through PROTO
/// interfaces too) and that do not already run at load.
pub fn event_started(routes: &[Route]) -> HashSet<*const AstNode> {
    let mut out = HashSet::new();
    for r in routes {
        let mut targets = Vec::new();
        resolve(&r.to, &r.to_field, &mut targets, 0);
        for (t, f) in targets {
            let t = t.effective();
            let field = f.strip_prefix("set_").unwrap_or(&f);
            if t.kind == "TimeSensor" && field == "startTime" && !runs_at_load(&t) {
                out.insert(Rc::as_ptr(&t));
            }
        }
    }
    out
}

/// A looping sensor whose `stopTime` is not after its `startTime` runs
/// forever from `startTime` (§6.50), so it runs at load whatever starts
/// it later; any other one waits for its start event.
fn runs_at_load(ts: &AstNode) -> bool {
    let start = ts.num("startTime").unwrap_or(0.0);
    let stop = ts.num("stopTime").unwrap_or(0.0);
    ts.bool("loop", false) && stop <= start
}

/// Moves the tracks the import added (from index `first` on; `owners`
/// names each one's TimeSensor) whose sensor is in `waiting` into one clip
/// per sensor, in file order; the rest play at load. `end` gives a sensor's
/// last frame (its clip's length). Nothing changes when no track waits, or
/// when the scene already has named clips (an Inline's).
pub fn split(
    b: &mut Builder,
    first: usize,
    owners: &[(usize, NodeRef)],
    waiting: &HashSet<*const AstNode>,
    end: impl Fn(&AstNode) -> f32,
) {
    let waits = |n: &NodeRef| waiting.contains(&Rc::as_ptr(n));
    if !owners.iter().any(|(_, s)| waits(s)) || !b.scene.clips.is_empty() {
        return;
    }
    let owner_of: HashMap<usize, &NodeRef> = owners.iter().map(|(i, s)| (*i, s)).collect();
    let tracks = std::mem::take(&mut b.scene.animation.tracks);
    let mut load = Animation::default();
    let mut load_end = if first > 0 {
        b.scene.settings.duration
    } else {
        0.0
    };
    // One clip per waiting sensor, in the order its first track came.
    let mut clips: Vec<(*const AstNode, Clip)> = Vec::new();
    for (i, track) in tracks.into_iter().enumerate() {
        let owner = owner_of.get(&i).copied();
        match owner.filter(|s| waits(s)) {
            Some(s) => {
                let key = Rc::as_ptr(s);
                let at = match clips.iter().position(|(k, _)| *k == key) {
                    Some(at) => at,
                    None => {
                        let name = clip_name(s, &clips);
                        clips.push((
                            key,
                            Clip {
                                name,
                                animation: Animation::default(),
                                duration: end(s),
                            },
                        ));
                        clips.len() - 1
                    }
                };
                clips[at].1.animation.tracks.push(track);
            }
            None => {
                if let Some(s) = owner {
                    load_end = load_end.max(end(s));
                }
                load.tracks.push(track);
            }
        }
    }
    let mut all = vec![Clip {
        name: AT_LOAD.to_string(),
        animation: load,
        duration: load_end,
    }];
    all.extend(clips.into_iter().map(|(_, c)| c));
    b.scene.set_clips(all, 0);
}

/// The sensor's DEF name (or where it is), made unique among `taken` (a
/// PROTO used twice holds two sensors of one DEF name).
fn clip_name(s: &AstNode, taken: &[(*const AstNode, Clip)]) -> String {
    let base = match &s.def {
        Some(d) if !d.is_empty() => d.clone(),
        _ => format!("TimeSensor {}:{}", s.pos.line, s.pos.column),
    };
    let used = |n: &str| n == AT_LOAD || taken.iter().any(|(_, c)| c.name == n);
    if !used(&base) {
        return base;
    }
    (2..)
        .map(|k| format!("{base} {k}"))
        .find(|n| !used(n))
        .unwrap_or(base)
}
