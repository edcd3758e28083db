//! The sampled interpolators play within tolerance of the authored curves
//! (random tracks of every interpolation, TCB, ease and repeat mode), and
//! linear tracks cost no more keys than they have.
mod writers_common;

use animed::internals::anim::{
    Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Value,
};
use animed::internals::format::export::channels::channels;
use animed::internals::format::sampling::{angle_between, slerp_shortest, Tolerances};
use animed::internals::scene::{Light, LightKind, Node, NodeKind, Scene};
use glam::{Quat, Vec3};
use proptest::prelude::*;

/// What a linear interpolator over `s` plays at `frame`.
fn played(s: &[(f32, Value)], frame: f32) -> Value {
    let j = s.partition_point(|k| k.0 <= frame);
    if j == 0 {
        return s[0].1;
    }
    if j >= s.len() {
        return s[s.len() - 1].1;
    }
    let (a, b) = (s[j - 1], s[j]);
    let f = (frame - a.0) / (b.0 - a.0);
    match (a.1, b.1) {
        (Value::Vec3(x), Value::Vec3(y)) => Value::Vec3(x.lerp(y, f)),
        (Value::Rotation(x), Value::Rotation(y)) => Value::Rotation(slerp_shortest(x, y, f)),
        (Value::Scalar(x), Value::Scalar(y)) => Value::Scalar(x + (y - x) * f),
        _ => a.1,
    }
}

fn near_jump(s: &[(f32, Value)], t: f32) -> bool {
    s.windows(2)
        .any(|w| w[1].0 - w[0].0 < 2e-3 && t >= w[0].0 - 1e-3 && t <= w[1].0 + 1e-3)
}

fn scene_with(track: Track, duration: f32) -> Scene {
    let mut s = Scene::new();
    s.settings.duration = duration;
    s.add_node(None, Node::group("N"));
    s.animation.tracks.push(track);
    s
}

/// Gap to the next key, interpolation, TCB, ease, value numbers.
type RawKey = (f32, u8, [f32; 3], [f32; 2], [f32; 4]);

fn key_strategy() -> impl Strategy<Value = RawKey> {
    (
        0.5f32..20.0,
        0u8..3,
        [-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0],
        [0.0f32..1.0, 0.0f32..1.0],
        [-2.0f32..2.0, -2.0f32..2.0, -2.0f32..2.0, -3.0f32..3.0],
    )
}

