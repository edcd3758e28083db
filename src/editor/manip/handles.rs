//! The viewport's handles as a component: hit testing, the drag and
//! drawing in one place. [`Manip`] holds the tool, the hover highlight, a
//! press on the selection's body (or inside the rotate rings) waiting to
//! become a drag, and the drag itself; [`Manip::handle`] answers presses,
//! moves, releases and keys with a [`Response`] whose intents (show the
//! node moved, put it back, record it, a status line) the editor applies,
//! and [`Manip::draw`] draws the current tool's handles. What it sees of
//! the editor is [`HandlesCtx`]; it never names the `Editor`.

use super::body;
use super::geom::{grid_step, snap, unwrap_angle};
use super::{rotate, scale, translate};
use super::{Handle, HandleDrag, Manip, Target, Tool, HOT};
use crate::anim::Property;
use crate::editor::component::{Intent, Response};
use crate::input::camera::Projector;
use crate::input::{Event, Key, Mods, MouseButton};
use crate::scene::{LightKind, Node, NodeKind};
use crate::ui::{Painter, Rect};
use glam::{Mat4, Quat, Vec3};

/// What the handles see of the editor.
#[derive(Clone, Debug)]
pub struct HandlesCtx {
    /// The projector the handles are sized with (shrunk round a small
    /// selection).
    pub proj: Projector,
    /// Direction from the view's target to the eye (rotate rings).
    pub back: Vec3,
    pub viewport: Rect,
    /// Select mode: handles only show and grab there.
    pub select_mode: bool,
    /// What each tool's handles act on for the selection ([`targets`]),
    /// in the order of [`Tool::ALL`].
    pub targets: [Option<Target>; 3],
    /// The selection as stored in the scene now (a drag's previews show
    /// in it) and as shown at the frame (animated values).
    pub stored: Option<Node>,
    pub shown: Option<Node>,
    /// The scene's radius (Ctrl snaps moves to its grid step).
    pub radius: f32,
    /// The selection's name (the status line).
    pub name: String,
    /// A press: whether the selection's own pixels are under it.
    pub on_selection: bool,
}

impl HandlesCtx {
    fn target(&self, tool: Tool) -> Option<Target> {
        self.targets[tool as usize]
    }
}

/// What `tool`'s handles act on for node `n` (shown at the frame) with
/// world matrix `world` and parent world matrix `parent` (`None` when
/// that tool has nothing to change there: a directional light cannot
/// move, a point light cannot turn, a light cannot scale), for every tool
/// in [`Tool::ALL`] order.
pub fn targets(
    id: crate::scene::NodeId,
    world: Mat4,
    parent: Mat4,
    n: &Node,
) -> [Option<Target>; 3] {
    // The space translation, rotation and scale live in: the parent's
    // world matrix, then an Inventor MatrixTransform's raw matrix.
    let tr = &n.transform;
    let parent = parent * tr.extra.unwrap_or(Mat4::IDENTITY);
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
    Tool::ALL.map(|tool| match (&n.kind, tool) {
        (NodeKind::Light(l), Tool::Translate) if l.kind == LightKind::Directional => None,
        (NodeKind::Light(_), Tool::Translate) => light(Property::LightLocation),
        (NodeKind::Light(l), Tool::Rotate) if l.kind == LightKind::Point => None,
        (NodeKind::Light(_), Tool::Rotate) => light(Property::LightDirection),
        (NodeKind::Light(_), Tool::Scale) => None,
        (_, Tool::Translate) => Some(object(Property::Translation, world.w_axis.truncate())),
        (_, Tool::Rotate) => Some(object(Property::Rotation, fixed)),
        (_, Tool::Scale) => Some(object(Property::Scale, fixed)),
    })
}

impl Manip {
    /// Picks the tool (not during a drag).
    pub fn set_tool(&mut self, t: Tool) {
        if self.drag.is_none() {
            self.tool = t;
            self.hover = None;
        }
    }

    /// Whether a handle drag is running.
    pub fn dragging(&self) -> bool {
        self.drag.is_some()
    }

    /// Whether a press waits to become a drag once the mouse moves.
    pub fn armed(&self) -> bool {
        self.armed.is_some()
    }

    /// The handle of the current tool under window pixel (x, y).
    pub fn hit(&self, ctx: &HandlesCtx, x: f32, y: f32) -> Option<Handle> {
        if !ctx.viewport.contains(x, y) || !ctx.select_mode {
            return None;
        }
        let t = ctx.target(self.tool)?;
        let proj = &ctx.proj;
        match self.tool {
            Tool::Translate => translate::hit(proj, t.pivot, x, y),
            Tool::Rotate => rotate::hit(proj, t.pivot, ctx.back, x, y),
            Tool::Scale => scale::hit(proj, t.pivot, &t.frame, x, y),
        }
    }

