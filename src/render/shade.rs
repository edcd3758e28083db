//! Per-pixel lighting: the VRML97 lighting model (ISO/IEC 14772-1 §4.14.4),
//!
//! ```text
//! I = O_E + Σ_i on_i · att_i · spot_i · I_L,i · (ambient_i + diffuse_i + specular_i)
//!   ambient_i  = I_ia · O_D · O_a
//!   diffuse_i  = I_i · O_D · max(N·L, 0)
//!   specular_i = I_i · O_S · max(N·H, 0)^(shininess·128),  H = (L + V)/|L + V|
//!   att_i      = 1 / max(c1 + c2·d + c3·d², 1)   (point and spot lights)
//! ```
//! Spot lights use the VRML ramp between beamWidth and cutOffAngle, or,
//! when Inventor's dropOffRate is non-zero, `cos(angle)^(128·rate)` inside
//! the cut-off (the OpenGL spot exponent Inventor maps dropOffRate to).
//! Lights are prepared once per frame in world space.

use crate::scene::{Light, LightKind, Material};
use glam::{Mat4, Vec3};

/// A light in world space, ready for [`shade`].
#[derive(Clone, Debug, PartialEq)]
pub struct WorldLight {
    pub kind: WorldLightKind,
    /// colour × intensity (diffuse and specular strength).
    pub color: Vec3,
    /// colour × ambientIntensity.
    pub ambient: Vec3,
    pub attenuation: Vec3,
}

#[derive(Clone, Debug, PartialEq)]
pub enum WorldLightKind {
    /// `to_light` is the unit direction towards the light (−direction).
    Directional {
        to_light: Vec3,
    },
    Point {
        location: Vec3,
        radius: f32,
    },
    Spot {
        location: Vec3,
        radius: f32,
        /// Unit direction the spot points along.
        axis: Vec3,
        cos_cut_off: f32,
        cut_off: f32,
        beam_width: f32,
        /// 128·dropOffRate; 0 = use the VRML ramp.
        exponent: f32,
    },
}

impl WorldLight {
    /// Places `light` (in the coordinates of a node with matrix `world`).
    /// `None` for lights that are off or contribute nothing.
    pub fn new(light: &Light, world: Mat4) -> Option<WorldLight> {
        if !light.on || !(light.intensity > 0.0 || light.ambient_intensity > 0.0) {
            return None;
        }
        let dir = world.transform_vector3(light.direction).normalize_or_zero();
        let location = world.transform_point3(light.location);
        // Radii scale with the node's (average) scale.
        let scale = world.determinant().abs().cbrt();
        let radius = light.radius * if scale.is_finite() { scale } else { 1.0 };
        let kind = match light.kind {
            LightKind::Directional => WorldLightKind::Directional { to_light: -dir },
            LightKind::Point => WorldLightKind::Point { location, radius },
            LightKind::Spot {
                beam_width,
                cut_off_angle,
                drop_off_rate,
            } => WorldLightKind::Spot {
                location,
                radius,
                axis: dir,
                cos_cut_off: libm::cosf(cut_off_angle),
                cut_off: cut_off_angle,
                beam_width,
                exponent: 128.0 * drop_off_rate.clamp(0.0, 1.0),
            },
        };
        Some(WorldLight {
            kind,
            color: light.color * light.intensity.clamp(0.0, 1.0),
            ambient: light.color * light.ambient_intensity.clamp(0.0, 1.0),
            attenuation: light.attenuation,
        })
    }

    /// The headlight: a white directional light of intensity 1 shining along
    /// the view direction (what Coin's and VRML browsers' headlights are).
    pub fn headlight(forward: Vec3) -> WorldLight {
        WorldLight {
            kind: WorldLightKind::Directional { to_light: -forward },
            color: Vec3::ONE,
            ambient: Vec3::ZERO,
            attenuation: Vec3::new(1.0, 0.0, 0.0),
        }
    }
}

/// A material ready for shading.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadeMaterial {
    pub diffuse: Vec3,
    pub ambient_intensity: f32,
    pub specular: Vec3,
    pub emissive: Vec3,
    /// shininess·128, rounded to an integer so `powi` is exact and fast.
    pub exponent: i32,
    /// 1 − transparency.
    pub alpha: f32,
}

