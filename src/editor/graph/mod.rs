//! The graph (curve) editor: value over time of the selected object's
//! animated channels, drawn by sampling `Track::sample`, with the keys as
//! points to select and drag (time and value), a tangent handle on TCB
//! keys that sets tension (its length) and bias (its direction; continuity
//! with Alt), zoom, pan, framing, a normalised view and a scrubbable frame
//! line. It takes the key strip's place (toolbar `Graph`, Shift+F6).
//!
//! A component: it owns its view, channel switches, key selection and the
//! one gesture in progress, takes events through [`GraphEditor::handle`]
//! and returns a [`Response`] whose intents the editor applies (previews
//! while dragging, one `SetAnimation` command at release). It never names
//! the editor.

pub mod channel;
pub mod curve;
mod draw;
pub mod edit;
pub mod view;

use super::component::{Intent, Keyed, Response};
use super::keystrip::KeyRef;
use crate::anim::hermite::Tcb;
use crate::anim::Animation;
use crate::input::{Event, Key, Mods, MouseButton};
use crate::scene::NodeId;
use crate::ui::Rect;
use channel::{channels_of, Channel};
use curve::Curve;
use edit::{Chords, CurveKey};
use view::View;

/// Height of the splitter bar at the top of the graph area.
pub const SPLIT_H: i32 = 5;
/// Height of the frame-number band at the top of the plot (scrubs).
pub const BAND_H: i32 = 14;
/// Height of a channel list row.
pub const CHANNEL_ROW: i32 = 16;
/// Pixels within which a click takes a key or a handle.
const GRAB: f32 = 6.0;
/// Pixels the mouse may move before a press on a key counts as a drag.
const SLOP: f32 = 3.0;

/// What the graph needs to know of the editor for one event or draw.
pub struct Ctx<'a> {
    /// The animation, selected object, frame and length (`ctx.anim`, ...).
    pub keyed: Keyed<'a>,
    /// The whole graph area (splitter, channel list, plot).
    pub rect: Rect,
    /// The editor's selected keys (shared with the key strip and panel).
    pub selected: &'a [KeyRef],
}

impl<'a> std::ops::Deref for Ctx<'a> {
    type Target = Keyed<'a>;
    fn deref(&self) -> &Keyed<'a> {
        &self.keyed
    }
}

/// The graph area's parts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Areas {
    pub split: Rect,
    pub list: Rect,
    pub band: Rect,
    pub plot: Rect,
}

impl Areas {
    pub fn new(r: Rect) -> Areas {
        let (split, rest) = r.take_top(SPLIT_H);
        let list_w = (rest.w / 4).clamp(60, 150);
        let (list, right) = rest.take_left(list_w);
        let (band, plot) = right.take_top(BAND_H);
        Areas {
            split,
            list,
            band,
            plot,
        }
    }
}

/// The one gesture in progress.
#[derive(Clone, Debug)]
enum Gesture {
    /// Pressed on a key: drags the selected keys from `base`.
    Keys {
        start: (f32, f32),
        base: Box<Animation>,
        keys: Vec<CurveKey>,
        moved: bool,
        /// A click (no drag) on a selected key selects just it.
        narrow_to: Option<CurveKey>,
    },
    /// Pressed on a TCB key's tangent handle.
    Handle {
        key: CurveKey,
        base: Box<Animation>,
        tcb: Tcb,
        chords: Chords,
        start: (f32, f32),
    },
    Box {
        from: (f32, f32),
        to: (f32, f32),
        add: bool,
    },
    Pan {
        last: (f32, f32),
    },
    /// Right button in the plot: a drag pans, a click asks for the keys'
    /// context menu.
    Context {
        at: (f32, f32),
        last: (f32, f32),
        moved: bool,
    },
    Scrub,
    /// Dragging the splitter: the graph's height from `h0` at `y0`.
    Split {
        y0: f32,
        h0: i32,
    },
}

