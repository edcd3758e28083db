//! Reading a check suite (TOML) into [`Suite`]: cases with their scene
//! file, times, render options, golden and tolerance. Every mistake is
//! reported as `suite.toml:line:column: message` (the `toml` crate gives
//! byte spans; we turn them into lines and columns) and unknown keys are
//! errors, so a typo never silently changes what is tested.

use crate::compare::{Allowance, Tolerance};
use crate::error::{Error, ErrorKind, Result};
use crate::front::{RenderSpec, Style};
use crate::render::job::Headlight;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// A parsed suite: where it is and the cases in file order.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Suite {
    /// The suite file (relative paths inside it are relative to its folder).
    pub path: PathBuf,
    /// The cases, in the order the file lists them.
    pub cases: Vec<Case>,
}

/// When in the animation a case takes its pictures.
#[derive(Clone, Debug, PartialEq)]
pub enum When {
    /// One picture at this time (seconds); the shot is named like the case.
    Time(f32),
    /// One picture at this scene frame (uses the scene's fps).
    Frame(f32),
    /// One picture per time, named `CASE@T` (e.g. `walk@0.5`).
    Times(Vec<f32>),
    /// One picture per scene frame, named `CASE@fN` (e.g. `walk@f12`).
    Frames(Vec<f32>),
}

/// One case of a suite: a scene, how to draw it, which golden to match.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Case {
    /// Unique name; goldens and output files are named after it.
    pub name: String,
    /// The scene file (resolved against the suite's folder).
    pub file: PathBuf,
    /// Size, camera, style, headlight, … (`time` is set per shot).
    pub spec: RenderSpec,
    /// The time(s) or frame(s) to draw.
    pub when: When,
    /// Explicit golden (only with one time); else `GOLDENS/SHOT.png`.
    pub golden: Option<PathBuf>,
    /// The folder of default goldens.
    pub goldens: PathBuf,
    /// What differences pass.
    pub tolerance: Tolerance,
}

/// One picture to take: a case at one time.
#[derive(Clone, Debug, PartialEq)]
pub struct Shot {
    /// `CASE`, `CASE@T` or `CASE@fN`.
    pub name: String,
    /// Index of the case in [`Suite::cases`].
    pub case: usize,
    /// Time (seconds) or, when `frame` is true, scene frame.
    pub at: f32,
    /// Whether `at` is a frame number.
    pub frame: bool,
    /// The golden to compare with.
    pub golden: PathBuf,
}

/// Formats a time for a file name: shortest form, `-` kept, `.` kept
/// (`0`, `0.5`, `12.25`, `-1`).
pub fn time_label(t: f32) -> String {
    let s = format!("{t}");
    s.replace('+', "")
}

impl Case {
    /// A case with an explicit golden file (what `animed check FILE
    /// --golden G.png` builds).
    pub fn new(
        name: String,
        file: PathBuf,
        spec: RenderSpec,
        when: When,
        golden: PathBuf,
        tolerance: Tolerance,
    ) -> Case {
        let goldens = golden.parent().unwrap_or(Path::new("")).to_path_buf();
        Case {
            name,
            file,
            spec,
            when,
            golden: Some(golden),
            goldens,
            tolerance,
        }
    }
}

impl Suite {
    /// A suite of one case (its path is the case's scene file).
    pub fn single(case: Case) -> Suite {
        Suite {
            path: case.file.clone(),
            cases: vec![case],
        }
    }

    /// The pictures the suite takes, case by case, time by time.
    pub fn shots(&self) -> Vec<Shot> {
        let mut out = Vec::new();
        for (i, c) in self.cases.iter().enumerate() {
            let list: Vec<(String, f32, bool)> = match &c.when {
                When::Time(t) => vec![(c.name.clone(), *t, false)],
                When::Frame(f) => vec![(c.name.clone(), *f, true)],
                When::Times(ts) => ts
                    .iter()
                    .map(|t| (format!("{}@{}", c.name, time_label(*t)), *t, false))
                    .collect(),
                When::Frames(fs) => fs
                    .iter()
                    .map(|f| (format!("{}@f{}", c.name, time_label(*f)), *f, true))
                    .collect(),
            };
            for (name, at, frame) in list {
                let golden = c
                    .golden
                    .clone()
                    .unwrap_or_else(|| c.goldens.join(format!("{name}.png")));
                out.push(Shot {
                    name,
                    case: i,
                    at,
                    frame,
                    golden,
                });
            }
        }
        out
    }

