//! The graph editor's edits, as pure functions from an animation to a new
//! one: moving keys in time and value, and turning a dragged tangent
//! handle into Kochanek-Bartels tension, continuity and bias. The editor
//! records the result as one undoable `SetAnimation`.

use super::channel::{component, with_component, Channel};
use crate::anim::hermite::{kb_in, kb_out, Tcb};
use crate::anim::{Animation, Interp, KEY_EPS};
use crate::editor::keyedit::retime;
use crate::editor::keystrip::KeyRef;

/// A key on one curve: the channel and the key's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveKey {
    pub ch: Channel,
    pub frame: f32,
}

impl CurveKey {
    pub fn key_ref(&self) -> KeyRef {
        KeyRef {
            node: self.ch.node,
            property: self.ch.property,
            frame: self.frame,
        }
    }
    pub fn same(&self, o: &CurveKey) -> bool {
        self.ch == o.ch && (self.frame - o.frame).abs() <= KEY_EPS
    }
}

/// The distinct keys (whole track keys) behind curve keys.
pub fn key_refs(keys: &[CurveKey]) -> Vec<KeyRef> {
    let mut out: Vec<KeyRef> = Vec::new();
    for k in keys {
        let r = k.key_ref();
        if !out.iter().any(|o| o.same(&r)) {
            out.push(r);
        }
    }
    out
}

/// `base` with each curve key's component moved by `dv` (its channel's
/// units: degrees for rotations) and then every key behind them moved by
/// `df` frames. Returns the new animation and the keys' new places.
pub fn move_keys(
    base: &Animation,
    keys: &[CurveKey],
    df: f32,
    dv: f32,
) -> Result<(Animation, Vec<CurveKey>), String> {
    let mut out = base.clone();
    if dv != 0.0 {
        for k in keys {
            let r = k.key_ref();
            let Some(key) = r.get(&out) else { continue };
            let Some(v) = component(key.value, k.ch.comp) else {
                continue;
            };
            let Some(track) = out.track_mut(r.target()) else {
                continue;
            };
            let mut new = key;
            new.value = with_component(key.value, k.ch.comp, v + dv);
            track.insert_key(new).map_err(|e| e.to_string())?;
        }
    }
    if df == 0.0 {
        return Ok((out, keys.to_vec()));
    }
    let (moved, _) = retime(&out, &key_refs(keys), |f| f + df)?;
    let moved_keys = keys
        .iter()
        .map(|k| CurveKey {
            frame: k.frame + df,
            ..*k
        })
        .collect();
    Ok((moved, moved_keys))
}

/// The chords around a key on one curve: (value change, frames) of the
/// segment arriving at it and of the one leaving it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Chords {
    pub before: Option<(f32, f32)>,
    pub after: Option<(f32, f32)>,
}

impl Chords {
    /// Chords of the key at index `i` of a curve's `(frame, value)` keys.
    pub fn at(keys: &[(f32, f32)], i: usize) -> Chords {
        let chord = |a: (f32, f32), b: (f32, f32)| (b.1 - a.1, b.0 - a.0);
        Chords {
            before: i
                .checked_sub(1)
                .and_then(|j| Some(chord(*keys.get(j)?, *keys.get(i)?))),
            after: keys.get(i + 1).and_then(|n| Some(chord(*keys.get(i)?, *n))),
        }
    }

    /// The curve's slope (value per frame) leaving the key (arriving, for
    /// the last key), from the KB tangent rule the curves play
    /// (`anim::hermite`), with no ease.
    pub fn slope(&self, tcb: Tcb) -> Option<f32> {
        match (self.before, self.after) {
            (b, Some(a)) if a.1 > 0.0 => Some(kb_out(b, a, tcb) / a.1),
            (Some(b), None) if b.1 > 0.0 => Some(kb_in(b, None, tcb) / b.1),
            _ => None,
        }
    }

    /// The bias after turning the tangent handle by `turn` radians (up,
    /// counter-clockwise on screen, is positive) from bias `from`, at the
    /// tension and continuity of `tcb`: [`TURN_PER_BIAS`] per unit, in the
    /// direction that steepens the curve the way the handle turned;
    /// clamped to [-1, 1]. An angle scale, as tension's length is a ratio
    /// scale: solving the bias that points the tangent at the mouse made
    /// a flat curve span its whole bias range in a few degrees (a 10-px
    /// tilt over a 40-px pull hit 1). `None` where bias does nothing (an
    /// end key, or equal chords' slopes).
    pub fn bias_turned(&self, tcb: Tcb, from: f32, turn: f32) -> Option<f32> {
        self.before?;
        let at = |bias| self.slope(Tcb { bias, ..tcb });
        let (lo, hi) = (at(-1.0)?, at(1.0)?);
        if (hi - lo).abs() < 1e-6 || !turn.is_finite() {
            return None;
        }
        let steeper = (hi - lo).signum();
        Some((from + steeper * turn / TURN_PER_BIAS).clamp(-1.0, 1.0))
    }
}

/// `anim` with the key at `r` given T, C, B (clamped to [-1, 1]); a step or
/// linear key becomes TCB so the change shows, as in the key panel.
pub fn set_tcb(anim: &Animation, r: KeyRef, tcb: Tcb) -> Result<Animation, String> {
    let mut out = anim.clone();
    let key = r.get(&out).ok_or("the key is gone")?;
    let track = out.track_mut(r.target()).ok_or("the track is gone")?;
    let mut k = key;
    k.tension = tcb.tension.clamp(-1.0, 1.0);
    k.continuity = tcb.continuity.clamp(-1.0, 1.0);
    k.bias = tcb.bias.clamp(-1.0, 1.0);
    if matches!(k.interp, Interp::Step | Interp::Linear) {
        k.interp = Interp::Tcb;
    }
    track.insert_key(k).map_err(|e| e.to_string())?;
    Ok(out)
}

