//! The IK target's drag as the viewport component holds it (`viewport_ui.rs`):
//! whether a press grabs the target, where a move puts it (in the plane
//! facing the viewer through the end joint), the two joints' rotations
//! that follow (`anim::ik` by the law of cosines), and the target's
//! drawing. Pure: it never names the `Editor`, so the component can hold
//! the drag without importing the editor back (`ik.rs` builds the drag at
//! a press and records what it leaves).

use super::state::IkDrag;
use crate::anim::ik;
use crate::editor::manip::geom::{pixel_ray, ray_plane};
use crate::input::camera::Projector;
use crate::scene::{Node, NodeId};
use crate::ui::{Painter, Rect};
use glam::{Quat, Vec3};

/// The target's colour (the IK handle).
const IK: u32 = 0xf0d040;
/// How close (pixels) a press must be to the end joint to grab the target.
pub const GRAB_PX: f32 = 9.0;

/// Whether a press at (x, y) grabs the target drawn at `end`.
pub fn grabs(end: (f32, f32), x: f32, y: f32) -> bool {
    (end.0 - x).hypot(end.1 - y) <= GRAB_PX
}

/// `local` turned by the world rotation `turn` about its own pivot, for a
/// node whose parent's world rotation is `parent`: P⁻¹·Δ·P·L (exact for
/// parents without non-uniform scale).
pub(super) fn turned_local(parent: Quat, turn: Quat, local: Quat) -> Quat {
    (parent.inverse() * turn * parent * local).normalize()
}

/// The two joints' new local rotations for the target `t`.
fn solve(d: &IkDrag, t: Vec3) -> Option<[Node; 2]> {
    let s = ik::solve(d.chain, t, d.pole)?;
    let mut root = d.posed[0].clone();
    let mut mid = d.posed[1].clone();
    root.transform.rotation = turned_local(d.parent_rot, s.root_turn, root.transform.rotation);
    let root_after = (s.root_turn * d.root_rot).normalize();
    mid.transform.rotation = turned_local(root_after, s.mid_turn, mid.transform.rotation);
    Some([root, mid])
}

/// A move to window pixel (x, y): the target follows the mouse in the
/// drag plane (`None`: the ray misses it, nothing changes); the joints'
/// pose when the chain reaches a solution.
pub fn moved(
    d: &mut IkDrag,
    proj: &Projector,
    x: f32,
    y: f32,
) -> Option<Option<[(NodeId, Node); 2]>> {
    let (ro, rd) = pixel_ray(proj, x, y);
    let t = ray_plane(d.plane.0, d.plane.1, ro, rd)?;
    d.target = t;
    Some(solve(d, t).map(|[root, mid]| [(d.root, root), (d.mid, mid)]))
}

/// Where the target is drawn: where the mouse put it during a drag.
pub fn target(d: &IkDrag) -> Vec3 {
    d.target
}

/// The IK handle: the chain `pts` (root, middle, end joint) in yellow and
/// a diamond at `target`.
pub fn draw(p: &mut Painter, proj: &Projector, vp: Rect, pts: [Vec3; 3], target: Vec3) {
    p.set_clip(Some(vp));
    for w in pts.windows(2) {
        if let Some((a, b)) = proj.segment(w[0], w[1]) {
            p.line(a, b, IK, 1.5);
        }
    }
    if let Some((x, y)) = proj.point(target) {
        let r = 6.0;
        p.fill_polygon(&[(x, y - r), (x + r, y), (x, y + r), (x - r, y)], IK, 220);
    }
    p.set_clip(None);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_turn_in_world_space_becomes_the_local_one() {
        // Parent turned 90° about y: a world turn about z is a local turn
        // about the parent's local axis that maps to world z, i.e. −x.
        let parent = Quat::from_rotation_y(std::f32::consts::FRAC_PI_2);
        let turn = Quat::from_rotation_z(0.3);
        let local = turned_local(parent, turn, Quat::IDENTITY);
        let want = Quat::from_rotation_x(-0.3);
        // (angle_between is an acos: about 3e-4 of noise near zero.)
        assert!(local.angle_between(want) < 1e-3, "{local:?}");
        // And back: parent · local = turn · parent.
        assert!((parent * local).angle_between(turn * parent) < 1e-3);
    }

    #[test]
    fn a_press_grabs_the_target_within_its_radius_only() {
        assert!(grabs((10.0, 10.0), 10.0 + GRAB_PX, 10.0));
        assert!(!grabs((10.0, 10.0), 10.0 + GRAB_PX + 0.5, 10.0));
    }
}
