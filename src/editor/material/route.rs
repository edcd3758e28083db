//! The editor's side of the material panel: its widgets in the
//! properties' place, what an edit does, K, the wrap toggles and drawing
//! the swatches and the texture thumbnail.
//!
//! An edit follows the other fields' rules (`route/record.rs`): in record
//! mode it keys the property at the current frame (one undo step, the
//! stored value set too when the property was not animated yet); without
//! record mode an animated property keeps the change pending — shown
//! until the frame changes, K keys it — and an unanimated one is set on
//! the material (one undo step). A drag shows its values the pending way
//! and records once at release.

use super::thumb;
use super::{property_value, shown, target, MatAction, MatBase, MatField, MatPending, Shown};
use crate::anim::Property;
use crate::editor::command::Command;
use crate::editor::fields::{format_fit, format_number, FieldId};
use crate::editor::panel::{button, field_row, label, w, Action, Widget, WidgetKind};
use crate::editor::Editor;
use crate::scene::{Material, MaterialId, Scene};
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{theme, Painter, Rect};

/// Rows under the panel's header: name, three colours, shininess and
/// transparency, texture name, wrap, and the emissive map's name (only
/// shown when the material has one).
const ROWS: i32 = 8;

/// The panel's rows inside the properties rect `r`.
struct Rows {
    header: Rect,
    rows: [Rect; ROWS as usize],
    /// The texture thumbnail's box (left of the two texture rows).
    thumb: Rect,
}

fn rows(r: Rect) -> Rows {
    let (header, body) = r.take_top(ROW);
    let body = Rect::new(body.x + 2, body.y + 1, body.w - 4, body.h - 1);
    let rows = std::array::from_fn(|i| Rect::new(body.x, body.y + i as i32 * ROW, body.w, ROW));
    let side = 2 * ROW - 2;
    let thumb = Rect::new(body.x, body.y + 5 * ROW + 1, side, side);
    Rows {
        header,
        rows,
        thumb,
    }
}

/// Short wrap names for the toggles ("S:Rep").
fn wrap_short(w: crate::scene::Wrap) -> &'static str {
    match w {
        crate::scene::Wrap::Repeat => "Rep",
        crate::scene::Wrap::Clamp => "Clamp",
        crate::scene::Wrap::Mirror => "Mir",
    }
}

impl Editor {
    /// What the material panel shows, when it is open and the selection
    /// has a shape.
    pub fn material_panel(&self) -> Option<Shown> {
        if !self.material.open {
            return None;
        }
        shown(&self.scene, self.selection?)
    }

    /// Rows the open panel needs (for the side panel split).
    pub(in crate::internals::editor) fn material_rows(&self) -> Option<i32> {
        let sh = self.material_panel()?;
        let glow = self.scene.materials[sh.material.0 as usize]
            .emissive_texture
            .is_some();
        Some(if glow { ROWS } else { ROWS - 1 })
    }

    /// The pending material change, if it still applies.
    pub fn material_pending(&self) -> Option<&MatPending> {
        self.material
            .pending
            .as_ref()
            .filter(|p| p.frame == self.frame && p.revision == self.history.revision())
    }

    /// Material `id` as shown at the current frame (a pending change
    /// included).
    pub fn shown_material(&self, id: MaterialId) -> Option<Material> {
        if let Some(p) = self.material_pending().filter(|p| p.material == id) {
            return Some(p.value.clone());
        }
        let i = id.0 as usize;
        match &self.pose {
            Some((r, f, pose)) if *r == self.scene_rev && *f == self.frame => {
                pose.materials.get(i).cloned()
            }
            _ => {
                let t = self.frame / self.scene.settings.fps.max(1e-6);
                self.evaluate_shown(t).materials.get(i).cloned()
            }
        }
    }

    /// The scene as shown with a pending material change: its tracks set
    /// aside and the shown values on the material (`evaluate_shown`).
    pub(in crate::internals::editor) fn material_shown_scene(&self) -> Option<Scene> {
        let p = self.material_pending()?;
        let mut s = self.scene.clone();
        *s.materials.get_mut(p.material.0 as usize)? = p.value.clone();
        for &prop in &p.props {
            s.animation.remove_tracks(target(p.material, prop));
        }
        Some(s)
    }

