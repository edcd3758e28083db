//! The in-app file browser (minifb has no native dialog): a folder listing
//! of sub-folders and known scene files, and a typed path with Tab
//! completion.

use std::path::{Path, PathBuf};

/// What the chosen file will be used for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    Open,
    Import,
    SaveAs,
    /// An image for the material panel's texture.
    Texture,
}

impl Purpose {
    pub fn title(self) -> &'static str {
        match self {
            Purpose::Open => "Open scene",
            Purpose::Import => "Import model",
            Purpose::SaveAs => "Save scene as",
            Purpose::Texture => "Texture image",
        }
    }

    pub fn verb(self) -> &'static str {
        match self {
            Purpose::Open => "Open",
            Purpose::Import => "Import",
            Purpose::SaveAs => "Save",
            Purpose::Texture => "Use",
        }
    }

    /// Which files the listing shows (folders always).
    pub fn lists(self) -> fn(&str) -> bool {
        match self {
            Purpose::Texture => is_image_file,
            _ => is_known_file,
        }
    }
}

/// A row of the listing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Entry {
    pub name: String,
    pub is_dir: bool,
}

/// File kinds the browser shows.
pub fn is_known_file(name: &str) -> bool {
    let l = name.to_ascii_lowercase();
    [
        ".iv", ".wrl", ".wrl.gz", ".wrz", ".vrml", ".obj", ".gz", ".gltf", ".glb", ".x3d", ".x3dv",
        ".x3dz", ".x3dvz",
    ]
    .iter()
    .any(|e| l.ends_with(e))
}

/// Image files a texture can be read from (`format::textures::decode`).
pub fn is_image_file(name: &str) -> bool {
    let l = name.to_ascii_lowercase();
    [
        ".png", ".jpg", ".jpeg", ".gif", ".bmp", ".rgb", ".rgba", ".bw", ".sgi",
    ]
    .iter()
    .any(|e| l.ends_with(e))
}

/// Browser state.
#[derive(Clone, Debug)]
pub struct Browser {
    pub purpose: Purpose,
    pub dir: PathBuf,
    pub entries: Vec<Entry>,
    /// The typed path (absolute or relative to `dir`).
    pub input: String,
    /// Highlighted row.
    pub highlight: Option<usize>,
    /// First visible row.
    pub scroll: usize,
    /// A problem to show (unreadable folder, no match).
    pub message: Option<String>,
}

impl Browser {
    pub fn new(purpose: Purpose, dir: &Path) -> Browser {
        let mut b = Browser {
            purpose,
            dir: dir.to_path_buf(),
            entries: Vec::new(),
            input: String::new(),
            highlight: None,
            scroll: 0,
            message: None,
        };
        b.enter(dir);
        b
    }

    /// Lists `dir`: ".." first, then folders, then known files, each sorted
    /// case-insensitively; hidden entries are skipped.
    pub fn enter(&mut self, dir: &Path) {
        let dir = normalize(dir);
        match list(&dir, self.purpose.lists()) {
            Ok(entries) => {
                self.entries = entries;
                self.dir = dir;
                self.input = with_slash(&self.dir);
                self.highlight = None;
                self.scroll = 0;
                self.message = None;
            }
            Err(e) => self.message = Some(format!("{}: {e}", dir.display())),
        }
    }

    /// The typed path: a bare name is in the shown folder; anything with a
    /// '/' is a path as a shell would read it (absolute, `~/…`, or relative
    /// to the working directory, which is how the shown folder is written).
    pub fn resolved(&self) -> PathBuf {
        let t = restart_at_root(self.input.trim());
        if t.contains('/') {
            expand_home(t)
        } else {
            self.dir.join(t)
        }
    }

    /// Enter / the accept button: a folder is entered (`None`), a file
    /// that is not there for reading is refused with a message (`None`);
    /// otherwise the path to use.
    pub fn accept(&mut self) -> Option<PathBuf> {
        let path = self.resolved();
        if path.is_dir() {
            self.enter(&path);
            return None;
        }
        if self.purpose != Purpose::SaveAs && !path.is_file() {
            self.message = Some(format!("no file {}", path.display()));
            return None;
        }
        Some(path)
    }

