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
/// unit length (they are normalised here, all lanes at once).
///
/// On x86-64 CPUs with AVX2 the same code is compiled a second time for
/// 8-wide registers and chosen at run time. Without FMA (never enabled) both
/// versions perform the same IEEE operations per lane, so the bits match;
/// `avx2_and_baseline_agree` checks it.
pub fn shade_batch(
    m: &ShadeMaterial,
    lights: &[WorldLight],
    eye: Vec3,
    b: &Batch,
    out: &mut [Vec3; LANES],
) {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2 (checked just above).
        unsafe { shade_batch_avx2(m, lights, eye, b, out) };
        return;
    }
    shade_batch_any(m, lights, eye, b, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn shade_batch_avx2(
    m: &ShadeMaterial,
    lights: &[WorldLight],
    eye: Vec3,
    b: &Batch,
    out: &mut [Vec3; LANES],
) {
    shade_batch_any(m, lights, eye, b, out);
}

#[inline(always)]
fn shade_batch_any(
    m: &ShadeMaterial,
    lights: &[WorldLight],
    eye: Vec3,
    b: &Batch,
    out: &mut [Vec3; LANES],
) {
    const L: usize = LANES;
    let [px, py, pz] = &b.p;
    let [cr, cg, cb] = &b.c;
    let (mut nx, mut ny, mut nz) = (b.n[0], b.n[1], b.n[2]);
    for k in 0..L {
        let len = (nx[k] * nx[k] + ny[k] * ny[k] + nz[k] * nz[k]).sqrt();
        let inv = if len > 0.0 { 1.0 / len } else { 0.0 };
        nx[k] *= inv;
        ny[k] *= inv;
        nz[k] *= inv;
    }
    // Unit vector to the eye.
    let (mut vx, mut vy, mut vz) = ([0.0; L], [0.0; L], [0.0; L]);
    for k in 0..L {
        let (x, y, z) = (eye.x - px[k], eye.y - py[k], eye.z - pz[k]);
        let len = (x * x + y * y + z * z).sqrt();
        let inv = if len > 0.0 { 1.0 / len } else { 0.0 };
        vx[k] = x * inv;
        vy[k] = y * inv;
        vz[k] = z * inv;
    }
    let (mut sr, mut sg, mut sb) = ([m.emissive.x; L], [m.emissive.y; L], [m.emissive.z; L]);
    let use_specular = m.specular != Vec3::ZERO;
    for l in lights {
        // Per lane: unit vector to the light and attenuation × spot factor
        // (0 where the light does not reach).
        let (mut lx, mut ly, mut lz, mut factor) = ([0.0; L], [0.0; L], [0.0; L], [0.0; L]);
        match l.kind {
            WorldLightKind::Directional { to_light } => {
                lx = [to_light.x; L];
                ly = [to_light.y; L];
                lz = [to_light.z; L];
                factor = [1.0; L];
            }
            WorldLightKind::Point { location, radius }
            | WorldLightKind::Spot {
                location, radius, ..
            } => {
                let a = l.attenuation;
                for k in 0..L {
                    let (x, y, z) = (location.x - px[k], location.y - py[k], location.z - pz[k]);
                    let d2 = x * x + y * y + z * z;
                    let dist = d2.sqrt();
                    let reach = dist <= radius && dist > 0.0;
                    let inv = if reach { 1.0 / dist } else { 0.0 };
                    lx[k] = x * inv;
                    ly[k] = y * inv;
                    lz[k] = z * inv;
                    let att = 1.0 / (a.x + a.y * dist + a.z * d2).max(1.0);
                    factor[k] = if reach { att } else { 0.0 };
                }
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
                    spot_factor(
                        &mut factor,
                        [&lx, &ly, &lz],
                        axis,
                        cos_cut_off,
                        cos_beam,
                        cut_off,
                        beam_width,
                        exponent,
                    );
                }
            }
        }
        let amb = l.ambient * m.ambient_intensity;
        let mut ndl = [0.0; L];
        for k in 0..L {
            ndl[k] = (nx[k] * lx[k] + ny[k] * ly[k] + nz[k] * lz[k]).max(0.0);
        }
        let mut spec = [0.0; L];
        if use_specular {
            let mut ndh = [0.0; L];
            for k in 0..L {
                let (hx, hy, hz) = (lx[k] + vx[k], ly[k] + vy[k], lz[k] + vz[k]);
                let hl = (hx * hx + hy * hy + hz * hz).sqrt();
                let d = nx[k] * hx + ny[k] * hy + nz[k] * hz;
                ndh[k] = if hl > 0.0 { (d / hl).max(0.0) } else { 0.0 };
            }
            let p = pow_lanes(ndh, m.exponent as u32);
            for k in 0..L {
                spec[k] = if ndl[k] > 0.0 { p[k] } else { 0.0 };
            }
        }
        for k in 0..L {
            let f = factor[k];
            let d = ndl[k];
            sr[k] +=
                f * (amb.x * cr[k] + l.color.x * cr[k] * d + l.color.x * m.specular.x * spec[k]);
            sg[k] +=
                f * (amb.y * cg[k] + l.color.y * cg[k] * d + l.color.y * m.specular.y * spec[k]);
            sb[k] +=
                f * (amb.z * cb[k] + l.color.z * cb[k] * d + l.color.z * m.specular.z * spec[k]);
        }
    }
    for k in 0..b.len.min(L) {
        out[k] = Vec3::new(sr[k], sg[k], sb[k]);
    }
}

