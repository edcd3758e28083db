//! The editor's side of `manip`: routes events to it and applies what it returns.

use crate::anim::Property;
use crate::editor::command::Command;
use crate::editor::gesture::Drag;
use crate::editor::manip::geom::{grid_step, snap};
#[allow(unused_imports)]
use crate::editor::manip::*;
use crate::editor::record::Pending;
use crate::editor::{ops, Editor};
use crate::input::{Key, Mods};
use crate::scene::{LightKind, Node, NodeId, NodeKind};
use crate::ui::Painter;
use glam::{Mat4, Quat, Vec3};

impl Editor {
    /// The current tool.
    pub fn tool(&self) -> Tool {
        self.manip.tool
    }

    /// Picks the tool (W / E / T, toolbar).
    pub fn set_tool(&mut self, t: Tool) {
        if self.handle_drag().is_none() {
            self.manip.tool = t;
            self.manip.hover = None;
        }
    }

    /// What `tool`'s handles act on for the selection (`None` when that
    /// tool has nothing to change there: a directional light cannot move, a
    /// point light cannot turn, a light cannot scale).
    pub(in crate::internals::editor) fn target(&mut self, tool: Tool) -> Option<Target> {
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
        crate::editor::manip::translate::points(&self.handle_projector(), t.pivot)
    }

    /// Window pixel of world point `p` as the viewport shows it (`None`
    /// behind the eye); tests and scripts aim with it.
    pub fn pixel_of(&mut self, p: Vec3) -> Option<(f32, f32)> {
        self.projector().point(p)
    }

    /// Pixel positions of the scale pivot and the three scale boxes.
    pub fn scale_points(&mut self) -> Option<[(f32, f32); 4]> {
        let t = self.target(Tool::Scale)?;
        crate::editor::manip::scale::points(&self.handle_projector(), t.pivot, &t.frame)
    }

    /// Pixel of the point of ring `h` at angle `theta` (radians from the
    /// ring's first in-plane axis: y for the x ring, z for y, x for z, and
    /// screen right for the view ring; positive turns right-handed about
    /// the ring's axis, which for the view ring points at the eye).
    pub fn ring_pixel(&mut self, h: Handle, theta: f32) -> Option<(f32, f32)> {
        let t = self.target(Tool::Rotate)?;
        let proj = self.handle_projector();
        let w =
            crate::editor::manip::rotate::ring_point(&proj, h, t.pivot, self.camera.back(), theta)?;
        proj.point(w)
    }

    /// The handle of the current tool under window pixel (x, y).
    pub fn handle_at(&mut self, x: f32, y: f32) -> Option<Handle> {
        if !self.layout().viewport.contains(x, y) || self.mode != crate::editor::Mode::Select {
            return None;
        }
        let tool = self.manip.tool;
        let t = self.target(tool)?;
        let proj = self.handle_projector();
        match tool {
            Tool::Translate => crate::editor::manip::translate::hit(&proj, t.pivot, x, y),
            Tool::Rotate => {
                crate::editor::manip::rotate::hit(&proj, t.pivot, self.camera.back(), x, y)
            }
            Tool::Scale => crate::editor::manip::scale::hit(&proj, t.pivot, &t.frame, x, y),
        }
    }

    /// Starts a drag of `h` grabbed at pixel (x, y) (false when the grab
    /// point cannot be found, e.g. a plane seen edge-on).
    pub(in crate::internals::editor) fn start_drag(
        &mut self,
        h: Handle,
        t: Target,
        x: f32,
        y: f32,
    ) -> bool {
        let proj = self.handle_projector();
        let back = self.camera.back();
        let (mut grab, mut along, mut ring_axis, mut edge_on) = (t.pivot, 0.0, Vec3::Z, None);
        match h {
            Handle::Axis(_) | Handle::Plane(_) => {
                let Some(g) = crate::editor::manip::translate::grab_point(&proj, h, t.pivot, x, y)
                else {
                    return false;
                };
                grab = g;
            }
            Handle::Ring(_) | Handle::ViewRing => {
                ring_axis = crate::editor::manip::rotate::basis(h, back).map_or(Vec3::Z, |b| b.0);
                edge_on = crate::editor::manip::rotate::edge_on_drag(&proj, h, t.pivot, back);
                if edge_on.is_none() {
                    let Some(g) =
                        crate::editor::manip::rotate::grab_point(&proj, h, t.pivot, back, x, y)
                    else {
                        return false;
                    };
                    grab = g;
                }
            }
            Handle::ScaleAxis(i) => {
                match crate::editor::manip::scale::along(&proj, t.pivot, t.frame[i as usize], x, y)
                {
                    Some(s) if s.abs() > proj.world_per_px(t.pivot) * 2.0 => along = s,
                    _ => return false,
                }
            }
            Handle::Uniform => {}
            Handle::Trackball => {
                let r = proj.world_per_px(t.pivot) * crate::editor::manip::rotate::RING_PX;
                let Some(g) = crate::editor::manip::rotate::sphere_point(&proj, t.pivot, r, x, y)
                else {
                    return false;
                };
                grab = g;
            }
            Handle::Body => {
                let Some(g) = crate::editor::manip::body::grab_point(&proj, t.pivot, back, x, y)
                else {
                    return false;
                };
                grab = g;
            }
        }
        self.stop_playback();
        self.drag = Drag::Handle(Box::new(HandleDrag {
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
        }));
        self.manip.hover = (h != Handle::Body && h != Handle::Trackball).then_some(h);
        true
    }

