//! Rendering one frame of a scene the way `animed render` does: choose the
//! camera (named viewpoint, else the first camera, else Coin's view-all),
//! decide the headlight, evaluate the animation at a time and draw.
//! The CLI, GIF/sequence output and sharded rendering all call
//! [`render_at`], so every frame they write is the same picture.

use super::{render_color_into, render_into, Frame, RenderOptions, View};
use crate::anim::{evaluate, Pose};
use crate::scene::{NodeId, RenderStyle, Scene, SourceFormat};
use glam::Vec3;

/// `--headlight on|off|auto`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Headlight {
    On,
    Off,
    /// VRML97: NavigationInfo.headlight (default on); every other format:
    /// on, as the examiner viewers do.
    #[default]
    Auto,
}

impl Headlight {
    pub fn parse(s: &str) -> Option<Headlight> {
        match s.to_ascii_lowercase().as_str() {
            "on" | "true" | "1" => Some(Headlight::On),
            "off" | "false" | "0" => Some(Headlight::Off),
            "auto" => Some(Headlight::Auto),
            _ => None,
        }
    }

    /// Whether the headlight shines for `scene`.
    pub fn resolve(self, scene: &Scene) -> bool {
        match self {
            Headlight::On => true,
            Headlight::Off => false,
            // Only VRML97 readers set `settings.headlight` (NavigationInfo);
            // other formats leave it `None` and get the examiner headlight.
            Headlight::Auto => match scene.format {
                SourceFormat::Vrml97 | SourceFormat::X3d | SourceFormat::Gltf => {
                    scene.settings.headlight.unwrap_or(true)
                }
                _ => true,
            },
        }
    }
}

/// What to draw, independent of time.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameSpec {
    pub width: u32,
    pub height: u32,
    /// Camera description or node name; `None` = first camera, else view-all.
    pub viewpoint: Option<String>,
    pub style: Option<RenderStyle>,
    /// `None` = the scene's background.
    pub background: Option<Vec3>,
    pub headlight: Headlight,
    /// 0 = all cores; never changes the picture.
    pub threads: usize,
    /// Samples per pixel (1 = no anti-aliasing, 4, 8); see `RenderOptions::aa`.
    pub aa: u32,
}

impl Default for FrameSpec {
    fn default() -> Self {
        FrameSpec {
            width: 640,
            height: 480,
            viewpoint: None,
            style: None,
            background: None,
            headlight: Headlight::Auto,
            threads: 0,
            aa: 1,
        }
    }
}

/// The camera node a spec asks for: `Ok(None)` means "no camera, view all".
/// A name that matches nothing is an error listing the cameras there are.
pub fn find_camera(scene: &Scene, name: Option<&str>) -> Result<Option<NodeId>, String> {
    let cameras: Vec<NodeId> = scene
        .walk()
        .into_iter()
        .filter(|&id| scene.node(id).camera().is_some())
        .collect();
    let Some(name) = name else {
        return Ok(cameras.first().copied());
    };
    let matches = |id: &NodeId| {
        let n = scene.node(*id);
        n.camera().is_some_and(|c| c.description == name) || n.name == name
    };
    if let Some(id) = cameras.iter().find(|id| matches(id)) {
        return Ok(Some(*id));
    }
    let names: Vec<String> = cameras
        .iter()
        .map(|&id| {
            let n = scene.node(id);
            let d = n.camera().map(|c| c.description.as_str()).unwrap_or("");
            if d.is_empty() {
                format!("{:?}", n.name)
            } else {
                format!("{d:?}")
            }
        })
        .collect();
    Err(if names.is_empty() {
        format!("no viewpoint named {name:?}: the scene has no cameras")
    } else {
        format!(
            "no viewpoint named {name:?}; the scene has {}",
            names.join(", ")
        )
    })
}

/// The view through `camera` (animated values from `pose`), or view-all
/// framed once from the start of the animation
/// ([`View::view_all_from_start`]), so a file without a camera does not
/// jump from frame to frame.
pub fn view_for(scene: &Scene, pose: &Pose, camera: Option<NodeId>, aspect: f32) -> View {
    if let Some(id) = camera {
        let cam = pose.camera(id).or_else(|| scene.node(id).camera());
        if let Some(cam) = cam {
            let world = pose
                .world
                .get(id.0 as usize)
                .copied()
                .unwrap_or(glam::Mat4::IDENTITY);
            return View::for_scene(cam, world, aspect, scene, pose);
        }
    }
    View::view_all_from_start(scene, &evaluate(scene, 0.0), pose, aspect)
}

/// The render options a spec means for `scene`.
pub fn options_for(scene: &Scene, spec: &FrameSpec) -> RenderOptions {
    RenderOptions {
        width: spec.width,
        height: spec.height,
        threads: spec.threads,
        style_override: spec.style,
        headlight: spec.headlight.resolve(scene),
        background: spec.background.unwrap_or(scene.settings.background),
        // `--bg` overrides a file's Background gradient too.
        sky: spec.background.is_none(),
        aa: spec.aa,
    }
}

/// Renders `scene` at `time` seconds as `spec` says.
pub fn render_at(scene: &Scene, spec: &FrameSpec, time: f32) -> Result<Frame, String> {
    frame_at(scene, spec, time, render_into)
}

