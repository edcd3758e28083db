//! `animed sample`: print the value of an animated property at given times.
//!
//! The value is read from the evaluated pose, so any animatable property can
//! be sampled, animated or not. Rotations print as VRML axis-angle
//! `[x, y, z, angle]`, colours as `[r, g, b]`, booleans as `[1]` / `[0]`.

use super::info::short;
use crate::anim::{evaluate, Pose, Property};
use crate::scene::{CameraKind, LightKind, MaterialId, NodeId, Scene};
use glam::{Quat, Vec3};
use serde_json::json;
use std::path::PathBuf;

/// Print the value of an animated property at given times.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The scene file.
    pub file: PathBuf,
    /// `NAME.property`, e.g. `Ball.translation`, `Lamp.color`,
    /// `BallMat.diffuseColor`, `Face.weights` (NAME: DEF name, or `#N` as
    /// `animed info` shows).
    #[arg(long, required_unless_present = "bounds", conflicts_with = "bounds")]
    pub target: Option<String>,
    /// Print every visible mesh's world-space axis-aligned bounds after
    /// deformation (morph targets, skinning) instead of a property.
    #[arg(long)]
    pub bounds: bool,
    /// Comma-separated times in seconds.
    #[arg(long, value_delimiter = ',', required = true)]
    pub times: Vec<f32>,
    /// Print a JSON array of `{"time": t, "value": [numbers]}`.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

/// What a `NAME.property` resolves to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Owner {
    Node(NodeId),
    Material(MaterialId),
}

/// Resolves `NAME.property` in `scene`.
pub fn resolve(scene: &Scene, target: &str) -> Result<(Owner, Property), String> {
    let (name, prop) = target
        .rsplit_once('.')
        .ok_or_else(|| format!("target '{target}' must be NAME.property"))?;
    let property = Property::parse(prop).ok_or_else(|| {
        let all: Vec<&str> = Property::ALL.iter().map(|p| p.name()).collect();
        format!("unknown property '{prop}' (one of: {})", all.join(", "))
    })?;
    let node = scene.find_node(name).or_else(|| {
        let i: u32 = name.strip_prefix('#')?.parse().ok()?;
        ((i as usize) < scene.nodes.len()).then_some(NodeId(i))
    });
    let material = scene.find_material(name).or_else(|| {
        let i: u32 = name.strip_prefix("material#")?.parse().ok()?;
        ((i as usize) < scene.materials.len()).then_some(MaterialId(i))
    });
    let owner = if property.owner() == "material" {
        material.map(Owner::Material)
    } else {
        node.map(Owner::Node)
    };
    let owner = owner.ok_or_else(|| {
        format!(
            "no {} named '{name}' (see `animed info`)",
            if property.owner() == "material" {
                "material"
            } else {
                "node"
            }
        )
    })?;
    // `Group.weights` on a multi-primitive node: its first morphed shape.
    let owner = match owner {
        Owner::Node(id) if property.owner() == "shape" && !has_morphs(scene, id) => scene
            .node(id)
            .children
            .iter()
            .copied()
            .find(|&c| has_morphs(scene, c))
            .map_or(owner, Owner::Node),
        o => o,
    };
    if let Owner::Node(id) = owner {
        let n = scene.node(id);
        let fits = match property.owner() {
            "light" => n.light().is_some(),
            "camera" => n.camera().is_some(),
            "shape" => has_morphs(scene, id),
            _ => true,
        };
        if !fits {
            return Err(match property.owner() {
                "shape" => format!("'{name}' is not a shape with morph targets"),
                o => format!("'{name}' is not a {o}"),
            });
        }
    }
    Ok((owner, property))
}

/// Whether node `id` is a shape whose mesh has morph targets.
pub fn has_morphs(scene: &Scene, id: NodeId) -> bool {
    match &scene.node(id).kind {
        crate::scene::NodeKind::Shape(s) => scene
            .meshes
            .get(s.mesh.0 as usize)
            .is_some_and(|m| m.morph.is_some()),
        _ => false,
    }
}

