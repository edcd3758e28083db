//! Rotate handles: three rings about the world axes through the pivot and
//! a larger view-aligned ring about the view direction.
//!
//! A ring drag intersects the mouse ray with the ring's plane; the angle
//! turned is the signed angle (atan2) between the grab vector and the
//! current vector about the ring's axis, so the grabbed point stays on the
//! line from the pivot through the mouse. A ring seen (nearly) edge-on
//! turns instead by the mouse motion along its screen line over its pixel
//! radius (ray–plane hits run away there). Ctrl snaps the angle to 15°.
//!
//! Inside the rings a drag turns freely: the grabbed point of the sphere
//! the rings outline is turned along the shortest arc onto the point under
//! the mouse (trackball).
//!
//! Objects: the world-axis turn is taken into the node's parent space
//! (axis through the inverse parent matrix) and composed before the posed
//! rotation, so it is right for parented nodes. Lights: the turn is applied
//! to the world direction and taken back into the light's node space.

use super::geom::{angle_about, axis, pixel_ray, ray_plane, seg_dist};
use super::{Handle, ARROW_PX, AXIS_COLORS, GRAB_PX, HOT};
use crate::input::camera::Projector;
use crate::scene::{Node, NodeKind};
use crate::ui::Painter;
use glam::{Mat4, Quat, Vec3};

/// Radius of the axis rings and of the view ring, in pixels.
pub const RING_PX: f32 = ARROW_PX * 0.85;
pub const VIEW_RING_PX: f32 = ARROW_PX * 1.1;
/// Ctrl snap step (15°).
pub const SNAP: f32 = std::f32::consts::PI / 12.0;
const SEGMENTS: usize = 64;
const VIEW_RING: u32 = 0xd8d8d8;

/// Axis `n` and in-plane basis (`u`, `v` = `n` × `u`) of a ring; `back` is
/// the unit vector from the view target to the eye. A positive angle turns
/// `u` towards `v` (anticlockwise on screen for the view ring).
pub fn basis(h: Handle, back: Vec3) -> Option<(Vec3, Vec3, Vec3)> {
    match h {
        Handle::Ring(i) => Some((axis(i), axis((i + 1) % 3), axis((i + 2) % 3))),
        Handle::ViewRing => {
            let n = back.normalize_or(Vec3::Z);
            let u = Vec3::Y.cross(n).normalize_or(Vec3::X);
            Some((n, u, n.cross(u)))
        }
        _ => None,
    }
}

/// World radius of ring `h` at `pivot`.
fn radius(proj: &Projector, h: Handle, pivot: Vec3) -> f32 {
    let px = if h == Handle::ViewRing {
        VIEW_RING_PX
    } else {
        RING_PX
    };
    proj.world_per_px(pivot) * px
}

/// World point of ring `h` at angle `theta` from its `u` axis.
pub fn ring_point(
    proj: &Projector,
    h: Handle,
    pivot: Vec3,
    back: Vec3,
    theta: f32,
) -> Option<Vec3> {
    let (_, u, v) = basis(h, back)?;
    let r = radius(proj, h, pivot);
    Some(pivot + (u * theta.cos() + v * theta.sin()) * r)
}

/// A projected ring segment: its ends in pixels and whether it faces the eye.
type Segment = ((f32, f32), (f32, f32), bool);

/// Ring `h` as projected segments, each flagged front-facing (towards the
/// eye from the pivot) or not; the view ring is all front.
fn segments(proj: &Projector, h: Handle, pivot: Vec3, back: Vec3) -> Vec<Segment> {
    let mut out = Vec::with_capacity(SEGMENTS);
    let pts: Vec<Vec3> = (0..=SEGMENTS)
        .filter_map(|k| {
            let t = k as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            ring_point(proj, h, pivot, back, t)
        })
        .collect();
    // Front: the side of the pivot facing the eye (a small margin keeps the
    // silhouette points of an edge-on ring grabbable).
    let r = radius(proj, h, pivot);
    for w in pts.windows(2) {
        let mid = (w[0] + w[1]) * 0.5;
        let front = h == Handle::ViewRing || (mid - pivot).dot(back) >= -0.05 * r;
        if let Some((a, b)) = proj.segment(w[0], w[1]) {
            out.push((a, b, front));
        }
    }
    out
}

