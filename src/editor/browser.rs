//! The in-app file browser (minifb has no native dialog): a folder listing
//! of sub-folders and known scene files, and a typed path with Tab
//! completion. It reads no folder itself: what it needs from the disk is
//! an [`Ask`] the shell answers with what it [`Found`] (`shell.rs`), so
//! the browser is plain state and can be driven without a disk.

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

    /// Whether a file called `name` is listed for this purpose (folders
    /// always are).
    pub fn shows(self, name: &str) -> bool {
        match self {
            Purpose::Texture => is_image_file(name),
            _ => is_known_file(name),
        }
    }
}

/// What the browser needs read from the disk (the shell answers it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Ask {
    /// List this folder and show it.
    Enter(PathBuf),
    /// List this folder to complete the typed path in it (Tab).
    Complete(PathBuf),
    /// Is this typed path a folder (then list it), a file, or nothing?
    Probe(PathBuf),
}

/// The shell's answer to an [`Ask`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Found {
    /// A folder's rows (`..` first, then folders, then the files the
    /// purpose shows), or why it could not be read.
    Listing(Result<Vec<Entry>, String>),
    /// A file.
    File,
    /// Nothing there.
    Missing,
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

/// Where the shell says paths start (the editor reads no environment):
/// the folder the browser opens in when no file is open (`animed edit`'s
/// working directory; `.` until told) and `$HOME`, which a typed `~/`
/// stands for (`None`: `~/` is an ordinary name).
#[derive(Clone, Debug)]
pub struct Places {
    pub start: PathBuf,
    pub home: Option<PathBuf>,
}

impl Default for Places {
    fn default() -> Self {
        Places {
            start: PathBuf::from("."),
            home: None,
        }
    }
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
    /// What it waits to have read (the editor hands it to the shell).
    pub asks: Option<Ask>,
    /// What a typed `~/` stands for (`Places::home`).
    pub home: Option<PathBuf>,
}

impl Browser {
    /// A browser showing `dir`; `home` is what `~/` stands for.
    pub fn new(purpose: Purpose, dir: &Path, home: Option<&Path>) -> Browser {
        let mut b = Browser {
            purpose,
            dir: dir.to_path_buf(),
            entries: Vec::new(),
            input: String::new(),
            highlight: None,
            scroll: 0,
            message: None,
            asks: None,
            home: home.map(Path::to_path_buf),
        };
        b.enter(dir);
        b
    }

    /// Asks for `dir`'s listing; it is shown once the shell answers.
    pub fn enter(&mut self, dir: &Path) {
        self.asks = Some(Ask::Enter(normalize(dir)));
    }

