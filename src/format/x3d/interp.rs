//! X3D's own interpolation nodes (ISO/IEC 19775-1 §19) as animed keys:
//! SplinePositionInterpolator, SplineScalarInterpolator,
//! SquadOrientationInterpolator, and EaseInEaseOut between a TimeSensor
//! and an interpolator.
//!
//! **Exact where they match.** X3D's splines are cubic Hermite curves with
//! Catmull-Rom tangents `T_i = (v_{i+1} − v_{i−1})/2`, zero tangents at the
//! ends of an open curve, and (§19.2.4) the outgoing tangent scaled by
//! `2·Δt_{i−1}/(Δt_{i−1}+Δt_i)`, the incoming by `2·Δt_i/(…)`. animed's KB
//! spline with tension = continuity = bias = 0 has the same tangents and
//! the same curve where the keys on both sides of a key are evenly spaced
//! (the two scalings then are 1; they differ otherwise, X3D scaling each
//! side by the other side's interval); tension 1 at the end keys gives the
//! zero end tangents. Squad is Shoemake's with `s_i = q_i·exp(−(log(q_i⁻¹
//! q_{i+1}) + log(q_i⁻¹q_{i−1}))/4)` and `s = q` at open ends: animed's
//! squad-TCB with TCB 0 on even spacing, its end keys at fractions 0 and 1.
//! EaseInEaseOut's remap (§19.4.4) is the constant-acceleration ease animed's
//! keys carry (`anim::ease`), per key: exact when its keys are the
//! interpolator's.
//!
//! **Sampled otherwise** (uneven spacing, `keyVelocity`, `closed`, ease keys
//! that differ): the X3D curve is evaluated here and written as linear
//! (slerp) keys, [`SAMPLES`] per segment.

use crate::anim::{ease::ease, Interp, Key, Keys, ValueKind};
use crate::format::syntax::{axis_angle, AstNode};
use glam::{DQuat, DVec3, Quat, Vec3};

/// Linear keys per segment where a curve is sampled.
pub const SAMPLES: usize = 16;

/// Whether [`keys`] handles this interpolator (with this ease node).
pub fn handles(interp: &AstNode, ease: Option<&AstNode>) -> bool {
    ease.is_some()
        || matches!(
            interp.kind.as_str(),
            "SplinePositionInterpolator"
                | "SplineScalarInterpolator"
                | "SquadOrientationInterpolator"
        )
}

/// The value kind an interpolator node produces, if it is one of ours.
fn value_kind(kind: &str) -> Option<ValueKind> {
    Some(match kind {
        "ScalarInterpolator" | "SplineScalarInterpolator" => ValueKind::Scalar,
        "PositionInterpolator" | "SplinePositionInterpolator" => ValueKind::Vec3,
        "OrientationInterpolator" | "SquadOrientationInterpolator" => ValueKind::Rotation,
        _ => return None,
    })
}

/// One interpolator's curve over fractions, as X3D evaluates it.
struct Curve {
    kind: String,
    keys: Vec<f64>,
    /// Values as f64 rows (1 or 3 wide; rotations as quaternions).
    rows: Vec<Vec<f64>>,
    quats: Vec<DQuat>,
    /// Spline tangents: outgoing (T0) and incoming (T1) per key.
    t0: Vec<Vec<f64>>,
    t1: Vec<Vec<f64>>,
    /// Squad intermediates.
    s: Vec<DQuat>,
    /// Whether animed's KB/squad keys give this curve exactly.
    exact: bool,
}

fn sub(a: &[f64], b: &[f64]) -> Vec<f64> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

fn scale(a: &[f64], k: f64) -> Vec<f64> {
    a.iter().map(|x| x * k).collect()
}

fn qlog(q: DQuat) -> DVec3 {
    let v = DVec3::new(q.x, q.y, q.z);
    let s = v.length();
    if s < 1e-15 {
        return v;
    }
    v * (s.atan2(q.w) / s)
}