    /// Answers one event: a left press in the viewport in select mode, a
    /// move, a release, or a key.
    pub fn handle(&mut self, ev: &Event, ctx: &HandlesCtx) -> Response {
        match *ev {
            Event::MouseDown {
                button: MouseButton::Left,
                x,
                y,
                ..
            } => self.press(x, y, ctx),
            Event::MouseMove { x, y, mods } => self.moved(x, y, mods, ctx),
            Event::MouseUp { .. } => self.release(ctx),
            Event::KeyDown { key, mods } => self.key(key, mods),
            _ => Response::ignored(),
        }
    }

    /// A press starts a drag when a handle is hit, or, on the selection's
    /// body (or inside the rotate rings), arms one for when the mouse
    /// moves past the slop (a click still picks on release).
    fn press(&mut self, x: f32, y: f32, ctx: &HandlesCtx) -> Response {
        if let Some(h) = self.hit(ctx, x, y) {
            if let Some(t) = ctx.target(self.tool) {
                return self.start(h, t, x, y, ctx);
            }
        }
        let mut armed = None;
        if ctx.on_selection && ctx.target(Tool::Translate).is_some() {
            armed = Some(Handle::Body);
        } else if self.tool == Tool::Rotate && ctx.select_mode {
            if let Some(t) = ctx.target(Tool::Rotate) {
                if rotate::in_trackball(&ctx.proj, t.pivot, x, y) {
                    armed = Some(Handle::Trackball);
                }
            }
        }
        self.armed = armed.map(|h| ((x, y), h));
        match armed {
            Some(_) => Response::taken(),
            None => Response::ignored(),
        }
    }

    /// Starts a drag of `h` grabbed at pixel (x, y) (ignored when the grab
    /// point cannot be found, e.g. a plane seen edge-on).
    fn start(&mut self, h: Handle, t: Target, x: f32, y: f32, ctx: &HandlesCtx) -> Response {
        let (Some(stored), Some(shown)) = (&ctx.stored, &ctx.shown) else {
            return Response::ignored();
        };
        let proj = &ctx.proj;
        let back = ctx.back;
        let (mut grab, mut along, mut ring_axis, mut edge_on) = (t.pivot, 0.0, Vec3::Z, None);
        match h {
            Handle::Axis(_) | Handle::Plane(_) => {
                let Some(g) = translate::grab_point(proj, h, t.pivot, x, y) else {
                    return Response::ignored();
                };
                grab = g;
            }
            Handle::Ring(_) | Handle::ViewRing => {
                ring_axis = rotate::basis(h, back).map_or(Vec3::Z, |b| b.0);
                edge_on = rotate::edge_on_drag(proj, h, t.pivot, back);
                if edge_on.is_none() {
                    let Some(g) = rotate::grab_point(proj, h, t.pivot, back, x, y) else {
                        return Response::ignored();
                    };
                    grab = g;
                }
            }
            Handle::ScaleAxis(i) => match scale::along(proj, t.pivot, t.frame[i as usize], x, y) {
                Some(s) if s.abs() > proj.world_per_px(t.pivot) * 2.0 => along = s,
                _ => return Response::ignored(),
            },
            Handle::Uniform => {}
            Handle::Trackball => {
                let r = proj.world_per_px(t.pivot) * rotate::RING_PX;
                let Some(g) = rotate::sphere_point(proj, t.pivot, r, x, y) else {
                    return Response::ignored();
                };
                grab = g;
            }
            Handle::Body => {
                let Some(g) = body::grab_point(proj, t.pivot, back, x, y) else {
                    return Response::ignored();
                };
                grab = g;
            }
        }
        self.drag = Some(HandleDrag {
            handle: h,
            t,
            stored: Box::new(stored.clone()),
            shown: Box::new(shown.clone()),
            grab,
            press: (x, y),
            along,
            ring_axis,
            angle: 0.0,
            edge_on,
        });
        self.hover = (h != Handle::Body && h != Handle::Trackball).then_some(h);
        Response::taken().with(Intent::StopPlayback)
    }

