//! The viewport as a component: what a press in the 3D view starts and
//! where the mouse takes it — the IK target, the handles (a part it
//! owns), a click that picks, orbit, pan, the wheel's zoom, and the right
//! button's pan-or-menu — held as ONE [`Gesture`] until the release. It
//! answers events with a [`Response`] (a new camera, "pick at this
//! pixel", "open the viewport menu here", the handles' node intents, the
//! IK pose) and draws the overlays its gestures own (IK target, handles);
//! it never names the `Editor`. `route/viewport.rs` builds its context,
//! routes to it and keeps the editor's one gesture (`Drag::Viewport`)
//! in step; `route/intents.rs` applies what it returns.
//!
//! The handles stay a part of it rather than a component beside it: the
//! same left press is the IK target's, a handle's, a body press the
//! handles arm, or a pick, in that order, and an armed pick turns into a
//! handle drag past the slop — one owner decides, so the editor never
//! asks two parts in turn.

use crate::editor::component::{Intent, Response};
use crate::editor::gesture::DRAG_SLOP;
use crate::editor::manip::handles::HandlesCtx;
use crate::editor::manip::{Manip, Tool};
use crate::editor::rig::ik_drag;
use crate::editor::rig::state::IkDrag;
use crate::input::camera::Projector;
use crate::input::{Event, Key, Mods, MouseButton, OrbitCamera};
use crate::ui::{Painter, Rect};
use glam::Vec3;

/// The viewport's one gesture in progress, from press to release.
#[derive(Clone, Debug, Default)]
enum Gesture {
    #[default]
    None,
    /// A handle drag: the handles keep its state (`manip/handles.rs`).
    Handle,
    /// The IK target follows the mouse (`rig/ik_drag.rs`).
    Ik(Box<IkDrag>),
    Orbit {
        last: (f32, f32),
    },
    Pan {
        last: (f32, f32),
    },
    /// A left press in select mode: a click picks on release. When the
    /// handles armed it (the selection's body, inside the rotate rings), a
    /// move past the slop turns it into their drag.
    Pick {
        at: (f32, f32),
    },
    /// The right button: a drag pans, a click opens the viewport menu.
    Context {
        at: (f32, f32),
        last: (f32, f32),
        moved: bool,
    },
}

/// The viewport's own state: its gesture and its handles.
#[derive(Clone, Debug, Default)]
pub struct Viewport {
    /// The handles of the current tool (tool, hover, drag, armed press).
    pub handles: Manip,
    gesture: Gesture,
}

/// The IK target as the viewport sees it (IK on for the selected joint).
#[derive(Clone, Debug)]
pub struct IkCtx {
    /// Root, middle and end joint as shown.
    pub chain: [Vec3; 3],
    /// Whether the target is drawn (the joint's skeleton shows).
    pub drawn: bool,
    /// The drag a press on the target starts (built for presses only).
    pub grab: Option<Box<IkDrag>>,
}

/// What the viewport sees of the editor.
#[derive(Clone, Debug)]
pub struct ViewportCtx {
    pub viewport: Rect,
    /// Select mode (left button picks and grabs) or view mode (it orbits).
    pub select_mode: bool,
    pub camera: OrbitCamera,
    /// The view's projector (IK rays and drawing).
    pub proj: Projector,
    /// The handles' context, built only for events that reach them (it
    /// costs a pick and the selection's pixels; see
    /// [`Viewport::wants_handles`]).
    pub handles: Option<HandlesCtx>,
    pub ik: Option<IkCtx>,
}

impl Viewport {
    /// Whether a gesture of the viewport runs (the editor's gesture is
    /// then `Drag::Viewport`).
    pub fn busy(&self) -> bool {
        !matches!(self.gesture, Gesture::None)
    }

