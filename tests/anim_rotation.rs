//! Rotation curves: unit length, keys, hemisphere rules (170° short way,
//! 270° over three keys), squad-TCB = Shoemake's squad at TCB 0, C¹ angular
//! velocity at keys (also with uneven spacing), loop wrap and ease.

use animed::internals::anim::{
    Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Value,
};
use animed::internals::scene::NodeId;
use glam::{Quat, Vec3};
use std::f32::consts::PI;

fn rtrack(keys: Vec<Key<Quat>>, repeat: Repeat) -> Track {
    let target = Target {
        of: TargetRef::Node(NodeId(0)),
        property: Property::Rotation,
    };
    Track::new(target, repeat, Keys::Rotation(keys)).expect("valid test track")
}

fn q(t: &Track, f: f32) -> Quat {
    match t.sample(f) {
        Value::Rotation(q) => q,
        other => panic!("expected a rotation, got {other:?}"),
    }
}

/// Angle in radians between two rotations (sign of the quaternions ignored).
/// (atan2 of the relative rotation, accurate for small angles unlike acos.)
fn angle_between(a: Quat, b: Quat) -> f32 {
    let r = a.conjugate() * b;
    2.0 * Vec3::new(r.x, r.y, r.z).length().atan2(r.w.abs())
}

/// Body-frame rotation vector from `a` to `b` (short way), radians.
fn rotvec(a: Quat, b: Quat) -> Vec3 {
    let mut r = a.conjugate() * b;
    if r.w < 0.0 {
        r = -r;
    }
    let (axis, angle) = r.to_axis_angle();
    if angle.abs() < 1e-9 {
        Vec3::ZERO
    } else {
        axis * angle
    }
}

/// Angular velocity (rad/frame) left and right of `f`, second order.
fn omegas(t: &Track, f: f32, h: f32) -> (Vec3, Vec3) {
    let l1 = rotvec(q(t, f - h), q(t, f)) / h; // at f − h/2
    let l2 = rotvec(q(t, f - 2.0 * h), q(t, f - h)) / h; // at f − 3h/2
    let r1 = rotvec(q(t, f), q(t, f + h)) / h;
    let r2 = rotvec(q(t, f + h), q(t, f + 2.0 * h)) / h;
    (l1 * 1.5 - l2 * 0.5, r1 * 1.5 - r2 * 0.5)
}

fn rz(deg: f32) -> Quat {
    Quat::from_rotation_z(deg.to_radians())
}

fn uneven(tcb: impl Fn(usize) -> (f32, f32, f32)) -> Vec<Key<Quat>> {
    let pts = [
        (0.0, Quat::IDENTITY),
        (
            4.0,
            Quat::from_axis_angle(Vec3::new(1.0, 1.0, 0.0).normalize(), 1.2),
        ),
        (
            13.0,
            Quat::from_axis_angle(Vec3::new(0.0, 1.0, 1.0).normalize(), 2.5),
        ),
        (
            16.0,
            Quat::from_axis_angle(Vec3::new(-1.0, 0.0, 1.0).normalize(), 0.9),
        ),
        (
            30.0,
            Quat::from_axis_angle(Vec3::new(0.3, -1.0, 0.2).normalize(), -1.4),
        ),
        (33.0, Quat::from_axis_angle(Vec3::X, 0.4)),
    ];
    pts.iter()
        .enumerate()
        .map(|(i, &(f, r))| {
            let (t, c, b) = tcb(i);
            Key::new(f, r).with_tcb(t, c, b)
        })
        .collect()
}

#[test]
fn outputs_are_unit_length_and_pass_through_keys() {
    for interp in [Interp::Step, Interp::Linear, Interp::Tcb] {
        for (t_, c_, b_) in [
            (0.0, 0.0, 0.0),
            (-1.0, 1.0, -1.0),
            (1.0, -1.0, 1.0),
            (-1.0, -1.0, 1.0),
        ] {
            let keys: Vec<_> = uneven(|_| (t_, c_, b_))
                .into_iter()
                .map(|k| k.with_interp(interp).with_ease(0.2, 0.4))
                .collect();
            let t = rtrack(keys.clone(), Repeat::Loop);
            for i in -50..400 {
                let r = q(&t, i as f32 * 0.1);
                assert!(
                    (r.length() - 1.0).abs() < 1e-5,
                    "{interp:?} at {i}: |q| = {}",
                    r.length()
                );
            }
            for k in &keys[..5] {
                let a = angle_between(q(&t, k.frame), k.value);
                assert!(a < 1e-3, "{interp:?} key {} off by {a}", k.frame);
            }
        }
    }
}

