//! Translate handles on the selected object or light: three axis arrows
//! and three plane squares at its pivot, hover highlight, and drags that
//! keep the grabbed point under the mouse.
//!
//! An axis drag takes the point of the axis line closest to the mouse ray
//! (closest points of two lines); a plane drag intersects the mouse ray
//! with the plane through the pivot. Either way the pivot moves by exactly
//! the grabbed point's motion, so the object follows the mouse. Ctrl snaps
//! the moved world coordinates to the grid step.
//!
//! During a drag the node is previewed as a [`super::record::Pending`]
//! change (shown over its tracks); the release records one command, with a
//! key in record mode.

use super::camera::Projector;
use super::command::Command;
use super::event::{Key, Mods};
use super::record::Pending;
use super::{ops, Editor};
use crate::anim::Property;
use crate::scene::{LightKind, Node, NodeId, NodeKind};
use crate::ui::Painter;
use glam::{Mat4, Vec3, Vec4};

/// Arrow length on screen, in pixels.
pub const ARROW_PX: f32 = 70.0;
/// How close (pixels) the mouse must be to an arrow to grab it.
const GRAB_PX: f32 = 6.0;
/// Plane squares span this part of the arrow length.
const PLANE_FROM: f32 = 0.25;
const PLANE_TO: f32 = 0.45;

const AXIS_COLORS: [u32; 3] = [0xe04848, 0x5cc040, 0x4c8fe8];
const HOT: u32 = 0xffe040;

/// One grabbable part of the handles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Handle {
    /// Arrow along world axis 0/1/2.
    Axis(u8),
    /// Square in the plane whose normal is world axis 0/1/2.
    Plane(u8),
}

/// Hover and drag state of the handles.
#[derive(Clone, Debug, Default)]
pub struct Manip {
    pub hover: Option<Handle>,
    drag: Option<HandleDrag>,
}

#[derive(Clone, Debug)]
struct HandleDrag {
    handle: Handle,
    id: NodeId,
    /// The node as stored at press (restored before recording).
    stored: Box<Node>,
    /// The node as shown at press (what the drag changes).
    shown: Box<Node>,
    pivot: Vec3,
    /// World point grabbed at press.
    grab: Vec3,
    /// World → the space the moved value lives in (parent space for a
    /// translation, the light's node space for a location).
    to_local: Mat4,
    property: Property,
}

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