/// Graph editor state.
#[derive(Clone, Debug)]
pub struct GraphEditor {
    pub view: View,
    /// Height of the graph area (the split with the viewport).
    pub height: i32,
    pub normalised: bool,
    hidden: Vec<Channel>,
    locked: Vec<Channel>,
    /// Which curves' keys are selected (the editor's key selection says
    /// which keys; this says which of their components).
    sel: Vec<CurveKey>,
    gesture: Option<Gesture>,
    /// The node the view was last framed for (a new one is framed).
    framed: Option<NodeId>,
    /// Normalisation ranges frozen while a drag runs.
    frozen: Option<Vec<(Channel, (f32, f32))>>,
    /// The channel of the key a context menu was opened on ("Select all
    /// on channel").
    menu_channel: Option<Channel>,
}

impl Default for GraphEditor {
    fn default() -> Self {
        GraphEditor {
            view: View::default(),
            height: 200,
            normalised: false,
            hidden: Vec::new(),
            locked: Vec::new(),
            sel: Vec::new(),
            gesture: None,
            framed: None,
            frozen: None,
            menu_channel: None,
        }
    }
}

/// A key's tangent handle as drawn and grabbed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TangentHandle {
    /// The key's pixel.
    pub key: (f32, f32),
    /// The grabbed end (the outgoing side; the incoming side mirrors it).
    pub end: (f32, f32),
    pub tcb: Tcb,
    /// The chords around the key on its curve.
    pub chords: Chords,
}

/// One channel as shown: its curve and how its values map to the plot.
pub struct Shown {
    pub ch: Channel,
    pub curve: Curve,
    /// Value → plot value: `(v - offset) * scale` (normalised view), or
    /// identity.
    pub offset: f32,
    pub scale: f32,
}

impl Shown {
    pub fn to_plot(&self, v: f32) -> f32 {
        (v - self.offset) * self.scale
    }
}

impl GraphEditor {
    pub fn is_dragging(&self) -> bool {
        self.gesture.is_some()
    }

    pub fn is_hidden(&self, c: &Channel) -> bool {
        self.hidden.contains(c)
    }

    pub fn is_locked(&self, c: &Channel) -> bool {
        self.locked.contains(c)
    }

    /// The channels of the selected object.
    pub fn channels(&self, ctx: &Ctx) -> Vec<Channel> {
        ctx.node
            .map(|n| channels_of(ctx.anim, n))
            .unwrap_or_default()
    }

    /// Curve keys shown selected: the graph's own picks among the editor's
    /// selected keys; a selected key the graph did not pick (chosen in the
    /// strip) shows on all its curves.
    pub fn selected(&self, ctx: &Ctx) -> Vec<CurveKey> {
        let mut out: Vec<CurveKey> = Vec::new();
        for r in ctx.selected {
            let own: Vec<CurveKey> = self
                .sel
                .iter()
                .filter(|k| k.key_ref().same(r))
                .copied()
                .collect();
            if own.is_empty() {
                for ch in self.channels(ctx) {
                    if ch.property == r.property && ch.node == r.node && !self.is_hidden(&ch) {
                        out.push(CurveKey { ch, frame: r.frame });
                    }
                }
            } else {
                out.extend(own);
            }
        }
        out
    }

    /// The visible channels' curves over the plot's frames.
    pub fn shown(&self, ctx: &Ctx) -> Vec<Shown> {
        let a = Areas::new(ctx.rect);
        let step = (self.view.f1 - self.view.f0) / a.plot.w.max(1) as f32;
        self.channels(ctx)
            .into_iter()
            .filter(|c| !self.is_hidden(c))
            .filter_map(|ch| {
                let curve = curve::sample(ctx.anim, ch, self.view.f0, self.view.f1, step)?;
                let (offset, scale) = if self.normalised {
                    let range = self
                        .frozen
                        .as_ref()
                        .and_then(|f| f.iter().find(|(c, _)| *c == ch).map(|x| x.1))
                        .or_else(|| self.full_range(ctx.anim, ch));
                    normalise(range)
                } else {
                    (0.0, 1.0)
                };
                Some(Shown {
                    ch,
                    curve,
                    offset,
                    scale,
                })
            })
            .collect()
    }

    /// A channel's value range over its whole key span.
    fn full_range(&self, anim: &Animation, ch: Channel) -> Option<(f32, f32)> {
        let (f0, f1) = anim.track(ch.target())?.frame_range()?;
        curve::sample(anim, ch, f0, f1, ((f1 - f0) / 200.0).max(0.05))?.value_range()
    }

