//! Clips → glTF animations, exactly where glTF can say the same curve:
//! * vector tracks (translation, scale, camera position, light location)
//!   whose keys are all step → STEP, all linear → LINEAR, linear and TCB
//!   mixed → CUBICSPLINE with the Kochanek-Bartels tangents of
//!   `anim::hermite` (Appendix C's in/out tangents are per second: the
//!   per-segment tangent divided by the segment's length in seconds), so
//!   the file plays the authored curve with no sampling at all;
//! * rotation tracks all step → STEP, all slerp → LINEAR (both sides take
//!   the short way per segment);
//! * everything else (squad, eases, looping tracks, visibility folded into
//!   scale, keys before time 0) is sampled adaptively within the writer
//!   tolerances by `export::channels`, and reported;
//! * light colour and intensity, spot cones, a camera's field of view and
//!   material colours go out as KHR_animation_pointer channels
//!   (`write_pointer`), sampled; specular colour and shininess, which core
//!   materials lack, live in the key note only (and the report says so);
//! * a channel that loops with its own period (`Channel::period`) is
//!   unrolled over the clip: glTF has no per-channel clock, and a file
//!   holding one period would stop there in every other player.

use super::bin::Bin;
use super::write_pointer::{pointed, PointerSlots, EXTENSION};
use crate::anim::hermite::{kb_in, kb_out, Tcb};
use crate::anim::repeat::{after, before};
use crate::anim::{Interp, Key, Keys, Property, Repeat, TargetRef, Track, Value, Weights};
use crate::format::export::channels::{channels, Channel};
use crate::format::export::sampling::{per_frame_keys, Tolerances};
use crate::format::export::{ChannelReport, WriteReport};
use crate::scene::{ClipRef, Scene};
use glam::{Quat, Vec3};
use serde_json::{json, Value as Json};

/// Where a node's animated properties go in the glTF node list.
pub struct NodeSlots {
    /// glTF node written for each scene node (`None`: not written).
    pub node: Vec<Option<usize>>,
    /// glTF node that carries a light's or camera's own placement.
    pub part: Vec<Option<usize>>,
    /// The node is written as a matrix (its TRS cannot be animated).
    pub matrix: Vec<bool>,
    /// The node is a shape whose mesh has morph targets (its `weights`
    /// can be animated).
    pub morphed: Vec<bool>,
}

fn tcb<V>(k: &Key<V>) -> Tcb {
    Tcb {
        tension: k.tension,
        continuity: k.continuity,
        bias: k.bias,
    }
}

/// glTF target (node, path) of a property, if glTF can animate it.
fn slot(slots: &NodeSlots, of: TargetRef, p: Property) -> Option<(usize, &'static str)> {
    let TargetRef::Node(id) = of else { return None };
    let i = id.0 as usize;
    match p {
        Property::Translation | Property::Rotation | Property::Scale => {
            if *slots.matrix.get(i)? {
                return None;
            }
            let path = match p {
                Property::Translation => "translation",
                Property::Rotation => "rotation",
                _ => "scale",
            };
            Some((slots.node.get(i).copied()??, path))
        }
        Property::CameraPosition | Property::LightLocation => {
            Some((slots.part.get(i).copied()??, "translation"))
        }
        Property::CameraOrientation => Some((slots.part.get(i).copied()??, "rotation")),
        Property::MorphWeights if *slots.morphed.get(i)? => {
            Some((slots.node.get(i).copied()??, "weights"))
        }
        _ => None,
    }
}

/// A written sampler: times (s), flat values, interpolation.
struct Written {
    times: Vec<f32>,
    values: Vec<f32>,
    width: usize,
    interp: &'static str,
    keys: usize,
}

fn no_ease<V>(k: &[Key<V>]) -> bool {
    k.iter().all(|k| k.ease_in == 0.0 && k.ease_out == 0.0)
}

