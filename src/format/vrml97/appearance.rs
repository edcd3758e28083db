//! VRML97 Appearance textures (ISO/IEC 14772-1 §6.22 ImageTexture, §6.36
//! PixelTexture, §6.28 MovieTexture, §6.49 TextureTransform) and the
//! Background node (§6.5) → scene textures and background.
//!
//! An image that cannot be read is a warning `cannot read texture 'x':
//! reason` at the texture node; the shape is then drawn untextured.

use super::build::Builder;
use crate::format::syntax::{AstNode, NodeRef};
use crate::format::textures::{self, cannot_read};
use crate::scene::{
    Background, Face, ImageId, TexTransform, TexTransformOrder, Texture, TextureModel, Wrap,
};
use glam::{Vec2, Vec3};
use std::rc::Rc;

impl Builder {
    /// The texture of an Appearance node, if it has one that loads.
    pub(super) fn texture(&mut self, app: &NodeRef) -> Option<Texture> {
        let tex = app.node("texture")?.effective();
        let image = match self.texture_images.get(&Rc::as_ptr(&tex)) {
            Some(id) => *id,
            None => {
                let id = self.texture_image(&tex);
                self.texture_images.insert(Rc::as_ptr(&tex), id);
                id
            }
        }?;
        let mut t = Texture::new(image);
        if !tex.bool("repeatS", true) {
            t.wrap_s = Wrap::Clamp;
        }
        if !tex.bool("repeatT", true) {
            t.wrap_t = Wrap::Clamp;
        }
        if let Some(tt) = app.node("textureTransform").map(|n| n.effective()) {
            if tt.kind == "TextureTransform" {
                t.transform = TexTransform {
                    translation: vec2(&tt, "translation", Vec2::ZERO),
                    rotation: tt.f32("rotation", 0.0),
                    scale: vec2(&tt, "scale", Vec2::ONE),
                    center: vec2(&tt, "center", Vec2::ZERO),
                    order: TexTransformOrder::Vrml97,
                };
            }
        }
        // §4.14.3: without a Material the texture colour is the unlit colour.
        if app.node("material").is_none() {
            t.model = TextureModel::Replace;
        }
        Some(t)
    }

    /// Loads the image of a texture node (once per node).
    fn texture_image(&mut self, tex: &AstNode) -> Option<ImageId> {
        match tex.kind.as_str() {
            "ImageTexture" | "MovieTexture" => {
                let urls = tex.strings("url");
                if urls.is_empty() {
                    return None;
                }
                match self.loader.load(&mut self.scene, &urls) {
                    Ok(id) => Some(id),
                    Err(msgs) => {
                        for m in msgs {
                            let m = if tex.kind == "MovieTexture" {
                                format!("MovieTexture: {m} (only a first frame in an image format is shown)")
                            } else {
                                m
                            };
                            self.warn(tex.pos, &m);
                        }
                        None
                    }
                }
            }
            "PixelTexture" => {
                let name = tex.def.clone().unwrap_or_else(|| "PixelTexture".into());
                let nums = tex.nums("image").unwrap_or(&[]);
                match textures::sf_image(nums, &name) {
                    Ok(Some(img)) => match self.scene.add_image(img) {
                        Ok(id) => Some(id),
                        Err(e) => {
                            self.warn(tex.pos, &cannot_read(&name, &e.to_string()));
                            None
                        }
                    },
                    Ok(None) => None,
                    Err(e) => {
                        self.warn(tex.pos, &cannot_read(&name, &e));
                        None
                    }
                }
            }
            k => {
                let msg = format!("texture node '{k}' is not supported; drawn untextured");
                self.warn_once(k, tex.pos, &msg);
                None
            }
        }
    }

    /// The first Background node's sky, ground and panorama.
    pub(super) fn background(&mut self, n: &AstNode) -> Background {
        let mut bg = Background {
            sky_color: colors(n, "skyColor"),
            sky_angle: angles(n, "skyAngle"),
            ground_color: colors(n, "groundColor"),
            ground_angle: angles(n, "groundAngle"),
            ..Background::default()
        };
        if bg.sky_color.is_empty() {
            bg.sky_color.push(Vec3::ZERO);
        }
        for (i, face) in Face::ALL.iter().enumerate() {
            let urls = n.strings(face.field());
            if urls.is_empty() {
                continue;
            }
            match self.loader.load(&mut self.scene, &urls) {
                Ok(id) => bg.panorama[i] = Some(id),
                Err(msgs) => {
                    for m in msgs {
                        self.warn(n.pos, &format!("Background {}: {m}", face.field()));
                    }
                }
            }
        }
        bg
    }
}

fn vec2(n: &AstNode, field: &str, default: Vec2) -> Vec2 {
    match n.nums(field) {
        Some([x, y, ..]) => Vec2::new(*x as f32, *y as f32),
        _ => default,
    }
}

fn colors(n: &AstNode, field: &str) -> Vec<Vec3> {
    n.nums(field)
        .unwrap_or(&[])
        .chunks_exact(3)
        .map(|c| Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32).clamp(Vec3::ZERO, Vec3::ONE))
        .collect()
}

fn angles(n: &AstNode, field: &str) -> Vec<f32> {
    n.nums(field)
        .unwrap_or(&[])
        .iter()
        .map(|a| *a as f32)
        .filter(|a| a.is_finite())
        .collect()
}