    /// Pixel position of a curve key.
    pub fn key_point(&self, ctx: &Ctx, k: CurveKey) -> Option<(f32, f32)> {
        let a = Areas::new(ctx.rect);
        let s = self.shown(ctx).into_iter().find(|s| s.ch == k.ch)?;
        let v = s.curve.key_value(k.frame)?;
        Some((
            self.view.frame_to_x(a.plot, k.frame),
            self.view.value_to_y(a.plot, s.to_plot(v)),
        ))
    }

    /// The tangent handle of a selected key: key point, handle end, the
    /// key's TCB and the chords around it on its curve. Step and linear
    /// keys have one too (drawn dim): it shows the TCB tangent their
    /// numbers would give, and dragging it makes them TCB keys, as editing
    /// T, C or B in the key panel does.
    pub fn handle_of(&self, ctx: &Ctx, k: CurveKey) -> Option<TangentHandle> {
        let a = Areas::new(ctx.rect);
        let key = k.key_ref().get(ctx.anim)?;
        let s = self.shown(ctx).into_iter().find(|s| s.ch == k.ch)?;
        let i = s
            .curve
            .keys
            .iter()
            .position(|p| (p.0 - k.frame).abs() <= crate::anim::KEY_EPS)?;
        let chords = Chords::at(&s.curve.keys, i);
        let tcb = Tcb {
            tension: key.tension,
            continuity: key.continuity,
            bias: key.bias,
        };
        let slope = chords.slope(tcb)?;
        let p = self.key_point(ctx, k)?;
        let (sx, sy) = self.view.scale(a.plot);
        let d = glam::Vec2::new(sx, -slope * s.scale * sy).normalize_or(glam::Vec2::X);
        let len = edit::handle_len(key.tension);
        Some(TangentHandle {
            key: p,
            end: (p.0 + d.x * len, p.1 + d.y * len),
            tcb,
            chords,
        })
    }

    /// Shows everything (Home) or the selected keys (F).
    pub fn frame(&mut self, ctx: &Ctx, selected_only: bool) {
        let sel = self.selected(ctx);
        let mut f = (f32::INFINITY, f32::NEG_INFINITY);
        let mut v = f;
        let saved = self.view;
        // Curves over the whole key span, whatever the view shows now.
        if let Some(r) = self
            .channels(ctx)
            .iter()
            .filter_map(|c| ctx.anim.track(c.target())?.frame_range())
            .reduce(|a, b| (a.0.min(b.0), a.1.max(b.1)))
        {
            self.view.f0 = r.0;
            self.view.f1 = r.1.max(r.0 + 1.0);
        }
        for s in self.shown(ctx) {
            for &(kf, kv) in &s.curve.keys {
                let take = !selected_only
                    || sel
                        .iter()
                        .any(|k| k.ch == s.ch && (k.frame - kf).abs() < 1e-3);
                if take {
                    f = (f.0.min(kf), f.1.max(kf));
                    v = (v.0.min(s.to_plot(kv)), v.1.max(s.to_plot(kv)));
                }
            }
            if !selected_only {
                for &(_, sv) in &s.curve.samples {
                    v = (v.0.min(s.to_plot(sv)), v.1.max(s.to_plot(sv)));
                }
            }
        }
        self.view = saved;
        if f.0 <= f.1 && v.0 <= v.1 {
            self.view.fit(f, v);
        }
    }

    /// Frames the channels of a newly shown object.
    pub fn follow(&mut self, ctx: &Ctx) {
        if ctx.node != self.framed {
            self.framed = ctx.node;
            self.sel.clear();
            if ctx.node.is_some() {
                self.frame(ctx, false);
            }
        }
    }

    /// Feeds one event. Mouse events outside the graph area are not taken
    /// unless a gesture that started in it is running.
    pub fn handle(&mut self, ev: &Event, ctx: &Ctx) -> Response {
        let a = Areas::new(ctx.rect);
        match *ev {
            Event::MouseDown { button, x, y, mods } if ctx.rect.contains(x, y) => {
                self.press(button, x, y, mods, ctx, &a)
            }
            Event::MouseMove { x, y, mods } if self.gesture.is_some() => {
                self.drag(x, y, mods, ctx, &a)
            }
            Event::MouseUp { x, y, .. } if self.gesture.is_some() => self.release(x, y, ctx),
            Event::Wheel { delta, x, y, mods }
                if a.plot.contains(x, y) || a.band.contains(x, y) =>
            {
                self.view.zoom(a.plot, delta, x, y, mods.ctrl);
                Response::redraw()
            }
            Event::KeyDown { key, mods } => self.key(key, mods, ctx),
            _ => Response::ignored(),
        }
    }

