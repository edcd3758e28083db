//! Analytic two-bone inverse kinematics: the editor's IK handle (issue 13
//! item 7) moves an end joint to a target by turning its parent and
//! grandparent, as an arm bends at the elbow.
//!
//! The construction is the planar two-link solution by the law of
//! cosines (e.g. Craig, *Introduction to Robotics*, §4.4 "the planar
//! 2-link arm"): with upper length a, lower length b and root-to-target
//! distance d, the angle α at the root between the root→target line and
//! the upper bone satisfies
//!
//! ```text
//! b² = a² + d² − 2·a·d·cos α   ⇒   cos α = (a² + d² − b²) / (2·a·d)
//! ```
//!
//! The middle joint goes to `root + a·(cos α·t̂ + sin α·n̂)`, where t̂ points
//! at the target and n̂ is the bend (pole) direction made perpendicular to
//! t̂; the end joint goes to `root + d·t̂`. d is clamped to
//! [|a − b|, a + b] so an unreachable target gives the straight (or fully
//! folded) arm pointing at it, never NaN. The two joints' turns are the
//! shortest rotations taking the old bone directions to the new ones
//! (upper first, then the lower bone as the upper's turn carried it), so
//! the bones keep their lengths exactly and twist as little as possible.
//!
//! Pure maths on world positions; the editor turns the world rotations
//! into local keys (`editor/rig/ik.rs`).

use glam::{Quat, Vec3};

/// Lengths and distances below this are treated as zero (a bone of no
/// length cannot be aimed).
const TINY: f32 = 1e-6;

/// The three joints of a two-bone chain, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Chain {
    /// The grandparent (shoulder, hip).
    pub root: Vec3,
    /// The parent (elbow, knee).
    pub mid: Vec3,
    /// The joint that should reach the target (wrist, ankle).
    pub end: Vec3,
}

/// What the solver found: world-space turns of the root and middle joint
/// about their own pivots, and where the joints end up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solution {
    /// Turn of the root joint (applied first).
    pub root_turn: Quat,
    /// Turn of the middle joint, in world space after the root's turn.
    pub mid_turn: Quat,
    pub mid: Vec3,
    pub end: Vec3,
    /// The target was out of reach (too far or too close): the chain
    /// points at it as far as it can.
    pub clamped: bool,
}

/// Solves the chain for `target`. `pole` is the bend direction: the
/// middle joint goes to the side of the root→target line it points to
/// (any vector; its part along that line is ignored). When `pole` is
/// along the line, the chain's current bend is kept, and failing that any
/// perpendicular. `None` when a bone has no length or the target sits on
/// the root.
pub fn solve(chain: Chain, target: Vec3, pole: Vec3) -> Option<Solution> {
    let upper = chain.mid - chain.root;
    let lower = chain.end - chain.mid;
    let (a, b) = (upper.length(), lower.length());
    let to_target = target - chain.root;
    let dist = to_target.length();
    if a < TINY || b < TINY || dist < TINY || !dist.is_finite() {
        return None;
    }
    let t = to_target / dist;
    let lo = (a - b).abs();
    let hi = a + b;
    let d = dist.clamp(lo, hi);
    let clamped = d != dist;
    let n = bend_direction(t, pole)
        .or_else(|| bend_direction(t, upper))
        .unwrap_or_else(|| t.any_orthonormal_vector());
    // Law of cosines for the angle at the root; the clamp above keeps the
    // ratio in [-1, 1] up to rounding, which the second clamp removes.
    let cos_a = ((a * a + d * d - b * b) / (2.0 * a * d)).clamp(-1.0, 1.0);
    let sin_a = (1.0 - cos_a * cos_a).max(0.0).sqrt();
    let mid = chain.root + a * (cos_a * t + sin_a * n);
    let end = chain.root + d * t;
    let root_turn = Quat::from_rotation_arc(upper / a, (mid - chain.root) / a);
    let carried = root_turn * lower;
    let mid_turn = Quat::from_rotation_arc(carried / b, (end - mid) / (end - mid).length());
    Some(Solution {
        root_turn: root_turn.normalize(),
        mid_turn: mid_turn.normalize(),
        mid,
        end,
        clamped,
    })
}

