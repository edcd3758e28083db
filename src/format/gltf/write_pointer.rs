//! KHR_animation_pointer on the writing side: the channels plain glTF
//! cannot target (a node's TRS and weights are the only core paths) become
//! channels whose target is a JSON pointer into the document, the inverse
//! of `pointer_anim`'s reading:
//! * light colour → `/extensions/KHR_lights_punctual/lights/L/color`
//!   (sRGB → linear, as the static colour), intensity (with `on` folded in
//!   by `export::channels`) → `…/intensity` through the static mapping of
//!   `lights::punctual_from_light`, beam width and cut-off angle → a spot's
//!   `innerConeAngle` / `outerConeAngle`;
//! * a perspective camera's field of view → `/cameras/C/perspective/yfov`;
//! * a material's diffuse colour → `baseColorFactor` (alpha from its
//!   transparency at the same time), transparency alone → the alpha of
//!   `baseColorFactor`, emissive colour → `emissiveFactor` (or the base
//!   colour of an unlit material), through `material::pbr_from_phong`.
//!
//! Values are converted sample by sample (the channel is sampled within the
//! writer's tolerances), so a viewer interpolating linearly in linear light
//! is within those tolerances of animed's sRGB-space keys; animed's own
//! reader takes the exact keys from the key note instead. Specular colour
//! and shininess have no pointer target a core material has (they would
//! need KHR_materials_specular): they stay in the key note and the report
//! says so. Spec: KHR_animation_pointer (Khronos, 2024), "Animation
//! pointer" and its table of animatable properties.

use super::lights::punctual_from_light;
use super::material::{linear_exact, pbr_from_phong};
use crate::anim::{Property, TargetRef, Track, Value};
use crate::format::export::channels::Channel;
use crate::scene::{CameraKind, LightKind, Material, NodeKind, Scene};
use std::f32::consts::FRAC_PI_2;

/// The extension's name, as it appears in `extensionsUsed`.
pub const EXTENSION: &str = "KHR_animation_pointer";

/// A glTF material written for a scene material.
#[derive(Clone, Copy, Debug)]
pub struct WrittenMaterial {
    /// Index in the glTF `materials` array.
    pub index: usize,
    /// Vertex colours or a replacing texture carry the diffuse colour: the
    /// base colour factor is white and stays so.
    pub white: bool,
}

/// Where the writer put each light, camera and material, for pointers.
#[derive(Debug, Default)]
pub struct PointerSlots {
    /// Index in `KHR_lights_punctual.lights`, per scene node.
    pub light: Vec<Option<usize>>,
    /// Index in `cameras`, per scene node.
    pub camera: Vec<Option<usize>>,
    /// glTF materials written for each scene material.
    pub material: Vec<Vec<WrittenMaterial>>,
    /// The reference distance of the static light mapping.
    pub reference: f32,
}

/// One pointer channel's target and its values, `width` floats per sample.
#[derive(Clone, Debug, PartialEq)]
pub struct Pointed {
    pub pointer: String,
    pub width: usize,
    pub values: Vec<f32>,
}

/// The pointer channels that carry `ch`, or why there are none. `track`
/// finds the clip's track of a property of the same target (diffuse needs
/// the transparency at the same time, and transparency defers to it).
pub fn pointed<'a>(
    scene: &Scene,
    slots: &PointerSlots,
    ch: &Channel,
    samples: &[(f32, Value)],
    track: &dyn Fn(TargetRef, Property) -> Option<&'a Track>,
) -> Result<Vec<Pointed>, &'static str> {
    let scalar = |v: &Value| match v {
        Value::Scalar(s) => *s,
        _ => 0.0,
    };
    let vec3 = |v: &Value| match v {
        Value::Vec3(c) => *c,
        _ => glam::Vec3::ZERO,
    };
    let one = |pointer: String, width: usize, f: &dyn Fn(&Value) -> Vec<f32>| {
        let values = samples.iter().flat_map(|(_, v)| f(v)).collect();
        Ok(vec![Pointed {
            pointer,
            width,
            values,
        }])
    };
    match ch.of {
        TargetRef::Node(id) => {
            let i = id.0 as usize;
            match (&scene.node(id).kind, ch.property) {
                (NodeKind::Light(l), p) => {
                    let Some(li) = slots.light.get(i).copied().flatten() else {
                        return Err("the light was not written");
                    };
                    let at = format!("/extensions/KHR_lights_punctual/lights/{li}");
                    let spot = match l.kind {
                        LightKind::Spot {
                            beam_width,
                            cut_off_angle,
                            ..
                        } => Some((beam_width, cut_off_angle)),
                        _ => None,
                    };
                    match (p, spot) {
                        (Property::LightColor, _) => one(format!("{at}/color"), 3, &|v| {
                            linear_exact(vec3(v)).to_array().to_vec()
                        }),
                        (Property::LightIntensity, _) => one(format!("{at}/intensity"), 1, &|v| {
                            let mut lit = l.clone();
                            lit.on = true;
                            lit.intensity = scalar(v);
                            vec![punctual_from_light(&lit, slots.reference).intensity]
                        }),
                        (Property::LightBeamWidth, Some((_, cut))) => {
                            one(format!("{at}/spot/innerConeAngle"), 1, &|v| {
                                vec![scalar(v).min(cut).clamp(0.0, FRAC_PI_2)]
                            })
                        }
                        (Property::LightCutOff, Some(_)) => {
                            one(format!("{at}/spot/outerConeAngle"), 1, &|v| {
                                vec![scalar(v).clamp(0.0, FRAC_PI_2).max(1e-4)]
                            })
                        }
                        _ => Err("glTF has no such light property"),
                    }
                }
                (NodeKind::Camera(c), Property::CameraFov) => {
                    if !matches!(c.kind, CameraKind::Perspective { .. }) {
                        return Err("an orthographic camera has no field of view");
                    }
                    let Some(ci) = slots.camera.get(i).copied().flatten() else {
                        return Err("the camera was not written");
                    };
                    one(format!("/cameras/{ci}/perspective/yfov"), 1, &|v| {
                        vec![scalar(v).clamp(1e-4, std::f32::consts::PI - 1e-4)]
                    })
                }
                _ => Err("glTF has no pointer target for it"),
            }
        }
        TargetRef::Material(m) => {
            let Some(base) = scene.materials.get(m.0 as usize) else {
                return Err("no such material");
            };
            let written = slots.material.get(m.0 as usize).map_or(&[][..], |w| w);
            material(base, written, ch, samples, &|p| track(ch.of, p))
        }
    }
}

