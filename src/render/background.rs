//! The VRML97 Background drawn per pixel from the view ray (ISO/IEC
//! 14772-1 §6.5): sky and ground colour spheres at infinity, then the
//! panorama cube at infinity over them. Only the camera's rotation
//! matters, so the background turns with the camera and never moves.
//!
//! Colours are interpolated linearly in RGB by the angle from the zenith
//! (sky) or the nadir (ground), as view3dscene draws them; the ground is
//! drawn over the sky only up to its last angle. Panorama faces are seen
//! from inside the cube upright (front −Z, back +Z, left −X, right +X with
//! +Y up; top with +Z up; bottom with −Z up), checked against view3dscene.

use super::texture::Sampler;
use crate::scene::{Background, Image, Scene, Texture, Wrap};
use glam::{Mat3, Mat4, Vec2, Vec3};
use std::f32::consts::PI;

/// A background ready to draw into a picture of a given size.
#[derive(Clone, Debug)]
pub struct Painter {
    bg: Background,
    faces: [Option<Sampler>; 6],
    /// Level of detail of each face (texels per pixel, log2).
    lods: [f32; 6],
    /// View space → world rotation.
    to_world: Mat3,
    /// NDC → view-space ray slopes.
    slope: Vec2,
    size: Vec2,
}

impl Painter {
    /// `None` when the background is one flat colour (the caller fills it).
    pub fn new(
        scene: &Scene,
        bg: &Background,
        view: Mat4,
        proj: Mat4,
        width: u32,
        height: u32,
    ) -> Option<Painter> {
        if bg.is_flat() {
            return None;
        }
        let to_world = Mat3::from_mat4(view).inverse();
        // Perspective: x_ndc = P00·x / −z. Orthographic views get a 45°
        // field of view so the gradient still shows.
        let slope = if proj.w_axis.w == 0.0 && proj.x_axis.x != 0.0 && proj.y_axis.y != 0.0 {
            Vec2::new(1.0 / proj.x_axis.x, 1.0 / proj.y_axis.y)
        } else {
            let t = libm::tanf(PI / 8.0);
            Vec2::new(t * width as f32 / height.max(1) as f32, t)
        };
        let size = Vec2::new(width.max(1) as f32, height.max(1) as f32);
        let mut faces: [Option<Sampler>; 6] = Default::default();
        let mut lods = [0.0; 6];
        for (i, id) in bg.panorama.iter().enumerate() {
            let Some(img): Option<&Image> = id.and_then(|id| scene.image(id)) else {
                continue;
            };
            let mut t = Texture::new(crate::scene::ImageId(0));
            t.wrap_s = Wrap::Clamp;
            t.wrap_t = Wrap::Clamp;
            // A face spans slope 2 (−1..1); a pixel spans 2·slope.y / height.
            let texels_per_pixel = img.width().max(img.height()) as f32 * slope.y / size.y;
            lods[i] = if texels_per_pixel > 1.0 {
                libm::log2f(texels_per_pixel)
            } else {
                0.0
            };
            faces[i] = Some(Sampler::new(&t, img));
        }
        Some(Painter {
            bg: bg.clone(),
            faces,
            lods,
            to_world,
            slope,
            size,
        })
    }

    /// Paints the background pixels (`ids` 0) of a tile whose top-left
    /// pixel is `(x0, y0)`; buffers have rows of `stride`.
    #[allow(clippy::too_many_arguments)]
    pub fn fill_tile(
        &self,
        (x0, y0): (i32, i32),
        (w, h): (usize, usize),
        stride: usize,
        ids: &[u32],
        rgb: [&mut [f32]; 3],
    ) {
        let [r, g, b] = rgb;
        for row in 0..h {
            for col in 0..w {
                let i = row * stride + col;
                if ids[i] == 0 {
                    let c = self.pixel((x0 + col as i32) as u32, (y0 + row as i32) as u32);
                    r[i] = c.x;
                    g[i] = c.y;
                    b[i] = c.z;
                }
            }
        }
    }

    /// Colour of pixel (x, y) (row 0 at the top), linear 0..1 RGB.
    pub fn pixel(&self, x: u32, y: u32) -> Vec3 {
        let ndc = Vec2::new(
            2.0 * (x as f32 + 0.5) / self.size.x - 1.0,
            1.0 - 2.0 * (y as f32 + 0.5) / self.size.y,
        );
        let d = self.to_world * Vec3::new(ndc.x * self.slope.x, ndc.y * self.slope.y, -1.0);
        self.color(d)
    }