    /// Whether `ev` reaches the handles, so the editor builds their
    /// context: a left press that may grab, moves while nothing else runs
    /// (hover) or their drag or armed press does, the release of those,
    /// and their keys (W / E / T, anything during a drag).
    pub fn wants_handles(&self, ev: &Event, select_mode: bool) -> bool {
        let armed = self.handles.armed();
        match *ev {
            Event::MouseDown {
                button: MouseButton::Left,
                mods,
                ..
            } => select_mode && !mods.alt,
            Event::MouseMove { .. } => match self.gesture {
                Gesture::None | Gesture::Handle => true,
                Gesture::Pick { .. } => armed,
                _ => false,
            },
            Event::MouseUp { .. } => match self.gesture {
                Gesture::Handle => true,
                Gesture::Pick { .. } => armed,
                _ => false,
            },
            Event::KeyDown { key, mods } => self.handles_key(key, mods),
            _ => false,
        }
    }

    /// Keys the handles take: any during their drag, else W / E / T
    /// without Ctrl or Alt.
    fn handles_key(&self, key: Key, mods: Mods) -> bool {
        self.handles.dragging()
            || (!(mods.ctrl || mods.alt) && Tool::ALL.iter().any(|t| key == Key::Char(t.key())))
    }

    /// Answers one event the editor routed here: a press in the viewport,
    /// any move or release while its gesture runs (hover otherwise), the
    /// wheel over it, the handles' keys.
    pub fn handle(&mut self, ev: &Event, ctx: &ViewportCtx) -> Response {
        let r = match *ev {
            Event::MouseDown { button, x, y, mods } => self.press(button, x, y, mods, ctx),
            Event::MouseMove { x, y, mods } => self.moved(x, y, mods, ctx),
            Event::MouseUp { x, y, .. } => self.release(x, y, ctx),
            Event::Wheel { delta, .. } => {
                let mut cam = ctx.camera;
                cam.zoom(delta);
                Response::redraw().with(Intent::Camera(cam))
            }
            Event::KeyDown { key, mods } if self.handles_key(key, mods) => {
                self.ask_handles(ev, ctx)
            }
            _ => Response::ignored(),
        };
        // A handle drag started or ended inside the handles.
        if self.handles.dragging() {
            self.gesture = Gesture::Handle;
        } else if matches!(self.gesture, Gesture::Handle) {
            self.gesture = Gesture::None;
        }
        r
    }

    /// Esc while the editor's gesture is the viewport's (the handles take
    /// their own Esc first): the gesture ends where it is.
    pub fn cancel(&mut self) {
        if !self.handles.dragging() {
            self.gesture = Gesture::None;
        }
    }

    fn ask_handles(&mut self, ev: &Event, ctx: &ViewportCtx) -> Response {
        match &ctx.handles {
            Some(h) => self.handles.handle(ev, h),
            None => Response::ignored(),
        }
    }

    fn press(&mut self, b: MouseButton, x: f32, y: f32, mods: Mods, ctx: &ViewportCtx) -> Response {
        let grab = b == MouseButton::Left && !mods.alt && ctx.select_mode;
        if grab {
            let ik = ctx.ik.as_ref().and_then(|ik| {
                let end = ctx.proj.point(ik.chain[2])?;
                ik.grab.clone().filter(|_| ik_drag::grabs(end, x, y))
            });
            if let Some(d) = ik {
                self.gesture = Gesture::Ik(d);
                return Response::redraw().with(Intent::StopPlayback);
            }
            let ev = Event::MouseDown {
                button: MouseButton::Left,
                x,
                y,
                mods: Mods::NONE,
            };
            let r = self.ask_handles(&ev, ctx);
            if r.consumed {
                if !self.handles.dragging() {
                    // Armed on the selection: a click still picks.
                    self.gesture = Gesture::Pick { at: (x, y) };
                }
                return r;
            }
        }
        let at = (x, y);
        self.gesture = match (b, ctx.select_mode) {
            (MouseButton::Middle, _) if mods.shift => Gesture::Pan { last: at },
            (MouseButton::Middle, _) => Gesture::Orbit { last: at },
            (MouseButton::Left, _) if mods.alt => Gesture::Orbit { last: at },
            (MouseButton::Left, false) if mods.shift => Gesture::Pan { last: at },
            (MouseButton::Left, false) => Gesture::Orbit { last: at },
            (MouseButton::Left, true) => Gesture::Pick { at },
            (MouseButton::Right, _) => Gesture::Context {
                at,
                last: at,
                moved: false,
            },
        };
        Response::redraw()
    }