    /// The shell's answer to `ask`: a listing is shown (or Tab completes
    /// in it), a missing file is refused unless saving. Returns the path
    /// to use when the answer settles the choice.
    pub fn found(&mut self, ask: Ask, found: Found) -> Option<PathBuf> {
        match (ask, found) {
            (Ask::Complete(folder), Found::Listing(Ok(entries))) => {
                self.complete_with(&folder, &entries);
            }
            (Ask::Complete(folder), _) => {
                self.message = Some(format!("no folder {}", folder.display()));
            }
            (Ask::Enter(dir) | Ask::Probe(dir), Found::Listing(listing)) => {
                let dir = normalize(&dir);
                match listing {
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
            (Ask::Probe(path), Found::File) => return Some(path),
            (Ask::Probe(path), _) if self.purpose == Purpose::SaveAs => return Some(path),
            (Ask::Probe(path) | Ask::Enter(path), _) => {
                self.message = Some(format!("no file {}", path.display()));
            }
        }
        None
    }

    /// The typed path: a bare name is in the shown folder; anything with a
    /// '/' is a path as a shell would read it (absolute, `~/…`, or relative
    /// to the working directory, which is how the shown folder is written).
    pub fn resolved(&self) -> PathBuf {
        let t = restart_at_root(self.input.trim());
        if t.contains('/') {
            self.expand_home(t)
        } else {
            self.dir.join(t)
        }
    }

    /// Enter / the accept button: a listed folder is entered (`None`), a
    /// listed file is the path to use; anything else is asked of the shell
    /// (`Ask::Probe`: a folder is entered, a file used, a missing file
    /// refused with a message unless saving).
    pub fn accept(&mut self) -> Option<PathBuf> {
        let path = self.resolved();
        let listed = self.entries.iter().find(|e| {
            e.name != ".." && path.parent() == Some(&self.dir) && path.ends_with(&e.name)
        });
        match listed {
            Some(e) if e.is_dir => self.enter(&path),
            Some(_) => return Some(path),
            None => self.asks = Some(Ask::Probe(path)),
        }
        None
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
    /// The shown folder's listing serves; another folder is asked for.
    pub fn complete(&mut self) {
        let folder = self.typed_folder();
        if folder == self.dir {
            let entries = self.entries.clone();
            self.complete_with(&folder, &entries);
        } else {
            self.asks = Some(Ask::Complete(folder));
        }
    }

    /// `~/…` in the home folder the shell gave; anything else as typed.
    fn expand_home(&self, s: &str) -> PathBuf {
        match (s.strip_prefix("~/"), &self.home) {
            (Some(rest), Some(home)) => home.join(rest),
            _ => PathBuf::from(s),
        }
    }

    /// The folder the typed path's last part is in.
    fn typed_folder(&self) -> PathBuf {
        match self.input.rfind('/') {
            Some(i) => self.expand_home(&self.input[..=i]),
            None => self.dir.clone(),
        }
    }

    /// Completes the typed path among `entries`, the listing of `folder`.
    fn complete_with(&mut self, folder: &Path, entries: &[Entry]) {
        let typed = self.input.clone();
        let (head, prefix) = match typed.rfind('/') {
            Some(i) => (typed[..=i].to_string(), typed[i + 1..].to_string()),
            None => (String::new(), typed.clone()),
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
pub(crate) mod tests {
    use super::*;

    /// Answers what the browser asked, as the shell does; the path to
    /// use, if an answer settled one.
    pub(crate) fn settle(b: &mut Browser) -> Option<PathBuf> {
        let mut used = None;
        while let Some(ask) = b.asks.take() {
            let found = crate::editor::shell::look(&ask, b.purpose);
            used = b.found(ask, found).or(used);
        }
        used
    }

    #[test]
    fn a_typed_absolute_path_replaces_the_folder() {
        assert_eq!(restart_at_root("/home/u//tmp/a.wrl"), "/tmp/a.wrl");
        assert_eq!(restart_at_root("/home/u/~/a.wrl"), "~/a.wrl");
        assert_eq!(restart_at_root("/home/u/a.wrl"), "/home/u/a.wrl");
        let dir = std::env::temp_dir();
        let mut b = Browser::new(Purpose::Open, &dir, None);
        assert!(
            b.entries.is_empty(),
            "nothing is read before the shell answers"
        );
        settle(&mut b);
        assert!(b.input.ends_with('/'), "{}", b.input);
        b.type_text("/tmp/x.wrl");
        assert_eq!(b.input, "/tmp/x.wrl");
        assert_eq!(b.resolved(), PathBuf::from("/tmp/x.wrl"));
    }

    #[test]
    fn a_typed_home_is_the_one_the_shell_gave() {
        let mut b = Browser::new(Purpose::Open, Path::new("/d"), Some(Path::new("/u")));
        b.type_text("~/m/a.wrl");
        assert_eq!(b.resolved(), PathBuf::from("/u/m/a.wrl"));
        b.complete();
        assert_eq!(b.asks, Some(Ask::Complete(PathBuf::from("/u/m/"))));
        let mut b = Browser::new(Purpose::Open, Path::new("/d"), None);
        b.type_text("~/a.wrl");
        assert_eq!(b.resolved(), PathBuf::from("~/a.wrl"), "no home given");
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
        let mut b = Browser::new(Purpose::Open, &d, None);
        assert_eq!(b.asks, Some(Ask::Enter(d.clone())));
        settle(&mut b);
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
    fn a_texture_browser_shows_images_not_scenes() {
        let t = Purpose::Texture;
        assert!(t.shows("Brick.PNG") && t.shows("a.jpeg") && t.shows("head.rgb"));
        assert!(!t.shows("walk.wrl") && !t.shows("notes.txt"));
        assert!(!Purpose::Open.shows("brick.png"));
        assert_eq!(t.verb(), "Use");
    }

    #[test]
    fn tab_completes_common_prefix_then_unique() {
        let d = tree("complete");
        let mut b = Browser::new(Purpose::Open, &d, None);
        settle(&mut b);
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
        settle(&mut b);
        // A bare name completes in the shown folder.
        assert_eq!(b.input, format!("{}/models/", d.display()));
        assert!(b.dir.ends_with("models"));
        // Tab in another folder asks the shell for its listing.
        b.input = format!("{}/wa", d.display());
        b.complete();
        assert_eq!(b.asks, Some(Ask::Complete(d.clone())));
        settle(&mut b);
        assert_eq!(b.input, format!("{}/wa", d.display()));
        let _ = std::fs::remove_dir_all(&d);
    }
}