impl ShadeMaterial {
    pub fn new(m: &Material) -> ShadeMaterial {
        ShadeMaterial {
            diffuse: m.diffuse,
            ambient_intensity: m.ambient_intensity,
            specular: m.specular,
            emissive: m.emissive,
            exponent: (m.shininess.clamp(0.0, 1.0) * 128.0).round() as i32,
            alpha: 1.0 - m.transparency.clamp(0.0, 1.0),
        }
    }
}

/// The VRML97 colour of a surface point `p` with unit normal `n` (already
/// facing the viewer for two-sided surfaces), seen from `eye`. `diffuse` is
/// the material's diffuse colour or the per-vertex colour that replaces it.
#[inline]
pub fn shade(
    m: &ShadeMaterial,
    diffuse: Vec3,
    lights: &[WorldLight],
    p: Vec3,
    n: Vec3,
    eye: Vec3,
) -> Vec3 {
    let v = (eye - p).normalize_or_zero();
    let mut sum = m.emissive;
    for l in lights {
        let (to_light, factor) = match l.kind {
            WorldLightKind::Directional { to_light } => (to_light, 1.0),
            WorldLightKind::Point { location, radius } => {
                let d = location - p;
                let dist = d.length();
                if dist > radius || dist == 0.0 {
                    continue;
                }
                (d / dist, attenuation(l.attenuation, dist))
            }
            WorldLightKind::Spot {
                location,
                radius,
                axis,
                cos_cut_off,
                cut_off,
                beam_width,
                exponent,
            } => {
                let d = location - p;
                let dist = d.length();
                if dist > radius || dist == 0.0 {
                    continue;
                }
                let to_light = d / dist;
                let cos_angle = -to_light.dot(axis);
                if cos_angle <= cos_cut_off {
                    continue;
                }
                let spot = if exponent > 0.0 {
                    libm::powf(cos_angle, exponent)
                } else {
                    let angle = libm::acosf(cos_angle.clamp(-1.0, 1.0));
                    if angle <= beam_width {
                        1.0
                    } else {
                        ((angle - cut_off) / (beam_width - cut_off)).clamp(0.0, 1.0)
                    }
                };
                (to_light, attenuation(l.attenuation, dist) * spot)
            }
        };
        if !(factor > 0.0) {
            continue;
        }
        let mut c = l.ambient * diffuse * m.ambient_intensity;
        let ndl = n.dot(to_light);
        if ndl > 0.0 {
            c += l.color * diffuse * ndl;
            if m.exponent > 0 && m.specular != Vec3::ZERO {
                let h = (to_light + v).normalize_or_zero();
                let ndh = n.dot(h);
                if ndh > 0.0 {
                    c += l.color * m.specular * pow_int(ndh, m.exponent as u32);
                }
            } else if m.exponent == 0 {
                // x^0 = 1: a fully matte-shiny (shininess 0) surface still gets
                // its specular colour wherever it is lit.
                c += l.color * m.specular;
            }
        }
        sum += c * factor;
    }
    sum
}

/// `x^e` by repeated squaring: exact same bits on every machine and build
/// (the design rules out platform `powf` for specular powers).
#[inline]
pub fn pow_int(mut x: f32, mut e: u32) -> f32 {
    let mut r = 1.0;
    while e > 0 {
        if e & 1 == 1 {
            r *= x;
        }
        x *= x;
        e >>= 1;
    }
    r
}

