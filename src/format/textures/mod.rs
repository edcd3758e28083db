//! Texture images for the readers: url lists resolved against the file that
//! names them (first one that loads wins), each file read and decoded once
//! per load, inline SFImage pixels, and one wording for what went wrong.
//! A texture that cannot be read is a warning, never an error for the file:
//! the shape is then drawn untextured.

pub mod decode;

use crate::scene::{check_image_size, Image, ImageId, ImageSource, Scene};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// The warning text for an image that could not be used.
pub fn cannot_read(url: &str, reason: &str) -> String {
    format!("cannot read texture '{url}': {reason}")
}

/// Loads texture files for one scene file, sharing each decoded image.
pub struct Loader {
    base: PathBuf,
    cache: HashMap<PathBuf, Result<ImageId, String>>,
}

impl Loader {
    /// `base` is the file whose relative urls are resolved.
    pub fn new(base: &Path) -> Loader {
        Loader {
            base: base.to_path_buf(),
            cache: HashMap::new(),
        }
    }

    /// Resolves relative urls against `base` from now on (an Inventor
    /// `File`'s nodes name their textures relative to their own file);
    /// returns the previous base.
    pub fn set_base(&mut self, base: &Path) -> PathBuf {
        std::mem::replace(&mut self.base, base.to_path_buf())
    }

    /// Tries `urls` in order and returns the first that loads. When none
    /// does, returns one warning text per url.
    pub fn load(&mut self, scene: &mut Scene, urls: &[String]) -> Result<ImageId, Vec<String>> {
        let mut errs = Vec::new();
        for u in urls {
            match self.load_one(scene, u) {
                Ok(id) => return Ok(id),
                Err(e) => errs.push(cannot_read(u, &e)),
            }
        }
        if errs.is_empty() {
            errs.push("texture has no url".to_string());
        }
        Err(errs)
    }

    /// Loads one url (relative to the base file) or says why not.
    pub fn load_one(&mut self, scene: &mut Scene, url: &str) -> Result<ImageId, String> {
        let path = self.resolve(url)?;
        if let Some(r) = self.cache.get(&path) {
            return r.clone();
        }
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let source = ImageSource::File {
            url: url.to_string(),
            path: path.clone(),
        };
        let r = decode::read_file(&path)
            .and_then(|bytes| decode::decode(&bytes, &name, source))
            .and_then(|img| scene.add_image(img).map_err(|e| e.to_string()));
        self.cache.insert(path, r.clone());
        r
    }

    /// Decodes one url without adding it to a scene (for images that are
    /// combined with another before use, like an MTL `map_d`).
    pub fn read(&self, url: &str) -> Result<Image, String> {
        let path = self.resolve(url)?;
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let source = ImageSource::File {
            url: url.to_string(),
            path: path.clone(),
        };
        decode::read_file(&path).and_then(|bytes| decode::decode(&bytes, &name, source))
    }

    fn resolve(&self, url: &str) -> Result<PathBuf, String> {
        let u = url.trim();
        let u = u.strip_prefix("file://").unwrap_or(u);
        if u.is_empty() {
            return Err("empty url".into());
        }
        if u.contains("://") || u.starts_with("data:") {
            return Err("only local files are read".into());
        }
        let p = Path::new(u);
        Ok(if p.is_absolute() {
            p.to_path_buf()
        } else {
            self.base.parent().unwrap_or(Path::new("")).join(p)
        })
    }
}

