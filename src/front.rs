//! The library's two verbs besides [`crate::compare`]: [`load`] a scene
//! file and [`render`] it as a [`RenderSpec`] says. Both go through exactly
//! the code `animed render` uses (`format::load`, `render::job::render_color_at`),
//! so a picture made here has the bytes the command line writes.

use crate::error::{Error, ErrorKind, Result};
use crate::picture::Image;
use crate::render::job::{self, FrameSpec, Headlight};
use crate::scene::{RenderStyle, Scene};
use std::path::Path;

/// Loads a scene file: Inventor `.iv`, VRML 1.0, VRML97 `.wrl` (gzipped
/// too), Wavefront `.obj`, detected by content. Non-fatal problems are
/// dropped; [`load_with_warnings`] returns them.
///
/// ```
/// let scene = animed::load("assets/demo.wrl")?;
/// assert!(!scene.nodes.is_empty());
/// # Ok::<(), animed::Error>(())
/// ```
pub fn load(path: impl AsRef<Path>) -> Result<Scene> {
    load_with_warnings(path).map(|(scene, _)| scene)
}

/// [`load`], plus the reader's warnings (each `path:line:column: message`).
///
/// ```
/// let (scene, warnings) = animed::load_with_warnings("assets/demo.wrl")?;
/// assert!(warnings.is_empty());
/// # let _ = scene;
/// # Ok::<(), animed::Error>(())
/// ```
pub fn load_with_warnings(path: impl AsRef<Path>) -> Result<(Scene, Vec<String>)> {
    let loaded = crate::format::load(path.as_ref())?;
    Ok((loaded.scene, loaded.warnings))
}

/// The demo scene bundled in the library (`assets/demo.wrl`): an animated
/// scene that needs no file on disk.
///
/// ```
/// let scene = animed::demo_scene();
/// assert!(scene.settings.fps > 0.0);
/// ```
pub fn demo_scene() -> Scene {
    crate::format::demo()
        // The bundled file is parsed by every test run; it cannot fail here.
        .expect("the bundled demo scene parses")
        .scene
}

/// How to draw a picture of a scene: size, time, camera, style, lights.
///
/// Start from [`RenderSpec::new`] (or `default()`, 640×480) and change what
/// you need, by field or by the builder methods:
///
/// ```
/// use animed::{Headlight, RenderSpec, Style};
/// let spec = RenderSpec::new(160, 120)
///     .at(0.5)
///     .style(Style::Lines)
///     .headlight(Headlight::On)
///     .threads(2);
/// assert_eq!((spec.width, spec.height, spec.time), (160, 120, 0.5));
/// ```
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct RenderSpec {
    /// Picture width in pixels (1..=16384).
    pub width: u32,
    /// Picture height in pixels (1..=16384; width × height ≤ 64 Mpix).
    pub height: u32,
    /// Animation time in seconds.
    pub time: f32,
    /// Animation clip to play: its name, or its 0-based index as
    /// `animed info` lists them. `None` = the clip the scene plays (the
    /// file's first).
    pub clip: Option<String>,
    /// Camera to look through: a viewpoint description or camera node name.
    /// `None` = the scene's first camera, or a view of the whole scene
    /// when it has none.
    pub viewpoint: Option<String>,
    /// Draw every object in this style instead of its own.
    pub style: Option<Style>,
    /// Background colour, linear 0..1 RGB; `None` = the scene's.
    pub background: Option<[f32; 3]>,
    /// The light at the camera ([`Headlight::Auto`]: VRML97 files decide
    /// through NavigationInfo, others get it on).
    pub headlight: Headlight,
    /// Anti-aliasing: samples per pixel, 1 (off), 4 or 8 (multisampling:
    /// depth and coverage per sample, shading once per pixel per triangle,
    /// box-filter resolve; as deterministic as 1). Other values are an error.
    pub aa: u32,
    /// Worker threads, 0 = one per core. Never changes the picture.
    pub threads: usize,
}

/// How objects are drawn (filled, lines, points, hidden).
pub type Style = RenderStyle;

impl Default for RenderSpec {
    fn default() -> Self {
        RenderSpec::new(640, 480)
    }
}

impl RenderSpec {
    /// A `width`×`height` picture at time 0 through the default camera.
    pub fn new(width: u32, height: u32) -> RenderSpec {
        RenderSpec {
            width,
            height,
            time: 0.0,
            clip: None,
            viewpoint: None,
            style: None,
            background: None,
            headlight: Headlight::Auto,
            aa: 1,
            threads: 0,
        }
    }

    /// At `seconds` into the animation.
    pub fn at(mut self, seconds: f32) -> Self {
        self.time = seconds;
        self
    }

    /// Through the camera with this description or node name.
    pub fn viewpoint(mut self, name: impl Into<String>) -> Self {
        self.viewpoint = Some(name.into());
        self
    }

    /// Every object in `style`.
    pub fn style(mut self, style: Style) -> Self {
        self.style = Some(style);
        self
    }

    /// Headlight on, off or as the file says.
    pub fn headlight(mut self, headlight: Headlight) -> Self {
        self.headlight = headlight;
        self
    }

    /// Background colour (linear RGB, 0..1).
    pub fn background(mut self, rgb: [f32; 3]) -> Self {
        self.background = Some(rgb);
        self
    }

    /// Playing the clip with this name (or 0-based index).
    pub fn clip(mut self, name: impl Into<String>) -> Self {
        self.clip = Some(name.into());
        self
    }

    /// Anti-aliasing samples per pixel.
    pub fn aa(mut self, samples: u32) -> Self {
        self.aa = samples;
        self
    }

