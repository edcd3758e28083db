//! The editor as a pure state machine: [`Editor::handle`] takes an input
//! [`Event`] and says whether the picture changed; [`Editor::draw`] paints
//! the current state (scene + overlay) into a [`Frame`]. No window code
//! here: `app/` feeds it from minifb and `script.rs` from a text file, so
//! tests and `animed edit --script` drive exactly what users see.
//!
//! Every change to the scene goes through [`command::History`] so it can be
//! undone; a drag previews live and records one command at release.
//!
//! The animating tools: `record.rs` (record mode, K, pending changes),
//! `viewport_ui.rs` (the viewport: orbit, pan, pick, its handles from
//! `manip/`, one file per kind), `keystrip.rs` + `keyedit.rs` +
//! `keystrip_draw.rs` (the key strip under the ruler), `keyprops.rs` (the
//! key panel), `motion_path.rs`, `onion.rs`, `recovery.rs` (autosave). A
//! new drag previews with `preview` and records one command at release
//! with `push_applied`/`execute`; both stop playback.

pub mod bench;
pub mod browser;
pub mod browser_ui;
pub mod command;
pub mod component;
pub mod create;
pub mod dialog;
pub mod disk;
mod draw;
pub mod field_press;
pub mod fields;
mod gesture;
pub mod gizmo;
pub mod graph;
mod graph_menu;
pub mod help;
pub mod keyedit;
pub mod keymenu;
pub mod keypanel;
pub mod keyprops;
pub mod keystrip;
mod keystrip_draw;
pub mod keystrip_ui;
pub mod live_field;
pub mod manip;
pub mod material;
pub mod menu;
pub mod motion_path;
pub mod node_props;
mod onion;
pub mod ops;
pub mod panel;
pub mod props_view;
pub mod record;
pub mod recovery;
pub mod request;
pub mod rig;
mod route;
pub mod scene_section;
mod screen;
pub mod script;
pub mod search;
mod sel_outline;
pub mod shell;
pub mod side_faces;
pub mod side_ui;
mod split;
mod strip_tips;
pub mod timeline;
pub mod tooltip;
mod viewport;
pub mod viewport_ui;
pub mod views;
mod widget_paint;

pub use crate::input::{Event, Key, Mods, MouseButton};
pub use dialog::Dialog;
pub use request::After;

use crate::anim::Pose;
use crate::format::export::atomic::Stamp;
use crate::input::OrbitCamera;
use crate::render::Frame;
use crate::scene::{NodeId, RenderStyle, Scene};
use crate::ui::{Layout, Painter};
use browser::{Browser, Purpose};
use command::{Command, History};
use fields::FieldId;
use std::path::{Path, PathBuf};

/// Left mouse in the viewport: select things (default) or turn the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Select,
    View,
}

/// The line of feedback at the bottom.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Status {
    pub text: String,
    pub error: bool,
}

/// A field being typed into.
#[derive(Clone, Debug, PartialEq)]
pub struct TextEdit {
    pub field: FieldId,
    pub text: String,
    /// The first typed character replaces the whole text (it starts out
    /// selected, as in Blender).
    pub fresh: bool,
}

/// Playback clock: frame = start_frame + (now - start_time) · fps.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Playback {
    start_time: Option<f64>,
    start_frame: f32,
}