/// The exact form of a track, if it has one (module doc).
fn exact(track: &Track, fps: f32) -> Option<Written> {
    if track.repeat != Repeat::Constant {
        return None;
    }
    let sec = |f: f32| f / fps;
    match &track.keys {
        Keys::Vec3(k) if no_ease(k) && k.first()?.frame >= 0.0 => {
            let segs = &k[..k.len() - 1];
            let times: Vec<f32> = k.iter().map(|k| sec(k.frame)).collect();
            let flat = |v: &mut Vec<f32>, x: Vec3| v.extend_from_slice(&x.to_array());
            if segs.iter().all(|k| k.interp == Interp::Step) && k.len() > 1
                || segs.iter().all(|k| k.interp == Interp::Linear)
            {
                let mut values = Vec::with_capacity(k.len() * 3);
                k.iter().for_each(|k| flat(&mut values, k.value));
                let interp = if segs.iter().all(|k| k.interp == Interp::Linear) {
                    "LINEAR"
                } else {
                    "STEP"
                };
                return Some(Written {
                    times,
                    values,
                    width: 3,
                    interp,
                    keys: k.len(),
                });
            }
            if segs.iter().any(|k| k.interp == Interp::Step) {
                return None;
            }
            // CUBICSPLINE: per key [in-tangent, value, out-tangent] per second.
            let mut tin = vec![Vec3::ZERO; k.len()];
            let mut tout = vec![Vec3::ZERO; k.len()];
            for i in 0..segs.len() {
                let (k0, k1) = (&k[i], &k[i + 1]);
                let chord = k1.value - k0.value;
                let len = k1.frame - k0.frame;
                let (m0, m1) = if k0.interp == Interp::Linear {
                    (chord, chord)
                } else {
                    let prev = before(k, i, Repeat::Constant)
                        .map(|(j, f)| (k0.value - k[j].value, k0.frame - f));
                    let next = after(k, i + 1, Repeat::Constant)
                        .map(|(j, f)| (k[j].value - k1.value, f - k1.frame));
                    (
                        kb_out(prev, (chord, len), tcb(k0)),
                        kb_in((chord, len), next, tcb(k1)),
                    )
                };
                let dt = sec(len);
                tout[i] = m0 / dt;
                tin[i + 1] = m1 / dt;
            }
            let mut values = Vec::with_capacity(k.len() * 9);
            for (i, key) in k.iter().enumerate() {
                flat(&mut values, tin[i]);
                flat(&mut values, key.value);
                flat(&mut values, tout[i]);
            }
            Some(Written {
                times,
                values,
                width: 3,
                interp: "CUBICSPLINE",
                keys: k.len(),
            })
        }
        Keys::Weights(k) if no_ease(k) && k.first()?.frame >= 0.0 => {
            let width = k.iter().map(|k| k.value.len()).max()?;
            exact_weights(k, width, fps)
        }
        Keys::Rotation(k) if no_ease(k) && k.first()?.frame >= 0.0 => {
            let segs = &k[..k.len() - 1];
            let interp = if segs.iter().all(|k| k.interp == Interp::Linear) {
                "LINEAR"
            } else if segs.iter().all(|k| k.interp == Interp::Step) {
                "STEP"
            } else {
                return None;
            };
            let times = k.iter().map(|k| sec(k.frame)).collect();
            let values = k.iter().flat_map(|k| k.value.to_array()).collect();
            Some(Written {
                times,
                values,
                width: 4,
                interp,
                keys: k.len(),
            })
        }
        _ => None,
    }
}

/// Weights keys as STEP, LINEAR or CUBICSPLINE (Kochanek-Bartels tangents
/// per component, as for vectors above), `width` numbers per value.
fn exact_weights(k: &[Key<Weights>], width: usize, fps: f32) -> Option<Written> {
    let sec = |f: f32| f / fps;
    let segs = &k[..k.len() - 1];
    let times: Vec<f32> = k.iter().map(|k| sec(k.frame)).collect();
    let flat = |v: &mut Vec<f32>, w: &Weights| {
        let s = w.as_slice();
        v.extend((0..width).map(|c| s.get(c).copied().unwrap_or(0.0)));
    };
    let all = |i: Interp| segs.iter().all(|k| k.interp == i);
    if all(Interp::Step) && k.len() > 1 || all(Interp::Linear) {
        let mut values = Vec::with_capacity(k.len() * width);
        k.iter().for_each(|k| flat(&mut values, &k.value));
        return Some(Written {
            times,
            values,
            width,
            interp: if all(Interp::Linear) {
                "LINEAR"
            } else {
                "STEP"
            },
            keys: k.len(),
        });
    }
    if segs.iter().any(|k| k.interp == Interp::Step) {
        return None;
    }
    let zero = Weights::zeros(width);
    let mut tin = vec![zero; k.len()];
    let mut tout = vec![zero; k.len()];
    for i in 0..segs.len() {
        let (k0, k1) = (&k[i], &k[i + 1]);
        let chord = k1.value - k0.value;
        let len = k1.frame - k0.frame;
        let (m0, m1) = if k0.interp == Interp::Linear {
            (chord, chord)
        } else {
            let prev =
                before(k, i, Repeat::Constant).map(|(j, f)| (k0.value - k[j].value, k0.frame - f));
            let next = after(k, i + 1, Repeat::Constant)
                .map(|(j, f)| (k[j].value - k1.value, f - k1.frame));
            (
                kb_out(prev, (chord, len), tcb(k0)),
                kb_in((chord, len), next, tcb(k1)),
            )
        };
        let dt = sec(len);
        tout[i] = m0 * (1.0 / dt);
        tin[i + 1] = m1 * (1.0 / dt);
    }
    let mut values = Vec::with_capacity(k.len() * 3 * width);
    for (i, key) in k.iter().enumerate() {
        flat(&mut values, &tin[i]);
        flat(&mut values, &key.value);
        flat(&mut values, &tout[i]);
    }
    Some(Written {
        times,
        values,
        width,
        interp: "CUBICSPLINE",
        keys: k.len(),
    })
}

