//! `animed info`: describe a scene file: nodes, shapes, lights, cameras, textures, tracks, warnings.

use crate::anim::{TargetRef, Track};
use crate::format;
use crate::scene::{CameraKind, ImageSource, LightKind, NodeId, NodeKind, Scene, SourceFormat};
use serde_json::{json, Value as Json};
use std::path::PathBuf;

/// Describe a scene file: nodes, shapes, lights, cameras, textures, tracks, warnings.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The scene file (.iv, .wrl, .wrl.gz, .obj …).
    pub file: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Validate: exit with status 3 when the reader warned that the file
    /// breaks its spec (an unknown node or field, IS outside a PROTO…),
    /// after printing the report; warnings about nodes animed does not
    /// support or files that are not there do not count. For people who
    /// check files before publishing.
    #[arg(long)]
    pub strict: bool,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

/// The name `info` shows for a node and `sample` accepts: its DEF name, or
/// `#N` (its index) when it has none.
pub fn node_label(scene: &Scene, id: NodeId) -> String {
    let n = scene.node(id);
    if n.name.is_empty() {
        format!("#{}", id.0)
    } else {
        n.name.clone()
    }
}

/// `NAME.property` of a track's target (materials by name or `material#N`).
pub fn target_label(scene: &Scene, t: &Track) -> String {
    let owner = match t.target.of {
        TargetRef::Node(id) if (id.0 as usize) < scene.nodes.len() => node_label(scene, id),
        TargetRef::Node(id) => format!("#{}", id.0),
        TargetRef::Material(m) => match scene.materials.get(m.0 as usize) {
            Some(mat) if !mat.name.is_empty() => mat.name.clone(),
            _ => format!("material#{}", m.0),
        },
    };
    format!("{owner}.{}", t.target.property.name())
}

/// An f32 as the shortest f64 that prints the same (0.6, not 0.6000000238).
pub fn short(x: f32) -> f64 {
    format!("{x}").parse().unwrap_or(0.0)
}

fn format_name(f: SourceFormat) -> &'static str {
    match f {
        SourceFormat::Native => "native",
        SourceFormat::Inventor => "Open Inventor",
        SourceFormat::Vrml1 => "VRML 1.0",
        SourceFormat::Vrml97 => "VRML97",
        SourceFormat::X3d => "X3D",
        SourceFormat::Obj => "Wavefront OBJ",
        SourceFormat::Gltf => "glTF 2.0",
    }
}

/// One entry per image: its size, components, where it came from, and the
/// materials and shapes that draw it.
fn describe_textures(s: &Scene) -> Vec<Json> {
    s.images
        .iter()
        .enumerate()
        .map(|(i, image)| {
            let uses = |m: &crate::scene::Material| m.textures().any(|t| t.image.0 as usize == i);
            let materials: Vec<usize> = (0..s.materials.len())
                .filter(|&m| uses(&s.materials[m]))
                .collect();
            let material_names: Vec<String> = materials
                .iter()
                .map(|&m| match s.materials[m].name.as_str() {
                    "" => format!("material#{m}"),
                    n => n.to_string(),
                })
                .collect();
            let shapes: Vec<String> = s
                .walk()
                .into_iter()
                .filter(|&id| match &s.node(id).kind {
                    NodeKind::Shape(sh) => materials.contains(&(sh.material.0 as usize)),
                    _ => false,
                })
                .map(|id| node_label(s, id))
                .collect();
            let (source, url) = match &image.source {
                ImageSource::Inline => ("inline", Json::Null),
                ImageSource::File { url, .. } => ("file", json!(url)),
            };
            json!({
                "name": image.name,
                "source": source,
                "url": url,
                "width": image.width(),
                "height": image.height(),
                "components": image.components(),
                "materials": material_names,
                "shapes": shapes,
            })
        })
        .collect()
}