    /// Reads and checks a suite file.
    pub fn load(path: impl AsRef<Path>) -> Result<Suite> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path)
            .map_err(|e| Error::in_file(ErrorKind::Suite, path, e.to_string()))?;
        Suite::parse(&text, path)
    }

    /// Parses suite text; `path` names it in errors and anchors relative
    /// paths.
    pub fn parse(text: &str, path: &Path) -> Result<Suite> {
        let p = Parser { text, path };
        let doc = DeTable::parse(text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            p.err(span, e.message().trim_end().to_string())
        })?;
        p.suite(doc.get_ref())
    }
}

/// Top-level keys: suite settings plus the defaults every case inherits.
const SUITE_KEYS: &[&str] = &[
    "goldens",
    "case",
    "tolerance",
    "size",
    "viewpoint",
    "style",
    "headlight",
    "background",
    "aa",
    "threads",
    "clip",
];
const CASE_KEYS: &[&str] = &[
    "name",
    "file",
    "golden",
    "time",
    "times",
    "frame",
    "frames",
    "tolerance",
    "size",
    "viewpoint",
    "style",
    "headlight",
    "background",
    "aa",
    "threads",
    "clip",
];
const TOLERANCE_KEYS: &[&str] = &["channel", "pixels", "fraction", "ssim"];

/// Defaults when neither suite nor case sets them: small goldens.
const DEFAULT_SIZE: (u32, u32) = (320, 240);

type Value<'i> = Spanned<DeValue<'i>>;

struct Parser<'a> {
    text: &'a str,
    path: &'a Path,
}