/// Distance from `p` to the segment `a`–`b` (pixels).
fn seg_dist(p: (f32, f32), a: (f32, f32), b: (f32, f32)) -> f32 {
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

/// Whether `p` is inside the convex quad `q` (either winding).
fn in_quad(p: (f32, f32), q: &[(f32, f32); 4]) -> bool {
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

/// The two axes spanning the plane with normal axis `n`.
fn plane_axes(n: u8) -> (u8, u8) {
    match n {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    }
}

/// World corners of plane square `n` for a pivot and arrow length.
fn plane_corners(pivot: Vec3, len: f32, n: u8) -> [Vec3; 4] {
    let (a, b) = plane_axes(n);
    let (u, v) = (axis(a) * len, axis(b) * len);
    [
        pivot + u * PLANE_FROM + v * PLANE_FROM,
        pivot + u * PLANE_TO + v * PLANE_FROM,
        pivot + u * PLANE_TO + v * PLANE_TO,
        pivot + u * PLANE_FROM + v * PLANE_TO,
    ]
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

impl Editor {
    /// Node, moved property, pivot and world→value-space matrix of the
    /// selection's handles (`None` without a movable selection).
    fn handle_target(&mut self) -> Option<(NodeId, Property, Vec3, Mat4)> {
        let id = self.selection?;
        let pose = self.pose().clone();
        let world = *pose.world.get(id.0 as usize)?;
        let n = self.posed_node(id);
        match &n.kind {
            NodeKind::Light(l) if l.kind == LightKind::Directional => None,
            NodeKind::Light(l) => Some((
                id,
                Property::LightLocation,
                world.transform_point3(l.location),
                world.inverse(),
            )),
            _ => {
                let parent = n
                    .parent
                    .and_then(|p| pose.world.get(p.0 as usize).copied())
                    .unwrap_or(Mat4::IDENTITY);
                Some((
                    id,
                    Property::Translation,
                    world.w_axis.truncate(),
                    parent.inverse(),
                ))
            }
        }
    }

    /// Pixel positions of the pivot and of the three arrow tips (tests and
    /// scripts aim at them).
    pub fn handle_points(&mut self) -> Option<[(f32, f32); 4]> {
        let (_, _, pivot, _) = self.handle_target()?;
        let proj = self.projector();
        let len = proj.world_per_px(pivot) * ARROW_PX;
        Some([
            proj.point(pivot)?,
            proj.point(pivot + Vec3::X * len)?,
            proj.point(pivot + Vec3::Y * len)?,
            proj.point(pivot + Vec3::Z * len)?,
        ])
    }

    /// The handle under window pixel (x, y).
    pub fn handle_at(&mut self, x: f32, y: f32) -> Option<Handle> {
        if !self.layout().viewport.contains(x, y) {
            return None;
        }
        let (_, _, pivot, _) = self.handle_target()?;
        let proj = self.projector();
        let len = proj.world_per_px(pivot) * ARROW_PX;
        let c = proj.point(pivot)?;
        let mut best: Option<(f32, Handle)> = None;
        for i in 0..3u8 {
            if let Some(tip) = proj.point(pivot + axis(i) * len) {
                let d = seg_dist((x, y), c, tip);
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
            let w = plane_corners(pivot, len, n);
            let q: Option<Vec<(f32, f32)>> = w.iter().map(|&p| proj.point(p)).collect();
            q.is_some_and(|q| in_quad((x, y), &[q[0], q[1], q[2], q[3]]))
        })
    }

    /// The world point under the mouse for `h` (on its axis line or plane).
    fn grab_point(proj: &Projector, h: Handle, pivot: Vec3, x: f32, y: f32) -> Option<Vec3> {
        let (ro, rd) = pixel_ray(proj, x, y);
        match h {
            Handle::Axis(i) => closest_on_line(pivot, axis(i), ro, rd).map(|s| pivot + axis(i) * s),
            Handle::Plane(n) => ray_plane(pivot, axis(n), ro, rd),
        }
    }

    /// Mouse down in the viewport: starts a handle drag when one is hit.
    pub(super) fn handles_press(&mut self, x: f32, y: f32) -> bool {
        let Some(h) = self.handle_at(x, y) else {
            return false;
        };
        let Some((id, property, pivot, to_local)) = self.handle_target() else {
            return false;
        };
        let proj = self.projector();
        let Some(grab) = Self::grab_point(&proj, h, pivot, x, y) else {
            return false;
        };
        self.stop_playback();
        self.manip.drag = Some(HandleDrag {
            handle: h,
            id,
            stored: Box::new(self.scene.node(id).clone()),
            shown: Box::new(self.posed_node(id)),
            pivot,
            grab,
            to_local,
            property,
        });
        self.manip.hover = Some(h);
        true
    }

    /// Mouse move: drags the active handle, or updates the hover highlight.
    /// `Some(redraw)` when the handles took the event.
    pub(super) fn handles_move(&mut self, x: f32, y: f32, mods: Mods) -> Option<bool> {
        let Some(d) = self.manip.drag.clone() else {
            if !matches!(self.drag, super::input::Drag::None) {
                return None;
            }
            let h = self.handle_at(x, y);
            let changed = h != self.manip.hover;
            self.manip.hover = h;
            return changed.then_some(true);
        };
        let proj = self.projector();
        let Some(now) = Self::grab_point(&proj, d.handle, d.pivot, x, y) else {
            return Some(false);
        };
        let mut pivot = d.pivot + (now - d.grab);
        if mods.ctrl {
            let step = {
                let pose = self.pose().clone();
                grid_step(ops::sphere(ops::scene_bounds(&self.scene, &pose)).1)
            };
            let moved: Vec<u8> = match d.handle {
                Handle::Axis(i) => vec![i],
                Handle::Plane(n) => {
                    let (a, b) = plane_axes(n);
                    vec![a, b]
                }
            };
            for i in moved {
                pivot[i as usize] = snap(pivot[i as usize], step);
            }
        }
        let delta = d.to_local.transform_vector3(pivot - d.pivot);
        let mut node = (*d.shown).clone();
        match (&mut node.kind, d.property) {
            (NodeKind::Light(l), Property::LightLocation) => l.location += delta,
            _ => node.transform.translation += delta,
        }
        self.show_moved(d.id, d.property, node);
        Some(true)
    }

    /// Previews `node` (shown over its tracks as a pending change).
    fn show_moved(&mut self, id: NodeId, property: Property, node: Node) {
        let c = Command::SetNode {
            id,
            before: Box::new(self.scene.node(id).clone()),
            after: Box::new(node.clone()),
        };
        self.preview(&c);
        self.pending = Some(Pending {
            id,
            props: vec![property],
            frame: self.frame,
            node: Box::new(self.scene.node(id).clone()),
        });
    }

    /// Mouse up: ends a handle drag as one undo step (with a key in record
    /// mode). False when no handle drag was running.
    pub(super) fn handles_release(&mut self) -> bool {
        let Some(d) = self.manip.drag.take() else {
            return false;
        };
        let after = Box::new(self.scene.node(d.id).clone());
        self.pending = None;
        // Put back the stored node so the command starts from it.
        self.preview(&Command::SetNode {
            id: d.id,
            before: after.clone(),
            after: d.stored.clone(),
        });
        if *after == *d.stored || *after == *d.shown {
            return true;
        }
        let c = Command::SetNode {
            id: d.id,
            before: d.stored,
            after,
        };
        let c = self.recorded(c, &[d.property]);
        let name = ops::display_name(&self.scene, d.id);
        self.execute(&format!("Move {name}"), c);
        true
    }

    /// Keys during a handle drag: Esc cancels it, others are ignored.
    pub(super) fn handles_key(&mut self, key: Key) -> bool {
        let Some(d) = &self.manip.drag else {
            return false;
        };
        if key == Key::Escape {
            let c = Command::SetNode {
                id: d.id,
                before: Box::new(self.scene.node(d.id).clone()),
                after: d.stored.clone(),
            };
            self.manip.drag = None;
            self.pending = None;
            self.preview(&c);
        }
        true
    }

    /// Whether a handle drag is running.
    pub fn handle_dragging(&self) -> bool {
        self.manip.drag.is_some()
    }

    /// Draws the handles of the selection over the viewport.
    pub(super) fn draw_handles(&mut self, p: &mut Painter) {
        if self.mode != super::Mode::Select {
            return;
        }
        let Some((_, _, pivot, _)) = self.handle_target() else {
            return;
        };
        let proj = self.projector();
        let len = proj.world_per_px(pivot) * ARROW_PX;
        let Some(c) = proj.point(pivot) else { return };
        let active = self.manip.drag.as_ref().map(|d| d.handle);
        let hot = active.or(self.manip.hover);
        p.set_clip(Some(self.layout().viewport));
        for n in 0..3u8 {
            let w = plane_corners(pivot, len, n);
            let q: Option<Vec<(f32, f32)>> = w.iter().map(|&x| proj.point(x)).collect();
            if let Some(q) = q {
                let color = if hot == Some(Handle::Plane(n)) {
                    HOT
                } else {
                    AXIS_COLORS[n as usize]
                };
                p.fill_polygon(&q, color, 110);
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
            p.line(c, tip, color, 2.0);
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
        p.fill_circle(c, 3.0, 0xffffff);
        p.set_clip(None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::editor::camera::{look_at, perspective};
    use crate::render::View;

    fn projector() -> Projector {
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
            let grab = Editor::grab_point(&p, Handle::Axis(i), pivot, m0.0, m0.1).unwrap();
            let now = Editor::grab_point(&p, Handle::Axis(i), pivot, m1.0, m1.1).unwrap();
            assert!((grab - g0).length() < 1e-3, "axis {i}: grabbed {grab}");
            let moved = pivot + (now - grab);
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
        let a = Editor::grab_point(&p, Handle::Plane(1), pivot, m0.0, m0.1).unwrap();
        let b = Editor::grab_point(&p, Handle::Plane(1), pivot, m1.0, m1.1).unwrap();
        assert!((a - g0).length() < 1e-3 && (b - g1).length() < 1e-3);
        assert!(((b - a).y).abs() < 1e-6, "stays in the plane");
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
    fn quad_and_segment_hits() {
        let q = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
        assert!(in_quad((5.0, 5.0), &q));
        assert!(!in_quad((11.0, 5.0), &q));
        assert!((seg_dist((5.0, 3.0), (0.0, 0.0), (10.0, 0.0)) - 3.0).abs() < 1e-6);
        assert!((seg_dist((13.0, 4.0), (0.0, 0.0), (10.0, 0.0)) - 5.0).abs() < 1e-6);
    }
}
