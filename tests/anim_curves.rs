//! Vector / scalar Kochanek-Bartels curves: hand-worked values, Catmull-Rom
//! equivalence, passing through keys, C¹ continuity (also with uneven key
//! spacing), tension, continuity, bias, step, ease and looping.

use animed::internals::anim::{
    Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Value,
};
use animed::internals::scene::NodeId;
use glam::Vec3;

fn target(p: Property) -> Target {
    Target {
        of: TargetRef::Node(NodeId(0)),
        property: p,
    }
}

fn vtrack(keys: Vec<Key<Vec3>>, repeat: Repeat) -> Track {
    Track::new(target(Property::Translation), repeat, Keys::Vec3(keys)).expect("valid test track")
}

fn strack(keys: Vec<Key<f32>>) -> Track {
    Track::new(
        target(Property::LightIntensity),
        Repeat::Constant,
        Keys::Scalar(keys),
    )
    .expect("valid test track")
}

fn v(t: &Track, f: f32) -> Vec3 {
    match t.sample(f) {
        Value::Vec3(x) => x,
        other => panic!("expected a Vec3, got {other:?}"),
    }
}

fn s(t: &Track, f: f32) -> f32 {
    match t.sample(f) {
        Value::Scalar(x) => x,
        other => panic!("expected a scalar, got {other:?}"),
    }
}

/// Second-order one-sided derivatives (per frame) at `f`: (left, right).
fn derivs(t: &Track, f: f32, h: f32) -> (Vec3, Vec3) {
    let l = (v(t, f) * 3.0 - v(t, f - h) * 4.0 + v(t, f - 2.0 * h)) / (2.0 * h);
    let r = (v(t, f) * -3.0 + v(t, f + h) * 4.0 - v(t, f + 2.0 * h)) / (2.0 * h);
    (l, r)
}

fn close(a: Vec3, b: Vec3, tol: f32) -> bool {
    (a - b).length() <= tol * (1.0 + b.length())
}

/// Uneven keys that are not collinear.
fn wobbly(tcb: impl Fn(usize) -> (f32, f32, f32)) -> Vec<Key<Vec3>> {
    let pts = [
        (0.0, Vec3::new(0.0, 0.0, 0.0)),
        (3.0, Vec3::new(2.0, 1.0, -1.0)),
        (10.0, Vec3::new(3.0, -2.0, 0.5)),
        (12.0, Vec3::new(5.0, 0.0, 2.0)),
        (25.0, Vec3::new(1.0, 4.0, -3.0)),
        (27.0, Vec3::new(0.0, 3.0, 1.0)),
    ];
    pts.iter()
        .enumerate()
        .map(|(i, &(f, p))| {
            let (t, c, b) = tcb(i);
            Key::new(f, p).with_tcb(t, c, b)
        })
        .collect()
}

#[test]
fn catmull_rom_hand_worked_value() {
    // Keys 0, 1, 3, 2 at frames 0, 10, 20, 30. Worked by hand for the middle
    // segment at s = 0.5 with the Catmull-Rom matrix form
    // p(s) = ½[2p1 + (−p0+p2)s + (2p0−5p1+4p2−p3)s² + (−p0+3p1−3p2+p3)s³]
    //      = ½[2 + 3·0.5 + 5·0.25 + (−4)·0.125] = ½·4.25 = 2.125,
    // and cross-checked with Hermite: m1 = (3−0)/2 = 1.5, m2 = (2−1)/2 = 0.5,
    // h00 = h01 = 0.5, h10 = 0.125, h11 = −0.125:
    // 0.5·1 + 0.125·1.5 + 0.5·3 − 0.125·0.5 = 2.125.
    let t = strack(vec![
        Key::new(0.0, 0.0),
        Key::new(10.0, 1.0),
        Key::new(20.0, 3.0),
        Key::new(30.0, 2.0),
    ]);
    assert!((s(&t, 15.0) - 2.125).abs() < 1e-5, "got {}", s(&t, 15.0));
    // s = 0.25 by hand: ½[2 + 3·0.25 + 5·0.0625 − 4·0.015625] = ½·3.0 = 1.5.
    assert!((s(&t, 12.5) - 1.5).abs() < 1e-5, "got {}", s(&t, 12.5));
    // First segment, open start (one-sided tangent m0 = 1−0 = 1, m1 = 1.5):
    // at s = 0.5: 0.5·0 + 0.125·1 + 0.5·1 − 0.125·1.5 = 0.4375.
    assert!((s(&t, 5.0) - 0.4375).abs() < 1e-5, "got {}", s(&t, 5.0));
}

