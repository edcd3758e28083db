//! The editor's side of `create` and `menu`: opens the Add menu, routes
//! events to an open menu, adds, duplicates and re-parents objects (each
//! one undoable step).

use crate::editor::command::Command;
use crate::editor::create::{self, NewThing};
use crate::editor::menu::{Menu, MenuItem, Reply};
use crate::editor::ops;
use crate::editor::panel::Action;
use crate::editor::views::ViewCmd;
use crate::editor::Editor;
use crate::input::Event;
use crate::scene::{NodeId, Scene};

/// The Add menu's title (how `add_menu_open` knows it).
const ADD_TITLE: &str = "Add (Shift+A)";

impl Editor {
    /// The open pop-up menu, if any.
    pub fn menu(&self) -> Option<&Menu> {
        self.menu.as_ref()
    }

    /// Whether the open menu is the Add menu (the toolbar's `Add` is lit
    /// by it only, not by context menus or the search).
    pub fn add_menu_open(&self) -> bool {
        self.menu.as_ref().is_some_and(|m| m.title == ADD_TITLE)
    }

    /// Opens the Add menu with its top-left corner at (x, y).
    pub fn open_add_menu(&mut self, x: i32, y: i32) {
        let items = NewThing::ALL
            .iter()
            .map(|&t| MenuItem::new(t.label(), "", Action::Add(t)))
            .collect();
        self.menu = Some(Menu::new(ADD_TITLE, items, (x, y)));
    }

    /// Right-click in the viewport: add, duplicate, delete, key, frame,
    /// and the View menu.
    pub fn open_context_menu(&mut self, x: i32, y: i32) {
        let items = vec![
            MenuItem::new("Add...", "Shift+A", Action::AddMenuHere),
            MenuItem::new("Duplicate", "Shift+D", Action::Duplicate),
            MenuItem::new("Delete", "Delete", Action::Delete),
            MenuItem::new("Key the selection", "K", Action::KeySelection),
            MenuItem::new("Clear keys", "Alt+I", Action::ClearKeys),
            MenuItem::new("Frame selected", "F", Action::View(ViewCmd::FrameSelected)),
            MenuItem::new("Frame all", "Home", Action::View(ViewCmd::FrameAll)),
            MenuItem::new("View...", "Num 1 3 7 5 0", Action::ViewMenu),
        ];
        self.menu = Some(Menu::new("Viewport", items, (x, y)));
    }

    /// "Clear keys" (Alt+I): every key of the selected object or light
    /// goes, as one undo step, and the status line says how many.
    pub(in crate::internals::editor) fn clear_selection_keys(&mut self) {
        let Some(sel) = self.selection else {
            self.set_status(
                "Nothing selected: select an object to clear its keys",
                false,
            );
            return;
        };
        let name = ops::display_name(&self.scene, sel);
        let mine = |t: &crate::anim::Track| t.target.of == crate::anim::TargetRef::Node(sel);
        let n: usize = self
            .scene
            .animation
            .tracks
            .iter()
            .filter(|t| mine(t))
            .map(|t| t.key_count())
            .sum();
        if n == 0 {
            self.set_status(&format!("{name} has no keys to clear"), false);
            return;
        }
        let mut after = self.scene.animation.clone();
        after.tracks.retain(|t| !mine(t));
        self.stop_playback();
        self.execute(
            &format!("Clear keys of {name}"),
            Command::SetAnimation {
                before: Box::new(self.scene.animation.clone()),
                after: Box::new(after),
            },
        );
        let s = if n == 1 { "key" } else { "keys" };
        self.set_status(
            &format!("Cleared {n} {s} of {name} (Ctrl+Z brings them back)"),
            false,
        );
    }

    /// F3: the command search over the window.
    pub fn open_search(&mut self) {
        self.menu = None;
        self.search = Some(crate::editor::search::Search::new(self.layout().window));
    }

    /// The open command search, if any.
    pub fn search(&self) -> Option<&crate::editor::search::Search> {
        self.search.as_ref()
    }

