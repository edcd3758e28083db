//! The side panel's scene section as a part: the "Scene" title, the
//! frame rate and length fields, and in a short panel (the graph editor
//! open) one row with the clips behind a `Clips` button. [`SceneSection`]
//! lays it out from a snapshot ([`SceneCtx`]), paints it and owns the
//! press, drag and click-to-type of its two fields (`field_press.rs`),
//! answering with [`Response`]s (show the settings, record them, type)
//! the editor applies. It never names the `Editor`; the clip row at the
//! title's right is the clips' own (`rig/clips.rs`), placed from here.

use super::component::{Intent, Response};
use super::field_press::{drag_of, FieldEvent, FieldPress};
use super::fields::{clamp_note, format_fit, FieldId, FieldValue};
use super::panel::{button, field_row, w, Action, Widget, WidgetKind};
use super::props_view::Look;
use super::rig::clip_action::ClipAction;
use crate::scene::Settings;
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{Painter, Rect};

/// What the scene section sees of the editor.
#[derive(Clone, Debug, Default)]
pub struct SceneCtx {
    /// The section's place (the side panel's `scene`).
    pub area: Rect,
    pub settings: Settings,
    /// Whether the scene has named clips.
    pub has_clips: bool,
    /// The clips' widgets in the title row (`rig/clips.rs`), when the
    /// section is tall enough for a title.
    pub clip_row: Vec<Widget>,
}

/// The scene section's state: the press on fps or len until release.
#[derive(Clone, Debug, Default)]
pub struct SceneSection {
    press: Option<FieldPress<FieldId, Settings>>,
}

impl SceneSection {
    /// Whether `f` is one of its fields.
    pub fn owns(f: FieldId) -> bool {
        f.is_setting()
    }

    /// The title row of a section in `r`, if it is tall enough for one.
    pub fn title_row(r: Rect) -> Option<Rect> {
        (r.h >= 2 * ROW).then(|| r.take_top(ROW).0)
    }

    /// The section's widgets: title, the clips' row, fps and len.
    pub fn widgets(&self, ctx: &SceneCtx, out: &mut Vec<Widget>) {
        let r = ctx.area;
        let mut row = match Self::title_row(r) {
            Some(h) => {
                out.push(w(h, WidgetKind::Header("Scene".into())));
                out.extend(ctx.clip_row.iter().cloned());
                Rect::new(r.x + 2, h.bottom() + 1, r.w - 4, ROW)
            }
            // A short panel (the graph editor open): one row, no title,
            // the clips behind their menu button.
            None => Rect::new(r.x + 2, r.y + 1, r.w - 4, ROW),
        };
        if r.h < 2 * ROW && ctx.has_clips {
            let bw = text::width("Clips") + 4;
            let menu = Rect::new(row.right() - bw, row.y + 1, bw, ROW - 2);
            out.push(button(menu, "Clips", Action::Clip(ClipAction::Menu), false));
            row.w -= bw + 2;
        }
        let half = row.w / 2;
        let (a, b) = row.take_left(half);
        field_row(out, a, "fps", 4 * CHAR_W, &[FieldId::Fps]);
        let b = Rect::new(b.x + 2, b.y, b.w - 2, b.h);
        field_row(out, b, "len", 4 * CHAR_W, &[FieldId::Duration]);
    }

    /// Its own widgets (the clips' row is theirs).
    pub fn own_widgets(&self, ctx: &SceneCtx) -> Vec<Widget> {
        let mut out = Vec::new();
        self.widgets(ctx, &mut out);
        out.retain(|wd| !ctx.clip_row.contains(wd));
        out
    }

    /// The text field `id` shows, at most `max_chars` long.
    pub fn text(id: FieldId, max_chars: usize, ctx: &SceneCtx) -> String {
        match id.read_settings(&ctx.settings) {
            Some(FieldValue::Number(x)) => format_fit(x, max_chars),
            Some(v) => v.display(),
            None => String::new(),
        }
    }

    /// Paints its own widgets, looking as `look` says.
    pub fn draw(&self, p: &mut Painter, ctx: &SceneCtx, look: &Look) {
        for wd in &self.own_widgets(ctx) {
            look.paint(p, wd, |id, max_chars| Self::text(id, max_chars, ctx));
        }
    }

    /// Whether a press on one of its fields holds the mouse.
    pub fn pressed(&self) -> bool {
        self.press.is_some()
    }

