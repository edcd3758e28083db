//! Image files → [`Image`]: SGI through `format::sgi_image`, everything
//! else (PNG, JPEG, GIF first frame, BMP) through the `image` crate.
//!
//! The size is checked from the header before decoding: a file claiming
//! 60000×60000 costs a header read, not an allocation.

use crate::format::sgi_image;
use crate::scene::{check_image_size, Image, ImageSource, MAX_IMAGE_PIXELS};
use std::io::{Cursor, Read};
use std::path::Path;

/// Largest image file read from disk.
pub const MAX_IMAGE_FILE_BYTES: u64 = 256 << 20;

/// Reads at most [`MAX_IMAGE_FILE_BYTES`] of `path`.
pub fn read_file(path: &Path) -> Result<Vec<u8>, String> {
    let f = std::fs::File::open(path).map_err(|e| match e.kind() {
        std::io::ErrorKind::NotFound => "file not found".to_string(),
        _ => e.to_string(),
    })?;
    let len = f.metadata().map_err(|e| e.to_string())?.len();
    if len > MAX_IMAGE_FILE_BYTES {
        return Err(format!(
            "file is {len} bytes, more than the {MAX_IMAGE_FILE_BYTES} allowed for an image"
        ));
    }
    let mut bytes = Vec::with_capacity(len as usize);
    f.take(MAX_IMAGE_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    if bytes.len() as u64 > MAX_IMAGE_FILE_BYTES {
        return Err(format!("file grew past {MAX_IMAGE_FILE_BYTES} bytes"));
    }
    Ok(bytes)
}

/// Decodes an image file's bytes.
pub fn decode(bytes: &[u8], name: &str, source: ImageSource) -> Result<Image, String> {
    let (w, h, comps, rgba) = if sgi_image::is_sgi(bytes) {
        let img = sgi_image::decode(bytes, MAX_IMAGE_PIXELS)?;
        let px = img
            .rgba
            .chunks_exact(4)
            .map(|c| [c[0], c[1], c[2], c[3]])
            .collect();
        (img.width, img.height, img.components, px)
    } else {
        decode_common(bytes)?
    };
    Image::new(name, source, w, h, comps, rgba).map_err(|e| e.to_string())
}

/// Width, height, components and RGBA8 pixels (top row first).
type Pixels = (u32, u32, u8, Vec<[u8; 4]>);

fn decode_common(bytes: &[u8]) -> Result<Pixels, String> {
    let reader = || {
        image::ImageReader::new(Cursor::new(bytes))
            .with_guessed_format()
            .map_err(|e| e.to_string())
    };
    let r = reader()?;
    let Some(format) = r.format() else {
        return Err("not a PNG, JPEG, GIF, BMP or SGI image".into());
    };
    let (w, h) = r.into_dimensions().map_err(|e| e.to_string())?;
    check_image_size(w, h).map_err(|e| e.to_string())?;
    let mut r = reader()?;
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(w);
    limits.max_image_height = Some(h);
    limits.max_alloc = Some(MAX_IMAGE_PIXELS * 16);
    r.limits(limits);
    let img = r.decode().map_err(|e| e.to_string())?;
    let mut comps = img.color().channel_count();
    let rgba: Vec<[u8; 4]> = img.to_rgba8().pixels().map(|p| p.0).collect();
    // GIF decodes to RGBA always; without a transparent pixel it is RGB.
    if format == image::ImageFormat::Gif && comps == 4 && rgba.iter().all(|p| p[3] == 255) {
        comps = 3;
    }
    Ok((w, h, comps, rgba))
}