    /// A move: an armed press past the slop becomes its drag; a drag shows
    /// the node moved; otherwise the hover highlight follows the mouse
    /// (ignored when it stays).
    fn moved(&mut self, x: f32, y: f32, mods: Mods, ctx: &HandlesCtx) -> Response {
        let mut started = Response::ignored();
        if let Some((at, h)) = self.armed {
            if !body::past_slop(at, x, y) {
                return Response::ignored();
            }
            // Past the slop: the press becomes a drag, not a click.
            self.armed = None;
            let tool = if h == Handle::Body {
                Tool::Translate
            } else {
                Tool::Rotate
            };
            let Some(t) = ctx.target(tool) else {
                return Response::taken();
            };
            started = self.start(h, t, at.0, at.1, ctx);
            if !started.consumed {
                return Response::taken();
            }
        }
        let Some(mut d) = self.drag.take() else {
            let h = self.hit(ctx, x, y);
            let changed = h != self.hover;
            self.hover = h;
            return if changed {
                Response::redraw()
            } else {
                Response::ignored()
            };
        };
        let moved = dragged_node(&mut d, x, y, mods, ctx);
        let r = match moved {
            Some(n) => {
                let text = readout(&d, &n, mods, ctx);
                Response::redraw()
                    .with(Intent::Status(text, false))
                    .with(Intent::ShowNode {
                        id: d.t.id,
                        property: d.t.property,
                        node: Box::new(n),
                    })
            }
            None => Response::taken(),
        };
        self.drag = Some(d);
        let mut r = r;
        let mut intents = started.intents;
        intents.append(&mut r.intents);
        r.intents = intents;
        r
    }

    /// A release ends a drag as one undo step (with a key in record mode,
    /// which the editor adds); a press that stayed armed picks (the
    /// editor's click).
    fn release(&mut self, ctx: &HandlesCtx) -> Response {
        self.armed = None;
        let Some(d) = self.drag.take() else {
            return Response::ignored();
        };
        let id = d.t.id;
        // The previews changed the stored node: put it back so the
        // command starts from it.
        let after = ctx.stored.clone().unwrap_or_else(|| (*d.stored).clone());
        let mut r = Response::redraw().with(Intent::PutBack {
            id,
            node: d.stored.clone(),
        });
        if matches!(d.handle, Handle::Body | Handle::Trackball) {
            self.hover = None;
        }
        if after == *d.stored || after == *d.shown {
            return r;
        }
        r = r.with(Intent::RecordNode {
            label: format!("{} {}", d.handle.verb(), ctx.name),
            id,
            before: d.stored,
            after: Box::new(after),
            property: d.t.property,
        });
        r
    }

    /// Keys: during a drag Esc cancels it and other keys are taken;
    /// otherwise W / E / T pick the tool.
    fn key(&mut self, key: Key, mods: Mods) -> Response {
        let Some(d) = &self.drag else {
            if mods.ctrl || mods.alt {
                return Response::ignored();
            }
            let Some(t) = Tool::ALL.into_iter().find(|t| key == Key::Char(t.key())) else {
                return Response::ignored();
            };
            self.set_tool(t);
            return Response::redraw();
        };
        if key != Key::Escape {
            return Response::taken();
        }
        let put_back = Intent::PutBack {
            id: d.t.id,
            node: d.stored.clone(),
        };
        self.drag = None;
        Response::redraw().with(put_back)
    }

    /// Draws the current tool's handles for the selection over the
    /// viewport (the one being dragged or hovered highlighted).
    pub fn draw(&self, p: &mut Painter, ctx: &HandlesCtx) {
        if !ctx.select_mode {
            return;
        }
        let Some(t) = ctx.target(self.tool) else {
            return;
        };
        let proj = &ctx.proj;
        let active = self
            .drag
            .as_ref()
            .map(|d| d.handle)
            .filter(|&h| h != Handle::Body && h != Handle::Trackball);
        let hot = active.or(self.hover);
        p.set_clip(Some(ctx.viewport));
        match self.tool {
            Tool::Translate => translate::draw(p, proj, t.pivot, hot),
            Tool::Rotate => {
                // While turning, a spoke from the pivot to the grabbed point
                // as turned shows the angle.
                if let Some(d) = &self.drag {
                    if matches!(d.handle, Handle::Ring(_) | Handle::ViewRing) {
                        let g = d.t.pivot
                            + Quat::from_axis_angle(d.ring_axis, d.angle) * (d.grab - d.t.pivot);
                        if let Some((a, b)) = proj.segment(d.t.pivot, g) {
                            p.line(a, b, HOT, 1.0);
                        }
                    }
                }
                rotate::draw(p, proj, t.pivot, ctx.back, hot)
            }
            Tool::Scale => scale::draw(p, proj, t.pivot, &t.frame, hot),
        }
        p.set_clip(None);
    }
}

