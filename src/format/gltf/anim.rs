//! glTF animations (spec §3.11) → animed clips, one per animation, named
//! by the animation's name or `animation_N`.
//!
//! Channels on translation, rotation and scale become tracks:
//! * STEP → step keys; LINEAR → linear keys (slerp for rotations, which
//!   takes the short way per segment in both glTF and animed);
//! * CUBICSPLINE (Appendix C): each key carries an in-tangent, a value and
//!   an out-tangent, and a segment of length Δt is the Hermite curve
//!   p(s) = (2s³−3s²+1)·v₀ + (s³−2s²+s)·Δt·b₀ + (−2s³+3s²)·v₁ + (s³−s²)·Δt·a₁
//!   (rotations: the same on the four components, then normalised).
//!   animed's keys carry Kochanek-Bartels parameters, not free tangents, so
//!   such a curve is sampled here into linear keys: each segment is halved
//!   until the chord stays within [`CUBIC_TOLERANCE`] (relative to the
//!   channel's largest value; radians for rotations) of the curve at the
//!   eighths of every piece, at most 64 pieces a segment.
//! * `weights` channels (morph targets) become `NAME.weights` tracks of N
//!   components (N = the node's mesh's target count), with the same three
//!   interpolations; CUBICSPLINE is sampled per component like the others.
//!
//! Key times are seconds in glTF and frames in animed; [`choose_fps`] picks
//! a frame rate that puts every key on a whole frame where one exists.

use super::accessor::read_f32;
use super::container::{Buffers, GltfError, Result};
use super::pointer::pointer;
use crate::anim::{
    Animation, Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Weights,
};
use crate::scene::{Clip, NodeId};
use glam::{Quat, Vec3, Vec4};
use gltf::animation::{Interpolation, Property as Path};

/// Sampling tolerance for CUBICSPLINE channels (see the module doc).
pub const CUBIC_TOLERANCE: f32 = 1e-5;

/// Frame rates tried, in order, by [`choose_fps`].
const RATES: [f32; 6] = [24.0, 30.0, 25.0, 60.0, 50.0, 120.0];

/// The first common frame rate that puts every key time on a whole frame
/// (within 1/1000 of a frame), else 24.
pub fn choose_fps(times: &[f32]) -> f32 {
    RATES
        .into_iter()
        .find(|fps| {
            times.iter().all(|t| {
                let f = t * fps;
                (f - f.round()).abs() < 1e-3
            })
        })
        .unwrap_or(24.0)
}

/// Every input (time) accessor's values, for [`choose_fps`].
pub fn all_times(doc: &gltf::Document, buffers: &Buffers) -> Vec<f32> {
    let mut times = Vec::new();
    for a in doc.animations() {
        for s in a.samplers() {
            if let Ok(t) = read_f32(&s.input(), buffers) {
                times.extend(t);
            }
        }
    }
    times
}

/// What a channel drives: the scene node and property for glTF node `i`
/// and a path (`None`: not in the loaded scene, or not animatable).
pub type TargetOf<'a> = &'a dyn Fn(usize, Path) -> Option<(NodeId, Property)>;

/// The usual mapping: node `i`'s translation, rotation and scale.
pub fn node_target(
    node_ids: &[Option<NodeId>],
    i: usize,
    path: Path,
) -> Option<(NodeId, Property)> {
    let id = node_ids.get(i).copied()??;
    let p = match path {
        Path::Translation => Property::Translation,
        Path::Rotation => Property::Rotation,
        Path::Scale => Property::Scale,
        Path::MorphTargetWeights => Property::MorphWeights,
    };
    Some((id, p))
}

