//! What the writers share about textures: image urls relative to the file
//! being written, copying texture files beside an export, inline pixels as
//! VRML/Inventor `SFImage` text, and texture transforms across the two
//! families' different orders.

use super::text::Out;
use crate::scene::{Image, ImageSource, Scene, TexTransform, TexTransformOrder};
use glam::{Mat2, Vec2};
use std::borrow::Cow;
use std::path::{Component, Path, PathBuf};

/// The scene with every file texture's url made relative to the folder of
/// `out_file` (the file the writer's text will be saved as), pointing at the
/// file that was actually read. Borrowed unchanged when there is nothing to
/// rebase, so saving an untextured scene copies nothing.
pub fn rebase_urls<'a>(scene: &'a Scene, out_file: &Path) -> Cow<'a, Scene> {
    let has_files = scene
        .images
        .iter()
        .any(|i| matches!(i.source, ImageSource::File { .. }));
    if !has_files {
        return Cow::Borrowed(scene);
    }
    let out_dir = absolute(out_file.parent().unwrap_or(Path::new(".")));
    let mut s = scene.clone();
    for image in &mut s.images {
        if let ImageSource::File { url, path } = &mut image.source {
            *url = relative_url(&out_dir, &absolute(path));
        }
    }
    Cow::Owned(s)
}

/// `convert --copy-textures DIR`: copies every file texture into `dir`
/// (created if missing) and points the scene at the copies. Two different
/// files with one name get `_2`, `_3`… suffixes; one file used twice is
/// copied once. Returns (from, to) per copied file.
pub fn copy_textures(scene: &mut Scene, dir: &Path) -> Result<Vec<(PathBuf, PathBuf)>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut copied: Vec<(PathBuf, PathBuf)> = Vec::new();
    for image in &mut scene.images {
        let ImageSource::File { url, path } = &mut image.source else {
            continue;
        };
        let from = absolute(path);
        let to = match copied.iter().find(|(f, _)| *f == from) {
            Some((_, to)) => to.clone(),
            None => {
                let to = free_name(dir, &from, &copied);
                std::fs::copy(&from, &to).map_err(|e| {
                    format!(
                        "cannot copy texture {} to {}: {e}",
                        from.display(),
                        to.display()
                    )
                })?;
                copied.push((from, to.clone()));
                to
            }
        };
        *url = to.to_string_lossy().replace('\\', "/");
        *path = to;
    }
    Ok(copied)
}

fn free_name(dir: &Path, from: &Path, taken: &[(PathBuf, PathBuf)]) -> PathBuf {
    let stem = from
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "texture".into());
    let ext = from
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    let mut n = 1;
    loop {
        let name = if n == 1 {
            format!("{stem}{ext}")
        } else {
            format!("{stem}_{n}{ext}")
        };
        let to = dir.join(name);
        if !taken.iter().any(|(_, t)| *t == to) {
            return to;
        }
        n += 1;
    }
}

fn absolute(p: &Path) -> PathBuf {
    std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf())
}

