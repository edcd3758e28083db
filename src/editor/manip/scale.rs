//! Scale handles: three lines along the node's own scale axes ending in
//! boxes, and a centre box for uniform scale. Not for lights.
//!
//! An axis drag takes the point of the axis line closest to the mouse ray
//! (as a translate arrow does) and scales by the ratio of its distance from
//! the pivot now to that at the press, so the grabbed point stays under the
//! mouse. The centre box scales all three by 1 + (right + up motion) /
//! arrow length: dragging right or up by one arrow length doubles, left or
//! down shrinks. Ctrl snaps an axis scale to steps of 0.1 and the uniform
//! factor to steps of 0.1.

use super::geom::{closest_on_line, in_box, pixel_ray, seg_dist, shaft_start, snap};
use super::{Handle, ARROW_PX, AXIS_COLORS, GRAB_PX, HOT};
use crate::input::camera::Projector;
use crate::scene::Node;
use crate::ui::Painter;
use glam::Vec3;

/// Half size of the end boxes and of the centre box, in pixels.
const END_BOX: f32 = 4.0;
const CENTRE_BOX: f32 = 6.0;
/// The smallest factor a drag applies (scales stay positive, as VRML97
/// requires).
const MIN_RATIO: f32 = 0.01;
/// Ctrl snap step.
pub const SNAP: f32 = 0.1;

/// Pixel positions of the pivot and the three box centres; `frame` holds
/// the world directions of the node's scale axes.
pub fn points(proj: &Projector, pivot: Vec3, frame: &[Vec3; 3]) -> Option<[(f32, f32); 4]> {
    let len = proj.world_per_px(pivot) * ARROW_PX;
    Some([
        proj.point(pivot)?,
        proj.point(pivot + frame[0] * len)?,
        proj.point(pivot + frame[1] * len)?,
        proj.point(pivot + frame[2] * len)?,
    ])
}

/// Where the uniform-scale box goes: on the pivot, except over a small
/// object (handles keep `gap` pixels clear round the pivot), where it
/// would hide the object — there it sits just outside that disc, in the
/// screen direction farthest from every axis shaft, so it lands on
/// neither the object nor an axis. Axes too short on screen to have a
/// shaft (pointing at the eye) do not count; their boxes stay inside the
/// disc.
pub fn centre_box(pts: &[(f32, f32); 4], gap: f32) -> (f32, f32) {
    let c = pts[0];
    if gap <= 0.0 {
        return c;
    }
    let shafts: Vec<f32> = pts[1..]
        .iter()
        .filter(|&&e| shaft_start(c, e, gap).is_some())
        .map(|e| (e.1 - c.1).atan2(e.0 - c.0))
        .collect();
    let apart = |a: f32, b: f32| {
        let d = (a - b).rem_euclid(std::f32::consts::TAU);
        d.min(std::f32::consts::TAU - d)
    };
    // 24 candidate directions from screen down-left round; the first of
    // equally good ones wins, so the choice is the same every frame.
    let best = (0..24)
        .map(|k| 0.75 * std::f32::consts::PI + k as f32 * std::f32::consts::TAU / 24.0)
        .map(|a| {
            (
                shafts.iter().map(|&s| apart(a, s)).fold(f32::MAX, f32::min),
                a,
            )
        })
        .fold((f32::MIN, 0.0), |b, x| if x.0 > b.0 { x } else { b })
        .1;
    // The box's half diagonal is under 1.5 half sides: all of it outside.
    let r = gap + CENTRE_BOX * 1.5 + 1.0;
    (c.0 + best.cos() * r, c.1 + best.sin() * r)
}

/// The box or axis line under pixel (x, y): the centre box first, then
/// the closest axis.
pub fn hit(proj: &Projector, pivot: Vec3, frame: &[Vec3; 3], x: f32, y: f32) -> Option<Handle> {
    let pts = points(proj, pivot, frame)?;
    if in_box((x, y), centre_box(&pts, proj.gap_px()), CENTRE_BOX + 1.0) {
        return Some(Handle::Uniform);
    }
    let mut best: Option<(f32, Handle)> = None;
    for i in 0..3u8 {
        let end = pts[i as usize + 1];
        let d = if in_box((x, y), end, END_BOX + 1.0) {
            0.0
        } else if let Some(start) = shaft_start(pts[0], end, proj.gap_px()) {
            seg_dist((x, y), start, end)
        } else {
            f32::INFINITY
        };
        if d <= GRAB_PX && best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, Handle::ScaleAxis(i)));
        }
    }
    best.map(|(_, h)| h)
}

/// Distance along world direction `dir` from the pivot of the point of that
/// axis line closest to the mouse ray.
pub fn along(proj: &Projector, pivot: Vec3, dir: Vec3, x: f32, y: f32) -> Option<f32> {
    let (ro, rd) = pixel_ray(proj, x, y);
    closest_on_line(pivot, dir, ro, rd)
}

/// `shown` with scale axis `i` multiplied by `now / grab` (distances along
/// the axis); `snapped` rounds the new scale to [`SNAP`].
pub fn scaled_axis(shown: &Node, i: u8, grab: f32, now: f32, snapped: bool) -> Node {
    let mut node = shown.clone();
    let ratio = (now / grab).max(MIN_RATIO);
    let s = &mut node.transform.scale[i as usize];
    *s *= ratio;
    if snapped {
        *s = snap(*s, SNAP).max(SNAP);
    }
    node
}

