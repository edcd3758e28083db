//! Handles on the selected object or light, one file per kind: translate
//! arrows and plane squares (`translate`), rotate rings (`rotate`), scale
//! boxes (`scale`), and dragging the object's body in the view plane
//! (`body`). With the rotate tool a drag inside the rings (not on a ring
//! or the body) turns freely (trackball). This file holds the tool choice, hover and drag state, and
//! dispatches mouse events to the kind under the mouse.
//!
//! Tools: W move, E rotate, T scale (R is record mode), or the toolbar's
//! Mov / Rot / Scl buttons. Ctrl snaps: grid step, 15°, 0.1. Esc cancels.
//!
//! During a drag the node is previewed as a [`super::record::Pending`]
//! change (shown over its tracks); the release records one command, with a
//! key in record mode on the changed property.

mod aim;
mod body;
pub mod geom;
pub mod rotate;
pub mod scale;
pub mod translate;

pub use geom::{axis, closest_on_line, grid_step, pixel_ray, ray_plane, snap};

use super::command::Command;
use super::input::Drag;
use super::record::Pending;
use super::{ops, Editor};
use crate::anim::Property;
use crate::input::{Key, Mods};
use crate::scene::{LightKind, Node, NodeId, NodeKind};
use crate::ui::Painter;
use glam::{Mat4, Quat, Vec3};

/// Arrow length on screen, in pixels.
pub const ARROW_PX: f32 = 70.0;
/// How close (pixels) the mouse must be to a handle to grab it.
const GRAB_PX: f32 = 6.0;

const AXIS_COLORS: [u32; 3] = [0xe04848, 0x5cc040, 0x4c8fe8];
const HOT: u32 = 0xffe040;

/// Which handles the selection shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Tool {
    #[default]
    Translate,
    Rotate,
    Scale,
}

impl Tool {
    /// Name shown in the viewport label.
    pub fn name(self) -> &'static str {
        match self {
            Tool::Translate => "Move",
            Tool::Rotate => "Rotate",
            Tool::Scale => "Scale",
        }
    }

    /// The key that picks the tool.
    pub fn key(self) -> char {
        match self {
            Tool::Translate => 'w',
            Tool::Rotate => 'e',
            Tool::Scale => 't',
        }
    }
}

/// One grabbable part of the handles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Handle {
    /// Arrow along world axis 0/1/2.
    Axis(u8),
    /// Square in the plane whose normal is world axis 0/1/2.
    Plane(u8),
    /// Ring about world axis 0/1/2.
    Ring(u8),
    /// The outer ring about the view direction.
    ViewRing,
    /// Box on the node's own scale axis 0/1/2.
    ScaleAxis(u8),
    /// The centre box of the scale handles.
    Uniform,
    /// Inside the rotate rings (not on a ring or the body): free rotation
    /// on the sphere the rings outline.
    Trackball,
    /// The selected object's own pixels (moves in the view plane).
    Body,
}

impl Handle {
    /// The undo label's verb.
    fn verb(self) -> &'static str {
        match self {
            Handle::Ring(_) | Handle::ViewRing | Handle::Trackball => "Rotate",
            Handle::ScaleAxis(_) | Handle::Uniform => "Scale",
            _ => "Move",
        }
    }
}

/// Tool, hover and drag state of the handles.
#[derive(Clone, Debug, Default)]
pub struct Manip {
    pub tool: Tool,
    pub hover: Option<Handle>,
    drag: Option<HandleDrag>,
    /// A press on the selection's body (or inside the rotate rings): what
    /// it would drag and where, until it becomes a drag or a click.
    armed: Option<(Handle, (f32, f32))>,
}

/// What the handles of a tool act on.
#[derive(Clone, Copy, Debug)]
struct Target {
    id: NodeId,
    property: Property,
    /// The fixed point of the change, in world space.
    pivot: Vec3,
    /// World → the space the changed value lives in (parent space for an
    /// object's transform, the light's node space for its fields).
    to_local: Mat4,
    /// World directions of the node's scale axes (scale handles).
    frame: [Vec3; 3],
}

