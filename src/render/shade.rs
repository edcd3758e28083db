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

use super::simd::{Lanes, Sse8, V8};
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
        /// cos(beamWidth): inside it the spot term is 1.
        cos_beam: f32,
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
                cos_beam: libm::cosf(beam_width),
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

/// The VRML97 colour of a surface point `p` with normal `n` (already
/// facing the viewer for two-sided surfaces), seen from `eye`. `diffuse` is
/// the material's diffuse colour or the per-vertex colour that replaces it.
/// One pixel through the same [`shade8`] the shading pass uses (all lanes
/// alike), so a lone pixel gets exactly the bits a block would give it.
pub fn shade(
    m: &ShadeMaterial,
    diffuse: Vec3,
    lights: &[WorldLight],
    p: Vec3,
    n: Vec3,
    eye: Vec3,
) -> Vec3 {
    let s = |v: Vec3| {
        [
            <Sse8 as Lanes>::splat(v.x),
            <Sse8 as Lanes>::splat(v.y),
            <Sse8 as Lanes>::splat(v.z),
        ]
    };
    let c = shade8(m, lights, eye, s(p), s(n), s(diffuse));
    let lane0 = |v: Sse8| {
        let mut a = [0.0; 8];
        v.store(&mut a);
        a[0]
    };
    Vec3::new(lane0(c[0]), lane0(c[1]), lane0(c[2]))
}

#[inline(always)]
fn dot<V: Lanes>(a: &[V; 3], b: &[V; 3]) -> V {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline(always)]
fn splat3<V: Lanes>(v: Vec3) -> [V; 3] {
    [V::splat(v.x), V::splat(v.y), V::splat(v.z)]
}

/// `v / |v|`, or zero for a zero vector; also returns |v|.
#[inline(always)]
fn normalize<V: Lanes>(v: [V; 3]) -> ([V; 3], V) {
    let len = dot(&v, &v).sqrt();
    let zero = V::splat(0.0);
    let inv = (V::splat(1.0) / len).keep(len.gt(zero));
    ([v[0] * inv, v[1] * inv, v[2] * inv], len)
}

/// The lighting model for eight pixels of one material: world positions
/// `p`, normals `n` (any length; normalised here) and diffuse colours.
/// Every lane does exactly the arithmetic a lone pixel would, so grouping
/// never changes a result; per-light and per-material constants are
/// computed once per call, outside the lane arithmetic.
#[inline(always)]
pub fn shade8<V: Lanes>(
    m: &ShadeMaterial,
    lights: &[WorldLight],
    eye: Vec3,
    p: [V; 3],
    n: [V; 3],
    diffuse: [V; 3],
) -> [V; 3] {
    let zero = V::splat(0.0);
    let one = V::splat(1.0);
    let (n, _) = normalize(n);
    let e: [V; 3] = splat3(eye);
    let (v, _) = normalize([e[0] - p[0], e[1] - p[1], e[2] - p[2]]);
    let mut sum: [V; 3] = splat3(m.emissive);
    let use_specular = m.specular != Vec3::ZERO;
    for l in lights {
        if l.color == Vec3::ZERO {
            if let WorldLightKind::Directional { .. } = l.kind {
                // Ambient only (Inventor's global ambient, a light of
                // intensity 0): attenuation and spot are 1, and the direct
                // terms below are 0·x, so the term is ambient × diffuse.
                // Adding +0 keeps the sign of a zero as the full sum
                // would; no vector, square root or division per lane.
                let amb = l.ambient * m.ambient_intensity;
                for ch in 0..3 {
                    let term = V::splat(amb[ch]) * diffuse[ch] + zero;
                    sum[ch] = sum[ch] + term;
                }
                continue;
            }
        }
        // Unit vector to the light and attenuation × spot factor per lane
        // (0 where the light does not reach).
        let (to_light, factor) = match l.kind {
            WorldLightKind::Directional { to_light } => (splat3(to_light), one),
            WorldLightKind::Point {
                location, radius, ..
            }
            | WorldLightKind::Spot {
                location, radius, ..
            } => {
                let loc: [V; 3] = splat3(location);
                let (to_light, dist) = normalize([loc[0] - p[0], loc[1] - p[1], loc[2] - p[2]]);
                let a = l.attenuation;
                let denom =
                    (V::splat(a.x) + V::splat(a.y) * dist + V::splat(a.z) * (dist * dist)).max(one);
                let reach = dist.le(V::splat(radius)).and(dist.gt(zero));
                let mut factor = (one / denom).keep(reach);
                if let WorldLightKind::Spot { axis, .. } = l.kind {
                    let cos = zero - dot(&to_light, &splat3(axis));
                    factor = spot(&l.kind, factor, cos);
                }
                (to_light, factor)
            }
        };
        let amb = l.ambient * m.ambient_intensity;
        let ndl = dot(&n, &to_light).max(zero);
        let spec = if use_specular {
            let (h, _) = normalize([to_light[0] + v[0], to_light[1] + v[1], to_light[2] + v[2]]);
            let ndh = dot(&n, &h).max(zero);
            powi(ndh, m.exponent as u32).keep(ndl.gt(zero))
        } else {
            zero
        };
        for ch in 0..3 {
            let term = V::splat(amb[ch]) * diffuse[ch]
                + V::splat(l.color[ch]) * diffuse[ch] * ndl
                + V::splat(l.color[ch] * m.specular[ch]) * spec;
            sum[ch] = sum[ch] + factor * term;
        }
    }
    sum
}