/// The rendered scene (plus grid) for the viewport, kept until something
/// that affects it changes.
struct SceneLayer {
    key: Option<LayerKey>,
    frame: Frame,
    /// The picture with the selection outlined (`sel_outline.rs`), made
    /// again when the layer or the selection changes.
    outlined: Option<sel_outline::Outlined>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct LayerKey {
    rev: u64,
    frame: f32,
    camera: OrbitCamera,
    w: u32,
    h: u32,
    grid: bool,
    style: Option<RenderStyle>,
    aa: u32,
}

/// The whole editor state.
pub struct Editor {
    scene: Scene,
    path: Option<PathBuf>,
    /// `path` as read or last saved: a save onto it first checks that
    /// nobody changed it meanwhile (format::export::atomic).
    disk_stamp: Option<Stamp>,
    history: History,
    saved_revision: u64,
    /// Bumped on every change to `scene` (commands and live previews).
    scene_rev: u64,
    camera: OrbitCamera,
    /// The view before looking through the scene camera (numpad 0).
    through: Option<OrbitCamera>,
    /// Where views are remembered per file (`views.rs`), if anywhere.
    view_memory: Option<PathBuf>,
    selection: Option<NodeId>,
    mode: Mode,
    frame: f32,
    playback: Option<Playback>,
    record: bool,
    /// A change on an animated property not yet keyed (record off).
    pending: Option<record::Pending>,
    /// The viewport component: its one gesture (orbit, pan, pick, menu,
    /// IK target) and its handles (tool, hover, drag).
    viewport: viewport_ui::Viewport,
    /// Key strip: selected keys, fold state, clipboard, strip drags.
    keys: keystrip::KeyStrip,
    /// Onion skin switch and its cached copies.
    onion: onion::Onion,
    /// The graph editor (taken out while it handles an event; created
    /// when first shown).
    graph: Option<Box<graph::GraphEditor>>,
    /// The strip's zoom/pan and the preview range.
    timeline: timeline::Timeline,
    show_grid: bool,
    view_style: Option<RenderStyle>,
    /// Anti-aliasing samples per pixel of the viewport (1, 4, 8); the
    /// window uses 4, headless sessions 1 (see `set_aa`).
    aa: u32,
    /// The window's size and split (graph or key strip, dragged heights).
    split: split::Split,
    mouse: (f32, f32),
    drag: gesture::Drag,
    edit: Option<TextEdit>,
    browser: Option<Browser>,
    /// What a save-as browser should continue with.
    browser_then: Option<After>,
    dialog: Option<Dialog>,
    /// An open pop-up menu (Add, context, View): modal while open.
    menu: Option<menu::Menu>,
    /// The tooltip timer.
    hover: tooltip::Hover,
    /// The F3 command search, when open.
    search: Option<search::Search>,
    status: Status,
    quit: bool,
    /// The F1 key reference is shown.
    help: bool,
    /// How far the side panel's lists and properties are scrolled.
    side: side_ui::Side,
    /// Where the file browser starts when no file is open and what `~/`
    /// stands for: the shell says (`set_start_dir`, `set_home`).
    places: browser::Places,
    pose: Option<(u64, f32, Pose)>,
    /// Bounding sphere of the shown scene, cached like `pose` (handles ask
    /// for it on every mouse move; it walks every vertex).
    sphere: Option<(u64, f32, (glam::Vec3, f32))>,
    /// Recovery copies of unsaved work.
    autosave: recovery::Autosave,
    layer: SceneLayer,
    painter: Painter,
    /// Skeleton, IK, morph and clip tools' state (`rig/`).
    rig: rig::state::RigState,
    /// The material panel's state (`material/`).
    material: material::MatState,
    /// File work asked for and not yet performed (`request.rs`; the shell
    /// takes it with `take_requests`).
    requests: Vec<request::Request>,
}

impl Editor {
    /// An editor on `scene` (loaded from `path`, if any) for a `width`×`height` window.
    pub fn new(scene: Scene, path: Option<PathBuf>, width: u32, height: u32) -> Editor {
        let mut e = Editor {
            scene,
            path,
            disk_stamp: None,
            history: History::default(),
            saved_revision: 0,
            scene_rev: 1,
            camera: OrbitCamera::default(),
            through: None,
            view_memory: None,
            selection: None,
            mode: Mode::Select,
            frame: 0.0,
            playback: None,
            record: false,
            pending: None,
            viewport: viewport_ui::Viewport::default(),
            keys: keystrip::KeyStrip::default(),
            onion: onion::Onion::default(),
            graph: None,
            timeline: timeline::Timeline::default(),
            show_grid: true,
            view_style: None,
            aa: 1,
            split: split::Split::new(width, height),
            mouse: (-1.0, -1.0),
            drag: gesture::Drag::None,
            edit: None,
            browser: None,
            browser_then: None,
            dialog: None,
            menu: None,
            hover: tooltip::Hover::default(),
            search: None,
            status: Status::default(),
            quit: false,
            help: false,
            side: side_ui::Side::default(),
            // The shell passes the working directory and $HOME.
            places: browser::Places::default(),
            pose: None,
            sphere: None,
            autosave: recovery::Autosave::default(),
            layer: SceneLayer {
                key: None,
                frame: Frame::new(1, 1, glam::Vec3::ZERO),
                outlined: None,
            },
            painter: Painter::new(),
            rig: rig::state::RigState::default(),
            material: material::MatState::default(),
            requests: Vec::new(),
        };
        e.frame_all();
        e
    }

    /// The editor on the bundled demo scene; if it cannot be loaded, an
    /// empty scene and the reason in the status line.
    pub fn with_demo(width: u32, height: u32) -> Editor {
        match crate::format::demo() {
            Ok(l) => {
                let mut e = Editor::new(l.scene, None, width, height);
                e.set_status("Demo scene: Ctrl+O opens a file, Ctrl+S saves", false);
                e
            }
            Err(err) => {
                let mut e = Editor::new(Scene::new(), None, width, height);
                e.set_status(&format!("demo scene unavailable: {err}"), true);
                e
            }
        }
    }

