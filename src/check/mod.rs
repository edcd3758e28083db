//! Screenshot tests, as a library: [`verify`] one picture against its
//! golden file (the bookkeeping every golden test needs), or [`run`] a whole
//! [`Suite`] (what `animed check` does) and turn the [`Report`] into a
//! terminal table, JUnit XML or JSON.
//!
//! The rules, the same for `animed check`, `cargo test` goldens and users:
//! - a picture that matches within the tolerance passes; stale
//!   `NAME.actual.png` / `NAME.diff.png` from an earlier failure are removed;
//! - a picture that does not match fails and writes `NAME.actual.png` and
//!   `NAME.diff.png` into the output folder;
//! - a missing golden is `New` (a failure) and writes `NAME.actual.png`;
//!   it is never created silently;
//! - with `update`, failing and new goldens are overwritten with the actual
//!   picture (`Updated` / `Created`, not failures); passing goldens are left
//!   byte for byte as they are.

mod report;
mod run;
pub mod suite;

pub use report::{Report, ShotResult};
pub use run::run;
pub use suite::{Case, Shot, Suite, When};

use crate::compare::{compare, Comparison, Tolerance};
use crate::error::{Error, ErrorKind, Result};
use crate::picture::Image;
use std::path::{Path, PathBuf};

/// What happened to one picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Matches its golden within the tolerance.
    Passed,
    /// Differs from its golden beyond the tolerance.
    Failed,
    /// Has no golden yet (run with update to accept it).
    New,
    /// Differed; the golden was overwritten (update).
    Updated,
    /// Had no golden; it was written (update).
    Created,
    /// Could not be drawn or compared (bad scene, unreadable golden).
    Error,
}

impl Status {
    /// Whether this outcome fails a test run.
    pub fn is_failure(self) -> bool {
        matches!(self, Status::Failed | Status::New | Status::Error)
    }

    /// Lower-case word for tables and reports.
    pub fn word(self) -> &'static str {
        match self {
            Status::Passed => "pass",
            Status::Failed => "FAIL",
            Status::New => "NEW",
            Status::Updated => "updated",
            Status::Created => "created",
            Status::Error => "ERROR",
        }
    }
}

/// Where failed pictures go and whether to accept them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Folder for `NAME.actual.png` and `NAME.diff.png`.
    pub out_dir: PathBuf,
    /// Accept the actual pictures as the new goldens.
    pub update: bool,
}

impl Options {
    /// Writing into `out_dir`, updating when `ANIMED_UPDATE` is set (to
    /// anything but empty or `0`).
    pub fn new(out_dir: impl Into<PathBuf>) -> Options {
        Options {
            out_dir: out_dir.into(),
            update: update_requested(),
        }
    }
}

/// Whether the environment asks to accept new pictures (`ANIMED_UPDATE=1`).
pub fn update_requested() -> bool {
    std::env::var("ANIMED_UPDATE").is_ok_and(|v| !v.is_empty() && v != "0")
}

/// The outcome of [`verify`].
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Verdict {
    /// What happened.
    pub status: Status,
    /// The comparison, when there was a golden to compare with.
    pub comparison: Option<Comparison>,
    /// `NAME.actual.png` when one was written.
    pub actual_png: Option<PathBuf>,
    /// `NAME.diff.png` when one was written.
    pub diff_png: Option<PathBuf>,
}

/// Compares `actual` with the golden PNG at `golden` and does the file
/// work (see the module rules). `name` names the output files.
///
/// ```
/// use animed::check::{verify, Options, Status};
/// use animed::{Image, Tolerance};
/// let dir = std::env::temp_dir().join(format!("animed-verify-doc-{}", std::process::id()));
/// let golden = dir.join("goldens/box.png");
/// let mut opts = Options::new(dir.join("out"));
/// opts.update = false;
/// let picture = Image::new(16, 16, [40, 80, 120]);
///
/// // No golden yet: reported as new, the actual picture written for a look.
/// let v = verify(&picture, &golden, "box", &Tolerance::exact(), &opts)?;
/// assert_eq!(v.status, Status::New);
/// assert!(dir.join("out/box.actual.png").exists());
///
/// // Accept it, then it passes.
/// opts.update = true;
/// assert_eq!(verify(&picture, &golden, "box", &Tolerance::exact(), &opts)?.status, Status::Created);
/// opts.update = false;
/// assert_eq!(verify(&picture, &golden, "box", &Tolerance::exact(), &opts)?.status, Status::Passed);
/// # std::fs::remove_dir_all(&dir).ok();
/// # Ok::<(), animed::Error>(())
/// ```
pub fn verify(
    actual: &Image,
    golden: &Path,
    name: &str,
    tolerance: &Tolerance,
    options: &Options,
) -> Result<Verdict> {
    let actual_path = options.out_dir.join(format!("{name}.actual.png"));
    let diff_path = options.out_dir.join(format!("{name}.diff.png"));
    let expected = if golden.exists() {
        Some(Image::load_png(golden)?)
    } else {
        None
    };
    let comparison = expected.as_ref().map(|g| compare(actual, g, tolerance));
    let verdict = |status, comparison, actual_png, diff_png| Verdict {
        status,
        comparison,
        actual_png,
        diff_png,
    };
    match comparison {
        Some(c) if c.passed => {
            remove_stale(&[&actual_path, &diff_path])?;
            Ok(verdict(Status::Passed, Some(c), None, None))
        }
        c if options.update => {
            actual.save_png(golden)?;
            remove_stale(&[&actual_path, &diff_path])?;
            let status = if c.is_some() {
                Status::Updated
            } else {
                Status::Created
            };
            Ok(verdict(status, c, None, None))
        }
        Some(c) => {
            actual.save_png(&actual_path)?;
            c.diff.save_png(&diff_path)?;
            Ok(verdict(
                Status::Failed,
                Some(c),
                Some(actual_path),
                Some(diff_path),
            ))
        }
        None => {
            actual.save_png(&actual_path)?;
            remove_stale(&[&diff_path])?;
            Ok(verdict(Status::New, None, Some(actual_path), None))
        }
    }
}

fn remove_stale(paths: &[&Path]) -> Result<()> {
    for p in paths {
        match std::fs::remove_file(p) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => return Err(Error::in_file(ErrorKind::Io, p, e.to_string())),
        }
    }
    Ok(())
}