/// The node as drag `d` makes it with the mouse at (x, y) (`None` when the
/// mouse ray misses what the handle needs, e.g. a plane edge-on). A ring
/// drag keeps its angle continuous across half turns in `d.angle`.
fn dragged_node(d: &mut HandleDrag, x: f32, y: f32, mods: Mods, ctx: &HandlesCtx) -> Option<Node> {
    let proj = &ctx.proj;
    let back = ctx.back;
    let t = d.t;
    match d.handle {
        Handle::Axis(_) | Handle::Plane(_) => {
            let now = translate::grab_point(proj, d.handle, t.pivot, x, y)?;
            let step = mods.ctrl.then(|| grid_step(ctx.radius));
            let pivot = translate::moved_pivot(d.handle, t.pivot, d.grab, now, step);
            let delta = t.to_local.transform_vector3(pivot - t.pivot);
            Some(translate::moved_by(&d.shown, t.property, delta))
        }
        Handle::Body => {
            let now = body::grab_point(proj, t.pivot, back, x, y)?;
            let mut pivot = t.pivot + (now - d.grab);
            if mods.ctrl {
                // Snapping leaves the view plane: the pivot lands on grid
                // points in all three world axes, as in Blender.
                let step = grid_step(ctx.radius);
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
                    let now = rotate::grab_point(proj, d.handle, t.pivot, back, x, y)?;
                    let raw = rotate::drag_angle(d.ring_axis, t.pivot, d.grab, now);
                    unwrap_angle(raw, d.angle)
                }
            };
            d.angle = angle;
            let shown = if mods.ctrl {
                snap(angle, rotate::SNAP)
            } else {
                angle
            };
            rotate::turned(&d.shown, d.ring_axis, shown, &t.to_local)
        }
        Handle::Trackball => {
            let r = proj.world_per_px(t.pivot) * rotate::RING_PX;
            let now = rotate::sphere_point(proj, t.pivot, r, x, y)?;
            let (axis, angle) = rotate::arc(d.grab - t.pivot, now - t.pivot);
            let angle = if mods.ctrl {
                snap(angle, rotate::SNAP)
            } else {
                angle
            };
            rotate::turned(&d.shown, axis, angle, &t.to_local)
        }
        Handle::ScaleAxis(i) => {
            let now = scale::along(proj, t.pivot, t.frame[i as usize], x, y)?;
            Some(scale::scaled_axis(&d.shown, i, d.along, now, mods.ctrl))
        }
        Handle::Uniform => {
            let r = scale::uniform_ratio(x - d.press.0, y - d.press.1, mods.ctrl);
            Some(scale::scaled_uniform(&d.shown, r))
        }
    }
}