/// Multiplies `factor` by the spot term: 0 outside the cut-off cone; inside,
/// `cos^exponent` (Inventor dropOffRate) or the VRML97 ramp — 1 within the
/// beam width, linear in the angle down to 0 at the cut-off.
#[allow(clippy::too_many_arguments)]
#[inline]
fn spot_factor(
    factor: &mut Lanes,
    l: [&Lanes; 3],
    axis: Vec3,
    cos_cut_off: f32,
    cos_beam: f32,
    cut_off: f32,
    beam_width: f32,
    exponent: f32,
) {
    let mut cos = [0.0; LANES];
    for k in 0..LANES {
        cos[k] = -(l[0][k] * axis.x + l[1][k] * axis.y + l[2][k] * axis.z);
        if cos[k] <= cos_cut_off {
            factor[k] = 0.0;
        }
    }
    for k in 0..LANES {
        if factor[k] == 0.0 {
            continue;
        }
        let spot = if exponent > 0.0 {
            libm::powf(cos[k], exponent)
        } else if cos[k] >= cos_beam {
            1.0
        } else {
            let angle = libm::acosf(cos[k].clamp(-1.0, 1.0));
            ((angle - cut_off) / (beam_width - cut_off)).clamp(0.0, 1.0)
        };
        factor[k] *= spot;
    }
}

/// `x^e` on every lane by repeated squaring (the exponent is the same for
/// all): exact same bits on every machine and build, unlike platform `powf`.
#[inline]
fn pow_lanes(mut x: Lanes, mut e: u32) -> Lanes {
    let mut r = [1.0; LANES];
    while e > 0 {
        if e & 1 == 1 {
            for k in 0..LANES {
                r[k] *= x[k];
            }
        }
        for v in &mut x {
            *v *= *v;
        }
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
        assert_eq!(pow_lanes([0.5; LANES], 10), [1.0 / 1024.0; LANES]);
    }

    /// The AVX2 build of the shader gives the same bits as the baseline one.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn avx2_and_baseline_agree() {
        if !std::is_x86_feature_detected!("avx2") {
            eprintln!("*** NOTE: no AVX2 on this CPU; nothing to compare ***");
            return;
        }
        let mut lights =
            vec![WorldLight::new(&Light::new(LightKind::Directional), Mat4::IDENTITY).unwrap()];
        let mut spot = Light::spot();
        spot.location = Vec3::new(0.3, 0.2, 2.0);
        spot.attenuation = Vec3::new(0.5, 0.3, 0.1);
        lights.push(WorldLight::new(&spot, Mat4::IDENTITY).unwrap());
        let mut point = Light::new(LightKind::Point);
        point.location = Vec3::new(-1.0, 1.0, 1.0);
        lights.push(WorldLight::new(&point, Mat4::IDENTITY).unwrap());
        let m = ShadeMaterial::new(&Material {
            specular: Vec3::new(0.9, 0.8, 0.7),
            shininess: 0.37,
            ..Material::default()
        });
        let mut b = Batch::default();
        let mut seed = 12345u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            (seed >> 8) as f32 / (1 << 24) as f32 * 2.0 - 1.0
        };
        for round in 0..200 {
            b.len = 0;
            for k in 0..LANES {
                let p = Vec3::new(rnd(), rnd(), rnd() * 0.2);
                let n = Vec3::new(rnd(), rnd(), 1.0);
                b.push(k as u32, p, n, Vec3::new(rnd().abs(), 0.5, 0.25));
            }
            let (mut x, mut y) = ([Vec3::ZERO; LANES], [Vec3::ZERO; LANES]);
            shade_batch_any(&m, &lights, Vec3::new(0.0, 0.0, 5.0), &b, &mut x);
            // SAFETY: AVX2 is present (checked above).
            unsafe { shade_batch_avx2(&m, &lights, Vec3::new(0.0, 0.0, 5.0), &b, &mut y) };
            for k in 0..LANES {
                assert_eq!(
                    x[k].to_array().map(f32::to_bits),
                    y[k].to_array().map(f32::to_bits),
                    "round {round} lane {k}"
                );
            }
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