#[test]
fn two_keys_170_degrees_apart_take_the_short_way() {
    for stored in [rz(170.0), -rz(170.0)] {
        for interp in [Interp::Linear, Interp::Tcb] {
            let t = rtrack(
                vec![
                    Key::new(0.0, Quat::IDENTITY).with_interp(interp),
                    Key::new(10.0, stored),
                ],
                Repeat::Constant,
            );
            let mid = q(&t, 5.0);
            assert!(angle_between(mid, rz(85.0)) < 1e-4, "{interp:?}: {mid}");
        }
    }
    // 190° authored over two keys is the same as −170°: the short way.
    let t = rtrack(
        vec![
            Key::new(0.0, Quat::IDENTITY).with_interp(Interp::Linear),
            Key::new(10.0, rz(190.0)),
        ],
        Repeat::Constant,
    );
    assert!(angle_between(q(&t, 5.0), rz(-85.0)) < 1e-4);
}

/// Total angle turned between frames a and b, summed over small steps.
fn turned(t: &Track, a: f32, b: f32) -> f32 {
    let n = 2000;
    (0..n)
        .map(|i| {
            let f0 = a + (b - a) * i as f32 / n as f32;
            let f1 = a + (b - a) * (i + 1) as f32 / n as f32;
            angle_between(q(t, f0), q(t, f1))
        })
        .sum()
}

#[test]
fn turn_of_270_degrees_over_three_keys_plays_270() {
    for interp in [Interp::Linear, Interp::Tcb] {
        let t = rtrack(
            vec![
                Key::new(0.0, rz(0.0)).with_interp(interp),
                Key::new(10.0, rz(135.0)).with_interp(interp),
                Key::new(20.0, rz(270.0)),
            ],
            Repeat::Constant,
        );
        let total = turned(&t, 0.0, 20.0);
        assert!(
            (total - 1.5 * PI).abs() < 1e-2,
            "{interp:?}: turned {} deg",
            total.to_degrees()
        );
        // Uniform keys about one axis: constant angular speed, so frame 15 is
        // 202.5° (hand-worked: 135 + 0.5·135).
        assert!(angle_between(q(&t, 15.0), rz(202.5)) < 1e-3, "{interp:?}");
        assert!(angle_between(q(&t, 5.0), rz(67.5)) < 1e-3, "{interp:?}");
    }
}

/// Shoemake's squad, written independently with glam's slerp and
/// axis-angle for log/exp (log(q) = axis·θ/2).
fn shoemake(q: [Quat; 4], h: f32) -> Quat {
    let log = |q: Quat| {
        let (axis, angle) = q.to_axis_angle();
        axis * (angle / 2.0)
    };
    let exp = |v: Vec3| {
        let l = v.length();
        if l < 1e-9 {
            Quat::IDENTITY
        } else {
            Quat::from_axis_angle(v / l, 2.0 * l)
        }
    };
    let inter = |prev: Quat, cur: Quat, next: Quat| {
        cur * exp(-(log(cur.inverse() * next) + log(cur.inverse() * prev)) / 4.0)
    };
    let s1 = inter(q[0], q[1], q[2]);
    let s2 = inter(q[1], q[2], q[3]);
    q[1].slerp(q[2], h)
        .slerp(s1.slerp(s2, h), 2.0 * h * (1.0 - h))
}

#[test]
fn squad_tcb_zero_is_shoemakes_squad() {
    // Keys within one hemisphere of each other, evenly spaced.
    let keys: Vec<Quat> = (0..6)
        .map(|i| {
            let x = i as f32;
            Quat::from_euler(
                glam::EulerRot::XYZ,
                0.5 * x.sin(),
                0.3 * x,
                0.4 * (1.3 * x).cos(),
            )
        })
        .collect();
    let t = rtrack(
        keys.iter()
            .enumerate()
            .map(|(i, &r)| Key::new(i as f32 * 6.0, r))
            .collect(),
        Repeat::Constant,
    );
    for seg in 1..4 {
        for j in 0..=12 {
            let h = j as f32 / 12.0;
            let got = q(&t, (seg as f32 + h) * 6.0);
            let want = shoemake([keys[seg - 1], keys[seg], keys[seg + 1], keys[seg + 2]], h);
            assert!(angle_between(got, want) < 2e-4, "seg {seg} h {h}");
        }
    }
}

