use super::Texture;
use glam::Vec3;

/// VRML97 Material fields (ISO/IEC 14772-1 §6.27), colours linear 0..1.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    pub diffuse: Vec3,
    pub ambient_intensity: f32,
    pub specular: Vec3,
    pub emissive: Vec3,
    /// 0..1 as in VRML97; the specular exponent is `shininess * 128`.
    pub shininess: f32,
    pub transparency: f32,
    /// An image texture (VRML97 Appearance.texture, Inventor Texture2, OBJ
    /// map_Kd, glTF baseColorTexture); drawn only on meshes with texcoords.
    pub texture: Option<Texture>,
}

impl Default for Material {
    /// The VRML97 defaults.
    fn default() -> Self {
        Material {
            name: String::new(),
            diffuse: Vec3::splat(0.8),
            ambient_intensity: 0.2,
            specular: Vec3::ZERO,
            emissive: Vec3::ZERO,
            shininess: 0.2,
            transparency: 0.0,
            texture: None,
        }
    }
}