    /// The handle drag, when it is the editor's gesture.
    pub(in crate::internals::editor) fn handle_drag(&self) -> Option<&HandleDrag> {
        match &self.drag {
            Drag::Handle(d) => Some(d),
            _ => None,
        }
    }

    /// Mouse down in the viewport (left, select mode): starts a handle
    /// drag when one is hit, or, on the selection's body (or inside the
    /// rotate rings), a pick armed to become that drag once the mouse
    /// moves past the slop (a click still picks on release). True when
    /// the press is the handles'.
    pub(in crate::internals::editor) fn handles_press(&mut self, x: f32, y: f32) -> bool {
        let tool = self.manip.tool;
        if let Some(h) = self.handle_at(x, y) {
            if let Some(t) = self.target(tool) {
                return self.start_drag(h, t, x, y);
            }
        }
        let sel = self.selection;
        let mut armed = None;
        if sel.is_some() && self.pick_at(x, y) == sel && self.target(Tool::Translate).is_some() {
            armed = Some(Handle::Body);
        } else if tool == Tool::Rotate && self.mode == crate::editor::Mode::Select {
            if let Some(t) = self.target(Tool::Rotate) {
                let proj = self.handle_projector();
                if crate::editor::manip::rotate::in_trackball(&proj, t.pivot, x, y) {
                    armed = Some(Handle::Trackball);
                }
            }
        }
        if armed.is_some() {
            self.drag = Drag::Pick { at: (x, y), armed };
        }
        armed.is_some()
    }

