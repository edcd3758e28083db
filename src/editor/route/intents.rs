//! Applying what components return: every component's [`Response`]
//! passes here, so an intent means the same whichever part asked for it
//! (scene changes go through undoable commands).

use crate::anim::Property;
use crate::editor::command::Command;
use crate::editor::component::{Intent, Response};
use crate::editor::fields::FieldId;
use crate::editor::record::Pending;
use crate::editor::{Editor, TextEdit};
use crate::scene::{Node, NodeId};

impl Editor {
    /// Applies a component's intents; `Some(redraw)` when it took the event.
    pub(in crate::internals::editor) fn apply_response(&mut self, r: Response) -> Option<bool> {
        for i in r.intents {
            match i {
                // Keys edited (strip, graph, key panel): a change not yet
                // keyed is dropped, whichever part edits them.
                Intent::Preview(after) => {
                    self.pending = None;
                    let before = Box::new(self.scene.animation.clone());
                    self.preview(&Command::SetAnimation {
                        before,
                        after: Box::new(after),
                    });
                }
                Intent::Commit {
                    label,
                    before,
                    after,
                } => {
                    self.pending = None;
                    self.scene.animation = after.clone();
                    self.push_applied(
                        &label,
                        Command::SetAnimation {
                            before: Box::new(before),
                            after: Box::new(after),
                        },
                    );
                }
                Intent::SelectKeys(keys) => self.set_key_selection(keys),
                Intent::ShowKeys(keys) => self.keys.selected = keys,
                Intent::Seek(f) => {
                    self.stop_playback();
                    self.frame = f;
                }
                Intent::Status(s, error) => self.set_status(&s, error),
                Intent::ContextMenu(at) => self.open_graph_menu(at),
                Intent::StopPlayback => self.stop_playback(),
                Intent::ShowNode { id, property, node } => self.show_moved(id, property, *node),
                Intent::PutBack { id, node } => {
                    self.pending = None;
                    self.preview(&Command::SetNode {
                        id,
                        before: Box::new(self.scene.node(id).clone()),
                        after: node,
                    });
                }
                Intent::RecordNode {
                    label,
                    id,
                    before,
                    after,
                    property,
                } => {
                    let c = self.recorded(Command::SetNode { id, before, after }, &[property]);
                    self.execute(&label, c);
                }
                Intent::Type { field, text } => {
                    self.edit = Some(TextEdit {
                        field,
                        text,
                        fresh: true,
                    })
                }
                Intent::Select(node) => self.selection = Some(node),
                Intent::Reparent { node, parent } => self.reparent(node, parent),
                Intent::Camera(c) => self.camera = c,
                Intent::Pick((x, y)) => self.pick(x, y),
                Intent::ViewportMenu((x, y)) => self.open_context_menu(x as i32, y as i32),
                Intent::IkPose(joints) => self.show_ik(*joints),
                Intent::IkDone => self.ik_released(),
                // The side panel's faces (material rows, morph sliders,
                // clip name): applied by the record rules of their files.
                Intent::ShowMaterial { id, props, value } => self.show_material(id, props, *value),
                Intent::SetMaterial { field, base, value } => {
                    self.set_material(field, &base, value)
                }
                Intent::DropMaterial => self.cancel_material_drag(),
                Intent::ShowWeight { base, index, value } => {
                    self.drag_morph(FieldId::Morph(index), &base, value)
                }
                Intent::SetWeight { base, index, value } => {
                    self.set_morph(FieldId::Morph(index), &base, value)
                }
                Intent::DropWeights => {
                    self.rig.morph_pending = None;
                    self.scene_rev += 1;
                }
                Intent::RenameClip(name) => self.rename_clip(&name),
                // The node face and the scene section (`node_props.rs`,
                // `scene_section.rs`).
                Intent::PreviewNode { id, node } => self.preview(&Command::SetNode {
                    id,
                    before: Box::new(self.scene.node(id).clone()),
                    after: node,
                }),
                Intent::SetNode {
                    label,
                    id,
                    before,
                    after,
                    props,
                } => {
                    if let Some(b) = before {
                        self.scene.nodes[id.0 as usize] = *b;
                    }
                    let before = Box::new(self.scene.node(id).clone());
                    let c = self.recorded(Command::SetNode { id, before, after }, &props);
                    self.execute(&label, c);
                }
                Intent::PreviewSettings(after) => self.preview(&Command::SetSettings {
                    before: self.scene.settings.clone(),
                    after,
                }),
                Intent::SetSettings {
                    label,
                    before,
                    after,
                } => self.execute(&label, Command::SetSettings { before, after }),
                Intent::NoteKeysAfterEnd => self.note_keys_after_end(),
            }
        }
        r.consumed.then_some(r.redraw)
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
}