fn qexp(v: DVec3) -> DQuat {
    let h = v.length();
    if h < 1e-15 {
        return DQuat::from_xyzw(v.x, v.y, v.z, 1.0).normalize();
    }
    let a = v * (h.sin() / h);
    DQuat::from_xyzw(a.x, a.y, a.z, h.cos())
}

fn short(b: DQuat, a: DQuat) -> DQuat {
    if a.dot(b) < 0.0 {
        -b
    } else {
        b
    }
}

impl Curve {
    fn new(n: &AstNode, frames: &[f32]) -> Option<Curve> {
        let kind = n.kind.clone();
        let vk = value_kind(&kind)?;
        let keys: Vec<f64> = n.nums("key")?.to_vec();
        let kv = n.nums("keyValue").unwrap_or(&[]);
        let width = match vk {
            ValueKind::Scalar => 1,
            ValueKind::Rotation => 4,
            _ => 3,
        };
        let count = keys.len().min(kv.len() / width);
        if count == 0
            || keys[..count]
                .windows(2)
                .any(|w| w[1].partial_cmp(&w[0]).is_none_or(|o| o.is_lt()))
        {
            return None;
        }
        let keys = keys[..count].to_vec();
        let rows: Vec<Vec<f64>> = kv
            .chunks_exact(width)
            .take(count)
            .map(|c| c.to_vec())
            .collect();
        let mut quats = Vec::new();
        if vk == ValueKind::Rotation {
            for r in &rows {
                let q = axis_angle(r[0], r[1], r[2], r[3]);
                let q = DQuat::from_xyzw(q.x as f64, q.y as f64, q.z as f64, q.w as f64);
                let q = match quats.last() {
                    Some(p) => short(q, *p),
                    None => q,
                };
                quats.push(q);
            }
        }
        let mut c = Curve {
            kind,
            keys,
            rows,
            quats,
            t0: Vec::new(),
            t1: Vec::new(),
            s: Vec::new(),
            exact: true,
        };
        // Even spacing around every interior key, in the frames the track
        // will hold (what animed's KB spacing factors see).
        let even = frames.windows(3).all(|w| {
            let (a, b) = (w[1] - w[0], w[2] - w[1]);
            (a - b).abs() <= 1e-5 * a.abs().max(b.abs())
        });
        c.exact = even;
        match c.kind.as_str() {
            "SplinePositionInterpolator" | "SplineScalarInterpolator" => c.spline_tangents(n),
            "SquadOrientationInterpolator" => c.squad_intermediates(n),
            _ => {}
        }
        Some(c)
    }

    /// §19.2.4: tangents from keyVelocity, or Catmull-Rom (zero at the ends
    /// of an open curve, wrapped for a closed one), scaled for key spacing.
    fn spline_tangents(&mut self, n: &AstNode) {
        let k = &self.keys;
        let v = &self.rows;
        let cnt = k.len();
        let width = v[0].len();
        let vel: Vec<Vec<f64>> = n
            .nums("keyVelocity")
            .unwrap_or(&[])
            .chunks_exact(width)
            .map(|c| c.to_vec())
            .collect();
        let closed = n.bool("closed", false) && cnt > 2 && v[0] == v[cnt - 1];
        let mut t: Vec<Vec<f64>> = Vec::with_capacity(cnt);
        if vel.len() == cnt && cnt > 1 {
            self.exact = false;
            t = vel;
            if n.bool("normalizeVelocity", false) {
                let total: f64 = v
                    .windows(2)
                    .map(|w| sub(&w[1], &w[0]).iter().map(|x| x * x).sum::<f64>().sqrt())
                    .sum();
                for ti in t.iter_mut() {
                    let len = ti.iter().map(|x| x * x).sum::<f64>().sqrt();
                    if len > 0.0 {
                        *ti = scale(ti, total / len);
                    }
                }
            }
        } else {
            if !vel.is_empty() {
                // Velocities at the ends only: X3D uses them there.
                self.exact = false;
            }
            for i in 0..cnt {
                let ti = if i > 0 && i + 1 < cnt {
                    scale(&sub(&v[i + 1], &v[i - 1]), 0.5)
                } else if closed {
                    scale(&sub(&v[1], &v[cnt - 2]), 0.5)
                } else if vel.len() == 2 {
                    vel[if i == 0 { 0 } else { 1 }].clone()
                } else {
                    vec![0.0; width]
                };
                t.push(ti);
            }
            if closed {
                self.exact = false;
            }
        }
        // Spacing factors F⁻ (incoming) and F⁺ (outgoing), §19.2.4.
        for i in 0..cnt {
            let (dp, dn) = if i > 0 && i + 1 < cnt {
                (k[i] - k[i - 1], k[i + 1] - k[i])
            } else if closed && cnt > 2 {
                (k[cnt - 1] - k[cnt - 2], k[1] - k[0])
            } else {
                (1.0, 1.0)
            };
            let sum = dp + dn;
            let (f_out, f_in) = if sum > 0.0 {
                (2.0 * dp / sum, 2.0 * dn / sum)
            } else {
                (1.0, 1.0)
            };
            self.t0.push(scale(&t[i], f_out));
            self.t1.push(scale(&t[i], f_in));
        }
    }

