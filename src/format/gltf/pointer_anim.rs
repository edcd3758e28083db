//! KHR_animation_pointer: animation channels whose target is a JSON pointer
//! into the document instead of a node and one of four paths.
//!
//! The `gltf` crate (1.4) requires every channel to name a node and one of
//! translation/rotation/scale/weights, so a file using the extension would
//! not parse at all. [`take`] therefore rewrites the JSON before the crate
//! sees it: pointers at a node's TRS or weights become ordinary channels,
//! every other pointer channel is taken out and mapped here by [`add_tracks`]
//! onto what animed animates:
//! * `/extensions/KHR_lights_punctual/lights/L/color` → the light's colour
//!   (linear → sRGB, like its static colour);
//! * `…/lights/L/intensity` → intensity, in the units of `lights.rs`:
//!   directional min(E/π, 1); point and spot lights keep the inverse-square
//!   falloff with the largest intensity the file reaches as the reference
//!   (attenuation π/I_max, intensity I/I_max), so brightness over time is
//!   exactly I/(π·d²) as in the static mapping;
//! * `…/spot/innerConeAngle` and `…/spot/outerConeAngle` → beam width and
//!   cut-off angle;
//! * `/cameras/C/perspective/yfov` → the camera's field of view (its height
//!   angle, as read statically);
//! * `/materials/M/pbrMetallicRoughness/baseColorFactor` → diffuse colour
//!   through the static Phong mapping (and transparency for BLEND
//!   materials); `/materials/M/emissiveFactor` → emissive colour.
//!
//! Colours are converted key by key and interpolated in animed's (sRGB)
//! space between keys; CUBICSPLINE samplers are sampled like the node
//! channels. Anything else is a warning naming the pointer.

use super::anim::{cubic_rows, frames_of, sampler_values};
use super::container::{json_error, GltfError, Result};
use super::lights::{animed_light, intensity_from_punctual};
use super::material::{srgb_from_linear, Pbr};
use super::pointer::pointer;
use crate::anim::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track};
use crate::scene::{Clip, LightKind, MaterialId, NodeId, NodeKind, Scene};
use glam::Vec3;
use gltf::animation::Interpolation;
use serde_json::Value as Json;
use std::collections::HashMap;
use std::f32::consts::PI;

/// The extension's name, as it appears in `extensionsUsed`.
pub const EXTENSION: &str = "KHR_animation_pointer";

/// A channel [`take`] moved out of the document.
#[derive(Clone, Debug, PartialEq)]
pub struct PointerChannel {
    pub animation: usize,
    /// Its index in the file (for messages; later channels moved down).
    pub channel: usize,
    pub sampler: usize,
    pub pointer: String,
}

/// The JSON with pointer channels rewritten or taken out, and the ones
/// taken out. `None` when the document has no pointer channel (the common
/// case costs one byte search, no second parse).
pub fn take(json: &[u8]) -> Result<Option<(Vec<u8>, Vec<PointerChannel>)>> {
    if !contains(json, EXTENSION.as_bytes()) {
        return Ok(None);
    }
    let mut root: Json = serde_json::from_slice(json).map_err(|e| json_error(&e))?;
    let mut taken = Vec::new();
    let Some(animations) = root.get_mut("animations").and_then(Json::as_array_mut) else {
        return Ok(None);
    };
    for (a, anim) in animations.iter_mut().enumerate() {
        let Some(channels) = anim.get_mut("channels").and_then(Json::as_array_mut) else {
            continue;
        };
        let mut kept = Vec::with_capacity(channels.len());
        for (c, mut ch) in std::mem::take(channels).into_iter().enumerate() {
            let at = pointer(&[&"animations", &a, &"channels", &c, &"target"]);
            let Some(target) = ch.get_mut("target") else {
                kept.push(ch);
                continue;
            };
            if target.get("path").and_then(Json::as_str) != Some("pointer") {
                kept.push(ch);
                continue;
            }
            let p = target
                .pointer(&format!("/extensions/{EXTENSION}/pointer"))
                .and_then(Json::as_str)
                .ok_or_else(|| {
                    GltfError::at(
                        format!("{at}/extensions/{EXTENSION}/pointer"),
                        "a channel with path \"pointer\" needs the pointer string",
                    )
                })?
                .to_string();
            if let Some((node, path)) = node_path(&p) {
                target["node"] = Json::from(node);
                target["path"] = Json::from(path);
                kept.push(ch);
                continue;
            }
            let sampler = ch.get("sampler").and_then(Json::as_u64).ok_or_else(|| {
                GltfError::at(
                    pointer(&[&"animations", &a, &"channels", &c, &"sampler"]),
                    "required property missing",
                )
            })?;
            let sampler = usize::try_from(sampler).unwrap_or(usize::MAX);
            taken.push(PointerChannel {
                animation: a,
                channel: c,
                sampler,
                pointer: p,
            });
        }
        *channels = kept;
    }
    let bytes = serde_json::to_vec(&root)
        .map_err(|e| GltfError::whole(format!("cannot re-encode the JSON: {e}")))?;
    Ok(Some((bytes, taken)))
}