    /// Typed text: a `/` or `~/` typed right after a folder's `/` starts
    /// a new path (as in GTK's location bar), so typing an absolute path
    /// over the shown folder never gives `DIR//typed/path`.
    pub fn type_text(&mut self, s: &str) {
        self.input.extend(s.chars().filter(|c| !c.is_control()));
        let fresh = restart_at_root(&self.input).to_string();
        self.input = fresh;
        self.message = None;
    }

    /// Tab: completes the typed path to the longest common prefix of the
    /// matching entries in its folder (a unique folder gets a trailing '/').
    pub fn complete(&mut self) {
        let typed = self.input.clone();
        let (head, prefix) = match typed.rfind('/') {
            Some(i) => (typed[..=i].to_string(), typed[i + 1..].to_string()),
            None => (String::new(), typed.clone()),
        };
        let folder = if head.is_empty() {
            self.dir.clone()
        } else {
            expand_home(&head)
        };
        let Ok(entries) = list(&folder, self.purpose.lists()) else {
            self.message = Some(format!("no folder {}", folder.display()));
            return;
        };
        let matches: Vec<&Entry> = entries
            .iter()
            .filter(|e| e.name != ".." && e.name.starts_with(&prefix))
            .collect();
        match matches.len() {
            0 => self.message = Some(format!("no match for '{prefix}'")),
            1 => {
                let e = matches[0];
                self.input = format!("{head}{}{}", e.name, if e.is_dir { "/" } else { "" });
                self.message = None;
                if e.is_dir {
                    // Show the folder; the input becomes its full path.
                    self.enter(&folder.join(&e.name));
                }
            }
            _ => {
                let common = matches
                    .iter()
                    .skip(1)
                    .fold(matches[0].name.clone(), |acc, e| {
                        acc.chars()
                            .zip(e.name.chars())
                            .take_while(|(a, b)| a == b)
                            .map(|(a, _)| a)
                            .collect()
                    });
                self.input = format!("{head}{common}");
                self.message = Some(format!("{} matches", matches.len()));
            }
        }
    }

    /// Moves the highlight by `d` rows and copies the entry into the input.
    pub fn step(&mut self, d: i32) {
        if self.entries.is_empty() {
            return;
        }
        let n = self.entries.len() as i32;
        let cur = self
            .highlight
            .map_or(if d > 0 { -1 } else { n }, |h| h as i32);
        let h = (cur + d).clamp(0, n - 1) as usize;
        self.highlight = Some(h);
        self.input = self.entry_path_text(h);
    }

    /// The typed-path text for entry `i`.
    pub fn entry_path_text(&self, i: usize) -> String {
        let e = &self.entries[i];
        if e.name == ".." {
            let parent = self.dir.parent().unwrap_or(&self.dir);
            with_slash(parent)
        } else {
            let p = self.dir.join(&e.name);
            if e.is_dir {
                with_slash(&p)
            } else {
                p.display().to_string()
            }
        }
    }

    /// Keeps the highlighted row inside a window of `rows` visible rows.
    pub fn scroll_to_highlight(&mut self, rows: usize) {
        if let Some(h) = self.highlight {
            if h < self.scroll {
                self.scroll = h;
            } else if rows > 0 && h >= self.scroll + rows {
                self.scroll = h + 1 - rows;
            }
        }
    }
}

fn with_slash(p: &Path) -> String {
    let s = p.display().to_string();
    if s.ends_with('/') {
        s
    } else {
        format!("{s}/")
    }
}

fn expand_home(s: &str) -> PathBuf {
    if let Some(rest) = s.strip_prefix("~/") {
        if let Some(home) = std::env::var_os("HOME") {
            return PathBuf::from(home).join(rest);
        }
    }
    PathBuf::from(s)
}