/// Axis-angle `[x, y, z, angle]` with the angle in [0, π].
pub fn axis_angle(q: Quat) -> Vec<f32> {
    let q = if q.w < 0.0 { -q } else { q };
    let (axis, angle) = q.normalize().to_axis_angle();
    if angle.abs() < 1e-7 || !axis.is_finite() {
        return vec![0.0, 0.0, 1.0, 0.0];
    }
    vec![axis.x, axis.y, axis.z, angle]
}

fn v3(v: Vec3) -> Vec<f32> {
    vec![v.x, v.y, v.z]
}

/// The property's value in `pose`, as numbers.
pub fn value(pose: &Pose, owner: Owner, p: Property) -> Option<Vec<f32>> {
    use Property as P;
    match owner {
        Owner::Material(m) => {
            let m = pose.materials.get(m.0 as usize)?;
            Some(match p {
                P::Diffuse => v3(m.diffuse),
                P::Emissive => v3(m.emissive),
                P::Specular => v3(m.specular),
                P::Transparency => vec![m.transparency],
                P::Shininess => vec![m.shininess],
                _ => return None,
            })
        }
        Owner::Node(id) => {
            let i = id.0 as usize;
            match p.owner() {
                "light" => {
                    let l = pose.light(id)?;
                    let spot = match l.kind {
                        LightKind::Spot {
                            beam_width,
                            cut_off_angle,
                            drop_off_rate,
                        } => Some((beam_width, cut_off_angle, drop_off_rate)),
                        _ => None,
                    };
                    Some(match p {
                        P::LightOn => vec![if l.on { 1.0 } else { 0.0 }],
                        P::LightIntensity => vec![l.intensity],
                        P::LightColor => v3(l.color),
                        P::LightLocation => v3(l.location),
                        P::LightDirection => v3(l.direction),
                        P::LightCutOff => vec![spot?.1],
                        P::LightBeamWidth => vec![spot?.0],
                        P::LightDropOff => vec![spot?.2],
                        _ => return None,
                    })
                }
                "shape" => pose.weights(id).map(|w| w.as_slice().to_vec()),
                "camera" => {
                    let c = pose.camera(id)?;
                    Some(match p {
                        P::CameraPosition => v3(c.position),
                        P::CameraOrientation => axis_angle(c.orientation),
                        P::CameraFov => match c.kind {
                            CameraKind::Perspective { height_angle } => vec![height_angle],
                            CameraKind::Orthographic { height } => vec![height],
                        },
                        _ => return None,
                    })
                }
                _ => {
                    let t = pose.transforms.get(i)?;
                    Some(match p {
                        P::Translation => v3(t.translation),
                        P::Rotation => axis_angle(t.rotation),
                        P::Scale => v3(t.scale),
                        P::Visibility => vec![if *pose.visible.get(i)? { 1.0 } else { 0.0 }],
                        _ => return None,
                    })
                }
            }
        }
    }
}

pub fn run(args: Args) -> i32 {
    let loaded = match args.clip.load(&args.file) {
        Ok(l) => l,
        Err(e) => {
            eprintln!("{e}");
            return 1;
        }
    };
    let mut loaded = loaded;
    if let Err(e) = args.clip.apply(&mut loaded.scene) {
        eprintln!("animed sample: {e}");
        return 2;
    }
    let scene = &loaded.scene;
    if args.bounds {
        return print_bounds(scene, &args.times, args.json);
    }
    let target = args.target.as_deref().unwrap_or_default();
    let (owner, property) = match resolve(scene, target) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("animed sample: {e}");
            return 2;
        }
    };
    let mut rows = Vec::new();
    for &t in &args.times {
        let pose = evaluate(scene, t);
        let Some(v) = value(&pose, owner, property) else {
            eprintln!("animed sample: {target} has no value here");
            return 2;
        };
        rows.push((t, v));
    }
    if args.json {
        let arr: Vec<_> = rows
            .iter()
            .map(|(t, v)| {
                json!({
                    "time": short(*t),
                    "value": v.iter().map(|x| short(*x)).collect::<Vec<_>>(),
                })
            })
            .collect();
        println!("{}", serde_json::Value::Array(arr));
    } else {
        for (t, v) in rows {
            let nums: Vec<String> = v.iter().map(|x| format!("{x}")).collect();
            println!("{t}\t{}", nums.join(" "));
        }
    }
    0
}

