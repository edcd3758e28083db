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

use super::simd::F4;
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

/// Pixels shaded together: the lighting loops below run over fixed-size
/// lane arrays so the compiler turns them into SIMD instructions (each lane
/// does exactly the arithmetic a lone pixel would, so results do not depend
/// on how pixels are grouped).
pub const LANES: usize = 8;
type Lanes = [f32; LANES];

/// Inputs of up to [`LANES`] pixels of one item (same material and lights),
/// structure-of-arrays. Unused lanes hold harmless values.
#[derive(Clone, Debug)]
pub struct Batch {
    pub len: usize,
    /// World position, unit normal (facing the viewer), diffuse colour.
    pub p: [Lanes; 3],
    pub n: [Lanes; 3],
    pub c: [Lanes; 3],
    /// Where each lane's result goes (pixel index in the tile).
    pub dest: [u32; LANES],
}

impl Default for Batch {
    fn default() -> Self {
        Batch {
            len: 0,
            p: [[0.0; LANES]; 3],
            n: [[0.0; LANES], [0.0; LANES], [1.0; LANES]],
            c: [[0.0; LANES]; 3],
            dest: [0; LANES],
        }
    }
}

impl Batch {
    /// Adds a pixel; the caller flushes when `len == LANES`.
    #[inline]
    pub fn push(&mut self, dest: u32, p: Vec3, n: Vec3, c: Vec3) {
        let k = self.len;
        self.p[0][k] = p.x;
        self.p[1][k] = p.y;
        self.p[2][k] = p.z;
        self.n[0][k] = n.x;
        self.n[1][k] = n.y;
        self.n[2][k] = n.z;
        self.c[0][k] = c.x;
        self.c[1][k] = c.y;
        self.c[2][k] = c.z;
        self.dest[k] = dest;
        self.len += 1;
    }
}

/// The VRML97 colour of a surface point `p` with normal `n` (already
/// facing the viewer for two-sided surfaces), seen from `eye`. `diffuse` is
/// the material's diffuse colour or the per-vertex colour that replaces it.
pub fn shade(
    m: &ShadeMaterial,
    diffuse: Vec3,
    lights: &[WorldLight],
    p: Vec3,
    n: Vec3,
    eye: Vec3,
) -> Vec3 {
    let mut b = Batch::default();
    b.push(0, p, n, diffuse);
    let mut out = [Vec3::ZERO; LANES];
    shade_batch(m, lights, eye, &b, &mut out);
    out[0]
}

/// Shades every lane of `b` (see [`shade`]) into `out`. Normals need not be
/// unit length (they are normalised here). Runs four lanes at a time in
/// SSE2 registers (see `simd`); each lane does exactly the arithmetic a lone
/// pixel would, so grouping never changes a result.
pub fn shade_batch(
    m: &ShadeMaterial,
    lights: &[WorldLight],
    eye: Vec3,
    b: &Batch,
    out: &mut [Vec3; LANES],
) {
    for half in 0..LANES / 4 {
        if half * 4 >= b.len {
            break;
        }
        let r = half * 4..half * 4 + 4;
        let load3 = |v: &[Lanes; 3]| {
            [
                F4::load(&v[0][r.clone()]),
                F4::load(&v[1][r.clone()]),
                F4::load(&v[2][r.clone()]),
            ]
        };
        let c = shade4(m, lights, eye, load3(&b.p), load3(&b.n), load3(&b.c));
        let [cr, cg, cb] = c.map(F4::to_array);
        for k in 0..4 {
            out[half * 4 + k] = Vec3::new(cr[k], cg[k], cb[k]);
        }
    }
}

#[inline(always)]
fn dot(a: &[F4; 3], b: &[F4; 3]) -> F4 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `v / |v|`, or zero for a zero vector; also returns |v|.
#[inline(always)]
fn normalize(v: [F4; 3]) -> ([F4; 3], F4) {
    let len = dot(&v, &v).sqrt();
    let zero = F4::splat(0.0);
    let inv = len.gt(zero).select(F4::splat(1.0).div(len), zero);
    ([v[0] * inv, v[1] * inv, v[2] * inv], len)
}