impl Parser<'_> {
    fn err(&self, span: Range<usize>, msg: impl Into<String>) -> Error {
        let (line, col) = line_col(self.text, span.start);
        Error::at(ErrorKind::Suite, self.path, line, col, msg)
    }

    fn check_keys(&self, t: &DeTable, allowed: &[&str], what: &str) -> Result<()> {
        for (k, _) in t.iter() {
            if !allowed.contains(&k.get_ref().as_ref()) {
                return Err(self.err(
                    k.span(),
                    format!(
                        "unknown key {:?} in {what} (known: {})",
                        k.get_ref(),
                        allowed.join(", ")
                    ),
                ));
            }
        }
        Ok(())
    }

    fn suite(&self, top: &DeTable) -> Result<Suite> {
        self.check_keys(top, SUITE_KEYS, "the suite")?;
        let base = self.path.parent().unwrap_or(Path::new("")).to_path_buf();
        let goldens = match top.get("goldens") {
            Some(v) => base.join(self.string(v, "goldens")?),
            None => base.join("goldens"),
        };
        let mut defaults = RenderSpec::new(DEFAULT_SIZE.0, DEFAULT_SIZE.1);
        self.render_keys(top, &mut defaults)?;
        let mut tolerance = Tolerance::exact();
        if let Some(v) = top.get("tolerance") {
            self.tolerance(v, &mut tolerance)?;
        }
        let Some(cases) = top.get("case") else {
            return Err(self.err(
                0..0,
                "no cases: add at least one [[case]] with name and file",
            ));
        };
        let DeValue::Array(list) = cases.get_ref() else {
            return Err(self.err(cases.span(), "`case` must be [[case]] tables"));
        };
        let mut out: Vec<Case> = Vec::new();
        for item in list.iter() {
            let DeValue::Table(t) = item.get_ref() else {
                return Err(self.err(item.span(), "each case must be a table"));
            };
            let case = self.case(item.span(), t, &base, &goldens, &defaults, &tolerance)?;
            if out.iter().any(|c| c.name == case.name) {
                let span = t.get("name").map(|v| v.span()).unwrap_or(item.span());
                return Err(self.err(span, format!("a second case named {:?}", case.name)));
            }
            out.push(case);
        }
        if out.is_empty() {
            return Err(self.err(cases.span(), "no cases"));
        }
        Ok(Suite {
            path: self.path.to_path_buf(),
            cases: out,
        })
    }

    fn case(
        &self,
        span: Range<usize>,
        t: &DeTable,
        base: &Path,
        goldens: &Path,
        defaults: &RenderSpec,
        tolerance: &Tolerance,
    ) -> Result<Case> {
        self.check_keys(t, CASE_KEYS, "a case")?;
        let name_v = t
            .get("name")
            .ok_or_else(|| self.err(span.clone(), "this case has no `name`"))?;
        let name = self.string(name_v, "name")?;
        let ok = |c: char| c.is_ascii_alphanumeric() || "_-.".contains(c);
        if name.is_empty() || !name.chars().all(ok) || name.starts_with('.') {
            return Err(self.err(
                name_v.span(),
                format!("case name {name:?}: use letters, digits, '_', '-', '.' (it names files)"),
            ));
        }
        let file_v = t
            .get("file")
            .ok_or_else(|| self.err(span.clone(), format!("case {name:?} has no `file`")))?;
        let file = base.join(self.string(file_v, "file")?);
        let mut spec = defaults.clone();
        self.render_keys(t, &mut spec)?;
        let mut tol = *tolerance;
        if let Some(v) = t.get("tolerance") {
            self.tolerance(v, &mut tol)?;
        }
        let whens: Vec<(&str, &Value)> = ["time", "times", "frame", "frames"]
            .iter()
            .filter_map(|k| t.get(*k).map(|v| (*k, v)))
            .collect();
        if whens.len() > 1 {
            return Err(self.err(
                whens[1].1.span(),
                format!(
                    "give only one of time, times, frame, frames (also has {})",
                    whens[0].0
                ),
            ));
        }
        let when = match whens.first() {
            None => When::Time(0.0),
            Some(("time", v)) => When::Time(self.number(v, "time")?),
            Some(("frame", v)) => When::Frame(self.number(v, "frame")?),
            Some((k, v)) => {
                let DeValue::Array(items) = v.get_ref() else {
                    return Err(
                        self.err(v.span(), format!("`{k}` must be a list, e.g. [0, 0.5, 1]"))
                    );
                };
                if items.is_empty() {
                    return Err(self.err(v.span(), format!("`{k}` is empty")));
                }
                let mut list = Vec::new();
                for i in items.iter() {
                    let x = self.number(i, k)?;
                    if list.contains(&x) {
                        return Err(self.err(i.span(), format!("{x} is listed twice")));
                    }
                    list.push(x);
                }
                if *k == "times" {
                    When::Times(list)
                } else {
                    When::Frames(list)
                }
            }
        };
        let golden = match t.get("golden") {
            None => None,
            Some(v) => {
                if matches!(when, When::Times(_) | When::Frames(_)) {
                    return Err(self.err(
                        v.span(),
                        "`golden` names one file; with times/frames the goldens are \
                         GOLDENS/NAME@T.png (leave `golden` out)",
                    ));
                }
                Some(base.join(self.string(v, "golden")?))
            }
        };
        Ok(Case {
            name,
            file,
            spec,
            when,
            golden,
            goldens: goldens.to_path_buf(),
            tolerance: tol,
        })
    }

    /// Render options, shared by the suite (defaults) and cases.
    fn render_keys(&self, t: &DeTable, spec: &mut RenderSpec) -> Result<()> {
        if let Some(v) = t.get("size") {
            let s = self.string(v, "size")?;
            let (w, h) = parse_size(&s).map_err(|m| self.err(v.span(), m))?;
            spec.width = w;
            spec.height = h;
        }
        if let Some(v) = t.get("viewpoint") {
            spec.viewpoint = Some(self.string(v, "viewpoint")?);
        }
        if let Some(v) = t.get("clip") {
            spec.clip = Some(self.string(v, "clip")?);
        }
        if let Some(v) = t.get("style") {
            let s = self.string(v, "style")?;
            spec.style = Some(parse_style(&s).ok_or_else(|| {
                self.err(
                    v.span(),
                    format!("style {s:?} is not filled, lines, points or hidden"),
                )
            })?);
        }
        if let Some(v) = t.get("headlight") {
            spec.headlight = match v.get_ref() {
                DeValue::Boolean(true) => Headlight::On,
                DeValue::Boolean(false) => Headlight::Off,
                _ => {
                    let s = self.string(v, "headlight")?;
                    Headlight::parse(&s).ok_or_else(|| {
                        self.err(v.span(), format!("headlight {s:?} is not on, off or auto"))
                    })?
                }
            };
        }
        if let Some(v) = t.get("background") {
            let DeValue::Array(items) = v.get_ref() else {
                return Err(self.err(v.span(), "background must be [r, g, b] in 0..1"));
            };
            if items.len() != 3 {
                return Err(self.err(v.span(), "background must be [r, g, b] in 0..1"));
            }
            let mut rgb = [0.0f32; 3];
            for (c, i) in rgb.iter_mut().zip(items.iter()) {
                *c = self.number(i, "background")?;
                if !(0.0..=1.0).contains(c) {
                    return Err(self.err(i.span(), "background components are in 0..1"));
                }
            }
            spec.background = Some(rgb);
        }
        if let Some(v) = t.get("aa") {
            spec.aa = self.integer(v, "aa", 1, 64)? as u32;
        }
        if let Some(v) = t.get("threads") {
            spec.threads = self.integer(v, "threads", 0, 1024)? as usize;
        }
        Ok(())
    }

    fn tolerance(&self, v: &Value, tol: &mut Tolerance) -> Result<()> {
        let DeValue::Table(t) = v.get_ref() else {
            return Err(self.err(
                v.span(),
                "tolerance must be a table, e.g. { channel = 2, fraction = 0.001 }",
            ));
        };
        self.check_keys(t, TOLERANCE_KEYS, "a tolerance")?;
        if let Some(v) = t.get("channel") {
            tol.channel = self.integer(v, "channel", 0, 255)? as u8;
        }
        match (t.get("pixels"), t.get("fraction")) {
            (Some(_), Some(f)) => {
                return Err(self.err(f.span(), "give pixels or fraction, not both"));
            }
            (Some(v), None) => {
                tol.pixels = Allowance::Count(self.integer(v, "pixels", 0, i64::MAX)? as u64)
            }
            (None, Some(v)) => {
                let f = self.float(v, "fraction")?;
                if !(0.0..=1.0).contains(&f) {
                    return Err(self.err(v.span(), "fraction is in 0..1 (0.001 = 0.1 %)"));
                }
                tol.pixels = Allowance::Fraction(f);
            }
            (None, None) => {}
        }
        if let Some(v) = t.get("ssim") {
            let s = self.float(v, "ssim")?;
            if !(0.0..=1.0).contains(&s) {
                return Err(self.err(v.span(), "ssim is in 0..1 (1 = identical; try 0.99)"));
            }
            tol.ssim = Some(s);
        }
        Ok(())
    }

    fn string(&self, v: &Value, key: &str) -> Result<String> {
        match v.get_ref() {
            DeValue::String(s) => Ok(s.to_string()),
            other => Err(self.err(
                v.span(),
                format!("`{key}` must be a string, not {}", other.type_str()),
            )),
        }
    }

    fn float(&self, v: &Value, key: &str) -> Result<f64> {
        let x = match v.get_ref() {
            DeValue::Integer(i) => i64::from_str_radix(i.as_str(), i.radix())
                .ok()
                .map(|i| i as f64),
            DeValue::Float(f) => f.as_str().parse::<f64>().ok(),
            other => {
                return Err(self.err(
                    v.span(),
                    format!("`{key}` must be a number, not {}", other.type_str()),
                ))
            }
        };
        match x {
            Some(x) if x.is_finite() => Ok(x),
            _ => Err(self.err(v.span(), format!("`{key}` must be a finite number"))),
        }
    }

    fn number(&self, v: &Value, key: &str) -> Result<f32> {
        let x = self.float(v, key)?;
        if x.abs() > 1e9 {
            return Err(self.err(v.span(), format!("`{key}` {x} is out of range")));
        }
        Ok(x as f32)
    }

    fn integer(&self, v: &Value, key: &str, min: i64, max: i64) -> Result<i64> {
        let DeValue::Integer(i) = v.get_ref() else {
            return Err(self.err(v.span(), format!("`{key}` must be a whole number")));
        };
        match i64::from_str_radix(i.as_str(), i.radix()) {
            Ok(n) if (min..=max).contains(&n) => Ok(n),
            _ => Err(self.err(v.span(), format!("`{key}` must be in {min}..={max}"))),
        }
    }
}