    /// §19.4.13: Shoemake's intermediates (s = q at open ends).
    fn squad_intermediates(&mut self, n: &AstNode) {
        let q = &self.quats;
        let cnt = q.len();
        let closed = n.bool("closed", false) && cnt > 2 && self.rows[0] == self.rows[cnt - 1];
        if closed {
            self.exact = false;
        }
        let mid = |a: DQuat, b: DQuat, c: DQuat| {
            let inv = b.inverse();
            b * qexp(-(qlog(inv * short(c, b)) + qlog(inv * short(a, b))) / 4.0)
        };
        for i in 0..cnt {
            let s = if i > 0 && i + 1 < cnt {
                mid(q[i - 1], q[i], q[i + 1])
            } else if closed {
                let (a, c) = (q[cnt - 2], q[1]);
                mid(a, q[i], c)
            } else {
                q[i]
            };
            self.s.push(s);
        }
        // Squad ends with s = q only where the track has no pad keys.
        let (first, last) = (self.keys[0], self.keys[cnt - 1]);
        if first > 0.0 || last < 1.0 {
            self.exact = false;
        }
    }

    /// The segment holding fraction `f` and the position in it.
    fn locate(&self, f: f64) -> Option<(usize, f64)> {
        let k = &self.keys;
        if k.len() < 2 || f <= k[0] || f >= k[k.len() - 1] {
            return None;
        }
        let i = k
            .partition_point(|x| *x <= f)
            .saturating_sub(1)
            .min(k.len() - 2);
        let len = k[i + 1] - k[i];
        Some((i, if len > 0.0 { (f - k[i]) / len } else { 0.0 }))
    }

    fn end_index(&self, f: f64) -> usize {
        if f <= self.keys[0] {
            0
        } else {
            self.keys.len() - 1
        }
    }

    /// The vector value at a fraction (scalars in row[0]).
    fn vector(&self, f: f64) -> Vec<f64> {
        let Some((i, s)) = self.locate(f) else {
            return self.rows[self.end_index(f)].clone();
        };
        let (p0, p1) = (&self.rows[i], &self.rows[i + 1]);
        if self.t0.is_empty() {
            return p0.iter().zip(p1).map(|(a, b)| a + (b - a) * s).collect();
        }
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        (0..p0.len())
            .map(|d| p0[d] * h00 + self.t0[i][d] * h10 + p1[d] * h01 + self.t1[i + 1][d] * h11)
            .collect()
    }

    fn rotation(&self, f: f64) -> DQuat {
        let Some((i, s)) = self.locate(f) else {
            return self.quats[self.end_index(f)];
        };
        let (q0, q1) = (self.quats[i], self.quats[i + 1]);
        if self.s.is_empty() {
            return q0.slerp(q1, s);
        }
        let a = q0.slerp(q1, s);
        let b = self.s[i].slerp(short(self.s[i + 1], self.s[i]), s);
        a.slerp(short(b, a), 2.0 * s * (1.0 - s))
    }
}

