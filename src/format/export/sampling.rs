//! Adaptive sampling of authored curves into linear interpolator keys.
//!
//! VRML97 interpolators (and the Inventor engine chains) play straight lines
//! between keys (slerp for rotations). An authored track is cut at its key
//! times (and, for looping tracks, at every repeat of them); each piece is
//! then halved until the line between the samples stays within the
//! tolerance of the authored curve at the eighths (1/8 … 7/8) of every piece.
//! A linear piece therefore costs one key, a spline piece as many as its
//! bending needs, and a jump (step keys, visibility, light on/off) two keys
//! at the same time — VRML97 allows repeated key fractions, which play as a
//! discontinuity. (A jump that float arithmetic puts a hair away from the
//! key time, e.g. after many loop repeats, plays as a ramp at most 0.001
//! frames wide.)
//!
//! Tolerances (`Tolerances::for_scene`): positions 0.1 % of the scene's
//! bounding-box diagonal, scale 0.1 % (relative), rotations and directions
//! 0.1°, colours and other 0..1 values 0.002.

use crate::anim::{Property, Value};
use crate::format::hsv::hsv_lerp_rgb;
use glam::Quat;

/// How far the played curve may stray from the authored one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Positions, in world units.
    pub distance: f32,
    /// Relative (scale factors).
    pub relative: f32,
    /// Rotations, directions and angles, in radians.
    pub angle: f32,
    /// Colours and other 0..1 values.
    pub unit: f32,
}

impl Tolerances {
    /// `relative` is a fraction of the bounding-box diagonal (e.g. 0.001),
    /// `angle_degrees` the angle tolerance.
    pub fn new(diagonal: f32, relative: f32, angle_degrees: f32) -> Tolerances {
        let diagonal = if diagonal.is_finite() && diagonal > 0.0 {
            diagonal
        } else {
            1.0
        };
        Tolerances {
            distance: relative * diagonal,
            relative,
            angle: angle_degrees.to_radians(),
            unit: 0.002,
        }
    }

    /// How errors of `property` are measured, and against what.
    pub fn metric(&self, property: Property) -> Metric {
        match property {
            Property::Translation | Property::LightLocation | Property::CameraPosition => {
                Metric::Distance(self.distance)
            }
            Property::Scale => Metric::Distance(self.relative),
            Property::Rotation | Property::CameraOrientation => Metric::Angle(self.angle),
            Property::LightDirection
            | Property::CameraFov
            | Property::LightCutOff
            | Property::LightBeamWidth => Metric::Distance(self.angle),
            Property::LightColor | Property::Diffuse | Property::Emissive | Property::Specular => {
                Metric::Color(self.unit)
            }
            Property::LightIntensity
            | Property::Transparency
            | Property::Shininess
            | Property::LightDropOff
            | Property::Visibility
            | Property::LightOn
            | Property::MorphWeights => Metric::Distance(self.unit),
        }
    }
}

/// How the error between the authored and the played value is measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Metric {
    /// Euclidean distance of numbers; played as a straight line.
    Distance(f32),
    /// Rotation angle between quaternions; played as shortest-path slerp.
    Angle(f32),
    /// Largest channel difference; the played curve may be an RGB line
    /// (Coin) or an HSV line (the VRML97 spec, view3dscene): both must fit.
    Color(f32),
}

/// One sampled key: frame and value.
pub type Sample = (f32, Value);

/// A curve to sample: its value at a frame, and the frames where it may
/// bend or jump (key times).
pub struct Curve<'a> {
    pub eval: &'a dyn Fn(f32) -> Value,
    pub breaks: Vec<f32>,
    pub metric: Metric,
}

/// Deepest halving of one piece; bounds the work on pathological curves.
const MAX_DEPTH: u32 = 14;
/// Pieces shorter than this (in frames) are not split further.
const MIN_SPAN: f32 = 1e-3;
/// At most this many break points per curve.
pub const MAX_BREAKS: usize = 100_000;

/// Samples `curve` over frames `0..=duration`.
pub fn sample(curve: &Curve, duration: f32) -> Vec<Sample> {
    let mut points = vec![0.0f32];
    let mut breaks: Vec<f32> = curve
        .breaks
        .iter()
        .copied()
        .filter(|b| b.is_finite() && *b > 0.0 && *b < duration)
        .collect();
    breaks.sort_by(f32::total_cmp);
    breaks.dedup();
    breaks.truncate(MAX_BREAKS);
    points.extend(breaks);
    points.push(duration.max(0.0));
    let mut out: Vec<Sample> = Vec::new();
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b <= a {
            continue;
        }
        let va = (curve.eval)(a);
        match out.last() {
            Some(&(_, last)) if error(curve.metric, last, va) <= 1.0 => {}
            _ => out.push((a, va)),
        }
        let vb = (curve.eval)(just_before(b));
        subdivide(curve, (a, va), (b, vb), 0, &mut out);
    }
    if out.is_empty() {
        out.push((0.0, (curve.eval)(0.0)));
    }
    out
}