/// The ring under pixel (x, y): the closest front-facing ring within reach.
pub fn hit(proj: &Projector, pivot: Vec3, back: Vec3, x: f32, y: f32) -> Option<Handle> {
    let mut best: Option<(f32, Handle)> = None;
    for h in [
        Handle::Ring(0),
        Handle::Ring(1),
        Handle::Ring(2),
        Handle::ViewRing,
    ] {
        for (a, b, front) in segments(proj, h, pivot, back) {
            let d = seg_dist((x, y), a, b);
            if front && d <= GRAB_PX && best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, h));
            }
        }
    }
    best.map(|(_, h)| h)
}

/// The world point under the mouse in ring `h`'s plane.
pub fn grab_point(
    proj: &Projector,
    h: Handle,
    pivot: Vec3,
    back: Vec3,
    x: f32,
    y: f32,
) -> Option<Vec3> {
    let (n, _, _) = basis(h, back)?;
    let (ro, rd) = pixel_ray(proj, x, y);
    ray_plane(pivot, n, ro, rd)
}

/// Below this |cos| between a ring's axis and the view direction the ring
/// is seen (nearly) edge-on, where ray–plane hits run away to infinity.
pub const EDGE_ON: f32 = 0.2;

/// For a ring seen edge-on: the unit screen direction in which the ring's
/// front point moves when the angle grows (the projection of axis × view)
/// and the ring's radius in pixels along it. The drag then turns by the
/// mouse's motion along that direction over the radius, so the front of
/// the ring follows the mouse. `None` when the ring faces the eye enough
/// for ray–plane dragging.
pub fn edge_on_drag(
    proj: &Projector,
    h: Handle,
    pivot: Vec3,
    back: Vec3,
) -> Option<((f32, f32), f32)> {
    let (n, _, _) = basis(h, back)?;
    if n.dot(back).abs() >= EDGE_ON {
        return None;
    }
    let t = n.cross(back).normalize_or_zero();
    let a = proj.point(pivot)?;
    let b = proj.point(pivot + t * radius(proj, h, pivot))?;
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l = (dx * dx + dy * dy).sqrt();
    (l > 1.0).then(|| ((dx / l, dy / l), l))
}

/// Whether pixel (x, y) is inside the disc the axis rings outline (where a
/// drag turns freely).
pub fn in_trackball(proj: &Projector, pivot: Vec3, x: f32, y: f32) -> bool {
    proj.point(pivot).is_some_and(|c| {
        ((x - c.0).powi(2) + (y - c.1).powi(2)).sqrt() < RING_PX * proj.px_scale() - GRAB_PX
    })
}

/// The trackball point under pixel (x, y): where the mouse ray first meets
/// the sphere of radius `r` about the pivot, or when it misses, the point
/// of the sphere's rim nearest the ray (so the drag continues outside).
pub fn sphere_point(proj: &Projector, pivot: Vec3, r: f32, x: f32, y: f32) -> Option<Vec3> {
    let (ro, rd) = pixel_ray(proj, x, y);
    let oc = ro - pivot;
    let b = oc.dot(rd);
    let disc = b * b - (oc.dot(oc) - r * r);
    if disc >= 0.0 {
        let t = -b - disc.sqrt();
        if t >= 0.0 {
            return Some(ro + rd * t);
        }
    }
    let p = ro + rd * (-b).max(0.0);
    let v = (p - pivot).normalize_or_zero();
    (v != Vec3::ZERO).then(|| pivot + v * r)
}

