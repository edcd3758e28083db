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
use crate::scene::{Justify, NodeId, NodeKind, Scene, TextKind, TextSpec};
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
/// matrix; `None` for other nodes and empty or hidden shapes. `picture`:
/// the size of the picture view-all frames, for Text2 labels.
fn own_box(scene: &Scene, pose: &Pose, i: usize, picture: Option<(u32, u32)>) -> Option<XfBox> {
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
    // Coin's box is its pixel rectangle as the camera before view-all
    // sees it; without a picture size only its anchor counts.
    let label = mesh
        .text
        .as_deref()
        .filter(|t| t.kind == TextKind::Text2 && t.units_per_pixel > 0.0);
    let (lo, hi) = match (label, picture) {
        (Some(t), Some(px)) => {
            let (lo, hi) = label_extent(t, geo.positions)?;
            return label_box(lo, hi, geo.world, t.units_per_pixel, px);
        }
        (Some(_), None) => (Vec3::ZERO, Vec3::ZERO),
        (None, _) => {
            let (mut lo, mut hi) = points_bounds(geo.positions)?;
            if let Some(top) = mesh.text.as_deref().and_then(text_top) {
                hi.y = hi.y.max(top);
            }
            // Coin's box of a text spans its lines' advances along x, not
            // the ink (probed through pivy with the Liberation faces: a
            // VRML97 "x" is 0.5 wide at size 1, its advance; Text3 "Maxi"
            // centred at size 10 spans ±10.625, the sum of its advances as
            // Coin rounds them at 40 ppem; the font's sum is 21.11).
            if let Some([x0, x1]) = mesh
                .text
                .as_deref()
                .and_then(crate::format::text::advance_span)
            {
                lo.x = lo.x.min(x0);
                hi.x = hi.x.max(x1);
            }
            (lo, hi)
        }
    };
    (geo.world.is_finite()).then_some(XfBox {
        lo,
        hi,
        m: geo.world,
    })
}

/// The top of a VRML97 `Text`'s box as Coin's `SoGetBoundingBoxAction`
/// measures it: `size` above the first baseline, whatever glyphs the
/// first line holds (probed through pivy: "x", "X", "sphere should be
/// yellow" and two lines all reach y = size; size 2 reaches 2), where our
/// glyphs' ink reaches ~0.7 size. Only for horizontal, top-to-bottom text
/// with the minor justification FIRST (the default), whose first baseline
/// is y = 0 (VRML97 §6.20.3); the rest of the box is the glyphs' own.
fn text_top(t: &TextSpec) -> Option<f32> {
    let plain = t.kind == TextKind::Text
        && t.horizontal
        && t.top_to_bottom
        && t.justify[1] == Justify::First;
    (plain && t.size.is_finite() && t.size > 0.0).then_some(t.size)
}

/// Coin's box of an Inventor Text2 label for view-all (`SoText2`'s
/// bounding box, probed through pivy; tests below): the label's pixel
/// rectangle (`lo..hi` in local units, `units_per_pixel` of them a pixel)
/// as the camera *before* view-all sees it — Coin's default perspective
/// camera at (0, 0, 1) looking down −z, heightAngle 45°, near 1, far 10, in
/// a viewport of the picture's size — taken back to the anchor's depth and
/// into the label's frame. Coin truncates the anchor's pixel position
/// (from the viewport's lower left) toward zero, and gives no box when the
/// anchor is outside near..far or the rectangle misses the viewport.
fn label_box(
    lo: Vec3,
    hi: Vec3,
    world: Mat4,
    units_per_pixel: f32,
    (w, h): (u32, u32),
) -> Option<XfBox> {
    let eye = world.transform_point3(Vec3::ZERO) - Vec3::Z;
    let depth = -eye.z;
    if !(1.0..=10.0).contains(&depth) || w == 0 || h == 0 {
        return None;
    }
    let (wf, hf) = (w as f32, h as f32);
    // Eye units per pixel at that depth (the angle spans the smaller side).
    let upp = 2.0 * depth * libm::tanf(std::f32::consts::FRAC_PI_8) / wf.min(hf);
    let sx = (wf * 0.5 + eye.x / upp).trunc();
    let sy = (hf * 0.5 + eye.y / upp).trunc();
    let (x0, x1) = (sx + lo.x / units_per_pixel, sx + hi.x / units_per_pixel);
    let (y0, y1) = (sy + lo.y / units_per_pixel, sy + hi.y / units_per_pixel);
    // Measured edges: a rectangle touching the viewport's bottom or top
    // edge counts, one touching its left or right edge does not.
    if !(x1 > 0.0 && x0 < wf && y1 >= 0.0 && y0 <= hf) {
        return None;
    }
    let to_local = world.inverse();
    let corner = |x: f32, y: f32| {
        let p = Vec3::new((x - wf * 0.5) * upp, (y - hf * 0.5) * upp, -depth) + Vec3::Z;
        to_local.transform_point3(p)
    };
    let pts = [
        corner(x0, y0),
        corner(x1, y0),
        corner(x0, y1),
        corner(x1, y1),
    ];
    let (lo, hi) = points_bounds(&pts)?;
    Some(XfBox { lo, hi, m: world })
}