/// Removes `.` and resolves `..` textually (no symlink lookups).
fn normalize(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            other => out.push(other.as_os_str()),
        }
    }
    if out.as_os_str().is_empty() {
        out.push(".");
    }
    out
}

/// `dir`'s folders and the files `shown` accepts.
fn list(dir: &Path, shown: fn(&str) -> bool) -> std::io::Result<Vec<Entry>> {
    let mut dirs = Vec::new();
    let mut files = Vec::new();
    for e in std::fs::read_dir(dir)? {
        let Ok(e) = e else { continue };
        let name = e.file_name().to_string_lossy().to_string();
        if name.starts_with('.') {
            continue;
        }
        let is_dir = e.path().is_dir();
        if is_dir {
            dirs.push(Entry { name, is_dir });
        } else if shown(&name) {
            files.push(Entry { name, is_dir });
        }
    }
    let key = |e: &Entry| e.name.to_lowercase();
    dirs.sort_by_key(key);
    files.sort_by_key(key);
    let mut out = Vec::with_capacity(dirs.len() + files.len() + 1);
    if dir.parent().is_some() {
        out.push(Entry {
            name: "..".into(),
            is_dir: true,
        });
    }
    out.extend(dirs);
    out.extend(files);
    Ok(out)
}

/// The part of a typed path from its last restart: `DIR//abs/path` →
/// `/abs/path`, `DIR/~/x` → `~/x`; anything else unchanged.
pub fn restart_at_root(t: &str) -> &str {
    let slash = t.rfind("//").map(|i| i + 1);
    let home = t.rfind("/~/").map(|i| i + 1);
    match slash.max(home) {
        Some(i) => &t[i..],
        None => t,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_typed_absolute_path_replaces_the_folder() {
        assert_eq!(restart_at_root("/home/u//tmp/a.wrl"), "/tmp/a.wrl");
        assert_eq!(restart_at_root("/home/u/~/a.wrl"), "~/a.wrl");
        assert_eq!(restart_at_root("/home/u/a.wrl"), "/home/u/a.wrl");
        let dir = std::env::temp_dir();
        let mut b = Browser::new(Purpose::Open, &dir);
        assert!(b.input.ends_with('/'), "{}", b.input);
        b.type_text("/tmp/x.wrl");
        assert_eq!(b.input, "/tmp/x.wrl");
        assert_eq!(b.resolved(), PathBuf::from("/tmp/x.wrl"));
    }

    /// A small folder tree; `tag` keeps parallel tests apart.
    fn tree(tag: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("animed-browser-unit-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(d.join("models")).unwrap();
        std::fs::create_dir_all(d.join(".hidden")).unwrap();
        for f in ["walk.wrl", "wave.wrl.gz", "cube.obj", "notes.txt", "Box.iv"] {
            std::fs::write(d.join(f), b"x").unwrap();
        }
        d
    }

    #[test]
    fn lists_folders_then_known_files() {
        let d = tree("list");
        let b = Browser::new(Purpose::Open, &d);
        let names: Vec<_> = b.entries.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(
            names,
            vec![
                "..",
                "models",
                "Box.iv",
                "cube.obj",
                "walk.wrl",
                "wave.wrl.gz"
            ]
        );
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn tab_completes_common_prefix_then_unique() {
        let d = tree("complete");
        let mut b = Browser::new(Purpose::Open, &d);
        b.input = format!("{}/wa", d.display());
        b.complete();
        assert_eq!(
            b.input,
            format!("{}/wa", d.display()),
            "walk/wave share 'wa'"
        );
        b.input.push('l');
        b.complete();
        assert_eq!(b.input, format!("{}/walk.wrl", d.display()));
        b.input = "mo".into();
        b.complete();
        // A bare name completes in the shown folder.
        assert_eq!(b.input, format!("{}/models/", d.display()));
        assert!(b.dir.ends_with("models"));
        let _ = std::fs::remove_dir_all(&d);
    }
}