/// Everything `info` reports, as JSON (the text form prints the same data).
pub fn describe(loaded: &format::Loaded) -> Json {
    let s = &loaded.scene;
    let mut shapes = 0usize;
    let mut triangles = 0usize;
    let mut lights = Vec::new();
    let mut cameras = Vec::new();
    for id in s.walk() {
        let n = s.node(id);
        match &n.kind {
            NodeKind::Shape(sh) => {
                shapes += 1;
                triangles += s
                    .meshes
                    .get(sh.mesh.0 as usize)
                    .map_or(0, |m| m.triangles.len());
            }
            NodeKind::Light(l) => lights.push(json!({
                "name": node_label(s, id),
                "kind": match l.kind {
                    LightKind::Directional => "directional",
                    LightKind::Point => "point",
                    LightKind::Spot { .. } => "spot",
                },
                "on": l.on,
                "intensity": short(l.intensity),
                "color": [short(l.color.x), short(l.color.y), short(l.color.z)],
            })),
            NodeKind::Camera(c) => {
                let (kind, size) = match c.kind {
                    CameraKind::Perspective { height_angle } => ("perspective", height_angle),
                    CameraKind::Orthographic { height } => ("orthographic", height),
                };
                let mut cam = json!({
                    "name": node_label(s, id),
                    "kind": kind,
                    "description": c.description,
                    "position": [short(c.position.x), short(c.position.y), short(c.position.z)],
                });
                let key = if kind == "perspective" {
                    "fieldOfView"
                } else {
                    "height"
                };
                cam[key] = json!(short(size));
                cameras.push(cam);
            }
            NodeKind::Group => {}
        }
    }
    let textures = describe_textures(s);
    let fps = s.settings.fps.max(1e-6);
    let tracks: Vec<Json> = s
        .animation
        .tracks
        .iter()
        .map(|t| {
            let frames = t.keys.frames();
            let first = frames.first().copied().unwrap_or(0.0);
            let last = frames.last().copied().unwrap_or(0.0);
            json!({
                "target": target_label(s, t),
                "keys": t.keys.len(),
                "start": short(first / fps),
                "end": short(last / fps),
                "loop": t.repeat == crate::anim::Repeat::Loop,
            })
        })
        .collect();
    json!({
        "format": format_name(s.format),
        "nodes": s.nodes.len(),
        "shapes": shapes,
        "meshes": s.meshes.len(),
        "materials": s.materials.len(),
        "triangles": triangles,
        "lights": lights,
        "cameras": cameras,
        "textures": textures,
        "fps": short(s.settings.fps),
        "duration": short(s.duration_seconds()),
        "animations": clips_json(s),
        "morphs": super::info_deform::morphs_json(s),
        "skins": super::info_deform::skins_json(s),
        "animation": s.clips.active(),
        "tracks": tracks,
        "info": s.info,
        "warnings": loaded.warnings,
    })
}

/// Every clip: name, length and track count, the playing one marked.
fn clips_json(s: &Scene) -> Json {
    let fps = s.settings.fps.max(1e-6);
    s.clip_refs()
        .iter()
        .map(|c| {
            json!({
                "index": c.index,
                "name": c.name,
                "duration": short(c.duration / fps),
                "tracks": c.animation.tracks.len(),
                "playing": c.playing,
            })
        })
        .collect()
}