/// The largest f32 below `x` (x > 0): the left-hand limit of a step.
fn just_before(x: f32) -> f32 {
    if x > 0.0 {
        f32::from_bits(x.to_bits() - 1)
    } else {
        x
    }
}

fn subdivide(curve: &Curve, a: Sample, b: Sample, depth: u32, out: &mut Vec<Sample>) {
    let span = b.0 - a.0;
    let worst = [0.125f32, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875]
        .iter()
        .map(|&f| {
            let authored = (curve.eval)(a.0 + span * f);
            played_error(curve.metric, authored, a.1, b.1, f)
        })
        .fold(0.0f32, f32::max);
    if worst <= 1.0 || depth >= MAX_DEPTH || span < MIN_SPAN {
        out.push(b);
        return;
    }
    let m = a.0 + span * 0.5;
    let mid = (m, (curve.eval)(m));
    subdivide(curve, a, mid, depth + 1, out);
    subdivide(curve, mid, b, depth + 1, out);
}

/// Error of `played` against `authored`, as a multiple of the tolerance
/// (≤ 1 is good enough).
pub fn error(metric: Metric, authored: Value, played: Value) -> f32 {
    let e = match (authored, played) {
        (Value::Scalar(a), Value::Scalar(b)) => (a - b).abs(),
        (Value::Vec3(a), Value::Vec3(b)) if matches!(metric, Metric::Color(_)) => {
            (a - b).abs().max_element()
        }
        (Value::Vec3(a), Value::Vec3(b)) => a.distance(b),
        (Value::Rotation(a), Value::Rotation(b)) => angle_between(a, b),
        (Value::Bool(a), Value::Bool(b)) => f32::from(u8::from(a != b)),
        (Value::Weights(a), Value::Weights(b)) => (a - b)
            .as_slice()
            .iter()
            .fold(0.0f32, |m, x| m.max(x.abs())),
        _ => f32::INFINITY,
    };
    let tol = match metric {
        Metric::Distance(t) | Metric::Angle(t) | Metric::Color(t) => t,
    };
    if e == 0.0 {
        0.0
    } else {
        e / tol.max(f32::MIN_POSITIVE)
    }
}

/// Angle of the rotation that takes `a` to `b`, in radians. Uses atan2 of
/// the relative rotation's vector and scalar parts, which stays exact for
/// small angles (acos of a dot product near 1 cannot resolve below ~0.04°).
pub fn angle_between(a: Quat, b: Quat) -> f32 {
    let r = a.conjugate() * b;
    2.0 * r.xyz().length().atan2(r.w.abs())
}

/// What a linear interpolator plays between `a` and `b` at fraction `f`
/// (colours: RGB, as Coin plays them; see [`played_error`] for HSV).
fn played(a: Value, b: Value, f: f32) -> Value {
    match (a, b) {
        (Value::Scalar(x), Value::Scalar(y)) => Value::Scalar(x + (y - x) * f),
        (Value::Vec3(x), Value::Vec3(y)) => Value::Vec3(x.lerp(y, f)),
        (Value::Weights(x), Value::Weights(y)) => Value::Weights(x + (y - x) * f),
        (Value::Rotation(x), Value::Rotation(y)) => Value::Rotation(slerp_shortest(x, y, f)),
        _ => a,
    }
}

/// Error (in tolerances) of the played value between samples `a` and `b`
/// at fraction `f`. Colours are checked against both RGB playback (Coin)
/// and HSV playback (the VRML97 spec, view3dscene): the worse counts.
fn played_error(metric: Metric, authored: Value, a: Value, b: Value, f: f32) -> f32 {
    let e = error(metric, authored, played(a, b, f));
    match (metric, a, b) {
        (Metric::Color(_), Value::Vec3(x), Value::Vec3(y)) => {
            e.max(error(metric, authored, Value::Vec3(hsv_lerp_rgb(x, y, f))))
        }
        _ => e,
    }
}

/// Slerp along the shorter arc, as VRML97 OrientationInterpolator and
/// Coin's SbRotation::slerp play it.
pub fn slerp_shortest(a: Quat, b: Quat, f: f32) -> Quat {
    let mut d = a.dot(b);
    let b = if d < 0.0 {
        d = -d;
        -b
    } else {
        b
    };
    if d > 0.9995 {
        return (a * (1.0 - f) + b * f).normalize();
    }
    let theta = d.min(1.0).acos();
    let s = theta.sin();
    let wa = ((1.0 - f) * theta).sin() / s;
    let wb = (f * theta).sin() / s;
    (a * wa + b * wb).normalize()
}