    fn press(
        &mut self,
        button: MouseButton,
        x: f32,
        y: f32,
        mods: Mods,
        ctx: &Ctx,
        a: &Areas,
    ) -> Response {
        if self.gesture.is_some() {
            return Response::taken();
        }
        if button == MouseButton::Middle {
            self.gesture = Some(Gesture::Pan { last: (x, y) });
            return Response::taken();
        }
        if button == MouseButton::Right && a.plot.contains(x, y) {
            self.gesture = Some(Gesture::Context {
                at: (x, y),
                last: (x, y),
                moved: false,
            });
            return Response::taken();
        }
        if button != MouseButton::Left {
            return Response::taken();
        }
        if a.split.contains(x, y) {
            self.gesture = Some(Gesture::Split {
                y0: y,
                h0: self.height,
            });
            return Response::taken();
        }
        if a.list.contains(x, y) {
            return self.press_list(x, y, mods, ctx, a);
        }
        let cursor_x = self.view.frame_to_x(a.plot, ctx.frame);
        if a.band.contains(x, y)
            || ((x - cursor_x).abs() <= 3.0 && self.key_at(ctx, x, y).is_none())
        {
            self.gesture = Some(Gesture::Scrub);
            return self.scrub(x, ctx, a);
        }
        if !a.plot.contains(x, y) {
            return Response::taken();
        }
        // A selected TCB key's handle first (it sits over other keys).
        for k in self.selected(ctx) {
            if self.is_locked(&k.ch) {
                continue;
            }
            if let Some(TangentHandle {
                end, tcb, chords, ..
            }) = self.handle_of(ctx, k)
            {
                if dist((x, y), end) <= GRAB {
                    self.gesture = Some(Gesture::Handle {
                        key: k,
                        base: Box::new(ctx.anim.clone()),
                        tcb,
                        chords,
                        start: (x, y),
                    });
                    self.freeze(ctx);
                    return Response::redraw();
                }
            }
        }
        if let Some(k) = self.key_at(ctx, x, y) {
            let mut sel = self.selected(ctx);
            let was = sel.iter().any(|s| s.same(&k));
            let mut narrow_to = None;
            if mods.shift {
                if was {
                    sel.retain(|s| !s.same(&k));
                } else {
                    sel.push(k);
                }
            } else if was {
                narrow_to = Some(k);
            } else {
                sel = vec![k];
            }
            let keys: Vec<CurveKey> = sel
                .iter()
                .filter(|s| !self.is_locked(&s.ch))
                .copied()
                .collect();
            self.gesture = (!mods.shift || !was).then(|| Gesture::Keys {
                start: (x, y),
                base: Box::new(ctx.anim.clone()),
                keys,
                moved: false,
                narrow_to,
            });
            self.freeze(ctx);
            return self.set_selection(sel);
        }
        self.gesture = Some(Gesture::Box {
            from: (x, y),
            to: (x, y),
            add: mods.shift,
        });
        Response::redraw()
    }

    fn press_list(&mut self, x: f32, y: f32, mods: Mods, ctx: &Ctx, a: &Areas) -> Response {
        let row = ((y - a.list.y as f32) / CHANNEL_ROW as f32).floor() as i32 - 1;
        let chans = self.channels(ctx);
        let Some(&ch) = usize::try_from(row).ok().and_then(|r| chans.get(r)) else {
            return Response::taken();
        };
        let dx = x - a.list.x as f32;
        if dx < 16.0 {
            toggle(&mut self.hidden, ch);
            return Response::redraw();
        }
        if dx < 30.0 {
            toggle(&mut self.locked, ch);
            return Response::redraw();
        }
        // The name: select the channel's keys (Shift adds).
        let keys = self.channel_keys(ch, ctx);
        let mut sel = if mods.shift {
            self.selected(ctx)
        } else {
            Vec::new()
        };
        for k in keys {
            if !sel.iter().any(|s| s.same(&k)) {
                sel.push(k);
            }
        }
        self.hidden.retain(|c| *c != ch);
        self.set_selection(sel)
    }

