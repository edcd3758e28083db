//! The maths every handle shares: the mouse ray, closest points of two
//! lines, ray–plane intersection, screen-space hit tests and snapping.

use crate::input::camera::Projector;
use glam::{Vec3, Vec4};

/// Unit vector of world axis `i`.
pub fn axis(i: u8) -> Vec3 {
    match i {
        0 => Vec3::X,
        1 => Vec3::Y,
        _ => Vec3::Z,
    }
}

/// The mouse ray through window pixel (x, y): origin on the near plane and
/// unit direction.
pub fn pixel_ray(p: &Projector, x: f32, y: f32) -> (Vec3, Vec3) {
    let nx = (x - p.x) / p.w.max(1.0) * 2.0 - 1.0;
    let ny = 1.0 - (y - p.y) / p.h.max(1.0) * 2.0;
    let inv = (p.proj * p.view).inverse();
    let unproject = |z: f32| {
        let h = inv * Vec4::new(nx, ny, z, 1.0);
        h.truncate() / h.w
    };
    let a = unproject(-1.0);
    let b = unproject(1.0);
    (a, (b - a).normalize_or_zero())
}

/// Parameter `s` of the point `o + s·d` of a line closest to the ray
/// (`ro`, `rd`): the closest points of two lines (minimise
/// |o + s·d − ro − t·rd|², solve the 2×2 normal equations). `None` when
/// the lines are (nearly) parallel, as when an axis points at the eye.
pub fn closest_on_line(o: Vec3, d: Vec3, ro: Vec3, rd: Vec3) -> Option<f32> {
    let w = o - ro;
    let a = d.dot(d);
    let b = d.dot(rd);
    let c = rd.dot(rd);
    let dd = d.dot(w);
    let e = rd.dot(w);
    let den = a * c - b * b;
    if den.abs() <= 1e-6 * a * c {
        return None;
    }
    Some((b * e - c * dd) / den)
}

/// Where the ray meets the plane through `o` with normal `n` (`None` when
/// parallel or behind the ray's origin).
pub fn ray_plane(o: Vec3, n: Vec3, ro: Vec3, rd: Vec3) -> Option<Vec3> {
    let den = n.dot(rd);
    if den.abs() < 1e-6 {
        return None;
    }
    let t = n.dot(o - ro) / den;
    (t >= 0.0).then(|| ro + rd * t)
}

/// Signed angle (radians, in (−π, π]) that turns `a` onto `b` about the
/// unit axis `n` (right-handed): atan2 of the sine and cosine parts, so it
/// is exact at every angle (both vectors are taken in the plane ⟂ `n`).
pub fn angle_about(n: Vec3, a: Vec3, b: Vec3) -> f32 {
    let a = a - n * n.dot(a);
    let b = b - n * n.dot(b);
    n.dot(a.cross(b)).atan2(a.dot(b))
}

/// `a` moved by a whole number of turns to lie within π of `near` (keeps an
/// angle continuous when the mouse goes round more than half a turn).
pub fn unwrap_angle(a: f32, near: f32) -> f32 {
    use std::f32::consts::{PI, TAU};
    let mut x = a;
    while x - near > PI {
        x -= TAU;
    }
    while x - near < -PI {
        x += TAU;
    }
    x
}

/// Distance from `p` to the segment `a`–`b` (pixels).
pub fn seg_dist(p: (f32, f32), a: (f32, f32), b: (f32, f32)) -> f32 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (cx, cy) = (a.0 + t * dx, a.1 + t * dy);
    ((p.0 - cx).powi(2) + (p.1 - cy).powi(2)).sqrt()
}

/// Where a handle's shaft from pivot pixel `c` to `tip` starts when the
/// handles keep `gap` pixels clear around the pivot (a small object's own
/// disc): `c` itself without a gap, `None` when the gap swallows it.
pub fn shaft_start(c: (f32, f32), tip: (f32, f32), gap: f32) -> Option<(f32, f32)> {
    if gap <= 0.0 {
        return Some(c);
    }
    let (dx, dy) = (tip.0 - c.0, tip.1 - c.1);
    let l = (dx * dx + dy * dy).sqrt();
    (l > gap + 4.0).then(|| (c.0 + dx / l * gap, c.1 + dy / l * gap))
}

/// Whether `p` is inside the convex quad `q` (either winding).
pub fn in_quad(p: (f32, f32), q: &[(f32, f32); 4]) -> bool {
    let mut sign = 0.0f32;
    for i in 0..4 {
        let (a, b) = (q[i], q[(i + 1) % 4]);
        let c = (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0);
        if c != 0.0 {
            if sign != 0.0 && c.signum() != sign {
                return false;
            }
            sign = c.signum();
        }
    }
    sign != 0.0
}