    /// Start of a field drag or typed value.
    pub(in crate::internals::editor) fn material_base(&self) -> Option<MatBase> {
        let sh = self.material_panel()?;
        Some(MatBase {
            material: sh.material,
            start: self.shown_material(sh.material)?,
        })
    }

    /// The material's name for labels and messages: its own, else the
    /// shape's.
    pub(super) fn material_name(&self, id: MaterialId) -> String {
        let own = self
            .scene
            .materials
            .get(id.0 as usize)
            .map(|m| m.name.clone())
            .unwrap_or_default();
        if !own.is_empty() {
            return own;
        }
        match self.material_panel() {
            Some(sh) => crate::editor::ops::display_name(&self.scene, sh.shape),
            None => format!("Material #{}", id.0),
        }
    }

    /// Shows `m` as a pending change of `props` (live while dragging).
    fn show_material(&mut self, id: MaterialId, props: Vec<Property>, m: Material) {
        let mut props = props;
        if let Some(p) = self.material_pending().filter(|p| p.material == id) {
            for &q in &p.props {
                if !props.contains(&q) {
                    props.push(q);
                }
            }
        }
        self.material.pending = Some(MatPending {
            material: id,
            value: m,
            props,
            frame: self.frame,
            revision: self.history.revision(),
        });
        self.pending = None;
        self.rig.morph_pending = None;
        self.scene_rev += 1;
        self.stop_playback();
    }

    /// Live drag: shows the material with field `f` at `v`.
    pub(in crate::internals::editor) fn drag_material(
        &mut self,
        f: MatField,
        base: &MatBase,
        v: f32,
    ) {
        let mut m = base.start.clone();
        f.write(&mut m, v);
        self.show_material(base.material, vec![f.property()], m);
    }

    /// Esc during a drag: drops the shown change.
    pub(in crate::internals::editor) fn cancel_material_drag(&mut self) {
        self.material.pending = None;
        self.scene_rev += 1;
    }

    /// End of a drag: records the value the drag shows.
    pub(in crate::internals::editor) fn finish_material_drag(&mut self, f: MatField, b: &MatBase) {
        let shown = self.material_pending().map(|p| f.read(&p.value));
        if let Some(v) = shown {
            self.set_material(f, b, v);
        }
    }

    /// Typed value or end of a drag: records `v` for field `f` as the
    /// module doc says.
    pub(in crate::internals::editor) fn set_material(&mut self, f: MatField, b: &MatBase, v: f32) {
        if !v.is_finite() {
            self.set_status(&format!("{}: not a finite number", f.label()), true);
            return;
        }
        let id = b.material;
        let Some(stored) = self.scene.materials.get(id.0 as usize).cloned() else {
            return;
        };
        let mut after = b.start.clone();
        f.write(&mut after, v);
        let p = f.property();
        let tgt = target(id, p);
        let animated = self.scene.animation.track(tgt).is_some();
        let name = self.material_name(id);
        let kept = f.clamp(v);
        let note = crate::editor::fields::clamp_note(&f.label(), v, kept);
        if !self.record && animated {
            self.show_material(id, vec![p], after);
            let msg = note.unwrap_or_else(|| "Pending".into());
            self.set_status(
                &format!("{msg}: K keys the material, new frame drops it"),
                false,
            );
            return;
        }
        self.material.pending = None;
        self.scene_rev += 1;
        let mut set = stored.clone();
        f.write(&mut set, v);
        let set_cmd = Command::SetMaterial {
            id,
            before: Box::new(stored),
            after: Box::new(set),
        };
        if !self.record {
            self.stop_playback();
            self.execute(&format!("Set {name} {}", f.label()), set_cmd);
            let msg = note.unwrap_or_else(|| {
                let (l, x) = (f.label(), format_number(kept));
                format!("{name}: {l} = {x} (not animated; Rec or K keys it)")
            });
            self.set_status(&msg, false);
            return;
        }
        let Some(value) = property_value(&after, p) else {
            return;
        };
        let mut anim = self.scene.animation.clone();
        if let Err(e) = anim.set_key(tgt, self.frame, value) {
            self.set_status(&format!("cannot key {name}.{}: {e}", p.name()), true);
            return;
        }
        let mut cmds = Vec::new();
        if !animated {
            cmds.push(set_cmd);
        }
        cmds.push(Command::SetAnimation {
            before: Box::new(self.scene.animation.clone()),
            after: Box::new(anim),
        });
        self.stop_playback();
        let label = format!("Key {name}.{}", p.name());
        self.execute(&label, Command::Group(cmds));
        let fr = format_number(self.frame);
        let msg = note.unwrap_or_else(|| format!("{label} at frame {fr}"));
        self.set_status(&msg, false);
    }