    fn drag(&mut self, x: f32, y: f32, mods: Mods, ctx: &Ctx, a: &Areas) -> Response {
        let Some(g) = self.gesture.clone() else {
            return Response::ignored();
        };
        match g {
            Gesture::Pan { last } => {
                self.view.pan(a.plot, x - last.0, y - last.1);
                self.gesture = Some(Gesture::Pan { last: (x, y) });
                Response::redraw()
            }
            Gesture::Context { at, last, moved } => {
                let moved = moved || dist(at, (x, y)) > 3.0;
                if moved {
                    self.view.pan(a.plot, x - last.0, y - last.1);
                }
                self.gesture = Some(Gesture::Context {
                    at,
                    last: (x, y),
                    moved,
                });
                Response::redraw()
            }
            Gesture::Split { y0, h0 } => {
                self.height = h0 + (y0 - y).round() as i32;
                Response::redraw()
            }
            Gesture::Scrub => self.scrub(x, ctx, a),
            Gesture::Box { from, add, .. } => {
                self.gesture = Some(Gesture::Box {
                    from,
                    to: (x, y),
                    add,
                });
                Response::redraw()
            }
            Gesture::Keys {
                start,
                base,
                keys,
                moved,
                narrow_to,
            } => {
                if !moved && dist(start, (x, y)) < SLOP {
                    return Response::taken();
                }
                self.gesture = Some(Gesture::Keys {
                    start,
                    base: base.clone(),
                    keys: keys.clone(),
                    moved: true,
                    narrow_to,
                });
                let (sx, sy) = self.view.scale(a.plot);
                let mut df = (x - start.0) / sx;
                if mods.ctrl {
                    // Ctrl snaps: the grabbed key lands on a whole frame.
                    let f0 = keys.first().map(|k| k.frame).unwrap_or(0.0);
                    df = (f0 + df).round() - f0;
                }
                let dv_plot = -(y - start.1) / sy;
                // In the normalised view a pixel is a different value step
                // per curve: move each key by its own curve's scale.
                let shown = self.shown(ctx);
                let mut anim = (*base).clone();
                let mut moved_keys = Vec::new();
                let mut ok = true;
                // Values per curve scale first, then time once for all.
                for (scale, ks) in group_by_scale(&keys, &shown) {
                    let dv = if scale != 0.0 { dv_plot / scale } else { 0.0 };
                    match edit::move_keys(&anim, &ks, 0.0, dv) {
                        Ok((a2, _)) => anim = a2,
                        Err(_) => ok = false,
                    }
                    moved_keys.extend(ks);
                }
                if !ok {
                    return Response::taken();
                }
                match edit::move_keys(&anim, &moved_keys, df, 0.0) {
                    Ok((after, now)) => {
                        self.sel = now;
                        let refs = edit::key_refs(&self.sel);
                        Response::redraw()
                            .with(Intent::Preview(after))
                            .with(Intent::SelectKeys(refs))
                    }
                    // Two keys would meet: keep the last valid state.
                    Err(e) => Response::taken().with(Intent::Status(e, true)),
                }
            }
            Gesture::Handle {
                key,
                base,
                tcb,
                chords,
                start,
            } => {
                let Some(p) = self.key_point(ctx, key) else {
                    return Response::taken();
                };
                let mut new = tcb;
                if mods.alt {
                    // Continuity rides on Alt: sideways motion.
                    new.continuity = (tcb.continuity + (x - start.0) / 60.0).clamp(-1.0, 1.0);
                } else {
                    let (dx, dy) = ((x - p.0).max(1.0), y - p.1);
                    // Relative to where the handle was grabbed, so a press
                    // beside its end does not jump.
                    let grabbed = (start.0 - p.0).max(1.0).hypot(start.1 - p.1);
                    let len = edit::handle_len(tcb.tension) * dx.hypot(dy) / grabbed;
                    new.tension = edit::tension_for_len(len);
                    let (sx, sy) = self.view.scale(a.plot);
                    let scale = self
                        .shown(ctx)
                        .iter()
                        .find(|s| s.ch == key.ch)
                        .map(|s| s.scale)
                        .unwrap_or(1.0);
                    // Bias follows the handle's turn since the grab, on an
                    // angle scale (`edit::TURN_PER_BIAS`); screen up is
                    // up the curve unless the channel's scale flips it.
                    let flip = (sy * scale / sx).signum();
                    let angle = |dx: f32, dy: f32| (-dy * flip).atan2(dx);
                    let turn = angle(dx, dy) - angle((start.0 - p.0).max(1.0), start.1 - p.1);
                    if let Some(b) = chords.bias_turned(new, tcb.bias, turn) {
                        new.bias = b;
                    }
                }
                match edit::set_tcb(&base, key.key_ref(), new) {
                    Ok(after) => {
                        let msg = format!(
                            "T {:.2}  C {:.2}  B {:.2}",
                            new.tension, new.continuity, new.bias
                        );
                        Response::redraw()
                            .with(Intent::Preview(after))
                            .with(Intent::Status(msg, false))
                    }
                    Err(e) => Response::taken().with(Intent::Status(e, true)),
                }
            }
        }
    }