#[test]
fn angular_velocity_is_c1_at_keys_with_uneven_spacing() {
    let t = rtrack(
        uneven(|i| (0.3 - 0.15 * i as f32, 0.0, 0.2 * (i % 3) as f32 - 0.2)),
        Repeat::Constant,
    );
    for f in [4.0, 13.0, 16.0, 30.0] {
        let (l, r) = omegas(&t, f, 0.01);
        assert!(
            (l - r).length() < 3e-3 * (1.0 + l.length()),
            "frame {f}: {l} vs {r}"
        );
        assert!(l.length() > 0.02, "degenerate at {f}");
    }
    // Continuity ≠ 0 breaks it (the check above can fail).
    let kinked = rtrack(
        uneven(|i| (0.0, if i == 2 { 0.8 } else { 0.0 }, 0.0)),
        Repeat::Constant,
    );
    let (l, r) = omegas(&kinked, 13.0, 0.01);
    assert!((l - r).length() > 0.02, "{l} vs {r}");
}

#[test]
fn tension_one_stops_the_rotation_at_the_key() {
    let t = rtrack(
        uneven(|i| (if i == 2 { 1.0 } else { 0.0 }, 0.0, 0.0)),
        Repeat::Constant,
    );
    let (l, r) = omegas(&t, 13.0, 0.01);
    assert!(l.length() < 2e-3 && r.length() < 2e-3, "{l} {r}");
}

#[test]
fn neighbour_signs_do_not_matter() {
    // The same rotations with some keys stored as −q give the same motion.
    let keys = uneven(|_| (0.1, 0.0, -0.2));
    let mut flipped = keys.clone();
    flipped[1].value = -flipped[1].value;
    flipped[4].value = -flipped[4].value;
    let a = rtrack(keys, Repeat::Loop);
    let b = rtrack(flipped, Repeat::Loop);
    for i in 0..330 {
        let f = i as f32 * 0.1;
        assert!(angle_between(q(&a, f), q(&b, f)) < 1e-4, "frame {f}");
    }
}

#[test]
fn loop_rotation_is_continuous_across_the_wrap() {
    let mut keys = uneven(|_| (0.0, 0.0, 0.0));
    keys[5].value = -keys[0].value; // same rotation, other sign
    let t = rtrack(keys, Repeat::Loop);
    assert!(angle_between(q(&t, 33.0 - 1e-3), q(&t, 1e-3)) < 1e-3);
    let (l, _) = omegas(&t, 33.0, 0.01);
    let (_, r) = omegas(&t, 0.0, 0.01);
    assert!((l - r).length() < 3e-3 * (1.0 + l.length()), "{l} vs {r}");
    assert!(l.length() > 0.02);
    assert!(angle_between(q(&t, 7.5), q(&t, 7.5 + 33.0 * 3.0)) < 1e-4);
    assert!(angle_between(q(&t, -2.0), q(&t, 31.0)) < 1e-4);
}

#[test]
fn ease_on_rotations_changes_timing_not_path() {
    let keys = vec![
        Key::new(0.0, rz(0.0))
            .with_interp(Interp::Linear)
            .with_ease(0.0, 0.8),
        Key::new(10.0, rz(120.0)),
    ];
    let t = rtrack(keys, Repeat::Constant);
    // Path: rotations about z only; timing: slower than uniform early on.
    for i in 1..10 {
        let r = q(&t, i as f32);
        let (axis, angle) = r.to_axis_angle();
        assert!(
            angle < 1e-4 || axis.z.abs() > 0.9999,
            "left the z axis at {i}"
        );
    }
    let at2 = angle_between(q(&t, 2.0), Quat::IDENTITY).to_degrees();
    assert!(at2 < 0.5 * 24.0, "not eased: {at2} deg at frame 2");
}
