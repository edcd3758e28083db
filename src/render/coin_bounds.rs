//! The scene's bounding box the way Coin's `SoGetBoundingBoxAction`
//! builds it, so that view-all frames a file as Coin does.
//!
//! Coin keeps each box in its own frame together with a matrix (an
//! `SbXfBox3f`) and merges boxes group by group: a box with the same matrix
//! is a plain union in that frame; with another matrix, Coin extends either
//! box by the other's eight corners (each in the other's frame) and keeps
//! the one with the smaller volume (`SbXfBox3f::extendBy`). Only at the end
//! is the box taken to world space (`project`). For a rotated group this is
//! larger than the union of each shape's own world box (a cube and a sphere
//! under one rotation: the box of their union, rotated), and Coin's camera
//! stands back accordingly. Learned from Coin 4's `SbXfBox3f.cpp`,
//! `SoGetBoundingBoxAction.cpp` and `SoSeparator.cpp`; each scene node here
//! plays a Separator's part (its children merged in order, then handed to
//! its parent).

use super::geometry::Geometry;
use super::view::points_bounds;
use crate::anim::Pose;
use crate::scene::{NodeId, NodeKind, Scene, TextKind};
use glam::{Mat4, Vec3};

/// A box in the frame of `m` (that frame → world).
#[derive(Clone, Copy, Debug, PartialEq)]
struct XfBox {
    lo: Vec3,
    hi: Vec3,
    m: Mat4,
}

impl XfBox {
    fn corners(&self) -> [Vec3; 8] {
        std::array::from_fn(|k| {
            Vec3::new(
                if k & 1 == 0 { self.lo.x } else { self.hi.x },
                if k & 2 == 0 { self.lo.y } else { self.hi.y },
                if k & 4 == 0 { self.lo.z } else { self.hi.z },
            )
        })
    }

    /// This box grown by `other`'s corners, taken into this box's frame.
    fn grown_by(&self, other: &XfBox) -> Option<XfBox> {
        let to_here = self.m.inverse() * other.m;
        let mut out = *self;
        for c in other.corners() {
            let p = to_here.transform_point3(c);
            if !p.is_finite() {
                return None;
            }
            (out.lo, out.hi) = (out.lo.min(p), out.hi.max(p));
        }
        Some(out)
    }

    /// Coin's `SbXfBox3f::getVolume`: the box's volume times |det| of the
    /// matrix's 3×3 part, 0 for a box flat in some direction.
    fn volume(&self) -> f32 {
        let d = self.hi - self.lo;
        if d.x <= 0.0 || d.y <= 0.0 || d.z <= 0.0 {
            return 0.0;
        }
        (d.x * d.y * d.z * glam::Mat3::from_mat4(self.m).determinant()).abs()
    }

    /// For flat boxes Coin compares the spans scaled by the lengths of the
    /// matrix's rows (its columns in Coin's row-vector matrices), a zero
    /// span counting as 1.
    fn flat_measure(&self) -> f32 {
        let d = self.hi - self.lo;
        let r = self.m.transpose();
        let s = [r.x_axis, r.y_axis, r.z_axis].map(|row| row.truncate().length());
        let f = |v: f32| if v != 0.0 { v } else { 1.0 };
        (f(d.x * s[0]) * f(d.y * s[1]) * f(d.z * s[2])).abs()
    }

    /// `SbXfBox3f::extendBy`: the smaller of "this grown by other" and
    /// "other grown by this" (ties go to the second, as in Coin).
    fn extend(self, other: XfBox) -> XfBox {
        if self.m == other.m {
            return XfBox {
                lo: self.lo.min(other.lo),
                hi: self.hi.max(other.hi),
                m: self.m,
            };
        }
        match (self.grown_by(&other), other.grown_by(&self)) {
            (Some(a), Some(b)) => {
                let (va, vb) = (a.volume(), b.volume());
                let first = if va != 0.0 || vb != 0.0 {
                    va < vb
                } else {
                    a.flat_measure() < b.flat_measure()
                };
                if first {
                    a
                } else {
                    b
                }
            }
            (Some(a), None) => a,
            (None, Some(b)) => b,
            // Both matrices singular: fall back to world boxes.
            (None, None) => {
                let (a, b) = (self.world(), other.world());
                XfBox {
                    lo: a.0.min(b.0),
                    hi: a.1.max(b.1),
                    m: Mat4::IDENTITY,
                }
            }
        }
    }

    /// `SbXfBox3f::project`: the world box around the transformed corners.
    fn world(&self) -> (Vec3, Vec3) {
        let mut pts = self
            .corners()
            .map(|c| self.m.transform_point3(c))
            .into_iter();
        let first = pts.next().expect("8 corners");
        pts.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p)))
    }
}

fn merge(acc: Option<XfBox>, b: Option<XfBox>) -> Option<XfBox> {
    match (acc, b) {
        (Some(a), Some(b)) => Some(a.extend(b)),
        (a, b) => a.or(b),
    }
}