/// Keys a per-frame bake of `duration` frames would need (frames 0..=duration).
pub fn per_frame_keys(duration: f32) -> usize {
    if duration.is_finite() && duration > 0.0 {
        duration.ceil() as usize + 1
    } else {
        1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn max_err(curve: &Curve, s: &[Sample], duration: f32) -> f32 {
        let mut worst = 0.0f32;
        for i in 0..=1000 {
            let t = duration * i as f32 / 1000.0;
            // played value: find the segment
            let j = s.partition_point(|k| k.0 <= t).clamp(1, s.len() - 1);
            let (a, b) = (s[j - 1], s[j]);
            let f = if b.0 > a.0 {
                (t - a.0) / (b.0 - a.0)
            } else {
                1.0
            };
            let f = f.clamp(0.0, 1.0);
            worst = worst.max(played_error(curve.metric, (curve.eval)(t), a.1, b.1, f));
        }
        worst
    }

    #[test]
    fn linear_pieces_keep_one_key_each() {
        let f = |t: f32| Value::Scalar(if t < 10.0 { t * 2.0 } else { 20.0 - (t - 10.0) });
        let c = Curve {
            eval: &f,
            breaks: vec![10.0],
            metric: Metric::Distance(0.001),
        };
        let s = sample(&c, 30.0);
        assert_eq!(s.len(), 3, "{s:?}");
        assert_eq!(s[1].0, 10.0);
    }

    #[test]
    fn curves_are_split_until_within_tolerance() {
        let f = |t: f32| Value::Vec3(Vec3::new((t * 0.2).sin(), t * t * 0.01, 0.0));
        let c = Curve {
            eval: &f,
            breaks: vec![],
            metric: Metric::Distance(0.001),
        };
        let s = sample(&c, 48.0);
        assert!(s.len() > 10 && s.len() < 200, "{}", s.len());
        assert!(max_err(&c, &s, 48.0) < 1.5);
        let looser = Curve {
            metric: Metric::Distance(0.01),
            ..c
        };
        assert!(sample(&looser, 48.0).len() < s.len());
    }

    #[test]
    fn steps_become_repeated_keys() {
        let f = |t: f32| Value::Scalar(if t < 5.0 { 1.0 } else { 0.0 });
        let c = Curve {
            eval: &f,
            breaks: vec![5.0],
            metric: Metric::Distance(0.001),
        };
        let s = sample(&c, 10.0);
        let frames: Vec<f32> = s.iter().map(|k| k.0).collect();
        assert_eq!(frames, vec![0.0, 5.0, 5.0, 10.0]);
        assert_eq!(s[1].1, Value::Scalar(1.0));
        assert_eq!(s[2].1, Value::Scalar(0.0));
    }

    #[test]
    fn long_turns_are_split_so_shortest_path_slerp_plays_them() {
        // 300° about y over 10 frames, authored as a steady turn.
        let f = |t: f32| Value::Rotation(Quat::from_rotation_y((t / 10.0) * 300f32.to_radians()));
        let c = Curve {
            eval: &f,
            breaks: vec![],
            metric: Metric::Angle(0.1f32.to_radians()),
        };
        let s = sample(&c, 10.0);
        for w in s.windows(2) {
            let (Value::Rotation(a), Value::Rotation(b)) = (w[0].1, w[1].1) else {
                panic!()
            };
            assert!(angle_between(a, b) < std::f32::consts::PI);
        }
        let mid = s.iter().find(|k| k.0 == 5.0).expect("split at the middle");
        assert!(error(c.metric, f(5.0), mid.1) <= 1.0);
    }

    #[test]
    fn hsv_lerp_goes_the_short_way_round() {
        let red = Vec3::new(1.0, 0.0, 0.0);
        let magenta = Vec3::new(1.0, 0.0, 1.0);
        let m = hsv_lerp_rgb(red, magenta, 0.5);
        assert!((m - Vec3::new(1.0, 0.0, 0.5)).length() < 1e-6, "{m}");
        assert!((hsv_lerp_rgb(red, magenta, 0.0) - red).length() < 1e-6);
        assert!((hsv_lerp_rgb(red, magenta, 1.0) - magenta).length() < 1e-6);
    }

    #[test]
    fn per_frame_count() {
        assert_eq!(per_frame_keys(96.0), 97);
        assert_eq!(per_frame_keys(0.0), 1);
    }
}
