//! X3D 4 materials → animed's VRML97 Phong material, in ONE function
//! ([`to_material`]), so the approximation is written down once.
//!
//! * **PhysicalMaterial** (ISO/IEC 19775-1 4.0 §12.4.4) is glTF's
//!   metallic-roughness model with the same fields (baseColor, metallic,
//!   roughness, emissiveColor, transparency) and, like glTF's, linear
//!   colours (castle-model-viewer lights it in linear space). It goes
//!   through glTF's mapping, [`crate::format::gltf::phong_from_pbr`]:
//!   diffuse = sRGB(base)·(1 − metallic/2), specular = sRGB(F0)·(1 −
//!   roughness) with F0 = mix(0.04, base, metallic), shininess from the
//!   roughness by Walter et al. 2007, emissive = sRGB(emissive),
//!   transparency kept (alpha blending).
//! * **UnlitMaterial** (§12.4.6): the emissive colour alone (default
//!   white), which is exactly an unlit surface in the VRML lighting model:
//!   diffuse, specular and ambient black.
//! * **TwoSidedMaterial** (X3D 3.2 §12.4.6): its front fields are
//!   Material's; back colours are not drawn (warned when
//!   `separateBackColor` is TRUE).
//!
//! The result is written back as a `Material` node's fields, so material
//! animation ROUTEd to the VRML97 field names still finds it.

use crate::format::gltf::{phong_from_pbr, Pbr};
use crate::format::lexer::Pos;
use crate::format::syntax::{AstNode, Field, Value};
use crate::scene::Material;
use glam::Vec3;

/// Replaces a PhysicalMaterial, UnlitMaterial or TwoSidedMaterial node's
/// fields by the equivalent Material node's (see the module doc). Texture
/// fields are kept (the Appearance takes its texture from them).
pub fn to_material(n: &mut AstNode, warnings: &mut Vec<(Pos, String)>) {
    let m = match n.kind.as_str() {
        "PhysicalMaterial" => {
            let base = n.vec3("baseColor", Vec3::ONE);
            let transparency = n.f32("transparency", 0.0).clamp(0.0, 1.0);
            let pbr = Pbr {
                base_color: [base.x, base.y, base.z, 1.0 - transparency],
                metallic: n.f32("metallic", 1.0),
                roughness: n.f32("roughness", 1.0),
                emissive: n.vec3("emissiveColor", Vec3::ZERO),
                alpha_mode: if transparency > 0.0 {
                    gltf::material::AlphaMode::Blend
                } else {
                    gltf::material::AlphaMode::Opaque
                },
                ..Pbr::default()
            };
            phong_from_pbr(&pbr)
        }
        "UnlitMaterial" => Material {
            diffuse: Vec3::ZERO,
            ambient_intensity: 0.0,
            specular: Vec3::ZERO,
            emissive: n.vec3("emissiveColor", Vec3::ONE),
            shininess: 0.0,
            transparency: n.f32("transparency", 0.0),
            ..Material::default()
        },
        _ => {
            if n.bool("separateBackColor", false) {
                warnings.push((
                    n.pos,
                    "TwoSidedMaterial: back colours are not drawn; both sides use the front's"
                        .into(),
                ));
            }
            let d = Material::default();
            Material {
                diffuse: n.vec3("diffuseColor", d.diffuse),
                ambient_intensity: n.f32("ambientIntensity", d.ambient_intensity),
                specular: n.vec3("specularColor", d.specular),
                emissive: n.vec3("emissiveColor", d.emissive),
                shininess: n.f32("shininess", d.shininess),
                transparency: n.f32("transparency", d.transparency),
                ..d
            }
        }
    };
    let textures: Vec<Field> = n
        .fields
        .iter()
        .filter(|f| f.name.ends_with("Texture") && matches!(f.value, Value::Nodes(_)))
        .cloned()
        .collect();
    let pos = n.pos;
    let num = |name: &str, v: Vec<f64>| Field {
        name: name.into(),
        value: Value::Nums(v),
        pos,
    };
    let v3 = |c: Vec3| vec![c.x as f64, c.y as f64, c.z as f64];
    n.kind = "Material".into();
    n.fields = vec![
        num("diffuseColor", v3(m.diffuse)),
        num("ambientIntensity", vec![m.ambient_intensity as f64]),
        num("specularColor", v3(m.specular)),
        num("emissiveColor", v3(m.emissive)),
        num("shininess", vec![m.shininess as f64]),
        num("transparency", vec![m.transparency as f64]),
    ];
    n.fields.extend(textures);
}