    /// Worker threads (0 = one per core).
    pub fn threads(mut self, threads: usize) -> Self {
        self.threads = threads;
        self
    }

    /// Checks everything that does not need the scene.
    fn validate(&self) -> Result<()> {
        let bad = |m: String| Err(Error::new(ErrorKind::Invalid, m));
        let max = crate::render::MAX_SIDE;
        if self.width == 0 || self.height == 0 || self.width > max || self.height > max {
            return bad(format!(
                "size {}x{}: each side must be 1..={max}",
                self.width, self.height
            ));
        }
        if self.width as u64 * self.height as u64 > crate::render::MAX_PIXELS {
            return bad(format!(
                "size {}x{}: more than {} pixels",
                self.width,
                self.height,
                crate::render::MAX_PIXELS
            ));
        }
        if !self.time.is_finite() {
            return bad(format!("time {} is not a finite number", self.time));
        }
        if ![1, 4, 8].contains(&self.aa) {
            return bad(format!(
                "aa {}: samples per pixel are 1 (off), 4 or 8",
                self.aa
            ));
        }
        if let Some(bg) = self.background {
            if bg.iter().any(|v| !v.is_finite()) {
                return bad(format!("background {bg:?} is not finite"));
            }
        }
        Ok(())
    }
}

/// Draws `scene` as `spec` says. Deterministic: the same scene and spec
/// give the same pixels for any thread count, build profile and run.
///
/// ```
/// let scene = animed::demo_scene();
/// let img = animed::render(&scene, &animed::RenderSpec::new(64, 48).at(1.0))?;
/// assert_eq!((img.width(), img.height()), (64, 48));
/// let again = animed::render(&scene, &animed::RenderSpec::new(64, 48).at(1.0).threads(1))?;
/// assert_eq!(img, again);
///
/// let err = animed::render(&scene, &animed::RenderSpec::new(64, 48).viewpoint("nope"));
/// assert!(err.is_err());
/// # Ok::<(), animed::Error>(())
/// ```
pub fn render(scene: &Scene, spec: &RenderSpec) -> Result<Image> {
    spec.validate()?;
    // `..default()`: fields FrameSpec may grow keep their defaults until
    // they are wired here.
    #[allow(clippy::needless_update)]
    let frame_spec = FrameSpec {
        width: spec.width,
        height: spec.height,
        viewpoint: spec.viewpoint.clone(),
        style: spec.style,
        background: spec.background.map(glam::Vec3::from),
        headlight: spec.headlight,
        threads: spec.threads,
        aa: spec.aa,
        ..FrameSpec::default()
    };
    let invalid = |m: String| Error::new(ErrorKind::Invalid, m);
    // Another clip than the playing one: draw a copy that plays it (the
    // scene itself is never changed).
    let switched;
    let scene = match &spec.clip {
        Some(name) if scene.find_clip(name).map_err(invalid)? != scene.clips.active() => {
            let mut copy = scene.clone();
            copy.play_clip(name).map_err(invalid)?;
            switched = copy;
            &switched
        }
        _ => scene,
    };
    let frame = job::render_color_at(scene, &frame_spec, spec.time).map_err(invalid)?;
    Ok(Image::from(&frame))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Clip;

    /// The demo with two clips: "moving" (the demo's animation, playing)
    /// and "still" (no tracks).
    fn two_clips() -> Scene {
        let mut scene = demo_scene();
        let moving = Clip {
            name: "moving".into(),
            animation: scene.animation.clone(),
            duration: scene.settings.duration,
        };
        let still = Clip {
            name: "still".into(),
            ..Clip::default()
        };
        scene.set_clips(vec![moving, still], 0);
        scene
    }

    #[test]
    fn a_spec_picks_the_clip_without_changing_the_scene() {
        let scene = two_clips();
        let spec = RenderSpec::new(64, 48).at(1.0);
        let default = render(&scene, &spec).unwrap();
        let moving = render(&scene, &spec.clone().clip("moving")).unwrap();
        let by_index = render(&scene, &spec.clone().clip("1")).unwrap();
        let still = render(&scene, &spec.clone().clip("still")).unwrap();
        assert_eq!(default, moving);
        assert_eq!(by_index, still);
        assert_ne!(default, still, "the still clip must not animate");
        assert_eq!(scene.clips.active_name(), Some("moving"));
        let err = render(&scene, &spec.clip("run")).unwrap_err();
        assert_eq!(err.kind(), ErrorKind::Invalid);
    }

    #[test]
    fn aa_is_the_command_lines_anti_aliasing() {
        let scene = demo_scene();
        let plain = render(&scene, &RenderSpec::new(64, 48)).unwrap();
        let aa4 = render(&scene, &RenderSpec::new(64, 48).aa(4)).unwrap();
        assert_ne!(plain, aa4, "4 samples must smooth some edge");
        let again = render(&scene, &RenderSpec::new(64, 48).aa(4).threads(1)).unwrap();
        assert_eq!(aa4, again);
    }

    #[test]
    fn bad_specs_are_errors_not_panics() {
        let scene = demo_scene();
        for spec in [
            RenderSpec::new(0, 10),
            RenderSpec::new(20_000, 10),
            RenderSpec::new(10, 10).at(f32::NAN),
            RenderSpec::new(10, 10).aa(3),
            RenderSpec::new(10, 10).background([f32::INFINITY, 0.0, 0.0]),
        ] {
            let err = render(&scene, &spec).unwrap_err();
            assert_eq!(err.kind(), ErrorKind::Invalid, "{spec:?}");
        }
    }
}
