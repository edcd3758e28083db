//! Track construction errors, key editing, values ⇄ numbers and the
//! Animation helpers.

use animed::internals::anim::{
    Animation, Interp, Key, KeyParams, Keys, Property, Repeat, Target, TargetRef, Track,
    TrackError, Value, ValueKind,
};
use animed::internals::scene::{MaterialId, NodeId};
use glam::{Quat, Vec3};

fn node(p: Property) -> Target {
    Target {
        of: TargetRef::Node(NodeId(3)),
        property: p,
    }
}

fn scalar_keys(frames: &[f32]) -> Keys {
    Keys::Scalar(frames.iter().map(|&f| Key::new(f, f * 2.0)).collect())
}

fn intensity(frames: &[f32]) -> Result<Track, TrackError> {
    Track::new(
        node(Property::LightIntensity),
        Repeat::Constant,
        scalar_keys(frames),
    )
}

#[test]
fn constructor_rejects_bad_keys() {
    assert_eq!(intensity(&[]), Err(TrackError::Empty));
    assert_eq!(
        intensity(&[0.0, 5.0, 3.0]),
        Err(TrackError::NotSorted { index: 2 })
    );
    assert_eq!(
        intensity(&[0.0, 5.0, 5.0]),
        Err(TrackError::DuplicateTime { index: 2 })
    );
    assert_eq!(
        intensity(&[0.0, f32::NAN]),
        Err(TrackError::NotFinite { index: 1 })
    );
    assert_eq!(
        intensity(&[f32::INFINITY]),
        Err(TrackError::NotFinite { index: 0 })
    );
    let bad_value = Keys::Vec3(vec![Key::new(0.0, Vec3::new(0.0, f32::NAN, 0.0))]);
    assert_eq!(
        Track::new(node(Property::Translation), Repeat::Constant, bad_value),
        Err(TrackError::NotFinite { index: 0 })
    );
    for (k, what) in [
        (Key::new(1.0, 1.0).with_tcb(1.5, 0.0, 0.0), "tension"),
        (Key::new(1.0, 1.0).with_tcb(0.0, -1.01, 0.0), "continuity"),
        (Key::new(1.0, 1.0).with_tcb(0.0, 0.0, f32::NAN), "bias"),
        (Key::new(1.0, 1.0).with_ease(-0.1, 0.0), "ease in"),
        (Key::new(1.0, 1.0).with_ease(0.0, 1.1), "ease out"),
    ] {
        let keys = Keys::Scalar(vec![Key::new(0.0, 0.0), k]);
        assert_eq!(
            Track::new(node(Property::Shininess), Repeat::Loop, keys),
            Err(TrackError::OutOfRange { index: 1, what })
        );
    }
    // Value kind must fit the property; colours use Vec3 keys.
    assert_eq!(
        Track::new(
            node(Property::Rotation),
            Repeat::Constant,
            scalar_keys(&[0.0])
        ),
        Err(TrackError::WrongValueKind)
    );
    assert_eq!(
        Track::new(
            node(Property::Diffuse),
            Repeat::Constant,
            scalar_keys(&[0.0])
        ),
        Err(TrackError::WrongValueKind)
    );
    assert!(Track::new(
        node(Property::Diffuse),
        Repeat::Constant,
        Keys::Vec3(vec![Key::new(0.0, Vec3::ONE)])
    )
    .is_ok());
    let zero = Keys::Rotation(vec![Key::new(0.0, Quat::from_xyzw(0.0, 0.0, 0.0, 0.0))]);
    assert!(matches!(
        Track::new(node(Property::Rotation), Repeat::Constant, zero),
        Err(TrackError::OutOfRange { index: 0, .. })
    ));
    // Messages say what is wrong.
    assert_eq!(
        TrackError::DuplicateTime { index: 2 }.to_string(),
        "key 2 has the same time as the key before it"
    );
}

#[test]
fn constructor_normalises_rotations_and_validate_checks_literals() {
    let keys = Keys::Rotation(vec![Key::new(0.0, Quat::from_xyzw(0.0, 0.0, 2.0, 0.0))]);
    let t = Track::new(node(Property::Rotation), Repeat::Constant, keys).expect("valid");
    let Keys::Rotation(k) = &t.keys else {
        panic!("kind changed")
    };
    assert!((k[0].value.length() - 1.0).abs() < 1e-6);
    let literal = Track {
        target: node(Property::Rotation),
        repeat: Repeat::Constant,
        keys: Keys::Rotation(vec![Key::new(0.0, Quat::from_xyzw(0.0, 0.0, 2.0, 0.0))]),
    };
    assert!(matches!(
        literal.validate(),
        Err(TrackError::OutOfRange { .. })
    ));
    // Sampling it anyway gives a unit quaternion, no panic.
    let Value::Rotation(r) = literal.sample(3.0) else {
        panic!("not a rotation")
    };
    assert!((r.length() - 1.0).abs() < 1e-6);
}