/// The uniform factor for a mouse motion of (`dx`, `dy`) pixels since the
/// press (right and up grow); `snapped` rounds it to [`SNAP`].
pub fn uniform_ratio(dx: f32, dy: f32, snapped: bool) -> f32 {
    let r = (1.0 + (dx - dy) / ARROW_PX).max(MIN_RATIO);
    if snapped {
        snap(r, SNAP).max(SNAP)
    } else {
        r
    }
}

/// `shown` with its whole scale multiplied by `ratio`.
pub fn scaled_uniform(shown: &Node, ratio: f32) -> Node {
    let mut node = shown.clone();
    node.transform.scale *= ratio;
    node
}

/// Draws the axis lines, end boxes and centre box, `hot` highlighted.
pub fn draw(
    p: &mut Painter,
    proj: &Projector,
    pivot: Vec3,
    frame: &[Vec3; 3],
    hot: Option<Handle>,
) {
    let Some(pts) = points(proj, pivot, frame) else {
        return;
    };
    let square = |c: (f32, f32), h: f32| {
        [
            (c.0 - h, c.1 - h),
            (c.0 + h, c.1 - h),
            (c.0 + h, c.1 + h),
            (c.0 - h, c.1 + h),
        ]
    };
    for i in 0..3u8 {
        let color = if hot == Some(Handle::ScaleAxis(i)) {
            HOT
        } else {
            AXIS_COLORS[i as usize]
        };
        let end = pts[i as usize + 1];
        if let Some(start) = shaft_start(pts[0], end, proj.gap_px()) {
            p.line(start, end, color, 2.0);
        }
        p.fill_polygon(&square(end, END_BOX), color, 255);
    }
    let color = if hot == Some(Handle::Uniform) {
        HOT
    } else {
        0xe0e0e0
    };
    let q = square(centre_box(&pts, proj.gap_px()), CENTRE_BOX);
    p.fill_polygon(&q, color, 140);
    p.polyline(&q, color, 1.5, true);
}

#[cfg(test)]
mod tests {
    use super::super::geom::tests::projector;
    use super::*;

    #[test]
    fn axis_ratio_keeps_the_grabbed_point_under_the_mouse() {
        let p = projector();
        let pivot = Vec3::new(0.2, 0.1, 0.0);
        let dir = Vec3::new(1.0, 0.0, 1.0).normalize();
        let m0 = p.point(pivot + dir * 0.5).unwrap();
        let m1 = p.point(pivot + dir * 1.0).unwrap();
        let a = along(&p, pivot, dir, m0.0, m0.1).unwrap();
        let b = along(&p, pivot, dir, m1.0, m1.1).unwrap();
        assert!((a - 0.5).abs() < 1e-3 && (b - 1.0).abs() < 1e-3, "{a} {b}");
        let mut n = Node::group("n");
        n.transform.scale = Vec3::new(1.5, 1.0, 2.0);
        let out = scaled_axis(&n, 0, a, b, false);
        assert!((out.transform.scale.x - 3.0).abs() < 1e-2);
        assert_eq!(out.transform.scale.y, 1.0);
        assert_eq!(out.transform.scale.z, 2.0);
        // Past the pivot the scale stays positive.
        assert!(scaled_axis(&n, 0, a, -b, false).transform.scale.x > 0.0);
        // Snapped: a multiple of 0.1.
        let s = scaled_axis(&n, 2, 1.0, 1.234, true).transform.scale.z;
        assert!((s - 2.5).abs() < 1e-5, "{s}");
    }

    #[test]
    fn the_centre_box_leaves_a_small_objects_disc_away_from_every_shaft() {
        // Pivot at (100, 100); x right, y up, z down-left (a usual view).
        let pts = [(100.0, 100.0), (150.0, 100.0), (100.0, 50.0), (70.0, 130.0)];
        assert_eq!(
            centre_box(&pts, 0.0),
            (100.0, 100.0),
            "no gap: on the pivot"
        );
        let gap = 20.0;
        let b = centre_box(&pts, gap);
        let (dx, dy) = (b.0 - 100.0, b.1 - 100.0);
        let r = (dx * dx + dy * dy).sqrt();
        assert!(r - CENTRE_BOX * 1.5 > gap, "outside the disc: {r}");
        // Clear of every shaft by more than the box and the grab margin.
        for &e in &pts[1..] {
            let s = shaft_start(pts[0], e, gap).unwrap();
            assert!(seg_dist(b, s, e) > CENTRE_BOX + GRAB_PX, "{b:?} near {e:?}");
        }
        // The widest opening is between y (up) and z (down-left): the box
        // is on the left.
        assert!(dx < 0.0, "{b:?}");
        // An axis pointing at the eye (no shaft) does not steer it.
        let eye = [
            (100.0, 100.0),
            (150.0, 100.0),
            (100.0, 50.0),
            (101.0, 101.0),
        ];
        let b = centre_box(&eye, gap);
        assert!(
            b.0 < 100.0 && b.1 > 100.0,
            "down-left, opposite x and y: {b:?}"
        );
    }

    #[test]
    fn uniform_ratio_by_hand() {
        assert_eq!(uniform_ratio(0.0, 0.0, false), 1.0);
        assert!((uniform_ratio(ARROW_PX, 0.0, false) - 2.0).abs() < 1e-6);
        assert!((uniform_ratio(0.0, ARROW_PX * 0.5, false) - 0.5).abs() < 1e-6);
        assert_eq!(uniform_ratio(-1000.0, 0.0, false), MIN_RATIO);
        assert!((uniform_ratio(ARROW_PX * 0.33, 0.0, true) - 1.3).abs() < 1e-6);
    }
}
