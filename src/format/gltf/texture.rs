//! glTF base colour and emissive textures (spec §3.8, §3.9.2, §3.9.3) →
//! scene textures: the
//! image (PNG or JPEG, from a buffer view, a `data:` URI or a file beside
//! the .gltf), the sampler's wrap modes, the `texCoord` set and
//! KHR_texture_transform.
//!
//! glTF's uv origin is the image's top-left corner with v down; animed's
//! texture coordinates have t up from the bottom-left (VRML). The reader
//! stores t = 1 − v, and a texture transform is conjugated by that flip
//! ([`transform_from_khr`]) so it maps the same texels.
//!
//! An image that cannot be read is a warning naming its JSON pointer; the
//! material is then drawn untextured. Sampler wraps (REPEAT,
//! CLAMP_TO_EDGE, MIRRORED_REPEAT) and filters (NEAREST/LINEAR, mipmap
//! NEAREST/LINEAR or none) are drawn as given; alphaMode MASK is an alpha
//! test against alphaCutoff (see `read.rs`).

use super::container::Buffers;
use super::pointer::pointer;
use super::uri;
use crate::format::textures::decode;
use crate::scene::{
    Filter, ImageId, ImageSource, MipMode, Scene, TexTransform, TexTransformOrder, Texture,
    TextureModel, Wrap,
};
use glam::{Affine2, Vec2};
use gltf::texture::{MagFilter, MinFilter, WrappingMode};
use std::path::Path;

/// Decodes every image a material's base colour or emissive texture uses
/// (once each), by image index; `None` where it is unused or failed (with a
/// warning).
pub fn load_images(
    doc: &gltf::Document,
    buffers: &Buffers,
    base: &Path,
    read_file: &dyn Fn(&Path) -> Result<Vec<u8>, String>,
    scene: &mut Scene,
    warnings: &mut Vec<String>,
) -> Vec<Option<ImageId>> {
    let json = doc.as_json();
    let mut used = vec![false; json.images.len()];
    for m in doc.materials() {
        let base = m.pbr_metallic_roughness().base_color_texture();
        for info in [base, m.emissive_texture()].into_iter().flatten() {
            if let Some(u) = json
                .textures
                .get(info.texture().index())
                .and_then(|t| used.get_mut(t.source.value()))
            {
                *u = true;
            }
        }
    }
    let mut out = vec![None; json.images.len()];
    for (i, img) in json.images.iter().enumerate() {
        if !used[i] {
            continue;
        }
        let here = pointer(&[&"images", &i]);
        let name = img.name.clone().unwrap_or_else(|| format!("image{i}"));
        let r = image_bytes(img, doc, buffers, base, read_file).and_then(|(bytes, source)| {
            let name = match &source {
                ImageSource::File { url, .. } => url.clone(),
                ImageSource::Inline => name.clone(),
            };
            decode::decode(&bytes, &name, source)
        });
        match r.and_then(|image| scene.add_image(image).map_err(|e| e.to_string())) {
            Ok(id) => out[i] = Some(id),
            Err(e) => warnings.push(format!(
                "{here}: cannot read texture '{name}': {e}; drawn untextured"
            )),
        }
    }
    out
}

/// The encoded bytes of an image and where they came from.
fn image_bytes(
    img: &gltf::json::Image,
    doc: &gltf::Document,
    buffers: &Buffers,
    base: &Path,
    read_file: &dyn Fn(&Path) -> Result<Vec<u8>, String>,
) -> Result<(Vec<u8>, ImageSource), String> {
    if let Some(v) = &img.buffer_view {
        let view = doc
            .views()
            .nth(v.value())
            .ok_or("bufferView out of range")?;
        let data = buffers
            .data
            .get(view.buffer().index())
            .ok_or("buffer out of range")?;
        let end = view
            .offset()
            .checked_add(view.length())
            .filter(|&e| e <= data.len())
            .ok_or("bufferView runs past its buffer")?;
        return Ok((data[view.offset()..end].to_vec(), ImageSource::Inline));
    }
    let u = img
        .uri
        .as_deref()
        .ok_or("image has neither uri nor bufferView")?;
    if u.starts_with("data:") {
        return Ok((uri::resolve(u, base, read_file)?, ImageSource::Inline));
    }
    let path = uri::file_path(u, base)?;
    let bytes = read_file(&path)?;
    let url = uri::percent_decode(u)?;
    Ok((bytes, ImageSource::File { url, path }))
}