/// 1-based line and column (in characters) of byte `offset`.
fn line_col(text: &str, offset: usize) -> (u32, u32) {
    let mut end = offset.min(text.len());
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    let before = &text[..end];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
    (line as u32, col as u32)
}

/// `WIDTHxHEIGHT`, each side 1..=16384, at most 64 Mpix.
pub fn parse_size(s: &str) -> std::result::Result<(u32, u32), String> {
    let bad = || format!("size {s:?} is not WIDTHxHEIGHT (e.g. \"320x240\")");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    let max = crate::render::MAX_SIDE;
    if w == 0 || h == 0 || w > max || h > max {
        return Err(format!("size {s:?}: each side must be 1..={max}"));
    }
    if w as u64 * h as u64 > crate::render::MAX_PIXELS {
        return Err(format!(
            "size {s:?}: more than {} pixels",
            crate::render::MAX_PIXELS
        ));
    }
    Ok((w, h))
}

/// `filled`, `lines`, `points` or `hidden`.
pub fn parse_style(s: &str) -> Option<Style> {
    match s.to_ascii_lowercase().as_str() {
        "filled" | "fill" => Some(Style::Filled),
        "lines" | "line" | "wireframe" => Some(Style::Lines),
        "points" | "point" => Some(Style::Points),
        "hidden" => Some(Style::Hidden),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SUITE: &str = r#"
goldens = "pics"
size = "100x50"
tolerance = { channel = 3, pixels = 7 }

[[case]]
name = "a"
file = "a.wrl"
frames = [0, 12]
tolerance = { fraction = 0.5 }

[[case]]
name = "b"
file = "sub/b.iv"
golden = "b-golden.png"
time = 1.5
size = "20x10"
style = "lines"
headlight = false
tolerance = { ssim = 0.95 }
"#;

    #[test]
    fn suite_defaults_merge_into_cases_and_name_the_shots() {
        let s = Suite::parse(SUITE, Path::new("dir/suite.toml")).unwrap();
        assert_eq!(s.cases.len(), 2);
        let (a, b) = (&s.cases[0], &s.cases[1]);
        assert_eq!((a.spec.width, a.spec.height), (100, 50));
        assert_eq!((b.spec.width, b.spec.height), (20, 10));
        assert_eq!(b.spec.style, Some(Style::Lines));
        assert_eq!(b.spec.headlight, Headlight::Off);
        assert_eq!(a.file, Path::new("dir/a.wrl"));
        // Tolerance keys override one by one.
        assert_eq!(a.tolerance.channel, 3);
        assert_eq!(a.tolerance.pixels, Allowance::Fraction(0.5));
        assert_eq!(b.tolerance.pixels, Allowance::Count(7));
        assert_eq!(b.tolerance.ssim, Some(0.95));
        let shots = s.shots();
        let names: Vec<&str> = shots.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["a@f0", "a@f12", "b"]);
        assert_eq!(shots[1].golden, Path::new("dir/pics/a@f12.png"));
        assert!(shots[1].frame);
        assert_eq!(shots[2].golden, Path::new("dir/b-golden.png"));
        assert_eq!(shots[2].at, 1.5);
    }

    #[test]
    fn mistakes_point_at_their_line_and_column() {
        let err = |text: &str| {
            Suite::parse(text, Path::new("s.toml"))
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            err("[[case]]\nname = \"a\"\nfile = \"f\"\ntime = 1\ntimes = [2]\n"),
            "s.toml:5:9: give only one of time, times, frame, frames (also has time)"
        );
        assert_eq!(
            err("[[case]]\nname = \"a b\"\nfile = \"f\"\n"),
            "s.toml:2:8: case name \"a b\": use letters, digits, '_', '-', '.' (it names files)"
        );
        assert_eq!(
            err("[[case]]\nname = \"a\"\nfile = \"f\"\n[[case]]\nname = \"a\"\nfile = \"g\"\n"),
            "s.toml:5:8: a second case named \"a\""
        );
        assert!(err("x = 1\n").starts_with("s.toml:1:1: unknown key \"x\" in the suite"));
        assert!(err("size = \"1x1\"\n").contains("no cases"));
        assert!(
            err("[[case]]\nname = \"a\"\nfile = \"f\"\ntimes = [1, 1]\n")
                .starts_with("s.toml:4:13: 1 is listed twice")
        );
    }

    #[test]
    fn time_labels_are_short() {
        assert_eq!(time_label(0.0), "0");
        assert_eq!(time_label(0.5), "0.5");
        assert_eq!(time_label(12.25), "12.25");
        assert_eq!(time_label(-1.0), "-1");
    }
}