    /// The camera panned by the mouse's move from `last` to (x, y).
    fn panned(ctx: &ViewportCtx, last: (f32, f32), x: f32, y: f32) -> Response {
        let mut cam = ctx.camera;
        cam.pan(x - last.0, y - last.1, ctx.viewport.h as f32);
        Response::redraw().with(Intent::Camera(cam))
    }

    fn moved(&mut self, x: f32, y: f32, mods: Mods, ctx: &ViewportCtx) -> Response {
        let ev = Event::MouseMove { x, y, mods };
        match self.gesture {
            // Hover over the handles; not taken when it changes nothing.
            Gesture::None => return self.ask_handles(&ev, ctx),
            Gesture::Handle | Gesture::Pick { .. } => {
                let r = self.ask_handles(&ev, ctx);
                return if r.consumed { r } else { Response::taken() };
            }
            _ => {}
        }
        match &mut self.gesture {
            Gesture::Ik(d) => match ik_drag::moved(d, &ctx.proj, x, y) {
                None => Response::taken(),
                Some(None) => Response::redraw(),
                Some(Some(joints)) => Response::redraw().with(Intent::IkPose(Box::new(joints))),
            },
            Gesture::Orbit { last } => {
                let mut cam = ctx.camera;
                cam.orbit(x - last.0, y - last.1);
                *last = (x, y);
                Response::redraw().with(Intent::Camera(cam))
            }
            Gesture::Pan { last } => {
                let r = Self::panned(ctx, *last, x, y);
                *last = (x, y);
                r
            }
            Gesture::Context { at, last, moved } => {
                if !*moved && (x - at.0).abs().max((y - at.1).abs()) < DRAG_SLOP {
                    return Response::taken();
                }
                let r = Self::panned(ctx, *last, x, y);
                (*last, *moved) = ((x, y), true);
                r
            }
            _ => Response::taken(),
        }
    }

    fn release(&mut self, x: f32, y: f32, ctx: &ViewportCtx) -> Response {
        // The handles hear their release as a plain left one.
        let up = Event::MouseUp {
            button: MouseButton::Left,
            x,
            y,
            mods: Mods::NONE,
        };
        match std::mem::take(&mut self.gesture) {
            Gesture::Handle => {
                let mut r = self.ask_handles(&up, ctx);
                r.consumed = true;
                r
            }
            Gesture::Ik(_) => Response::redraw().with(Intent::IkDone),
            Gesture::Pick { at } => {
                let mut r = Response::redraw();
                if self.handles.armed() {
                    // Never past the slop: the handles let go, it stays a click.
                    r.intents = self.ask_handles(&up, ctx).intents;
                }
                if (x - at.0).abs() <= DRAG_SLOP && (y - at.1).abs() <= DRAG_SLOP {
                    r = r.with(Intent::Pick((x, y)));
                }
                r
            }
            Gesture::Context { moved: false, .. } => {
                Response::redraw().with(Intent::ViewportMenu((x, y)))
            }
            _ => Response::redraw(),
        }
    }