/// EaseInEaseOut's remap of a fraction (§19.4.4).
struct Ease {
    keys: Vec<f64>,
    /// (easeIn, easeOut) per key.
    pairs: Vec<(f32, f32)>,
}

impl Ease {
    fn new(n: &AstNode) -> Option<Ease> {
        let keys: Vec<f64> = n.nums("key")?.to_vec();
        let pairs: Vec<(f32, f32)> = n
            .nums("easeInEaseOut")
            .unwrap_or(&[])
            .chunks_exact(2)
            .map(|c| (c[0] as f32, c[1] as f32))
            .collect();
        let count = keys.len().min(pairs.len());
        if count < 2 {
            return None;
        }
        Some(Ease {
            keys: keys[..count].to_vec(),
            pairs: pairs[..count].to_vec(),
        })
    }

    fn remap(&self, f: f64) -> f64 {
        let k = &self.keys;
        if f <= k[0] || f >= k[k.len() - 1] {
            return f;
        }
        let i = k
            .partition_point(|x| *x <= f)
            .saturating_sub(1)
            .min(k.len() - 2);
        let len = k[i + 1] - k[i];
        if len <= 0.0 {
            return f;
        }
        let u = ((f - k[i]) / len) as f32;
        let e = ease(u, self.pairs[i].1, self.pairs[i + 1].0);
        k[i] + e as f64 * len
    }
}

/// The keys of an X3D spline/squad interpolator, or of any interpolator
/// behind an EaseInEaseOut, on the frames `frame(fraction)`. Returns the
/// keys and whether they are exact (else sampled). `None` when the node
/// has no usable keys.
pub fn keys(
    interp: &AstNode,
    ease_node: Option<&AstNode>,
    want: ValueKind,
    frame: &dyn Fn(f64) -> f32,
) -> Option<(Keys, bool)> {
    let fractions: Vec<f64> = interp.nums("key")?.to_vec();
    let frames: Vec<f32> = fractions.iter().map(|k| frame(k.clamp(0.0, 1.0))).collect();
    let mut curve = Curve::new(interp, &frames)?;
    if frames.windows(2).any(|w| w[1] <= w[0]) {
        // Jumps (equal key times) are kept exactly only by linear keys.
        curve.exact = false;
    }
    let ease = ease_node.and_then(Ease::new);
    if ease_node.is_some() {
        let aligned = ease.as_ref().is_some_and(|e| e.keys == curve.keys);
        if !aligned {
            curve.exact = false;
        }
    }
    let kind = value_kind(&curve.kind)?;
    let matches = match want {
        ValueKind::Scalar => kind == ValueKind::Scalar,
        ValueKind::Vec3 | ValueKind::Color => kind == ValueKind::Vec3,
        ValueKind::Rotation => kind == ValueKind::Rotation,
        _ => false,
    };
    if !matches {
        return None;
    }
    let spline = curve.kind.starts_with("Spline") || curve.kind.starts_with("Squad");
    if curve.exact {
        let interp_of = if spline { Interp::Tcb } else { Interp::Linear };
        let cnt = curve.keys.len();
        let mk = |i: usize| {
            let mut k = Key::new(frames[i], ()).with_interp(interp_of);
            if let Some(e) = &ease {
                k.ease_in = e.pairs[i].0.clamp(0.0, 1.0);
                k.ease_out = e.pairs[i].1.clamp(0.0, 1.0);
            }
            // Open spline ends: zero tangents (tension 1). Squad keeps s = q
            // (tension 0, its ends have no pad keys).
            if curve.kind.starts_with("Spline") && (i == 0 || i + 1 == cnt) {
                k.tension = 1.0;
            }
            k
        };
        let out = match kind {
            ValueKind::Scalar => Keys::Scalar(pad(
                (0..cnt)
                    .map(|i| with(mk(i), curve.rows[i][0] as f32))
                    .collect(),
                frame,
            )),
            ValueKind::Rotation => Keys::Rotation(pad(
                (0..cnt)
                    .map(|i| with(mk(i), to_quat(curve.quats[i])))
                    .collect(),
                frame,
            )),
            _ => Keys::Vec3(pad(
                (0..cnt)
                    .map(|i| with(mk(i), to_vec3(&curve.rows[i])))
                    .collect(),
                frame,
            )),
        };
        return Some((out, true));
    }
    // Sampled: every key of the curve and of the ease, SAMPLES per segment.
    let mut grid: Vec<f64> = curve.keys.clone();
    if let Some(e) = &ease {
        grid.extend(e.keys.iter().copied());
    }
    grid.retain(|f| f.is_finite());
    grid.sort_by(f64::total_cmp);
    grid.dedup();
    let mut fr: Vec<f64> = Vec::new();
    for w in grid.windows(2) {
        for j in 0..SAMPLES {
            fr.push(w[0] + (w[1] - w[0]) * j as f64 / SAMPLES as f64);
        }
    }
    if let Some(l) = grid.last() {
        fr.push(*l);
    }
    fr.retain(|f| (0.0..=1.0).contains(f));
    let at = |f: f64| ease.as_ref().map_or(f, |e| e.remap(f));
    let mut last_frame = f32::NEG_INFINITY;
    let mut picks: Vec<(f32, f64)> = Vec::new();
    for f in fr {
        let t = frame(f);
        if t > last_frame {
            picks.push((t, f));
            last_frame = t;
        }
    }
    let out = match kind {
        ValueKind::Scalar => Keys::Scalar(pad(
            picks
                .iter()
                .map(|(t, f)| lin(*t, curve.vector(at(*f))[0] as f32))
                .collect(),
            frame,
        )),
        ValueKind::Rotation => {
            let mut qs: Vec<Key<Quat>> = Vec::new();
            for (t, f) in &picks {
                let mut q = to_quat(curve.rotation(at(*f)));
                if let Some(p) = qs.last() {
                    if p.value.dot(q) < 0.0 {
                        q = -q;
                    }
                }
                qs.push(lin(*t, q));
            }
            Keys::Rotation(pad(qs, frame))
        }
        _ => Keys::Vec3(pad(
            picks
                .iter()
                .map(|(t, f)| lin(*t, to_vec3(&curve.vector(at(*f)))))
                .collect(),
            frame,
        )),
    };
    Some((out, false))
}

