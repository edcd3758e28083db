//! `animed key`: set, remove and list keys from the command line — what the
//! editor does to keys, for scripts.
//!
//! ```text
//! animed key new OUT [--node NAME]… [--box NAME]… [--light NAME]… [--camera NAME]…
//!                [--fps F] [--duration N]
//! animed key set FILE --target NAME.property (--frame N | --time S) --value V
//!                [--interp step|linear|tcb|slerp|squad] [--tcb T,C,B] [--ease IN,OUT]
//!                [--repeat constant|loop] [--fps F] [--duration N] [-o OUT]
//! animed key rm FILE --target NAME.property (--frame N | --time S) [-o OUT]
//! animed key list FILE [--json]
//! animed key settings FILE [--fps F] [--duration N] [-o OUT]
//! ```
//! Values are comma-separated: scalars `x`, vectors `x,y,z`, colours
//! `r,g,b`, rotations axis-angle `x,y,z,angle` (radians), booleans
//! `true`/`false`. `-o` defaults to FILE itself; saving is atomic.
//! `key new` starts a scene from nothing: empty named Transforms (`--node`),
//! unit cubes (`--box`), point lights (`--light`) and cameras (`--camera`),
//! so there is something to key.
//!
//! `NAME` is a node or material name. For light, camera and material
//! properties a group node's direct child of the right kind (or a shape's
//! material) also answers to the group's name, since files wrap animated
//! lights in a Transform.

use crate::anim::{
    Interp, Key, KeyParams, Keys, Property, Repeat, Target, TargetRef, Track, Value, ValueKind,
};
use crate::format::export::atomic::{EditLock, Replace};
use crate::format::{self, WriteOptions};
use crate::scene::{Light, LightKind, Material, Mesh, Node, NodeId, NodeKind, Scene, Shape};
use glam::Vec3;
use std::path::{Path, PathBuf};

/// Set, remove and list keys from the command line.
///
/// Editing commands hold an advisory lock on the file's folder from the
/// read to the replace, so two `animed key` (or `convert -o`, or editor
/// saves) on one file take turns and never lose an update.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub command: KeyCommand,
    /// Replace the file even if it is read-only.
    #[arg(long, global = true)]
    pub force: bool,
}

#[derive(clap::Subcommand, Debug)]
pub enum KeyCommand {
    /// Create a new scene file with named nodes to animate.
    New(NewArgs),
    /// Set (add or replace) a key.
    Set(SetArgs),
    /// Remove a key (and its track when it was the last key).
    Rm(RmArgs),
    /// List every track and key.
    List(ListArgs),
    /// Change the scene's frame rate or duration.
    Settings(SettingsArgs),
}

#[derive(clap::Args, Debug)]
pub struct NewArgs {
    /// The file to create (.wrl, .wrl.gz or .iv); it must not exist yet.
    pub output: PathBuf,
    /// An empty Transform with this name (repeatable).
    #[arg(long = "node")]
    pub nodes: Vec<String>,
    /// A unit cube with this name (repeatable).
    #[arg(long = "box")]
    pub boxes: Vec<String>,
    /// A point light with this name (repeatable).
    #[arg(long = "light")]
    pub lights: Vec<String>,
    /// A camera (VRML97 default viewpoint: at 0,0,10 looking down -z) with this name (repeatable).
    #[arg(long = "camera")]
    pub cameras: Vec<String>,
    #[command(flatten)]
    pub timing: Timing,
}

#[derive(clap::Args, Debug)]
pub struct Timing {
    /// Frames per second.
    #[arg(long)]
    pub fps: Option<f32>,
    /// Animation length in frames.
    #[arg(long)]
    pub duration: Option<f32>,
}

#[derive(clap::Args, Debug)]
pub struct When {
    /// Key time in frames.
    #[arg(long, conflicts_with = "time", required_unless_present = "time")]
    pub frame: Option<f32>,
    /// Key time in seconds (converted with the scene's fps).
    #[arg(long)]
    pub time: Option<f32>,
}