/// The status line during a drag: the moved value, the angle turned or
/// the new scale ("deg": the UI font has no degree sign).
fn readout(d: &HandleDrag, n: &Node, mods: Mods, ctx: &HandlesCtx) -> String {
    use crate::editor::fields::format_number as f;
    let name = &ctx.name;
    let v3 = |v: Vec3| format!("{} {} {}", f(v.x), f(v.y), f(v.z));
    let verb = d.handle.verb();
    match d.handle {
        Handle::Ring(_) | Handle::ViewRing => {
            let a = if mods.ctrl {
                snap(d.angle, rotate::SNAP)
            } else {
                d.angle
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::NodeId;

    /// A box at the origin, selected, seen by the test projector.
    fn ctx() -> HandlesCtx {
        let n = Node::group("Box");
        let id = NodeId(0);
        HandlesCtx {
            proj: super::super::geom::tests::projector(),
            back: Vec3::new(4.0, 3.0, 6.0).normalize(),
            viewport: Rect::new(10, 20, 320, 240),
            select_mode: true,
            targets: targets(id, Mat4::IDENTITY, Mat4::IDENTITY, &n),
            stored: Some(n.clone()),
            shown: Some(n),
            radius: 4.0,
            name: "Box".into(),
            on_selection: false,
        }
    }

    fn mouse(kind: &str, (x, y): (f32, f32)) -> Event {
        let (button, mods) = (MouseButton::Left, Mods::NONE);
        match kind {
            "down" => Event::MouseDown { button, x, y, mods },
            "up" => Event::MouseUp { button, x, y, mods },
            _ => Event::MouseMove { x, y, mods },
        }
    }

    /// A pixel 60 % of the way along arrow `i` (and the pivot's pixel).
    fn on_arrow(c: &HandlesCtx, i: usize) -> ((f32, f32), (f32, f32)) {
        let p = translate::points(&c.proj, Vec3::ZERO).unwrap();
        let (o, tip) = (p[0], p[i + 1]);
        ((o.0 + (tip.0 - o.0) * 0.6, o.1 + (tip.1 - o.1) * 0.6), o)
    }

    #[test]
    fn the_handles_hover_drag_and_record_by_themselves() {
        let mut c = ctx();
        let mut m = Manip::default();
        let (on_x, _) = on_arrow(&c, 0);
        assert_eq!(m.hit(&c, on_x.0, on_x.1), Some(Handle::Axis(0)));
        assert!(m.handle(&mouse("move", on_x), &c).redraw, "hover lights it");
        assert_eq!(m.hover, Some(Handle::Axis(0)));
        assert!(!m.handle(&mouse("move", on_x), &c).consumed, "no change");
        let r = m.handle(&mouse("down", on_x), &c);
        assert!(m.dragging());
        assert_eq!(r.intents, vec![Intent::StopPlayback]);
        // Dragging shows the node moved along x only, with a readout.
        let r = m.handle(&mouse("move", (on_x.0 + 30.0, on_x.1 + 5.0)), &c);
        let Some(Intent::ShowNode { node, property, .. }) = r.intents.get(1) else {
            panic!("the node shown moved: {r:?}");
        };
        assert_eq!(*property, Property::Translation);
        let t = node.transform.translation;
        assert!(t.x > 0.1 && t.y == 0.0 && t.z == 0.0, "{t}");
        assert!(matches!(&r.intents[0], Intent::Status(s, false) if s.starts_with("Move Box: ")));
        // Other keys are taken during the drag; the release records one
        // step from the node as stored to the node as previewed.
        assert!(
            m.handle(
                &Event::KeyDown {
                    key: Key::Char('e'),
                    mods: Mods::NONE
                },
                &c
            )
            .consumed
        );
        assert_eq!(m.tool, Tool::Translate);
        c.stored = Some((**node).clone());
        let r = m.handle(&mouse("up", on_x), &c);
        assert!(!m.dragging());
        assert_eq!(r.intents.len(), 2, "{r:?}");
        assert!(
            matches!(&r.intents[0], Intent::PutBack { node: n, .. } if n.transform.translation == Vec3::ZERO)
        );
        assert!(
            matches!(&r.intents[1], Intent::RecordNode { label, after, .. }
            if label == "Move Box" && after.transform.translation == t)
        );
    }

    #[test]
    fn esc_puts_the_node_back_and_a_body_press_waits_for_the_slop() {
        let mut c = ctx();
        let mut m = Manip::default();
        let (on_y, pivot) = on_arrow(&c, 1);
        m.handle(&mouse("down", on_y), &c);
        m.handle(&mouse("move", (on_y.0, on_y.1 - 20.0)), &c);
        let esc = Event::KeyDown {
            key: Key::Escape,
            mods: Mods::NONE,
        };
        let r = m.handle(&esc, &c);
        assert!(!m.dragging());
        assert!(matches!(&r.intents[..], [Intent::PutBack { .. }]), "{r:?}");
        // A press on the object's own pixels off the handles arms a body
        // drag; it starts only past the slop, where the press was.
        c.on_selection = true;
        // (The object's pixels are the caller's word; this one is on no
        // handle: a few pixels from the pivot, between the arrows.)
        let body = (0..16)
            .map(|k| k as f32 / 16.0 * std::f32::consts::TAU)
            .map(|a| (pivot.0 + 14.0 * a.cos(), pivot.1 + 14.0 * a.sin()))
            .find(|p| m.hit(&c, p.0, p.1).is_none())
            .expect("a pixel near the pivot off the handles");
        assert!(m.handle(&mouse("down", body), &c).consumed);
        assert!(m.armed() && !m.dragging());
        assert!(
            !m.handle(&mouse("move", (body.0 + 1.0, body.1)), &c)
                .consumed
        );
        let r = m.handle(&mouse("move", (body.0 + 20.0, body.1)), &c);
        assert!(m.dragging() && !m.armed());
        assert_eq!(r.intents[0], Intent::StopPlayback);
        assert!(
            matches!(r.intents.get(2), Some(Intent::ShowNode { .. })),
            "{r:?}"
        );
        // W / E / T pick the tool when nothing is dragged.
        m.handle(&mouse("up", body), &c);
        let e = Event::KeyDown {
            key: Key::Char('e'),
            mods: Mods::NONE,
        };
        assert!(m.handle(&e, &c).redraw);
        assert_eq!(m.tool, Tool::Rotate);
    }
}