    /// K with a pending material change, or with the mouse over a
    /// material field: keys those properties at the current frame with
    /// the values shown (one undo step). False when K should key
    /// something else.
    pub(in crate::internals::editor) fn key_material(&mut self) -> bool {
        let over = match self.widget_at(self.mouse.0, self.mouse.1).map(|w| w.kind) {
            Some(WidgetKind::Field(FieldId::Material(f))) => Some(f),
            _ => None,
        };
        let pending = self.material_pending().cloned();
        let (id, mut props) = match (&pending, over, self.material_panel()) {
            (Some(p), _, _) => (p.material, p.props.clone()),
            (None, Some(_), Some(sh)) => (sh.material, Vec::new()),
            _ => return false,
        };
        if let Some(f) = over {
            if !props.contains(&f.property()) {
                props.push(f.property());
            }
        }
        let Some(m) = self.shown_material(id) else {
            return false;
        };
        let mut anim = self.scene.animation.clone();
        for &p in &props {
            let Some(v) = property_value(&m, p) else {
                continue;
            };
            if let Err(e) = anim.set_key(target(id, p), self.frame, v) {
                self.set_status(&format!("cannot key {}: {e}", p.name()), true);
                return true;
            }
        }
        self.material.pending = None;
        self.scene_rev += 1;
        self.stop_playback();
        let name = self.material_name(id);
        let names: Vec<&str> = props.iter().map(|p| p.name()).collect();
        let label = format!("Key {name} {}", names.join(", "));
        self.execute(
            &label,
            Command::SetAnimation {
                before: Box::new(self.scene.animation.clone()),
                after: Box::new(anim),
            },
        );
        let fr = format_number(self.frame);
        self.set_status(&format!("{label} at frame {fr}"), false);
        true
    }

    /// M: the material panel in the properties' place, or back.
    pub(in crate::internals::editor) fn toggle_material_panel(&mut self) {
        let a = match self.material.open {
            true => MatAction::Close,
            false => MatAction::Open,
        };
        self.material_action(a);
    }

    /// The key strip's line for a selection without keys of its own
    /// whose material is animated (the strip's rows are the object's
    /// tracks, so material keys would otherwise look absent).
    pub fn material_keys_hint(&self) -> Option<String> {
        let sh = shown(&self.scene, self.selection?)?;
        let mut frames: Vec<f32> = self
            .scene
            .animation
            .tracks_of(crate::anim::TargetRef::Material(sh.material))
            .flat_map(|t| t.keys.frames())
            .collect();
        if frames.is_empty() {
            return None;
        }
        frames.sort_by(f32::total_cmp);
        frames.dedup();
        let list: Vec<String> = frames.iter().take(8).map(|&f| format_number(f)).collect();
        let more = if frames.len() > 8 { " …" } else { "" };
        Some(format!(
            "Material keys at {}{more} (M shows the material; K over a field keys it)",
            list.join(" ")
        ))
    }

