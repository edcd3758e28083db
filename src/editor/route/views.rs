//! The editor's side of `views`: axis views, orthographic toggle, looking
//! through the scene camera and back, the View menu, and the per-file
//! view memory.

use crate::editor::menu::{Menu, MenuItem};
use crate::editor::panel::Action;
use crate::editor::request::Request;
use crate::editor::views::{Memo, ViewCmd};
use crate::editor::Editor;
use crate::input::OrbitCamera;
use crate::scene::NodeKind;
use std::path::PathBuf;

impl Editor {
    /// Runs a view command.
    pub fn view_command(&mut self, v: ViewCmd) {
        if let Some((yaw, pitch)) = v.angles() {
            self.camera.yaw = yaw;
            self.camera.pitch = pitch;
            self.through = None;
            let how = if self.camera.ortho {
                "orthographic"
            } else {
                "perspective; Num 5: orthographic"
            };
            self.set_status(&format!("{} view ({how})", v.label()), false);
            return;
        }
        match v {
            ViewCmd::Ortho => {
                self.camera.ortho = !self.camera.ortho;
                let s = if self.camera.ortho {
                    "Orthographic view"
                } else {
                    "Perspective view"
                };
                self.set_status(s, false);
            }
            ViewCmd::Camera => self.toggle_look_through(),
            ViewCmd::FrameSelected => self.frame_selection(),
            ViewCmd::FrameAll => self.frame_all(),
            _ => {}
        }
    }

    /// Numpad 0: look through the selected camera (else the scene's first) (its eye, direction
    /// and field of view; roll is dropped, the orbit camera has none);
    /// again: back to the view before.
    fn toggle_look_through(&mut self) {
        if let Some(back) = self.through.take() {
            self.camera = back;
            self.set_status("Back to the editor's view", false);
            return;
        }
        let is_cam =
            |id: crate::scene::NodeId| matches!(self.scene.node(id).kind, NodeKind::Camera(_));
        // The selected camera, else the scene's first.
        let cam = self.selection.filter(|&s| is_cam(s)).or_else(|| {
            (0..self.scene.nodes.len() as u32)
                .map(crate::scene::NodeId)
                .find(|&id| is_cam(id))
        });
        let Some(cam) = cam else {
            self.set_status("The scene has no camera (Shift+A adds one)", false);
            return;
        };
        let vp = self.layout().viewport;
        let aspect = vp.w.max(1) as f32 / vp.h.max(1) as f32;
        let pose = self.pose().clone();
        let view = crate::render::job::view_for(&self.scene, &pose, Some(cam), aspect);
        let sphere = crate::render::bounding_sphere(&self.scene, &pose);
        self.through = Some(self.camera);
        self.camera = OrbitCamera::from_view(&view, sphere);
        let name = crate::editor::ops::display_name(&self.scene, cam);
        self.set_status(&format!("Looking through {name} (Num 0: back)"), false);
    }

    /// The View menu (toolbar `View`).
    pub fn open_view_menu(&mut self, x: i32, y: i32) {
        let items = ViewCmd::ALL
            .iter()
            .map(|&v| MenuItem::new(v.label(), v.shortcut(), Action::View(v)))
            .collect();
        self.menu = Some(Menu::new("View", items, (x, y)));
    }

    /// Where views are remembered per file (the window's editor uses the
    /// state folder; headless sessions and tests none unless set).
    pub fn set_view_memory(&mut self, file: Option<PathBuf>) {
        self.view_memory = file;
        self.recall_view();
    }

    /// The scene file's absolute path (the memory's key).
    fn view_key(&self) -> Option<PathBuf> {
        let p = self.path.as_deref()?;
        std::path::absolute(p).ok()
    }

    /// Asks for the remembered view of the open file, if any (the shell
    /// reads the memory and answers with `view_recalled`).
    pub(in crate::internals::editor) fn recall_view(&mut self) {
        if let Some(key) = self.view_key() {
            self.recall_view_of(key);
        }
    }

    /// Asks for the view remembered under `key`.
    pub(in crate::internals::editor) fn recall_view_of(&mut self, key: PathBuf) {
        let Some(mem) = self.view_memory.clone() else {
            return;
        };
        self.requests.push(Request::RecallView { memory: mem, key });
    }

    /// Asks to remember the view for the open file (after saves, at quit).
    pub fn remember_view(&mut self) {
        if let Some(key) = self.view_key() {
            self.remember_view_as(key);
        }
    }

    /// Asks to remember the view under `key` (a file's absolute path;
    /// untitled work's recovery copy, so recovered work comes back as it
    /// was seen).
    pub(in crate::internals::editor) fn remember_view_as(&mut self, key: PathBuf) {
        let Some(mem) = self.view_memory.clone() else {
            return;
        };
        let memo = Memo {
            camera: self.through.unwrap_or(self.camera),
            zoom: self.timeline.zoomed_span(),
            preview: self.timeline.preview,
        };
        self.requests.push(Request::RememberView {
            memory: mem,
            key,
            memo,
        });
    }
}
