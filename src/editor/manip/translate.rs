//! Translate handles: three world-axis arrows and three plane squares at
//! the pivot.
//!
//! An axis drag takes the point of the axis line closest to the mouse ray
//! (closest points of two lines); a plane drag intersects the mouse ray
//! with the plane through the pivot. Either way the pivot moves by exactly
//! the grabbed point's motion, so the object follows the mouse. Ctrl snaps
//! the moved world coordinates to the grid step.

use super::geom::{
    axis, closest_on_line, in_quad, pixel_ray, ray_plane, seg_dist, shaft_start, snap,
};
use super::{Handle, ARROW_PX, AXIS_COLORS, GRAB_PX, HOT};
use crate::anim::Property;
use crate::input::camera::Projector;
use crate::scene::{Node, NodeKind};
use crate::ui::Painter;
use glam::Vec3;

/// Plane squares span this part of the arrow length.
const PLANE_FROM: f32 = 0.25;
const PLANE_TO: f32 = 0.45;

/// The two axes spanning the plane with normal axis `n`.
pub fn plane_axes(n: u8) -> (u8, u8) {
    match n {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    }
}

/// World corners of plane square `n` for a pivot and arrow length; with a
/// gap around the pivot (a small object's disc, in pixels) the square moves
/// out beyond it.
fn plane_corners(proj: &Projector, pivot: Vec3, len: f32, n: u8) -> [Vec3; 4] {
    let (a, b) = plane_axes(n);
    let (u, v) = (axis(a) * len, axis(b) * len);
    let len_px = len / proj.world_per_px(pivot).max(1e-12);
    let from = PLANE_FROM.max(proj.gap_px() / len_px.max(1.0) + 0.05);
    let to = from + (PLANE_TO - PLANE_FROM);
    [
        pivot + u * from + v * from,
        pivot + u * to + v * from,
        pivot + u * to + v * to,
        pivot + u * from + v * to,
    ]
}

/// Pixel positions of the pivot and the three arrow tips.
pub fn points(proj: &Projector, pivot: Vec3) -> Option<[(f32, f32); 4]> {
    let len = proj.world_per_px(pivot) * ARROW_PX;
    Some([
        proj.point(pivot)?,
        proj.point(pivot + Vec3::X * len)?,
        proj.point(pivot + Vec3::Y * len)?,
        proj.point(pivot + Vec3::Z * len)?,
    ])
}

/// The arrow or plane square under pixel (x, y): arrows first (closest).
pub fn hit(proj: &Projector, pivot: Vec3, x: f32, y: f32) -> Option<Handle> {
    let len = proj.world_per_px(pivot) * ARROW_PX;
    let c = proj.point(pivot)?;
    let mut best: Option<(f32, Handle)> = None;
    for i in 0..3u8 {
        let tip = proj.point(pivot + axis(i) * len);
        if let Some((tip, start)) = tip.and_then(|t| Some((t, shaft_start(c, t, proj.gap_px())?))) {
            let d = seg_dist((x, y), start, tip);
            if d <= GRAB_PX && best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, Handle::Axis(i)));
            }
        }
    }
    if let Some((_, h)) = best {
        return Some(h);
    }
    (0..3u8).map(Handle::Plane).find(|&h| {
        let Handle::Plane(n) = h else { return false };
        let w = plane_corners(proj, pivot, len, n);
        let q: Option<Vec<(f32, f32)>> = w.iter().map(|&p| proj.point(p)).collect();
        q.is_some_and(|q| in_quad((x, y), &[q[0], q[1], q[2], q[3]]))
    })
}

/// The world point under the mouse for `h` (on its axis line or plane).
pub fn grab_point(proj: &Projector, h: Handle, pivot: Vec3, x: f32, y: f32) -> Option<Vec3> {
    let (ro, rd) = pixel_ray(proj, x, y);
    match h {
        Handle::Axis(i) => closest_on_line(pivot, axis(i), ro, rd).map(|s| pivot + axis(i) * s),
        Handle::Plane(n) => ray_plane(pivot, axis(n), ro, rd),
        _ => None,
    }
}

/// The new pivot for a drag that grabbed `grab` and is now at `now`; with
/// `snap_step`, the moved world coordinates land on multiples of it.
pub fn moved_pivot(h: Handle, pivot: Vec3, grab: Vec3, now: Vec3, snap_step: Option<f32>) -> Vec3 {
    let mut p = pivot + (now - grab);
    if let Some(step) = snap_step {
        let moved: Vec<u8> = match h {
            Handle::Axis(i) => vec![i],
            Handle::Plane(n) => {
                let (a, b) = plane_axes(n);
                vec![a, b]
            }
            _ => vec![0, 1, 2],
        };
        for i in moved {
            p[i as usize] = snap(p[i as usize], step);
        }
    }
    p
}