/// VRML97 attenuation `1 / max(c1 + c2·d + c3·d², 1)`.
#[inline]
fn attenuation(a: Vec3, d: f32) -> f32 {
    1.0 / (a.x + a.y * d + a.z * d * d).max(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mat() -> ShadeMaterial {
        ShadeMaterial::new(&Material {
            diffuse: Vec3::ONE,
            ambient_intensity: 0.0,
            ..Material::default()
        })
    }

    #[test]
    fn directional_diffuse_is_cosine() {
        let l = WorldLight::new(&Light::new(LightKind::Directional), Mat4::IDENTITY).unwrap();
        // Light shines down −z; a surface facing +z at 60° gets cos 60°.
        let n = Vec3::new(0.0, 0.75f32.sqrt(), 0.5);
        let c = shade(&mat(), Vec3::ONE, &[l], Vec3::ZERO, n, Vec3::Z * 5.0);
        assert!((c.x - 0.5).abs() < 1e-5, "{c}");
    }

    #[test]
    fn point_light_attenuation_and_radius() {
        let mut light = Light::new(LightKind::Point);
        light.location = Vec3::new(0.0, 0.0, 4.0);
        light.attenuation = Vec3::new(0.0, 0.0, 1.0); // 1/d²
        light.radius = 10.0;
        let l = WorldLight::new(&light, Mat4::IDENTITY).unwrap();
        let c = shade(
            &mat(),
            Vec3::ONE,
            &[l.clone()],
            Vec3::ZERO,
            Vec3::Z,
            Vec3::Z,
        );
        assert!((c.x - 1.0 / 16.0).abs() < 1e-6, "{c}");
        // Beyond the radius: nothing.
        let far = Vec3::new(0.0, 0.0, -7.0);
        let c = shade(&mat(), Vec3::ONE, &[l], far, Vec3::Z, Vec3::Z);
        assert_eq!(c, Vec3::ZERO);
    }

    #[test]
    fn spot_ramp_between_beam_and_cut_off() {
        let mut light = Light::new(LightKind::Spot {
            beam_width: 0.2,
            cut_off_angle: 0.4,
            drop_off_rate: 0.0,
        });
        light.location = Vec3::new(0.0, 0.0, 1.0);
        let l = WorldLight::new(&light, Mat4::IDENTITY).unwrap();
        let at = |angle: f32| {
            let p = Vec3::new(angle.tan(), 0.0, 0.0);
            shade(&mat(), Vec3::ONE, &[l.clone()], p, Vec3::Z, Vec3::Z).x / angle.cos()
        };
        assert!((at(0.1) - 1.0).abs() < 1e-4);
        assert!((at(0.3) - 0.5).abs() < 1e-3, "{}", at(0.3));
        assert_eq!(at(0.45), 0.0);
    }

    #[test]
    fn drop_off_rate_is_a_cosine_power() {
        let mut light = Light::new(LightKind::Spot {
            beam_width: 0.2,
            cut_off_angle: 0.8,
            drop_off_rate: 0.5,
        });
        light.location = Vec3::new(0.0, 0.0, 1.0);
        let l = WorldLight::new(&light, Mat4::IDENTITY).unwrap();
        let a: f32 = 0.3;
        let p = Vec3::new(a.tan(), 0.0, 0.0);
        let c = shade(&mat(), Vec3::ONE, &[l], p, Vec3::Z, Vec3::Z).x;
        let want = a.cos().powf(64.0) * a.cos();
        assert!((c - want).abs() < 1e-5, "{c} vs {want}");
    }

    #[test]
    fn specular_peaks_at_mirror_direction() {
        let m = ShadeMaterial::new(&Material {
            diffuse: Vec3::ZERO,
            specular: Vec3::ONE,
            shininess: 0.5,
            ambient_intensity: 0.0,
            ..Material::default()
        });
        assert_eq!(m.exponent, 64);
        let l = WorldLight::new(&Light::new(LightKind::Directional), Mat4::IDENTITY).unwrap();
        let c = shade(
            &m,
            Vec3::ZERO,
            &[l.clone()],
            Vec3::ZERO,
            Vec3::Z,
            Vec3::Z * 3.0,
        );
        assert!((c.x - 1.0).abs() < 1e-6);
        let tilted = Vec3::new(0.2, 0.0, 1.0).normalize();
        let c = shade(&m, Vec3::ZERO, &[l], Vec3::ZERO, tilted, Vec3::Z * 3.0);
        assert!((c.x - tilted.z.powi(64)).abs() < 1e-6);
        assert_eq!(pow_int(0.5, 10), 1.0 / 1024.0);
    }

    #[test]
    fn ambient_and_emissive() {
        let mut light = Light::new(LightKind::Directional);
        light.ambient_intensity = 0.5;
        light.intensity = 0.0;
        let l = WorldLight::new(&light, Mat4::IDENTITY).unwrap();
        let m = ShadeMaterial::new(&Material {
            diffuse: Vec3::ONE,
            ambient_intensity: 0.4,
            emissive: Vec3::new(0.1, 0.0, 0.0),
            ..Material::default()
        });
        let c = shade(&m, Vec3::ONE, &[l], Vec3::ZERO, Vec3::NEG_Z, Vec3::Z);
        assert!((c - Vec3::new(0.3, 0.2, 0.2)).length() < 1e-6, "{c}");
    }
}
