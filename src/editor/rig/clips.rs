//! The editor's clip list (issue 13 item 3, 14 item 5, 17 item 8): switch,
//! add, duplicate, rename and delete a scene's named animation clips,
//! each an undoable step.
//!
//! Where: with named clips the Scene header shows `< name >` (the name is a
//! field: click to rename) and `Clips`, a menu of every clip and the
//! actions; `C` opens the same menu at the mouse — also in a scene with
//! only its unnamed animation, where "New clip" names that one `Clip1`
//! and adds an empty `Clip2`. Switching is an undo step too, so undo
//! walks back exactly what the user saw.
//!
//! The edits are plain functions on a copy of the scene (`scene::clips`
//! holds the model: the playing clip's tracks live in `Scene::animation`);
//! the editor records the scene before and after.

use crate::editor::command::Command;
use crate::editor::fields::{sanitize_name, FieldId};
use crate::editor::menu::{Menu, MenuItem};
use crate::editor::panel::{Action, Widget};
use crate::editor::Editor;
use crate::scene::{Clip, Scene};
use crate::ui::Rect;

pub use super::clip_action::ClipAction;
use super::clip_ui::{ClipCtx, ClipField};

/// Most clips listed by name in the menu (the `<` `>` buttons reach all).
const MENU_CLIPS: usize = 24;

/// `base`, or `base2`, `base3`… whichever no clip has.
fn unique(names: &[String], base: &str) -> String {
    if !names.iter().any(|n| n == base) {
        return base.to_string();
    }
    (2..)
        .map(|i| format!("{base}{i}"))
        .find(|c| !names.iter().any(|n| n == c))
        .unwrap_or_else(|| base.to_string())
}

/// The scene's clips, the unnamed one named `Clip1` when there are none.
fn named_clips(scene: &Scene) -> Vec<Clip> {
    let mut clips = scene.clips_owned();
    if scene.clips.is_empty() {
        clips[0].name = "Clip1".into();
    }
    clips
}

/// Adds an empty clip of the playing clip's length and plays it; returns
/// its name.
pub fn add(scene: &mut Scene) -> String {
    let mut clips = named_clips(scene);
    let names: Vec<String> = clips.iter().map(|c| c.name.clone()).collect();
    let name = unique(&names, &format!("Clip{}", clips.len() + 1));
    clips.push(Clip {
        name: name.clone(),
        animation: Default::default(),
        duration: scene.settings.duration,
    });
    let i = clips.len() - 1;
    scene.set_clips(clips, i);
    name
}

/// Copies the playing clip (tracks and length) right after it and plays
/// the copy; returns its name.
pub fn duplicate(scene: &mut Scene) -> String {
    let mut clips = named_clips(scene);
    let at = scene.clips.active();
    let names: Vec<String> = clips.iter().map(|c| c.name.clone()).collect();
    let mut copy = clips[at].clone();
    copy.name = unique(&names, &format!("{}_copy", copy.name));
    let name = copy.name.clone();
    clips.insert(at + 1, copy);
    scene.set_clips(clips, at + 1);
    name
}

/// Deletes the playing clip and plays the one before it (the first when it
/// was the first). The last clip cannot go.
pub fn delete(scene: &mut Scene) -> Result<String, String> {
    if scene.clips.len() < 2 {
        return Err("The only clip cannot be deleted (clear its keys instead)".into());
    }
    let mut clips = scene.clips_owned();
    let at = scene.clips.active();
    let gone = clips.remove(at);
    scene.set_clips(clips, at.saturating_sub(1));
    Ok(gone.name)
}

/// Renames the playing clip. Names are made safe for the writers; an empty
/// name or one another clip has is refused.
pub fn rename(scene: &mut Scene, typed: &str) -> Result<String, String> {
    let name = sanitize_name(typed);
    if name.is_empty() {
        return Err("A clip needs a name".into());
    }
    let at = scene.clips.active();
    let mut clips = named_clips(scene);
    if clips
        .iter()
        .enumerate()
        .any(|(i, c)| i != at && c.name == name)
    {
        return Err(format!("There is already a clip named {name}"));
    }
    clips[at].name = name.clone();
    scene.set_clips(clips, at);
    Ok(name)
}