/// `v` made perpendicular to the unit vector `t` and normalised; `None`
/// when `v` is (nearly) along `t`.
fn bend_direction(t: Vec3, v: Vec3) -> Option<Vec3> {
    let p = v - v.dot(t) * t;
    let len = p.length();
    (len > TINY * v.length().max(1.0) && len.is_finite()).then(|| p / len)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    /// Equal rotations (q and −q are the same turn).
    fn same(a: Quat, b: Quat) -> bool {
        a.abs_diff_eq(b, 1e-5) || a.abs_diff_eq(-b, 1e-5)
    }

    fn arm() -> Chain {
        Chain {
            root: Vec3::ZERO,
            mid: Vec3::Y,
            end: 2.0 * Vec3::Y,
        }
    }

    #[test]
    fn hand_computed_right_angle() {
        // a = b = 1, target (1, 1, 0): d = √2, cos α = (1 + 2 − 1)/(2√2)
        // = 1/√2, α = 45°. t̂ = (1,1,0)/√2, pole +y → n̂ = (−1,1,0)/√2, so
        // mid = cos45·t̂ + sin45·n̂ = (0, 1, 0): the upper bone stays and
        // the lower turns −90° about z to point along +x.
        let s = solve(arm(), Vec3::new(1.0, 1.0, 0.0), Vec3::Y).unwrap();
        assert!(close(s.mid, Vec3::Y), "{:?}", s.mid);
        assert!(close(s.end, Vec3::new(1.0, 1.0, 0.0)), "{:?}", s.end);
        assert!(same(s.root_turn, Quat::IDENTITY), "{:?}", s.root_turn);
        let want = Quat::from_rotation_z(-std::f32::consts::FRAC_PI_2);
        assert!(same(s.mid_turn, want), "{:?}", s.mid_turn);
        assert!(!s.clamped);
    }

    #[test]
    fn the_pole_chooses_the_side_of_the_bend() {
        // Target straight up at distance √2 (a = b = 1): α = 45° either
        // side; the middle joint goes to +x with pole +x, −x with pole −x.
        let target = Vec3::new(0.0, 2f32.sqrt(), 0.0);
        let h = 0.5f32.sqrt();
        for (pole, x) in [(Vec3::X, h), (-Vec3::X, -h)] {
            let s = solve(arm(), target, pole).unwrap();
            assert!(close(s.mid, Vec3::new(x, h, 0.0)), "{pole}: {:?}", s.mid);
            assert!(close(s.end, target));
        }
    }

    #[test]
    fn turns_move_the_joints_where_the_solution_says() {
        let chain = Chain {
            root: Vec3::new(0.3, -0.2, 0.1),
            mid: Vec3::new(0.5, 0.9, 0.4),
            end: Vec3::new(1.3, 1.5, -0.2),
        };
        let target = Vec3::new(-0.4, 1.1, 0.9);
        let s = solve(chain, target, Vec3::Z).unwrap();
        let mid = chain.root + s.root_turn * (chain.mid - chain.root);
        let end = mid + s.mid_turn * (s.root_turn * (chain.end - chain.mid));
        assert!(close(mid, s.mid) && close(end, s.end));
        assert!(close(s.end, target), "reachable: the end reaches it");
        // Bone lengths kept.
        let (a, b) = (
            (chain.mid - chain.root).length(),
            (chain.end - chain.mid).length(),
        );
        assert!(((s.mid - chain.root).length() - a).abs() < 1e-5);
        assert!(((s.end - s.mid).length() - b).abs() < 1e-5);
        // The bend is on the pole's side of the root→target line.
        let t = (target - chain.root).normalize();
        let off = (s.mid - chain.root) - (s.mid - chain.root).dot(t) * t;
        assert!(off.dot(bend_direction(t, Vec3::Z).unwrap()) > 0.0);
    }

    #[test]
    fn out_of_reach_points_straight_at_the_target() {
        let s = solve(arm(), Vec3::new(10.0, 0.0, 0.0), Vec3::Y).unwrap();
        assert!(s.clamped);
        assert!(close(s.mid, Vec3::X) && close(s.end, 2.0 * Vec3::X));
        // Too close for unequal bones (a = 1, b = 0.5: nearest reach 0.5):
        // fully folded, the end half a unit from the root towards the target.
        let short = Chain {
            root: Vec3::ZERO,
            mid: Vec3::Y,
            end: 1.5 * Vec3::Y,
        };
        let s = solve(short, Vec3::new(0.1, 0.0, 0.0), Vec3::Y).unwrap();
        assert!(s.clamped);
        assert!(close(s.end, Vec3::new(0.5, 0.0, 0.0)), "{:?}", s.end);
        assert!(close(s.mid, Vec3::X), "folded straight back: {:?}", s.mid);
    }

    #[test]
    fn a_pole_along_the_line_keeps_the_current_bend() {
        let chain = Chain {
            root: Vec3::ZERO,
            mid: Vec3::new(0.5, 0.5, 0.0),
            end: Vec3::new(0.0, 1.0, 0.0),
        };
        let s = solve(chain, Vec3::new(0.0, 1.2, 0.0), Vec3::Y).unwrap();
        assert!(s.mid.x > 0.0, "still bent towards +x: {:?}", s.mid);
        assert!(close(s.end, Vec3::new(0.0, 1.2, 0.0)));
    }

    #[test]
    fn degenerate_chains_are_refused() {
        let zero = Chain {
            root: Vec3::ZERO,
            mid: Vec3::ZERO,
            end: Vec3::Y,
        };
        assert!(solve(zero, Vec3::X, Vec3::Y).is_none());
        assert!(solve(arm(), Vec3::ZERO, Vec3::Y).is_none());
        assert!(solve(arm(), Vec3::splat(f32::NAN), Vec3::Y).is_none());
    }
}