/// The spot term multiplied into `factor`, for lanes whose direction from
/// the light makes cosine `cos` with the spot axis: 0 outside the cut-off;
/// inside it either `cos^exponent` (Inventor dropOffRate) or the VRML97
/// ramp — 1 within the beam width, linear in the angle down to 0 at the
/// cut-off.
#[inline(always)]
fn spot<V: Lanes>(kind: &WorldLightKind, factor: V, cos: V) -> V {
    let WorldLightKind::Spot {
        cos_cut_off,
        cos_beam,
        cut_off,
        beam_width,
        exponent,
        ..
    } = *kind
    else {
        return factor;
    };
    let zero = V::splat(0.0);
    let inside = cos.gt(V::splat(cos_cut_off)).and(factor.gt(zero));
    let factor = factor.keep(inside);
    if inside.bits() == 0 {
        return factor;
    }
    if exponent > 0.0 {
        let c = cos.max(zero);
        if exponent.fract() == 0.0 && exponent <= 128.0 {
            // An integer exponent (dropOffRate k/128): exact repeated squaring.
            return factor * powi(c, exponent as u32);
        }
        return factor.map2(c, |f, c| {
            if f != 0.0 {
                f * libm::powf(c, exponent)
            } else {
                f
            }
        });
    }
    let full = V::splat(cos_beam).le(cos);
    if full.bits() & inside.bits() == inside.bits() {
        return factor;
    }
    let ramp = (acos(cos) - V::splat(cut_off)) / V::splat(beam_width - cut_off);
    let ramp = ramp.max(zero).min(V::splat(1.0));
    V::select(full, factor, factor * ramp)
}

/// arccos per lane from Abramowitz & Stegun, Handbook of Mathematical
/// Functions, 4.4.46: `acos x = √(1−x)·(a0 + a1·x + … + a7·x⁷)` for
/// 0 ≤ x ≤ 1 (absolute error ≤ 2·10⁻⁸), and `acos x = π − acos(−x)` below
/// 0. Only + − × √, so every machine gives the same bits.
#[inline(always)]
fn acos<V: Lanes>(x: V) -> V {
    // a0 is A&S's coefficient (one f32 ulp below π/2), not π/2 itself.
    #[allow(clippy::approx_constant)]
    const A: [f32; 8] = [
        1.570_796_3,
        -0.214_598_8,
        0.088_978_99,
        -0.050_174_303,
        0.030_891_88,
        -0.017_088_126,
        0.006_670_09,
        -0.001_262_491_1,
    ];
    let zero = V::splat(0.0);
    let one = V::splat(1.0);
    let neg = zero.gt(x);
    let a = V::select(neg, zero - x, x).min(one);
    let mut poly = V::splat(A[7]);
    for &c in A[..7].iter().rev() {
        poly = poly * a + V::splat(c);
    }
    let r = (one - a).sqrt() * poly;
    V::select(neg, V::splat(std::f32::consts::PI) - r, r)
}

/// `x^e` per lane by repeated squaring: the same bits on every machine and
/// build, unlike platform `powf`.
#[inline(always)]
fn powi<V: Lanes>(mut x: V, mut e: u32) -> V {
    let mut r = V::splat(1.0);
    while e > 0 {
        if e & 1 == 1 {
            r = r * x;
        }
        x = x * x;
        e >>= 1;
    }
    r
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
            std::slice::from_ref(&l),
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
            shade(
                &mat(),
                Vec3::ONE,
                std::slice::from_ref(&l),
                p,
                Vec3::Z,
                Vec3::Z,
            )
            .x / angle.cos()
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
            std::slice::from_ref(&l),
            Vec3::ZERO,
            Vec3::Z,
            Vec3::Z * 3.0,
        );
        assert!((c.x - 1.0).abs() < 1e-6);
        let tilted = Vec3::new(0.2, 0.0, 1.0).normalize();
        let c = shade(&m, Vec3::ZERO, &[l], Vec3::ZERO, tilted, Vec3::Z * 3.0);
        assert!((c.x - tilted.z.powi(64)).abs() < 1e-6);
        let mut out = [0.0; 8];
        powi(<Sse8 as Lanes>::splat(0.5), 10).store(&mut out);
        assert_eq!(out, [1.0 / 1024.0; 8]);
    }

    #[test]
    fn acos_matches_libm_closely() {
        for k in 0..=2000 {
            let x = -1.0 + k as f32 / 1000.0;
            let mut out = [0.0; 8];
            acos(<Sse8 as Lanes>::splat(x)).store(&mut out);
            assert!((out[0] - libm::acosf(x)).abs() < 1e-6, "{x}: {}", out[0]);
        }
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
