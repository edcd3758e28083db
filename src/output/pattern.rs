//! Output file names for frame sequences: one run of `#` in the pattern is
//! replaced by the zero-padded frame index (`frames/f_####.png` →
//! `frames/f_0007.png`), as Blender and ffmpeg-style tools do.

use std::path::{Path, PathBuf};

/// A parsed `-o` pattern.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pattern {
    prefix: String,
    /// Width of the `#` run; 0 = no run (a single fixed file name).
    width: usize,
    suffix: String,
}

impl Pattern {
    /// Parses `s`; more than one run of `#` is an error (which one would
    /// count?).
    pub fn parse(s: &str) -> Result<Pattern, String> {
        let runs = count_runs(s);
        if runs > 1 {
            return Err(format!(
                "output pattern {s:?} has {runs} runs of '#'; use one run (e.g. frames/f_####.png)"
            ));
        }
        match s.find('#') {
            None => Ok(Pattern {
                prefix: s.to_string(),
                width: 0,
                suffix: String::new(),
            }),
            Some(a) => {
                let b = a + s[a..].find(|c| c != '#').unwrap_or(s.len() - a);
                Ok(Pattern {
                    prefix: s[..a].to_string(),
                    width: b - a,
                    suffix: s[b..].to_string(),
                })
            }
        }
    }

    /// Parses a path (which must be UTF-8 when it holds a `#`).
    pub fn from_path(p: &Path) -> Result<Pattern, String> {
        let s = p
            .to_str()
            .ok_or_else(|| format!("output pattern {} is not valid UTF-8", p.to_string_lossy()))?;
        Pattern::parse(s)
    }

    /// Whether the pattern numbers its files.
    pub fn has_index(&self) -> bool {
        self.width > 0
    }

    /// Checks that `count` frames (indices `0..count`) fit: a sequence needs
    /// a `#` run wide enough for the largest index, so names sort in order
    /// and never collide.
    pub fn check_count(&self, count: u32) -> Result<(), String> {
        if !self.has_index() {
            if count > 1 {
                return Err(format!(
                    "output {:?} has no '#' but {count} frames were asked for; \
                     put a run of '#' where the frame number goes (e.g. frames/f_####.png)",
                    self.prefix
                ));
            }
            return Ok(());
        }
        let digits = (count.saturating_sub(1)).to_string().len();
        if digits > self.width {
            return Err(format!(
                "output pattern {:?} has {} '#' but frame {} needs {digits} digits; use at least {digits}",
                self.to_string(),
                self.width,
                count - 1
            ));
        }
        Ok(())
    }

    /// The file name of frame `index`.
    pub fn expand(&self, index: u32) -> PathBuf {
        if self.width == 0 {
            return PathBuf::from(&self.prefix);
        }
        PathBuf::from(format!(
            "{}{:0w$}{}",
            self.prefix,
            index,
            self.suffix,
            w = self.width
        ))
    }

    /// The pattern's file extension, lower-cased ("png", "gif").
    pub fn extension(&self) -> Option<String> {
        self.expand(0)
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase())
    }
}

impl std::fmt::Display for Pattern {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}{}{}",
            self.prefix,
            "#".repeat(self.width),
            self.suffix
        )
    }
}

fn count_runs(s: &str) -> usize {
    let mut runs = 0;
    let mut prev = false;
    for c in s.chars() {
        let hash = c == '#';
        if hash && !prev {
            runs += 1;
        }
        prev = hash;
    }
    runs
}

/// Creates the folder `path` will be written into, if it is missing.
pub fn create_parent(path: &Path) -> Result<(), String> {
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create folder {}: {e}", dir.display())),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hashes_become_zero_padded_indices() {
        let p = Pattern::parse("frames/f_####.png").unwrap();
        assert_eq!(p.expand(7), PathBuf::from("frames/f_0007.png"));
        assert_eq!(p.expand(1234), PathBuf::from("frames/f_1234.png"));
        assert_eq!(p.extension().as_deref(), Some("png"));
        let p = Pattern::parse("#.PNG").unwrap();
        assert_eq!(p.expand(3), PathBuf::from("3.PNG"));
        assert_eq!(p.extension().as_deref(), Some("png"));
        let p = Pattern::parse("a/b##").unwrap();
        assert_eq!(p.expand(5), PathBuf::from("a/b05"));
        assert_eq!(p.to_string(), "a/b##");
    }

    #[test]
    fn without_hashes_it_is_one_file() {
        let p = Pattern::parse("out/anim.gif").unwrap();
        assert!(!p.has_index());
        assert_eq!(p.expand(9), PathBuf::from("out/anim.gif"));
        assert_eq!(p.extension().as_deref(), Some("gif"));
        assert!(p.check_count(1).is_ok());
        let e = p.check_count(2).unwrap_err();
        assert!(e.contains("has no '#'"), "{e}");
    }

    #[test]
    fn too_few_hashes_or_two_runs_are_errors() {
        let p = Pattern::parse("f_##.png").unwrap();
        assert!(p.check_count(100).is_ok()); // indices 0..=99
        let e = p.check_count(101).unwrap_err();
        assert!(e.contains("needs 3 digits"), "{e}");
        let e = Pattern::parse("f_##_#.png").unwrap_err();
        assert!(e.contains("2 runs"), "{e}");
    }

    #[test]
    fn creates_missing_folders() {
        let dir = std::env::temp_dir().join(format!("animed-pattern-{}", std::process::id()));
        let file = dir.join("a/b/f_01.png");
        create_parent(&file).unwrap();
        assert!(dir.join("a/b").is_dir());
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(create_parent(Path::new("plain.png")).is_ok());
    }
}
