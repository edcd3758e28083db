//! Dragging the body of the selected object (its pixels, not a handle):
//! it moves in the view plane through its pivot (normal = the view
//! direction), so the grabbed point of that plane follows the mouse and
//! the depth from the camera does not change.
//!
//! A press on the selection only arms the drag; the ordinary click (pick
//! on release) stays in charge until the mouse moves past a few pixels.

use super::geom::{pixel_ray, ray_plane};
use crate::input::camera::Projector;
use glam::Vec3;

/// Pixels the mouse may move before a press on the body becomes a drag
/// (the same slop a click has).
pub const SLOP: f32 = 3.0;

/// The point of the view plane through `pivot` (normal `back`, the unit
/// vector towards the eye) under pixel (x, y).
pub fn grab_point(proj: &Projector, pivot: Vec3, back: Vec3, x: f32, y: f32) -> Option<Vec3> {
    let (ro, rd) = pixel_ray(proj, x, y);
    ray_plane(pivot, back, ro, rd)
}

/// Whether the mouse went past the click slop from `at`.
pub fn past_slop(at: (f32, f32), x: f32, y: f32) -> bool {
    (x - at.0).abs() > SLOP || (y - at.1).abs() > SLOP
}

#[cfg(test)]
mod tests {
    use super::super::geom::tests::projector;
    use super::*;

    #[test]
    fn view_plane_drag_keeps_depth_and_follows_the_mouse() {
        let p = projector();
        let back = Vec3::new(4.0, 3.0, 6.0).normalize();
        let pivot = Vec3::new(0.4, 0.3, -0.2);
        let m0 = p.point(pivot).unwrap();
        let m1 = (m0.0 + 37.0, m0.1 - 21.0);
        let a = grab_point(&p, pivot, back, m0.0, m0.1).unwrap();
        let b = grab_point(&p, pivot, back, m1.0, m1.1).unwrap();
        assert!((a - pivot).length() < 1e-3);
        let moved = pivot + (b - a);
        assert!(
            (moved - pivot).dot(back).abs() < 1e-4,
            "stays in the view plane"
        );
        let seen = p.point(moved).unwrap();
        assert!((seen.0 - m1.0).abs() < 0.05 && (seen.1 - m1.1).abs() < 0.05);
        assert!(past_slop(m0, m0.0 + 4.0, m0.1) && !past_slop(m0, m0.0 + 3.0, m0.1));
    }
}
