//! Writing one frame as PNG, atomically.

use crate::render::Frame;
use std::path::{Path, PathBuf};

/// Writes `frame` as an RGBA PNG beside `path` and renames it into place, so
/// a reader (or a resumed job) never sees a half-written frame. Uses the
/// same encoder call as `animed render -o x.png`, so a frame of a sequence
/// has the same bytes as a single-frame render at the same time.
pub fn save_atomic(frame: &Frame, path: &Path) -> Result<(), String> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".partial");
    let tmp = PathBuf::from(tmp);
    image::save_buffer_with_format(
        &tmp,
        &frame.to_rgba8(),
        frame.width,
        frame.height,
        image::ExtendedColorType::Rgba8,
        image::ImageFormat::Png,
    )
    .map_err(|e| format!("{}: {e}", path.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("{}: {e}", path.display())
    })
}
