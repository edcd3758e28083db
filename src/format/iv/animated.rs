//! Inventor's self-animating nodes as tracks: Rotor (a Rotation spinning at
//! `speed` turns per second), Pendulum (swinging between rotation0 and
//! rotation1) and Shuttle (moving between translation0 and translation1),
//! one full period per `1/speed` seconds, looping.

use crate::anim::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track};
use crate::format::syntax::AstNode;
use crate::scene::{NodeId, Scene};
use glam::{Quat, Vec3};

/// Keys per period; Pendulum/Shuttle follow Inventor's sinusoidal swing.
const STEPS: usize = 16;

/// True for the node types this module animates.
pub fn is_animated(kind: &str) -> bool {
    matches!(kind, "Rotor" | "Pendulum" | "Shuttle")
}

/// Adds the looping track of animated node `n` (a group at `id`).
pub fn add_track(scene: &mut Scene, n: &AstNode, id: NodeId) -> Result<(), String> {
    if !n.bool("on", true) {
        return Ok(());
    }
    let speed = n.f32("speed", 1.0);
    if !(speed.is_finite() && speed > 1e-4) {
        return Ok(());
    }
    let fps = scene.settings.fps.max(1.0);
    let period = fps / speed;
    let frame = |i: usize| period * i as f32 / STEPS as f32;
    // Sinusoidal swing 0 → 1 → 0 over one period.
    let swing = |i: usize| (1.0 - (std::f32::consts::TAU * i as f32 / STEPS as f32).cos()) / 2.0;
    let (property, keys) = match n.kind.as_str() {
        "Rotor" => {
            let r = n.nums("rotation").unwrap_or(&[]);
            let (axis, angle) = if r.len() >= 4 {
                (
                    Vec3::new(r[0] as f32, r[1] as f32, r[2] as f32),
                    r[3] as f32,
                )
            } else {
                (Vec3::Z, 0.0)
            };
            let axis = axis.try_normalize().unwrap_or(Vec3::Z);
            let keys = (0..=STEPS)
                .map(|i| {
                    let a = angle + std::f32::consts::TAU * i as f32 / STEPS as f32;
                    Key::new(frame(i), Quat::from_axis_angle(axis, a)).with_interp(Interp::Linear)
                })
                .collect();
            (Property::Rotation, Keys::Rotation(keys))
        }
        "Pendulum" => {
            let a = n.rotation("rotation0").unwrap_or(Quat::IDENTITY);
            let b = n.rotation("rotation1").unwrap_or(Quat::IDENTITY);
            let keys = (0..=STEPS)
                .map(|i| Key::new(frame(i), a.slerp(b, swing(i))).with_interp(Interp::Linear))
                .collect();
            (Property::Rotation, Keys::Rotation(keys))
        }
        _ => {
            let a = n.vec3("translation0", Vec3::ZERO);
            let b = n.vec3("translation1", Vec3::ZERO);
            let keys = (0..=STEPS)
                .map(|i| Key::new(frame(i), a.lerp(b, swing(i))).with_interp(Interp::Linear))
                .collect();
            (Property::Translation, Keys::Vec3(keys))
        }
    };
    let target = Target {
        of: TargetRef::Node(id),
        property,
    };
    let t = Track::new(target, Repeat::Loop, keys).map_err(|e| e.to_string())?;
    let first = scene.animation.tracks.is_empty();
    scene.animation.tracks.push(t);
    scene.settings.duration = if first {
        period
    } else {
        scene.settings.duration.max(period)
    };
    Ok(())
}
