//! KHR_lights_punctual and cameras → animed lights and cameras.
//!
//! **Light units, the one place they are converted.** KHR_lights_punctual
//! gives point and spot intensity in candela (falling off as 1/d²) and
//! directional intensity in lux. A Lambertian surface of albedo ρ lit with
//! illuminance E shows ρ·E/π (the Lambert BRDF is ρ/π), which is what
//! physically based viewers such as three.js draw. animed's VRML97 model
//! draws colour·intensity·ρ/max(c + l·d + q·d², 1), with intensity at most
//! 1. So:
//! * directional: intensity = min(E/π, 1);
//! * point and spot: intensity = 1 and attenuation (0, 0, π/I), giving
//!   min(I/(π·d²), 1): the physical falloff, clamped where VRML clamps;
//! * `range` → `radius` (no range: unlimited); spot `innerConeAngle` →
//!   beam width, `outerConeAngle` → cut-off angle (both are angles from
//!   the axis in either model);
//! * colours are linear in glTF and converted like material colours.
//!
//! The writer inverts this in [`punctual_from_light`]; VRML attenuations
//! that are not pure inverse-square are matched at a reference distance
//! (half the scene's diagonal).

use super::material::{linear_from_srgb, srgb_from_linear};
use crate::scene::{Camera, CameraKind, Light, LightKind};
use glam::Vec3;
use std::f32::consts::PI;