fn contains(hay: &[u8], needle: &[u8]) -> bool {
    hay.windows(needle.len()).any(|w| w == needle)
}

/// `/nodes/N/translation` and the like: an ordinary channel in disguise.
fn node_path(p: &str) -> Option<(u64, &'static str)> {
    let rest = p.strip_prefix("/nodes/")?;
    let (n, path) = rest.split_once('/')?;
    let n: u64 = n.parse().ok()?;
    let path = match path {
        "translation" => "translation",
        "rotation" => "rotation",
        "scale" => "scale",
        "weights" => "weights",
        _ => return None,
    };
    Some((n, path))
}

/// What a pointer names, in animed's terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pointed {
    LightColor(usize),
    LightIntensity(usize),
    LightInner(usize),
    LightOuter(usize),
    CameraYfov(usize),
    BaseColor(usize),
    Emissive(usize),
}

impl Pointed {
    pub fn parse(p: &str) -> Option<Pointed> {
        let parts: Vec<&str> = p.strip_prefix('/')?.split('/').collect();
        let index = |s: &str| s.parse::<usize>().ok();
        Some(match parts.as_slice() {
            ["extensions", "KHR_lights_punctual", "lights", l, rest @ ..] => {
                let l = index(l)?;
                match rest {
                    ["color"] => Pointed::LightColor(l),
                    ["intensity"] => Pointed::LightIntensity(l),
                    ["spot", "innerConeAngle"] => Pointed::LightInner(l),
                    ["spot", "outerConeAngle"] => Pointed::LightOuter(l),
                    _ => return None,
                }
            }
            ["cameras", c, "perspective", "yfov"] => Pointed::CameraYfov(index(c)?),
            ["materials", m, "pbrMetallicRoughness", "baseColorFactor"] => {
                Pointed::BaseColor(index(m)?)
            }
            ["materials", m, "emissiveFactor"] => Pointed::Emissive(index(m)?),
            _ => return None,
        })
    }

    /// Components per value.
    fn width(self) -> usize {
        match self {
            Pointed::LightColor(_) | Pointed::Emissive(_) => 3,
            Pointed::BaseColor(_) => 4,
            _ => 1,
        }
    }
}

/// Where glTF lights, cameras and materials went in the scene, and the
/// frame rate key times become frames at.
pub struct Targets<'a> {
    pub fps: f32,
    /// (glTF light index, animed node holding that light).
    pub lights: &'a [(usize, NodeId)],
    /// (glTF camera index, animed node holding that camera).
    pub cameras: &'a [(usize, NodeId)],
    /// glTF material index → animed material.
    pub materials: &'a HashMap<Option<usize>, MaterialId>,
}

/// Adds the tracks of the `taken` channels to `clips` (one per glTF
/// animation, in order), lengthening a clip its pointer channels outlast.
pub fn add_tracks(
    doc: &gltf::Document,
    buffers: &super::container::Buffers,
    taken: &[PointerChannel],
    targets: &Targets,
    scene: &mut Scene,
    clips: &mut [Clip],
    warnings: &mut Vec<String>,
) -> Result<()> {
    let animations: Vec<gltf::Animation> = doc.animations().collect();
    for ch in taken {
        let at = pointer(&[&"animations", &ch.animation, &"channels", &ch.channel]);
        let (Some(anim), Some(clip)) = (animations.get(ch.animation), clips.get_mut(ch.animation))
        else {
            continue;
        };
        let Some(sampler) = anim.samplers().nth(ch.sampler) else {
            return Err(GltfError::at(
                format!("{at}/sampler"),
                "index out of bounds",
            ));
        };
        let Some(what) = Pointed::parse(&ch.pointer) else {
            warnings.push(format!(
                "{at}: {EXTENSION} pointer {} is not something animed animates; the channel is skipped",
                ch.pointer
            ));
            continue;
        };
        let sp = pointer(&[&"animations", &ch.animation, &"samplers", &ch.sampler]);
        let (times, values) = sampler_values(&sampler, buffers, &sp, what.width())?;
        let (rows, interp) = match sampler.interpolation() {
            Interpolation::CubicSpline => {
                (cubic_rows(&times, &values, what.width()), Interp::Linear)
            }
            i => (
                times
                    .iter()
                    .copied()
                    .zip(values.chunks_exact(what.width()).map(<[f32]>::to_vec))
                    .collect(),
                if i == Interpolation::Step {
                    Interp::Step
                } else {
                    Interp::Linear
                },
            ),
        };
        let frames = frames_of(rows.iter().map(|(t, _)| *t), targets.fps);
        let tracks = map_channel(doc, what, &frames, &rows, interp, targets, scene);
        if tracks.is_empty() {
            warnings.push(format!(
                "{at}: {} names nothing in the loaded scene; the channel is skipped",
                ch.pointer
            ));
        }
        for track in tracks {
            let track = track.map_err(|e| GltfError::at(sp.clone(), e))?;
            clip.animation.tracks.push(track);
        }
        if let Some(&last) = frames.last() {
            clip.duration = clip.duration.max(last);
        }
    }
    Ok(())
}