fn print_text(path: &std::path::Path, d: &Json) {
    let n = |k: &str| d[k].as_u64().unwrap_or(0);
    println!("file:       {}", path.display());
    println!("format:     {}", d["format"].as_str().unwrap_or("?"));
    println!(
        "nodes:      {}   shapes: {}   meshes: {}   materials: {}   triangles: {}",
        n("nodes"),
        n("shapes"),
        n("meshes"),
        n("materials"),
        n("triangles")
    );
    let list = |k: &str| d[k].as_array().cloned().unwrap_or_default();
    let lights = list("lights");
    println!("lights:     {}", lights.len());
    for l in &lights {
        println!(
            "  {} ({}, intensity {}{})",
            l["name"].as_str().unwrap_or(""),
            l["kind"].as_str().unwrap_or(""),
            l["intensity"],
            if l["on"] == json!(false) { ", off" } else { "" }
        );
    }
    let cams = list("cameras");
    println!("cameras:    {}", cams.len());
    for c in &cams {
        let desc = c["description"].as_str().unwrap_or("");
        println!(
            "  {} ({}{})",
            c["name"].as_str().unwrap_or(""),
            c["kind"].as_str().unwrap_or(""),
            if desc.is_empty() {
                String::new()
            } else {
                format!(", \"{desc}\"")
            }
        );
    }
    let textures = list("textures");
    println!("textures:   {}", textures.len());
    for t in &textures {
        let names = |k: &str| -> String {
            let v: Vec<&str> = t[k].as_array().map_or(Vec::new(), |a| {
                a.iter().filter_map(|x| x.as_str()).collect()
            });
            if v.is_empty() {
                "nothing".into()
            } else {
                v.join(", ")
            }
        };
        let kind = match t["components"].as_u64().unwrap_or(0) {
            1 => "grey",
            2 => "grey+alpha",
            3 => "RGB",
            _ => "RGBA",
        };
        let from = match t["url"].as_str() {
            Some(u) => format!("\"{u}\""),
            None => "inline".into(),
        };
        println!(
            "  {from}: {}x{} {kind}, shapes: {} (materials: {})",
            t["width"],
            t["height"],
            names("shapes"),
            names("materials")
        );
    }
    super::info_deform::print_text(d);
    let clips = list("animations");
    if clips.len() > 1 || clips.iter().any(|c| c["name"] != json!("")) {
        println!("animations: {}", clips.len());
        for c in &clips {
            println!(
                "  {}{} `{}`: {} tracks, {:.3} s",
                if c["playing"] == json!(true) {
                    "*"
                } else {
                    " "
                },
                c["index"],
                c["name"].as_str().unwrap_or(""),
                c["tracks"],
                c["duration"].as_f64().unwrap_or(0.0)
            );
        }
    }
    let tracks = list("tracks");
    println!(
        "tracks:     {}   ({} fps, {:.3} s)",
        tracks.len(),
        d["fps"],
        d["duration"].as_f64().unwrap_or(0.0)
    );
    for t in &tracks {
        println!(
            "  {}: {} keys, {:.3}..{:.3} s{}",
            t["target"].as_str().unwrap_or(""),
            t["keys"],
            t["start"].as_f64().unwrap_or(0.0),
            t["end"].as_f64().unwrap_or(0.0),
            if t["loop"] == json!(true) {
                ", loop"
            } else {
                ""
            }
        );
    }
    let warnings = list("warnings");
    println!("warnings:   {}", warnings.len());
    for w in &warnings {
        println!("  {}", w.as_str().unwrap_or(""));
    }
}

pub fn run(args: Args) -> i32 {
    let mut loaded = match args.clip.load(&args.file) {
        Ok(l) => l,
        Err(e) => {
            eprintln!("{e}");
            return 1;
        }
    };
    if let Err(e) = args.clip.apply(&mut loaded.scene) {
        eprintln!("animed info: {e}");
        return 2;
    }
    let d = describe(&loaded);
    if args.json {
        println!("{}", serde_json::to_string_pretty(&d).unwrap_or_default());
    } else {
        print_text(&args.file, &d);
    }
    // Only warnings about the file itself fail --strict; those about
    // animed's own limits or missing files are printed but not counted
    // (`format::warn_kind`).
    let breaks = loaded
        .warnings
        .iter()
        .filter(|w| crate::format::warn_kind::breaks_the_spec(w))
        .count();
    if args.strict && breaks > 0 {
        eprintln!(
            "animed info --strict: {breaks} warning(s) in {} ({} more about what animed does not support or could not find, not counted)",
            args.file.display(),
            loaded.warnings.len() - breaks
        );
        return 3;
    }
    0
}