/// A pointer's floats for one sample (frame, value).
type ValueAt<'a> = dyn Fn(f32, &Value) -> Vec<f32> + 'a;

/// A material channel's pointers (module doc).
fn material<'a>(
    base: &Material,
    written: &[WrittenMaterial],
    ch: &Channel,
    samples: &[(f32, Value)],
    track: &dyn Fn(Property) -> Option<&'a Track>,
) -> Result<Vec<Pointed>, &'static str> {
    if written.is_empty() {
        return Err("no shape uses the material");
    }
    // An unlit material (`pbr_from_phong`) shows its emissive colour as
    // its base colour.
    let unlit = pbr_from_phong(base).unlit;
    let alpha = |t: f32| 1.0 - t.clamp(0.0, 1.0);
    let transparency_at = |f: f32| match track(Property::Transparency).map(|t| t.sample(f)) {
        Some(Value::Scalar(t)) => t,
        _ => base.transparency,
    };
    let rgba = |c: glam::Vec3, a: f32| {
        let c = linear_exact(c);
        vec![c.x, c.y, c.z, a]
    };
    let colour = |v: &Value| match v {
        Value::Vec3(c) => *c,
        _ => glam::Vec3::ZERO,
    };
    let (path, width, value): (&str, usize, Box<ValueAt>) = match ch.property {
        Property::Diffuse if unlit => return Err("an unlit material shows its emissive colour"),
        Property::Diffuse => (
            "pbrMetallicRoughness/baseColorFactor",
            4,
            Box::new(|f, v| rgba(colour(v), alpha(transparency_at(f)))),
        ),
        Property::Emissive if unlit => (
            "pbrMetallicRoughness/baseColorFactor",
            4,
            Box::new(|f, v| rgba(colour(v), alpha(transparency_at(f)))),
        ),
        Property::Emissive => (
            "emissiveFactor",
            3,
            Box::new(|_, v| linear_exact(colour(v)).to_array().to_vec()),
        ),
        Property::Transparency => {
            let drives = if unlit {
                Property::Emissive
            } else {
                Property::Diffuse
            };
            if track(drives).is_some() {
                return Err("written with the colour's channel");
            }
            let c = if unlit { base.emissive } else { base.diffuse };
            (
                "pbrMetallicRoughness/baseColorFactor",
                4,
                Box::new(move |_, v| {
                    let t = match v {
                        Value::Scalar(t) => *t,
                        _ => 0.0,
                    };
                    rgba(c, alpha(t))
                }),
            )
        }
        _ => return Err("a core glTF material has no such property"),
    };
    let values: Vec<f32> = samples.iter().flat_map(|(f, v)| value(*f, v)).collect();
    let out: Vec<Pointed> = written
        .iter()
        // A white base colour stays white (vertex colours or a texture
        // carry the diffuse colour); only its alpha may move.
        .filter(|w| width == 3 || !w.white || ch.property == Property::Transparency)
        .map(|w| {
            let mut values = values.clone();
            if w.white && width == 4 {
                for rgba in values.chunks_mut(4) {
                    rgba[..3].copy_from_slice(&[1.0; 3]);
                }
            }
            Pointed {
                pointer: format!("/materials/{}/{path}", w.index),
                width,
                values,
            }
        })
        .collect();
    if out.is_empty() {
        return Err("its shapes take their colour from vertex colours or a texture");
    }
    Ok(out)
}