/// A channel's samples over the whole clip: one period repeated when it
/// loops on a clock of its own (module doc), else as sampled. A repeat
/// starts where the last one ended; its first sample is dropped when it
/// equals that end (a smooth loop), kept when it jumps.
fn unrolled(ch: &Channel, duration: f32) -> Vec<(f32, Value)> {
    let Some(p) = ch.period.filter(|p| *p > 0.0) else {
        return ch.samples.clone();
    };
    let repeats = (duration / p).round().max(1.0) as usize;
    let mut out: Vec<(f32, Value)> = Vec::with_capacity(ch.samples.len() * repeats);
    for k in 0..repeats {
        let shift = k as f32 * p;
        for (j, &(f, v)) in ch.samples.iter().enumerate() {
            if j == 0 && k > 0 && out.last().is_some_and(|&(_, last)| last == v) {
                continue;
            }
            out.push((f + shift, v));
        }
    }
    out
}

/// The seconds of `samples` for a sampler's input: jumps (two samples at
/// one time) get the next representable time, as glTF times must increase.
fn seconds(samples: &[(f32, Value)], fps: f32) -> Vec<f32> {
    let mut times: Vec<f32> = Vec::with_capacity(samples.len());
    for &(f, _) in samples {
        let mut t = (f / fps).max(0.0);
        if let Some(&last) = times.last() {
            if t <= last {
                t = f32::from_bits(last.to_bits() + 1);
            }
        }
        times.push(t);
    }
    times
}

/// A sampled channel as LINEAR keys.
fn sampled(samples: &[(f32, Value)], fps: f32, rotation: bool) -> Written {
    let times = seconds(samples, fps);
    let mut values = Vec::new();
    for &(_, v) in samples {
        match v {
            Value::Vec3(v) if rotation => {
                // A direction: the rotation taking −z onto it.
                let q = Quat::from_rotation_arc(Vec3::NEG_Z, v.normalize_or(Vec3::NEG_Z));
                values.extend_from_slice(&q.to_array());
            }
            Value::Vec3(v) => values.extend_from_slice(&v.to_array()),
            Value::Rotation(q) => values.extend_from_slice(&q.to_array()),
            Value::Scalar(s) => values.extend_from_slice(&[s, s, s]),
            Value::Weights(w) => values.extend_from_slice(w.as_slice()),
            Value::Bool(_) => values.extend_from_slice(&[0.0, 0.0, 0.0]),
        }
    }
    let width = match samples.first() {
        Some((_, Value::Weights(w))) => w.len().max(1),
        _ if rotation => 4,
        _ => 3,
    };
    Written {
        keys: times.len(),
        times,
        values,
        width,
        interp: "LINEAR",
    }
}

/// `{"KHR_animation_pointer": {"pointer": …}}` of a channel target.
fn pointer_ext(pointer: &str) -> Json {
    let mut ext = serde_json::Map::new();
    ext.insert(EXTENSION.into(), json!({ "pointer": pointer }));
    Json::Object(ext)
}