/// A Text2 label's box in its local units: the whole pixels of its bitmap
/// (`text::bitmap::pixel_box`, as Coin's box is the union of its glyph
/// bitmaps), or the box of `positions` for a label drawn from outlines.
fn label_extent(t: &TextSpec, positions: &[Vec3]) -> Option<(Vec3, Vec3)> {
    let u = t.units_per_pixel;
    match crate::format::text::bitmap::pixel_box(t) {
        Some((lo, hi)) if u.is_finite() && u > 0.0 => Some((
            Vec3::new(lo[0] * u, lo[1] * u, 0.0),
            Vec3::new(hi[0] * u, hi[1] * u, 0.0),
        )),
        _ => points_bounds(positions),
    }
}

/// The world box of the Text2 label `t` whose glyphs span `positions`
/// (local units, `t.units_per_pixel` of them a pixel) under `world`, as
/// view-all of a `picture` counts it ([`label_box`]); `None` when that
/// view-all would not count it.
pub(super) fn label_world(
    t: &TextSpec,
    positions: &[Vec3],
    world: Mat4,
    picture: (u32, u32),
) -> Option<(Vec3, Vec3)> {
    // NaN or infinite scales too (speed's review).
    let units_per_pixel = t.units_per_pixel;
    if !units_per_pixel.is_finite() || units_per_pixel <= 0.0 {
        return None;
    }
    let (lo, hi) = label_extent(t, positions)?;
    label_box(lo, hi, world, units_per_pixel, picture).map(|b| b.world())
}

