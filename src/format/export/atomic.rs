//! Replacing a file safely: the new bytes go to a temporary file beside the
//! target, are flushed to disk (so a full disk shows up here, not later),
//! and only then renamed over the target. The target keeps its identity:
//! a symlink is followed (its target is replaced), permissions and, where
//! allowed, ownership are copied, a read-only file is refused unless
//! forced, and a device, FIFO or directory is never replaced.
//!
//! Hard links: the rename gives the path a new inode, so other hard links
//! to the old file keep the old contents (as with most editors' saves).
//!
//! Temporary files are named `.NAME.animed-PID.tmp`; one left by a killed
//! run (its process is gone) is removed by the next save beside it.
//!
//! Concurrent edits: [`EditLock`] (an advisory `flock` on the target's
//! folder) serialises animed's read-modify-write commands (`key`,
//! `convert -o`), and [`Stamp`] tells whether a file changed since it was
//! read, so a save never silently drops another writer's update.

use crate::format::limits::kind_of;
use std::fs::{File, Metadata};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// How a replacement may go.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Replace {
    /// Replace a read-only file too (`--force`).
    pub force: bool,
}

/// The file a write to `path` really replaces: symlinks followed (also a
/// dangling one: its target is created).
pub fn resolve_target(path: &Path) -> io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p)?;
                p = if to.is_absolute() {
                    to
                } else {
                    p.parent().unwrap_or(Path::new("")).join(to)
                };
            }
            _ => return Ok(p),
        }
    }
    Err(io::Error::other(format!(
        "{}: too many levels of symbolic links",
        path.display()
    )))
}

/// Checks that `target` (symlinks resolved) may be replaced; returns its
/// metadata when it exists.
fn check_target(target: &Path, how: Replace) -> io::Result<Option<Metadata>> {
    let m = match std::fs::metadata(target) {
        Ok(m) => m,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e),
    };
    if let Some(kind) = kind_of(&m) {
        return Err(io::Error::other(format!(
            "refusing to replace {}: it is {kind}, not a regular file",
            target.display()
        )));
    }
    if m.permissions().readonly() && !how.force {
        return Err(io::Error::new(
            io::ErrorKind::PermissionDenied,
            format!(
                "refusing to replace {}: the file is read-only (use --force to replace it anyway)",
                target.display()
            ),
        ));
    }
    Ok(Some(m))
}

/// `.NAME.animed-` — the start of our temporary files' names for `name`.
fn temp_prefix(name: &str) -> String {
    format!(".{name}.animed-")
}

/// Removes temporary files beside `target` left by animed processes that
/// no longer run (a killed save). Linux only (it asks /proc); elsewhere
/// they are left, and ignored.
fn clean_stale_temps(dir: &Path, name: &str) {
    if !Path::new("/proc/self").exists() {
        return;
    }
    let prefix = temp_prefix(name);
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let file = e.file_name();
        let file = file.to_string_lossy();
        let Some(pid) = file
            .strip_prefix(&prefix)
            .and_then(|r| r.strip_suffix(".tmp"))
            .and_then(|p| p.parse::<u32>().ok())
        else {
            continue;
        };
        if pid != std::process::id() && !Path::new(&format!("/proc/{pid}")).exists() {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

/// Writes `bytes` over `path` as described in the module doc. On any
/// failure the target is untouched and the temporary file removed.
pub fn write_atomic_with(path: &Path, bytes: &[u8], how: Replace) -> io::Result<()> {
    replace_with(path, how, |f| f.write_all(bytes))
}

/// Like [`write_atomic_with`], the contents written by `fill`.
pub fn replace_with(
    path: &Path,
    how: Replace,
    fill: impl FnOnce(&mut File) -> io::Result<()>,
) -> io::Result<()> {
    let (tmp, mut f) = TempFile::create(path, how)?;
    fill(&mut f)?;
    tmp.commit(f)
}

/// Gives the new file the old one's permissions and (where this process
/// may) owner and group.
fn keep_identity(f: &File, old: &Metadata) {
    let _ = f.set_permissions(old.permissions());
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        // Only root (or the owner, for the group) may; otherwise the new
        // file is the saver's, as with any editor.
        let _ = std::os::unix::fs::fchown(f, Some(old.uid()), Some(old.gid()));
    }
}

/// What a file looked like when it was read: a save compares it with the
/// file as it is now to tell whether someone else changed it meanwhile.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Stamp {
    len: u64,
    modified: Option<std::time::SystemTime>,
    #[cfg(unix)]
    inode: (u64, u64),
}