/// Axis and angle of the shortest turn taking direction `a` onto `b`
/// (the arcball of Shoemake, "ARCBALL", Graphics Interface 1992, without
/// its angle doubling: the grabbed point follows the mouse).
pub fn arc(a: Vec3, b: Vec3) -> (Vec3, f32) {
    let axis = a.cross(b).normalize_or_zero();
    if axis == Vec3::ZERO {
        return (Vec3::X, 0.0);
    }
    (axis, angle_about(axis, a, b))
}

/// The angle from grab point `a` to current point `b` about ring axis `n`.
pub fn drag_angle(n: Vec3, pivot: Vec3, a: Vec3, b: Vec3) -> f32 {
    angle_about(n, a - pivot, b - pivot)
}

/// `shown` turned by `angle` about world axis `n`; `to_local` maps world to
/// the node's parent space (objects) or the light's node space (lights).
/// `None` when there is nothing to turn.
pub fn turned(shown: &Node, n: Vec3, angle: f32, to_local: &Mat4) -> Option<Node> {
    let mut node = shown.clone();
    match &mut node.kind {
        NodeKind::Light(l) => {
            let from_local = to_local.inverse();
            let len = l.direction.length();
            let world = from_local.transform_vector3(l.direction);
            let world = Quat::from_axis_angle(n, angle) * world;
            l.direction = to_local.transform_vector3(world).normalize_or_zero() * len;
            if l.direction == Vec3::ZERO {
                return None;
            }
        }
        _ => {
            // The axis in parent space; a mirroring parent turns the other way.
            let ap = to_local.transform_vector3(n).normalize_or_zero();
            if ap == Vec3::ZERO {
                return None;
            }
            let sign = if to_local.determinant() < 0.0 {
                -1.0
            } else {
                1.0
            };
            let q = Quat::from_axis_angle(ap, angle * sign);
            node.transform.rotation = (q * shown.transform.rotation).normalize();
        }
    }
    Some(node)
}

/// Draws the rings (back halves dim and thin), `hot` highlighted.
pub fn draw(p: &mut Painter, proj: &Projector, pivot: Vec3, back: Vec3, hot: Option<Handle>) {
    for h in [
        Handle::ViewRing,
        Handle::Ring(0),
        Handle::Ring(1),
        Handle::Ring(2),
    ] {
        let base = match h {
            Handle::Ring(i) => AXIS_COLORS[i as usize],
            _ => VIEW_RING,
        };
        let is_hot = hot == Some(h);
        for (a, b, front) in segments(proj, h, pivot, back) {
            if front {
                p.line(a, b, if is_hot { HOT } else { base }, 2.0);
            } else {
                p.line(a, b, dim(base), 1.0);
            }
        }
    }
    if let Some(c) = proj.point(pivot) {
        p.fill_circle(c, 3.0, 0xffffff);
    }
}

/// A colour at half brightness (the far side of a ring).
fn dim(c: u32) -> u32 {
    (c >> 1) & 0x7f7f7f
}

#[cfg(test)]
mod tests {
    use super::super::geom::tests::projector;
    use super::*;
    use crate::scene::{Light, Transform};

    fn back(p: &Projector) -> Vec3 {
        // The projector's eye is at (4, 3, 6) looking at the origin.
        let _ = p;
        Vec3::new(4.0, 3.0, 6.0).normalize()
    }

    #[test]
    fn ring_drag_angle_matches_the_arc_and_follows_the_mouse() {
        let p = projector();
        let pivot = Vec3::new(0.3, 0.2, -0.1);
        let bk = back(&p);
        for h in [
            Handle::Ring(0),
            Handle::Ring(1),
            Handle::Ring(2),
            Handle::ViewRing,
        ] {
            let (n, _, _) = basis(h, bk).unwrap();
            let (t0, t1) = (0.4f32, 1.3f32);
            let g0 = ring_point(&p, h, pivot, bk, t0).unwrap();
            let g1 = ring_point(&p, h, pivot, bk, t1).unwrap();
            let m0 = p.point(g0).unwrap();
            let m1 = p.point(g1).unwrap();
            let a = grab_point(&p, h, pivot, bk, m0.0, m0.1).unwrap();
            let b = grab_point(&p, h, pivot, bk, m1.0, m1.1).unwrap();
            let ang = drag_angle(n, pivot, a, b);
            assert!((ang - (t1 - t0)).abs() < 1e-3, "{h:?}: angle {ang}");
            // The grabbed point, turned by the angle, lands under the mouse.
            let turned = pivot + Quat::from_axis_angle(n, ang) * (a - pivot);
            let seen = p.point(turned).unwrap();
            assert!(
                (seen.0 - m1.0).abs() < 0.05 && (seen.1 - m1.1).abs() < 0.05,
                "{h:?}: grabbed point at {seen:?}, mouse at {m1:?}"
            );
        }
    }

