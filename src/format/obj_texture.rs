//! MTL texture maps → a scene texture: `map_Kd` (the colour, multiplied by
//! Kd) and `map_d` (the alpha, from the image's alpha channel when it has
//! one, else its luminance, as the MTL spec's `-imfchan l` default for
//! scalar maps says), with the `-s`/`-o` scale and offset and `-clamp on`.
//! Wavefront "MTL material format" (Alias|Wavefront, 1995), texture map
//! options.
//!
//! A map that cannot be read is a warning; the material is then drawn with
//! what did load (or untextured).

use super::textures::{cannot_read, Loader};
use crate::scene::{Image, Scene, TexTransform, TexTransformOrder, Texture, TextureModel, Wrap};
use glam::Vec2;

/// A map statement's options and file name.
#[derive(Debug, PartialEq)]
pub struct MapSpec {
    pub file: String,
    pub scale: Vec2,
    pub offset: Vec2,
    pub clamp: bool,
}

/// Splits `-opt args… file name` (the rest of a `map_*` line).
pub fn parse_map(line: &str) -> MapSpec {
    let words: Vec<&str> = line.split_whitespace().collect();
    let mut spec = MapSpec {
        file: String::new(),
        scale: Vec2::ONE,
        offset: Vec2::ZERO,
        clamp: false,
    };
    let mut i = 0;
    while i < words.len() && words[i].starts_with('-') && words[i].len() > 1 {
        let opt = words[i];
        i += 1;
        // Up to three numbers follow -o, -s, -t; a fixed count the others.
        let numbers = |i: &mut usize, most: usize| -> Vec<f32> {
            let mut v = Vec::new();
            while v.len() < most {
                match words.get(*i).and_then(|w| w.parse::<f32>().ok()) {
                    Some(x) if x.is_finite() => {
                        v.push(x);
                        *i += 1;
                    }
                    _ => break,
                }
            }
            v
        };
        match opt {
            "-s" | "-o" => {
                let v = numbers(&mut i, 3);
                let u = v.first().copied();
                let w = v.get(1).copied();
                let d = if opt == "-s" { 1.0 } else { 0.0 };
                let p = Vec2::new(u.unwrap_or(d), w.unwrap_or(d));
                if opt == "-s" {
                    spec.scale = p;
                } else {
                    spec.offset = p;
                }
            }
            "-t" => {
                numbers(&mut i, 3);
            }
            "-clamp" => {
                spec.clamp = words.get(i).is_some_and(|w| w.eq_ignore_ascii_case("on"));
                i += 1;
            }
            "-mm" => {
                numbers(&mut i, 2);
            }
            // -blendu, -blendv, -cc, -bm, -boost, -texres, -imfchan, -type.
            _ => i += 1,
        }
    }
    spec.file = words[i.min(words.len())..].join(" ");
    spec
}