#[derive(clap::Args, Debug)]
pub struct SetArgs {
    /// Scene file to change.
    pub file: PathBuf,
    /// What to key: NAME.property (e.g. Box.translation, Lamp.intensity, Red.diffuseColor).
    #[arg(long)]
    pub target: String,
    #[command(flatten)]
    pub when: When,
    /// The value, comma-separated (rotation: x,y,z,angle in radians).
    #[arg(long, allow_hyphen_values = true)]
    pub value: String,
    /// Interpolation of the segment leaving this key.
    #[arg(long)]
    pub interp: Option<String>,
    /// Tension, continuity, bias, each in [-1, 1].
    #[arg(long, allow_hyphen_values = true)]
    pub tcb: Option<String>,
    /// Ease in, ease out, each in [0, 1].
    #[arg(long)]
    pub ease: Option<String>,
    /// Repeat mode of the track outside its keys.
    #[arg(long, value_parser = ["constant", "loop"])]
    pub repeat: Option<String>,
    #[command(flatten)]
    pub timing: Timing,
    /// Where to save (default: FILE itself).
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

#[derive(clap::Args, Debug)]
pub struct RmArgs {
    pub file: PathBuf,
    #[arg(long)]
    pub target: String,
    #[command(flatten)]
    pub when: When,
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

#[derive(clap::Args, Debug)]
pub struct ListArgs {
    pub file: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

#[derive(clap::Args, Debug)]
pub struct SettingsArgs {
    pub file: PathBuf,
    #[command(flatten)]
    pub timing: Timing,
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

pub fn run(args: Args) -> i32 {
    FORCE.store(args.force, std::sync::atomic::Ordering::Relaxed);
    // The file an editing command replaces: locked from before it is read.
    let edited = match &args.command {
        KeyCommand::New(a) => Some(a.output.clone()),
        KeyCommand::Set(a) => Some(a.output.clone().unwrap_or_else(|| a.file.clone())),
        KeyCommand::Rm(a) => Some(a.output.clone().unwrap_or_else(|| a.file.clone())),
        KeyCommand::Settings(a) => Some(a.output.clone().unwrap_or_else(|| a.file.clone())),
        KeyCommand::List(_) => None,
    };
    let _lock = match edited.map(|p| EditLock::acquire(&p).map_err(|e| (p, e))) {
        Some(Err((p, e))) => {
            eprintln!("animed key: {}: cannot lock for editing: {e}", p.display());
            return 1;
        }
        Some(Ok(l)) => Some(l),
        None => None,
    };
    let result = match args.command {
        KeyCommand::New(a) => new(a),
        KeyCommand::Set(a) => set(a),
        KeyCommand::Rm(a) => rm(a),
        KeyCommand::List(a) => list(a),
        KeyCommand::Settings(a) => settings(a),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("animed key: {e}");
            1
        }
    }
}

fn load(path: &Path, clip: &super::clip_arg::ClipArg) -> Result<Scene, String> {
    if !path.exists() {
        return Err(format!(
            "{}: no such file (start a scene with `animed key new {} --box NAME`)",
            path.display(),
            path.display()
        ));
    }
    let loaded = clip.load(path).map_err(|e| e.to_string())?;
    for w in &loaded.warnings {
        eprintln!("warning: {w}");
    }
    let mut scene = loaded.scene;
    clip.apply(&mut scene)?;
    Ok(scene)
}

/// `--force`, for [`save`].
static FORCE: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

fn save(scene: &Scene, path: &Path) -> Result<(), String> {
    let how = Replace {
        force: FORCE.load(std::sync::atomic::Ordering::Relaxed),
    };
    let report = format::save::save_with(scene, path, &WriteOptions::default(), how)
        .map_err(|e| e.to_string())?;
    for w in &report.warnings {
        eprintln!("warning: {w}");
    }
    Ok(())
}

fn apply_timing(scene: &mut Scene, t: &Timing) -> Result<(), String> {
    if let Some(fps) = t.fps {
        if !(fps.is_finite() && fps > 0.0) {
            return Err("--fps must be a positive number".into());
        }
        scene.settings.fps = fps;
    }
    if let Some(d) = t.duration {
        if !(d.is_finite() && d > 0.0) {
            return Err("--duration must be a positive number of frames".into());
        }
        scene.settings.duration = d;
    }
    Ok(())
}

fn new(a: NewArgs) -> Result<(), String> {
    if a.output.exists() {
        return Err(format!(
            "{}: already exists (key new only creates)",
            a.output.display()
        ));
    }
    let mut scene = Scene::new();
    apply_timing(&mut scene, &a.timing)?;
    let mut names = std::collections::HashSet::new();
    for n in a
        .nodes
        .iter()
        .chain(&a.boxes)
        .chain(&a.lights)
        .chain(&a.cameras)
    {
        if n.is_empty() || !names.insert(n.clone()) {
            return Err(format!("node name `{n}` is empty or given twice"));
        }
        if crate::format::export::plan::sanitize(n) != *n {
            return Err(format!(
                "node name `{n}` must be letters, digits and `_`, not starting with a digit"
            ));
        }
    }
    for n in &a.cameras {
        let camera = crate::scene::Camera {
            description: n.clone(),
            ..Default::default()
        };
        scene.add_node(None, Node::new(n.clone(), NodeKind::Camera(camera)));
    }
    for n in &a.nodes {
        scene.add_node(None, Node::group(n.clone()));
    }
    if !a.boxes.is_empty() {
        let mesh = scene.add_mesh(unit_cube());
        let material = scene.add_material(Material::default());
        for n in &a.boxes {
            scene.add_node(
                None,
                Node::new(n.clone(), NodeKind::Shape(Shape { mesh, material })),
            );
        }
    }
    for n in &a.lights {
        let mut l = Light::new(LightKind::Point);
        l.location = Vec3::new(0.0, 0.0, 5.0);
        scene.add_node(None, Node::new(n.clone(), NodeKind::Light(l)));
    }
    save(&scene, &a.output)
}

/// A unit cube centred on the origin, flat normals, CCW outside.
fn unit_cube() -> Mesh {
    let mut m = Mesh {
        name: "cube".into(),
        solid: true,
        ..Default::default()
    };
    let faces = [
        (Vec3::X, Vec3::Y, Vec3::Z),
        (Vec3::NEG_X, Vec3::Z, Vec3::Y),
        (Vec3::Y, Vec3::Z, Vec3::X),
        (Vec3::NEG_Y, Vec3::X, Vec3::Z),
        (Vec3::Z, Vec3::X, Vec3::Y),
        (Vec3::NEG_Z, Vec3::Y, Vec3::X),
    ];
    for (n, u, v) in faces {
        let base = m.positions.len() as u32;
        for (a, b) in [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)] {
            m.positions.push(n * 0.5 + u * a + v * b);
            m.normals.push(n);
        }
        m.triangles.push([base, base + 1, base + 2]);
        m.triangles.push([base, base + 2, base + 3]);
    }
    m
}

/// Resolves `NAME.property` to a target in `scene`.
pub fn resolve(scene: &Scene, spec: &str) -> Result<Target, String> {
    let (name, prop) = spec
        .rsplit_once('.')
        .ok_or_else(|| format!("--target `{spec}` must be NAME.property"))?;
    let property = Property::parse(prop).ok_or_else(|| {
        let all: Vec<&str> = Property::ALL.iter().map(|p| p.name()).collect();
        format!("unknown property `{prop}` (one of: {})", all.join(", "))
    })?;
    let owns = |id: NodeId| {
        matches!(
            (property.owner(), &scene.node(id).kind),
            ("node", _) | ("light", NodeKind::Light(_)) | ("camera", NodeKind::Camera(_))
        ) || (property.owner() == "shape" && super::sample::has_morphs(scene, id))
    };
    let node = scene.find_node(name);
    if property.owner() == "material" {
        if let Some(m) = scene.find_material(name) {
            return Ok(Target {
                of: TargetRef::Material(m),
                property,
            });
        }
        let shape_material = |id: NodeId| match &scene.node(id).kind {
            NodeKind::Shape(s) => Some(s.material),
            _ => None,
        };
        if let Some(id) = node {
            let m = shape_material(id).or_else(|| {
                scene
                    .node(id)
                    .children
                    .iter()
                    .find_map(|&c| shape_material(c))
            });
            if let Some(m) = m {
                return Ok(Target {
                    of: TargetRef::Material(m),
                    property,
                });
            }
        }
        return Err(format!("no material (or shape) named `{name}`"));
    }
    let id = node.ok_or_else(|| format!("no node named `{name}`"))?;
    let id = if owns(id) {
        id
    } else {
        scene
            .node(id)
            .children
            .iter()
            .copied()
            .find(|&c| owns(c))
            .ok_or_else(|| {
                format!(
                    "node `{name}` has no property `{}` (it belongs to a {})",
                    property.name(),
                    property.owner()
                )
            })?
    };
    Ok(Target {
        of: TargetRef::Node(id),
        property,
    })
}

fn numbers(s: &str, what: &str, count: usize) -> Result<Vec<f32>, String> {
    let v: Vec<f32> = s
        .split(',')
        .map(|w| w.trim().parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("{what} `{s}` must be {count} comma-separated numbers"))?;
    if v.len() != count || v.iter().any(|x| !x.is_finite()) {
        return Err(format!(
            "{what} `{s}` must be {count} comma-separated numbers"
        ));
    }
    Ok(v)
}

/// Parses a value for `kind` (see the module doc).
pub fn parse_value(kind: ValueKind, s: &str) -> Result<Value, String> {
    if kind == ValueKind::Bool {
        return match s.trim().to_ascii_lowercase().as_str() {
            "true" | "on" | "1" | "yes" => Ok(Value::Bool(true)),
            "false" | "off" | "0" | "no" => Ok(Value::Bool(false)),
            _ => Err(format!("value `{s}` must be true or false")),
        };
    }
    let what = match kind {
        ValueKind::Rotation => "rotation (x,y,z,angle)",
        ValueKind::Color => "colour (r,g,b)",
        ValueKind::Vec3 => "vector (x,y,z)",
        _ => "value",
    };
    let n = numbers(s, what, kind.arity())?;
    Value::from_numbers(kind, &n).map_err(|e| format!("value `{s}`: {e}"))
}

fn frame_of(scene: &Scene, w: &When) -> Result<f32, String> {
    let f = match (w.frame, w.time) {
        (Some(f), _) => f,
        (None, Some(t)) => t * scene.settings.fps,
        (None, None) => return Err("give --frame or --time".into()),
    };
    if !f.is_finite() {
        return Err("the key time must be a finite number".into());
    }
    Ok(f)
}

fn set(a: SetArgs) -> Result<(), String> {
    let mut scene = load(&a.file, &a.clip)?;
    apply_timing(&mut scene, &a.timing)?;
    let target = resolve(&scene, &a.target)?;
    let frame = frame_of(&scene, &a.when)?;
    let value = parse_value(target.property.kind(), &a.value)?;
    let anim = &mut scene.animation;
    let index = anim
        .set_key(target, frame, value)
        .map_err(|e| e.to_string())?;
    let track = anim
        .track_mut(target)
        .ok_or("the track vanished after setting a key")?;
    let mut p = track.key_params(index).unwrap_or_default();
    if let Some(i) = &a.interp {
        p.interp = Interp::parse(i).ok_or_else(|| format!("unknown interpolation `{i}`"))?;
    }
    if target.property.kind() == ValueKind::Bool {
        p.interp = Interp::Step;
    }
    if let Some(t) = &a.tcb {
        let v = numbers(t, "--tcb", 3)?;
        (p.tension, p.continuity, p.bias) = (v[0], v[1], v[2]);
    }
    if let Some(e) = &a.ease {
        let v = numbers(e, "--ease", 2)?;
        (p.ease_in, p.ease_out) = (v[0], v[1]);
    }
    track.set_key_params(index, p).map_err(|e| e.to_string())?;
    if let Some(r) = &a.repeat {
        track.repeat = if r == "loop" {
            Repeat::Loop
        } else {
            Repeat::Constant
        };
    }
    save(&scene, a.output.as_deref().unwrap_or(&a.file))
}

fn rm(a: RmArgs) -> Result<(), String> {
    let mut scene = load(&a.file, &a.clip)?;
    let target = resolve(&scene, &a.target)?;
    let frame = frame_of(&scene, &a.when)?;
    let track = scene
        .animation
        .track_mut(target)
        .ok_or_else(|| format!("`{}` has no keys", a.target))?;
    if track.key_index_at(frame).is_none() {
        return Err(format!("`{}` has no key at frame {frame}", a.target));
    }
    if track.key_count() == 1 {
        scene.animation.remove_tracks(target);
    } else {
        track.remove_key(frame).map_err(|e| e.to_string())?;
    }
    save(&scene, a.output.as_deref().unwrap_or(&a.file))
}

fn settings(a: SettingsArgs) -> Result<(), String> {
    let mut scene = load(&a.file, &a.clip)?;
    if a.timing.fps.is_none() && a.timing.duration.is_none() {
        println!(
            "fps {}\nduration {}",
            scene.settings.fps, scene.settings.duration
        );
        return Ok(());
    }
    apply_timing(&mut scene, &a.timing)?;
    save(&scene, a.output.as_deref().unwrap_or(&a.file))
}

/// `NAME.property` of a track, as `--target` accepts it.
fn target_label(scene: &Scene, t: &Track) -> String {
    let name = match t.target.of {
        TargetRef::Node(id) => scene
            .nodes
            .get(id.0 as usize)
            .map_or("?".to_string(), |n| n.name.clone()),
        TargetRef::Material(m) => scene
            .materials
            .get(m.0 as usize)
            .map_or("?".to_string(), |m| m.name.clone()),
    };
    format!("{name}.{}", t.target.property.name())
}

fn value_numbers(v: &Value) -> Vec<f32> {
    v.to_numbers()
}

fn list(a: ListArgs) -> Result<(), String> {
    let scene = load(&a.file, &a.clip)?;
    if a.json {
        println!("{}", list_json(&scene));
    } else {
        print!("{}", list_text(&scene));
    }
    Ok(())
}

fn keys_of(t: &Track) -> Vec<Key<Value>> {
    (0..t.keys.len()).filter_map(|i| t.keys.key(i)).collect()
}

fn fmt_numbers(v: &[f32]) -> String {
    v.iter()
        .map(|x| x.to_string())
        .collect::<Vec<_>>()
        .join(",")
}

/// The text listing: settings, then per track its keys.
pub fn list_text(scene: &Scene) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "fps {} duration {}",
        scene.settings.fps, scene.settings.duration
    );
    for t in &scene.animation.tracks {
        let rot = matches!(t.keys, Keys::Rotation(_));
        let repeat = match t.repeat {
            Repeat::Constant => "constant",
            Repeat::Loop => "loop",
        };
        let _ = writeln!(s, "{} ({repeat})", target_label(scene, t));
        for k in keys_of(t) {
            let p: KeyParams = k.params();
            let _ = writeln!(
                s,
                "  frame {} value {} interp {} tcb {},{},{} ease {},{}",
                k.frame,
                fmt_numbers(&value_numbers(&k.value)),
                p.interp.name(rot),
                p.tension,
                p.continuity,
                p.bias,
                p.ease_in,
                p.ease_out
            );
        }
    }
    s
}

