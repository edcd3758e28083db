//! Undoable changes to the scene. The editor never edits the `Scene`
//! directly for good: every change becomes a [`Command`] that knows how to
//! apply and revert itself, and [`History`] keeps them for undo/redo.
//!
//! Commands store *before* and *after* states rather than deltas, so a whole
//! drag (many intermediate previews) is one command built at release from the
//! state at press and the state at release.

use crate::anim::Animation;
use crate::scene::{Material, MaterialId, Node, NodeId, Scene, Settings};

/// One undoable change.
#[derive(Clone, Debug)]
pub enum Command {
    /// Replace one node's own fields (name, transform, style, light/camera).
    /// Its place in the tree (`parent`, `children`) is not touched.
    SetNode {
        id: NodeId,
        before: Box<Node>,
        after: Box<Node>,
    },
    SetSettings {
        before: Settings,
        after: Settings,
    },
    /// Replace all tracks (keys): record mode and the key strip build these.
    SetAnimation {
        before: Box<Animation>,
        after: Box<Animation>,
    },
    /// Structural change (add, delete, import): the whole scene before/after.
    ReplaceScene {
        before: Box<Scene>,
        after: Box<Scene>,
    },
    /// Replace one material (the material panel).
    SetMaterial {
        id: MaterialId,
        before: Box<Material>,
        after: Box<Material>,
    },
    /// Several commands as one step (applied in order, reverted in reverse).
    Group(Vec<Command>),
}

fn put_node(scene: &mut Scene, id: NodeId, n: &Node) {
    if let Some(slot) = scene.nodes.get_mut(id.0 as usize) {
        let parent = slot.parent;
        let children = std::mem::take(&mut slot.children);
        *slot = n.clone();
        slot.parent = parent;
        slot.children = children;
    }
}

fn put_material(scene: &mut Scene, id: MaterialId, m: &Material) {
    if let Some(slot) = scene.materials.get_mut(id.0 as usize) {
        *slot = m.clone();
    }
}

impl Command {
    pub fn apply(&self, scene: &mut Scene) {
        match self {
            Command::SetNode { id, after, .. } => put_node(scene, *id, after),
            Command::SetSettings { after, .. } => scene.settings = after.clone(),
            Command::SetAnimation { after, .. } => scene.animation = (**after).clone(),
            Command::ReplaceScene { after, .. } => *scene = (**after).clone(),
            Command::SetMaterial { id, after, .. } => put_material(scene, *id, after),
            Command::Group(cs) => cs.iter().for_each(|c| c.apply(scene)),
        }
    }

    pub fn revert(&self, scene: &mut Scene) {
        match self {
            Command::SetNode { id, before, .. } => put_node(scene, *id, before),
            Command::SetSettings { before, .. } => scene.settings = before.clone(),
            Command::SetAnimation { before, .. } => scene.animation = (**before).clone(),
            Command::ReplaceScene { before, .. } => *scene = (**before).clone(),
            Command::SetMaterial { id, before, .. } => put_material(scene, *id, before),
            Command::Group(cs) => cs.iter().rev().for_each(|c| c.revert(scene)),
        }
    }

    /// True when applying it would change nothing (e.g. a drag that ended
    /// where it started); such commands are not recorded.
    pub fn is_noop(&self) -> bool {
        match self {
            Command::SetNode { before, after, .. } => before == after,
            Command::SetSettings { before, after } => before == after,
            Command::SetAnimation { before, after } => before == after,
            Command::ReplaceScene { .. } => false,
            Command::SetMaterial { before, after, .. } => before == after,
            Command::Group(cs) => cs.iter().all(Command::is_noop),
        }
    }
}

/// A labelled command in the history.
#[derive(Clone, Debug)]
pub struct Step {
    pub label: String,
    pub command: Command,
}

/// Undo and redo stacks plus a revision counter that tells whether the
/// scene differs from what was last saved.
#[derive(Clone, Debug, Default)]
pub struct History {
    done: Vec<Step>,
    undone: Vec<Step>,
    /// Revision of the scene: changes with every do/undo/redo.
    revision: u64,
    /// Revision ids along the done stack, to compare with a saved revision.
    ids: Vec<u64>,
    next_id: u64,
}

/// Oldest steps are dropped beyond this many.
const LIMIT: usize = 500;

