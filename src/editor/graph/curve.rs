//! A channel's curve as the graph draws it: `Track::sample` at dense,
//! evenly spaced frames (so the curve is exactly what playback plays; no
//! spline code of its own), the keys as points on it, and rotations as
//! Euler degrees unwrapped along the curve so they do not jump at ±180.

use super::channel::{component, Channel};
use crate::anim::{Animation, Track};

/// Most samples one curve takes (a very long track zoomed in samples
/// more coarsely before the view instead of without bound).
const MAX_SAMPLES: usize = 20_000;

/// Samples and key points of one channel, values in the channel's units
/// (degrees for rotations).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Curve {
    /// (frame, value), increasing frames, covering the asked span.
    pub samples: Vec<(f32, f32)>,
    /// (frame, value) of every key of the track, in order.
    pub keys: Vec<(f32, f32)>,
}

impl Curve {
    /// Smallest and largest value of the keys and samples.
    pub fn value_range(&self) -> Option<(f32, f32)> {
        let vs = self.samples.iter().chain(&self.keys).map(|p| p.1);
        let (lo, hi) = vs.fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
        (lo <= hi).then_some((lo, hi))
    }

    /// The value at key `frame` (as drawn: unwrapped for rotations).
    pub fn key_value(&self, frame: f32) -> Option<f32> {
        self.keys
            .iter()
            .find(|k| (k.0 - frame).abs() <= crate::anim::KEY_EPS)
            .map(|k| k.1)
    }
}

/// Samples `ch` over `[f0, f1]` every `step` frames. Rotations are sampled
/// from the first key on (or `f0` if earlier) so the unwrapping, and so a
/// key's shown angle, does not depend on where the view starts.
pub fn sample(anim: &Animation, ch: Channel, f0: f32, f1: f32, step: f32) -> Option<Curve> {
    let track = anim.track(ch.target())?;
    let key_frames = track.keys.frames();
    let first = *key_frames.first()?;
    let last = *key_frames.last()?;
    let start = if ch.is_rotation() { f0.min(first) } else { f0 };
    let end = f1.max(if ch.is_rotation() { last } else { f1 });
    let span = (end - start).max(0.0);
    let step = step.max(span / MAX_SAMPLES as f32).max(1e-3);
    // Even frames plus every key frame, in order.
    let n = (span / step).ceil() as usize;
    let mut frames: Vec<f32> = (0..=n).map(|i| start + i as f32 * step).collect();
    frames.extend(
        key_frames
            .iter()
            .copied()
            .filter(|f| (start..=end).contains(f)),
    );
    if step <= 0.5 {
        // Whole frames too: the graph marks them to show the timing.
        let (a, b) = (start.ceil() as i64, end.floor() as i64);
        frames.extend((a..=b).map(|f| f as f32));
    }
    frames.sort_by(f32::total_cmp);
    frames.dedup_by(|a, b| (*a - *b).abs() < 1e-4);
    let mut samples = Vec::with_capacity(frames.len());
    let mut prev: Option<f32> = None;
    for f in frames {
        let Some(mut v) = value_at(track, ch, f) else {
            continue;
        };
        if let (true, Some(p)) = (ch.is_rotation(), prev) {
            v += 360.0 * ((p - v) / 360.0).round();
        }
        prev = Some(v);
        samples.push((f, v));
    }
    let keys = key_frames
        .iter()
        .filter_map(|&kf| {
            let v = match ch.is_rotation() {
                // The unwrapped sample at the key's own frame.
                true => samples.iter().find(|s| (s.0 - kf).abs() < 1e-4)?.1,
                false => value_at(track, ch, kf)?,
            };
            Some((kf, v))
        })
        .collect();
    if ch.is_rotation() {
        samples.retain(|s| s.0 >= f0 - step && s.0 <= f1 + step);
    }
    Some(Curve { samples, keys })
}

/// Component `ch.comp` of the track at `frame`.
fn value_at(track: &Track, ch: Channel, frame: f32) -> Option<f32> {
    component(track.sample(frame), ch.comp)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Key, Keys, Property, Repeat, Target, TargetRef, Value};
    use crate::scene::NodeId;
    use glam::{Quat, Vec3};

    fn anim(track: Track) -> Animation {
        let mut a = Animation::default();
        a.tracks.push(track);
        a
    }

    fn ch(property: Property, comp: u8) -> Channel {
        Channel {
            node: NodeId(1),
            property,
            comp,
        }
    }

    fn target(property: Property) -> Target {
        Target {
            of: TargetRef::Node(NodeId(1)),
            property,
        }
    }

    #[test]
    fn samples_are_what_the_track_plays() {
        let keys = vec![
            Key::new(0.0, Vec3::ZERO),
            Key::new(10.0, Vec3::new(0.0, 2.0, 0.0)),
            Key::new(30.0, Vec3::new(0.0, -1.0, 0.0)),
        ];
        let t = Track::new(
            target(Property::Translation),
            Repeat::Constant,
            Keys::Vec3(keys),
        )
        .unwrap();
        let a = anim(t.clone());
        let c = sample(&a, ch(Property::Translation, 1), 0.0, 30.0, 0.5).unwrap();
        for &(f, v) in &c.samples {
            let Value::Vec3(want) = t.sample(f) else {
                panic!()
            };
            assert_eq!(v, want.y, "frame {f}");
        }
        assert_eq!(c.keys, vec![(0.0, 0.0), (10.0, 2.0), (30.0, -1.0)]);
        assert!(
            c.samples.iter().any(|s| s.0 == 10.0),
            "keys are sample frames"
        );
        // The spline overshoots the middle key a little; the range has it.
        let (lo, hi) = c.value_range().unwrap();
        assert!(lo <= -1.0 && hi >= 2.0, "{lo} {hi}");
    }

    #[test]
    fn rotations_unwrap_past_180() {
        // Three quarter turns about y over three keys: 0, 135, 270 degrees.
        let keys: Vec<Key<Quat>> = [0.0f32, 135.0, 270.0]
            .iter()
            .enumerate()
            .map(|(i, d)| Key::new(i as f32 * 10.0, Quat::from_rotation_z(d.to_radians())))
            .collect();
        let t = Track::new(
            target(Property::Rotation),
            Repeat::Constant,
            Keys::Rotation(keys),
        )
        .unwrap();
        let c = sample(&anim(t), ch(Property::Rotation, 2), 0.0, 20.0, 0.25).unwrap();
        let last = c.keys[2].1;
        assert!((last - 270.0).abs() < 0.5, "unwrapped to 270, got {last}");
        for w in c.samples.windows(2) {
            assert!((w[1].1 - w[0].1).abs() < 20.0, "no jump: {w:?}");
        }
    }
}
