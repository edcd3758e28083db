//! Property tests over random keys: every sample is finite, curves pass
//! through their keys, loops repeat with their period, rotations stay unit
//! length, and Track::new accepts exactly the sorted, in-range key lists.

use animed::internals::anim::{
    Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Value,
};
use animed::internals::scene::NodeId;
use glam::{Quat, Vec3};
use proptest::prelude::*;

fn target(p: Property) -> Target {
    Target {
        of: TargetRef::Node(NodeId(0)),
        property: p,
    }
}

fn interp() -> impl Strategy<Value = Interp> {
    prop_oneof![Just(Interp::Step), Just(Interp::Linear), Just(Interp::Tcb)]
}

/// (gap to previous key, value seed, interp, t, c, b, ease in, ease out)
type Raw = (f32, [f32; 4], Interp, f32, f32, f32, f32, f32);

fn raw_keys() -> impl Strategy<Value = Vec<Raw>> {
    prop::collection::vec(
        (
            0.05f32..20.0,
            prop::array::uniform4(-10.0f32..10.0),
            interp(),
            -1.0f32..=1.0,
            -1.0f32..=1.0,
            -1.0f32..=1.0,
            0.0f32..=1.0,
            0.0f32..=1.0,
        ),
        1..9,
    )
}

fn build<V>(raw: &[Raw], value: impl Fn(&[f32; 4]) -> V) -> Vec<Key<V>> {
    let mut f = -5.0;
    raw.iter()
        .map(|(gap, v, i, t, c, b, ei, eo)| {
            f += gap;
            Key::new(f, value(v))
                .with_interp(*i)
                .with_tcb(*t, *c, *b)
                .with_ease(*ei, *eo)
        })
        .collect()
}

fn quat(v: &[f32; 4]) -> Quat {
    let q = Quat::from_xyzw(v[0], v[1], v[2], v[3]);
    if q.length() < 1e-3 {
        Quat::IDENTITY
    } else {
        q.normalize()
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn vec3_tracks_are_finite_pass_keys_and_loop(raw in raw_keys(), loop_ in any::<bool>(), probe in -50.0f32..200.0) {
        let keys = build(&raw, |v| Vec3::new(v[0], v[1], v[2]));
        let repeat = if loop_ { Repeat::Loop } else { Repeat::Constant };
        let t = Track::new(target(Property::Translation), repeat, Keys::Vec3(keys.clone())).unwrap();
        let Value::Vec3(x) = t.sample(probe) else { panic!("kind") };
        prop_assert!(x.is_finite());
        let last = keys.len() - 1;
        for (i, k) in keys.iter().enumerate() {
            // In a loop the last key's instant is the first key's.
            let want = if loop_ && i == last && last > 0 { keys[0].value } else { k.value };
            let Value::Vec3(got) = t.sample(k.frame) else { panic!("kind") };
            prop_assert!((got - want).length() < 1e-4 * (1.0 + want.length()), "key {} {:?} vs {:?}", i, got, want);
        }
        if loop_ {
            let period = keys[last].frame - keys[0].frame;
            let Value::Vec3(a) = t.sample(probe) else { panic!("kind") };
            let Value::Vec3(b) = t.sample(probe + 2.0 * period) else { panic!("kind") };
            // rem_euclid rounding can land on the other side of a step.
            prop_assert!((a - b).length() < 1e-2 * (1.0 + a.length()) || keys.iter().any(|k| k.interp == Interp::Step));
        }
    }

    #[test]
    fn rotation_tracks_are_unit_and_pass_keys(raw in raw_keys(), loop_ in any::<bool>(), probes in prop::collection::vec(-50.0f32..200.0, 16)) {
        let keys = build(&raw, quat);
        let repeat = if loop_ { Repeat::Loop } else { Repeat::Constant };
        let t = Track::new(target(Property::Rotation), repeat, Keys::Rotation(keys.clone())).unwrap();
        for f in probes {
            let Value::Rotation(q) = t.sample(f) else { panic!("kind") };
            prop_assert!(q.is_finite() && (q.length() - 1.0).abs() < 1e-4, "|q| = {} at {}", q.length(), f);
        }
        let n = if loop_ { keys.len() - 1 } else { keys.len() };
        for k in &keys[..n.max(1)] {
            let Value::Rotation(q) = t.sample(k.frame) else { panic!("kind") };
            prop_assert!(q.dot(k.value).abs() > 1.0 - 1e-5);
        }
    }

    #[test]
    fn constructor_accepts_exactly_valid_lists(frames in prop::collection::vec(-100.0f32..100.0, 0..8), tension in -1.5f32..1.5) {
        let keys: Vec<Key<f32>> = frames.iter().map(|&f| Key::new(f, f).with_tcb(tension, 0.0, 0.0)).collect();
        let valid = !frames.is_empty()
            && frames.windows(2).all(|w| w[0] < w[1])
            && (-1.0..=1.0).contains(&tension);
        let r = Track::new(target(Property::Shininess), Repeat::Constant, Keys::Scalar(keys));
        prop_assert_eq!(r.is_ok(), valid);
    }

    #[test]
    fn random_edits_keep_tracks_valid(ops in prop::collection::vec((0u8..3, -20.0f32..60.0, -5.0f32..5.0, -10.0f32..10.0), 1..40)) {
        let mut t = Track::new(
            target(Property::Transparency),
            Repeat::Constant,
            Keys::Scalar(vec![Key::new(0.0, 0.0)]),
        ).unwrap();
        for (op, frame, delta, value) in ops {
            let before = t.clone();
            let r = match op {
                0 => t.set_key(frame, Value::Scalar(value)).map(|_| ()),
                1 => {
                    // Remove the key nearest to `frame`.
                    let f = t.keys.frames().into_iter().min_by(|a, b| (a - frame).abs().total_cmp(&(b - frame).abs())).unwrap();
                    t.remove_key(f)
                }
                _ => {
                    let f = t.keys.frames()[(frame.abs() as usize) % t.key_count()];
                    t.move_keys(&[f], delta)
                }
            };
            prop_assert!(t.validate().is_ok(), "{:?} after op {}", t.validate(), op);
            if r.is_err() {
                prop_assert_eq!(&t, &before, "a failed edit changed the track");
            }
            if op == 0 && r.is_ok() {
                prop_assert_eq!(t.sample(t.key(t.key_index_at(frame).unwrap()).unwrap().frame), Value::Scalar(value));
            }
        }
    }
}
