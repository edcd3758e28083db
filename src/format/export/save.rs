//! Saving a scene: pick the writer by extension, then write atomically
//! (a temporary file beside the target, flushed to disk, then renamed over
//! it), so a crash never leaves a half-written scene behind.
//!
//! `.wrl` → VRML97, `.wrl.gz` / `.wrz` → gzip'd VRML97, `.iv` → Inventor.

use super::options::{WriteOptions, WriteReport};
use crate::format::{iv, vrml97};
use crate::scene::Scene;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// A file format the writers produce.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    Vrml97,
    Vrml97Gz,
    Inventor,
}

impl OutputFormat {
    /// By file name: `.wrl`, `.wrl.gz`/`.wrz`, `.iv` (case-insensitive).
    pub fn from_path(path: &Path) -> Option<OutputFormat> {
        let name = path.file_name()?.to_string_lossy().to_ascii_lowercase();
        if name.ends_with(".wrl.gz") || name.ends_with(".wrz") {
            Some(OutputFormat::Vrml97Gz)
        } else if name.ends_with(".wrl") {
            Some(OutputFormat::Vrml97)
        } else if name.ends_with(".iv") {
            Some(OutputFormat::Inventor)
        } else {
            None
        }
    }
}

/// Why a save failed.
#[derive(Debug)]
pub enum SaveError {
    UnknownExtension(PathBuf),
    Io(PathBuf, std::io::Error),
}

impl std::fmt::Display for SaveError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SaveError::UnknownExtension(p) => write!(
                f,
                "{}: cannot tell the format from the name (use .wrl, .wrl.gz or .iv)",
                p.display()
            ),
            SaveError::Io(p, e) => write!(f, "{}: {e}", p.display()),
        }
    }
}

impl std::error::Error for SaveError {}

/// The bytes of `scene` in `format`.
pub fn to_bytes(
    scene: &Scene,
    format: OutputFormat,
    opts: &WriteOptions,
) -> (Vec<u8>, WriteReport) {
    match format {
        OutputFormat::Vrml97 => {
            let (text, report) = vrml97::write::write(scene, opts);
            (text.into_bytes(), report)
        }
        OutputFormat::Vrml97Gz => {
            let (text, report) = vrml97::write::write(scene, opts);
            (gzip(text.as_bytes()), report)
        }
        OutputFormat::Inventor => {
            let (text, report) = iv::write::write(scene, opts);
            (text.into_bytes(), report)
        }
    }
}

/// Gzip with a fixed header (no name, time 0), so output is reproducible.
pub fn gzip(data: &[u8]) -> Vec<u8> {
    let mut enc = flate2::GzBuilder::new().mtime(0).write(
        Vec::with_capacity(data.len() / 4 + 64),
        flate2::Compression::best(),
    );
    // Writing into a Vec cannot fail.
    let _ = enc.write_all(data);
    enc.finish().unwrap_or_default()
}

/// Saves `scene` to `path`, the format chosen by its extension. Texture
/// files are referenced by their path relative to `path`'s folder.
pub fn save(scene: &Scene, path: &Path, opts: &WriteOptions) -> Result<WriteReport, SaveError> {
    let format =
        OutputFormat::from_path(path).ok_or_else(|| SaveError::UnknownExtension(path.into()))?;
    let scene = super::textures::rebase_urls(scene, path);
    let (bytes, report) = to_bytes(&scene, format, opts);
    write_atomic(path, &bytes).map_err(|e| SaveError::Io(path.into(), e))?;
    Ok(report)
}

/// Writes `bytes` to a temporary file beside `path`, syncs it, and renames
/// it over `path`. On failure the temporary file is removed and `path` is
/// untouched.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "no file name"))?;
    let tmp = dir.join(format!(
        ".{}.animed-{}.tmp",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        drop(f);
        std::fs::rename(&tmp, path)?;
        // Make the rename itself durable; not all systems can open a
        // directory, and the data is already safe, so this may fail quietly.
        if let Ok(d) = std::fs::File::open(&dir) {
            let _ = d.sync_all();
        }
        Ok(())
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_by_extension() {
        let f = |s: &str| OutputFormat::from_path(Path::new(s));
        assert_eq!(f("a.wrl"), Some(OutputFormat::Vrml97));
        assert_eq!(f("dir/A.WRL.GZ"), Some(OutputFormat::Vrml97Gz));
        assert_eq!(f("a.wrz"), Some(OutputFormat::Vrml97Gz));
        assert_eq!(f("a.iv"), Some(OutputFormat::Inventor));
        assert_eq!(f("a.obj"), None);
    }

    #[test]
    fn atomic_write_replaces_and_leaves_no_temp() {
        let dir = std::env::temp_dir().join(format!("animed-save-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("x.wrl");
        std::fs::write(&p, b"old").unwrap();
        write_atomic(&p, b"new contents").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"new contents");
        let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
        assert_eq!(left.len(), 1);
        // A directory that does not exist: error, nothing created.
        assert!(write_atomic(&dir.join("nope/x.wrl"), b"x").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn gzip_is_reproducible_and_decodes() {
        use std::io::Read as _;
        let a = gzip(b"#VRML V2.0 utf8\n");
        assert_eq!(a, gzip(b"#VRML V2.0 utf8\n"));
        let mut s = String::new();
        flate2::read::GzDecoder::new(&a[..])
            .read_to_string(&mut s)
            .unwrap();
        assert_eq!(s, "#VRML V2.0 utf8\n");
    }
}
