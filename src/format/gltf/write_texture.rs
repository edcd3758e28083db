//! The glTF writer's textures: a material's texture becomes its
//! `baseColorTexture` and its emissive map its `emissiveTexture` (each with
//! KHR_texture_transform when it has a transform), reading `TEXCOORD_0`
//! (written with v = 1 − t, see `texture`).
//!
//! Images: in a `.gltf`, a PNG or JPEG file texture is referenced by its
//! url (relative to the output, as the other writers do); everything else —
//! every image of a `.glb`, inline images, SGI/BMP/GIF files — is embedded
//! in the buffer: PNG and JPEG files byte for byte, other images encoded
//! as PNG with their component count. Samplers: REPEAT or CLAMP_TO_EDGE,
//! LINEAR / LINEAR_MIPMAP_LINEAR (what animed draws).

use super::bin::{num, Bin};
use super::texture::khr_from_transform;
use crate::format::export::WriteReport;
use crate::format::textures::decode::read_file;
use crate::scene::{Image, ImageSource, MipMode, Scene, Texture, TextureModel, Wrap};
use serde_json::{json, Value as Json};
use std::collections::BTreeMap;

/// Images, samplers and textures written so far.
#[derive(Default)]
pub struct TextureWriter {
    pub images: Vec<Json>,
    pub samplers: Vec<Json>,
    pub textures: Vec<Json>,
    image_index: BTreeMap<u32, usize>,
    /// Samplers by (wrapS, wrapT, magFilter, minFilter) codes.
    sampler_index: BTreeMap<[u32; 4], usize>,
    texture_index: BTreeMap<(usize, usize), usize>,
    /// Whether any texture info carries KHR_texture_transform.
    pub transform_used: bool,
}

impl TextureWriter {
    /// The textureInfo (`baseColorTexture`, `emissiveTexture`) of a
    /// material's texture, or None (with a warning) when its image is
    /// missing.
    pub fn info(
        &mut self,
        scene: &Scene,
        t: &Texture,
        bin: &mut Bin,
        binary: bool,
        report: &mut WriteReport,
    ) -> Option<Json> {
        let Some(image) = scene.image(t.image) else {
            report
                .warnings
                .push(format!("a material refers to missing image {}", t.image.0));
            return None;
        };
        let ii = match self.image_index.get(&t.image.0) {
            Some(&i) => i,
            None => {
                let j = image_json(image, bin, binary, report)?;
                self.images.push(j);
                self.image_index.insert(t.image.0, self.images.len() - 1);
                self.images.len() - 1
            }
        };
        let key = sampler_codes(t);
        let si = *self.sampler_index.entry(key).or_insert_with(|| {
            self.samplers.push(json!({
                "magFilter": key[2],
                "minFilter": key[3],
                "wrapS": key[0],
                "wrapT": key[1],
            }));
            self.samplers.len() - 1
        });
        let ti = *self.texture_index.entry((ii, si)).or_insert_with(|| {
            self.textures.push(json!({ "source": ii, "sampler": si }));
            self.textures.len() - 1
        });
        let mut info = json!({ "index": ti });
        if !t.transform.is_identity() {
            match khr_from_transform(&t.transform) {
                Some((o, r, s)) => {
                    let mut x = json!({});
                    if o != glam::Vec2::ZERO {
                        x["offset"] = json!([num(o.x), num(o.y)]);
                    }
                    if r != 0.0 {
                        x["rotation"] = num(r);
                    }
                    if s != glam::Vec2::ONE {
                        x["scale"] = json!([num(s.x), num(s.y)]);
                    }
                    info["extensions"] = json!({ "KHR_texture_transform": x });
                    self.transform_used = true;
                }
                None => report.warnings.push(format!(
                    "texture {:?}: a rotated, non-uniformly scaled texture transform has no KHR_texture_transform form; written without it",
                    image.name
                )),
            }
        }
        if matches!(
            t.model,
            TextureModel::Modulate | TextureModel::Decal | TextureModel::Blend
        ) {
            report.warnings.push(format!(
                "texture {:?}: Inventor's {:?} model has no glTF form; written as a base colour texture",
                image.name, t.model
            ));
        }
        Some(info)
    }

    /// Puts `images`, `samplers` and `textures` into the document.
    pub fn finish(self, doc: &mut Json) {
        for (key, v) in [
            ("images", self.images),
            ("samplers", self.samplers),
            ("textures", self.textures),
        ] {
            if !v.is_empty() {
                doc[key] = Json::Array(v);
            }
        }
    }
}

/// Whether VRML97 lighting lets this texture replace the diffuse colour
/// (then the glTF base colour factor is white, so glTF's multiply gives the
/// same colour).
pub fn replaces_diffuse(scene: &Scene, t: &Texture) -> bool {
    let comps = scene.image(t.image).map_or(0, Image::components);
    match t.model {
        TextureModel::Vrml97 => comps >= 3,
        TextureModel::Replace | TextureModel::Decal => true,
        _ => false,
    }
}