    /// The command search takes every input event and text while open.
    pub(in crate::internals::editor) fn search_event(&mut self, ev: &Event) -> Option<bool> {
        if matches!(
            ev,
            Event::Tick { .. } | Event::Resize { .. } | Event::KeyUp { .. }
        ) {
            return None;
        }
        let window = self.layout().window;
        let s = self.search.as_mut()?;
        match s.handle(ev, window) {
            Reply::Stay(redraw) => Some(redraw),
            Reply::Close => {
                self.search = None;
                Some(true)
            }
            Reply::Pick(a) => {
                self.search = None;
                self.run_action(a);
                Some(true)
            }
        }
    }

    /// The objects and lights lists' context menu (on the selected row).
    pub fn open_list_menu(&mut self, x: i32, y: i32) {
        let items = vec![
            MenuItem::new("Rename", "", Action::Rename),
            MenuItem::new("Duplicate", "Shift+D", Action::Duplicate),
            MenuItem::new("Delete", "Delete", Action::Delete),
        ];
        self.menu = Some(Menu::new("Object", items, (x, y)));
    }

    /// An open menu takes every input event; `None` when no menu is open
    /// or the event is not input.
    pub(in crate::internals::editor) fn menu_event(&mut self, ev: &Event) -> Option<bool> {
        let input = matches!(
            ev,
            Event::MouseMove { .. }
                | Event::MouseDown { .. }
                | Event::MouseUp { .. }
                | Event::KeyDown { .. }
                | Event::Wheel { .. }
        );
        if !input {
            return None;
        }
        let window = self.layout().window;
        let m = self.menu.as_mut()?;
        match m.handle(ev, window) {
            Reply::Stay(redraw) => Some(redraw),
            Reply::Close => {
                self.menu = None;
                Some(true)
            }
            Reply::Pick(a) => {
                self.menu = None;
                self.run_action(a);
                Some(true)
            }
        }
    }

    /// Adds `what` at the orbit centre, sized to the scene, selected.
    pub fn add_thing(&mut self, what: NewThing) {
        if let NewThing::Light(which) = what {
            self.run_action(Action::AddLight(which));
            return;
        }
        let pose = self.pose().clone();
        let empty = crate::render::scene_bounds(&self.scene, &pose).is_none();
        let size = create::size_for(self.camera.distance, empty);
        let (at, eye) = (self.camera.target, self.camera.eye());
        let mut after = self.scene.clone();
        let id = create::add(&mut after, what, at, size, eye);
        let name = after.node(id).name.clone();
        self.replace_with(&format!("Add {name}"), after);
        self.selection = Some(id);
        self.set_status(&format!("Added {name} (Shift+D duplicates)"), false);
    }

    /// Shift+D: a copy of the selection with its tracks, selected.
    pub fn duplicate_selection(&mut self) {
        let Some(sel) = self.selection else {
            self.set_status("Nothing selected to duplicate", false);
            return;
        };
        let mut after = self.scene.clone();
        let id = create::duplicate(&mut after, sel);
        let name = after.node(id).name.clone();
        self.replace_with(&format!("Duplicate as {name}"), after);
        self.selection = Some(id);
        self.set_status(&format!("Duplicated as {name} (with its keys)"), false);
    }

    /// Puts `id` under `parent` (`None`: top level), one undoable step;
    /// the object stays where it is in the world (at the frame shown).
    pub fn reparent(&mut self, id: NodeId, parent: Option<NodeId>) {
        let mut after = self.scene.clone();
        let pose = self.pose().clone();
        let world = |p: Option<NodeId>| {
            p.and_then(|p| pose.world.get(p.0 as usize).copied())
                .unwrap_or(glam::Mat4::IDENTITY)
        };
        let (old, new) = (world(self.scene.node(id).parent), world(parent));
        if let Err(e) = create::reparent_keeping_world(&mut after, id, parent, old, new) {
            self.set_status(&e, true);
            return;
        }
        let name = ops::display_name(&self.scene, id);
        let msg = match parent {
            Some(p) => format!("{name} is now under {}", ops::display_name(&self.scene, p)),
            None => format!("{name} is now at the top level"),
        };
        self.replace_with(&msg, after);
        self.selection = Some(id);
        self.set_status(&msg, false);
    }

    /// Records the whole scene replaced by `after` as one step.
    fn replace_with(&mut self, label: &str, after: Scene) {
        let before = Box::new(self.scene.clone());
        self.execute(
            label,
            Command::ReplaceScene {
                before,
                after: Box::new(after),
            },
        );
    }
}