    /// The panel's buttons.
    pub(in crate::internals::editor) fn material_action(&mut self, a: MatAction) {
        match a {
            MatAction::Open => {
                self.material.open = true;
                if self.material_panel().is_none() {
                    self.set_status("The selection has no shape, so no material", false);
                }
                return;
            }
            MatAction::Close => {
                self.material.open = false;
                return;
            }
            MatAction::LoadTexture => return self.browse_texture(),
            _ => {}
        }
        let Some(sh) = self.material_panel() else {
            return;
        };
        let id = sh.material;
        let before = self.scene.materials[id.0 as usize].clone();
        let mut after = before.clone();
        let name = self.material_name(id);
        let Some(t) = after.texture.as_mut() else {
            self.set_status(&format!("{name} has no texture"), false);
            return;
        };
        let label = match a {
            MatAction::WrapS => {
                t.wrap_s = super::next_wrap(t.wrap_s);
                format!("{name}: wrap S {}", super::wrap_name(t.wrap_s))
            }
            MatAction::WrapT => {
                t.wrap_t = super::next_wrap(t.wrap_t);
                format!("{name}: wrap T {}", super::wrap_name(t.wrap_t))
            }
            _ => {
                let tex = super::texture_name(&self.scene, &before).unwrap_or_default();
                after.texture = None;
                format!("{name}: texture {tex} removed (Ctrl+Z brings it back)")
            }
        };
        self.stop_playback();
        self.execute(
            &label,
            Command::SetMaterial {
                id,
                before: Box::new(before),
                after: Box::new(after),
            },
        );
        self.set_status(&label, false);
    }

    /// The "Mat" button in the object header that opens the panel.
    pub(in crate::internals::editor) fn material_switch(
        &self,
        header: Rect,
        out: &mut Vec<Widget>,
    ) {
        let Some(sel) = self.selection else { return };
        if shown(&self.scene, sel).is_none() {
            return;
        }
        // Left of the key panel's "Keys" button when that shows.
        let right = out
            .iter()
            .filter(|w| {
                w.rect.y == header.y + 1 && header.contains(w.rect.x as f32, w.rect.y as f32)
            })
            .map(|w| w.rect.x)
            .min()
            .unwrap_or(header.right());
        let bw = text::width("Mat") + 6;
        out.push(button(
            Rect::new(right - bw - 2, header.y + 1, bw, header.h - 2),
            "Mat",
            Action::Material(MatAction::Open),
            false,
        ));
    }