/// The JSON listing: `{fps, duration, tracks: [{target, property, repeat, keys: [...]}]}`.
pub fn list_json(scene: &Scene) -> String {
    use serde_json::json;
    let tracks: Vec<serde_json::Value> = scene
        .animation
        .tracks
        .iter()
        .map(|t| {
            let rot = matches!(t.keys, Keys::Rotation(_));
            let label = target_label(scene, t);
            let name = label.rsplit_once('.').map_or("", |(n, _)| n).to_string();
            json!({
                "target": label,
                "name": name,
                "property": t.target.property.name(),
                "repeat": match t.repeat { Repeat::Constant => "constant", Repeat::Loop => "loop" },
                "keys": keys_of(t).iter().map(|k| json!({
                    "frame": k.frame,
                    "value": value_numbers(&k.value),
                    "interp": k.interp.name(rot),
                    "tcb": [k.tension, k.continuity, k.bias],
                    "ease": [k.ease_in, k.ease_out],
                })).collect::<Vec<_>>(),
            })
        })
        .collect();
    json!({
        "fps": scene.settings.fps,
        "duration": scene.settings.duration,
        "tracks": tracks,
    })
    .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_parse_by_kind() {
        assert_eq!(
            parse_value(ValueKind::Vec3, "1,-2,3.5").unwrap(),
            Value::Vec3(Vec3::new(1.0, -2.0, 3.5))
        );
        assert_eq!(
            parse_value(ValueKind::Bool, "off").unwrap(),
            Value::Bool(false)
        );
        let Value::Rotation(q) = parse_value(ValueKind::Rotation, "0,1,0,1.5707964").unwrap()
        else {
            panic!()
        };
        assert!((q.y - std::f32::consts::FRAC_1_SQRT_2).abs() < 1e-6);
        assert!(parse_value(ValueKind::Vec3, "1,2").is_err());
        assert!(parse_value(ValueKind::Scalar, "x").is_err());
        assert!(parse_value(ValueKind::Rotation, "0,0,0,1").is_err());
    }

    #[test]
    fn targets_resolve_through_wrappers() {
        let mut s = Scene::new();
        let g = s.add_node(None, Node::group("Lamp"));
        let l = s.add_node(
            Some(g),
            Node::new("Lamp_light", NodeKind::Light(Light::new(LightKind::Point))),
        );
        let mesh = s.add_mesh(unit_cube());
        let material = s.add_material(Material::default());
        let b = s.add_node(
            None,
            Node::new("Box", NodeKind::Shape(Shape { mesh, material })),
        );
        assert_eq!(
            resolve(&s, "Lamp.intensity").unwrap().of,
            TargetRef::Node(l)
        );
        assert_eq!(
            resolve(&s, "Lamp.translation").unwrap().of,
            TargetRef::Node(g)
        );
        assert_eq!(
            resolve(&s, "Box.diffuseColor").unwrap().of,
            TargetRef::Material(material)
        );
        assert_eq!(resolve(&s, "Box.rotation").unwrap().of, TargetRef::Node(b));
        assert!(resolve(&s, "Box.intensity").unwrap_err().contains("light"));
        assert!(resolve(&s, "Nope.translation").is_err());
        assert!(resolve(&s, "Box.wobble")
            .unwrap_err()
            .contains("unknown property"));
        assert!(resolve(&s, "Box").is_err());
    }
}