    // ----- read access (tests, the app, issue 7's tools) -----

    pub fn scene(&self) -> &Scene {
        &self.scene
    }
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }
    pub fn selection(&self) -> Option<NodeId> {
        self.selection
    }
    pub fn mode(&self) -> Mode {
        self.mode
    }
    pub fn current_frame(&self) -> f32 {
        self.frame
    }
    pub fn is_playing(&self) -> bool {
        self.playback.is_some()
    }
    pub fn is_recording(&self) -> bool {
        self.record
    }
    pub fn grid_shown(&self) -> bool {
        self.show_grid
    }
    pub fn view_style(&self) -> Option<RenderStyle> {
        self.view_style
    }
    pub fn camera(&self) -> &OrbitCamera {
        &self.camera
    }
    pub fn size(&self) -> (u32, u32) {
        (self.split.width, self.split.height)
    }
    pub fn status(&self) -> &Status {
        &self.status
    }
    pub fn browser(&self) -> Option<&Browser> {
        self.browser.as_ref()
    }
    pub fn dialog(&self) -> Option<&Dialog> {
        self.dialog.as_ref()
    }
    pub fn text_edit(&self) -> Option<&TextEdit> {
        self.edit.as_ref()
    }
    pub fn history(&self) -> &History {
        &self.history
    }
    /// Unsaved changes?
    pub fn is_dirty(&self) -> bool {
        self.history.revision() != self.saved_revision
    }
    /// The user asked to quit and nothing is left unsaved (or they chose to
    /// discard it).
    pub fn wants_quit(&self) -> bool {
        self.quit
    }
    /// Whether the app should keep sending `Tick`s (playback runs).
    pub fn wants_ticks(&self) -> bool {
        self.playback.is_some() || self.hover.pending()
    }

    /// The tooltip shown under the mouse, if any.
    pub fn tooltip(&self) -> Option<String> {
        self.hover.text()
    }
    /// "animed — name.wrl *" (the mark when there are unsaved changes).
    pub fn window_title(&self) -> String {
        let name = self
            .path
            .as_ref()
            .and_then(|p| p.file_name())
            .map(|s| s.to_string_lossy().to_string())
            .unwrap_or_else(|| "untitled".into());
        format!("animed — {name}{}", if self.is_dirty() { " *" } else { "" })
    }

    /// Layout of the current window.
    pub fn layout(&self) -> Layout {
        self.split.layout()
    }

    /// Where the file browser starts when no file is open (`animed edit`
    /// passes the working directory; `.` until then: the editor asks the
    /// process for nothing).
    pub fn set_start_dir(&mut self, dir: &Path) {
        self.places.start = dir.to_path_buf();
    }

    /// What a typed `~/` in the file browser stands for (`animed edit`
    /// passes `$HOME`; until then `~/` is an ordinary name).
    pub fn set_home(&mut self, home: Option<&Path>) {
        self.places.home = home.map(Path::to_path_buf);
    }

    pub fn select(&mut self, id: Option<NodeId>) {
        self.selection = id.filter(|i| (i.0 as usize) < self.scene.nodes.len());
    }

    // ----- state changes -----

    fn set_status(&mut self, text: &str, error: bool) {
        self.status = Status {
            text: text.to_string(),
            error,
        };
    }

    /// The pose at the current frame (cached per scene revision and frame).
    pub fn pose(&mut self) -> &Pose {
        let fresh =
            matches!(&self.pose, Some((r, f, _)) if *r == self.scene_rev && *f == self.frame);
        if !fresh {
            let t = self.frame / self.scene.settings.fps.max(1e-6);
            self.pose = Some((self.scene_rev, self.frame, self.evaluate_shown(t)));
        }
        // Just filled above.
        &self.pose.as_ref().expect("pose cached").2
    }