/// [`render_at`] for a picture only: the same colour, no depth or ids
/// (what `animed render` and the library's `render` write out).
pub fn render_color_at(scene: &Scene, spec: &FrameSpec, time: f32) -> Result<Frame, String> {
    frame_at(scene, spec, time, render_color_into)
}

/// The camera, pose and view of `spec` at `time`, drawn by `draw`.
fn frame_at(
    scene: &Scene,
    spec: &FrameSpec,
    time: f32,
    draw: fn(&Scene, &Pose, &View, &RenderOptions, &mut Frame),
) -> Result<Frame, String> {
    let camera = find_camera(scene, spec.viewpoint.as_deref())?;
    let pose = evaluate(scene, time);
    let aspect = spec.width.max(1) as f32 / spec.height.max(1) as f32;
    let view = match camera {
        Some(_) => view_for(scene, &pose, camera, aspect),
        // View-all for this picture size (Text2 labels framed as Coin does).
        None => {
            View::view_all_for_picture(scene, &evaluate(scene, 0.0), &pose, spec.width, spec.height)
        }
    };
    let opts = options_for(scene, spec);
    let mut frame = Frame::new(0, 0, opts.background);
    draw(scene, &pose, &view, &opts, &mut frame);
    Ok(frame)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Key, Keys, Property, Repeat, Target, TargetRef, Track};
    use crate::scene::{primitives, Material, Node, NodeKind, Shape};

    /// A unit box that slides from x = 0 to x = 10 over the animation.
    fn sliding_box(animated: bool) -> Scene {
        let mut s = Scene::new();
        let mesh = s.add_mesh(primitives::box_mesh(Vec3::ONE));
        let material = s.add_material(Material::default());
        let id = s.add_node(
            None,
            Node::new("Box", NodeKind::Shape(Shape { mesh, material })),
        );
        if animated {
            let keys = Keys::Vec3(vec![
                Key::new(0.0, Vec3::ZERO),
                Key::new(48.0, Vec3::X * 10.0),
            ]);
            let target = Target {
                of: TargetRef::Node(id),
                property: Property::Translation,
            };
            s.animation
                .tracks
                .push(Track::new(target, Repeat::Constant, keys).unwrap());
        }
        s
    }

    #[test]
    fn view_all_is_framed_once_from_the_start_of_the_animation() {
        let s = sliding_box(true);
        let fps = s.settings.fps;
        let at = |t: f32| view_for(&s, &evaluate(&s, t), None, 1.5);
        let (v0, v1, v2) = (at(0.0), at(24.0 / fps), at(48.0 / fps));
        // Same camera at every time: the box moves, the view does not.
        assert_eq!(v0.view, v1.view);
        assert_eq!(v0.view, v2.view);
        assert_eq!(v0.eye, v2.eye);
        // The start frame is exactly Coin's view-all of the start pose.
        assert_eq!(v0, View::view_all(&s, &evaluate(&s, 0.0), 1.5));
        // Near/far widen so the moved box is not clipped away: its far
        // corner projects inside the depth range.
        let corner = v2.proj * v2.view * glam::Vec4::new(10.5, 0.5, -0.5, 1.0);
        assert!((corner.z / corner.w).abs() <= 1.0, "{corner}");
        // Re-framing per time (the old behaviour) would have moved the eye.
        let reframed = View::view_all(&s, &evaluate(&s, 48.0 / fps), 1.5);
        assert_ne!(reframed.eye, v2.eye);
    }

    /// A colour-only frame has exactly the full frame's colour bytes and
    /// no depth or ids, with and without multisampling; one frame reused
    /// across both kinds gets its buffers back.
    #[test]
    fn colour_only_frames_keep_the_colour_bytes() {
        let s = sliding_box(true);
        for aa in [1, 4] {
            let spec = FrameSpec {
                width: 70,
                height: 45,
                aa,
                ..FrameSpec::default()
            };
            let full = render_at(&s, &spec, 0.0).unwrap();
            let colour = render_color_at(&s, &spec, 0.0).unwrap();
            assert_eq!(colour.color, full.color, "aa {aa}");
            assert!(full.ids.iter().any(|&i| i != 0), "the box is drawn");
            assert!(colour.depth.is_empty() && colour.ids.is_empty());
            let pose = evaluate(&s, 0.0);
            let view = view_for(&s, &pose, None, 70.0 / 45.0);
            let opts = options_for(&s, &spec);
            let mut reused = render_at(&s, &spec, 0.0).unwrap();
            render_color_into(&s, &pose, &view, &opts, &mut reused);
            assert_eq!(reused.color, full.color);
            assert!(reused.depth.is_empty() && reused.ids.is_empty());
            render_into(&s, &pose, &view, &opts, &mut reused);
            assert_eq!(reused, full, "aa {aa}");
        }
    }

    #[test]
    fn a_still_scene_frames_exactly_as_before() {
        let s = sliding_box(false);
        let p = evaluate(&s, 1.0);
        assert_eq!(view_for(&s, &p, None, 1.0), View::view_all(&s, &p, 1.0));
    }
}