/// `--bounds`: per time, each visible shape's world-space bounds of its
/// drawn (deformed) vertices, named by the shape node (an unnamed shape —
/// one primitive of a multi-primitive node — by its nearest named ancestor,
/// else `#N`).
fn print_bounds(scene: &Scene, times: &[f32], json: bool) -> i32 {
    let mut rows = Vec::new();
    let mut pose = Pose::default();
    for &t in times {
        crate::anim::evaluate_into(scene, t, &mut pose);
        let meshes = crate::render::shape_bounds(scene, &pose);
        rows.push((t, meshes));
    }
    let name_of = |id: NodeId| -> String {
        let mut at = Some(id);
        while let Some(n) = at {
            let node = scene.node(n);
            if !node.name.is_empty() {
                return node.name.clone();
            }
            at = node.parent;
        }
        format!("#{}", id.0)
    };
    let nums = |v: Vec3| v.to_array().map(short).to_vec();
    if json {
        let arr: Vec<_> = rows
            .iter()
            .map(|(t, meshes)| {
                json!({
                    "time": short(*t),
                    "meshes": meshes.iter().map(|(id, lo, hi)| json!({
                        "name": name_of(*id),
                        "min": nums(*lo),
                        "max": nums(*hi),
                    })).collect::<Vec<_>>(),
                })
            })
            .collect();
        println!("{}", serde_json::Value::Array(arr));
    } else {
        for (t, meshes) in rows {
            for (id, lo, hi) in meshes {
                println!(
                    "{t}\t{}\t{} {} {}\t{} {} {}",
                    name_of(id),
                    lo.x,
                    lo.y,
                    lo.z,
                    hi.x,
                    hi.y,
                    hi.z
                );
            }
        }
    }
    0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resolves_nodes_materials_and_rejects_wrong_owners() {
        let s = crate::format::demo().unwrap().scene;
        let (o, p) = resolve(&s, "Ball.translation").unwrap();
        assert_eq!(o, Owner::Node(s.find_node("Ball").unwrap()));
        assert_eq!(p, Property::Translation);
        let (o, _) = resolve(&s, "BallMat.diffuseColor").unwrap();
        assert_eq!(o, Owner::Material(s.find_material("BallMat").unwrap()));
        assert!(resolve(&s, "Ball.intensity")
            .unwrap_err()
            .contains("not a light"));
        assert!(resolve(&s, "Nope.translation").is_err());
        assert!(resolve(&s, "Ball").is_err());
    }

    #[test]
    fn samples_the_demo_ball_at_its_keys() {
        let s = crate::format::demo().unwrap().scene;
        let (o, p) = resolve(&s, "Ball.translation").unwrap();
        // Key 0.25 of a 4 s cycle is at 1 s: (0, 1.6, 1.5).
        let v = value(&evaluate(&s, 1.0), o, p).unwrap();
        assert_eq!(v, vec![0.0, 1.6, 1.5]);
        let (o, p) = resolve(&s, "SpotLamp.intensity").unwrap();
        assert_eq!(value(&evaluate(&s, 2.0), o, p).unwrap(), vec![0.3]);
    }

    #[test]
    fn axis_angle_is_vrml_style() {
        assert_eq!(axis_angle(Quat::IDENTITY), vec![0.0, 0.0, 1.0, 0.0]);
        let a = axis_angle(-Quat::from_rotation_y(1.0));
        assert!(
            (a[1] - 1.0).abs() < 1e-6 && (a[3] - 1.0).abs() < 1e-6,
            "{a:?}"
        );
    }
}