/// Reads every animation into a clip; `target_of` maps channels to tracks.
pub fn read_clips(
    doc: &gltf::Document,
    buffers: &Buffers,
    target_of: TargetOf,
    fps: f32,
    warnings: &mut Vec<String>,
) -> Result<Vec<Clip>> {
    let mut clips = Vec::new();
    let mut sampled = 0usize;
    for a in doc.animations() {
        let here = pointer(&[&"animations", &a.index()]);
        let mut animation = Animation::default();
        let mut end = 0.0f32;
        for ch in a.channels() {
            let at = format!("{here}/channels/{}", ch.index());
            let target = ch.target();
            let node = target.node().index();
            let Some((id, property)) = target_of(node, target.property()) else {
                warnings.push(format!(
                    "{at}: node {node} is not in the loaded scene; the channel is skipped"
                ));
                continue;
            };
            let sampler = ch.sampler();
            let sp = format!("{here}/samplers/{}", sampler.index());
            let rotation = property.kind() == crate::anim::ValueKind::Rotation;
            let weights = property == Property::MorphWeights;
            let width = if rotation {
                4
            } else if weights {
                let n = morph_count(&target.node());
                if n == 0 {
                    warnings.push(format!(
                        "{at}: node {node} has no morph targets; the weights channel is skipped"
                    ));
                    continue;
                }
                n
            } else {
                3
            };
            let (times, values) = sampler_values(&sampler, buffers, &sp, width)?;
            end = end.max(times.last().copied().unwrap_or(0.0));
            let keys = match sampler.interpolation() {
                Interpolation::Step | Interpolation::Linear => {
                    let interp = if sampler.interpolation() == Interpolation::Step {
                        Interp::Step
                    } else {
                        Interp::Linear
                    };
                    if weights {
                        direct_weights(&times, &values, width, fps, interp)
                    } else {
                        direct_keys(&times, &values, rotation, fps, interp)
                    }
                }
                Interpolation::CubicSpline => {
                    sampled += 1;
                    if weights {
                        cubic_weights(&times, &values, width, fps)
                    } else {
                        cubic_keys(&times, &values, rotation, fps)
                    }
                }
            };
            let target = Target {
                of: TargetRef::Node(id),
                property,
            };
            match Track::new(target, Repeat::Constant, keys) {
                Ok(t) => animation.tracks.push(t),
                Err(e) => return Err(GltfError::at(sp, e.to_string())),
            }
        }
        clips.push(Clip {
            name: a
                .name()
                .filter(|n| !n.is_empty())
                .map_or_else(|| format!("animation_{}", a.index()), str::to_string),
            animation,
            duration: end * fps,
        });
    }
    if sampled > 0 {
        warnings.push(format!(
            "{sampled} CUBICSPLINE channel(s) sampled into linear keys (within {CUBIC_TOLERANCE} relative)"
        ));
    }
    Ok(clips)
}

/// A sampler's key times and output values, checked: `width` components
/// per value (three values per key for CUBICSPLINE), times increasing,
/// every number finite. `sp` is the sampler's JSON pointer.
pub(super) fn sampler_values(
    sampler: &gltf::animation::Sampler,
    buffers: &Buffers,
    sp: &str,
    width: usize,
) -> Result<(Vec<f32>, Vec<f32>)> {
    let times = read_f32(&sampler.input(), buffers)
        .map_err(|e| GltfError::at(format!("{sp}/input"), e.to_string()))?;
    let values = read_f32(&sampler.output(), buffers)
        .map_err(|e| GltfError::at(format!("{sp}/output"), e.to_string()))?;
    let cubic = sampler.interpolation() == Interpolation::CubicSpline;
    let per_key = if cubic { 3 } else { 1 };
    if values.len() != times.len() * per_key * width {
        return Err(GltfError::at(
            format!("{sp}/output"),
            format!(
                "{} values for {} key times (expected {} {}-component values)",
                values.len() / width.max(1),
                times.len(),
                times.len() * per_key,
                width
            ),
        ));
    }
    if let Some(bad) = times
        .windows(2)
        .position(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater))
    {
        return Err(GltfError::at(
            format!("{sp}/input"),
            format!(
                "key times must increase: key {} is not after key {bad}",
                bad + 1
            ),
        ));
    }
    if let Some(bad) = times.iter().chain(&values).find(|v| !v.is_finite()) {
        return Err(GltfError::at(sp, format!("a key holds {bad}")));
    }
    Ok((times, values))
}

/// Key frames for times in seconds: `t · fps`, kept strictly increasing
/// (two times a few ulps apart, as a jump in a sampled curve is written,
/// may land on one frame number after the multiplication).
pub(super) fn frames_of(times: impl IntoIterator<Item = f32>, fps: f32) -> Vec<f32> {
    let mut out: Vec<f32> = Vec::new();
    for t in times {
        let mut f = t * fps;
        if let Some(&last) = out.last() {
            if f <= last {
                f = next_up(last);
            }
        }
        out.push(f);
    }
    out
}

/// The next f32 above `x` (finite `x`).
fn next_up(x: f32) -> f32 {
    if x == 0.0 {
        f32::from_bits(1)
    } else if x > 0.0 {
        f32::from_bits(x.to_bits() + 1)
    } else {
        f32::from_bits(x.to_bits() - 1)
    }
}

/// How many morph targets node `g`'s mesh has (its first primitive's; the
/// spec requires all primitives to have the same count).
fn morph_count(g: &gltf::Node) -> usize {
    g.mesh()
        .and_then(|m| m.primitives().next())
        .map_or(0, |p| p.morph_targets().count())
}