impl Stamp {
    /// The stamp of `path` now (symlinks followed), `None` if it is absent.
    pub fn of(path: &Path) -> Option<Stamp> {
        let m = std::fs::metadata(path).ok()?;
        Some(Stamp {
            len: m.len(),
            modified: m.modified().ok(),
            #[cfg(unix)]
            inode: {
                use std::os::unix::fs::MetadataExt;
                (m.dev(), m.ino())
            },
        })
    }

    /// An error if `path` is no longer what this stamp saw.
    pub fn check(&self, path: &Path) -> io::Result<()> {
        if Stamp::of(path).as_ref() == Some(self) {
            Ok(())
        } else {
            Err(io::Error::other(format!(
                "{} changed since it was read (another program or animed saved it); \
                 not overwritten: load it again and redo the change",
                path.display()
            )))
        }
    }
}

/// An advisory lock on the folder of a file being edited, held from
/// before it is read until after it is replaced: two animed commands
/// editing files in one folder take turns instead of losing an update.
/// Other programs do not look at it.
#[derive(Debug)]
pub struct EditLock {
    _dir: File,
}

impl EditLock {
    /// Waits for the lock on `path`'s folder (symlinks followed).
    pub fn acquire(path: &Path) -> io::Result<EditLock> {
        let target = resolve_target(path)?;
        let dir = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let f = File::open(&dir)?;
        f.lock()?;
        Ok(EditLock { _dir: f })
    }
}

/// A temporary file beside a target, renamed over it by [`TempFile::commit`]
/// and removed if dropped uncommitted (an error, a panic): what a writer
/// that streams (a GIF, frame by frame) holds until it is done.
#[derive(Debug)]
pub struct TempFile {
    tmp: PathBuf,
    target: PathBuf,
    dir: PathBuf,
    done: bool,
}

impl TempFile {
    /// Checks `path` may be replaced ([`Replace`]) and opens the temporary
    /// file, with the target's permissions and owner if it exists.
    pub fn create(path: &Path, how: Replace) -> io::Result<(TempFile, File)> {
        let target = resolve_target(path)?;
        let old = check_target(&target, how)?;
        let dir = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let name = target
            .file_name()
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "no file name"))?
            .to_string_lossy()
            .into_owned();
        clean_stale_temps(&dir, &name);
        let tmp = dir.join(format!("{}{}.tmp", temp_prefix(&name), std::process::id()));
        let f = File::options().write(true).create_new(true).open(&tmp)?;
        let t = TempFile {
            tmp,
            target,
            dir,
            done: false,
        };
        if let Some(m) = &old {
            keep_identity(&f, m);
        }
        Ok((t, f))
    }

    /// Flushes `f` (this temporary file) to disk and renames it over the
    /// target; on failure the target is untouched and the file removed.
    pub fn commit(mut self, mut f: File) -> io::Result<()> {
        f.flush()?;
        // A full disk can stay hidden until the data is flushed.
        f.sync_all()?;
        drop(f);
        std::fs::rename(&self.tmp, &self.target)?;
        self.done = true;
        // Make the rename itself durable; not all systems can open a
        // directory, and the data is already safe, so this may fail quietly.
        if let Ok(d) = File::open(&self.dir) {
            let _ = d.sync_all();
        }
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.done {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}
