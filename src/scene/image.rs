//! Images as shared scene resources: decoded once to RGBA8, with a mip chain
//! built once and deterministically, owned by [`crate::scene::Scene::images`]
//! and addressed by [`ImageId`] so that several materials (DEF/USE, one url
//! used twice) share one copy.
//!
//! Every image goes through [`Image::new`], which checks the dimensions
//! against a pixel budget *before* anything is allocated: decoders call
//! [`check_size`] with the header's width and height first, so a file that
//! claims to be 60000×60000 gives a clear error and costs nothing.

use std::fmt;
use std::path::PathBuf;
use std::sync::Arc;

/// Index of an image in [`crate::scene::Scene::images`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ImageId(pub u32);

/// Largest width or height accepted (the biggest texture GL 4.x guarantees).
pub const MAX_IMAGE_SIDE: u32 = 16384;
/// Largest image accepted, in pixels (8192×8192: 256 MiB of RGBA8 plus a
/// third more for its mip chain).
pub const MAX_IMAGE_PIXELS: u64 = 1 << 26;
/// Largest total of base-level pixels one scene may hold over all images.
pub const MAX_SCENE_IMAGE_PIXELS: u64 = 1 << 27;

/// Why an image was refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImageError(pub String);

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ImageError {}

/// Checks a width × height (as read from a file header) against the budget.
/// Call it before allocating or decoding anything.
pub fn check_size(width: u32, height: u32) -> Result<(), ImageError> {
    if width == 0 || height == 0 {
        return Err(ImageError(format!("image is {width}x{height}: empty")));
    }
    if width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
        return Err(ImageError(format!(
            "image is {width}x{height}: larger than the limit of {MAX_IMAGE_SIDE} pixels a side"
        )));
    }
    let px = width as u64 * height as u64;
    if px > MAX_IMAGE_PIXELS {
        return Err(ImageError(format!(
            "image is {width}x{height} ({px} pixels): larger than the budget of {MAX_IMAGE_PIXELS} pixels"
        )));
    }
    Ok(())
}

/// Where an image came from, so writers can reference it again.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ImageSource {
    /// Stored in the file itself (VRML97 PixelTexture, Inventor Texture2
    /// `image`, glTF buffer views): writers write the pixels.
    Inline,
    /// Read from a file: `url` as written in the source file, `path` the
    /// file that was actually read (resolved against the source file).
    File { url: String, path: PathBuf },
}

/// One level of a mip chain: `width × height` RGBA8 pixels, row by row,
/// top row first (the way image files store them).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MipLevel {
    width: u32,
    height: u32,
    pixels: Vec<[u8; 4]>,
}

impl MipLevel {
    pub fn width(&self) -> u32 {
        self.width
    }
    pub fn height(&self) -> u32 {
        self.height
    }
    /// Row-major, top row first.
    pub fn pixels(&self) -> &[[u8; 4]] {
        &self.pixels
    }
    /// The pixel at column `x`, row `y` (top row 0). Panics out of range.
    pub fn texel(&self, x: u32, y: u32) -> [u8; 4] {
        self.pixels[(y * self.width + x) as usize]
    }
}

/// The decoded pixels and their mip chain; shared behind an `Arc` so that
/// cloning a scene (undo snapshots) does not copy pixels.
#[derive(Debug, PartialEq, Eq)]
struct ImageData {
    components: u8,
    levels: Vec<MipLevel>,
    /// Some pixel is not fully opaque (found once here: samplers are made
    /// every frame and ask).
    has_alpha: bool,
}

/// A decoded image: RGBA8 plus the number of components the source had
/// (1 intensity, 2 intensity+alpha, 3 RGB, 4 RGBA: the VRML97 lighting
/// rules depend on it). A 1- or 2-component image is stored with R = G = B.
///
/// Invariants (checked by [`Image::new`]): within the budget, 1..=4
/// components, `levels[0]` is the image, each next level halves each side
/// (rounding down, at least 1) down to 1×1.
#[derive(Clone)]
pub struct Image {
    /// A display name (file name, DEF name, or empty).
    pub name: String,
    pub source: ImageSource,
    data: Arc<ImageData>,
}

impl Image {
    /// Builds an image from `width × height` RGBA8 pixels (row-major, top
    /// row first) and builds its mip chain.
    pub fn new(
        name: impl Into<String>,
        source: ImageSource,
        width: u32,
        height: u32,
        components: u8,
        rgba: Vec<[u8; 4]>,
    ) -> Result<Image, ImageError> {
        check_size(width, height)?;
        if !(1..=4).contains(&components) {
            return Err(ImageError(format!(
                "image has {components} components (1 to 4 allowed)"
            )));
        }
        if rgba.len() as u64 != width as u64 * height as u64 {
            return Err(ImageError(format!(
                "image is {width}x{height} but has {} pixels",
                rgba.len()
            )));
        }
        let mut levels = vec![MipLevel {
            width,
            height,
            pixels: rgba,
        }];
        while let Some(next) = downsample(levels.last().expect("base level")) {
            levels.push(next);
        }
        Ok(Image {
            name: name.into(),
            source,
            data: Arc::new(ImageData {
                components,
                has_alpha: levels[0].pixels.iter().any(|p| p[3] != 255),
                levels,
            }),
        })
    }

    pub fn width(&self) -> u32 {
        self.data.levels[0].width
    }
    pub fn height(&self) -> u32 {
        self.data.levels[0].height
    }
    /// Components of the source image, 1..=4.
    pub fn components(&self) -> u8 {
        self.data.components
    }
    /// The mip chain, base level first, ending with a 1×1 level.
    pub fn levels(&self) -> &[MipLevel] {
        &self.data.levels
    }
    /// The base level.
    pub fn base(&self) -> &MipLevel {
        &self.data.levels[0]
    }
    /// Whether any pixel is not fully opaque.
    pub fn has_alpha(&self) -> bool {
        self.data.has_alpha
    }
    /// Whether both share one decoded copy (clones of one image).
    pub fn same_pixels(&self, other: &Image) -> bool {
        Arc::ptr_eq(&self.data, &other.data)
    }