/// World-space bounds of every visible shape, merged as Coin merges them
/// (see the module doc); `None` when nothing is visible. `picture`: the
/// picture's size in pixels when view-all frames one (Text2 labels then
/// count as Coin counts them, [`label_box`]).
pub fn coin_scene_bounds(
    scene: &Scene,
    pose: &Pose,
    picture: Option<(u32, u32)>,
) -> Option<(Vec3, Vec3)> {
    let order = scene.walk();
    let mut boxes: Vec<Option<XfBox>> = vec![None; scene.nodes.len()];
    // Reverse pre-order: every child is done before its parent.
    for &id in order.iter().rev() {
        let i = id.0 as usize;
        let mut acc = own_box(scene, pose, i, picture);
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
        let (lo, hi) = coin_scene_bounds(&s, &pose, None).unwrap();
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

    /// Coin's box of a VRML97 Text reaches `size` above the first baseline
    /// (pivy: "x" at size 1 → y 0..1, at size 2 → 0..2; two lines "x", "x"
    /// → −1..1); the rest is the glyphs' own. Other minor justifications
    /// and vertical text keep the glyphs' box.
    #[test]
    fn vrml97_text_boxes_reach_size_above_the_first_baseline() {
        use crate::scene::{Justify, Mesh, TextSpec};
        let bounds = |spec: TextSpec| {
            let mut s = Scene::new();
            let material = s.add_material(Material::default());
            // Ink of an "x" and of a second line's "x" below it.
            let mut m = Mesh {
                positions: vec![
                    Vec3::new(0.02, -0.01, 0.0),
                    Vec3::new(0.48, 0.46, 0.0),
                    Vec3::new(0.02, -1.01, 0.0),
                ],
                triangles: vec![[0, 1, 2]],
                ..Mesh::default()
            };
            m.text = Some(Box::new(spec));
            let mesh = s.add_mesh(m);
            s.add_node(
                None,
                Node::new("t", NodeKind::Shape(Shape { mesh, material })),
            );
            let pose = crate::anim::evaluate(&s, 0.0);
            coin_scene_bounds(&s, &pose, None).unwrap()
        };
        let spec = |size: f32| TextSpec {
            strings: vec!["x".into(), "x".into()],
            size,
            ..TextSpec::default()
        };
        let (lo, hi) = bounds(spec(1.0));
        assert_eq!((lo.y, hi.y), (-1.01, 1.0));
        // Along x the box is the line's advance (a serif "x" is 0.5 em
        // wide), not its ink, as in Coin.
        assert_eq!((lo.x, hi.x), (0.0, 0.5));
        assert_eq!(bounds(spec(2.0)).1, Vec3::new(1.0, 2.0, 0.0));
        // Ink reaching past the advance keeps its extent.
        assert_eq!(bounds(spec(0.25)).1.x, 0.48);
        // Ink taller than `size` keeps its top.
        assert_eq!(bounds(spec(0.25)).1.y, 0.46);
        let middle = TextSpec {
            justify: [Justify::Begin, Justify::Middle],
            ..spec(1.0)
        };
        assert_eq!(bounds(middle).1.y, 0.46);
        let vertical = TextSpec {
            horizontal: false,
            ..spec(1.0)
        };
        // Vertical text keeps its ink along x.
        let (vlo, vhi) = bounds(vertical);
        assert_eq!((vhi.y, vlo.x), (0.46, 0.02));
        let label = TextSpec {
            kind: TextKind::AsciiText,
            ..spec(1.0)
        };
        assert_eq!(bounds(label).1.y, 0.46);
    }

    /// Coin 4's box (pivy, SoGetBoundingBoxAction after a default
    /// SoPerspectiveCamera, 160×120) of a Courier `Text2` "quick", size 20,
    /// at (0, 0, −1): x 0.0138..0.8146, y −0.0552..0.1795 (1..59 and
    /// −4..13 pixels of 0.0138 at depth 2). Ours comes from our own glyphs
    /// (Liberation Mono, Courier's widths), so within a pixel or two.
    #[test]
    fn text2_boxes_are_coins_pixel_rectangles() {
        let b = |at: Vec3, size: (u32, u32)| {
            let upp = 0.05; // local units per pixel of the mesh
            let (lo, hi) = (
                Vec3::new(1.0, -4.0, 0.0) * upp,
                Vec3::new(59.0, 13.0, 0.0) * upp,
            );
            label_box(lo, hi, Mat4::from_translation(at), upp, size).map(|x| x.world())
        };
        let close = |a: Vec3, b: Vec3| (a - b).length() < 1e-3;
        let (lo, hi) = b(Vec3::new(0.0, 0.0, -1.0), (160, 120)).unwrap();
        assert!(close(lo, Vec3::new(0.0138, -0.0552, -1.0)), "{lo}");
        assert!(close(hi, Vec3::new(0.8146, 0.1795, -1.0)), "{hi}");
        // The anchor's pixel is truncated: x = 1 is 152.43 px → 152.
        let (lo, _) = b(Vec3::new(1.0, 0.0, -1.0), (160, 120)).unwrap();
        assert!((lo.x - 1.0079).abs() < 1e-3, "{lo}");
        // The smaller side sets the scale (120×160 as 160×120), 320×240 halves it.
        assert_eq!(
            b(Vec3::new(0.0, 0.0, -1.0), (120, 160)),
            b(Vec3::new(0.0, 0.0, -1.0), (160, 120))
        );
        let (_, hi) = b(Vec3::new(0.0, 0.0, -1.0), (320, 240)).unwrap();
        assert!((hi.x - 0.4073).abs() < 1e-3, "{hi}");
        // No box: nearer than 1 or beyond 10 from the camera, or outside
        // the viewport (Coin's edges: the anchor at pixel row −13 puts the
        // top on the bottom edge and counts, −14 does not; at column −59
        // the right end is on the left edge and does not count, −58 does).
        let px = |x: f32, y: f32| Vec3::new((x - 80.0) * 0.0138071, (y - 60.0) * 0.0138071, -1.0);
        for at in [
            Vec3::new(0.0, 0.0, 0.5),
            Vec3::new(0.0, 0.0, -10.0),
            Vec3::new(1.5, 0.0, -1.0),
            Vec3::new(1.0, 1.0, -1.0),
            px(0.0, -14.5),
            px(-59.5, 0.0),
            px(159.5, 0.0),
            px(0.0, 125.5),
        ] {
            assert_eq!(b(at, (160, 120)), None, "{at}");
        }
        for at in [
            px(0.0, -13.5),
            px(-58.5, 0.0),
            px(158.5, 0.0),
            px(0.0, 124.5),
        ] {
            assert!(b(at, (160, 120)).is_some(), "{at}");
        }
        let (lo, hi) = b(px(0.0, -13.5), (160, 120)).unwrap();
        assert!(
            (lo.y + 1.0631).abs() < 1e-3 && (hi.y + 0.8284).abs() < 1e-3,
            "{lo} {hi}"
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