/// The box of one visible shape node in its own frame, with its world
/// matrix; `None` for other nodes and empty or hidden shapes.
fn own_box(scene: &Scene, pose: &Pose, i: usize) -> Option<XfBox> {
    let node = &scene.nodes[i];
    let NodeKind::Shape(shape) = &node.kind else {
        return None;
    };
    if !pose.visible.get(i).copied().unwrap_or(node.visible) {
        return None;
    }
    let mesh = scene.meshes.get(shape.mesh.0 as usize)?;
    let world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
    let geo = Geometry::of(mesh, pose, NodeId(i as u32), world);
    // An Inventor Text2 label is drawn at a pixel size, not a scene size:
    // only its anchor counts.
    let label = matches!(mesh.text.as_deref(), Some(t) if t.kind == TextKind::Text2);
    let (lo, hi) = if label {
        (Vec3::ZERO, Vec3::ZERO)
    } else {
        points_bounds(geo.positions)?
    };
    (geo.world.is_finite()).then_some(XfBox {
        lo,
        hi,
        m: geo.world,
    })
}

/// World-space bounds of every visible shape, merged as Coin merges them
/// (see the module doc); `None` when nothing is visible.
pub fn coin_scene_bounds(scene: &Scene, pose: &Pose) -> Option<(Vec3, Vec3)> {
    let order = scene.walk();
    let mut boxes: Vec<Option<XfBox>> = vec![None; scene.nodes.len()];
    // Reverse pre-order: every child is done before its parent.
    for &id in order.iter().rev() {
        let i = id.0 as usize;
        let mut acc = own_box(scene, pose, i);
        for c in &scene.nodes[i].children {
            acc = merge(acc, boxes.get(c.0 as usize).copied().flatten());
        }
        boxes[i] = acc;
    }
    let mut acc = None;
    for r in &scene.roots {
        acc = merge(acc, boxes.get(r.0 as usize).copied().flatten());
    }
    let (lo, hi) = acc?.world();
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{primitives, Material, Node, Shape, Transform};
    use glam::Quat;

    /// Coin's own example: a 3×4×5 cube and a sphere of radius 2 under one
    /// rotation and scale (Toolmaker's volume.iv). Coin bounds the union
    /// of the two local boxes, rotated — larger than the two world boxes.
    #[test]
    fn one_rotation_bounds_the_union_of_local_boxes() {
        let mut s = Scene::new();
        let material = s.add_material(Material::default());
        let cube = s.add_mesh(primitives::box_mesh(Vec3::new(3.0, 4.0, 5.0)));
        let ball = s.add_mesh(primitives::box_mesh(Vec3::splat(4.0)));
        let t = Transform {
            rotation: Quat::from_axis_angle(Vec3::ONE.normalize(), 0.5),
            scale: Vec3::new(2.0, 1.0, 1.0),
            ..Default::default()
        };
        let root = s.add_node(None, Node::group("root").with_transform(t));
        for (name, mesh) in [("cube", cube), ("ball", ball)] {
            s.add_node(
                Some(root),
                Node::new(name, NodeKind::Shape(Shape { mesh, material })),
            );
        }
        let pose = crate::anim::evaluate(&s, 0.0);
        let (lo, hi) = coin_scene_bounds(&s, &pose).unwrap();
        let m = pose.world[root.0 as usize];
        let union = XfBox {
            lo: Vec3::new(-2.0, -2.0, -2.5),
            hi: Vec3::new(2.0, 2.0, 2.5),
            m,
        }
        .world();
        assert!((lo - union.0).length() < 1e-5 && (hi - union.1).length() < 1e-5);
        // Each shape's own world box is smaller.
        let shapes = super::super::view::shape_bounds(&s, &pose);
        let (plo, phi) = shapes
            .iter()
            .fold((hi, lo), |(a, b), s| (a.min(s.1), b.max(s.2)));
        assert!(
            hi.y - lo.y > phi.y - plo.y + 0.1,
            "{lo} {hi} vs {plo} {phi}"
        );
    }

    /// Different matrices: the smaller of the two candidate boxes is kept.
    #[test]
    fn different_frames_keep_the_smaller_candidate() {
        let unit = |m| XfBox {
            lo: Vec3::splat(-1.0),
            hi: Vec3::splat(1.0),
            m,
        };
        let a = unit(Mat4::IDENTITY);
        let b = unit(Mat4::from_scale_rotation_translation(
            Vec3::splat(0.1),
            Quat::from_rotation_z(0.7),
            Vec3::new(3.0, 0.0, 0.0),
        ));
        // Growing the big box by the small one is far smaller than growing
        // the small rotated one by the big one.
        let e = a.extend(b);
        assert_eq!(e.m, Mat4::IDENTITY);
        assert!((e.hi.x - (3.0 + 0.1 * (0.7f32.cos() + 0.7f32.sin()))).abs() < 1e-5);
        assert_eq!(b.extend(a).m, Mat4::IDENTITY);
    }
}