impl History {
    /// Applies `command` to `scene` and records it.
    pub fn execute(&mut self, scene: &mut Scene, label: &str, command: Command) {
        command.apply(scene);
        self.push_applied(label, command);
    }

    /// Records a command whose effect is already in the scene (a finished
    /// drag: the scene was previewed live). No-op commands are dropped.
    pub fn push_applied(&mut self, label: &str, command: Command) {
        if command.is_noop() {
            return;
        }
        self.done.push(Step {
            label: label.to_string(),
            command,
        });
        self.next_id += 1;
        self.ids.push(self.next_id);
        self.revision = self.next_id;
        self.undone.clear();
        if self.done.len() > LIMIT {
            self.done.remove(0);
            self.ids.remove(0);
        }
    }

    /// Reverts the last step; returns its label.
    pub fn undo(&mut self, scene: &mut Scene) -> Option<String> {
        let step = self.done.pop()?;
        self.ids.pop();
        step.command.revert(scene);
        let label = step.label.clone();
        self.undone.push(step);
        self.revision = self.ids.last().copied().unwrap_or(0);
        Some(label)
    }

    /// Re-applies the last undone step; returns its label.
    pub fn redo(&mut self, scene: &mut Scene) -> Option<String> {
        let step = self.undone.pop()?;
        step.command.apply(scene);
        let label = step.label.clone();
        self.done.push(step);
        self.next_id += 1;
        self.ids.push(self.next_id);
        self.revision = self.next_id;
        Some(label)
    }

    pub fn can_undo(&self) -> bool {
        !self.done.is_empty()
    }

    pub fn can_redo(&self) -> bool {
        !self.undone.is_empty()
    }

    /// Identifies the current state; equal revisions mean equal scenes
    /// (as far as the history knows).
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// Labels of the done steps, oldest first.
    pub fn labels(&self) -> impl Iterator<Item = &str> {
        self.done.iter().map(|s| s.label.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Node, Transform};
    use glam::Vec3;

    fn scene() -> (Scene, NodeId) {
        let mut s = Scene::new();
        let id = s.add_node(None, Node::group("a"));
        (s, id)
    }

    fn moved(s: &Scene, id: NodeId, x: f32) -> Command {
        let before = Box::new(s.node(id).clone());
        let mut after = before.clone();
        after.transform = Transform::from_translation(Vec3::new(x, 0.0, 0.0));
        Command::SetNode { id, before, after }
    }

    #[test]
    fn undo_redo_round_trip() {
        let (mut s, id) = scene();
        let mut h = History::default();
        let r0 = h.revision();
        let c = moved(&s, id, 2.0);
        h.execute(&mut s, "move", c);
        assert_eq!(s.node(id).transform.translation.x, 2.0);
        let r1 = h.revision();
        assert_ne!(r0, r1);
        assert_eq!(h.undo(&mut s).as_deref(), Some("move"));
        assert_eq!(s.node(id).transform.translation.x, 0.0);
        assert_eq!(h.revision(), r0);
        assert_eq!(h.redo(&mut s).as_deref(), Some("move"));
        assert_eq!(s.node(id).transform.translation.x, 2.0);
        assert!(h.undo(&mut s).is_some());
        assert!(h.undo(&mut s).is_none());
    }

    #[test]
    fn new_command_clears_redo_and_noops_are_dropped() {
        let (mut s, id) = scene();
        let mut h = History::default();
        let c = moved(&s, id, 1.0);
        h.execute(&mut s, "a", c);
        h.undo(&mut s);
        assert!(h.can_redo());
        let c = moved(&s, id, 3.0);
        h.execute(&mut s, "b", c);
        assert!(!h.can_redo());
        let same = moved(&s, id, 3.0);
        h.push_applied("noop", same);
        assert_eq!(h.labels().collect::<Vec<_>>(), vec!["b"]);
    }

    #[test]
    fn set_node_keeps_tree_links() {
        let (mut s, id) = scene();
        let child = s.add_node(Some(id), Node::group("c"));
        let before = Box::new(s.node(id).clone());
        let mut after = before.clone();
        after.name = "renamed".into();
        after.children.clear();
        Command::SetNode { id, before, after }.apply(&mut s);
        assert_eq!(s.node(id).name, "renamed");
        assert_eq!(s.node(id).children, vec![child]);
    }
}