    /// What the keys components (key strip, graph editor) see alike.
    pub fn keyed(&self) -> component::Keyed<'_> {
        component::Keyed {
            anim: &self.scene.animation,
            node: self.selection,
            node_name: self
                .selection
                .map(|s| ops::display_name(&self.scene, s))
                .unwrap_or_default(),
            morph_targets: self
                .selection
                .map(|s| rig::targets::targets_of(&self.scene, s))
                .unwrap_or(&[]),
            frame: self.frame,
            duration: self.scene.settings.duration,
        }
    }

    /// Applies and records a command.
    pub fn execute(&mut self, label: &str, c: Command) {
        self.history.execute(&mut self.scene, label, c);
        self.touched();
    }

    /// Records a command already applied by live previews.
    fn push_applied(&mut self, label: &str, c: Command) {
        self.history.push_applied(label, c);
        self.touched();
    }

    /// Applies a command as a preview (not recorded).
    fn preview(&mut self, c: &Command) {
        c.apply(&mut self.scene);
        self.scene_rev += 1;
        // Any edit stops playback (issue 7): every edit path passes here
        // or through `touched`.
        self.playback = None;
    }

    /// After any change: new revision, selection still valid, playback
    /// stopped.
    fn touched(&mut self) {
        self.scene_rev += 1;
        self.playback = None;
        self.select(self.selection);
        let n = self.scene.nodes.len();
        if self.selection.is_some_and(|s| s.0 as usize >= n) {
            self.selection = None;
        }
        self.key_selection_after_change();
    }

    pub fn undo(&mut self) {
        match self.history.undo(&mut self.scene) {
            Some(l) => self.set_status(&format!("Undo: {l}"), false),
            None => self.set_status("Nothing to undo", false),
        }
        self.touched();
    }

    pub fn redo(&mut self) {
        match self.history.redo(&mut self.scene) {
            Some(l) => self.set_status(&format!("Redo: {l}"), false),
            None => self.set_status("Nothing to redo", false),
        }
        self.touched();
    }

    /// Replaces the scene (new/open): history restarts, camera frames it.
    fn replace_scene(&mut self, scene: Scene, path: Option<PathBuf>) {
        // The file being left keeps its view; the next starts unzoomed.
        self.remember_view();
        self.timeline = timeline::Timeline::default();
        self.through = None;
        self.scene = scene;
        self.path = path;
        self.history = History::default();
        self.saved_revision = self.history.revision();
        self.selection = None;
        self.keys = keystrip::KeyStrip::default();
        self.frame = 0.0;
        self.playback = None;
        self.edit = None;
        self.side = side_ui::Side::default();
        self.scene_rev += 1;
        self.reset_recovery();
        self.frame_all();
    }

    pub fn new_scene(&mut self) {
        self.replace_scene(Scene::new(), None);
        self.set_status("New scene", false);
    }

    /// The file work asked for since the last call, oldest first (the
    /// shell performs it and answers through the `*_done` methods).
    pub fn take_requests(&mut self) -> Vec<request::Request> {
        if let Some(b) = &mut self.browser {
            // What the browser waits to have read.
            if let Some(ask) = b.asks.take() {
                let purpose = b.purpose;
                self.requests.push(request::Request::Look { ask, purpose });
            }
        }
        std::mem::take(&mut self.requests)
    }

    /// The file work asked for and not yet taken.
    pub fn requests(&self) -> &[request::Request] {
        &self.requests
    }

    /// What the open scene's file looked like when it was read (set by
    /// whoever read it: the shell, or `animed edit FILE`), so a save onto
    /// it first checks nobody changed it meanwhile.
    pub fn set_disk_stamp(&mut self, stamp: Option<Stamp>) {
        self.disk_stamp = stamp;
    }

    /// Looks at everything drawn (lights too when there is nothing else);
    /// Text2 labels count as `animed render` counts them for a picture of
    /// the viewport's size.
    pub fn frame_all(&mut self) {
        let vp = self.layout().viewport;
        let (w, h) = (vp.w.max(1) as u32, vp.h.max(1) as u32);
        let b = {
            let pose = self.pose().clone();
            crate::render::scene_bounds_for_picture(&self.scene, &pose, w, h)
                .or_else(|| ops::scene_bounds(&self.scene, &pose))
        };
        let (c, r) = ops::sphere(b);
        self.camera.frame_sphere(c, r);
    }

    /// Looks at the selection (nothing happens without one).
    pub fn frame_selection(&mut self) {
        let Some(sel) = self.selection else {
            self.set_status("Nothing selected to frame (Home frames all)", false);
            return;
        };
        let nodes = ops::subtree(&self.scene, sel);
        let pose = self.pose().clone();
        if let Some(b) = ops::bounds_of(&self.scene, &pose, &nodes) {
            let (c, r) = ops::sphere(Some(b));
            self.camera.frame_sphere(c, r);
        }
    }

    fn browse(&mut self, purpose: Purpose, then: Option<After>) {
        let dir = self
            .path
            .as_ref()
            .and_then(|p| p.parent())
            .filter(|p| !p.as_os_str().is_empty())
            .map(Path::to_path_buf)
            .unwrap_or_else(|| self.places.start.clone());
        let home = self.places.home.as_deref();
        self.browser = Some(Browser::new(purpose, &dir, home));
        self.browser_then = then;
        self.edit = None;
    }
}
