//! A material's texture slot: which image, how it wraps, how its
//! coordinates are transformed and how its colour combines with lighting.

use super::ImageId;
use glam::{Affine2, Vec2, Vec3};

/// What happens to a texture coordinate outside 0..1 (VRML97 `repeatS/T`,
/// Inventor `wrapS/T`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Wrap {
    #[default]
    Repeat,
    Clamp,
    /// Every other period flipped (glTF MIRRORED_REPEAT, OpenGL
    /// `MIRRORED_REPEAT`); VRML and Inventor cannot say it and write repeat.
    Mirror,
}

/// How texels are filtered (glTF samplers; VRML and Inventor always use
/// the defaults: bilinear within a level, linear between mip levels).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Filter {
    /// Magnified: the nearest texel instead of bilinear (glTF magFilter
    /// NEAREST).
    pub mag_nearest: bool,
    /// Minified: the nearest texel within a level (glTF NEAREST,
    /// NEAREST_MIPMAP_*).
    pub min_nearest: bool,
    /// Minified: how mip levels are used (glTF's minFilter suffix).
    pub mip: MipMode,
}

/// Mip-map use when minified.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MipMode {
    /// Only the base level (glTF NEAREST / LINEAR).
    None,
    /// The nearest level (glTF *_MIPMAP_NEAREST).
    Nearest,
    /// Blend the two nearest levels (glTF *_MIPMAP_LINEAR): trilinear.
    #[default]
    Linear,
}

impl Default for Filter {
    fn default() -> Self {
        Filter {
            mag_nearest: false,
            min_nearest: false,
            mip: MipMode::Linear,
        }
    }
}

/// How the texture colour combines with the material and the lighting.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TextureModel {
    /// VRML97 lighting (ISO/IEC 14772-1 §4.14.3, table 4.5): a 1- or
    /// 2-component texture multiplies the diffuse colour, a 3- or
    /// 4-component texture replaces it; the result is lit. 2- and 4-component
    /// textures give the alpha.
    #[default]
    Vrml97,
    /// The texture colour is the final, unlit colour (VRML97 Shape without
    /// a Material; OpenGL `GL_REPLACE`). Intensity textures give grey.
    Replace,
    /// Inventor MODULATE (OpenGL `GL_MODULATE`, which Coin and SGI Inventor
    /// draw with): the lit colour, specular included, × the texture colour;
    /// alpha × the texture's alpha.
    Modulate,
    /// The texture multiplies the diffuse colour (and its alpha the
    /// material's), then the result is lit: MTL `Kd × map_Kd`, glTF
    /// `baseColorFactor × baseColorTexture`.
    MultiplyDiffuse,
    /// Inventor DECAL: the texture is laid over the lit colour by its alpha
    /// (opaque texture: the texture colour, unlit).
    Decal,
    /// Inventor BLEND: the texture's intensity mixes the lit colour towards
    /// [`Texture::blend_color`] (OpenGL `GL_BLEND`).
    Blend,
}

/// Order of the texture transform's parts; the two file families differ.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TexTransformOrder {
    /// VRML97 §6.49 TextureTransform: `Tc' = -C × S × R × C × T × Tc`
    /// (translation first, then rotate and scale about the centre).
    #[default]
    Vrml97,
    /// Inventor Texture2Transform: scale, rotate about the centre, then
    /// translate.
    Inventor,
}

/// A 2D texture coordinate transform kept as its authored fields, so writers
/// write back what was read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexTransform {
    pub translation: Vec2,
    /// Radians, counter-clockwise.
    pub rotation: f32,
    pub scale: Vec2,
    pub center: Vec2,
    pub order: TexTransformOrder,
}

impl Default for TexTransform {
    fn default() -> Self {
        TexTransform {
            translation: Vec2::ZERO,
            rotation: 0.0,
            scale: Vec2::ONE,
            center: Vec2::ZERO,
            order: TexTransformOrder::Vrml97,
        }
    }
}

impl TexTransform {
    /// Whether this transform leaves coordinates unchanged.
    pub fn is_identity(&self) -> bool {
        self.translation == Vec2::ZERO && self.rotation == 0.0 && self.scale == Vec2::ONE
    }

    /// The matrix that maps a mesh texture coordinate to the coordinate
    /// looked up in the image.
    pub fn matrix(&self) -> Affine2 {
        let c = Affine2::from_translation(self.center);
        let minus_c = Affine2::from_translation(-self.center);
        let r = Affine2::from_angle(self.rotation);
        let s = Affine2::from_scale(self.scale);
        let t = Affine2::from_translation(self.translation);
        match self.order {
            TexTransformOrder::Vrml97 => minus_c * s * r * c * t,
            TexTransformOrder::Inventor => c * t * r * s * minus_c,
        }
    }
}

/// A material's texture.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    pub image: ImageId,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
    pub transform: TexTransform,
    pub model: TextureModel,
    /// Only for [`TextureModel::Blend`], linear 0..1 RGB.
    pub blend_color: Vec3,
    pub filter: Filter,
    /// glTF alphaMode MASK: a pixel is drawn opaque where its alpha
    /// (material × texture) reaches this value and not at all below.
    pub alpha_cutoff: Option<f32>,
}

impl Texture {
    /// A repeating texture with no transform and VRML97 lighting.
    pub fn new(image: ImageId) -> Texture {
        Texture {
            image,
            wrap_s: Wrap::Repeat,
            wrap_t: Wrap::Repeat,
            transform: TexTransform::default(),
            model: TextureModel::Vrml97,
            blend_color: Vec3::ZERO,
            filter: Filter::default(),
            alpha_cutoff: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vrml97_translates_before_rotating_about_the_centre() {
        let t = TexTransform {
            translation: Vec2::new(0.5, 0.0),
            rotation: std::f32::consts::FRAC_PI_2,
            center: Vec2::splat(0.5),
            ..TexTransform::default()
        };
        let p = t.matrix().transform_point2(Vec2::ZERO);
        // T: (0.5,0); C: (1,0.5); R: (-0.5,1); S: same; -C: (-1,0.5).
        assert!((p - Vec2::new(-1.0, 0.5)).length() < 1e-6, "{p}");
    }

    #[test]
    fn inventor_scales_about_the_centre_then_translates() {
        let t = TexTransform {
            translation: Vec2::new(0.25, 0.0),
            scale: Vec2::splat(2.0),
            center: Vec2::splat(0.5),
            order: TexTransformOrder::Inventor,
            ..TexTransform::default()
        };
        // -C: (-0.5,-0.5); S: (-1,-1); T: (-0.75,-1); C: (-0.25,-0.5).
        let p = t.matrix().transform_point2(Vec2::ZERO);
        assert!((p - Vec2::new(-0.25, -0.5)).length() < 1e-6, "{p}");
        assert!(!t.is_identity());
        assert!(TexTransform::default().is_identity());
    }
}