#[derive(Clone, Debug)]
struct HandleDrag {
    handle: Handle,
    t: Target,
    /// The node as stored at press (restored before recording).
    stored: Box<Node>,
    /// The node as shown at press (what the drag changes).
    shown: Box<Node>,
    /// World point grabbed at press (translate, rotate, body).
    grab: Vec3,
    /// Window pixel of the press (uniform scale).
    press: (f32, f32),
    /// Scale axis: distance along the axis at press.
    along: f32,
    /// Rotate: axis of the ring and the angle turned so far (kept
    /// continuous across half turns).
    ring_axis: Vec3,
    angle: f32,
    /// Rotate, ring seen edge-on: screen direction and pixel radius the
    /// mouse motion is measured along (see [`rotate::edge_on_drag`]).
    edge_on: Option<((f32, f32), f32)>,
}

impl Editor {
    /// The current tool.
    pub fn tool(&self) -> Tool {
        self.manip.tool
    }

    /// Picks the tool (W / E / T, toolbar).
    pub fn set_tool(&mut self, t: Tool) {
        if self.manip.drag.is_none() {
            self.manip.tool = t;
            self.manip.hover = None;
        }
    }

    /// What `tool`'s handles act on for the selection (`None` when that
    /// tool has nothing to change there: a directional light cannot move, a
    /// point light cannot turn, a light cannot scale).
    fn target(&mut self, tool: Tool) -> Option<Target> {
        let id = self.selection?;
        let pose = self.pose().clone();
        let world = *pose.world.get(id.0 as usize)?;
        let n = self.posed_node(id);
        // The space translation, rotation and scale live in: the parent's
        // world matrix, then an Inventor MatrixTransform's raw matrix.
        let tr = &n.transform;
        let parent = n
            .parent
            .and_then(|p| pose.world.get(p.0 as usize).copied())
            .unwrap_or(Mat4::IDENTITY)
            * tr.extra.unwrap_or(Mat4::IDENTITY);
        let frame = {
            let r = tr.rotation * tr.scale_orientation;
            [Vec3::X, Vec3::Y, Vec3::Z].map(|a| parent.transform_vector3(r * a).normalize_or(a))
        };
        let light = |property| match &n.kind {
            NodeKind::Light(l) => Some(Target {
                id,
                property,
                pivot: world.transform_point3(l.location),
                to_local: world.inverse(),
                frame,
            }),
            _ => None,
        };
        let object = |property, pivot| Target {
            id,
            property,
            pivot,
            to_local: parent.inverse(),
            frame,
        };
        // Rotation and scale keep translation + center fixed (VRML97 §6.52).
        let fixed = parent.transform_point3(tr.translation + tr.center);
        match (&n.kind, tool) {
            (NodeKind::Light(l), Tool::Translate) if l.kind == LightKind::Directional => None,
            (NodeKind::Light(_), Tool::Translate) => light(Property::LightLocation),
            (NodeKind::Light(l), Tool::Rotate) if l.kind == LightKind::Point => None,
            (NodeKind::Light(_), Tool::Rotate) => light(Property::LightDirection),
            (NodeKind::Light(_), Tool::Scale) => None,
            (_, Tool::Translate) => Some(object(Property::Translation, world.w_axis.truncate())),
            (_, Tool::Rotate) => Some(object(Property::Rotation, fixed)),
            (_, Tool::Scale) => Some(object(Property::Scale, fixed)),
        }
    }

    /// Pixel positions of the pivot and of the three translate arrow tips
    /// (tests and scripts aim at them).
    pub fn handle_points(&mut self) -> Option<[(f32, f32); 4]> {
        let t = self.target(Tool::Translate)?;
        translate::points(&self.projector(), t.pivot)
    }

    /// Window pixel of world point `p` as the viewport shows it (`None`
    /// behind the eye); tests and scripts aim with it.
    pub fn pixel_of(&mut self, p: Vec3) -> Option<(f32, f32)> {
        self.projector().point(p)
    }

    /// Pixel positions of the scale pivot and the three scale boxes.
    pub fn scale_points(&mut self) -> Option<[(f32, f32); 4]> {
        let t = self.target(Tool::Scale)?;
        scale::points(&self.projector(), t.pivot, &t.frame)
    }

    /// Pixel of the point of ring `h` at angle `theta` (radians from the
    /// ring's first in-plane axis: y for the x ring, z for y, x for z, and
    /// screen right for the view ring; positive turns right-handed about
    /// the ring's axis, which for the view ring points at the eye).
    pub fn ring_pixel(&mut self, h: Handle, theta: f32) -> Option<(f32, f32)> {
        let t = self.target(Tool::Rotate)?;
        let proj = self.projector();
        let w = rotate::ring_point(&proj, h, t.pivot, self.camera.back(), theta)?;
        proj.point(w)
    }