/// Tangent handle length in pixels for tension `t`: 40 px at t = 0, and
/// every doubling of the length loosens by 0.5 (80 px: -0.5, 160 px: -1),
/// every halving tightens by 0.5 (10 px: 1). A ratio scale, as weighted
/// tangents feel in Blender and Maya: a 40-px pull loosens a default
/// handle to -0.5, where a linear scale reached -1 after 30 px.
pub fn handle_len(t: f32) -> f32 {
    HANDLE_PX * LOOSEN.powf(-t)
}

/// Inverse of [`handle_len`], clamped to the tension range.
pub fn tension_for_len(len: f32) -> f32 {
    (-(len.max(1e-3) / HANDLE_PX).ln() / LOOSEN.ln()).clamp(-1.0, 1.0)
}

/// Handle turn per unit of bias: 45°, so tilting a handle from bias 0 to
/// either end takes an eighth of a turn, however flat the curve is.
pub const TURN_PER_BIAS: f32 = std::f32::consts::FRAC_PI_4;

/// The length ratio between tension 0 and tension -1 (or 1 and 0).
const LOOSEN: f32 = 4.0;
const HANDLE_PX: f32 = 40.0;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Key, Keys, Property, Repeat, Target, TargetRef, Track, Value};
    use crate::scene::NodeId;
    use glam::Vec3;

    fn anim() -> Animation {
        let keys = vec![
            Key::new(0.0, Vec3::ZERO),
            Key::new(10.0, Vec3::new(0.0, 2.0, 0.0)),
            Key::new(30.0, Vec3::new(0.0, -1.0, 0.0)),
        ];
        let t = Track::new(
            Target {
                of: TargetRef::Node(NodeId(1)),
                property: Property::Translation,
            },
            Repeat::Constant,
            Keys::Vec3(keys),
        )
        .unwrap();
        Animation { tracks: vec![t] }
    }

    fn ty(frame: f32) -> CurveKey {
        CurveKey {
            ch: Channel {
                node: NodeId(1),
                property: Property::Translation,
                comp: 1,
            },
            frame,
        }
    }

    #[test]
    fn a_key_moves_in_value_and_time() {
        let (a, moved) = move_keys(&anim(), &[ty(10.0)], 2.0, 0.5).unwrap();
        assert_eq!(moved[0].frame, 12.0);
        let k = moved[0].key_ref().get(&a).unwrap();
        assert_eq!(k.value, Value::Vec3(Vec3::new(0.0, 2.5, 0.0)));
        assert!(ty(10.0).key_ref().get(&a).is_none(), "left frame 10");
    }

    #[test]
    fn bias_turns_with_the_handle_on_an_angle_scale() {
        let keys = [(0.0, 0.0), (10.0, 2.0), (30.0, -1.0)];
        let c = Chords::at(&keys, 1);
        let tcb = Tcb {
            tension: 0.3,
            ..Tcb::default()
        };
        // Which way bias steepens this key's outgoing slope.
        let up = c.slope(Tcb { bias: 1.0, ..tcb }).unwrap() > c.slope(tcb).unwrap();
        let sign = if up { 1.0 } else { -1.0 };
        let q = TURN_PER_BIAS;
        assert!((c.bias_turned(tcb, 0.0, q / 2.0).unwrap() - sign * 0.5).abs() < 1e-6);
        assert!((c.bias_turned(tcb, 0.5, -q).unwrap() - (0.5 - sign)).abs() < 1e-6);
        assert_eq!(c.bias_turned(tcb, 0.0, 10.0 * q).unwrap(), sign, "clamped");
        assert_eq!(
            c.bias_turned(tcb, 0.2, 0.0),
            Some(0.2),
            "no turn, no change"
        );
        // A 10-px tilt over a 40-px pull: about 0.31, not the limit.
        let b = c.bias_turned(tcb, 0.0, 10.0f32.atan2(40.0)).unwrap();
        assert!((b.abs() - 0.312).abs() < 0.01, "{b}");
        assert_eq!(
            Chords::at(&keys, 0).bias_turned(tcb, 0.0, 0.3),
            None,
            "end key"
        );
        // Catmull-Rom with uneven spacing: (P2 - P0)/(t2 - t0) per frame.
        let s = Chords::at(&keys, 1).slope(Tcb::default()).unwrap();
        assert!((s - (-1.0 - 0.0) / 30.0).abs() < 1e-5, "{s}");
    }

    #[test]
    fn handle_length_and_tension_round_trip() {
        for t in [-1.0f32, -0.3, 0.0, 0.6, 1.0] {
            assert!((tension_for_len(handle_len(t)) - t).abs() < 1e-5);
        }
        // A comfortable range: pulling a default handle 40 px longer
        // loosens it halfway, not to the limit; the limits are 4x and 1/4
        // of the default length.
        assert!((tension_for_len(handle_len(0.0) + 40.0) + 0.5).abs() < 1e-5);
        assert!((tension_for_len(handle_len(0.0) - 20.0) - 0.5).abs() < 1e-5);
        assert_eq!(tension_for_len(160.0), -1.0);
        assert_eq!(tension_for_len(1000.0), -1.0);
        assert_eq!(tension_for_len(0.0), 1.0);
        let a = set_tcb(
            &anim(),
            ty(10.0).key_ref(),
            Tcb {
                tension: 2.0,
                continuity: 0.1,
                bias: -0.4,
            },
        )
        .unwrap();
        let k = ty(10.0).key_ref().get(&a).unwrap();
        assert_eq!((k.tension, k.continuity, k.bias), (1.0, 0.1, -0.4));
    }
}