    /// Answers a press, drag, release, Esc or typed number on fps or
    /// len: a drag shows the settings changed from the press (one undo
    /// step at the release), a click types, Esc puts them back.
    pub fn handle(&mut self, ev: FieldEvent, ctx: &SceneCtx) -> Response {
        match ev {
            FieldEvent::Press { field, x } => {
                self.press = Some(FieldPress::new(field, x, ctx.settings.clone()));
                Response::taken()
            }
            FieldEvent::Move { x } => {
                let (p, dx) = match drag_of(&mut self.press, x) {
                    Ok(held) => held,
                    Err(r) => return r,
                };
                let (f, base) = (p.field, &p.base);
                let r = Response::redraw().with(Intent::StopPlayback);
                let Some(FieldValue::Number(v0)) = f.read_settings(base) else {
                    return r;
                };
                let mut after = base.clone();
                let v = FieldValue::Number(f.clamp(v0 + dx * f.drag_step()));
                match f.write_settings(&mut after, &v) {
                    true => r.with(Intent::PreviewSettings(after)),
                    false => r,
                }
            }
            FieldEvent::Release => match self.press.take() {
                None => Response::ignored(),
                Some(p) if p.moved() => {
                    let r = Response::redraw().with(Intent::SetSettings {
                        label: format!("Drag {:?}", p.field),
                        before: p.base,
                        after: ctx.settings.clone(),
                    });
                    // A dragged length says what it left past the end,
                    // as a typed one does.
                    match p.field {
                        FieldId::Duration => r.with(Intent::NoteKeysAfterEnd),
                        _ => r,
                    }
                }
                Some(p) => match p.field.read_settings(&p.base) {
                    Some(v) => Response::redraw().with(Intent::Type {
                        field: p.field,
                        text: v.display(),
                    }),
                    None => Response::taken(),
                },
            },
            FieldEvent::Cancel => match self.press.take() {
                Some(p) => Response::redraw().with(Intent::PreviewSettings(p.base)),
                None => Response::ignored(),
            },
            FieldEvent::Typed { field, value } => {
                let mut after = ctx.settings.clone();
                if !field.write_settings(&mut after, &value) {
                    let why = format!("{}: cannot set '{}' here", field.label(), value.display());
                    return Response::redraw().with(Intent::Status(why, true));
                }
                let before = ctx.settings.clone();
                let label = format!("Set {field:?}");
                let mut r =
                    Response::redraw()
                        .with(Intent::StopPlayback)
                        .with(Intent::SetSettings {
                            label,
                            before,
                            after,
                        });
                if field == FieldId::Duration {
                    r = r.with(Intent::NoteKeysAfterEnd);
                }
                if let FieldValue::Number(x) = value {
                    if let Some(n) = clamp_note(&field.label(), x, field.clamp(x)) {
                        r = r.with(Intent::Status(n, false));
                    }
                }
                r
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ctx(h: i32) -> SceneCtx {
        SceneCtx {
            area: Rect::new(300, 20, 160, h),
            settings: Settings {
                fps: 24.0,
                duration: 48.0,
                ..Settings::default()
            },
            has_clips: true,
            clip_row: Vec::new(),
        }
    }

    #[test]
    fn fps_drags_from_the_press_and_len_typed_is_recorded_clamped_and_noted() {
        let (mut s, c) = (SceneSection::default(), ctx(2 * ROW + 4));
        let press = FieldEvent::Press {
            field: FieldId::Fps,
            x: 10.0,
        };
        assert!(s.handle(press, &c).consumed && s.pressed());
        let r = s.handle(FieldEvent::Move { x: 30.0 }, &c);
        let Some(Intent::PreviewSettings(shown)) = r.intents.last() else {
            panic!("a drag shows the settings: {r:?}")
        };
        assert_eq!(shown.fps, 29.0, "20 px x 0.25, whole frames");
        let mut now = c.clone();
        now.settings = shown.clone();
        let r = s.handle(FieldEvent::Release, &now);
        let Some(Intent::SetSettings { before, after, .. }) = r.intents.last() else {
            panic!("one record: {r:?}")
        };
        assert_eq!((before.fps, after.fps), (24.0, 29.0));
        assert!(!s.pressed());
        let typed = FieldEvent::Typed {
            field: FieldId::Duration,
            value: FieldValue::Number(0.2),
        };
        let r = s.handle(typed, &c);
        assert!(r.intents.contains(&Intent::NoteKeysAfterEnd));
        assert!(r.intents.iter().any(|i| matches!(i,
            Intent::SetSettings { after, .. } if after.duration == 1.0)));
        assert!(
            matches!(r.intents.last(), Some(Intent::Status(t, false)) if t.contains("set to 1"))
        );
    }

    #[test]
    fn a_dragged_len_notes_the_keys_after_the_end_and_fps_does_not() {
        for (field, noted) in [(FieldId::Duration, true), (FieldId::Fps, false)] {
            let (mut s, c) = (SceneSection::default(), ctx(2 * ROW + 4));
            s.handle(FieldEvent::Press { field, x: 50.0 }, &c);
            let r = s.handle(FieldEvent::Move { x: 10.0 }, &c);
            let Some(Intent::PreviewSettings(shown)) = r.intents.last() else {
                panic!("a drag shows the settings: {r:?}")
            };
            let mut now = c.clone();
            now.settings = shown.clone();
            let r = s.handle(FieldEvent::Release, &now);
            assert!(r
                .intents
                .iter()
                .any(|i| matches!(i, Intent::SetSettings { .. })));
            assert_eq!(
                r.intents.contains(&Intent::NoteKeysAfterEnd),
                noted,
                "{field:?}: {r:?}"
            );
        }
    }

    #[test]
    fn a_short_section_is_one_row_with_the_clips_behind_a_button() {
        let s = SceneSection::default();
        let mut out = Vec::new();
        s.widgets(&ctx(ROW + 2), &mut out);
        let kinds: Vec<String> = out.iter().map(|w| format!("{:?}", w.kind)).collect();
        assert!(!kinds.iter().any(|k| k.contains("Header")), "{kinds:?}");
        assert!(kinds.iter().any(|k| k.contains("Clips")), "{kinds:?}");
        let fields = out
            .iter()
            .filter(|w| matches!(w.kind, WidgetKind::Field(_)));
        assert_eq!(fields.count(), 2);
        assert!(out.iter().all(|w| w.rect.bottom() <= 20 + ROW + 2));
    }
}