type Rows = [(f32, Vec<f32>)];

fn map_channel(
    doc: &gltf::Document,
    what: Pointed,
    frames: &[f32],
    rows: &Rows,
    interp: Interp,
    targets: &Targets,
    scene: &mut Scene,
) -> Vec<std::result::Result<Track, String>> {
    let scalar = |f: &dyn Fn(f32) -> f32| {
        Keys::Scalar(
            frames
                .iter()
                .zip(rows)
                .map(|(&fr, (_, v))| Key::new(fr, f(v[0])).with_interp(interp))
                .collect(),
        )
    };
    let color = |f: &dyn Fn(&[f32]) -> Vec3| {
        Keys::Vec3(
            frames
                .iter()
                .zip(rows)
                .map(|(&fr, (_, v))| Key::new(fr, f(v)).with_interp(interp))
                .collect(),
        )
    };
    let track = |of: TargetRef, property: Property, keys: Keys| {
        Track::new(Target { of, property }, Repeat::Constant, keys).map_err(|e| e.to_string())
    };
    let nodes_of = |list: &[(usize, NodeId)], i: usize| -> Vec<NodeId> {
        list.iter()
            .filter(|(k, _)| *k == i)
            .map(|(_, id)| *id)
            .collect()
    };
    let mut out = Vec::new();
    match what {
        Pointed::LightColor(l) => {
            for id in nodes_of(targets.lights, l) {
                let keys = color(&|v| srgb_from_linear(Vec3::new(v[0], v[1], v[2])));
                out.push(track(TargetRef::Node(id), Property::LightColor, keys));
            }
        }
        Pointed::LightIntensity(l) => {
            for id in nodes_of(targets.lights, l) {
                let NodeKind::Light(light) = &mut scene.node_mut(id).kind else {
                    continue;
                };
                let ours = doc
                    .lights()
                    .and_then(|mut ls| ls.nth(l))
                    .and_then(|g| animed_light(&g));
                let keys = if matches!(light.kind, LightKind::Directional) {
                    scalar(&|e| (e.max(0.0) / PI).min(1.0))
                } else if let Some((mine, reference)) = ours {
                    // animed's own light keeps its attenuation: invert the
                    // writer's mapping instead of re-deriving one.
                    scalar(&|e| intensity_from_punctual(&mine, e, reference))
                } else {
                    let static_i = doc
                        .lights()
                        .and_then(|mut ls| ls.nth(l))
                        .map_or(0.0, |g| g.intensity().max(0.0));
                    let reference = rows
                        .iter()
                        .map(|(_, v)| v[0])
                        .fold(static_i, f32::max)
                        .max(1e-6);
                    light.attenuation = Vec3::new(0.0, 0.0, PI / reference);
                    light.intensity = static_i / reference;
                    scalar(&|i| i.max(0.0) / reference)
                };
                out.push(track(TargetRef::Node(id), Property::LightIntensity, keys));
            }
        }
        Pointed::LightInner(l) | Pointed::LightOuter(l) => {
            let property = if matches!(what, Pointed::LightInner(_)) {
                Property::LightBeamWidth
            } else {
                Property::LightCutOff
            };
            for id in nodes_of(targets.lights, l) {
                out.push(track(TargetRef::Node(id), property, scalar(&|a| a)));
            }
        }
        Pointed::CameraYfov(c) => {
            for id in nodes_of(targets.cameras, c) {
                out.push(track(
                    TargetRef::Node(id),
                    Property::CameraFov,
                    scalar(&|a| a),
                ));
            }
        }
        Pointed::BaseColor(m) | Pointed::Emissive(m) => {
            let (Some(&mid), Some(g)) = (targets.materials.get(&Some(m)), doc.materials().nth(m))
            else {
                return out;
            };
            let pbr = Pbr::from_gltf(&g);
            let of = TargetRef::Material(mid);
            if let Pointed::Emissive(_) = what {
                let strength = g.emissive_strength().unwrap_or(1.0);
                let keys = color(&|v| srgb_from_linear(Vec3::new(v[0], v[1], v[2]) * strength));
                out.push(track(of, Property::Emissive, keys));
                return out;
            }
            let metallic = pbr.metallic.clamp(0.0, 1.0);
            let (property, factor) = if pbr.unlit {
                (Property::Emissive, 1.0)
            } else {
                (Property::Diffuse, 1.0 - metallic / 2.0)
            };
            let keys = color(&|v| srgb_from_linear(Vec3::new(v[0], v[1], v[2])) * factor);
            out.push(track(of, property, keys));
            if pbr.alpha_mode == gltf::material::AlphaMode::Blend {
                let keys = Keys::Scalar(
                    frames
                        .iter()
                        .zip(rows)
                        .map(|(&fr, (_, v))| {
                            Key::new(fr, 1.0 - v[3].clamp(0.0, 1.0)).with_interp(interp)
                        })
                        .collect(),
                );
                out.push(track(of, Property::Transparency, keys));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pointers_parse_into_what_animed_animates() {
        use Pointed as P;
        let cases = [
            (
                "/extensions/KHR_lights_punctual/lights/2/color",
                Some(P::LightColor(2)),
            ),
            (
                "/extensions/KHR_lights_punctual/lights/0/intensity",
                Some(P::LightIntensity(0)),
            ),
            (
                "/extensions/KHR_lights_punctual/lights/1/spot/outerConeAngle",
                Some(P::LightOuter(1)),
            ),
            ("/cameras/3/perspective/yfov", Some(P::CameraYfov(3))),
            (
                "/materials/0/pbrMetallicRoughness/baseColorFactor",
                Some(P::BaseColor(0)),
            ),
            ("/materials/4/emissiveFactor", Some(P::Emissive(4))),
            ("/materials/0/alphaCutoff", None),
            ("/cameras/x/perspective/yfov", None),
            ("cameras/0/perspective/yfov", None),
        ];
        for (p, want) in cases {
            assert_eq!(Pointed::parse(p), want, "{p}");
        }
    }

    #[test]
    fn node_pointers_become_ordinary_channels_and_others_are_taken() {
        let json = br#"{"asset":{"version":"2.0"},"extensionsUsed":["KHR_animation_pointer"],
          "animations":[{"samplers":[{"input":0,"output":1},{"input":0,"output":2}],"channels":[
            {"sampler":0,"target":{"path":"pointer","extensions":{"KHR_animation_pointer":{"pointer":"/nodes/3/rotation"}}}},
            {"sampler":1,"target":{"path":"pointer","extensions":{"KHR_animation_pointer":{"pointer":"/cameras/0/perspective/yfov"}}}},
            {"sampler":0,"target":{"node":1,"path":"scale"}}]}]}"#;
        let (out, taken) = take(json).unwrap().expect("rewritten");
        let v: Json = serde_json::from_slice(&out).unwrap();
        let chans = v["animations"][0]["channels"].as_array().unwrap();
        assert_eq!(chans.len(), 2);
        assert_eq!(chans[0]["target"]["node"], 3);
        assert_eq!(chans[0]["target"]["path"], "rotation");
        assert_eq!(chans[1]["target"]["path"], "scale");
        assert_eq!(
            taken,
            vec![PointerChannel {
                animation: 0,
                channel: 1,
                sampler: 1,
                pointer: "/cameras/0/perspective/yfov".into()
            }]
        );
        assert!(take(br#"{"asset":{"version":"2.0"}}"#).unwrap().is_none());
        let bad = br#"{"animations":[{"channels":[{"sampler":0,"target":{"path":"pointer"}}]}],"x":"KHR_animation_pointer"}"#;
        let e = take(bad).unwrap_err().to_string();
        assert!(
            e.contains("/animations/0/channels/0/target/extensions/KHR_animation_pointer/pointer"),
            "{e}"
        );
    }
}