    #[test]
    fn trackball_turns_the_grabbed_sphere_point_under_the_mouse() {
        let p = projector();
        let pivot = Vec3::new(0.2, 0.1, 0.3);
        let r = 0.8;
        let eye = Vec3::new(4.0, 3.0, 6.0);
        // Two points of the sphere's front (facing the eye).
        let front = |d: Vec3| pivot + (d + (eye - pivot).normalize() * 1.5).normalize() * r;
        let g0 = front(Vec3::new(0.3, 0.2, -0.1));
        let g1 = front(Vec3::new(-0.4, -0.1, 0.3));
        let m0 = p.point(g0).unwrap();
        let m1 = p.point(g1).unwrap();
        let a = sphere_point(&p, pivot, r, m0.0, m0.1).unwrap();
        let b = sphere_point(&p, pivot, r, m1.0, m1.1).unwrap();
        assert!((a - g0).length() < 1e-3 && (b - g1).length() < 1e-3);
        let (axis, angle) = arc(a - pivot, b - pivot);
        let turned = pivot + Quat::from_axis_angle(axis, angle) * (a - pivot);
        let seen = p.point(turned).unwrap();
        assert!((seen.0 - m1.0).abs() < 0.05 && (seen.1 - m1.1).abs() < 0.05);
        // Off the sphere: the nearest rim point, still at radius r.
        let far = sphere_point(&p, pivot, r, 10.0, 20.0).unwrap();
        assert!(((far - pivot).length() - r).abs() < 1e-4);
        // No motion, no turn.
        assert_eq!(arc(a, a).1, 0.0);
    }

    #[test]
    fn turning_a_child_composes_in_parent_space() {
        // Parent turned a quarter about y: the world x axis is the parent's
        // +z axis (R_y(90°)·z = x), so a world-x turn is a parent-z turn.
        let parent = Mat4::from_quat(Quat::from_rotation_y(std::f32::consts::FRAC_PI_2));
        let mut n = Node::group("c");
        n.transform = Transform::default();
        let out = turned(&n, Vec3::X, 0.5, &parent.inverse()).unwrap();
        let want = Quat::from_rotation_z(0.5);
        assert!(out.transform.rotation.angle_between(want) < 1e-5);
        // In world terms the child turned by 0.5 about world x.
        let world = parent * Mat4::from_quat(out.transform.rotation);
        let expect = Mat4::from_quat(Quat::from_rotation_x(0.5)) * parent;
        assert!(world.abs_diff_eq(expect, 1e-5));
    }

    #[test]
    fn turning_a_spot_turns_its_direction_only() {
        let mut l = Light::spot();
        l.direction = Vec3::new(0.0, 0.0, -2.0);
        let n = Node::new("s", NodeKind::Light(l));
        let out = turned(&n, Vec3::Y, std::f32::consts::FRAC_PI_2, &Mat4::IDENTITY).unwrap();
        let NodeKind::Light(o) = &out.kind else {
            panic!("still a light")
        };
        // −z turned a quarter about +y is −x; the length is kept.
        assert!((o.direction - Vec3::new(-2.0, 0.0, 0.0)).length() < 1e-5);
        assert_eq!(out.transform, n.transform);
    }
}