/// The lighting model for four pixels.
fn shade4(
    m: &ShadeMaterial,
    lights: &[WorldLight],
    eye: Vec3,
    p: [F4; 3],
    n: [F4; 3],
    diffuse: [F4; 3],
) -> [F4; 3] {
    let zero = F4::splat(0.0);
    let one = F4::splat(1.0);
    let (n, _) = normalize(n);
    let (v, _) = normalize([
        F4::splat(eye.x) - p[0],
        F4::splat(eye.y) - p[1],
        F4::splat(eye.z) - p[2],
    ]);
    let mut sum = [
        F4::splat(m.emissive.x),
        F4::splat(m.emissive.y),
        F4::splat(m.emissive.z),
    ];
    let use_specular = m.specular != Vec3::ZERO;
    for l in lights {
        // Unit vector to the light and attenuation × spot factor per lane
        // (0 where the light does not reach).
        let (to_light, factor) = match l.kind {
            WorldLightKind::Directional { to_light } => (
                [
                    F4::splat(to_light.x),
                    F4::splat(to_light.y),
                    F4::splat(to_light.z),
                ],
                one,
            ),
            WorldLightKind::Point {
                location, radius, ..
            }
            | WorldLightKind::Spot {
                location, radius, ..
            } => {
                let d = [
                    F4::splat(location.x) - p[0],
                    F4::splat(location.y) - p[1],
                    F4::splat(location.z) - p[2],
                ];
                let (to_light, dist) = normalize(d);
                let d2 = dist * dist;
                let a = l.attenuation;
                let denom = (F4::splat(a.x) + F4::splat(a.y) * dist + F4::splat(a.z) * d2).max(one);
                let reach = dist.le(F4::splat(radius)).and(dist.gt(zero));
                let mut factor = reach.select(one.div(denom), zero);
                if let WorldLightKind::Spot {
                    axis,
                    cos_cut_off,
                    cos_beam,
                    cut_off,
                    beam_width,
                    exponent,
                    ..
                } = l.kind
                {
                    let cos = zero
                        - (to_light[0] * F4::splat(axis.x)
                            + to_light[1] * F4::splat(axis.y)
                            + to_light[2] * F4::splat(axis.z));
                    let inside = cos.gt(F4::splat(cos_cut_off));
                    factor = inside.select(factor, zero);
                    let full = F4::splat(cos_beam).le(cos);
                    // Lanes lit by the spot but outside its full beam need the ramp.
                    let partial = inside.and(factor.gt(zero)).and(F4::splat(cos_beam).gt(cos));
                    if exponent > 0.0 || partial.any() {
                        factor = spot_lanes(factor, cos, cos_beam, cut_off, beam_width, exponent);
                    } else {
                        factor = full.select(factor, zero);
                    }
                }
                (to_light, factor)
            }
        };
        let amb = l.ambient * m.ambient_intensity;
        let ndl = dot(&n, &to_light).max(zero);
        let lit = ndl.gt(zero);
        let spec = if use_specular {
            let (h, _) = normalize([to_light[0] + v[0], to_light[1] + v[1], to_light[2] + v[2]]);
            let ndh = dot(&n, &h).max(zero);
            lit.select(pow4(ndh, m.exponent as u32), zero)
        } else {
            zero
        };
        for ch in 0..3 {
            let term = F4::splat(amb[ch]) * diffuse[ch]
                + F4::splat(l.color[ch]) * diffuse[ch] * ndl
                + F4::splat(l.color[ch] * m.specular[ch]) * spec;
            sum[ch] = sum[ch] + factor * term;
        }
    }
    sum
}

/// The spot term per lane, multiplied into `factor`: `cos^exponent`
/// (Inventor dropOffRate) or the VRML97 ramp — 1 within the beam width,
/// linear in the angle down to 0 at the cut-off. Lanes with `factor` 0 stay 0.
#[inline(never)]
fn spot_lanes(
    factor: F4,
    cos: F4,
    cos_beam: f32,
    cut_off: f32,
    beam_width: f32,
    exponent: f32,
) -> F4 {
    let mut f = factor.to_array();
    let c = cos.to_array();
    for k in 0..4 {
        if f[k] == 0.0 {
            continue;
        }
        let spot = if exponent > 0.0 {
            libm::powf(c[k], exponent)
        } else if c[k] >= cos_beam {
            1.0
        } else {
            let angle = libm::acosf(c[k].clamp(-1.0, 1.0));
            ((angle - cut_off) / (beam_width - cut_off)).clamp(0.0, 1.0)
        };
        f[k] *= spot;
    }
    F4::load(&f)
}

/// `x^e` per lane by repeated squaring: the same bits on every machine and
/// build, unlike platform `powf`.
#[inline(always)]
fn pow4(mut x: F4, mut e: u32) -> F4 {
    let mut r = F4::splat(1.0);
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
        assert_eq!(pow4(F4::splat(0.5), 10).to_array(), [1.0 / 1024.0; 4]);
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