/// The animations of every clip, and the report lines; also the JSON
/// pointers the KHR_animation_pointer channels target (empty: the
/// extension is not used).
#[allow(clippy::too_many_arguments)]
pub fn animations(
    scene: &Scene,
    clips: &[ClipRef],
    slots: &NodeSlots,
    pointers: &PointerSlots,
    names: &[String],
    tol: &Tolerances,
    bin: &mut Bin,
    report: &mut WriteReport,
) -> (Vec<Json>, Vec<String>) {
    let fps = scene.settings.fps.max(1e-6);
    let mut out = Vec::new();
    let mut targets = Vec::new();
    for clip in clips {
        // A scene holding just this clip, without meshes, for the sampler.
        let one = Scene {
            nodes: scene.nodes.clone(),
            roots: scene.roots.clone(),
            materials: scene.materials.clone(),
            settings: crate::scene::Settings {
                duration: clip.duration,
                ..scene.settings.clone()
            },
            animation: clip.animation.clone(),
            ..Scene::default()
        };
        let mut samplers = Vec::new();
        let mut chans = Vec::new();
        for ch in channels(&one, tol) {
            let label = match ch.of {
                TargetRef::Node(id) => names.get(id.0 as usize).cloned().unwrap_or_default(),
                TargetRef::Material(m) => scene
                    .materials
                    .get(m.0 as usize)
                    .map(|m| m.name.clone())
                    .unwrap_or_default(),
            };
            let label = format!("{label}.{}", ch.property.name());
            let samples = unrolled(&ch, clip.duration);
            let Some((node, path)) = slot(slots, ch.of, ch.property) else {
                let track = |of: TargetRef, p: Property| {
                    clip.animation
                        .tracks
                        .iter()
                        .rev()
                        .find(|t| t.target.of == of && t.target.property == p)
                };
                match pointed(scene, pointers, &ch, &samples, &track) {
                    Ok(list) => {
                        let input = bin.floats(&seconds(&samples, fps), 1, true, None);
                        for p in list {
                            let output = bin.floats(&p.values, p.width, false, None);
                            samplers.push(json!({
                                "input": input,
                                "output": output,
                                "interpolation": "LINEAR",
                            }));
                            chans.push(json!({
                                "sampler": samplers.len() - 1,
                                "target": { "path": "pointer", "extensions": pointer_ext(&p.pointer) },
                            }));
                            targets.push(p.pointer);
                        }
                        report.channels.push(ChannelReport {
                            name: format!("{label} ({EXTENSION}, sampled)"),
                            authored_keys: ch.authored_keys,
                            written_keys: samples.len(),
                            per_frame_keys: per_frame_keys(clip.duration),
                        });
                    }
                    Err(why) => report.warnings.push(format!(
                        "{label}: not written as a glTF channel ({why}); it is kept in the key note only"
                    )),
                }
                continue;
            };
            let track = clip
                .animation
                .tracks
                .iter()
                .rev()
                .find(|t| t.target.of == ch.of && t.target.property == ch.property);
            // Scale also carries visibility: exact only when nothing hides.
            let folded = ch.property == Property::Scale
                && match ch.of {
                    TargetRef::Node(id) => {
                        let n = scene.node(id);
                        !n.visible
                            || n.style == crate::scene::RenderStyle::Hidden
                            || clip.animation.tracks.iter().any(|t| {
                                t.target.of == ch.of && t.target.property == Property::Visibility
                            })
                    }
                    _ => false,
                };
            let rotation = path == "rotation";
            let (w, how) = match track.filter(|_| !folded).and_then(|t| exact(t, fps)) {
                Some(w) => {
                    let how = format!("{} exact", w.interp);
                    (w, how)
                }
                None => (sampled(&samples, fps, rotation), "sampled".to_string()),
            };
            report.channels.push(ChannelReport {
                name: format!("{label} ({how})"),
                authored_keys: ch.authored_keys,
                written_keys: w.keys,
                per_frame_keys: per_frame_keys(clip.duration),
            });
            let input = bin.floats(&w.times, 1, true, None);
            // Weights outputs are SCALAR (N per key), others one element per key.
            let elem = if path == "weights" { 1 } else { w.width };
            let output = bin.floats(&w.values, elem, false, None);
            samplers.push(json!({
                "input": input,
                "output": output,
                "interpolation": w.interp,
            }));
            chans.push(json!({
                "sampler": samplers.len() - 1,
                "target": { "node": node, "path": path },
            }));
        }
        if chans.is_empty() {
            continue;
        }
        let name = if clip.name.is_empty() {
            format!("animation_{}", clip.index)
        } else {
            clip.name.to_string()
        };
        out.push(json!({ "name": name, "channels": chans, "samplers": samplers }));
    }
    (out, targets)
}