/// The scene texture of a glTF material's base colour texture, if its image
/// loaded: multiplies the base colour (MultiplyDiffuse), wraps and
/// transform from the sampler and KHR_texture_transform. Also returns the
/// TEXCOORD set it reads.
pub fn base_color_texture(
    m: &gltf::Material,
    images: &[Option<ImageId>],
) -> Option<(Texture, u32)> {
    let info = m.pbr_metallic_roughness().base_color_texture()?;
    let mut t = from_info(&info, images)?;
    t.model = TextureModel::MultiplyDiffuse;
    Some((t, set_of(&info)))
}

/// The scene texture of a glTF material's emissive texture (§3.9.3), if its
/// image loaded, and the TEXCOORD set it reads. It scales the emissive
/// factor (see `scene::Material::emissive_texture`); the model field is
/// unused for emissive maps.
pub fn emissive_texture(m: &gltf::Material, images: &[Option<ImageId>]) -> Option<(Texture, u32)> {
    let info = m.emissive_texture()?;
    Some((from_info(&info, images)?, set_of(&info)))
}

/// A textureInfo's image, sampler and KHR_texture_transform as a scene
/// texture (VRML97 model; the caller sets its own).
fn from_info(info: &gltf::texture::Info, images: &[Option<ImageId>]) -> Option<Texture> {
    let tex = info.texture();
    let image = tex.source().index();
    let id = images.get(image).copied().flatten()?;
    let mut t = Texture::new(id);
    let s = tex.sampler();
    let wrap = |w: WrappingMode| match w {
        WrappingMode::ClampToEdge => Wrap::Clamp,
        WrappingMode::Repeat => Wrap::Repeat,
        WrappingMode::MirroredRepeat => Wrap::Mirror,
    };
    t.wrap_s = wrap(s.wrap_s());
    t.wrap_t = wrap(s.wrap_t());
    t.filter = filter(s.mag_filter(), s.min_filter());
    if let Some(x) = info.texture_transform() {
        t.transform = transform_from_khr(
            Vec2::from_array(x.offset()),
            x.rotation(),
            Vec2::from_array(x.scale()),
        );
    }
    Some(t)
}

/// glTF sampler filters (§3.8.4; absent = the implementation's choice:
/// trilinear) as the scene's [`Filter`].
pub fn filter(mag: Option<MagFilter>, min: Option<MinFilter>) -> Filter {
    use MinFilter::*;
    let (min_nearest, mip) = match min {
        None | Some(LinearMipmapLinear) => (false, MipMode::Linear),
        Some(Nearest) => (true, MipMode::None),
        Some(Linear) => (false, MipMode::None),
        Some(NearestMipmapNearest) => (true, MipMode::Nearest),
        Some(LinearMipmapNearest) => (false, MipMode::Nearest),
        Some(NearestMipmapLinear) => (true, MipMode::Linear),
    };
    Filter {
        mag_nearest: mag == Some(MagFilter::Nearest),
        min_nearest,
        mip,
    }
}

/// The TEXCOORD set a textureInfo reads (KHR_texture_transform's
/// `texCoord` overrides the textureInfo's).
fn set_of(info: &gltf::texture::Info) -> u32 {
    info.texture_transform()
        .and_then(|x| x.tex_coord())
        .unwrap_or(info.tex_coord())
}

/// KHR_texture_transform (uv' = T(offset)·R(rotation)·S(scale)·uv, with
/// R = [[cos, sin], [−sin, cos]] in uv, v down) in animed's coordinates
/// (s = u, t = 1 − v). With F(s, t) = (s, 1 − t), the map is F∘G∘F =
/// T(t')·R'(θ)·S where R' is the ordinary counter-clockwise rotation by θ
/// and t' = (oₓ + sin θ·s_y, 1 − o_y − cos θ·s_y): an Inventor-order
/// transform (scale, rotate, translate) with a zero centre.
pub fn transform_from_khr(offset: Vec2, rotation: f32, scale: Vec2) -> TexTransform {
    let (s, c) = (libm::sinf(rotation), libm::cosf(rotation));
    TexTransform {
        translation: Vec2::new(offset.x + s * scale.y, 1.0 - offset.y - c * scale.y),
        rotation,
        scale,
        center: Vec2::ZERO,
        order: TexTransformOrder::Inventor,
    }
}

