//! Saving a scene: pick the writer by extension, then write atomically
//! (a temporary file beside the target, flushed to disk, then renamed over
//! it), so a crash never leaves a half-written scene behind.
//!
//! `.wrl` → VRML97, `.wrl.gz` / `.wrz` → gzip'd VRML97, `.iv` → Inventor,
//! `.x3dv` / `.x3d` → X3D classic / XML (`.x3dvz`, `.x3dz`, `.gz`: gzip'd).

use super::atomic::Replace;
use super::options::{WriteOptions, WriteReport};
use crate::format::{gltf, iv, vrml97, x3d};
use crate::scene::Scene;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// A file format the writers produce.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    Vrml97,
    Vrml97Gz,
    Inventor,
    /// glTF 2.0 JSON with the buffer embedded as a data: URI.
    Gltf,
    /// Binary glTF.
    Glb,
    /// X3D 4.0, classic encoding (`.x3dv`), and gzipped (`.x3dvz`, `.x3dv.gz`).
    X3dClassic,
    X3dClassicGz,
    /// X3D 4.0, XML encoding (`.x3d`), and gzipped (`.x3dz`, `.x3d.gz`).
    X3dXml,
    X3dXmlGz,
}

impl OutputFormat {
    /// By file name: `.wrl`, `.wrl.gz`/`.wrz`, `.iv`, `.gltf`, `.glb`,
    /// `.x3dv`, `.x3dvz`/`.x3dv.gz`, `.x3d`, `.x3dz`/`.x3d.gz`
    /// (case-insensitive).
    pub fn from_path(path: &Path) -> Option<OutputFormat> {
        let name = path.file_name()?.to_string_lossy().to_ascii_lowercase();
        if name.ends_with(".wrl.gz") || name.ends_with(".wrz") {
            Some(OutputFormat::Vrml97Gz)
        } else if name.ends_with(".wrl") {
            Some(OutputFormat::Vrml97)
        } else if name.ends_with(".iv") {
            Some(OutputFormat::Inventor)
        } else if name.ends_with(".gltf") {
            Some(OutputFormat::Gltf)
        } else if name.ends_with(".glb") {
            Some(OutputFormat::Glb)
        } else if name.ends_with(".x3dv") {
            Some(OutputFormat::X3dClassic)
        } else if name.ends_with(".x3dvz") || name.ends_with(".x3dv.gz") {
            Some(OutputFormat::X3dClassicGz)
        } else if name.ends_with(".x3d") {
            Some(OutputFormat::X3dXml)
        } else if name.ends_with(".x3dz") || name.ends_with(".x3d.gz") {
            Some(OutputFormat::X3dXmlGz)
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
    /// The written file would nest deeper than animed's reader reads:
    /// refused rather than written unreadable.
    TooDeep {
        path: PathBuf,
        depth: usize,
        max: u64,
    },
}

impl std::fmt::Display for SaveError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SaveError::UnknownExtension(p) => write!(
                f,
                "{}: cannot tell the format from the name (use .wrl, .wrl.gz, .iv, .gltf, .glb, .x3dv or .x3d)",
                p.display()
            ),
            SaveError::Io(p, e) => write!(f, "{}: {e}", p.display()),
            SaveError::TooDeep { path, depth, max } => write!(
                f,
                "{}: not written: the file would nest {depth} levels deep and animed reads \
                 at most {max} (raise it with --max-depth N or ANIMED_MAX_DEPTH=N, up to {}, \
                 when writing and when reading)",
                path.display(),
                crate::format::limits::DEPTH_CEILING
            ),
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
    if let Some(binary) = gltf_bytes(scene, format, opts) {
        return binary;
    }
    let (text, report) = to_text(scene, format, opts);
    (encode(text, format), report)
}

/// glTF output (never nested text, so never depth-checked), or `None` for
/// the text formats.
fn gltf_bytes(
    scene: &Scene,
    format: OutputFormat,
    opts: &WriteOptions,
) -> Option<(Vec<u8>, WriteReport)> {
    match format {
        OutputFormat::Gltf => Some(gltf::to_bytes(scene, opts, false)),
        OutputFormat::Glb => Some(gltf::to_bytes(scene, opts, true)),
        _ => None,
    }
}

/// The text of `scene` in a text `format` (before any gzip). The text
/// formats hold one clip; the others are named in a warning.
fn to_text(scene: &Scene, format: OutputFormat, opts: &WriteOptions) -> (String, WriteReport) {
    let (text, mut report) = match format {
        OutputFormat::Inventor => iv::write::write(scene, opts),
        OutputFormat::X3dClassic | OutputFormat::X3dClassicGz => x3d::write::classic(scene, opts),
        OutputFormat::X3dXml | OutputFormat::X3dXmlGz => x3d::write::xml(scene, opts),
        _ => vrml97::write::write(scene, opts),
    };
    if scene.clips.len() > 1 {
        report.warnings.push(format!(
            "only the playing animation `{}` is written; {} other clip(s) are left out \
             (.gltf/.glb keep every clip)",
            scene.clips.active_name().unwrap_or(""),
            scene.clips.len() - 1
        ));
    }
    (text, report)
}

fn encode(text: String, format: OutputFormat) -> Vec<u8> {
    match format {
        OutputFormat::Vrml97Gz | OutputFormat::X3dClassicGz | OutputFormat::X3dXmlGz => {
            gzip(text.as_bytes())
        }
        _ => text.into_bytes(),
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
    save_with(scene, path, opts, Replace::default())
}

/// [`save`], `how` saying whether a read-only file may be replaced.
pub fn save_with(
    scene: &Scene,
    path: &Path,
    opts: &WriteOptions,
    how: Replace,
) -> Result<WriteReport, SaveError> {
    let format =
        OutputFormat::from_path(path).ok_or_else(|| SaveError::UnknownExtension(path.into()))?;
    let scene = super::textures::rebase_urls(scene, path);
    if let Some((bytes, report)) = gltf_bytes(&scene, format, opts) {
        super::atomic::write_atomic_with(path, &bytes, how)
            .map_err(|e| SaveError::Io(path.into(), e))?;
        return Ok(report);
    }
    let (text, report) = to_text(&scene, format, opts);
    // Never write what our own reader would refuse (XML nests as its
    // classic twin does).
    let depth = match format {
        OutputFormat::X3dXml | OutputFormat::X3dXmlGz => {
            super::text::nesting(&x3d::write::classic(&scene, opts).0)
        }
        _ => super::text::nesting(&text),
    };
    let max = crate::format::limits::current().max_depth;
    if depth as u64 > max {
        return Err(SaveError::TooDeep {
            path: path.into(),
            depth,
            max,
        });
    }
    let bytes = encode(text, format);
    super::atomic::write_atomic_with(path, &bytes, how)
        .map_err(|e| SaveError::Io(path.into(), e))?;
    Ok(report)
}

/// Writes `bytes` over `path` atomically, keeping the file's identity
/// (see [`atomic`](super::atomic)): symlinks followed, permissions kept,
/// devices and read-only files refused. On failure `path` is untouched and
/// no temporary file is left.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    super::atomic::write_atomic_with(path, bytes, Replace::default())
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