    /// Colour seen along world direction `d`.
    pub fn color(&self, d: Vec3) -> Vec3 {
        let d = d.normalize_or_zero();
        let theta = libm::acosf(d.y.clamp(-1.0, 1.0));
        let mut c =
            bands(&self.bg.sky_color, &self.bg.sky_angle, theta, true).unwrap_or(Vec3::ZERO);
        if let Some(g) = bands(
            &self.bg.ground_color,
            &self.bg.ground_angle,
            PI - theta,
            false,
        ) {
            c = g;
        }
        if self.faces.iter().any(Option::is_some) {
            let (face, st) = cube_face(d);
            if let Some(s) = &self.faces[face] {
                let t = s.sample(st, self.lods[face]);
                c = c + (t.truncate() - c) * t.w;
            }
        }
        c
    }
}

/// The colour at `angle` from the pole of a band list, or `None` past the
/// last angle when `hold_last` is false (the ground stops there).
fn bands(colors: &[Vec3], angles: &[f32], angle: f32, hold_last: bool) -> Option<Vec3> {
    let first = *colors.first()?;
    let n = angles.len().min(colors.len() - 1);
    if n == 0 {
        return hold_last.then_some(first);
    }
    let mut lo_angle = 0.0;
    let mut lo = first;
    for i in 0..n {
        let (a, c) = (angles[i], colors[i + 1]);
        if angle <= a {
            let span = a - lo_angle;
            let f = if span > 0.0 {
                (angle - lo_angle) / span
            } else {
                1.0
            };
            return Some(lo + (c - lo) * f.clamp(0.0, 1.0));
        }
        lo_angle = a;
        lo = c;
    }
    hold_last.then_some(lo)
}

/// The panorama face a direction hits ([`crate::scene::Face::ALL`] order:
/// back, bottom, front, left, right, top) and the (s, t) on it.
fn cube_face(d: Vec3) -> (usize, Vec2) {
    let a = d.abs();
    let st = |u: f32, v: f32, m: f32| Vec2::new(0.5 + 0.5 * u / m, 0.5 + 0.5 * v / m);
    if a.z >= a.x && a.z >= a.y {
        if d.z < 0.0 {
            (2, st(d.x, d.y, a.z)) // front
        } else {
            (0, st(-d.x, d.y, a.z)) // back
        }
    } else if a.x >= a.y {
        if d.x < 0.0 {
            (3, st(-d.z, d.y, a.x)) // left
        } else {
            (4, st(d.z, d.y, a.x)) // right
        }
    } else if d.y > 0.0 {
        (5, st(d.x, d.z, a.y)) // top
    } else {
        (1, st(d.x, -d.z, a.y)) // bottom
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sky_bands_interpolate_by_angle() {
        let c = [Vec3::Z, Vec3::X, Vec3::ONE];
        let a = [1.0, 2.0];
        assert_eq!(bands(&c, &a, 0.0, true), Some(Vec3::Z));
        assert_eq!(bands(&c, &a, 0.5, true), Some(Vec3::new(0.5, 0.0, 0.5)));
        assert_eq!(bands(&c, &a, 1.5, true), Some(Vec3::new(1.0, 0.5, 0.5)));
        assert_eq!(bands(&c, &a, 3.0, true), Some(Vec3::ONE));
        // The ground stops at its last angle; one colour alone draws nothing.
        assert_eq!(bands(&c, &a, 3.0, false), None);
        assert_eq!(bands(&[Vec3::Y], &[], 0.1, false), None);
        assert_eq!(bands(&[Vec3::Y], &[], 2.0, true), Some(Vec3::Y));
        assert_eq!(bands(&[], &[], 2.0, true), None);
        // More angles than colours: extra angles ignored.
        assert_eq!(
            bands(&[Vec3::Z, Vec3::X], &[1.0, 2.0, 3.0], 2.5, true),
            Some(Vec3::X)
        );
    }

    #[test]
    fn cube_faces_are_upright_from_inside() {
        // Straight ahead (−Z) is the front centre; up on screen is t up.
        assert_eq!(cube_face(Vec3::NEG_Z), (2, Vec2::splat(0.5)));
        assert_eq!(cube_face(Vec3::new(0.0, 0.5, -1.0)).1, Vec2::new(0.5, 0.75));
        // Looking at −X, the right of the screen is −Z.
        assert_eq!(
            cube_face(Vec3::new(-1.0, 0.0, -0.5)),
            (3, Vec2::new(0.75, 0.5))
        );
        // Looking up with +Z up: +Z is t up.
        assert_eq!(
            cube_face(Vec3::new(0.0, 1.0, 0.5)),
            (5, Vec2::new(0.5, 0.75))
        );
        // Looking down with −Z up.
        assert_eq!(
            cube_face(Vec3::new(0.0, -1.0, -0.5)),
            (1, Vec2::new(0.5, 0.75))
        );
        assert_eq!(
            cube_face(Vec3::new(0.5, 0.0, 1.0)),
            (0, Vec2::new(0.25, 0.5))
        );
    }
}