fn build<V>(raw: &[RawKey], v: impl Fn(&[f32; 4]) -> V) -> Vec<Key<V>> {
    let mut frame = 0.0;
    raw.iter()
        .map(|(dt, interp, tcb, ease, val)| {
            let mut k = Key::new(frame, v(val));
            k.interp = [Interp::Step, Interp::Linear, Interp::Tcb][*interp as usize];
            (k.tension, k.continuity, k.bias) = (tcb[0], tcb[1], tcb[2]);
            (k.ease_in, k.ease_out) = (ease[0], ease[1]);
            frame += dt;
            k
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn played_translation_stays_within_tolerance(
        raw in prop::collection::vec(key_strategy(), 1..6),
        looped in any::<bool>(),
    ) {
        let keys = build(&raw, |v| Vec3::new(v[0], v[1], v[2]));
        let track = Track {
            target: Target { of: TargetRef::Node(animed::internals::scene::NodeId(0)), property: Property::Translation },
            repeat: if looped { Repeat::Loop } else { Repeat::Constant },
            keys: Keys::Vec3(keys),
        };
        let s = scene_with(track.clone(), 60.0);
        let tol = Tolerances::new(10.0, 0.001, 0.1);
        let ch = channels(&s, &tol);
        prop_assert_eq!(ch.len(), 1);
        let samples = &ch[0].samples;
        let mut worst = 0.0f32;
        for i in 0..=3000 {
            let t = 60.0 * i as f32 / 3000.0;
            // A loop with a clock of its own holds one period of samples.
            let local = ch[0].local_frame(t);
            let (Value::Vec3(a), Value::Vec3(p)) = (track.sample(t), played(samples, local)) else { unreachable!() };
            // A jump plays as two keys at one time, or (when the loop
            // arithmetic puts the jump a hair off the key time) as a ramp
            // narrower than 0.002 frames: skip times inside those.
            if near_jump(samples, local) { continue; }
            worst = worst.max(a.distance(p) / tol.distance);
        }
        prop_assert!(worst <= 2.0, "played curve off by {} tolerances ({} keys)", worst, samples.len());
    }

    #[test]
    fn played_rotation_stays_within_tolerance(raw in prop::collection::vec(key_strategy(), 1..6)) {
        let keys = build(&raw, |v| Quat::from_axis_angle(Vec3::new(v[0], v[1], v[2] + 2.5).normalize(), v[3] * 2.0));
        let track = Track {
            target: Target { of: TargetRef::Node(animed::internals::scene::NodeId(0)), property: Property::Rotation },
            repeat: Repeat::Constant,
            keys: Keys::Rotation(keys),
        };
        let s = scene_with(track.clone(), 60.0);
        let tol = Tolerances::new(10.0, 0.001, 0.1);
        let ch = channels(&s, &tol);
        let samples = &ch[0].samples;
        let mut worst = 0.0f32;
        for i in 0..=3000 {
            let t = 60.0 * i as f32 / 3000.0;
            let (Value::Rotation(a), Value::Rotation(p)) = (track.sample(t), played(samples, t)) else { unreachable!() };
            if near_jump(samples, t) { continue; }
            worst = worst.max(angle_between(a, p) / tol.angle);
        }
        prop_assert!(worst <= 2.0, "played rotation off by {} tolerances ({} keys)", worst, samples.len());
    }
}

#[test]
fn linear_keys_are_kept_as_they_are() {
    let keys: Vec<Key<Vec3>> = [0.0, 10.0, 25.0, 40.0]
        .iter()
        .enumerate()
        .map(|(i, &f)| {
            Key::new(f, Vec3::new(i as f32, (i * i) as f32, 0.0)).with_interp(Interp::Linear)
        })
        .collect();
    let track = Track {
        target: Target {
            of: TargetRef::Node(animed::internals::scene::NodeId(0)),
            property: Property::Translation,
        },
        repeat: Repeat::Constant,
        keys: Keys::Vec3(keys),
    };
    let s = scene_with(track, 48.0);
    let ch = channels(&s, &Tolerances::new(10.0, 0.001, 0.1));
    let frames: Vec<f32> = ch[0].samples.iter().map(|k| k.0).collect();
    assert_eq!(frames, vec![0.0, 10.0, 25.0, 40.0, 48.0]);
}

#[test]
fn spline_keys_cost_fewer_keys_than_per_frame_baking_at_default_tolerance() {
    let s = writers_common::demo_scene();
    let (_, report) = animed::internals::format::save::to_bytes(
        &s,
        animed::internals::format::OutputFormat::Vrml97,
        &animed::internals::format::WriteOptions::default(),
    );
    let (w, p) = (report.written_keys(), report.per_frame_keys());
    println!("demo: {w} keys written, {p} per frame");
    assert!(w < p, "{w} >= {p}");
    // Looser tolerance, fewer keys.
    let (_, loose) = animed::internals::format::save::to_bytes(
        &s,
        animed::internals::format::OutputFormat::Vrml97,
        &animed::internals::format::WriteOptions {
            tolerance: 0.01,
            angle_tolerance: 1.0,
            ..Default::default()
        },
    );
    assert!(loose.written_keys() < w);
}

/// A track looping over 24 frames in a 2,400-frame scene: one period of
/// keys on a clock of its own (`cycleInterval 1` at 24 fps), not a hundred
/// unrolled periods; the file plays it as authored and reads back with
/// the same keys.
#[test]
fn a_loop_gets_its_own_clock_instead_of_being_unrolled() {
    use animed::internals::format::load_bytes;
    use animed::internals::format::save::{to_bytes, OutputFormat};
    use animed::internals::format::WriteOptions;
    let mut keys = vec![
        Key::new(0.0, Vec3::ZERO),
        Key::new(12.0, Vec3::X),
        Key::new(24.0, Vec3::ZERO),
    ];
    for k in &mut keys {
        k.interp = Interp::Tcb;
    }
    let track = Track {
        target: Target {
            of: TargetRef::Node(animed::internals::scene::NodeId(0)),
            property: Property::Translation,
        },
        repeat: Repeat::Loop,
        keys: Keys::Vec3(keys),
    };
    let s = scene_with(track.clone(), 2400.0);
    let tol = Tolerances::new(10.0, 0.001, 0.1);
    let ch = channels(&s, &tol);
    assert_eq!(ch[0].period, Some(24.0));
    assert!(ch[0].samples.last().unwrap().0 <= 24.0);
    for t in [0.0, 5.5, 30.25, 1000.0, 2399.0] {
        let (Value::Vec3(a), Value::Vec3(p)) = (
            track.sample(t),
            played(&ch[0].samples, ch[0].local_frame(t)),
        ) else {
            unreachable!()
        };
        assert!(a.distance(p) <= 2.0 * tol.distance, "at {t}: {a} vs {p}");
    }
    let (bytes, _) = to_bytes(&s, OutputFormat::Vrml97, &WriteOptions::default());
    let text = String::from_utf8(bytes.clone()).unwrap();
    assert!(
        text.contains("TimeSensor { cycleInterval 1 loop TRUE }"),
        "{text}"
    );
    // Size: one period of samples, not a hundred.
    let short = scene_with(track.clone(), 48.0);
    let (small, _) = to_bytes(&short, OutputFormat::Vrml97, &WriteOptions::default());
    assert!(
        bytes.len() < small.len() + 200,
        "{} vs {}",
        bytes.len(),
        small.len()
    );
    let back = load_bytes(&bytes, std::path::Path::new("loop.wrl")).unwrap();
    assert!(back.warnings.is_empty(), "{:?}", back.warnings);
    assert_eq!(back.scene.animation.tracks.len(), 1);
    assert_eq!(back.scene.animation.tracks[0].keys, track.keys);
    assert_eq!(back.scene.animation.tracks[0].repeat, Repeat::Loop);
}

/// A light off at rest with an animated intensity (and no `on` track) is
/// played dark by animed, so every writer's intensity channel is 0; the
/// same light on plays its keys.
#[test]
fn a_light_off_at_rest_writes_a_dark_intensity_channel() {
    for on in [false, true] {
        let mut s = Scene::new();
        s.settings.duration = 24.0;
        let mut light = Light::new(LightKind::Point);
        light.on = on;
        let id = s.add_node(None, Node::new("Lamp", NodeKind::Light(light)));
        s.animation.tracks.push(
            Track::new(
                Target {
                    of: TargetRef::Node(id),
                    property: Property::LightIntensity,
                },
                Repeat::Constant,
                Keys::Scalar(vec![
                    Key::new(0.0, 0.2).with_interp(Interp::Linear),
                    Key::new(24.0, 0.9).with_interp(Interp::Linear),
                ]),
            )
            .unwrap(),
        );
        let chans = channels(&s, &Tolerances::new(10.0, 0.001, 0.1));
        let ch = chans
            .iter()
            .find(|c| c.property == Property::LightIntensity)
            .expect("an intensity channel");
        for f in [0.0, 12.0, 24.0] {
            let want = if on { 0.2 + 0.7 * f / 24.0 } else { 0.0 };
            match played(&ch.samples, f) {
                Value::Scalar(x) => {
                    assert!((x - want).abs() < 1e-3, "on={on} f={f}: {x} vs {want}")
                }
                v => panic!("{v:?}"),
            }
        }
    }
}