    /// Draws the overlays the viewport's gestures own: the IK target (and
    /// its chain) and, in select mode, the current tool's handles.
    pub fn draw(&self, p: &mut Painter, ctx: &ViewportCtx) {
        if let Some(ik) = ctx.ik.as_ref().filter(|ik| ik.drawn) {
            let target = match &self.gesture {
                Gesture::Ik(d) => ik_drag::target(d),
                _ => ik.chain[2],
            };
            ik_drag::draw(p, &ctx.proj, ctx.viewport, ik.chain, target);
        }
        if let Some(h) = ctx.handles.as_ref().filter(|_| ctx.select_mode) {
            self.handles.draw(p, h);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ctx(select_mode: bool) -> ViewportCtx {
        let camera = OrbitCamera::default();
        let v = camera.view(200, 100, 1.0);
        ViewportCtx {
            viewport: Rect::new(0, 0, 200, 100),
            select_mode,
            camera,
            proj: Projector::new(&v, 0.0, 0.0, 200.0, 100.0),
            handles: None,
            ik: None,
        }
    }

    fn down(button: MouseButton, x: f32, y: f32, mods: Mods) -> Event {
        Event::MouseDown { button, x, y, mods }
    }
    fn mv(x: f32, y: f32) -> Event {
        Event::MouseMove {
            x,
            y,
            mods: Mods::NONE,
        }
    }
    fn up(x: f32, y: f32) -> Event {
        Event::MouseUp {
            button: MouseButton::Left,
            x,
            y,
            mods: Mods::NONE,
        }
    }
    fn camera_of(r: &Response) -> Option<OrbitCamera> {
        r.intents.iter().find_map(|i| match i {
            Intent::Camera(c) => Some(*c),
            _ => None,
        })
    }

    #[test]
    fn a_click_picks_and_a_drag_in_view_mode_orbits_by_itself() {
        let mut v = Viewport::default();
        let c = ctx(true);
        v.handle(&down(MouseButton::Left, 50.0, 40.0, Mods::NONE), &c);
        assert!(v.busy(), "the press is the viewport's gesture");
        let r = v.handle(&up(52.0, 41.0), &c);
        assert_eq!(r.intents, vec![Intent::Pick((52.0, 41.0))]);
        assert!(!v.busy());
        // Past the slop it is no click.
        v.handle(&down(MouseButton::Left, 50.0, 40.0, Mods::NONE), &c);
        assert!(v.handle(&up(60.0, 40.0), &c).intents.is_empty());
        // View mode: the left button orbits, from the last point each move.
        let c = ctx(false);
        v.handle(&down(MouseButton::Left, 50.0, 40.0, Mods::NONE), &c);
        let cam = camera_of(&v.handle(&mv(60.0, 40.0), &c)).expect("orbited");
        let mut want = c.camera;
        want.orbit(10.0, 0.0);
        assert_eq!(cam, want);
        let second = ViewportCtx {
            camera: cam,
            ..c.clone()
        };
        let cam2 = camera_of(&v.handle(&mv(65.0, 40.0), &second)).unwrap();
        want.orbit(5.0, 0.0);
        assert_eq!(cam2, want);
        v.handle(&up(65.0, 40.0), &c);
        assert!(!v.busy());
    }

    #[test]
    fn the_right_button_pans_past_the_slop_or_opens_the_menu() {
        let mut v = Viewport::default();
        let c = ctx(true);
        v.handle(&down(MouseButton::Right, 80.0, 50.0, Mods::NONE), &c);
        let r = v.handle(&mv(81.0, 51.0), &c);
        assert!(r.consumed && !r.redraw, "within the slop nothing moves");
        assert_eq!(
            v.handle(&up(81.0, 51.0), &c).intents,
            vec![Intent::ViewportMenu((81.0, 51.0))]
        );
        v.handle(&down(MouseButton::Right, 80.0, 50.0, Mods::NONE), &c);
        let cam = camera_of(&v.handle(&mv(90.0, 50.0), &c)).expect("panned");
        let mut want = c.camera;
        want.pan(10.0, 0.0, 100.0);
        assert_eq!(cam, want);
        assert!(v.handle(&up(90.0, 50.0), &c).intents.is_empty(), "no menu");
    }

    #[test]
    fn the_wheel_zooms_and_esc_ends_the_gesture() {
        let mut v = Viewport::default();
        let c = ctx(true);
        let wheel = Event::Wheel {
            delta: 1.0,
            x: 10.0,
            y: 10.0,
            mods: Mods::NONE,
        };
        let mut want = c.camera;
        want.zoom(1.0);
        assert_eq!(camera_of(&v.handle(&wheel, &c)), Some(want));
        v.handle(&down(MouseButton::Middle, 10.0, 10.0, Mods::shift()), &c);
        assert!(v.busy());
        v.cancel();
        assert!(!v.busy());
        assert!(
            v.handle(&mv(30.0, 10.0), &c).intents.is_empty(),
            "no pan left"
        );
    }
}