    fn release(&mut self, x: f32, y: f32, ctx: &Ctx) -> Response {
        let g = self.gesture.take();
        self.frozen = None;
        match g {
            Some(Gesture::Keys {
                base, moved: true, ..
            }) => Response::redraw().with(commit("Move keys in graph", *base, ctx)),
            Some(Gesture::Keys {
                narrow_to: Some(k),
                moved: false,
                ..
            }) => self.set_selection(vec![k]),
            Some(Gesture::Handle { base, .. }) => {
                Response::redraw().with(commit("Shape tangent in graph", *base, ctx))
            }
            Some(Gesture::Box { from, add, .. }) => {
                let r = rect_of(from, (x, y));
                let mut sel = if add { self.selected(ctx) } else { Vec::new() };
                for s in self.shown(ctx) {
                    for &(f, _) in &s.curve.keys {
                        let k = CurveKey { ch: s.ch, frame: f };
                        if let Some(p) = self.key_point(ctx, k) {
                            if r.contains(p.0, p.1) && !sel.iter().any(|o| o.same(&k)) {
                                sel.push(k);
                            }
                        }
                    }
                }
                self.set_selection(sel)
            }
            Some(Gesture::Context {
                at, moved: false, ..
            }) => self.context_click(at, ctx),
            Some(_) => Response::redraw(),
            None => Response::ignored(),
        }
    }

    /// A right click in the plot: the key under the mouse is selected
    /// (unless it already is) and the editor is asked for the keys'
    /// context menu.
    fn context_click(&mut self, at: (f32, f32), ctx: &Ctx) -> Response {
        let hit = self.key_at(ctx, at.0, at.1);
        self.menu_channel = hit.map(|k| k.ch);
        let mut r = match hit {
            Some(k) if !self.selected(ctx).iter().any(|s| s.same(&k)) => {
                self.set_selection(vec![k])
            }
            _ => Response::redraw(),
        };
        r.intents.push(Intent::ContextMenu(at));
        r
    }

    /// The channel the context menu was opened on, if any.
    pub fn menu_channel(&self) -> Option<Channel> {
        self.menu_channel
    }

    /// "Select all on channel": every key of the menu's channel.
    pub fn select_channel(&mut self, ctx: &Ctx) -> Response {
        let Some(ch) = self.menu_channel else {
            return Response::ignored();
        };
        let sel = self.channel_keys(ch, ctx).collect();
        self.hidden.retain(|c| *c != ch);
        self.set_selection(sel)
    }

    /// Every key of channel `ch`'s curve.
    fn channel_keys(&self, ch: Channel, ctx: &Ctx) -> impl Iterator<Item = CurveKey> {
        ctx.anim
            .track(ch.target())
            .map(|t| t.keys.frames())
            .unwrap_or_default()
            .into_iter()
            .map(move |frame| CurveKey { ch, frame })
    }

    fn key(&mut self, key: Key, mods: Mods, ctx: &Ctx) -> Response {
        if let Some(g) = &self.gesture {
            if key != Key::Escape {
                return Response::taken();
            }
            let base = match g {
                Gesture::Keys { base, .. } | Gesture::Handle { base, .. } => Some((**base).clone()),
                _ => None,
            };
            self.gesture = None;
            self.frozen = None;
            let r = Response::redraw();
            return match base {
                Some(b) => r.with(Intent::Preview(b)),
                None => r,
            };
        }
        match (key, mods.ctrl) {
            (Key::Home, _) => {
                self.frame(ctx, false);
                Response::redraw()
            }
            (Key::Char('f'), false) => {
                self.frame(ctx, true);
                Response::redraw()
            }
            (Key::Char('n'), false) if !mods.shift => {
                self.normalised = !self.normalised;
                self.frame(ctx, false);
                Response::redraw()
            }
            // Delete, Ctrl+C and Ctrl+V fall through to the key strip's
            // edits of the (shared) selected keys.
            _ => Response::ignored(),
        }
    }