/// Catmull-Rom written independently in matrix form.
fn catmull_rom(p0: Vec3, p1: Vec3, p2: Vec3, p3: Vec3, s: f32) -> Vec3 {
    0.5 * (2.0 * p1
        + (p2 - p0) * s
        + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * (s * s)
        + (3.0 * p1 - p0 - 3.0 * p2 + p3) * (s * s * s))
}

#[test]
fn tcb_zero_even_spacing_is_catmull_rom() {
    let p: Vec<Vec3> = (0..7)
        .map(|i| {
            let x = i as f32;
            Vec3::new(x.sin() * 3.0, (x * 0.7).cos() * 2.0, x * x * 0.1)
        })
        .collect();
    let t = vtrack(
        p.iter()
            .enumerate()
            .map(|(i, &v)| Key::new(i as f32 * 5.0, v))
            .collect(),
        Repeat::Constant,
    );
    for seg in 1..5 {
        for j in 0..=20 {
            let u = j as f32 / 20.0;
            let got = v(&t, seg as f32 * 5.0 + u * 5.0);
            let want = catmull_rom(p[seg - 1], p[seg], p[seg + 1], p[seg + 2], u);
            assert!(close(got, want, 1e-5), "seg {seg} s {u}: {got} vs {want}");
        }
    }
}

#[test]
fn passes_through_every_key() {
    for interp in [Interp::Step, Interp::Linear, Interp::Tcb] {
        let keys: Vec<_> = wobbly(|i| (0.3 - 0.2 * i as f32, 0.5 - 0.25 * i as f32, -0.4))
            .into_iter()
            .map(|k| k.with_interp(interp).with_ease(0.3, 0.6))
            .collect();
        for repeat in [Repeat::Constant, Repeat::Loop] {
            let t = vtrack(keys.clone(), repeat);
            for k in &keys {
                assert!(
                    close(v(&t, k.frame), k.value, 1e-6)
                        || repeat == Repeat::Loop && k.frame == 27.0,
                    "{interp:?} {repeat:?} key at {}",
                    k.frame
                );
            }
        }
    }
}

#[test]
fn c1_at_keys_with_uneven_spacing() {
    // Continuity 0, assorted tension and bias: left and right derivatives
    // per frame agree at every interior key. Without the uneven-spacing
    // factors they would differ by Δt_next/Δt_prev (here up to 13/2).
    let t = vtrack(
        wobbly(|i| (0.4 * (i as f32 - 2.0) / 3.0, 0.0, 0.3 - 0.15 * i as f32)),
        Repeat::Constant,
    );
    for f in [3.0, 10.0, 12.0, 25.0] {
        let (l, r) = derivs(&t, f, 0.01);
        assert!(close(l, r, 2e-3), "frame {f}: left {l} right {r}");
        assert!(l.length() > 0.05, "degenerate test at {f}");
    }
}

#[test]
fn tension_one_gives_zero_tangents() {
    let t = vtrack(
        wobbly(|i| (if i == 2 { 1.0 } else { 0.0 }, 0.0, 0.0)),
        Repeat::Constant,
    );
    let (l, r) = derivs(&t, 10.0, 0.01);
    assert!(l.length() < 1e-3 && r.length() < 1e-3, "{l} {r}");
    // A neighbouring key without tension still moves.
    let (l, _) = derivs(&t, 12.0, 0.01);
    assert!(l.length() > 0.1);
}