/// The texture of an MTL material with `map_Kd` and/or `map_d`, loading
/// images through `loader`; each warning is pushed with the MTL statement
/// it is about (`map_Kd` or `map_d`), which the caller turns into a place.
pub fn material_texture(
    m: &tobj::Material,
    scene: &mut Scene,
    loader: &mut Loader,
    warnings: &mut Vec<(&'static str, String)>,
) -> Option<Texture> {
    let kd = m.diffuse_texture.as_deref().map(parse_map);
    let d = m.dissolve_texture.as_deref().map(parse_map);
    let color = kd.as_ref().and_then(|k| match loader.read(&k.file) {
        Ok(img) => Some(img),
        Err(e) => {
            warnings.push(("map_Kd", cannot_read(&k.file, &e)));
            None
        }
    });
    let alpha = d.as_ref().and_then(|k| match loader.read(&k.file) {
        Ok(img) => Some(img),
        Err(e) => {
            warnings.push(("map_d", cannot_read(&k.file, &e)));
            None
        }
    });
    let statement = if color.is_some() { "map_Kd" } else { "map_d" };
    let spec = if color.is_some() { kd } else { d }?;
    let image = match (color, alpha) {
        (Some(c), None) => c,
        (c, Some(a)) => match with_alpha(c.as_ref(), &a) {
            Ok(img) => img,
            Err(e) => {
                warnings.push(("map_d", cannot_read(&a.name, &e)));
                c?
            }
        },
        (None, None) => return None,
    };
    let id = match scene.add_image(image) {
        Ok(id) => id,
        Err(e) => {
            warnings.push((statement, cannot_read(&spec.file, &e.to_string())));
            return None;
        }
    };
    let mut t = Texture::new(id);
    t.model = TextureModel::MultiplyDiffuse;
    if spec.clamp {
        t.wrap_s = Wrap::Clamp;
        t.wrap_t = Wrap::Clamp;
    }
    // MTL: st' = st × s + o, i.e. VRML97's order (translate, then scale)
    // with the translation o / s.
    if spec.scale != Vec2::ONE || spec.offset != Vec2::ZERO {
        let s = spec.scale;
        if s.x != 0.0 && s.y != 0.0 {
            t.transform = TexTransform {
                translation: spec.offset / s,
                scale: s,
                rotation: 0.0,
                center: Vec2::ZERO,
                order: TexTransformOrder::Vrml97,
            };
        }
    }
    Some(t)
}

/// `color` (white when None) with the alpha of `alpha`: its alpha channel
/// when it has a varying one, else its luminance; sampled nearest when the
/// sizes differ. Keeps `color`'s source (writers name its file).
fn with_alpha(color: Option<&Image>, alpha: &Image) -> Result<Image, String> {
    let a = alpha.base();
    let (w, h) = color.map_or((a.width(), a.height()), |c| {
        (c.base().width(), c.base().height())
    });
    let use_alpha = matches!(alpha.components(), 2 | 4) && alpha.has_alpha();
    let mut px = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h {
        for x in 0..w {
            let ax = (x as u64 * a.width() as u64 / w as u64) as u32;
            let ay = (y as u64 * a.height() as u64 / h as u64) as u32;
            let t = a.texel(ax, ay);
            let alpha = if use_alpha {
                t[3]
            } else {
                // Rec. 601 luma, integer weights summing to 1000.
                ((t[0] as u32 * 299 + t[1] as u32 * 587 + t[2] as u32 * 114 + 500) / 1000) as u8
            };
            let rgb = color.map_or([255; 4], |c| c.base().texel(x, y));
            px.push([rgb[0], rgb[1], rgb[2], alpha]);
        }
    }
    let (name, source, comps) = match color {
        Some(c) => (c.name.clone(), c.source.clone(), 4),
        None => (alpha.name.clone(), alpha.source.clone(), 2),
    };
    Image::new(&name, source, w, h, comps, px).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::ImageSource;

    #[test]
    fn map_options_and_names_with_spaces() {
        let m = parse_map("-s 2 3 1 -o 0.5 -clamp on -bm 0.2 my bark.png");
        assert_eq!(m.file, "my bark.png");
        assert_eq!(m.scale, Vec2::new(2.0, 3.0));
        assert_eq!(m.offset, Vec2::new(0.5, 0.0));
        assert!(m.clamp);
        assert_eq!(parse_map("tex.jpg").file, "tex.jpg");
        assert_eq!(parse_map("-imfchan m a.png").file, "a.png");
        // An option with nothing after it leaves no file name (not a panic).
        assert_eq!(parse_map("-s").file, "");
    }

    #[test]
    fn alpha_from_luminance_or_alpha_channel() {
        let c = Image::new(
            "c",
            ImageSource::Inline,
            2,
            1,
            3,
            vec![[10, 20, 30, 255]; 2],
        )
        .unwrap();
        let grey = Image::new(
            "a",
            ImageSource::Inline,
            1,
            1,
            1,
            vec![[128, 128, 128, 255]],
        )
        .unwrap();
        let img = with_alpha(Some(&c), &grey).unwrap();
        assert_eq!((img.components(), img.name.as_str()), (4, "c"));
        assert_eq!(img.base().texel(1, 0), [10, 20, 30, 128]);
        let rgba = Image::new("a", ImageSource::Inline, 1, 1, 4, vec![[255, 255, 255, 7]]).unwrap();
        let img = with_alpha(None, &rgba).unwrap();
        assert_eq!(img.components(), 2);
        assert_eq!(img.base().texel(0, 0), [255, 255, 255, 7]);
    }
}
