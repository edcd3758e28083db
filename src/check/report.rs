//! What a suite run found, and the three ways to show it: a table for the
//! terminal, JUnit XML (the format CI systems such as GitLab, Jenkins and
//! GitHub test reporters read) and JSON for scripts.

use super::Status;
use crate::compare::Comparison;
use crate::error::{Error, ErrorKind, Result};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// One picture's outcome.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct ShotResult {
    /// `CASE`, `CASE@T` or `CASE@fN`.
    pub name: String,
    /// The case it belongs to.
    pub case: String,
    /// The scene file.
    pub file: PathBuf,
    /// The golden it was compared with (or written to).
    pub golden: PathBuf,
    /// Animation time in seconds.
    pub time: f32,
    /// What happened.
    pub status: Status,
    /// The comparison, when a golden was there.
    pub comparison: Option<Comparison>,
    /// `NAME.actual.png`, when written.
    pub actual_png: Option<PathBuf>,
    /// `NAME.diff.png`, when written.
    pub diff_png: Option<PathBuf>,
    /// Why it is an `Error`.
    pub error: Option<String>,
    /// Wall time of this shot.
    pub seconds: f64,
}

impl ShotResult {
    /// One line saying why it did not pass (empty for passes).
    pub fn reason(&self) -> String {
        match self.status {
            Status::Passed => String::new(),
            Status::Error => self.error.clone().unwrap_or_default(),
            Status::New | Status::Created => format!("no golden at {}", self.golden.display()),
            Status::Failed | Status::Updated => self
                .comparison
                .as_ref()
                .map(|c| c.to_string())
                .unwrap_or_default(),
        }
    }
}

/// Everything a suite run found.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Report {
    /// The suite file.
    pub suite: PathBuf,
    /// One result per shot, in suite order.
    pub results: Vec<ShotResult>,
    /// Wall time of the whole run.
    pub seconds: f64,
}

impl Report {
    /// How many results have `status`.
    pub fn count(&self, status: Status) -> usize {
        self.results.iter().filter(|r| r.status == status).count()
    }

    /// `animed check`'s exit code: 2 if any shot could not be drawn or
    /// compared, else 1 if any failed or is new, else 0.
    pub fn exit_code(&self) -> i32 {
        if self.count(Status::Error) > 0 {
            2
        } else if self.results.iter().any(|r| r.status.is_failure()) {
            1
        } else {
            0
        }
    }

    /// The closing line: `3 passed, 1 failed, 1 new`.
    pub fn totals(&self) -> String {
        let mut parts = vec![
            format!("{} passed", self.count(Status::Passed)),
            format!("{} failed", self.count(Status::Failed)),
        ];
        for (s, word) in [
            (Status::New, "new"),
            (Status::Updated, "updated"),
            (Status::Created, "created"),
            (Status::Error, "errors"),
        ] {
            let n = self.count(s);
            if n > 0 {
                parts.push(format!("{n} {word}"));
            }
        }
        parts.join(", ")
    }

