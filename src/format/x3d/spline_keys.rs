//! Which animed tracks X3D's own spline interpolators carry exactly, for
//! the X3D writer: the inverse of what [`super::interp`] reads exactly.
//!
//! ISO/IEC 19775-1 §19.2.4 (Hermite spline interpolation): between keys i
//! and i+1 the value is the cubic Hermite curve of v_i, v_{i+1} with
//! tangents T_i = (v_{i+1} − v_{i−1})/2 (Catmull-Rom; zero at the ends of
//! an open curve when no keyVelocity is given), the outgoing tangent
//! scaled by 2·Δt_{i−1}/(Δt_{i−1}+Δt_i) and the incoming by
//! 2·Δt_i/(Δt_{i−1}+Δt_i). animed's Kochanek-Bartels spline with tension =
//! continuity = bias = 0 has the same tangents; where the keys on both
//! sides of every inner key are evenly spaced both scalings are 1 (X3D
//! scales each side by the *other* interval, KB by its own, so uneven
//! spacing differs); tension 1 gives X3D's zero end tangents. So a vector or
//! scalar track is a SplinePositionInterpolator / SplineScalarInterpolator
//! exactly when its keys are TCB with T = C = B = 0 inside, tension 1 (C =
//! B = 0) at both ends, no ease, evenly spaced. §19.4.13
//! SquadOrientationInterpolator is Shoemake's squad with
//! s_i = q_i·exp(−(log(q_i⁻¹q_{i+1}) + log(q_i⁻¹q_{i−1}))/4) and s = q at
//! the open ends: animed's squad-TCB with TCB 0 on even spacing, keyed at
//! both ends of the cycle. Everything else is sampled into linear keys.

use crate::anim::{Interp, Key, Keys, Property, Repeat, Track};

/// The X3D spline node that plays `track` exactly over a cycle of
/// `duration` frames starting at frame 0, if there is one.
pub fn exact_node(track: &Track, duration: f32) -> Option<&'static str> {
    let frames = track.keys.frames();
    let (first, last) = (*frames.first()?, *frames.last()?);
    if frames.len() < 2 || duration.is_nan() || duration <= 0.0 || first < 0.0 || last > duration {
        return None;
    }
    // Outside its keys an X3D interpolator holds its end values: a loop
    // only matches when the keys span the whole cycle.
    let spans = first == 0.0 && last == duration;
    if track.repeat == Repeat::Loop && !spans {
        return None;
    }
    let even = frames.windows(3).all(|w| {
        let (a, b) = (w[1] - w[0], w[2] - w[1]);
        (a - b).abs() <= 1e-5 * a.abs().max(b.abs())
    });
    if !even {
        return None;
    }
    match &track.keys {
        Keys::Scalar(k) if spline_keys(k) => Some("SplineScalarInterpolator"),
        Keys::Vec3(k) if spline_keys(k) && !is_color(track.target.property) => {
            Some("SplinePositionInterpolator")
        }
        Keys::Rotation(k) if spans && squad_keys(k) => Some("SquadOrientationInterpolator"),
        _ => None,
    }
}

/// Colours are SFColor: X3D has no spline interpolator for them.
fn is_color(p: Property) -> bool {
    matches!(
        p,
        Property::LightColor | Property::Diffuse | Property::Emissive | Property::Specular
    )
}

fn plain<V>(k: &Key<V>) -> bool {
    k.interp == Interp::Tcb
        && k.continuity == 0.0
        && k.bias == 0.0
        && k.ease_in == 0.0
        && k.ease_out == 0.0
}

fn spline_keys<V>(keys: &[Key<V>]) -> bool {
    let n = keys.len();
    keys.iter().enumerate().all(|(i, k)| {
        let end = i == 0 || i + 1 == n;
        // The last key's interpolation starts no segment.
        (plain(k) || (i + 1 == n && k.continuity == 0.0 && k.bias == 0.0))
            && k.tension == if end { 1.0 } else { 0.0 }
    })
}

fn squad_keys<V>(keys: &[Key<V>]) -> bool {
    let n = keys.len();
    keys.iter()
        .enumerate()
        .all(|(i, k)| (plain(k) || i + 1 == n) && k.tension == 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Target, TargetRef};
    use crate::scene::NodeId;
    use glam::Vec3;

    fn track(keys: Vec<Key<Vec3>>, repeat: Repeat) -> Track {
        Track::new(
            Target {
                of: TargetRef::Node(NodeId(0)),
                property: Property::Translation,
            },
            repeat,
            Keys::Vec3(keys),
        )
        .unwrap()
    }

    fn key(frame: f32, tension: f32) -> Key<Vec3> {
        let mut k = Key::new(frame, Vec3::splat(frame)).with_interp(Interp::Tcb);
        k.tension = tension;
        k
    }

    #[test]
    fn only_evenly_spaced_catmull_rom_with_flat_ends_is_exact() {
        let ok = vec![key(0.0, 1.0), key(10.0, 0.0), key(20.0, 1.0)];
        assert_eq!(
            exact_node(&track(ok.clone(), Repeat::Loop), 20.0),
            Some("SplinePositionInterpolator")
        );
        // Uneven spacing, inner tension, end tangents not flat, a loop that
        // does not span the cycle: sampled.
        let uneven = vec![key(0.0, 1.0), key(5.0, 0.0), key(20.0, 1.0)];
        assert_eq!(exact_node(&track(uneven, Repeat::Constant), 20.0), None);
        let mut tense = ok.clone();
        tense[1].tension = 0.5;
        assert_eq!(exact_node(&track(tense, Repeat::Constant), 20.0), None);
        let mut ends = ok.clone();
        ends[0].tension = 0.0;
        assert_eq!(exact_node(&track(ends, Repeat::Constant), 20.0), None);
        assert_eq!(exact_node(&track(ok.clone(), Repeat::Loop), 30.0), None);
        assert_eq!(
            exact_node(&track(ok, Repeat::Constant), 30.0),
            Some("SplinePositionInterpolator")
        );
    }
}