/// A KHR_lights_punctual light as plain numbers (linear colour).
#[derive(Clone, Debug, PartialEq)]
pub struct Punctual {
    pub kind: PunctualKind,
    pub color: Vec3,
    pub intensity: f32,
    pub range: Option<f32>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PunctualKind {
    Directional,
    Point,
    Spot { inner: f32, outer: f32 },
}

impl Punctual {
    pub fn from_gltf(l: &gltf::khr_lights_punctual::Light) -> Punctual {
        use gltf::khr_lights_punctual::Kind;
        Punctual {
            kind: match l.kind() {
                Kind::Directional => PunctualKind::Directional,
                Kind::Point => PunctualKind::Point,
                Kind::Spot {
                    inner_cone_angle,
                    outer_cone_angle,
                } => PunctualKind::Spot {
                    inner: inner_cone_angle,
                    outer: outer_cone_angle,
                },
            },
            color: Vec3::from(l.color()),
            intensity: l.intensity(),
            range: l.range(),
        }
    }
}

/// KHR_lights_punctual → VRML97 light (module doc: the unit conversion).
pub fn light_from_punctual(p: &Punctual) -> Light {
    let mut light = match p.kind {
        PunctualKind::Directional => Light::new(LightKind::Directional),
        PunctualKind::Point => Light::new(LightKind::Point),
        PunctualKind::Spot { inner, outer } => Light::new(LightKind::Spot {
            beam_width: inner,
            cut_off_angle: outer,
            drop_off_rate: 0.0,
        }),
    };
    light.color = srgb_from_linear(p.color);
    let i = p.intensity.max(0.0);
    match p.kind {
        PunctualKind::Directional => light.intensity = (i / PI).min(1.0),
        _ => {
            light.intensity = if i > 0.0 { 1.0 } else { 0.0 };
            light.attenuation = Vec3::new(0.0, 0.0, if i > 0.0 { PI / i } else { 1.0 });
        }
    }
    light.radius = p.range.filter(|r| *r > 0.0).unwrap_or(f32::MAX);
    light.location = Vec3::ZERO;
    light.direction = Vec3::NEG_Z;
    light
}

/// VRML97 light → KHR_lights_punctual (the writer's direction).
/// `reference` is the distance at which a non-inverse-square attenuation is
/// matched (half the scene's diagonal).
pub fn punctual_from_light(l: &Light, reference: f32) -> Punctual {
    let kind = match l.kind {
        LightKind::Directional => PunctualKind::Directional,
        LightKind::Point => PunctualKind::Point,
        LightKind::Spot {
            beam_width,
            cut_off_angle,
            ..
        } => PunctualKind::Spot {
            inner: beam_width.min(cut_off_angle).clamp(0.0, PI / 2.0),
            outer: cut_off_angle.clamp(0.0, PI / 2.0),
        },
    };
    let on = if l.on {
        l.intensity.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let intensity = match kind {
        PunctualKind::Directional => on * PI,
        _ => {
            let a = l.attenuation;
            if a.x == 0.0 && a.y == 0.0 && a.z > 0.0 {
                on * PI / a.z
            } else {
                let d = if reference.is_finite() && reference > 0.0 {
                    reference
                } else {
                    1.0
                };
                PI * d * d * on / (a.x + a.y * d + a.z * d * d).max(1.0)
            }
        }
    };
    Punctual {
        kind,
        color: linear_from_srgb(l.color),
        intensity,
        range: (l.radius.is_finite()
            && l.radius < f32::MAX
            && !matches!(kind, PunctualKind::Directional))
        .then_some(l.radius),
    }
}

/// The exact light animed wrote into `extras.animed`, when the glTF values
/// still say what animed wrote for it; `direction` and `location` come from
/// the placement node animed wrote beside it (see `read`).
pub fn light_from_extras(l: &gltf::khr_lights_punctual::Light, read: &Punctual) -> Option<Light> {
    extras_light(l, read).map(|(light, _)| light)
}

/// [`light_from_extras`] with the reference distance its intensity was
/// mapped with, from one parse of the extras.
fn extras_light(l: &gltf::khr_lights_punctual::Light, read: &Punctual) -> Option<(Light, f32)> {
    let raw = l.extras().as_ref()?;
    let v: serde_json::Value = serde_json::from_str(raw.get()).ok()?;
    let a = v.get("animed")?;
    let f = |k: &str| a.get(k)?.as_f64().map(|x| x as f32);
    let b = |k: &str| a.get(k)?.as_bool();
    let att: Vec<f32> = a
        .get("attenuation")?
        .as_array()?
        .iter()
        .filter_map(|x| x.as_f64().map(|x| x as f32))
        .collect();
    if att.len() != 3 {
        return None;
    }
    let mut light = light_from_punctual(read);
    light.intensity = f("intensity")?;
    light.on = b("on")?;
    light.ambient_intensity = f("ambientIntensity")?;
    light.attenuation = Vec3::new(att[0], att[1], att[2]);
    light.radius = f("radius")?;
    light.scoped = b("scoped")?;
    if let (LightKind::Spot { .. }, PunctualKind::Spot { inner, outer }) = (&light.kind, read.kind)
    {
        // The writer clamps cones into glTF's range; keep what it wrote.
        light.kind = LightKind::Spot {
            beam_width: inner,
            cut_off_angle: outer,
            drop_off_rate: 0.0,
        };
    }
    let reference = f("reference")?;
    let mut want = punctual_from_light(&light, reference);
    want.color = read.color;
    (want.intensity == read.intensity && want.range == read.range).then_some((light, reference))
}

/// A light animed wrote (restored exactly by [`light_from_extras`]) and
/// the reference distance its intensity was mapped with.
pub fn animed_light(l: &gltf::khr_lights_punctual::Light) -> Option<(Light, f32)> {
    extras_light(l, &Punctual::from_gltf(l))
}

/// The inverse of [`punctual_from_light`]'s intensity for a light that is
/// on: the animed intensity whose glTF intensity is `e` (an animated
/// intensity of a light animed wrote, read back without its key note).
pub fn intensity_from_punctual(l: &Light, e: f32, reference: f32) -> f32 {
    let e = e.max(0.0);
    match l.kind {
        LightKind::Directional => (e / PI).min(1.0),
        _ => {
            let a = l.attenuation;
            if a.x == 0.0 && a.y == 0.0 && a.z > 0.0 {
                e * a.z / PI
            } else {
                let d = if reference.is_finite() && reference > 0.0 {
                    reference
                } else {
                    1.0
                };
                e * (a.x + a.y * d + a.z * d * d).max(1.0) / (PI * d * d)
            }
        }
    }
}

/// A glTF camera (§3.10) → animed camera at its node's origin looking down −z.
pub fn camera_from_gltf(c: &gltf::Camera) -> Camera {
    let (kind, near, far) = match c.projection() {
        gltf::camera::Projection::Perspective(p) => (
            CameraKind::Perspective {
                height_angle: p.yfov(),
            },
            p.znear(),
            p.zfar(),
        ),
        gltf::camera::Projection::Orthographic(o) => (
            CameraKind::Orthographic {
                height: 2.0 * o.ymag(),
            },
            o.znear(),
            Some(o.zfar()),
        ),
    };
    Camera {
        kind,
        position: Vec3::ZERO,
        orientation: glam::Quat::IDENTITY,
        description: c.name().unwrap_or_default().to_string(),
        fov_smaller_side: false,
        near: (near > 0.0).then_some(near),
        far: far.filter(|f| *f > 0.0),
        ..Camera::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_light_falls_off_as_candela_over_pi_d_squared() {
        let l = light_from_punctual(&Punctual {
            kind: PunctualKind::Point,
            color: Vec3::ONE,
            intensity: 100.0,
            range: Some(20.0),
        });
        let at = |d: f32| {
            let a = l.attenuation;
            l.intensity / (a.x + a.y * d + a.z * d * d).max(1.0)
        };
        // 100 cd at 10 m: 1 lux, shown as 1/π.
        assert!((at(10.0) - 1.0 / PI).abs() < 1e-6);
        assert_eq!(at(1.0), 1.0, "clamped near the light as VRML clamps");
        assert_eq!(l.radius, 20.0);
        let back = punctual_from_light(&l, 5.0);
        assert!((back.intensity - 100.0).abs() < 1e-3);
        assert_eq!(back.range, Some(20.0));
    }

    #[test]
    fn directional_lux_and_spot_cones() {
        let sun = light_from_punctual(&Punctual {
            kind: PunctualKind::Directional,
            color: Vec3::ONE,
            intensity: 2.0,
            range: None,
        });
        assert!((sun.intensity - 2.0 / PI).abs() < 1e-6);
        assert!((punctual_from_light(&sun, 1.0).intensity - 2.0).abs() < 1e-5);
        let spot = light_from_punctual(&Punctual {
            kind: PunctualKind::Spot {
                inner: 0.2,
                outer: 0.5,
            },
            color: Vec3::new(1.0, 0.5, 0.0),
            intensity: 10.0,
            range: None,
        });
        assert!(matches!(
            spot.kind,
            LightKind::Spot { beam_width, cut_off_angle, .. } if beam_width == 0.2 && cut_off_angle == 0.5
        ));
        assert_eq!(spot.radius, f32::MAX);
        assert!((spot.color.y - 0.735_36).abs() < 1e-4);
    }

    #[test]
    fn vrml_lights_without_falloff_match_at_the_reference_distance() {
        let mut l = Light::new(LightKind::Point);
        l.intensity = 0.5;
        let p = punctual_from_light(&l, 4.0);
        // I/(π·16) must equal 0.5 at d = 4.
        assert!((p.intensity / (PI * 16.0) - 0.5).abs() < 1e-6);
    }
}