/// STEP/LINEAR weights keys: N values per key (the first
/// [`MAX_MORPH_TARGETS`] kept).
fn direct_weights(times: &[f32], values: &[f32], n: usize, fps: f32, interp: Interp) -> Keys {
    Keys::Weights(
        frames_of(times.iter().copied(), fps)
            .into_iter()
            .zip(values.chunks_exact(n))
            .map(|(f, w)| Key::new(f, Weights::from_slice_truncated(w)).with_interp(interp))
            .collect(),
    )
}

/// CUBICSPLINE weights sampled into linear keys like [`cubic_keys`]: each
/// segment halved until every component's chord is within
/// [`CUBIC_TOLERANCE`] (relative to the largest weight) at the eighths.
fn cubic_weights(times: &[f32], values: &[f32], n: usize, fps: f32) -> Keys {
    let out = cubic_rows(times, values, n);
    let frames = frames_of(out.iter().map(|(t, _)| *t), fps);
    Keys::Weights(
        frames
            .into_iter()
            .zip(out)
            .map(|(f, (_, w))| {
                Key::new(f, Weights::from_slice_truncated(&w)).with_interp(Interp::Linear)
            })
            .collect(),
    )
}

/// A CUBICSPLINE sampler of `n` independent components (in-tangent, value,
/// out-tangent per key) sampled into rows `(time, values)` to be joined
/// linearly: each segment halved until every component's chord is within
/// [`CUBIC_TOLERANCE`] (relative to the largest value) at the eighths, at
/// most 64 pieces a segment.
pub(super) fn cubic_rows(times: &[f32], values: &[f32], n: usize) -> Vec<(f32, Vec<f32>)> {
    let get = |k: usize, part: usize, c: usize| values[(3 * k + part) * n + c];
    let scale = (0..times.len())
        .flat_map(|k| (0..n).map(move |c| (k, c)))
        .map(|(k, c)| get(k, 1, c).abs())
        .fold(1e-6f32, f32::max);
    let tol = CUBIC_TOLERANCE * scale;
    let mut out: Vec<(f32, Vec<f32>)> = Vec::new();
    for k in 0..times.len().saturating_sub(1) {
        let dt = times[k + 1] - times[k];
        let seg = |s: f32| -> Vec<f32> {
            (0..n)
                .map(|c| {
                    let v = hermite(
                        Vec4::splat(get(k, 1, c)),
                        Vec4::splat(get(k, 2, c)),
                        Vec4::splat(get(k + 1, 1, c)),
                        Vec4::splat(get(k + 1, 0, c)),
                        dt,
                        s,
                    );
                    v.x
                })
                .collect()
        };
        let error = |a: f32, b: f32| -> f32 {
            let (pa, pb) = (seg(a), seg(b));
            (1..8)
                .map(|j| {
                    let f = j as f32 / 8.0;
                    let curve = seg(a + (b - a) * f);
                    (0..n)
                        .map(|c| (pa[c] + (pb[c] - pa[c]) * f - curve[c]).abs())
                        .fold(0.0, f32::max)
                })
                .fold(0.0, f32::max)
        };
        let mut pieces = 1usize;
        while pieces < 64 {
            let worst = (0..pieces)
                .map(|i| error(i as f32 / pieces as f32, (i + 1) as f32 / pieces as f32))
                .fold(0.0, f32::max);
            if worst <= tol {
                break;
            }
            pieces *= 2;
        }
        for i in 0..pieces {
            let s = i as f32 / pieces as f32;
            out.push((times[k] + dt * s, seg(s)));
        }
    }
    if let Some(k) = times.len().checked_sub(1) {
        out.push((times[k], (0..n).map(|c| get(k, 1, c)).collect()));
    }
    out
}

fn direct_keys(times: &[f32], values: &[f32], rotation: bool, fps: f32, interp: Interp) -> Keys {
    let frames = frames_of(times.iter().copied(), fps).into_iter();
    if rotation {
        Keys::Rotation(
            frames
                .zip(values.chunks_exact(4))
                .map(|(f, q)| {
                    Key::new(f, Quat::from_xyzw(q[0], q[1], q[2], q[3])).with_interp(interp)
                })
                .collect(),
        )
    } else {
        Keys::Vec3(
            frames
                .zip(values.chunks_exact(3))
                .map(|(f, v)| Key::new(f, Vec3::new(v[0], v[1], v[2])).with_interp(interp))
                .collect(),
        )
    }
}

/// One CUBICSPLINE segment at s ∈ [0, 1] (module doc), on 4-vectors.
fn hermite(v0: Vec4, b0: Vec4, v1: Vec4, a1: Vec4, dt: f32, s: f32) -> Vec4 {
    let s2 = s * s;
    let s3 = s2 * s;
    v0 * (2.0 * s3 - 3.0 * s2 + 1.0)
        + b0 * (dt * (s3 - 2.0 * s2 + s))
        + v1 * (-2.0 * s3 + 3.0 * s2)
        + a1 * (dt * (s3 - s2))
}

