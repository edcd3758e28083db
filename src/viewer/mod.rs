//! `animed view`: plays a scene's animation. A pure state machine like the
//! editor — `handle(Event)` and `draw(&mut Frame)` — shown in a window by
//! `app::run` (the same window loop as the editor), and driven directly by
//! tests.
//!
//! It shares the input events, the orbit camera
//! (`input::OrbitCamera`) and the overlay painter (`ui`); what is
//! its own is the playback [`clock::Clock`] (real time, dropping frames,
//! looping), the viewpoint cycle and the scrub bar.

mod clips;
pub mod clock;
mod draw;
mod eye;
mod input;

pub use clock::Clock;
pub use eye::Eye;

use crate::input::camera::OrbitCamera;
use crate::render::job::{find_camera, Headlight};
use crate::render::Frame;
use crate::scene::{NodeId, Scene};
use crate::ui::Painter;
use std::time::Duration;

/// How `animed view` starts.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewerOptions {
    pub width: u32,
    pub height: u32,
    /// Start at this viewpoint (description or node name).
    pub viewpoint: Option<String>,
    pub headlight: Headlight,
    /// Show render time and frame rate.
    pub stats: bool,
    /// Name shown in the window title.
    pub title: String,
    /// Anti-aliasing samples per pixel (1, 4, 8); `animed view` uses 4.
    pub aa: u32,
}

impl Default for ViewerOptions {
    fn default() -> Self {
        ViewerOptions {
            width: 800,
            height: 600,
            viewpoint: None,
            headlight: Headlight::Auto,
            stats: false,
            title: String::new(),
            aa: 1,
        }
    }
}

/// What a mouse drag does.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Drag {
    None,
    Orbit {
        last: (f32, f32),
    },
    Pan {
        last: (f32, f32),
    },
    /// Dragging on the scrub bar; `resume` = play again on release.
    Scrub {
        resume: bool,
    },
}

/// The picture of the scene last rendered, and what it was rendered for.
#[derive(Clone, Debug, PartialEq)]
struct LayerKey {
    frame: u64,
    eye: Eye,
    w: u32,
    h: u32,
    headlight: bool,
}

/// Timing figures for `--stats`.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Wall time of the last scene render.
    pub last_render: Duration,
    /// New scene pictures shown in the last whole second (re-renders; at
    /// most the file's fps while playing), and the current second's count.
    pub shown_fps: u32,
    count: u32,
    second: Option<f64>,
}

/// The viewer's whole state.
pub struct Viewer {
    scene: Scene,
    width: u32,
    height: u32,
    clock: Clock,
    /// Camera nodes in traversal order (PageUp/PageDown cycle them).
    cameras: Vec<NodeId>,
    eye: Eye,
    headlight: bool,
    aa: u32,
    show_stats: bool,
    stats: Stats,
    drag: Drag,
    mouse: (f32, f32),
    /// Times (seconds) of every key of every track, sorted, no repeats.
    key_times: Vec<f32>,
    title: String,
    painter: Painter,
    layer: Option<(LayerKey, Frame)>,
    quit: bool,
    /// Wall time of the last tick (seconds).
    now: Option<f64>,
    /// The viewpoint last looked through (PageUp/PageDown and Home start here).
    vp_index: usize,
}

impl Viewer {
    /// A viewer on `scene`, playing from time 0. A `--viewpoint` that names
    /// nothing is an error listing the viewpoints there are.
    pub fn new(scene: Scene, opts: &ViewerOptions) -> Result<Viewer, String> {
        let cameras: Vec<NodeId> = scene
            .walk()
            .into_iter()
            .filter(|&id| scene.node(id).camera().is_some())
            .collect();
        let eye = match find_camera(&scene, opts.viewpoint.as_deref())? {
            Some(id) => Eye::Viewpoint(cameras.iter().position(|&c| c == id).unwrap_or(0)),
            None => Eye::ViewAll,
        };
        let fps = scene.settings.fps;
        let key_times = clips::key_times(&scene);
        Ok(Viewer {
            clock: Clock::new(fps, scene.settings.duration),
            headlight: opts.headlight.resolve(&scene),
            aa: opts.aa,
            width: opts.width.max(16),
            height: opts.height.max(16),
            cameras,
            show_stats: opts.stats,
            stats: Stats::default(),
            drag: Drag::None,
            mouse: (-1.0, -1.0),
            key_times,
            title: if opts.title.is_empty() {
                "animed view".to_string()
            } else {
                format!("animed view — {}", opts.title)
            },
            painter: Painter::new(),
            layer: None,
            quit: false,
            now: None,
            vp_index: match eye {
                Eye::Viewpoint(i) => i,
                _ => 0,
            },
            eye,
            scene,
        })
    }

    pub fn scene(&self) -> &Scene {
        &self.scene
    }
    pub fn clock(&self) -> &Clock {
        &self.clock
    }
    pub fn eye(&self) -> &Eye {
        &self.eye
    }
    pub fn headlight(&self) -> bool {
        self.headlight
    }
    pub fn key_times(&self) -> &[f32] {
        &self.key_times
    }
    pub fn stats(&self) -> &Stats {
        &self.stats
    }
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }
    pub fn wants_quit(&self) -> bool {
        self.quit
    }
    /// Playback needs ticks; so does `--stats` (its fps counter).
    pub fn wants_ticks(&self) -> bool {
        self.clock.is_playing()
    }

    /// Name of the current viewpoint ("" when the view is free).
    pub fn viewpoint_name(&self) -> String {
        match self.eye {
            Eye::Viewpoint(i) => {
                let Some(&id) = self.cameras.get(i) else {
                    return String::new();
                };
                let n = self.scene.node(id);
                match n.camera() {
                    Some(c) if !c.description.is_empty() => c.description.clone(),
                    _ if !n.name.is_empty() => n.name.clone(),
                    _ => format!("viewpoint {}", i + 1),
                }
            }
            Eye::ViewAll => "view all".to_string(),
            Eye::Orbit(_) => "free".to_string(),
        }
    }

    /// The orbit camera the view would become if the user dragged now.
    fn orbit_from_current(&self) -> OrbitCamera {
        let (w, h) = self.viewport_size();
        let pose = crate::anim::evaluate(&self.scene, self.clock.time());
        let view = self.eye.view(&self.scene, &pose, &self.cameras, w, h);
        eye::orbit_from_view(&view, crate::render::bounding_sphere(&self.scene, &pose))
    }
}

impl crate::input::Screen for Viewer {
    fn size(&self) -> (u32, u32) {
        Viewer::size(self)
    }
    fn handle(&mut self, ev: crate::input::Event) -> bool {
        Viewer::handle(self, ev)
    }
    fn draw(&mut self, frame: &mut Frame) {
        Viewer::draw(self, frame)
    }
    fn wants_quit(&self) -> bool {
        Viewer::wants_quit(self)
    }
    fn wants_ticks(&self) -> bool {
        // Ticks also keep the stats' frame counter honest while paused.
        Viewer::wants_ticks(self) || self.show_stats
    }
    fn window_title(&self) -> String {
        self.title.clone()
    }
}