fn lin<V>(t: f32, v: V) -> Key<V> {
    Key::new(t, v).with_interp(Interp::Linear)
}

fn with<V>(k: Key<()>, v: V) -> Key<V> {
    Key {
        frame: k.frame,
        value: v,
        interp: k.interp,
        tension: k.tension,
        continuity: k.continuity,
        bias: k.bias,
        ease_in: k.ease_in,
        ease_out: k.ease_out,
    }
}

fn to_vec3(r: &[f64]) -> Vec3 {
    Vec3::new(r[0] as f32, r[1] as f32, r[2] as f32)
}

fn to_quat(q: DQuat) -> Quat {
    Quat::from_xyzw(q.x as f32, q.y as f32, q.z as f32, q.w as f32)
}

/// Pads keys to the whole cycle [0, 1] with held values, as the VRML97
/// importer does, so a looping track repeats exactly one cycle.
fn pad<V: Copy>(mut keys: Vec<Key<V>>, frame: &dyn Fn(f64) -> f32) -> Vec<Key<V>> {
    let (Some(first), Some(last)) = (keys.first().cloned(), keys.last().cloned()) else {
        return keys;
    };
    let (start, end) = (frame(0.0), frame(1.0));
    if first.frame > start {
        keys.insert(0, Key::new(start, first.value).with_interp(Interp::Linear));
    }
    if last.frame < end {
        let n = keys.len();
        keys[n - 1].interp = Interp::Linear;
        keys.push(Key::new(end, last.value).with_interp(Interp::Linear));
    }
    keys
}
