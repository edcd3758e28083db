//! [`Image`]: the 8-bit RGB picture the front door renders, compares and
//! writes. A plain owned buffer, so users need neither our `Frame` (with its
//! depth and id buffers) nor a particular version of the `image` crate.

use crate::error::{Error, ErrorKind, Result};
use std::path::{Path, PathBuf};

/// An 8-bit RGB picture, row-major, top row first, 3 bytes per pixel.
///
/// ```
/// let mut img = animed::Image::new(4, 2, [10, 20, 30]);
/// img.set_pixel(3, 1, [255, 0, 0]);
/// assert_eq!(img.pixel(3, 1), [255, 0, 0]);
/// assert_eq!(img.pixel(0, 0), [10, 20, 30]);
/// assert_eq!(img.as_rgb().len(), 4 * 2 * 3);
/// ```
#[derive(Clone, PartialEq, Eq)]
pub struct Image {
    width: u32,
    height: u32,
    rgb: Vec<u8>,
}

impl std::fmt::Debug for Image {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Image({}x{})", self.width, self.height)
    }
}

impl Image {
    /// A `width`×`height` picture filled with one colour.
    pub fn new(width: u32, height: u32, fill: [u8; 3]) -> Image {
        let n = width as usize * height as usize;
        let mut rgb = Vec::with_capacity(n * 3);
        for _ in 0..n {
            rgb.extend_from_slice(&fill);
        }
        Image { width, height, rgb }
    }

    /// Wraps RGB bytes (`width * height * 3` of them).
    pub fn from_rgb(width: u32, height: u32, rgb: Vec<u8>) -> Result<Image> {
        if rgb.len() as u64 != width as u64 * height as u64 * 3 {
            return Err(Error::new(
                ErrorKind::Invalid,
                format!(
                    "{} bytes is not a {width}x{height} RGB picture ({} bytes)",
                    rgb.len(),
                    width as u64 * height as u64 * 3
                ),
            ));
        }
        Ok(Image { width, height, rgb })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The RGB bytes, row-major, top row first.
    pub fn as_rgb(&self) -> &[u8] {
        &self.rgb
    }

    /// The pixel at column `x`, row `y` (panics outside the picture, like
    /// slice indexing).
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside"
        );
        let i = (y as usize * self.width as usize + x as usize) * 3;
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// Sets the pixel at column `x`, row `y` (panics outside the picture).
    pub fn set_pixel(&mut self, x: u32, y: u32, rgb: [u8; 3]) {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside"
        );
        let i = (y as usize * self.width as usize + x as usize) * 3;
        self.rgb[i..i + 3].copy_from_slice(&rgb);
    }

    /// Reads a PNG (any colour type; alpha is dropped, grey is expanded).
    pub fn load_png(path: impl AsRef<Path>) -> Result<Image> {
        let path = path.as_ref();
        let img = image::open(path).map_err(|e| match e {
            image::ImageError::IoError(io) => Error::in_file(ErrorKind::Io, path, io.to_string()),
            other => Error::in_file(ErrorKind::Image, path, other.to_string()),
        })?;
        let rgb = img.to_rgb8();
        Ok(Image {
            width: rgb.width(),
            height: rgb.height(),
            rgb: rgb.into_raw(),
        })
    }

    /// Writes a PNG, atomically (beside `path`, then renamed), creating
    /// missing folders. The bytes are those `animed render -o` writes for
    /// the same picture (8-bit RGBA, alpha 255), so a golden written by
    /// either tool is identical.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<()> {
        let path = path.as_ref();
        let io = |e: std::io::Error| Error::in_file(ErrorKind::Io, path, e.to_string());
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(io)?;
        }
        let mut rgba = Vec::with_capacity(self.rgb.len() / 3 * 4);
        for p in self.rgb.chunks_exact(3) {
            rgba.extend_from_slice(&[p[0], p[1], p[2], 255]);
        }
        let mut tmp = path.as_os_str().to_owned();
        tmp.push(".partial");
        let tmp = PathBuf::from(tmp);
        image::save_buffer_with_format(
            &tmp,
            &rgba,
            self.width,
            self.height,
            image::ExtendedColorType::Rgba8,
            image::ImageFormat::Png,
        )
        .map_err(|e| Error::in_file(ErrorKind::Image, path, e.to_string()))?;
        std::fs::rename(&tmp, path).map_err(|e| {
            let _ = std::fs::remove_file(&tmp);
            io(e)
        })
    }
}

impl From<&crate::render::Frame> for Image {
    fn from(frame: &crate::render::Frame) -> Image {
        let mut rgb = Vec::with_capacity(frame.color.len() * 3);
        for &c in &frame.color {
            rgb.extend_from_slice(&[(c >> 16) as u8, (c >> 8) as u8, c as u8]);
        }
        Image {
            width: frame.width,
            height: frame.height,
            rgb,
        }
    }
}