fn is_png(b: &[u8]) -> bool {
    b.starts_with(b"\x89PNG\r\n\x1a\n")
}

fn is_jpeg(b: &[u8]) -> bool {
    b.starts_with(&[0xFF, 0xD8, 0xFF])
}

fn image_json(
    image: &Image,
    bin: &mut Bin,
    binary: bool,
    report: &mut WriteReport,
) -> Option<Json> {
    let mut j = json!({});
    if !image.name.is_empty() {
        j["name"] = json!(image.name);
    }
    if let ImageSource::File { url, path } = &image.source {
        let lower = url.to_ascii_lowercase();
        let web = [".png", ".jpg", ".jpeg"].iter().any(|e| lower.ends_with(e));
        if !binary && web {
            j["uri"] = json!(uri_escape(url));
            return Some(j);
        }
        // Embed the file itself when it is PNG or JPEG.
        if let Ok(bytes) = read_file(path) {
            let mime = if is_png(&bytes) {
                Some("image/png")
            } else if is_jpeg(&bytes) {
                Some("image/jpeg")
            } else {
                None
            };
            if let Some(m) = mime {
                j["bufferView"] = json!(bin.raw(&bytes));
                j["mimeType"] = json!(m);
                return Some(j);
            }
        }
    }
    match encode_png(image) {
        Ok(bytes) => {
            j["bufferView"] = json!(bin.raw(&bytes));
            j["mimeType"] = json!("image/png");
            Some(j)
        }
        Err(e) => {
            report.warnings.push(format!(
                "texture {:?}: cannot encode it as PNG: {e}; written untextured",
                image.name
            ));
            None
        }
    }
}

/// The image's base level as PNG, keeping its component count.
pub fn encode_png(image: &Image) -> Result<Vec<u8>, String> {
    let base = image.base();
    let (w, h) = (base.width(), base.height());
    let px = base.pixels();
    let (data, color): (Vec<u8>, image::ExtendedColorType) = match image.components() {
        1 => (
            px.iter().map(|p| p[0]).collect(),
            image::ExtendedColorType::L8,
        ),
        2 => (
            px.iter().flat_map(|p| [p[0], p[3]]).collect(),
            image::ExtendedColorType::La8,
        ),
        3 => (
            px.iter().flat_map(|p| [p[0], p[1], p[2]]).collect(),
            image::ExtendedColorType::Rgb8,
        ),
        _ => (
            px.iter().flatten().copied().collect(),
            image::ExtendedColorType::Rgba8,
        ),
    };
    let mut out = Vec::new();
    image::ImageEncoder::write_image(
        image::codecs::png::PngEncoder::new(&mut out),
        &data,
        w,
        h,
        color,
    )
    .map_err(|e| e.to_string())?;
    Ok(out)
}

/// A relative file url as a URI reference: RFC 3986 unreserved characters
/// and `/` kept, everything else percent-encoded.
fn uri_escape(url: &str) -> String {
    let mut s = String::new();
    for b in url.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~/".contains(&b) {
            s.push(b as char);
        } else {
            s.push_str(&format!("%{b:02X}"));
        }
    }
    s
}

/// A texture's glTF sampler codes (§5.26): wrapS, wrapT, magFilter,
/// minFilter.
fn sampler_codes(t: &Texture) -> [u32; 4] {
    let wrap = |w: Wrap| match w {
        Wrap::Repeat => 10497,
        Wrap::Clamp => 33071,
        Wrap::Mirror => 33648,
    };
    let f = t.filter;
    let mag = if f.mag_nearest { 9728 } else { 9729 };
    let min = match (f.min_nearest, f.mip) {
        (true, MipMode::None) => 9728,
        (false, MipMode::None) => 9729,
        (true, MipMode::Nearest) => 9984,
        (false, MipMode::Nearest) => 9985,
        (true, MipMode::Linear) => 9986,
        (false, MipMode::Linear) => 9987,
    };
    [wrap(t.wrap_s), wrap(t.wrap_t), mag, min]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn urls_escape_and_png_keeps_components() {
        assert_eq!(uri_escape("my tex/ä.png"), "my%20tex/%C3%A4.png");
        let img = Image::new(
            "g",
            ImageSource::Inline,
            2,
            1,
            2,
            vec![[9, 9, 9, 100], [7, 7, 7, 255]],
        )
        .unwrap();
        let png = encode_png(&img).unwrap();
        let back = crate::format::textures::decode::decode(&png, "g", ImageSource::Inline).unwrap();
        assert_eq!(back.components(), 2);
        assert_eq!(back.base().pixels(), img.base().pixels());
    }
}