#[test]
fn unvalidated_tracks_never_panic() {
    let mk = |keys| Track {
        target: node(Property::LightIntensity),
        repeat: Repeat::Loop,
        keys,
    };
    assert_eq!(mk(Keys::Scalar(vec![])).sample(1.0), Value::Scalar(0.0));
    let weird = mk(Keys::Scalar(vec![
        Key::new(5.0, 1.0),
        Key::new(1.0, 2.0),
        Key::new(1.0, 3.0),
        Key::new(f32::NAN, 4.0),
    ]));
    for f in [-1.0, 0.0, 1.0, 3.0, 5.0, 100.0, f32::NAN, f32::INFINITY] {
        let _ = weird.sample(f);
    }
    let ok = intensity(&[0.0, 10.0]).expect("valid");
    assert_eq!(ok.sample(f32::NAN), Value::Scalar(0.0));
}

#[test]
fn set_key_inserts_in_order_and_replaces_keeping_settings() {
    let mut t = intensity(&[0.0, 10.0, 20.0]).expect("valid");
    let p = KeyParams {
        interp: Interp::Step,
        tension: 0.5,
        ..KeyParams::default()
    };
    t.set_key_params(1, p).expect("in range");
    // Replace at 10: value changes, settings stay.
    assert_eq!(t.set_key(10.0, Value::Scalar(7.0)), Ok(1));
    assert_eq!(t.key(1).map(|k| k.value), Some(Value::Scalar(7.0)));
    assert_eq!(t.key_params(1), Some(p));
    // Insert at 15: lands between, inherits the settings of the key before.
    assert_eq!(t.set_key(15.0, Value::Scalar(9.0)), Ok(2));
    assert_eq!(t.keys.frames(), vec![0.0, 10.0, 15.0, 20.0]);
    assert_eq!(t.key_params(2), Some(p));
    // Before the first key: inherits from the first.
    assert_eq!(t.set_key(-5.0, Value::Scalar(1.0)), Ok(0));
    assert_eq!(t.keys.frames(), vec![-5.0, 0.0, 10.0, 15.0, 20.0]);
    assert_eq!(t.sample(15.0), Value::Scalar(9.0));
    assert!(t.validate().is_ok());
    // Wrong kind and bad numbers are refused and change nothing.
    let before = t.clone();
    assert_eq!(
        t.set_key(3.0, Value::Bool(true)),
        Err(TrackError::WrongValueKind)
    );
    assert!(t.set_key(3.0, Value::Scalar(f32::NAN)).is_err());
    assert!(t.set_key(f32::INFINITY, Value::Scalar(1.0)).is_err());
    assert_eq!(t, before);
}

#[test]
fn remove_and_move_keys() {
    let mut t = intensity(&[0.0, 10.0, 20.0, 30.0]).expect("valid");
    assert_eq!(t.remove_key(10.0), Ok(()));
    assert_eq!(t.remove_key(11.0), Err(TrackError::NoKeyAt { frame: 11.0 }));
    assert_eq!(t.keys.frames(), vec![0.0, 20.0, 30.0]);
    // Move 20 past 30: re-sorted, value travels with the key.
    assert_eq!(t.move_key(20.0, 35.0), Ok(2));
    assert_eq!(t.keys.frames(), vec![0.0, 30.0, 35.0]);
    assert_eq!(t.sample(35.0), Value::Scalar(40.0));
    // Collision is refused and leaves the track as it was.
    let before = t.clone();
    assert!(matches!(
        t.move_keys(&[0.0], 30.0),
        Err(TrackError::DuplicateTime { .. })
    ));
    assert_eq!(t, before);
    assert_eq!(t.move_keys(&[0.0, 30.0], -5.0), Ok(()));
    assert_eq!(t.keys.frames(), vec![-5.0, 25.0, 35.0]);
    assert_eq!(t.frame_range(), Some((-5.0, 35.0)));
    // The last key cannot be removed.
    t.remove_key(-5.0).expect("exists");
    t.remove_key(25.0).expect("exists");
    assert_eq!(t.remove_key(35.0), Err(TrackError::Empty));
    assert_eq!(t.key_count(), 1);
}