fn cubic_keys(times: &[f32], values: &[f32], rotation: bool, fps: f32) -> Keys {
    let w = if rotation { 4 } else { 3 };
    let get = |k: usize, part: usize| -> Vec4 {
        let at = (3 * k + part) * w;
        let c = &values[at..at + w];
        Vec4::new(c[0], c[1], c[2], if rotation { c[3] } else { 0.0 })
    };
    let scale = if rotation {
        1.0
    } else {
        (0..times.len())
            .map(|k| get(k, 1).abs().max_element())
            .fold(1e-6f32, f32::max)
    };
    let tol = CUBIC_TOLERANCE * scale;
    // Error of the chord from a to b (parameters s) against the curve.
    let error = |seg: &dyn Fn(f32) -> Vec4, a: f32, b: f32| -> f32 {
        let (pa, pb) = (seg(a), seg(b));
        (1..8)
            .map(|j| {
                let f = j as f32 / 8.0;
                let curve = seg(a + (b - a) * f);
                if rotation {
                    let q = Quat::from_vec4(curve).normalize();
                    let chord = Quat::from_vec4(pa)
                        .normalize()
                        .slerp(Quat::from_vec4(pb).normalize(), f);
                    q.angle_between(chord)
                } else {
                    (pa.lerp(pb, f) - curve).abs().max_element()
                }
            })
            .fold(0.0, f32::max)
    };
    let mut out: Vec<(f32, Vec4)> = Vec::new();
    for k in 0..times.len().saturating_sub(1) {
        let dt = times[k + 1] - times[k];
        let (v0, b0, v1, a1) = (get(k, 1), get(k, 2), get(k + 1, 1), get(k + 1, 0));
        let seg = |s: f32| hermite(v0, b0, v1, a1, dt, s);
        let mut pieces = 1usize;
        while pieces < 64 {
            let worst = (0..pieces)
                .map(|i| {
                    error(
                        &seg,
                        i as f32 / pieces as f32,
                        (i + 1) as f32 / pieces as f32,
                    )
                })
                .fold(0.0, f32::max);
            if worst <= tol {
                break;
            }
            pieces *= 2;
        }
        for i in 0..pieces {
            let s = i as f32 / pieces as f32;
            out.push((times[k] + dt * s, seg(s)));
        }
    }
    if let Some(k) = times.len().checked_sub(1) {
        out.push((times[k], get(k, 1)));
    }
    let frames = frames_of(out.iter().map(|(t, _)| *t), fps);
    let out = frames.into_iter().zip(out.into_iter().map(|(_, v)| v));
    if rotation {
        Keys::Rotation(
            out.map(|(f, v)| {
                let q = Quat::from_vec4(v);
                let l = q.length();
                let q = if l > 1e-12 && l.is_finite() {
                    q / l
                } else {
                    Quat::IDENTITY
                };
                Key::new(f, q).with_interp(Interp::Linear)
            })
            .collect(),
        )
    } else {
        Keys::Vec3(
            out.map(|(f, v)| Key::new(f, v.truncate()).with_interp(Interp::Linear))
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fps_puts_keys_on_frames() {
        assert_eq!(choose_fps(&[0.0, 1.0 / 24.0, 0.5]), 24.0);
        assert_eq!(choose_fps(&[0.0, 1.0 / 30.0, 0.1]), 30.0);
        assert_eq!(choose_fps(&[0.013]), 24.0);
    }

    #[test]
    fn cubic_segments_pass_their_keys_and_match_the_spec_curve() {
        // One segment 0 → 2 s from 0 to 1 with out-tangent 1/s and
        // in-tangent 0: p(s) = s³·(Δt−2)… sampled and compared.
        let times = [0.0, 2.0];
        #[rustfmt::skip]
        let values = [
            0.0, 0.0, 0.0,  0.0, 0.0, 0.0,  1.0, 0.0, 0.0, // key 0: in, value, out
            0.0, 0.0, 0.0,  1.0, 0.0, 0.0,  0.0, 0.0, 0.0, // key 1
        ];
        let Keys::Vec3(keys) = cubic_keys(&times, &values, false, 24.0) else {
            panic!()
        };
        assert_eq!(keys.first().unwrap().value, Vec3::ZERO);
        assert_eq!(keys.last().unwrap().value, Vec3::X);
        assert_eq!(keys.last().unwrap().frame, 48.0);
        assert!(keys.len() > 4, "a curved segment needs several keys");
        for k in &keys {
            let s = k.frame / 48.0;
            let want = hermite(Vec4::ZERO, Vec4::X, Vec4::X, Vec4::ZERO, 2.0, s);
            assert!((k.value.x - want.x).abs() < 1e-6);
        }
    }
}