/// The url of `target` as seen from folder `from` (both absolute), with
/// forward slashes; `..` climbs where needed.
pub fn relative_url(from: &Path, target: &Path) -> String {
    fn norm(p: &Path) -> Vec<Component<'_>> {
        let mut v: Vec<Component> = Vec::new();
        for c in p.components() {
            match c {
                Component::CurDir => {}
                Component::ParentDir if matches!(v.last(), Some(Component::Normal(_))) => {
                    v.pop();
                }
                c => v.push(c),
            }
        }
        v
    }
    let (a, b) = (norm(from), norm(target));
    if a.first() != b.first() {
        // Different roots (another drive): only an absolute url works.
        return target.to_string_lossy().replace('\\', "/");
    }
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut parts: Vec<String> = vec!["..".into(); a.len() - common];
    parts.extend(
        b[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    parts.join("/")
}

/// An inline image as `SFImage` text (VRML97 §5.5, Inventor `SFImage`):
/// the header `width height components`, then one line per image row from
/// the BOTTOM row up (both formats start at the lower-left pixel), each
/// pixel one hex number of `components` bytes (grey, grey+alpha, RGB, RGBA).
pub fn sfimage(image: &Image) -> (String, Vec<String>) {
    let base = image.base();
    let (w, h, c) = (base.width(), base.height(), image.components());
    let head = format!("{w} {h} {c}");
    let rows = (0..h)
        .rev()
        .map(|y| {
            (0..w)
                .map(|x| {
                    let p = base.texel(x, y);
                    match c {
                        1 => format!("0x{:02X}", p[0]),
                        2 => format!("0x{:02X}{:02X}", p[0], p[3]),
                        3 => format!("0x{:02X}{:02X}{:02X}", p[0], p[1], p[2]),
                        _ => format!("0x{:02X}{:02X}{:02X}{:02X}", p[0], p[1], p[2], p[3]),
                    }
                })
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    (head, rows)
}

/// Writes the `image` field of a PixelTexture / Texture2: the [`sfimage`]
/// header, then one indented line per row.
pub fn image_field(out: &mut Out, image: &Image) {
    let (head, rows) = sfimage(image);
    out.line(&format!("image {head}"));
    out.depth += 1;
    for r in rows {
        out.line(&r);
    }
    out.depth -= 1;
}

/// `t` rewritten in `order` so that it maps texture coordinates exactly as
/// before, or `None` when that order cannot express it.
///
/// VRML97 (§6.49) maps `x ↦ S·R·(x + c + t) − c` (translation first, then
/// rotate and scale about the centre); Inventor's Texture2Transform maps
/// `x ↦ R·S·(x − c) + c + t` (scale first). The linear parts `S·R` and
/// `R·S` are equal when the scale is uniform or there is no rotation; the
/// rest is then matched with a zero centre: VRML97 → Inventor
/// `t' = S·R·(c + t) − c`, Inventor → VRML97 `t' = (R·S)⁻¹·(c + t) − c`.
pub fn transform_in(t: &TexTransform, order: TexTransformOrder) -> Option<TexTransform> {
    if t.order == order {
        return Some(*t);
    }
    let uniform = t.scale.x == t.scale.y;
    if !(uniform || t.rotation == 0.0) {
        return None;
    }
    let linear = Mat2::from_angle(t.rotation) * Mat2::from_diagonal(t.scale);
    let translation = match order {
        TexTransformOrder::Inventor => linear * (t.center + t.translation) - t.center,
        TexTransformOrder::Vrml97 => {
            if linear.determinant() == 0.0 {
                return None;
            }
            linear.inverse() * (t.center + t.translation) - t.center
        }
    };
    Some(TexTransform {
        translation,
        rotation: t.rotation,
        scale: t.scale,
        center: Vec2::ZERO,
        order,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn urls_climb_and_descend() {
        let u = relative_url(Path::new("/a/b/out"), Path::new("/a/b/tex/brick.png"));
        assert_eq!(u, "../tex/brick.png");
        assert_eq!(
            relative_url(Path::new("/a/b"), Path::new("/a/b/brick.png")),
            "brick.png"
        );
        assert_eq!(
            relative_url(Path::new("/x/./y/../z"), Path::new("/x/z/i.jpg")),
            "i.jpg"
        );
    }

    #[test]
    fn transforms_convert_between_orders_exactly() {
        let cases = [
            TexTransform {
                translation: Vec2::new(0.25, -0.5),
                rotation: 0.7,
                scale: Vec2::splat(2.0),
                center: Vec2::new(0.5, 0.5),
                order: TexTransformOrder::Vrml97,
            },
            TexTransform {
                translation: Vec2::new(0.1, 0.2),
                rotation: 0.0,
                scale: Vec2::new(3.0, 0.5),
                center: Vec2::new(0.3, 0.9),
                order: TexTransformOrder::Inventor,
            },
        ];
        for t in cases {
            for order in [TexTransformOrder::Vrml97, TexTransformOrder::Inventor] {
                let u = transform_in(&t, order).unwrap();
                assert_eq!(u.order, order);
                for p in [Vec2::ZERO, Vec2::ONE, Vec2::new(0.3, -2.0)] {
                    let (a, b) = (
                        t.matrix().transform_point2(p),
                        u.matrix().transform_point2(p),
                    );
                    assert!((a - b).length() < 1e-5, "{t:?} -> {u:?}: {a} vs {b}");
                }
            }
        }
        // Rotation with a non-uniform scale has no form in the other order.
        let skew = TexTransform {
            rotation: 0.5,
            scale: Vec2::new(2.0, 1.0),
            ..TexTransform::default()
        };
        assert!(transform_in(&skew, TexTransformOrder::Inventor).is_none());
        assert!(transform_in(&skew, TexTransformOrder::Vrml97).is_some());
    }

    #[test]
    fn sfimage_starts_at_the_bottom_row() {
        let px = vec![
            [1, 2, 3, 255],
            [4, 5, 6, 255],
            [7, 8, 9, 10],
            [11, 12, 13, 14],
        ];
        let img = Image::new("i", ImageSource::Inline, 2, 2, 4, px).unwrap();
        let (head, rows) = sfimage(&img);
        assert_eq!(head, "2 2 4");
        assert_eq!(rows, ["0x0708090A 0x0B0C0D0E", "0x010203FF 0x040506FF"]);
        let grey = Image::new("g", ImageSource::Inline, 1, 1, 1, vec![[9, 9, 9, 255]]).unwrap();
        assert_eq!(sfimage(&grey).1, ["0x09"]);
    }
}