/// An inline SFImage (VRML97 PixelTexture `image`, Inventor Texture2
/// `image`): `width height components` then one integer per pixel with the
/// components packed high byte first (0xRRGGBB, 0xIIAA …), rows bottom-up.
/// `Ok(None)` for the empty image `0 0 0`.
pub fn sf_image(nums: &[f64], name: &str) -> Result<Option<Image>, String> {
    let [w, h, c] = match nums {
        [w, h, c, ..] => [*w, *h, *c],
        _ => return Ok(None),
    };
    let ok = |v: f64| v.fract() == 0.0 && v >= 0.0 && v <= u32::MAX as f64;
    if !ok(w) || !ok(h) || !ok(c) {
        return Err(format!("image size {w} {h} {c} is not three whole numbers"));
    }
    let (w, h, c) = (w as u32, h as u32, c as u32);
    if w == 0 || h == 0 {
        return Ok(None);
    }
    if !(1..=4).contains(&c) {
        return Err(format!("image has {c} components (1 to 4 allowed)"));
    }
    check_image_size(w, h).map_err(|e| e.to_string())?;
    let n = w as usize * h as usize;
    let px = &nums[3..];
    if px.len() < n {
        return Err(format!("image is {w}x{h} but has only {} pixels", px.len()));
    }
    let mut rgba = vec![[0u8; 4]; n];
    for y in 0..h as usize {
        // File rows are bottom-up; ours are top row first.
        let dst = (h as usize - 1 - y) * w as usize;
        for x in 0..w as usize {
            let v = px[y * w as usize + x].clamp(0.0, u32::MAX as f64) as u32;
            let b = |k: u32| (v >> (8 * k)) as u8;
            rgba[dst + x] = match c {
                1 => [b(0), b(0), b(0), 255],
                2 => [b(1), b(1), b(1), b(0)],
                3 => [b(2), b(1), b(0), 255],
                _ => [b(3), b(2), b(1), b(0)],
            };
        }
    }
    Image::new(name, ImageSource::Inline, w, h, c as u8, rgba)
        .map(Some)
        .map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sf_image_unpacks_components_and_flips_rows() {
        // 1x2 RGB: bottom red, top blue.
        let i = sf_image(&[1.0, 2.0, 3.0, 0xFF0000 as f64, 0x0000FF as f64], "p")
            .unwrap()
            .unwrap();
        assert_eq!(i.components(), 3);
        assert_eq!(i.base().pixels(), &[[0, 0, 255, 255], [255, 0, 0, 255]]);
        let i = sf_image(&[1.0, 1.0, 2.0, 0x8040 as f64], "p")
            .unwrap()
            .unwrap();
        assert_eq!(i.base().texel(0, 0), [0x80, 0x80, 0x80, 0x40]);
        let i = sf_image(&[1.0, 1.0, 4.0, 0x11223344u32 as f64], "p")
            .unwrap()
            .unwrap();
        assert_eq!(i.base().texel(0, 0), [0x11, 0x22, 0x33, 0x44]);
    }

    #[test]
    fn sf_image_bad_input() {
        assert_eq!(sf_image(&[0.0, 0.0, 0.0], "p"), Ok(None));
        assert_eq!(sf_image(&[], "p"), Ok(None));
        assert!(sf_image(&[2.0, 2.0, 3.0, 1.0], "p")
            .unwrap_err()
            .contains("only 1"));
        assert!(sf_image(&[60000.0, 60000.0, 3.0], "p")
            .unwrap_err()
            .contains("60000x60000"));
        assert!(sf_image(&[1.0, 1.0, 7.0, 1.0], "p").is_err());
        assert!(sf_image(&[1.5, 1.0, 3.0, 1.0], "p").is_err());
    }

    /// A PNG signature, an IHDR chunk claiming `w × h` and an empty IDAT
    /// (valid CRCs): what a huge PNG's header looks like.
    fn png_header(w: u32, h: u32) -> Vec<u8> {
        let mut f = b"\x89PNG\r\n\x1a\n".to_vec();
        let mut ihdr = w.to_be_bytes().to_vec();
        ihdr.extend(h.to_be_bytes());
        ihdr.extend([8, 2, 0, 0, 0]);
        for (kind, data) in [(&b"IHDR"[..], &ihdr[..]), (b"IDAT", &[])] {
            let mut crc = flate2::Crc::new();
            crc.update(kind);
            crc.update(data);
            f.extend((data.len() as u32).to_be_bytes());
            f.extend(kind);
            f.extend(data);
            f.extend(crc.sum().to_be_bytes());
        }
        f
    }

    #[test]
    fn bad_image_files_are_reasons_not_panics() {
        let src = || ImageSource::Inline;
        let d = |b: &[u8]| decode::decode(b, "x", src()).map(|i| (i.width(), i.height()));
        // Sizes claimed by the header are refused before decoding.
        let e = d(&png_header(16384, 16384)).unwrap_err();
        assert!(e.contains("16384x16384") && e.contains("budget"), "{e}");
        let e = d(&png_header(60000, 60000)).unwrap_err();
        assert!(e.contains("60000x60000"), "{e}");
        // A header with no pixel data after it.
        assert!(d(&png_header(4, 4)).is_err());
        // Not an image at all.
        let e = d(b"hello, world").unwrap_err();
        assert!(e.contains("not a PNG"), "{e}");
        assert!(d(&[]).is_err());
        // Truncated PNG and JPEG.
        let img =
            image::RgbImage::from_fn(16, 16, |x, y| image::Rgb([x as u8 * 16, y as u8 * 16, 7]));
        let mut png = Vec::new();
        img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .unwrap();
        assert_eq!(d(&png), Ok((16, 16)));
        assert!(d(&png[..png.len() / 2]).is_err());
        let mut jpg = Vec::new();
        img.write_to(
            &mut std::io::Cursor::new(&mut jpg),
            image::ImageFormat::Jpeg,
        )
        .unwrap();
        assert_eq!(d(&jpg), Ok((16, 16)));
        assert!(d(&jpg[..jpg.len() / 3]).is_err());
        // 1x1 works and has a one-level chain.
        let one = image::GrayImage::from_pixel(1, 1, image::Luma([9]));
        let mut b = Vec::new();
        one.write_to(&mut std::io::Cursor::new(&mut b), image::ImageFormat::Png)
            .unwrap();
        let i = decode::decode(&b, "one", src()).unwrap();
        assert_eq!((i.components(), i.levels().len()), (1, 1));
        // BMP and GIF decode; an opaque GIF counts as RGB.
        for f in [image::ImageFormat::Bmp, image::ImageFormat::Gif] {
            let mut b = Vec::new();
            image::DynamicImage::ImageRgb8(img.clone())
                .to_rgba8()
                .write_to(&mut std::io::Cursor::new(&mut b), f)
                .unwrap();
            let i = decode::decode(&b, "x", src()).unwrap();
            assert_eq!(i.width(), 16);
            if f == image::ImageFormat::Gif {
                assert_eq!(i.components(), 3);
            }
        }
    }

    #[test]
    fn urls_fall_back_in_order_and_fail_with_reasons() {
        let dir = std::env::temp_dir().join(format!("animed-tex-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let img = image::RgbImage::from_pixel(2, 2, image::Rgb([10, 20, 30]));
        img.save(dir.join("third.png")).unwrap();
        std::fs::write(dir.join("broken.png"), b"\x89PNG\r\n\x1a\nxx").unwrap();
        let mut scene = Scene::new();
        let mut l = Loader::new(&dir.join("scene.wrl"));
        let urls: Vec<String> = ["missing.png", "broken.png", "third.png"]
            .map(String::from)
            .to_vec();
        let id = l.load(&mut scene, &urls).unwrap();
        assert_eq!(scene.images[id.0 as usize].components(), 3);
        // Loaded once, shared after.
        assert_eq!(l.load(&mut scene, &urls[2..]).unwrap(), id);
        assert_eq!(scene.images.len(), 1);
        let errs = l.load(&mut scene, &urls[..2]).unwrap_err();
        assert_eq!(errs.len(), 2);
        assert!(
            errs[0].starts_with("cannot read texture 'missing.png': "),
            "{errs:?}"
        );
        assert!(
            errs[1].starts_with("cannot read texture 'broken.png': "),
            "{errs:?}"
        );
        let e = l
            .load_one(&mut scene, "http://example.com/a.png")
            .unwrap_err();
        assert!(e.contains("local"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