/// The KHR_texture_transform (offset, rotation, scale) of a scene texture
/// transform, or `None` when its linear part is not a rotation times a
/// scale (a shear, from a rotated non-uniform VRML97 transform).
pub fn khr_from_transform(t: &TexTransform) -> Option<(Vec2, f32, Vec2)> {
    let m: Affine2 = t.matrix();
    let (a, b) = (m.matrix2.x_axis, m.matrix2.y_axis);
    let sx = a.length();
    let rotation = libm::atan2f(a.y, a.x);
    let (s, c) = (libm::sinf(rotation), libm::cosf(rotation));
    // b must be s_y·(−sin, cos).
    let sy = b.dot(Vec2::new(-s, c));
    let fits = (b - sy * Vec2::new(-s, c)).length() <= 1e-5 * (sx.abs() + sy.abs()).max(1e-6);
    if !fits || sx == 0.0 || sy == 0.0 || !m.translation.is_finite() {
        return None;
    }
    let tr = m.translation;
    let offset = Vec2::new(tr.x - s * sy, 1.0 - c * sy - tr.y);
    Some((offset, rotation, Vec2::new(sx, sy)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The spec's example: the lower-left quadrant of the image, turned.
    #[test]
    fn khr_example_maps_the_unit_square_to_the_lower_left_quadrant() {
        let off = Vec2::new(0.0, 1.0);
        let (rot, sc) = (std::f32::consts::FRAC_PI_2, Vec2::splat(0.5));
        // glTF directly: uv' = o + R·S·uv with R = [[c, s], [−s, c]].
        let g = |uv: Vec2| {
            let p = uv * sc;
            let (s, c) = (rot.sin(), rot.cos());
            off + Vec2::new(c * p.x + s * p.y, -s * p.x + c * p.y)
        };
        let t = transform_from_khr(off, rot, sc).matrix();
        for uv in [Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ONE, Vec2::new(0.3, 0.8)] {
            let ours = t.transform_point2(Vec2::new(uv.x, 1.0 - uv.y));
            let want = g(uv);
            let want = Vec2::new(want.x, 1.0 - want.y);
            assert!((ours - want).length() < 1e-6, "{uv}: {ours} vs {want}");
            // Lower-left quadrant: u in 0..0.5, v in 0.5..1, i.e. t in 0..0.5.
            assert!(ours.x > -1e-6 && ours.x < 0.5 + 1e-6 && ours.y > -1e-6 && ours.y < 0.5 + 1e-6);
        }
        let (o2, r2, s2) = khr_from_transform(&transform_from_khr(off, rot, sc)).unwrap();
        assert!((o2 - off).length() < 1e-6 && (r2 - rot).abs() < 1e-6 && (s2 - sc).length() < 1e-6);
    }

    #[test]
    fn sheared_transforms_have_no_khr_form() {
        let t = TexTransform {
            rotation: 0.5,
            scale: Vec2::new(2.0, 1.0),
            ..TexTransform::default()
        };
        // VRML97 order: S·R — a shear once conjugated.
        assert!(khr_from_transform(&t).is_none());
        let t = TexTransform {
            scale: Vec2::new(2.0, -1.0),
            translation: Vec2::new(0.25, 0.5),
            ..TexTransform::default()
        };
        let (o, r, s) = khr_from_transform(&t).unwrap();
        let back = transform_from_khr(o, r, s).matrix();
        let m = t.matrix();
        for p in [Vec2::ZERO, Vec2::ONE, Vec2::new(0.2, 0.7)] {
            assert!((back.transform_point2(p) - m.transform_point2(p)).length() < 1e-5);
        }
    }
}
