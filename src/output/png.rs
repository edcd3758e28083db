//! Writing one frame as PNG, atomically.

use crate::format::export::atomic::{replace_with, Replace};
use crate::render::Frame;
use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};
use std::io::Write as _;
use std::path::Path;

/// Writes `frame` as an RGBA PNG beside `path`, flushes it to disk and
/// renames it into place (`format::export::atomic`), so a reader (or a
/// resumed job) never sees a half-written frame and a failed write (a full
/// disk) leaves the old file as it was, with no temporary file behind. Uses
/// the same encoder as `animed render -o x.png`, so a frame of a sequence
/// has the same bytes as a single-frame render at the same time.
pub fn save_atomic(frame: &Frame, path: &Path) -> Result<(), String> {
    save_atomic_with(frame, path, Replace::default())
}

/// [`save_atomic`], `how` saying whether a read-only file may be replaced.
pub fn save_atomic_with(frame: &Frame, path: &Path, how: Replace) -> Result<(), String> {
    check_png_name(path)?;
    let rgba = frame.to_rgba8();
    replace_with(path, how, |f| {
        let mut w = std::io::BufWriter::new(f);
        PngEncoder::new(&mut w)
            .write_image(&rgba, frame.width, frame.height, ExtendedColorType::Rgba8)
            .map_err(std::io::Error::other)?;
        w.flush()
    })
    .map_err(|e| format!("{}: {e}", path.display()))
}

/// A PNG goes only into a `.png` file: anything else would be PNG bytes
/// under another format's name.
pub fn check_png_name(path: &Path) -> Result<(), String> {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    match ext.as_deref() {
        Some("png") => Ok(()),
        Some(other) => Err(format!(
            "{}: animed writes PNG (.png), or GIF (.gif) for a --range; not .{other}",
            path.display()
        )),
        None => Err(format!(
            "{}: give the output a .png (or, for a --range, .gif) extension",
            path.display()
        )),
    }
}
