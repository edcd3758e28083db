//! glTF materials ⇄ animed's VRML97 Phong material, each way in ONE
//! function ([`phong_from_pbr`], [`pbr_from_phong`]), plus the colour-space
//! conversion both use.
//!
//! **Colour space.** glTF colour factors, vertex colours and light colours
//! are linear (spec §3.9.2); animed's VRML97 lighting works on display
//! values, as VRML browsers do. Colours are therefore converted with the
//! sRGB transfer function (IEC 61966-2-1) on the way in and back on the
//! way out, so a Blender colour picked as (0.8, 0.2, 0.2) shows as that.
//!
//! **Metallic-roughness → Phong** (an approximation; glTF's BRDF is not
//! Phong's):
//! * diffuse = sRGB(base colour) × (1 − metallic / 2): metals keep half
//!   their colour as diffuse, because animed has no environment for them
//!   to reflect and a black metal would hide the shape;
//! * specular = sRGB(F0) × (1 − roughness) with F0 = mix(0.04, base,
//!   metallic), the metal-rough Fresnel reflectance at normal incidence;
//! * shininess: the Blinn-Phong exponent matching a microfacet roughness
//!   α = roughness² is n = 2/α² − 2 (Walter et al., "Microfacet models for
//!   refraction through rough surfaces", EGSR 2007, §5.2); VRML shininess
//!   = n / 128, clamped to [0, 1];
//! * emissive = sRGB(emissive factor × KHR_materials_emissive_strength);
//!   an emissiveTexture becomes the material's emissive map, drawn as
//!   emissive × texel added to the lit colour before it is clamped (§3.9.3:
//!   "the emissive texture and factor control the color and intensity of
//!   the light being emitted"; Appendix B adds the emission to the BRDF's
//!   result). The texel stays in its sRGB encoding and multiplies the
//!   sRGB factor — the same approximation (sRGB(a·b) ≈ sRGB(a)·sRGB(b)) the
//!   base colour texture makes, exact for a factor of 0 or 1;
//! * transparency = 1 − alpha for alphaMode BLEND; MASK shows the material
//!   opaque when alpha ≥ alphaCutoff and fully transparent below; OPAQUE
//!   ignores alpha (§3.9.4);
//! * KHR_materials_unlit: an unlit material (`Material::unlit`, lighting
//!   off as for a VRML97 Shape without Material) whose colour is the base
//!   colour (kept as the emissive colour, diffuse and specular black), or
//!   the vertex colours (COLOR_0 × base colour, see `mesh.rs`) where the
//!   primitive has them; its base colour texture multiplies that colour;
//!   its emissive factor and texture are ignored, as the extension says;
//! * a primitive without a material gets animed's (VRML97) default
//!   material rather than glTF's white rough metal, which renders black
//!   without an environment.
//!
//! doubleSided is a mesh property here (`Mesh::solid`), set by the reader.

use crate::scene::Material;
use glam::Vec3;

/// sRGB transfer function (IEC 61966-2-1), per channel, clamped to 0..1.
pub fn srgb_from_linear(c: Vec3) -> Vec3 {
    let f = |x: f32| {
        let x = x.clamp(0.0, 1.0);
        if x >= 1.0 {
            1.0 // 1.055 − 0.055 is 0.99999994 in f32
        } else if x <= 0.003_130_8 {
            12.92 * x
        } else {
            1.055 * libm::powf(x, 1.0 / 2.4) - 0.055
        }
    };
    Vec3::new(f(c.x), f(c.y), f(c.z))
}

/// Inverse of [`srgb_from_linear`].
pub fn linear_from_srgb(c: Vec3) -> Vec3 {
    let f = |x: f32| {
        let x = x.clamp(0.0, 1.0);
        if x <= 0.040_45 {
            x / 12.92
        } else {
            libm::powf((x + 0.055) / 1.055, 2.4)
        }
    };
    Vec3::new(f(c.x), f(c.y), f(c.z))
}

/// The writer's sRGB → linear: a linear value that the reader's
/// [`srgb_from_linear`] maps back to exactly the same f32 when one exists
/// (the smallest such), else the smallest one for the sRGB value that
/// `srgb_from_linear(linear_from_srgb(c))` gives. Either way, writing what
/// was read gives the same bits again, so export → import → export is
/// byte-identical even though the two curves are not exact inverses in f32.
pub fn linear_exact(c: Vec3) -> Vec3 {
    Vec3::new(
        linear_channel(c.x),
        linear_channel(c.y),
        linear_channel(c.z),
    )
}

fn srgb1(x: f32) -> f32 {
    srgb_from_linear(Vec3::splat(x)).x
}

