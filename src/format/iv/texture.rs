//! Inventor / VRML 1.0 Texture2 (filename or inline `image`, wrapS/T,
//! model MODULATE/DECAL/BLEND with blendColor) → a scene texture.
//!
//! A file that cannot be read is a warning `cannot read texture 'x':
//! reason` at the Texture2 node; the inline image is used instead when the
//! node has one, otherwise the shapes are drawn untextured.

use super::build::Builder;
use super::state::{State, TexXf};
use crate::format::syntax::AstNode;
use crate::format::textures::{self, cannot_read};
use crate::scene::{ImageId, TexTransform, Texture, TextureModel, Wrap};
use std::rc::Rc;

impl Builder {
    /// The texture the state puts on shapes, if its image loads.
    pub(super) fn texture(&mut self, st: &State) -> Option<Texture> {
        let node = st.texture.as_ref()?;
        let key = Rc::as_ptr(node) as usize;
        let image = match self.texture_images.get(&key) {
            Some(id) => *id,
            None => {
                let id = self.texture_image(node);
                self.texture_images.insert(key, id);
                id
            }
        }?;
        let mut t = Texture::new(image);
        let wrap = |f: &str| match node.words(f).first().map(String::as_str) {
            Some("CLAMP") => Wrap::Clamp,
            _ => Wrap::Repeat,
        };
        t.wrap_s = wrap("wrapS");
        t.wrap_t = wrap("wrapT");
        t.model = match node.words("model").first().map(String::as_str) {
            Some("DECAL") => TextureModel::Decal,
            Some("BLEND") => TextureModel::Blend,
            // Coin's extension: the texture colour, unlit.
            Some("REPLACE") => TextureModel::Replace,
            _ => TextureModel::Modulate,
        };
        if t.model == TextureModel::Blend {
            t.blend_color = node
                .vec3("blendColor", glam::Vec3::ZERO)
                .clamp(glam::Vec3::ZERO, glam::Vec3::ONE);
        }
        t.transform = match st.tex_transform {
            TexXf::One(x) => x,
            // Baked into the shape's coordinates (see shapes::mesh).
            TexXf::None | TexXf::Baked(_) => TexTransform::default(),
        };
        Some(t)
    }

    /// Loads a Texture2's image: the file when `filename` is given (the
    /// inline image is the fallback), else the inline `image`.
    fn texture_image(&mut self, n: &AstNode) -> Option<ImageId> {
        let files: Vec<String> = n
            .strings("filename")
            .into_iter()
            .filter(|f| !f.trim().is_empty())
            .collect();
        if !files.is_empty() {
            match self.loader.load(&mut self.scene, &files) {
                Ok(id) => return Some(id),
                Err(msgs) => {
                    for m in msgs {
                        self.warn(n.pos, &m);
                    }
                }
            }
        }
        let nums = n.nums("image").unwrap_or(&[]);
        let name = n.def.clone().unwrap_or_else(|| "Texture2".into());
        match textures::sf_image(nums, &name) {
            Ok(Some(img)) => match self.scene.add_image(img) {
                Ok(id) => Some(id),
                Err(e) => {
                    self.warn(n.pos, &cannot_read(&name, &e.to_string()));
                    None
                }
            },
            Ok(None) => None,
            Err(e) => {
                self.warn(n.pos, &cannot_read(&name, &e));
                None
            }
        }
    }
}