#[test]
fn continuity_gives_predicted_left_right_derivatives() {
    // Key 2 (frame 10) with continuity c, spacing Δp = 7, Δn = 2.
    // Per frame: left = ((1−c)A + (1+c)B)/(Δp+Δn),
    //            right = ((1+c)A + (1−c)B)/(Δp+Δn)  (K&B eqs. (9)/(10) with the
    // uneven-spacing factors 2Δp/(Δp+Δn), 2Δn/(Δp+Δn), divided by Δp, Δn).
    for c in [-0.8f32, -0.3, 0.5, 1.0] {
        let keys = wobbly(|i| (0.0, if i == 2 { c } else { 0.0 }, 0.0));
        let a = keys[2].value - keys[1].value;
        let b = keys[3].value - keys[2].value;
        let t = vtrack(keys, Repeat::Constant);
        let (l, r) = derivs(&t, 10.0, 0.005);
        let want_l = ((1.0 - c) * a + (1.0 + c) * b) / 9.0;
        let want_r = ((1.0 + c) * a + (1.0 - c) * b) / 9.0;
        assert!(close(l, want_l, 2e-3), "c {c}: left {l} want {want_l}");
        assert!(close(r, want_r, 2e-3), "c {c}: right {r} want {want_r}");
        assert!((l - r).length() > 0.05, "c {c}: sides should differ");
    }
}

#[test]
fn bias_weights_the_predicted_side() {
    // b = +1: both tangents are the incoming chord A (overshoot, follow
    // through); b = −1: the outgoing chord B. Per frame: 2A/(Δp+Δn), 2B/(Δp+Δn).
    for (bias, pick_a) in [(1.0f32, true), (-1.0, false)] {
        let keys = wobbly(|i| (0.0, 0.0, if i == 2 { bias } else { 0.0 }));
        let a = keys[2].value - keys[1].value;
        let b = keys[3].value - keys[2].value;
        let t = vtrack(keys, Repeat::Constant);
        let want = if pick_a { a } else { b } * (2.0 / 9.0);
        let (l, r) = derivs(&t, 10.0, 0.005);
        assert!(
            close(l, want, 2e-3) && close(r, want, 2e-3),
            "bias {bias}: {l} {r} want {want}"
        );
    }
}

#[test]
fn open_end_keys_use_one_sided_differences() {
    // First key: tangent (1−t)·(P1−P0) per segment; per frame divide by Δ.
    let keys = wobbly(|i| (if i == 0 { 0.5 } else { 0.0 }, 0.0, 0.0));
    let chord = (keys[1].value - keys[0].value) / 3.0;
    let last = (keys[5].value - keys[4].value) / 2.0;
    let t = vtrack(keys, Repeat::Constant);
    let (_, r) = derivs(&t, 0.0, 0.005);
    assert!(close(r, 0.5 * chord, 2e-3), "{r} vs {}", 0.5 * chord);
    let (l, _) = derivs(&t, 27.0, 0.005);
    assert!(close(l, last, 2e-3), "{l} vs {last}");
    // Two keys, t = 0: a straight line at constant speed.
    let two = vtrack(
        vec![
            Key::new(0.0, Vec3::ZERO),
            Key::new(4.0, Vec3::new(4.0, 8.0, -4.0)),
        ],
        Repeat::Constant,
    );
    assert!(close(v(&two, 1.0), Vec3::new(1.0, 2.0, -1.0), 1e-6));
    assert!(close(v(&two, 3.0), Vec3::new(3.0, 6.0, -3.0), 1e-6));
}

#[test]
fn constant_repeat_holds_outside_keys() {
    let t = vtrack(wobbly(|_| (0.0, 0.0, 0.0)), Repeat::Constant);
    assert_eq!(v(&t, -100.0), Vec3::ZERO);
    assert_eq!(v(&t, 1e6), Vec3::new(0.0, 3.0, 1.0));
}

#[test]
fn step_holds_and_linear_interpolates() {
    let keys = vec![
        Key::new(0.0, 1.0).with_interp(Interp::Step),
        Key::new(10.0, 5.0).with_interp(Interp::Linear),
        Key::new(20.0, 7.0),
    ];
    let t = strack(keys);
    for f in [0.0, 0.5, 5.0, 9.999] {
        assert_eq!(s(&t, f), 1.0, "step at {f}");
    }
    assert_eq!(s(&t, 10.0), 5.0);
    assert!((s(&t, 15.0) - 6.0).abs() < 1e-6);
    assert!((s(&t, 12.5) - 5.5).abs() < 1e-6);
}

