//! The texture row's thumbnail: a few dozen pixels that tell a user which
//! image a material carries. Sampled nearest from the smallest mip level
//! that still has a texel per thumbnail pixel, so it reads the image's
//! average colours (the mip chain's box filter) instead of aliasing
//! single texels of a big image, and costs a handful of lookups.

use crate::scene::{Image, MipLevel};

/// The smallest level of `img` at least `w`×`h` (the base level when
/// even that is smaller).
pub fn level_for(img: &Image, w: u32, h: u32) -> &MipLevel {
    img.levels()
        .iter()
        .rev()
        .find(|l| l.width() >= w && l.height() >= h)
        .unwrap_or_else(|| img.base())
}

/// The thumbnail's size inside a `side`×`side` box: the image's aspect
/// kept, the long side `side` (at least one pixel each way).
pub fn fit(img: &Image, side: u32) -> (u32, u32) {
    let (w, h) = (img.width().max(1) as u64, img.height().max(1) as u64);
    let side = side.max(1) as u64;
    if w >= h {
        (side as u32, ((side * h + w / 2) / w).max(1) as u32)
    } else {
        (((side * w + h / 2) / h).max(1) as u32, side as u32)
    }
}

/// `w`×`h` pixels as 0x00RRGGBB, row by row (top row first, as images
/// are stored): each the texel under the pixel's centre, composited over
/// a grey checker of 4-pixel squares where the texture is see-through.
pub fn pixels(img: &Image, w: u32, h: u32) -> Vec<u32> {
    let l = level_for(img, w, h);
    let (lw, lh) = (l.width() as u64, l.height() as u64);
    let mut out = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h {
        // Pixel centre (y + 1/2) / h of the way down, in whole texels.
        let ty = (((2 * y as u64 + 1) * lh) / (2 * h as u64)).min(lh - 1);
        for x in 0..w {
            let tx = (((2 * x as u64 + 1) * lw) / (2 * w as u64)).min(lw - 1);
            let [r, g, b, a] = l.texel(tx as u32, ty as u32);
            let back: u32 = if ((x / 4) + (y / 4)) % 2 == 0 {
                0x99
            } else {
                0x66
            };
            let mix = |c: u8| (c as u32 * a as u32 + back * (255 - a as u32) + 127) / 255;
            out.push(mix(r) << 16 | mix(g) << 8 | mix(b));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::ImageSource;

    fn checker(n: u32) -> Image {
        let px = (0..n * n)
            .map(|i| match (i % n + i / n) % 2 {
                0 => [255, 0, 0, 255],
                _ => [0, 0, 255, 255],
            })
            .collect();
        Image::new("c", ImageSource::Inline, n, n, 4, px).unwrap()
    }

    #[test]
    fn the_smallest_adequate_level_is_sampled() {
        let img = checker(128);
        assert_eq!(level_for(&img, 30, 30).width(), 32);
        assert_eq!(level_for(&img, 32, 16).width(), 32);
        assert_eq!(level_for(&img, 200, 200).width(), 128, "base when small");
        // Level 32 of a one-texel checker is the box-filtered average:
        // every pixel purple-ish, no red/blue aliasing.
        let p = pixels(&img, 30, 30);
        assert_eq!(p.len(), 900);
        assert!(p.iter().all(|&c| c == p[0]), "uniform average");
        let (r, b) = (p[0] >> 16, p[0] & 0xff);
        assert!(
            (100..=155).contains(&r) && (100..=155).contains(&b),
            "{:06x}",
            p[0]
        );
    }

    #[test]
    fn aspect_is_kept_and_alpha_shows_the_checker() {
        let img = Image::new("t", ImageSource::Inline, 8, 2, 4, vec![[0, 0, 0, 0]; 16]).unwrap();
        assert_eq!(fit(&img, 30), (30, 8));
        let p = pixels(&img, 8, 4);
        assert_eq!(p[0], 0x999999);
        assert_eq!(p[4], 0x666666);
        let tall = Image::new("t", ImageSource::Inline, 1, 3, 3, vec![[9, 9, 9, 255]; 3]).unwrap();
        assert_eq!(fit(&tall, 30), (10, 30));
        assert!(pixels(&tall, 10, 30).iter().all(|&c| c == 0x090909));
    }
}