    /// Mouse move: drags the active handle, or updates the hover highlight.
    /// `Some(redraw)` when the handles took the event.
    pub(in crate::internals::editor) fn handles_move(
        &mut self,
        x: f32,
        y: f32,
        mods: Mods,
    ) -> Option<bool> {
        if let Drag::Pick { at, armed: Some(h) } = self.drag {
            if !crate::editor::manip::body::past_slop(at, x, y) {
                return None;
            }
            // Past the slop: the press becomes a drag, not a click.
            self.drag = Drag::Pick { at, armed: None };
            let tool = if h == Handle::Body {
                Tool::Translate
            } else {
                Tool::Rotate
            };
            let t = self.target(tool)?;
            if !self.start_drag(h, t, at.0, at.1) {
                return None;
            }
        }
        let Some(d) = self.handle_drag().cloned() else {
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
    pub(in crate::internals::editor) fn readout(
        &self,
        d: &HandleDrag,
        n: &Node,
        mods: Mods,
    ) -> String {
        use crate::editor::fields::format_number as f;
        let name = ops::display_name(&self.scene, d.t.id);
        let v3 = |v: Vec3| format!("{} {} {}", f(v.x), f(v.y), f(v.z));
        let verb = d.handle.verb();
        match d.handle {
            Handle::Ring(_) | Handle::ViewRing => {
                let live = self.handle_drag().map_or(d.angle, |l| l.angle);
                let a = if mods.ctrl {
                    snap(live, crate::editor::manip::rotate::SNAP)
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
    pub(in crate::internals::editor) fn dragged_node(
        &mut self,
        d: &HandleDrag,
        x: f32,
        y: f32,
        mods: Mods,
    ) -> Option<Node> {
        let proj = self.handle_projector();
        let back = self.camera.back();
        let t = d.t;
        match d.handle {
            Handle::Axis(_) | Handle::Plane(_) => {
                let now =
                    crate::editor::manip::translate::grab_point(&proj, d.handle, t.pivot, x, y)?;
                let step = mods.ctrl.then(|| grid_step(self.scene_radius().1));
                let pivot = crate::editor::manip::translate::moved_pivot(
                    d.handle, t.pivot, d.grab, now, step,
                );
                let delta = t.to_local.transform_vector3(pivot - t.pivot);
                Some(crate::editor::manip::translate::moved_by(
                    &d.shown, t.property, delta,
                ))
            }
            Handle::Body => {
                let now = crate::editor::manip::body::grab_point(&proj, t.pivot, back, x, y)?;
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
                Some(crate::editor::manip::translate::moved_by(
                    &d.shown, t.property, delta,
                ))
            }
            Handle::Ring(_) | Handle::ViewRing => {
                let angle = match d.edge_on {
                    Some((dir, r)) => ((x - d.press.0) * dir.0 + (y - d.press.1) * dir.1) / r,
                    None => {
                        let now = crate::editor::manip::rotate::grab_point(
                            &proj, d.handle, t.pivot, back, x, y,
                        )?;
                        let raw = crate::editor::manip::rotate::drag_angle(
                            d.ring_axis,
                            t.pivot,
                            d.grab,
                            now,
                        );
                        crate::editor::manip::geom::unwrap_angle(raw, d.angle)
                    }
                };
                if let Drag::Handle(live) = &mut self.drag {
                    live.angle = angle;
                }
                let shown = if mods.ctrl {
                    snap(angle, crate::editor::manip::rotate::SNAP)
                } else {
                    angle
                };
                crate::editor::manip::rotate::turned(&d.shown, d.ring_axis, shown, &t.to_local)
            }
            Handle::Trackball => {
                let r = proj.world_per_px(t.pivot) * crate::editor::manip::rotate::RING_PX;
                let now = crate::editor::manip::rotate::sphere_point(&proj, t.pivot, r, x, y)?;
                let (axis, angle) =
                    crate::editor::manip::rotate::arc(d.grab - t.pivot, now - t.pivot);
                let angle = if mods.ctrl {
                    snap(angle, crate::editor::manip::rotate::SNAP)
                } else {
                    angle
                };
                crate::editor::manip::rotate::turned(&d.shown, axis, angle, &t.to_local)
            }
            Handle::ScaleAxis(i) => {
                let now =
                    crate::editor::manip::scale::along(&proj, t.pivot, t.frame[i as usize], x, y)?;
                Some(crate::editor::manip::scale::scaled_axis(
                    &d.shown, i, d.along, now, mods.ctrl,
                ))
            }
            Handle::Uniform => {
                let r = crate::editor::manip::scale::uniform_ratio(
                    x - d.press.0,
                    y - d.press.1,
                    mods.ctrl,
                );
                Some(crate::editor::manip::scale::scaled_uniform(&d.shown, r))
            }
        }
    }

    /// Previews `node` (shown over its tracks as a pending change).
    pub(in crate::internals::editor) fn show_moved(
        &mut self,
        id: NodeId,
        property: Property,
        node: Node,
    ) {
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
    pub(in crate::internals::editor) fn handles_release(&mut self) -> bool {
        let Some(d) = self.drag.take_handle() else {
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
    pub(in crate::internals::editor) fn handles_key(&mut self, key: Key, mods: Mods) -> bool {
        let Some(d) = self.handle_drag() else {
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
            self.drag = Drag::None;
            self.pending = None;
            self.preview(&c);
        }
        true
    }

    /// Whether a handle drag is running.
    pub fn handle_dragging(&self) -> bool {
        self.handle_drag().is_some()
    }

    /// Draws the current tool's handles for the selection over the viewport.
    pub(in crate::internals::editor) fn draw_handles(&mut self, p: &mut Painter) {
        if self.mode != crate::editor::Mode::Select {
            return;
        }
        let tool = self.manip.tool;
        let Some(t) = self.target(tool) else {
            return;
        };
        let proj = self.handle_projector();
        let active = self
            .handle_drag()
            .map(|d| d.handle)
            .filter(|&h| h != Handle::Body && h != Handle::Trackball);
        let hot = active.or(self.manip.hover);
        p.set_clip(Some(self.layout().viewport));
        match tool {
            Tool::Translate => crate::editor::manip::translate::draw(p, &proj, t.pivot, hot),
            Tool::Rotate => {
                let back = self.camera.back();
                // While turning, a spoke from the pivot to the grabbed point
                // as turned shows the angle.
                if let Some(d) = self.handle_drag() {
                    if matches!(d.handle, Handle::Ring(_) | Handle::ViewRing) {
                        let g = d.t.pivot
                            + Quat::from_axis_angle(d.ring_axis, d.angle) * (d.grab - d.t.pivot);
                        if let Some((a, b)) = proj.segment(d.t.pivot, g) {
                            p.line(a, b, HOT, 1.0);
                        }
                    }
                }
                crate::editor::manip::rotate::draw(p, &proj, t.pivot, back, hot)
            }
            Tool::Scale => crate::editor::manip::scale::draw(p, &proj, t.pivot, &t.frame, hot),
        }
        p.set_clip(None);
    }
}