    /// The panel's widgets in the properties rect `r`.
    pub(in crate::internals::editor) fn material_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        let Some(sh) = self.material_panel() else {
            return;
        };
        let l = rows(r);
        out.push(w(l.header, WidgetKind::Header("Material".into())));
        let bw = text::width("Obj") + 6;
        out.push(button(
            Rect::new(
                l.header.right() - bw - 2,
                l.header.y + 1,
                bw,
                l.header.h - 2,
            ),
            "Obj",
            Action::Material(MatAction::Close),
            false,
        ));
        let bottom = r.bottom() + 1;
        let ok = |r: &Rect| r.bottom() <= bottom;
        let [name_r, dif, spe, emi, se, tex_r, wrap, glow] = l.rows;
        let lw = 5 * CHAR_W;
        if ok(&name_r) {
            let name = self.material_name(sh.material);
            let text = match sh.differ {
                true => format!("{name} (first of {} shapes)", sh.shapes),
                false => name,
            };
            out.push(label(name_r, &text, false));
        }
        for (row, (name, fields)) in [dif, spe, emi]
            .iter()
            .zip(["Dif", "Spe", "Emi"].iter().zip(MatField::ROWS))
        {
            if ok(row) {
                let ids: Vec<FieldId> = fields.iter().map(|&f| FieldId::Material(f)).collect();
                field_row(out, *row, name, lw, &ids);
            }
        }
        if ok(&se) {
            let (a, b) = se.take_left(se.w / 2);
            field_row(
                out,
                a,
                "Shin",
                lw,
                &[FieldId::Material(MatField::Shininess)],
            );
            let b = Rect::new(b.x + 2, b.y, b.w - 2, b.h);
            field_row(
                out,
                b,
                "Tra",
                4 * CHAR_W,
                &[FieldId::Material(MatField::Transparency)],
            );
        }
        let m = self.scene.materials.get(sh.material.0 as usize);
        let tex = m.and_then(|m| super::texture_name(&self.scene, m));
        let texture = m.and_then(|m| m.texture.as_ref());
        let x0 = l.thumb.right() + 4;
        if ok(&tex_r) {
            // Right to left: [x] (with a texture), [Load].
            let mut right = tex_r.right() + 2;
            let buttons = [
                ("x", MatAction::RemoveTexture, texture.is_some()),
                ("Load", MatAction::LoadTexture, true),
            ];
            for (name, a, _) in buttons.into_iter().filter(|b| b.2) {
                let bw = text::width(name) + 6;
                right -= bw + 2;
                let r = Rect::new(right, tex_r.y + 1, bw, ROW - 2);
                out.push(button(r, name, Action::Material(a), false));
            }
            match (&tex, texture) {
                (Some(name), Some(_)) => {
                    let nr = Rect::new(x0, tex_r.y, right - x0 - 2, ROW);
                    out.push(label(nr, name, false));
                }
                _ => {
                    let nr = Rect::new(tex_r.x, tex_r.y, right - tex_r.x - 2, ROW);
                    out.push(label(nr, "Texture: none", true));
                }
            }
        }
        // The emissive map (glTF emissiveTexture): named, not edited here.
        let glow_map = m.and_then(|m| m.emissive_texture.as_ref());
        if let (true, Some(t)) = (ok(&glow), glow_map) {
            let name = super::image_name(&self.scene, t).unwrap_or_default();
            out.push(label(glow, &format!("Emissive map: {name}"), false));
        }
        if let (true, Some(t)) = (ok(&wrap), texture) {
            let mut x = x0;
            for (axis, wr, a) in [
                ("S", t.wrap_s, MatAction::WrapS),
                ("T", t.wrap_t, MatAction::WrapT),
            ] {
                let s = format!("{axis}:{}", wrap_short(wr));
                let bw = text::width(&s) + 4;
                if x + bw > wrap.right() {
                    break;
                }
                out.push(button(
                    Rect::new(x, wrap.y + 1, bw, ROW - 2),
                    &s,
                    Action::Material(a),
                    false,
                ));
                x += bw + 2;
            }
        }
    }

    /// A material field's text (the shown value).
    pub(in crate::internals::editor) fn material_text(&self, f: MatField, max: usize) -> String {
        self.material_panel()
            .and_then(|sh| self.shown_material(sh.material))
            .map(|m| format_fit(f.read(&m), max))
            .unwrap_or_default()
    }

    /// Colour swatches beside the colour rows' labels and the texture
    /// thumbnail (drawn after the widgets).
    pub(in crate::internals::editor) fn draw_material_extras(&self, p: &mut Painter) {
        let Some(sh) = self.material_panel() else {
            return;
        };
        // Laid out like the widgets: in the scrolled rows, drawn where
        // they show.
        let (props, tall) = self.props_view();
        let l = rows(tall);
        let Some(m) = self.shown_material(sh.material) else {
            return;
        };
        let bottom = props.bottom() + 1;
        let top = props.y + ROW;
        for (i, c) in [m.diffuse, m.specular, m.emissive].into_iter().enumerate() {
            let r = l.rows[1 + i];
            if r.y >= top && r.bottom() <= bottom {
                let s = Rect::new(r.x + 3 * CHAR_W + 3, r.y + 4, 8, 8);
                p.fill_rect(s, super::swatch(c));
                p.stroke_rect(s.inset(-1), theme::BORDER);
            }
        }
        let t = l.thumb;
        if t.y < top || t.bottom() > bottom {
            return;
        }
        let img = m.texture.as_ref().and_then(|tx| self.scene.image(tx.image));
        let Some(img) = img else {
            return;
        };
        p.fill_rect(t, theme::FIELD);
        let inner = t.inset(1);
        let (tw, th) = thumb::fit(img, inner.w as u32);
        let px = thumb::pixels(img, tw, th);
        let x0 = inner.x + (inner.w - tw as i32) / 2;
        let y0 = inner.y + (inner.h - th as i32) / 2;
        for (i, &c) in px.iter().enumerate() {
            let (x, y) = ((i as u32 % tw) as i32, (i as u32 / tw) as i32);
            p.fill_rect(Rect::new(x0 + x, y0 + y, 1, 1), c);
        }
        p.stroke_rect(t, theme::BORDER);
    }
}