/// Whether `p` is within `half` pixels of `c` on both axes (a square box).
pub fn in_box(p: (f32, f32), c: (f32, f32), half: f32) -> bool {
    (p.0 - c.0).abs() <= half && (p.1 - c.1).abs() <= half
}

/// Rounds `x` to a multiple of `step`.
pub fn snap(x: f32, step: f32) -> f32 {
    if step > 0.0 {
        (x / step).round() * step
    } else {
        x
    }
}

/// The grid spacing the viewport draws for a scene of `radius` (matches
/// the ground grid, so Ctrl-snapped objects land on its lines).
pub fn grid_step(radius: f32) -> f32 {
    10f32.powf((radius * 0.5).max(1e-3).log10().floor())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::input::camera::{look_at, perspective};
    use crate::render::View;

    /// A perspective projector looking at the origin from (4, 3, 6).
    pub(crate) fn projector() -> Projector {
        let eye = Vec3::new(4.0, 3.0, 6.0);
        let v = View {
            view: look_at(eye, Vec3::ZERO, Vec3::Y),
            proj: perspective(0.8, 4.0 / 3.0, 0.1, 100.0),
            eye,
        };
        Projector::new(&v, 10.0, 20.0, 320.0, 240.0)
    }

    #[test]
    fn closest_point_of_two_lines_by_hand() {
        // Axis: the x axis. Ray: from (3, 5, 2) straight down (−y). The
        // closest point of the x axis is x = 3.
        let s = closest_on_line(Vec3::ZERO, Vec3::X, Vec3::new(3.0, 5.0, 2.0), Vec3::NEG_Y);
        assert!((s.unwrap() - 3.0).abs() < 1e-6);
        // A non-unit axis direction scales the parameter.
        let s = closest_on_line(
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(3.0, 5.0, 2.0),
            Vec3::NEG_Y,
        );
        assert!((s.unwrap() - 1.0).abs() < 1e-6);
        // Parallel lines have no single closest point.
        assert!(closest_on_line(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::X).is_none());
    }

    #[test]
    fn ray_through_a_projected_point_passes_through_it() {
        let p = projector();
        let w = Vec3::new(0.7, -0.4, 1.3);
        let (x, y) = p.point(w).unwrap();
        let (o, d) = pixel_ray(&p, x, y);
        let off = (w - o) - d * (w - o).dot(d);
        assert!(off.length() < 1e-3, "ray misses by {}", off.length());
    }

    #[test]
    fn angles_about_an_axis_by_hand() {
        let q = std::f32::consts::FRAC_PI_2;
        // x onto y about +z is a quarter turn anticlockwise.
        assert!((angle_about(Vec3::Z, Vec3::X, Vec3::Y) - q).abs() < 1e-6);
        assert!((angle_about(Vec3::Z, Vec3::Y, Vec3::X) + q).abs() < 1e-6);
        // Components along the axis do not matter.
        let a = angle_about(
            Vec3::Z,
            Vec3::new(1.0, 0.0, 5.0),
            Vec3::new(-1.0, 0.0, -2.0),
        );
        assert!((a.abs() - std::f32::consts::PI).abs() < 1e-6);
        // Unwrapping keeps a drag continuous past half a turn.
        let u = unwrap_angle(-3.0, 3.0);
        assert!((u - (-3.0 + std::f32::consts::TAU)).abs() < 1e-6);
        assert_eq!(unwrap_angle(0.5, 0.2), 0.5);
    }

    #[test]
    fn snapping_and_grid_step() {
        assert_eq!(snap(0.74, 0.5), 0.5);
        assert_eq!(snap(-0.76, 0.5), -1.0);
        assert_eq!(grid_step(5.0), 1.0);
        assert_eq!(grid_step(50.0), 10.0);
        assert!((grid_step(1.0) - 0.1).abs() < 1e-6);
    }

    #[test]
    fn quad_box_and_segment_hits() {
        let q = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
        assert!(in_quad((5.0, 5.0), &q));
        assert!(!in_quad((11.0, 5.0), &q));
        assert!((seg_dist((5.0, 3.0), (0.0, 0.0), (10.0, 0.0)) - 3.0).abs() < 1e-6);
        assert!((seg_dist((13.0, 4.0), (0.0, 0.0), (10.0, 0.0)) - 5.0).abs() < 1e-6);
        assert!(in_box((3.0, -3.0), (0.0, 0.0), 3.0));
        assert_eq!(shaft_start((0.0, 0.0), (30.0, 40.0), 0.0), Some((0.0, 0.0)));
        assert_eq!(
            shaft_start((0.0, 0.0), (30.0, 40.0), 10.0),
            Some((6.0, 8.0))
        );
        assert_eq!(shaft_start((0.0, 0.0), (3.0, 4.0), 10.0), None);
        assert!(!in_box((3.5, 0.0), (0.0, 0.0), 3.0));
    }
}