    /// The handle of the current tool under window pixel (x, y).
    pub fn handle_at(&mut self, x: f32, y: f32) -> Option<Handle> {
        if !self.layout().viewport.contains(x, y) || self.mode != super::Mode::Select {
            return None;
        }
        let tool = self.manip.tool;
        let t = self.target(tool)?;
        let proj = self.projector();
        match tool {
            Tool::Translate => translate::hit(&proj, t.pivot, x, y),
            Tool::Rotate => rotate::hit(&proj, t.pivot, self.camera.back(), x, y),
            Tool::Scale => scale::hit(&proj, t.pivot, &t.frame, x, y),
        }
    }

    /// Starts a drag of `h` grabbed at pixel (x, y) (false when the grab
    /// point cannot be found, e.g. a plane seen edge-on).
    fn start_drag(&mut self, h: Handle, t: Target, x: f32, y: f32) -> bool {
        let proj = self.projector();
        let back = self.camera.back();
        let (mut grab, mut along, mut ring_axis, mut edge_on) = (t.pivot, 0.0, Vec3::Z, None);
        match h {
            Handle::Axis(_) | Handle::Plane(_) => {
                let Some(g) = translate::grab_point(&proj, h, t.pivot, x, y) else {
                    return false;
                };
                grab = g;
            }
            Handle::Ring(_) | Handle::ViewRing => {
                ring_axis = rotate::basis(h, back).map_or(Vec3::Z, |b| b.0);
                edge_on = rotate::edge_on_drag(&proj, h, t.pivot, back);
                if edge_on.is_none() {
                    let Some(g) = rotate::grab_point(&proj, h, t.pivot, back, x, y) else {
                        return false;
                    };
                    grab = g;
                }
            }
            Handle::ScaleAxis(i) => match scale::along(&proj, t.pivot, t.frame[i as usize], x, y) {
                Some(s) if s.abs() > proj.world_per_px(t.pivot) * 2.0 => along = s,
                _ => return false,
            },
            Handle::Uniform => {}
            Handle::Trackball => {
                let r = proj.world_per_px(t.pivot) * rotate::RING_PX;
                let Some(g) = rotate::sphere_point(&proj, t.pivot, r, x, y) else {
                    return false;
                };
                grab = g;
            }
            Handle::Body => {
                let Some(g) = body::grab_point(&proj, t.pivot, back, x, y) else {
                    return false;
                };
                grab = g;
            }
        }
        self.stop_playback();
        self.manip.drag = Some(HandleDrag {
            handle: h,
            t,
            stored: Box::new(self.scene.node(t.id).clone()),
            shown: Box::new(self.posed_node(t.id)),
            grab,
            press: (x, y),
            along,
            ring_axis,
            angle: 0.0,
            edge_on,
        });
        self.manip.hover = (h != Handle::Body && h != Handle::Trackball).then_some(h);
        true
    }

    /// Mouse down in the viewport: starts a handle drag when one is hit
    /// (true), or arms a body drag when the press is on the selection
    /// (false: the click still picks on release unless the mouse moves).
    pub(super) fn handles_press(&mut self, x: f32, y: f32) -> bool {
        self.manip.armed = None;
        let tool = self.manip.tool;
        if let Some(h) = self.handle_at(x, y) {
            if let Some(t) = self.target(tool) {
                return self.start_drag(h, t, x, y);
            }
        }
        let sel = self.selection;
        if sel.is_some() && self.pick_at(x, y) == sel && self.target(Tool::Translate).is_some() {
            self.manip.armed = Some((Handle::Body, (x, y)));
        } else if tool == Tool::Rotate && self.mode == super::Mode::Select {
            if let Some(t) = self.target(Tool::Rotate) {
                let proj = self.projector();
                if rotate::in_trackball(&proj, t.pivot, x, y) {
                    self.manip.armed = Some((Handle::Trackball, (x, y)));
                }
            }
        }
        false
    }