impl Editor {
    /// The playing clip's name ("" without named clips).
    pub fn clip_name(&self) -> String {
        self.scene.clips.active_name().unwrap_or("").to_string()
    }

    /// What the clip name field sees (`rig/clip_ui.rs`).
    pub(in crate::internals::editor) fn clip_ctx(&self) -> ClipCtx {
        ClipCtx {
            name: self.clip_name(),
            named: !self.scene.clips.is_empty(),
        }
    }

    /// `< name > Clips` at the right of the Scene header, when the scene
    /// has named clips (the component lays them out).
    pub(in crate::internals::editor) fn clip_widgets(&self, h: Rect, out: &mut Vec<Widget>) {
        ClipField::widgets(h, &self.clip_ctx(), out);
    }

    /// The clip menu at (x, y): every clip (the playing one marked) and
    /// the actions.
    pub fn open_clip_menu(&mut self, x: i32, y: i32) {
        let refs = self.scene.clip_refs();
        let mut items: Vec<MenuItem> = Vec::new();
        if !self.scene.clips.is_empty() {
            for r in refs.iter().take(MENU_CLIPS) {
                let mark = if r.playing { "> " } else { "  " };
                let frames = crate::editor::fields::format_number(r.duration);
                items.push(MenuItem::new(
                    &format!("{mark}{}", r.name),
                    &format!("{frames} fr"),
                    Action::Clip(ClipAction::Play(r.index)),
                ));
            }
        }
        items.push(MenuItem::new("New clip", "", Action::Clip(ClipAction::New)));
        items.push(MenuItem::new(
            "Duplicate clip",
            "",
            Action::Clip(ClipAction::Duplicate),
        ));
        if !self.scene.clips.is_empty() {
            items.push(MenuItem::new(
                "Rename clip",
                "",
                Action::Clip(ClipAction::Rename),
            ));
        }
        if self.scene.clips.len() > 1 {
            items.push(MenuItem::new(
                "Delete clip",
                "",
                Action::Clip(ClipAction::Delete),
            ));
        }
        self.menu = Some(Menu::new("Clips (C)", items, (x, y)));
    }

    /// Runs a clip button or menu item.
    pub(in crate::internals::editor) fn clip_action(&mut self, a: ClipAction) {
        match a {
            ClipAction::Menu => {
                let at = self
                    .under_button(Action::Clip(ClipAction::Menu))
                    .unwrap_or((self.mouse.0 as i32, self.mouse.1 as i32));
                self.open_clip_menu(at.0, at.1);
            }
            ClipAction::Rename => {
                self.edit = Some(crate::editor::TextEdit {
                    field: FieldId::ClipName,
                    text: self.clip_name(),
                    fresh: true,
                });
            }
            ClipAction::Play(i) => self.clip_edit(|s| {
                s.play_clip_index(i)?;
                Ok(format!("Play clip {}", s.clips.active_name().unwrap_or("")))
            }),
            ClipAction::Step(d) => {
                let n = self.scene.clips.len();
                if n < 2 {
                    self.set_status("The scene has one clip (C: clip menu)", false);
                    return;
                }
                let i = (self.scene.clips.active() as i64 + d as i64).rem_euclid(n as i64);
                self.clip_action(ClipAction::Play(i as usize));
            }
            ClipAction::New => self.clip_edit(|s| Ok(format!("New clip {}", add(s)))),
            ClipAction::Duplicate => {
                self.clip_edit(|s| Ok(format!("Duplicate clip as {}", duplicate(s))))
            }
            ClipAction::Delete => self.clip_edit(|s| Ok(format!("Delete clip {}", delete(s)?))),
        }
    }