#[test]
fn set_key_params_checks_ranges() {
    let mut t = intensity(&[0.0, 10.0]).expect("valid");
    let bad = KeyParams {
        bias: 2.0,
        ..KeyParams::default()
    };
    assert_eq!(
        t.set_key_params(0, bad),
        Err(TrackError::OutOfRange {
            index: 0,
            what: "bias"
        })
    );
    assert!(t.set_key_params(5, KeyParams::default()).is_err());
}

#[test]
fn keys_from_values_sorts_and_checks_kinds() {
    let keys = Keys::from_values(
        ValueKind::Color,
        &[
            Key::new(10.0, Value::Vec3(Vec3::X)),
            Key::new(0.0, Value::Vec3(Vec3::Y)).with_interp(Interp::Linear),
        ],
    )
    .expect("valid");
    assert_eq!(keys.frames(), vec![0.0, 10.0]);
    assert_eq!(keys.key(0).map(|k| k.interp), Some(Interp::Linear));
    assert_eq!(
        Keys::from_values(ValueKind::Scalar, &[Key::new(0.0, Value::Bool(true))]),
        Err(TrackError::WrongValueKind)
    );
    assert!(matches!(
        Keys::from_values(
            ValueKind::Scalar,
            &[
                Key::new(1.0, Value::Scalar(1.0)),
                Key::new(1.0, Value::Scalar(2.0))
            ]
        ),
        Err(TrackError::DuplicateTime { .. })
    ));
    assert_eq!(
        Keys::from_values(ValueKind::Bool, &[]),
        Err(TrackError::Empty)
    );
}

#[test]
fn numbers_round_trip_every_kind() {
    let cases = [
        (ValueKind::Scalar, vec![0.25]),
        (ValueKind::Vec3, vec![1.0, -2.0, 3.5]),
        (ValueKind::Color, vec![0.1, 0.2, 0.3]),
        (ValueKind::Rotation, vec![0.0, 0.0, 1.0, 2.0]),
        (ValueKind::Bool, vec![0.0]),
    ];
    for (kind, n) in cases {
        let v = Value::from_numbers(kind, &n).expect("valid numbers");
        let back = v.to_numbers();
        assert_eq!(back.len(), kind.arity());
        for (a, b) in back.iter().zip(&n) {
            assert!((a - b).abs() < 1e-6, "{kind:?}: {back:?} vs {n:?}");
        }
    }
    // An axis-angle beyond π comes back as the same rotation the short way.
    let v = Value::from_numbers(ValueKind::Rotation, &[0.0, 1.0, 0.0, 4.0]).expect("valid");
    let n = v.to_numbers();
    assert!((n[1] + 1.0).abs() < 1e-6 && (n[3] - (std::f32::consts::TAU - 4.0)).abs() < 1e-5);
}

#[test]
fn animation_finds_and_creates_tracks() {
    let mut a = Animation::default();
    let pos = node(Property::Translation);
    let mat = Target {
        of: TargetRef::Material(MaterialId(0)),
        property: Property::Transparency,
    };
    assert!(a.track(pos).is_none());
    assert_eq!(a.set_key(pos, 10.0, Value::Vec3(Vec3::X)), Ok(0));
    assert_eq!(a.set_key(pos, 0.0, Value::Vec3(Vec3::Y)), Ok(0));
    assert_eq!(a.tracks.len(), 1);
    assert_eq!(a.track(pos).map(|t| t.keys.frames()), Some(vec![0.0, 10.0]));
    assert_eq!(
        a.set_key(pos, 5.0, Value::Scalar(1.0)),
        Err(TrackError::WrongValueKind)
    );
    assert_eq!(
        a.set_key(mat, 0.0, Value::Vec3(Vec3::X)),
        Err(TrackError::WrongValueKind)
    );
    assert_eq!(a.tracks.len(), 1, "a failed create adds no track");
    a.set_key(mat, 4.0, Value::Scalar(0.5)).expect("valid");
    assert_eq!(a.frame_range(), Some((0.0, 10.0)));
    assert_eq!(a.tracks_of(TargetRef::Node(NodeId(3))).count(), 1);
    a.track_mut(mat)
        .expect("exists")
        .set_key(40.0, Value::Scalar(1.0))
        .expect("valid");
    assert_eq!(a.frame_range(), Some((0.0, 40.0)));
    assert_eq!(a.remove_tracks(pos), 1);
    assert!(a.track(pos).is_none());
}