#[test]
fn bool_tracks_always_step() {
    let t = Track::new(
        target(Property::Visibility),
        Repeat::Constant,
        Keys::Bool(vec![
            Key::new(0.0, true).with_interp(Interp::Tcb),
            Key::new(10.0, false).with_interp(Interp::Linear),
            Key::new(20.0, true),
        ]),
    )
    .expect("valid");
    assert_eq!(t.sample(9.99), Value::Bool(true));
    assert_eq!(t.sample(10.0), Value::Bool(false));
    assert_eq!(t.sample(19.5), Value::Bool(false));
    assert_eq!(t.sample(25.0), Value::Bool(true));
}

#[test]
fn ease_changes_timing_not_path() {
    let plain = wobbly(|i| (0.0, 0.2 * (i % 2) as f32, -0.3));
    let mut eased = plain.clone();
    eased[1].ease_out = 0.7; // ease from key 1 ...
    eased[2].ease_in = 0.5; // ... and to key 2: segment 3..10.
    let a = vtrack(plain, Repeat::Constant);
    let b = vtrack(eased, Repeat::Constant);
    // Dense polyline of the un-eased segment.
    let path: Vec<Vec3> = (0..=4000)
        .map(|i| v(&a, 3.0 + 7.0 * i as f32 / 4000.0))
        .collect();
    let mut max_shift = 0.0f32;
    for i in 1..70 {
        let f = 3.0 + 0.1 * i as f32;
        let p = v(&b, f);
        let d = path
            .iter()
            .map(|q| (*q - p).length())
            .fold(f32::MAX, f32::min);
        assert!(d < 2e-3, "eased point at {f} is {d} off the path");
        max_shift = max_shift.max((p - v(&a, f)).length());
    }
    assert!(max_shift > 0.3, "ease did not change timing ({max_shift})");
    // Slower near both keys of the eased segment, same elsewhere.
    let h = 0.01;
    let speed = |t: &Track, f: f32| (v(t, f + h) - v(t, f)).length() / h;
    assert!(speed(&b, 3.0) < 0.05 * speed(&a, 3.0));
    assert!(speed(&b, 10.0 - h) < 0.05 * speed(&a, 10.0 - h));
    assert!(close(v(&b, 11.0), v(&a, 11.0), 1e-6));
    assert!(close(v(&b, 3.0), v(&a, 3.0), 1e-6) && close(v(&b, 10.0), v(&a, 10.0), 1e-6));
}

#[test]
fn loop_is_continuous_across_the_wrap() {
    let mut keys = wobbly(|i| (if i == 0 || i == 5 { 0.2 } else { -0.1 }, 0.0, 0.3));
    keys[5].value = keys[0].value;
    let t = vtrack(keys.clone(), Repeat::Loop);
    let period = 27.0;
    // Periodic, also before the first key.
    for f in [-40.0f32, -3.3, 1.5, 11.0, 26.9] {
        assert!(close(v(&t, f), v(&t, f + period), 1e-4), "period at {f}");
    }
    // C⁰ and C¹ at the wrap: approach frame 27 from below, frame 0 from above.
    let h = 0.01;
    let left = (v(&t, 27.0 - 2.0 * h) - v(&t, 27.0 - h) * 4.0 + v(&t, 27.0) * 3.0) / (2.0 * h);
    let right = (v(&t, 0.0) * -3.0 + v(&t, h) * 4.0 - v(&t, 2.0 * h)) / (2.0 * h);
    assert!(close(v(&t, 27.0 - 1e-3), keys[0].value, 1e-2));
    assert!(close(left, right, 2e-3), "wrap: left {left} right {right}");
    assert!(left.length() > 0.05);
    // The same keys held constant have a kink there instead.
    let open = vtrack(keys, Repeat::Constant);
    let (l, _) = derivs(&open, 27.0, h);
    assert!(
        !close(l, left, 2e-2),
        "loop tangents should differ from open ones"
    );
}