    fn scrub(&mut self, x: f32, ctx: &Ctx, a: &Areas) -> Response {
        let f = self
            .view
            .x_to_frame(a.plot, x)
            .round()
            .clamp(0.0, ctx.duration.max(0.0));
        Response::redraw().with(Intent::Seek(f))
    }

    fn set_selection(&mut self, sel: Vec<CurveKey>) -> Response {
        self.sel = sel;
        Response::redraw().with(Intent::SelectKeys(edit::key_refs(&self.sel)))
    }

    /// Keeps the normalised view's ranges still while a drag runs.
    fn freeze(&mut self, ctx: &Ctx) {
        if self.normalised {
            let f = self
                .channels(ctx)
                .into_iter()
                .filter_map(|c| Some((c, self.full_range(ctx.anim, c)?)))
                .collect();
            self.frozen = Some(f);
        }
    }

    /// The visible key nearest to (x, y) within [`GRAB`] pixels.
    pub fn key_at(&self, ctx: &Ctx, x: f32, y: f32) -> Option<CurveKey> {
        let mut best: Option<(f32, CurveKey)> = None;
        for s in self.shown(ctx) {
            for &(f, _) in &s.curve.keys {
                let k = CurveKey { ch: s.ch, frame: f };
                let Some(p) = self.key_point(ctx, k) else {
                    continue;
                };
                let d = dist(p, (x, y));
                if d <= GRAB && best.is_none_or(|b| d < b.0) {
                    best = Some((d, k));
                }
            }
        }
        best.map(|b| b.1)
    }

    /// The selection box being dragged, if any.
    pub fn box_rect(&self) -> Option<Rect> {
        match &self.gesture {
            Some(Gesture::Box { from, to, .. }) => Some(rect_of(*from, *to)),
            _ => None,
        }
    }
}

/// Commits a drag that previewed from `base`.
fn commit(label: &str, base: Animation, ctx: &Ctx) -> Intent {
    Intent::Commit {
        label: label.to_string(),
        before: base,
        after: ctx.anim.clone(),
    }
}

/// Groups keys by the plot scale of their curve (1 outside the normalised
/// view, so one group).
fn group_by_scale(keys: &[CurveKey], shown: &[Shown]) -> Vec<(f32, Vec<CurveKey>)> {
    let mut out: Vec<(f32, Vec<CurveKey>)> = Vec::new();
    for k in keys {
        let s = shown
            .iter()
            .find(|s| s.ch == k.ch)
            .map(|s| s.scale)
            .unwrap_or(1.0);
        match out.iter_mut().find(|g| g.0 == s) {
            Some(g) => g.1.push(*k),
            None => out.push((s, vec![*k])),
        }
    }
    out
}

/// (offset, scale) that maps `range` onto -1..1.
fn normalise(range: Option<(f32, f32)>) -> (f32, f32) {
    match range {
        Some((lo, hi)) if hi - lo > 1e-6 => ((lo + hi) / 2.0, 2.0 / (hi - lo)),
        Some((lo, _)) => (lo, 1.0),
        None => (0.0, 1.0),
    }
}

fn toggle(v: &mut Vec<Channel>, c: Channel) {
    match v.iter().position(|x| *x == c) {
        Some(i) => {
            v.remove(i);
        }
        None => v.push(c),
    }
}

fn dist(a: (f32, f32), b: (f32, f32)) -> f32 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

fn rect_of(a: (f32, f32), b: (f32, f32)) -> Rect {
    let (x0, y0) = (a.0.min(b.0), a.1.min(b.1));
    Rect::new(
        x0 as i32,
        y0 as i32,
        (a.0.max(b.0) - x0).round() as i32 + 1,
        (a.1.max(b.1) - y0).round() as i32 + 1,
    )
}