/// Smallest `l` in `[0, 1]` with `srgb1(l) == z`, searched near `guess`.
fn preimage(z: f32, guess: f32) -> Option<f32> {
    let step = |x: f32, up: bool| -> f32 {
        if up {
            if x <= 0.0 {
                f32::from_bits(1)
            } else {
                f32::from_bits(x.to_bits() + 1)
            }
        } else if x <= 0.0 {
            0.0
        } else {
            f32::from_bits(x.to_bits() - 1)
        }
    };
    let mut l = guess.clamp(0.0, 1.0);
    for _ in 0..256 {
        let y = srgb1(l);
        if y == z {
            // Walk down to the smallest preimage.
            while l > 0.0 && srgb1(step(l, false)) == z {
                l = step(l, false);
            }
            return Some(l);
        }
        let up = y < z;
        let n = step(l, up).clamp(0.0, 1.0);
        if n == l || (srgb1(n) < z) != up {
            // Stepped over z without hitting it: unreachable.
            return if srgb1(n) == z { preimage(z, n) } else { None };
        }
        l = n;
    }
    None
}

fn linear_channel(y: f32) -> f32 {
    let y = if y.is_finite() {
        y.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let guess = linear_from_srgb(Vec3::splat(y)).x;
    if let Some(l) = preimage(y, guess) {
        return l;
    }
    let z = srgb1(guess);
    preimage(z, guess).unwrap_or(guess)
}

/// The parts of a glTF material the mapping reads (linear values).
#[derive(Clone, Debug, PartialEq)]
pub struct Pbr {
    pub name: String,
    pub base_color: [f32; 4],
    pub metallic: f32,
    pub roughness: f32,
    pub emissive: Vec3,
    pub alpha_mode: gltf::material::AlphaMode,
    pub alpha_cutoff: f32,
    pub unlit: bool,
}

impl Default for Pbr {
    /// glTF's defaults (§5.19).
    fn default() -> Self {
        Pbr {
            name: String::new(),
            base_color: [1.0; 4],
            metallic: 1.0,
            roughness: 1.0,
            emissive: Vec3::ZERO,
            alpha_mode: gltf::material::AlphaMode::Opaque,
            alpha_cutoff: 0.5,
            unlit: false,
        }
    }
}

impl Pbr {
    pub fn from_gltf(m: &gltf::Material) -> Pbr {
        let pbr = m.pbr_metallic_roughness();
        Pbr {
            name: m.name().unwrap_or_default().to_string(),
            base_color: pbr.base_color_factor(),
            metallic: pbr.metallic_factor(),
            roughness: pbr.roughness_factor(),
            emissive: Vec3::from(m.emissive_factor()) * m.emissive_strength().unwrap_or(1.0),
            alpha_mode: m.alpha_mode(),
            alpha_cutoff: m.alpha_cutoff().unwrap_or(0.5),
            unlit: m.unlit(),
        }
    }
}

/// The exact Phong material animed wrote into `extras.animed`, when the
/// glTF values still say what animed wrote for it (another tool may have
/// edited the material since; then the glTF values win).
pub fn phong_from_extras(m: &gltf::Material, read: &Pbr) -> Option<Material> {
    let raw = m.extras().as_ref()?;
    let v: serde_json::Value = serde_json::from_str(raw.get()).ok()?;
    let a = v.get("animed")?;
    let f = |k: &str| a.get(k)?.as_f64().map(|x| x as f32);
    let v3 = |k: &str| -> Option<Vec3> {
        let arr = a.get(k)?.as_array()?;
        let c: Vec<f32> = arr
            .iter()
            .filter_map(|x| x.as_f64().map(|x| x as f32))
            .collect();
        (c.len() == 3).then(|| Vec3::new(c[0], c[1], c[2]))
    };
    // Stand-ins for the texture slots the glTF material fills (the reader
    // sets the real ones): whether it is written unlit depends on them.
    let slot = |used: bool| used.then(|| crate::scene::Texture::new(crate::scene::ImageId(0)));
    let phong = Material {
        name: read.name.clone(),
        diffuse: v3("diffuse")?,
        ambient_intensity: f("ambientIntensity")?,
        ambient_color: None,
        specular: v3("specular")?,
        emissive: v3("emissive")?,
        shininess: f("shininess")?,
        transparency: f("transparency")?,
        texture: slot(m.pbr_metallic_roughness().base_color_texture().is_some()),
        emissive_texture: slot(m.emissive_texture().is_some()),
        unlit: a.get("unlit").and_then(|u| u.as_bool()).unwrap_or(false),
    };
    let mut want = pbr_from_phong(&phong);
    want.name = read.name.clone();
    let white = read.base_color[..3] == [1.0, 1.0, 1.0];
    if white {
        want.base_color = [1.0, 1.0, 1.0, want.base_color[3]];
    }
    let same = want.base_color == read.base_color
        && want.metallic == read.metallic
        && want.roughness == read.roughness
        && want.emissive == read.emissive
        && want.unlit == read.unlit
        // The writer blends (or masks) a material opaque at rest when its
        // texture has alpha or its transparency is animated.
        && (want.alpha_mode == read.alpha_mode
            || want.alpha_mode == gltf::material::AlphaMode::Opaque);
    same.then_some(phong)
}

/// Blinn-Phong exponent for a roughness (see the module doc), as VRML
/// shininess.
fn shininess_from_roughness(roughness: f32) -> f32 {
    let alpha = (roughness * roughness).max(1e-3);
    let n = 2.0 / (alpha * alpha) - 2.0;
    (n / 128.0).clamp(0.0, 1.0)
}

fn roughness_from_shininess(shininess: f32) -> f32 {
    let n = shininess.clamp(0.0, 1.0) * 128.0;
    let alpha = (2.0 / (n + 2.0)).sqrt();
    alpha.sqrt().clamp(0.0, 1.0)
}

/// Metallic-roughness (and unlit) → Phong. See the module doc for every rule.
pub fn phong_from_pbr(p: &Pbr) -> Material {
    use gltf::material::AlphaMode;
    let base = Vec3::new(p.base_color[0], p.base_color[1], p.base_color[2]);
    let alpha = p.base_color[3].clamp(0.0, 1.0);
    let transparency = match p.alpha_mode {
        AlphaMode::Opaque => 0.0,
        AlphaMode::Blend => 1.0 - alpha,
        AlphaMode::Mask => {
            if alpha >= p.alpha_cutoff {
                0.0
            } else {
                1.0
            }
        }
    };
    if p.unlit {
        return Material {
            name: p.name.clone(),
            diffuse: Vec3::ZERO,
            ambient_intensity: 0.0,
            ambient_color: None,
            specular: Vec3::ZERO,
            emissive: srgb_from_linear(base),
            shininess: 0.0,
            transparency,
            texture: None,
            emissive_texture: None,
            unlit: true,
        };
    }
    let metallic = p.metallic.clamp(0.0, 1.0);
    let roughness = p.roughness.clamp(0.0, 1.0);
    let f0 = Vec3::splat(0.04).lerp(base, metallic);
    Material {
        name: p.name.clone(),
        diffuse: srgb_from_linear(base) * (1.0 - metallic / 2.0),
        ambient_intensity: 0.2,
        ambient_color: None,
        specular: srgb_from_linear(f0) * (1.0 - roughness),
        emissive: srgb_from_linear(p.emissive),
        shininess: shininess_from_roughness(roughness),
        transparency,
        texture: None,
        emissive_texture: None,
        unlit: false,
    }
}

/// Phong → metallic-roughness, the writer's direction: a dielectric
/// (metallic 0) whose base colour is the diffuse colour and whose
/// roughness gives the same Blinn-Phong exponent as the shininess; a
/// material with black diffuse and specular and a non-black emissive
/// colour is written unlit (KHR_materials_unlit) with that colour —
/// unless its only texture is an emissive map, which unlit glTF cannot
/// say without changing the texture's role (then it stays lit, with black
/// base colour, and the map is its emissiveTexture); an unlit material
/// (lighting off) is written unlit with its emissive colour, the colour it
/// draws without vertex colours.
/// Transparency becomes alpha with alphaMode BLEND.
pub fn pbr_from_phong(m: &Material) -> Pbr {
    use gltf::material::AlphaMode;
    let alpha = 1.0 - m.transparency.clamp(0.0, 1.0);
    let alpha_mode = if alpha < 1.0 {
        AlphaMode::Blend
    } else {
        AlphaMode::Opaque
    };
    let only_emissive_map = m.texture.is_none() && m.emissive_texture.is_some();
    if m.unlit
        || (m.diffuse == Vec3::ZERO
            && m.specular == Vec3::ZERO
            && m.emissive != Vec3::ZERO
            && !only_emissive_map)
    {
        let c = linear_exact(m.emissive);
        return Pbr {
            name: m.name.clone(),
            base_color: [c.x, c.y, c.z, alpha],
            metallic: 0.0,
            roughness: 1.0,
            emissive: Vec3::ZERO,
            alpha_mode,
            alpha_cutoff: 0.5,
            unlit: true,
        };
    }
    let c = linear_exact(m.diffuse);
    Pbr {
        name: m.name.clone(),
        base_color: [c.x, c.y, c.z, alpha],
        metallic: 0.0,
        roughness: roughness_from_shininess(m.shininess),
        emissive: linear_exact(m.emissive),
        alpha_mode,
        alpha_cutoff: 0.5,
        unlit: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_matches_the_standard_and_inverts() {
        // IEC 61966-2-1 reference points: 0.5 linear is 0.7354 sRGB.
        let s = srgb_from_linear(Vec3::new(0.0, 0.5, 1.0));
        assert!((s.y - 0.735_36).abs() < 1e-4, "{s}");
        assert_eq!((s.x, s.z), (0.0, 1.0));
        for x in [0.001f32, 0.02, 0.2, 0.5, 0.9] {
            let back = linear_from_srgb(srgb_from_linear(Vec3::splat(x)));
            assert!((back.x - x).abs() < 1e-5, "{x} → {back}");
        }
    }

    #[test]
    fn written_colours_read_back_and_rewrite_to_the_same_bits() {
        let mut x = 0.0f32;
        while x <= 1.0 {
            let l = linear_exact(Vec3::splat(x)).x;
            let read = srgb_from_linear(Vec3::splat(l)).x;
            assert!((read - x).abs() < 1e-5, "{x} → {l} → {read}");
            assert_eq!(
                linear_exact(Vec3::splat(read)).x.to_bits(),
                l.to_bits(),
                "{x}"
            );
            x += 0.000_37;
        }
    }

    #[test]
    fn dielectric_rough_plastic_and_metal() {
        let plastic = phong_from_pbr(&Pbr {
            base_color: [0.5, 0.0, 0.0, 1.0],
            metallic: 0.0,
            roughness: 0.5,
            ..Pbr::default()
        });
        assert!((plastic.diffuse.x - 0.735_36).abs() < 1e-4);
        // α = 0.25 → n = 2/0.0625 − 2 = 30 → shininess 30/128.
        assert!((plastic.shininess - 30.0 / 128.0).abs() < 1e-6);
        // F0 = 0.04 linear → sRGB 1.055·0.04^(1/2.4) − 0.055 = 0.22092, × (1 − 0.5).
        assert!(
            (plastic.specular.x - 0.220_92 * 0.5).abs() < 1e-4,
            "{}",
            plastic.specular
        );
        let metal = phong_from_pbr(&Pbr {
            base_color: [1.0, 1.0, 1.0, 1.0],
            metallic: 1.0,
            roughness: 0.0,
            ..Pbr::default()
        });
        assert_eq!(metal.diffuse, Vec3::splat(0.5));
        assert_eq!(metal.specular, Vec3::ONE);
        assert_eq!(metal.shininess, 1.0);
    }

    #[test]
    fn alpha_modes_and_unlit() {
        use gltf::material::AlphaMode;
        let p = |mode, a| Pbr {
            base_color: [1.0, 1.0, 1.0, a],
            alpha_mode: mode,
            alpha_cutoff: 0.5,
            ..Pbr::default()
        };
        assert_eq!(phong_from_pbr(&p(AlphaMode::Opaque, 0.2)).transparency, 0.0);
        assert!((phong_from_pbr(&p(AlphaMode::Blend, 0.25)).transparency - 0.75).abs() < 1e-6);
        assert_eq!(phong_from_pbr(&p(AlphaMode::Mask, 0.6)).transparency, 0.0);
        assert_eq!(phong_from_pbr(&p(AlphaMode::Mask, 0.4)).transparency, 1.0);
        let unlit = phong_from_pbr(&Pbr {
            unlit: true,
            base_color: [0.5, 0.5, 0.5, 1.0],
            ..Pbr::default()
        });
        assert_eq!((unlit.diffuse, unlit.specular), (Vec3::ZERO, Vec3::ZERO));
        let back = pbr_from_phong(&unlit);
        assert!(back.unlit && (back.base_color[0] - 0.5).abs() < 1e-5);
    }

    #[test]
    fn phong_to_pbr_and_back_keeps_diffuse_and_shininess() {
        let m = Material {
            diffuse: Vec3::new(0.8, 0.2, 0.1),
            shininess: 0.3,
            ..Material::default()
        };
        let p = pbr_from_phong(&m);
        assert_eq!(p.metallic, 0.0);
        let back = phong_from_pbr(&p);
        assert!((back.diffuse - m.diffuse).abs().max_element() < 1e-5);
        assert!((back.shininess - m.shininess).abs() < 1e-4);
    }
}