    /// Typing into the clip name field ended.
    pub(in crate::internals::editor) fn rename_clip(&mut self, typed: &str) {
        let typed = typed.to_string();
        self.clip_edit(move |s| Ok(format!("Rename clip to {}", rename(s, &typed)?)));
    }

    /// Applies `f` to a copy of the scene and records it as one step named
    /// by what `f` returns; an error goes to the status line unchanged.
    fn clip_edit(&mut self, f: impl FnOnce(&mut Scene) -> Result<String, String>) {
        let mut after = self.scene.clone();
        match f(&mut after) {
            Ok(label) => {
                if after.clips == self.scene.clips && after.animation == self.scene.animation {
                    return;
                }
                self.pending = None;
                self.rig.morph_pending = None;
                self.keys = crate::editor::keystrip::KeyStrip::default();
                let before = Box::new(self.scene.clone());
                self.execute(
                    &label,
                    Command::ReplaceScene {
                        before,
                        after: Box::new(after),
                    },
                );
                self.frame = self.frame.clamp(0.0, self.scene.settings.duration);
                let n = self.scene.clips.len().max(1);
                let i = self.scene.clips.active() + 1;
                self.set_status(&format!("{label} ({i}/{n})"), false);
            }
            Err(e) => self.set_status(&e, true),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Animation, Key, Keys, Property, Repeat, Target, TargetRef, Track};
    use crate::scene::Node;
    use glam::Vec3;

    fn keyed(s: &mut Scene, x: f32) {
        let n = s.find_node("Ball").unwrap();
        let target = Target {
            of: TargetRef::Node(n),
            property: Property::Translation,
        };
        let keys = Keys::Vec3(vec![Key::new(0.0, Vec3::ZERO), Key::new(10.0, Vec3::X * x)]);
        s.animation = Animation {
            tracks: vec![Track::new(target, Repeat::Constant, keys).unwrap()],
        };
    }

    fn names(s: &Scene) -> Vec<&str> {
        s.clips.names().collect()
    }

    #[test]
    fn new_names_the_unnamed_clip_and_plays_an_empty_one() {
        let mut s = Scene::new();
        s.add_node(None, Node::group("Ball"));
        keyed(&mut s, 2.0);
        s.settings.duration = 30.0;
        assert_eq!(add(&mut s), "Clip2");
        assert_eq!(names(&s), ["Clip1", "Clip2"]);
        assert_eq!(s.clips.active(), 1);
        assert!(s.animation.tracks.is_empty());
        assert_eq!(s.settings.duration, 30.0, "the new clip has the old length");
        s.play_clip_index(0).unwrap();
        assert_eq!(s.animation.tracks.len(), 1, "Clip1 kept its keys");
    }

    #[test]
    fn duplicate_rename_delete() {
        let mut s = Scene::new();
        s.add_node(None, Node::group("Ball"));
        keyed(&mut s, 2.0);
        assert_eq!(rename(&mut s, "Walk cycle").unwrap(), "Walk_cycle");
        assert_eq!(duplicate(&mut s), "Walk_cycle_copy");
        assert_eq!(s.clips.active(), 1);
        assert_eq!(s.animation.tracks.len(), 1, "the copy has the tracks");
        assert_eq!(duplicate(&mut s), "Walk_cycle_copy_copy");
        assert!(rename(&mut s, "Walk_cycle")
            .unwrap_err()
            .contains("already"));
        assert!(rename(&mut s, "  ").is_err());
        assert_eq!(delete(&mut s).unwrap(), "Walk_cycle_copy_copy");
        assert_eq!(names(&s), ["Walk_cycle", "Walk_cycle_copy"]);
        assert_eq!(s.clips.active(), 1, "the one before plays");
        delete(&mut s).unwrap();
        assert!(delete(&mut s).is_err(), "the last clip stays");
        assert_eq!(names(&s), ["Walk_cycle"]);
    }
}
