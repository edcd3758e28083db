use super::simd::V8;
use glam::Vec3;

/// A rendered picture: colour, depth and object ids, row-major, top row first.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    /// `0x00RRGGBB` per pixel (what minifb shows).
    pub color: Vec<u32>,
    /// Window-space depth in 0..1 (1 = far / empty); empty after a
    /// colour-only render (`render::render_color_into`), as are `ids`.
    pub depth: Vec<f32>,
    /// `NodeId.0 + 1` of the node drawn at each pixel; 0 = background.
    pub ids: Vec<u32>,
}

/// Packs a linear 0..1 colour into `0x00RRGGBB` (rounded, clamped).
pub fn pack_rgb(c: Vec3) -> u32 {
    let q = |x: f32| ((x.clamp(0.0, 1.0) * 255.0 + 0.5) as u32).min(255);
    (q(c.x) << 16) | (q(c.y) << 8) | q(c.z)
}

/// [`pack_rgb`] for eight pixels given as channel lanes: the same clamp,
/// scale, rounding and truncation lane by lane (MAXPS/MINPS send NaN to 0
/// as `clamp` + the saturating cast do), so the bytes are identical.
#[inline(always)]
pub fn pack_rgb8<V: V8>(r: V, g: V, b: V) -> [u32; 8] {
    // A function, not a closure: closures lose the caller's AVX target
    // feature and their lane operations stop being inlined.
    #[inline(always)]
    fn q<V: V8>(x: V) -> [i32; 8] {
        (x.max(V::splat(0.0)).min(V::splat(1.0)) * V::splat(255.0) + V::splat(0.5)).trunc_i32()
    }
    let (r, g, b) = (q(r), q(g), q(b));
    std::array::from_fn(|k| ((r[k] as u32) << 16) | ((g[k] as u32) << 8) | b[k] as u32)
}

impl Frame {
    pub fn new(width: u32, height: u32, background: Vec3) -> Frame {
        let n = width as usize * height as usize;
        Frame {
            width,
            height,
            color: vec![pack_rgb(background); n],
            depth: vec![1.0; n],
            ids: vec![0; n],
        }
    }

    /// Makes the buffers `width`×`height` pixels, keeping their memory when
    /// the size is unchanged; new pixels are zero (the renderer overwrites
    /// every pixel anyway).
    pub fn resize(&mut self, width: u32, height: u32) {
        self.fit(width, height, true);
    }

    /// [`Frame::resize`], with empty depth and id buffers unless
    /// `depth_and_ids` (a colour-only render, `render::render_color_into`).
    pub fn fit(&mut self, width: u32, height: u32, depth_and_ids: bool) {
        let n = width as usize * height as usize;
        self.width = width;
        self.height = height;
        let m = if depth_and_ids { n } else { 0 };
        if self.color.len() != n {
            self.color.clear();
            self.color.resize(n, 0);
        }
        if self.ids.len() != m {
            self.ids.clear();
            self.ids.resize(m, 0);
        }
        if self.depth.len() != m {
            self.depth.clear();
            self.depth.resize(m, 0.0);
        }
    }

    /// RGBA8 bytes for `image` (alpha 255).
    pub fn to_rgba8(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.color.len() * 4);
        for &c in &self.color {
            out.extend_from_slice(&[(c >> 16) as u8, (c >> 8) as u8, c as u8, 255]);
        }
        out
    }

    /// Saves as PNG.
    pub fn save_png(&self, path: &std::path::Path) -> Result<(), image::ImageError> {
        let img = image::RgbaImage::from_raw(self.width, self.height, self.to_rgba8())
            // from_raw only fails when the buffer is too small; to_rgba8 makes it exactly w*h*4.
            .expect("buffer size matches dimensions");
        img.save(path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::simd::Sse8;

    /// The eight-lane packing gives exactly `pack_rgb`'s bytes, edge cases
    /// included (NaN, infinities, −0, halfway values, out of range).
    #[test]
    fn pack_rgb8_matches_pack_rgb() {
        let mut xs = vec![
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -0.0,
            0.0,
            1.0,
            1.0001,
            -1e-9,
            1e30,
            -1e30,
            0.5 / 255.0,
            1.5 / 255.0,
            254.5 / 255.0,
        ];
        for k in 0..=5000 {
            xs.push(-0.1 + 1.2 * k as f32 / 5000.0);
        }
        for c in xs.chunks(8) {
            let mut a = [0.0f32; 8];
            a[..c.len()].copy_from_slice(c);
            // Rotate channels so every value appears in each of them.
            let g: [f32; 8] = std::array::from_fn(|k| a[(k + 3) % 8]);
            let b: [f32; 8] = std::array::from_fn(|k| a[(k + 5) % 8]);
            let got = pack_rgb8(Sse8::load(&a), Sse8::load(&g), Sse8::load(&b));
            for k in 0..8 {
                assert_eq!(got[k], pack_rgb(Vec3::new(a[k], g[k], b[k])), "{}", a[k]);
            }
        }
    }
}