    /// The terminal table: one row per picture, then the totals.
    pub fn table(&self) -> String {
        let name_w = self
            .results
            .iter()
            .map(|r| r.name.chars().count())
            .max()
            .unwrap_or(4)
            .max(4);
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{:<name_w$}  {:<7}  {:>17}  {:>5}  {:>7}  SEE",
            "SHOT", "RESULT", "DIFFERING/ALLOWED", "WORST", "SSIM"
        );
        for r in &self.results {
            let (counts, worst, ssim) = match &r.comparison {
                Some(c) if c.actual_size == c.golden_size => (
                    format!("{}/{}", c.differing, c.allowed),
                    c.worst.to_string(),
                    c.ssim.map(|v| format!("{v:.5}")).unwrap_or_default(),
                ),
                Some(c) => (
                    format!("size {}x{}", c.actual_size.0, c.actual_size.1),
                    "-".into(),
                    "-".into(),
                ),
                None => ("-".into(), "-".into(), "-".into()),
            };
            let see = match (r.status, &r.diff_png, &r.actual_png) {
                (Status::Error, _, _) => r.error.clone().unwrap_or_default(),
                (_, Some(d), _) => d.display().to_string(),
                (_, None, Some(a)) => a.display().to_string(),
                (Status::Updated | Status::Created, _, _) => r.golden.display().to_string(),
                _ => String::new(),
            };
            let _ = writeln!(
                s,
                "{:<name_w$}  {:<7}  {:>17}  {:>5}  {:>7}  {}",
                r.name,
                r.status.word(),
                counts,
                worst,
                ssim,
                see
            );
        }
        let _ = writeln!(s, "{} ({:.1} s)", self.totals(), self.seconds);
        s
    }

    /// JUnit XML: one `<testcase>` per picture; failures and new goldens
    /// are `<failure>`, shots that could not be drawn are `<error>`.
    pub fn junit(&self) -> String {
        let suite = self
            .suite
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "suite".into());
        let failures = self
            .results
            .iter()
            .filter(|r| matches!(r.status, Status::Failed | Status::New))
            .count();
        let errors = self.count(Status::Error);
        let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        let _ = writeln!(
            s,
            "<testsuites name=\"animed check\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" time=\"{:.3}\">",
            self.results.len(),
            self.seconds
        );
        let _ = writeln!(
            s,
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" skipped=\"0\" time=\"{:.3}\">",
            xml(&suite),
            self.results.len(),
            self.seconds
        );
        for r in &self.results {
            let _ = write!(
                s,
                "    <testcase name=\"{}\" classname=\"{}.{}\" file=\"{}\" time=\"{:.3}\"",
                xml(&r.name),
                xml(&suite),
                xml(&r.case),
                xml(&r.file.display().to_string()),
                r.seconds
            );
            let body = self.files_text(r);
            match r.status {
                Status::Passed | Status::Updated | Status::Created => {
                    let _ = writeln!(s, "/>");
                }
                Status::Failed | Status::New => {
                    let kind = if r.status == Status::New {
                        "new"
                    } else {
                        "differs"
                    };
                    let _ = writeln!(
                        s,
                        ">\n      <failure type=\"{kind}\" message=\"{}\">{}</failure>\n    </testcase>",
                        xml(&r.reason()),
                        xml(&body)
                    );
                }
                Status::Error => {
                    let _ = writeln!(
                        s,
                        ">\n      <error type=\"error\" message=\"{}\"/>\n    </testcase>",
                        xml(&r.reason())
                    );
                }
            }
        }
        s.push_str("  </testsuite>\n</testsuites>\n");
        s
    }

    fn files_text(&self, r: &ShotResult) -> String {
        let mut t = format!("golden: {}", r.golden.display());
        if let Some(a) = &r.actual_png {
            let _ = write!(t, "\nactual: {}", a.display());
        }
        if let Some(d) = &r.diff_png {
            let _ = write!(t, "\ndiff: {}", d.display());
        }
        t
    }

    /// JSON: `{"suite", "passed", "failed", …, "shots": [{"name", "status",
    /// "differing", "allowed", "worst", "ssim", "golden", "actual", "diff",
    /// "error", …}]}`.
    pub fn json(&self) -> String {
        let path = |p: &Option<PathBuf>| p.as_ref().map(|p| p.display().to_string());
        let shots: Vec<serde_json::Value> = self
            .results
            .iter()
            .map(|r| {
                let c = r.comparison.as_ref();
                serde_json::json!({
                    "name": r.name,
                    "case": r.case,
                    "file": r.file.display().to_string(),
                    "time": r.time,
                    "status": r.status.word().to_ascii_lowercase(),
                    "golden": r.golden.display().to_string(),
                    "actual": path(&r.actual_png),
                    "diff": path(&r.diff_png),
                    "differing": c.map(|c| c.differing),
                    "changed": c.map(|c| c.changed),
                    "allowed": c.map(|c| c.allowed),
                    "worst": c.map(|c| c.worst),
                    "ssim": c.and_then(|c| c.ssim),
                    "size": c.map(|c| [c.actual_size.0, c.actual_size.1]),
                    "golden_size": c.map(|c| [c.golden_size.0, c.golden_size.1]),
                    "message": r.reason(),
                    "seconds": r.seconds,
                })
            })
            .collect();
        let v = serde_json::json!({
            "suite": self.suite.display().to_string(),
            "passed": self.count(Status::Passed),
            "failed": self.count(Status::Failed),
            "new": self.count(Status::New),
            "updated": self.count(Status::Updated),
            "created": self.count(Status::Created),
            "errors": self.count(Status::Error),
            "exit_code": self.exit_code(),
            "seconds": self.seconds,
            "shots": shots,
        });
        let mut s = serde_json::to_string_pretty(&v).unwrap_or_default();
        s.push('\n');
        s
    }

    /// Writes the report to `path`: JUnit XML for `.xml`, JSON for `.json`.
    pub fn write(&self, path: &Path) -> Result<()> {
        let text = match path.extension().and_then(|e| e.to_str()) {
            Some("xml") => self.junit(),
            Some("json") => self.json(),
            _ => {
                return Err(Error::in_file(
                    ErrorKind::Invalid,
                    path,
                    "a report is .xml (JUnit) or .json",
                ))
            }
        };
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir)
                .map_err(|e| Error::in_file(ErrorKind::Io, dir, e.to_string()))?;
        }
        std::fs::write(path, text).map_err(|e| Error::in_file(ErrorKind::Io, path, e.to_string()))
    }
}

/// Escapes text for XML attributes and content.
fn xml(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            c if (c as u32) < 0x20 && c != '\t' => {}
            c => out.push(c),
        }
    }
    out
}
