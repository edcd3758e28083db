use super::Texture;
use glam::Vec3;

/// VRML97 Material fields (ISO/IEC 14772-1 §6.27), colours linear 0..1.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    pub diffuse: Vec3,
    pub ambient_intensity: f32,
    /// Inventor's and VRML 1.0's `ambientColor` (their first value), kept
    /// whole because their ambient term is not VRML97's: Coin lights it as
    /// OpenGL's material ambient times the light model's ambient (the
    /// scene's `Environment`, [`super::Settings::ambient`]), a constant
    /// colour that does not follow the diffuse one, and Inventor lights add
    /// no ambient of their own. `None` (VRML97, X3D, glTF, OBJ):
    /// `ambient_intensity × diffuse` per light, as §4.14.4 says.
    /// `ambient_intensity` still holds this colour's mean, for writers of
    /// formats that have only an intensity.
    pub ambient_color: Option<Vec3>,
    pub specular: Vec3,
    pub emissive: Vec3,
    /// 0..1 as in VRML97; the specular exponent is `shininess * 128`.
    pub shininess: f32,
    pub transparency: f32,
    /// An image texture (VRML97 Appearance.texture, Inventor Texture2, OBJ
    /// map_Kd, glTF baseColorTexture); drawn only on meshes with texcoords.
    pub texture: Option<Texture>,
    /// An emissive map (glTF emissiveTexture, X3D Material.emissiveTexture):
    /// the emitted colour is `emissive × texel`, added to the lit colour
    /// before it is clamped. It reads the mesh's one texture coordinate set,
    /// like [`Material::texture`], with its own wraps and transform; its
    /// image lives in the scene's image store like every other.
    pub emissive_texture: Option<Texture>,
    /// Lighting is off (VRML97 §4.14.2, table 4.5: a Shape without
    /// Material, whose colour is its Color node's or white): lights are ignored and the
    /// colour is the mesh's vertex colours, else `emissive`, like an
    /// unlit line set's. Writers keep it (no Material node in VRML97/X3D).
    pub unlit: bool,
}

impl Default for Material {
    /// The VRML97 defaults.
    fn default() -> Self {
        Material {
            name: String::new(),
            diffuse: Vec3::splat(0.8),
            ambient_intensity: 0.2,
            ambient_color: None,
            specular: Vec3::ZERO,
            emissive: Vec3::ZERO,
            shininess: 0.2,
            transparency: 0.0,
            texture: None,
            emissive_texture: None,
            unlit: false,
        }
    }
}

impl Material {
    /// Every texture this material draws (colour, then emissive map), for
    /// code that treats all image references alike (listing, remapping).
    pub fn textures(&self) -> impl Iterator<Item = &Texture> {
        self.texture.iter().chain(self.emissive_texture.iter())
    }

    /// Both texture slots, to remap or drop their images.
    pub fn texture_slots_mut(&mut self) -> [&mut Option<Texture>; 2] {
        [&mut self.texture, &mut self.emissive_texture]
    }
}
