use glam::Vec3;

/// A rendered picture: colour, depth and object ids, row-major, top row first.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    /// `0x00RRGGBB` per pixel (what minifb shows).
    pub color: Vec<u32>,
    /// Window-space depth in 0..1 (1 = far / empty).
    pub depth: Vec<f32>,
    /// `NodeId.0 + 1` of the node drawn at each pixel; 0 = background.
    pub ids: Vec<u32>,
}

/// Packs a linear 0..1 colour into `0x00RRGGBB` (rounded, clamped).
pub fn pack_rgb(c: Vec3) -> u32 {
    let q = |x: f32| ((x.clamp(0.0, 1.0) * 255.0 + 0.5) as u32).min(255);
    (q(c.x) << 16) | (q(c.y) << 8) | q(c.z)
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
        let n = width as usize * height as usize;
        if (self.width, self.height) != (width, height) {
            self.width = width;
            self.height = height;
            for v in [&mut self.color, &mut self.ids] {
                v.clear();
                v.resize(n, 0);
            }
            self.depth.clear();
            self.depth.resize(n, 0.0);
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