    /// Mouse move: drags the active handle, or updates the hover highlight.
    /// `Some(redraw)` when the handles took the event.
    pub(super) fn handles_move(&mut self, x: f32, y: f32, mods: Mods) -> Option<bool> {
        if self.manip.drag.is_none() {
            if let Some((h, at)) = self.manip.armed {
                if !matches!(self.drag, Drag::Pick { .. }) || !body::past_slop(at, x, y) {
                    return None;
                }
                // Past the slop: the press becomes a drag, not a click.
                self.manip.armed = None;
                let tool = if h == Handle::Body {
                    Tool::Translate
                } else {
                    Tool::Rotate
                };
                let t = self.target(tool)?;
                if !self.start_drag(h, t, at.0, at.1) {
                    return None;
                }
                self.drag = Drag::None;
            }
        }
        let Some(d) = self.manip.drag.clone() else {
            if !matches!(self.drag, Drag::None) {
                return None;
            }
            let h = self.handle_at(x, y);
            let changed = h != self.manip.hover;
            self.manip.hover = h;
            return changed.then_some(true);
        };
        match self.dragged_node(&d, x, y, mods) {
            Some(n) => {
                let text = self.readout(&d, &n, mods);
                self.set_status(&text, false);
                self.show_moved(d.t.id, d.t.property, n);
                Some(true)
            }
            None => Some(false),
        }
    }

    /// The status line during a drag: the moved value, the angle turned or
    /// the new scale ("deg": the UI font has no degree sign).
    fn readout(&self, d: &HandleDrag, n: &Node, mods: Mods) -> String {
        use super::fields::format_number as f;
        let name = ops::display_name(&self.scene, d.t.id);
        let v3 = |v: Vec3| format!("{} {} {}", f(v.x), f(v.y), f(v.z));
        let verb = d.handle.verb();
        match d.handle {
            Handle::Ring(_) | Handle::ViewRing => {
                let live = self.manip.drag.as_ref().map_or(d.angle, |l| l.angle);
                let a = if mods.ctrl {
                    snap(live, rotate::SNAP)
                } else {
                    live
                };
                let about = match d.handle {
                    Handle::Ring(i) => ["x", "y", "z"][i.min(2) as usize],
                    _ => "the view",
                };
                format!("{verb} {name}: {} deg about {about}", f(a.to_degrees()))
            }
            Handle::Trackball => {
                let a = match (&n.kind, &d.shown.kind) {
                    (NodeKind::Light(l), NodeKind::Light(l0)) => {
                        l0.direction.angle_between(l.direction)
                    }
                    _ => n
                        .transform
                        .rotation
                        .angle_between(d.shown.transform.rotation),
                };
                format!("{verb} {name}: {} deg", f(a.to_degrees()))
            }
            Handle::ScaleAxis(_) | Handle::Uniform => {
                format!("{verb} {name}: scale {}", v3(n.transform.scale))
            }
            _ => match &n.kind {
                NodeKind::Light(l) if d.t.property == Property::LightLocation => {
                    format!("{verb} {name}: location {}", v3(l.location))
                }
                _ => format!("{verb} {name}: {}", v3(n.transform.translation)),
            },
        }
    }

