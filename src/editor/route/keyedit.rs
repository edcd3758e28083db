//! The editor's side of `keyedit`: routes events to it and applies what it returns.

use crate::anim::{Animation, Key, Target, TargetRef};
use crate::editor::command::Command;
#[allow(unused_imports)]
use crate::editor::keyedit::*;
use crate::editor::keystrip::{row_name, KeyRef};
use crate::editor::record::{read_property, write_property};
use crate::editor::Editor;

impl Editor {
    /// Replaces the animation with `after` as one undo step.
    pub(in crate::internals::editor) fn apply_key_edit(
        &mut self,
        label: &str,
        after: Animation,
        extra: Vec<Command>,
    ) {
        self.stop_playback();
        self.pending = None;
        let c = Command::SetAnimation {
            before: Box::new(self.scene.animation.clone()),
            after: Box::new(after),
        };
        let c = if extra.is_empty() {
            c
        } else {
            let mut v = vec![c];
            v.extend(extra);
            Command::Group(v)
        };
        self.execute(label, c);
        self.set_status(label, false);
    }

    pub(in crate::internals::editor) fn delete_selected_keys(&mut self) {
        let keys = self.selected_keys();
        let Some(sel) = self.selection else { return };
        match delete(&self.scene.animation, &keys) {
            Ok((after, emptied)) => {
                // A property that loses its last key keeps the value shown
                // now (as Blender does when an F-curve goes away).
                let mut extra = Vec::new();
                if !emptied.is_empty() {
                    let shown = self.posed_node(sel);
                    let before = Box::new(self.scene.node(sel).clone());
                    let mut node = before.clone();
                    for t in &emptied {
                        if let Some(v) = read_property(&shown, t.property) {
                            write_property(&mut node, t.property, v);
                        }
                    }
                    extra.push(Command::SetNode {
                        id: sel,
                        before,
                        after: node,
                    });
                }
                let n = keys.len();
                self.set_key_selection(Vec::new());
                let label = format!("Delete {n} key{}", if n == 1 { "" } else { "s" });
                self.apply_key_edit(&label, after, extra);
            }
            Err(e) => self.set_status(&e, true),
        }
    }

    pub(in crate::internals::editor) fn paste_keys(&mut self) {
        let Some(sel) = self.selection else {
            self.set_status("Select something to paste keys onto", false);
            return;
        };
        let node = self.scene.node(sel).clone();
        let mut anim = self.scene.animation.clone();
        let mut pasted = Vec::new();
        let mut skipped = 0;
        for (p, k) in &self.keys.clipboard.keys {
            if read_property(&node, *p).is_none() {
                skipped += 1;
                continue;
            }
            let target = Target {
                of: TargetRef::Node(sel),
                property: *p,
            };
            let frame = self.frame + k.frame;
            let key = Key { frame, ..*k };
            let r = anim
                .track_or_insert(target, frame, k.value)
                .and_then(|t| t.insert_key(key));
            match r {
                Ok(_) => pasted.push(KeyRef {
                    node: sel,
                    property: *p,
                    frame,
                }),
                Err(e) => {
                    self.set_status(&format!("cannot paste {}: {e}", row_name(*p)), true);
                    return;
                }
            }
        }
        if pasted.is_empty() {
            self.set_status("The copied keys do not fit the selection", true);
            return;
        }
        let n = pasted.len();
        let label = format!("Paste {n} key{}", if n == 1 { "" } else { "s" });
        self.apply_key_edit(&label, anim, Vec::new());
        self.set_key_selection(pasted);
        if skipped > 0 {
            self.set_status(&format!("{label} ({skipped} did not fit)"), false);
        }
    }
}