/// `shown` moved by `delta` (in the value's space): a light's location or
/// a node's translation.
pub fn moved_by(shown: &Node, property: Property, delta: Vec3) -> Node {
    let mut node = shown.clone();
    match (&mut node.kind, property) {
        (NodeKind::Light(l), Property::LightLocation) => l.location += delta,
        _ => node.transform.translation += delta,
    }
    node
}

/// Draws the arrows and plane squares, `hot` highlighted.
pub fn draw(p: &mut Painter, proj: &Projector, pivot: Vec3, hot: Option<Handle>) {
    let len = proj.world_per_px(pivot) * ARROW_PX;
    let Some(c) = proj.point(pivot) else { return };
    for n in 0..3u8 {
        let w = plane_corners(proj, pivot, len, n);
        let q: Option<Vec<(f32, f32)>> = w.iter().map(|&x| proj.point(x)).collect();
        if let Some(q) = q {
            let color = if hot == Some(Handle::Plane(n)) {
                HOT
            } else {
                AXIS_COLORS[n as usize]
            };
            // Light enough that what is behind stays readable.
            p.fill_polygon(&q, color, 70);
            p.polyline(&q, color, 1.0, true);
        }
    }
    for i in 0..3u8 {
        let Some(tip) = proj.point(pivot + axis(i) * len) else {
            continue;
        };
        let color = if hot == Some(Handle::Axis(i)) {
            HOT
        } else {
            AXIS_COLORS[i as usize]
        };
        if let Some(start) = shaft_start(c, tip, proj.gap_px()) {
            p.line(start, tip, color, 2.0);
        }
        // Arrow head: a triangle along the screen direction.
        let (dx, dy) = (tip.0 - c.0, tip.1 - c.1);
        let l = (dx * dx + dy * dy).sqrt();
        if l > 1.0 {
            let (ux, uy) = (dx / l, dy / l);
            let head = [
                (tip.0 + ux * 9.0, tip.1 + uy * 9.0),
                (tip.0 - uy * 4.0, tip.1 + ux * 4.0),
                (tip.0 + uy * 4.0, tip.1 - ux * 4.0),
            ];
            p.fill_polygon(&head, color, 255);
        }
    }
    if proj.gap_px() <= 0.0 {
        p.fill_circle(c, 3.0, 0xffffff);
    }
}

#[cfg(test)]
mod tests {
    use super::super::geom::tests::projector;
    use super::*;

    #[test]
    fn axis_drag_keeps_the_grabbed_point_under_the_mouse() {
        let p = projector();
        let pivot = Vec3::new(0.5, 0.2, -0.3);
        for i in 0..3u8 {
            // Grab at the pixel of a point on the axis, move the mouse to the
            // pixel of another point on it: the grabbed point must follow.
            let g0 = pivot + axis(i) * 0.6;
            let g1 = pivot + axis(i) * 1.7;
            let m0 = p.point(g0).unwrap();
            let m1 = p.point(g1).unwrap();
            let grab = grab_point(&p, Handle::Axis(i), pivot, m0.0, m0.1).unwrap();
            let now = grab_point(&p, Handle::Axis(i), pivot, m1.0, m1.1).unwrap();
            assert!((grab - g0).length() < 1e-3, "axis {i}: grabbed {grab}");
            let moved = moved_pivot(Handle::Axis(i), pivot, grab, now, None);
            let seen = p.point(g0 + (moved - pivot)).unwrap();
            assert!(
                (seen.0 - m1.0).abs() < 0.05 && (seen.1 - m1.1).abs() < 0.05,
                "axis {i}: grabbed point at {seen:?}, mouse at {m1:?}"
            );
        }
    }

    #[test]
    fn plane_drag_follows_the_mouse() {
        let p = projector();
        let pivot = Vec3::new(0.0, 1.0, 0.0);
        let g0 = pivot + Vec3::new(0.3, 0.0, 0.3);
        let g1 = pivot + Vec3::new(-1.1, 0.0, 0.8);
        let m0 = p.point(g0).unwrap();
        let m1 = p.point(g1).unwrap();
        let a = grab_point(&p, Handle::Plane(1), pivot, m0.0, m0.1).unwrap();
        let b = grab_point(&p, Handle::Plane(1), pivot, m1.0, m1.1).unwrap();
        assert!((a - g0).length() < 1e-3 && (b - g1).length() < 1e-3);
        assert!(((b - a).y).abs() < 1e-6, "stays in the plane");
    }

    #[test]
    fn snapped_plane_drag_snaps_only_the_plane_axes() {
        let pivot = Vec3::new(0.3, 0.7, 0.2);
        let p = moved_pivot(
            Handle::Plane(1),
            pivot,
            Vec3::ZERO,
            Vec3::new(1.04, 0.0, 0.61),
            Some(0.5),
        );
        assert_eq!(p, Vec3::new(1.5, 0.7, 1.0));
    }
}