    /// The node as drag `d` makes it with the mouse at (x, y) (`None` when
    /// the mouse ray misses what the handle needs, e.g. a plane edge-on).
    fn dragged_node(&mut self, d: &HandleDrag, x: f32, y: f32, mods: Mods) -> Option<Node> {
        let proj = self.projector();
        let back = self.camera.back();
        let t = d.t;
        match d.handle {
            Handle::Axis(_) | Handle::Plane(_) => {
                let now = translate::grab_point(&proj, d.handle, t.pivot, x, y)?;
                let step = mods.ctrl.then(|| grid_step(self.scene_radius().1));
                let pivot = translate::moved_pivot(d.handle, t.pivot, d.grab, now, step);
                let delta = t.to_local.transform_vector3(pivot - t.pivot);
                Some(translate::moved_by(&d.shown, t.property, delta))
            }
            Handle::Body => {
                let now = body::grab_point(&proj, t.pivot, back, x, y)?;
                let mut pivot = t.pivot + (now - d.grab);
                if mods.ctrl {
                    // Snapping leaves the view plane: the pivot lands on
                    // grid points in all three world axes, as in Blender.
                    let step = grid_step(self.scene_radius().1);
                    pivot = Vec3::new(
                        snap(pivot.x, step),
                        snap(pivot.y, step),
                        snap(pivot.z, step),
                    );
                }
                let delta = t.to_local.transform_vector3(pivot - t.pivot);
                Some(translate::moved_by(&d.shown, t.property, delta))
            }
            Handle::Ring(_) | Handle::ViewRing => {
                let angle = match d.edge_on {
                    Some((dir, r)) => ((x - d.press.0) * dir.0 + (y - d.press.1) * dir.1) / r,
                    None => {
                        let now = rotate::grab_point(&proj, d.handle, t.pivot, back, x, y)?;
                        let raw = rotate::drag_angle(d.ring_axis, t.pivot, d.grab, now);
                        geom::unwrap_angle(raw, d.angle)
                    }
                };
                if let Some(live) = &mut self.manip.drag {
                    live.angle = angle;
                }
                let shown = if mods.ctrl {
                    snap(angle, rotate::SNAP)
                } else {
                    angle
                };
                rotate::turned(&d.shown, d.ring_axis, shown, &t.to_local)
            }
            Handle::Trackball => {
                let r = proj.world_per_px(t.pivot) * rotate::RING_PX;
                let now = rotate::sphere_point(&proj, t.pivot, r, x, y)?;
                let (axis, angle) = rotate::arc(d.grab - t.pivot, now - t.pivot);
                let angle = if mods.ctrl {
                    snap(angle, rotate::SNAP)
                } else {
                    angle
                };
                rotate::turned(&d.shown, axis, angle, &t.to_local)
            }
            Handle::ScaleAxis(i) => {
                let now = scale::along(&proj, t.pivot, t.frame[i as usize], x, y)?;
                Some(scale::scaled_axis(&d.shown, i, d.along, now, mods.ctrl))
            }
            Handle::Uniform => {
                let r = scale::uniform_ratio(x - d.press.0, y - d.press.1, mods.ctrl);
                Some(scale::scaled_uniform(&d.shown, r))
            }
        }
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
        self.manip.armed = None;
        let Some(d) = self.manip.drag.take() else {
            return false;
        };
        let id = d.t.id;
        let after = Box::new(self.scene.node(id).clone());
        self.pending = None;
        // Put back the stored node so the command starts from it.
        self.preview(&Command::SetNode {
            id,
            before: after.clone(),
            after: d.stored.clone(),
        });
        if matches!(d.handle, Handle::Body | Handle::Trackball) {
            self.manip.hover = None;
        }
        if *after == *d.stored || *after == *d.shown {
            return true;
        }
        let c = Command::SetNode {
            id,
            before: d.stored,
            after,
        };
        let c = self.recorded(c, &[d.t.property]);
        let name = ops::display_name(&self.scene, id);
        self.execute(&format!("{} {name}", d.handle.verb()), c);
        true
    }

    /// Keys for the handles: during a drag Esc cancels it and other keys
    /// are ignored; otherwise W / E / T pick the tool and O toggles the
    /// onion skin. True when the key was taken.
    pub(super) fn handles_key(&mut self, key: Key, mods: Mods) -> bool {
        let Some(d) = &self.manip.drag else {
            if mods.ctrl || mods.alt {
                return false;
            }
            let tool = [Tool::Translate, Tool::Rotate, Tool::Scale]
                .into_iter()
                .find(|t| key == Key::Char(t.key()));
            if let Some(t) = tool {
                self.set_tool(t);
                return true;
            }
            if key == Key::Char('o') {
                self.toggle_onion();
                return true;
            }
            return false;
        };
        if key == Key::Escape {
            let c = Command::SetNode {
                id: d.t.id,
                before: Box::new(self.scene.node(d.t.id).clone()),
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

    /// Draws the current tool's handles for the selection over the viewport.
    pub(super) fn draw_handles(&mut self, p: &mut Painter) {
        if self.mode != super::Mode::Select {
            return;
        }
        let tool = self.manip.tool;
        let Some(t) = self.target(tool) else {
            return;
        };
        let proj = self.projector();
        let active = self
            .manip
            .drag
            .as_ref()
            .map(|d| d.handle)
            .filter(|&h| h != Handle::Body && h != Handle::Trackball);
        let hot = active.or(self.manip.hover);
        p.set_clip(Some(self.layout().viewport));
        match tool {
            Tool::Translate => translate::draw(p, &proj, t.pivot, hot),
            Tool::Rotate => {
                let back = self.camera.back();
                // While turning, a spoke from the pivot to the grabbed point
                // as turned shows the angle.
                if let Some(d) = &self.manip.drag {
                    if matches!(d.handle, Handle::Ring(_) | Handle::ViewRing) {
                        let g = d.t.pivot
                            + Quat::from_axis_angle(d.ring_axis, d.angle) * (d.grab - d.t.pivot);
                        if let Some((a, b)) = proj.segment(d.t.pivot, g) {
                            p.line(a, b, HOT, 1.0);
                        }
                    }
                }
                rotate::draw(p, &proj, t.pivot, back, hot)
            }
            Tool::Scale => scale::draw(p, &proj, t.pivot, &t.frame, hot),
        }
        p.set_clip(None);
    }
}