    /// Pixels of the base level (what counts against the budgets).
    pub fn pixel_count(&self) -> u64 {
        self.width() as u64 * self.height() as u64
    }
}

impl PartialEq for Image {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
            && self.source == other.source
            && (Arc::ptr_eq(&self.data, &other.data) || self.data == other.data)
    }
}

impl fmt::Debug for Image {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Image")
            .field("name", &self.name)
            .field("source", &self.source)
            .field("width", &self.width())
            .field("height", &self.height())
            .field("components", &self.components())
            .field("levels", &self.levels().len())
            .finish()
    }
}

/// The next mip level: each side halves (rounding down, at least 1) and each
/// new texel is the rounded mean of the source box it covers. With an odd
/// side the boxes are 2 or 3 texels wide (`[x·w/w', (x+1)·w/w')`), so every
/// source texel counts and no texel is counted twice. Integer arithmetic
/// only, so the chain is the same everywhere. `None` at 1×1.
fn downsample(src: &MipLevel) -> Option<MipLevel> {
    if src.width == 1 && src.height == 1 {
        return None;
    }
    let (sw, sh) = (src.width as u64, src.height as u64);
    let w = (src.width / 2).max(1);
    let h = (src.height / 2).max(1);
    let mut pixels = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h as u64 {
        let (y0, y1) = (y * sh / h as u64, (y + 1) * sh / h as u64);
        for x in 0..w as u64 {
            let (x0, x1) = (x * sw / w as u64, (x + 1) * sw / w as u64);
            let mut sum = [0u64; 4];
            for sy in y0..y1 {
                let row = &src.pixels[(sy * sw) as usize..((sy + 1) * sw) as usize];
                for p in &row[x0 as usize..x1 as usize] {
                    for c in 0..4 {
                        sum[c] += p[c] as u64;
                    }
                }
            }
            let n = (x1 - x0) * (y1 - y0);
            pixels.push(sum.map(|s| ((s + n / 2) / n) as u8));
        }
    }
    Some(MipLevel {
        width: w,
        height: h,
        pixels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn img(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 4]) -> Result<Image, ImageError> {
        let px = (0..h).flat_map(|y| (0..w).map(move |x| (x, y)));
        let rgba = px.map(|(x, y)| f(x, y)).collect();
        Image::new("t", ImageSource::Inline, w, h, 4, rgba)
    }

    #[test]
    fn mip_chain_halves_to_one_by_one() {
        let i = img(8, 2, |_, _| [10, 20, 30, 255]).unwrap();
        let sizes: Vec<_> = i.levels().iter().map(|l| (l.width(), l.height())).collect();
        assert_eq!(sizes, vec![(8, 2), (4, 1), (2, 1), (1, 1)]);
        assert!(i
            .levels()
            .iter()
            .all(|l| l.pixels().iter().all(|p| *p == [10, 20, 30, 255])));
        assert!(!i.has_alpha());
    }

    #[test]
    fn checker_averages_to_grey() {
        let i = img(4, 4, |x, y| {
            if (x + y) % 2 == 0 {
                [255; 4]
            } else {
                [0, 0, 0, 255]
            }
        })
        .unwrap();
        // 2x2 boxes of a 1-texel checker hold two whites and two blacks:
        // mean 127.5 rounds up to 128.
        assert_eq!(i.levels()[1].texel(0, 0), [128, 128, 128, 255]);
        assert_eq!(i.levels()[2].texel(0, 0), [128, 128, 128, 255]);
    }

    #[test]
    fn odd_sides_count_every_texel_once() {
        // 3x1: one level 1x1 averaging all three texels.
        let i = img(3, 1, |x, _| {
            [[0, 0, 0, 255], [30, 0, 0, 255], [90, 0, 0, 255]][x as usize]
        })
        .unwrap();
        assert_eq!(i.levels().len(), 2);
        assert_eq!(i.levels()[1].texel(0, 0), [40, 0, 0, 255]);
    }

    #[test]
    fn budget_is_checked_before_allocating() {
        let e = check_size(60000, 60000).unwrap_err();
        assert!(e.to_string().contains("60000x60000"), "{e}");
        assert!(check_size(16384, 16384).is_err());
        assert!(check_size(0, 5).is_err());
        assert!(check_size(8192, 8192).is_ok());
        assert!(check_size(1, 1).is_ok());
        // The constructor refuses before looking at the (absent) pixels.
        let e = Image::new("big", ImageSource::Inline, 60000, 60000, 3, Vec::new()).unwrap_err();
        assert!(e.to_string().contains("larger than"), "{e}");
    }

    #[test]
    fn bad_shapes_are_errors() {
        assert!(Image::new("x", ImageSource::Inline, 2, 2, 3, vec![[0; 4]; 3]).is_err());
        assert!(Image::new("x", ImageSource::Inline, 1, 1, 5, vec![[0; 4]]).is_err());
        assert!(Image::new("x", ImageSource::Inline, 1, 1, 0, vec![[0; 4]]).is_err());
    }

    #[test]
    fn clones_share_pixels() {
        let a = img(2, 2, |_, _| [1, 2, 3, 4]).unwrap();
        let b = a.clone();
        assert!(Arc::ptr_eq(&a.data, &b.data));
        assert_eq!(a, b);
        assert!(a.has_alpha());
    }
}
