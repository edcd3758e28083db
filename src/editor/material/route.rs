//! The editor's side of the material panel: the snapshot its rows see
//! (`rows_ui.rs` lays them out, paints them and holds their press), what
//! an edit does, K and the wrap toggles.
//!
//! An edit follows the other fields' rules (`route/record.rs`): in record
//! mode it keys the property at the current frame (one undo step, the
//! stored value set too when the property was not animated yet); without
//! record mode an animated property keeps the change pending — shown
//! until the frame changes, K keys it — and an unanimated one is set on
//! the material (one undo step). A drag shows its values the pending way
//! and records once at release.

use super::rows_ui::MatCtx;
use super::{property_value, shown, target, MatAction, MatBase, MatField, MatPending, Shown};
use crate::anim::Property;
use crate::editor::command::Command;
use crate::editor::fields::{format_number, FieldId};
use crate::editor::panel::{Widget, WidgetKind};
use crate::editor::Editor;
use crate::scene::{Material, MaterialId, Scene};
use crate::ui::Rect;

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
        self.material_ctx().map(|c| c.rows())
    }

    /// What the material rows see (`material/rows_ui.rs`), when the panel
    /// is open and the selection has a shape.
    pub(in crate::internals::editor) fn material_ctx(&self) -> Option<MatCtx<'_>> {
        let sh = self.material_panel()?;
        let value = self.shown_material(sh.material)?;
        let stored = self.scene.materials.get(sh.material.0 as usize);
        let image = value
            .texture
            .as_ref()
            .and_then(|t| self.scene.image(t.image));
        Some(MatCtx {
            shown: sh,
            name: self.material_name(sh.material),
            texture_name: stored.and_then(|m| super::texture_name(&self.scene, m)),
            glow_name: stored
                .and_then(|m| m.emissive_texture.as_ref())
                .and_then(|t| super::image_name(&self.scene, t)),
            value,
            stored,
            image,
        })
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
    pub(in crate::internals::editor) fn show_material(
        &mut self,
        id: MaterialId,
        props: Vec<Property>,
        m: Material,
    ) {
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

    /// Esc during a drag: drops the shown change.
    pub(in crate::internals::editor) fn cancel_material_drag(&mut self) {
        self.material.pending = None;
        self.scene_rev += 1;
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
        if shown(&self.scene, sel).is_some() {
            super::rows_ui::switch(header, out);
        }
    }

    /// The panel's widgets in the properties rect `r` (the component lays
    /// them out).
    pub(in crate::internals::editor) fn material_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        if let Some(ctx) = self.material_ctx() {
            self.side.material.widgets(r, &ctx, out);
        }
    }
}
