//! A laid-out text → a mesh: each glyph's triangulated outline, moved and
//! scaled into place, facing +z (normal (0, 0, 1)); Inventor's `Text3`
//! adds the back face at z = −depth and the sides between the two.
//!
//! Texture coordinates follow VRML97 §6.47: origin at the first string's
//! origin, one unit = `size` in both directions, s right, t up.

use super::font::Font;
use super::layout::{layout, Layout};
use super::tessellate::{tessellate, Tessellation};
use crate::format::limits::{self, LimitError};
use crate::scene::{Mesh, TextKind, TextSpec};
use glam::{Vec2, Vec3};
use std::collections::BTreeMap;

/// The most glyphs one text shape may hold (a label, a page of text; not
/// a book). Longer texts are cut with a message.
pub const MAX_GLYPHS: usize = 20_000;

/// A glyph's outline and its triangles, in em units.
struct GlyphShape {
    contours: Vec<Vec<[f32; 2]>>,
    fill: Tessellation,
}

/// Builds the mesh of a text. `textured` adds texture coordinates. Fails,
/// before allocating it, when the mesh would not fit the load's geometry
/// budget (`format::limits`).
pub fn text_mesh(spec: &TextSpec, textured: bool) -> Result<Mesh, LimitError> {
    let font = Font::new(spec.family, spec.bold, spec.italic);
    let mut lay = layout(spec, &font);
    lay.glyphs.truncate(MAX_GLYPHS);
    let mut cache: BTreeMap<u16, GlyphShape> = BTreeMap::new();
    for p in &lay.glyphs {
        cache.entry(p.glyph.0).or_insert_with(|| {
            let contours = font.outline(p.glyph);
            let fill = tessellate(&contours);
            GlyphShape { contours, fill }
        });
    }
    let (front, sides, back, depth) = match spec.kind {
        TextKind::Text3 {
            front,
            sides,
            back,
            depth,
        } => (front, sides, back, depth.max(0.0)),
        _ => (true, false, false, 0.0),
    };
    let cost: u64 = lay
        .glyphs
        .iter()
        .filter_map(|p| cache.get(&p.glyph.0))
        .map(|g| {
            let face = (g.fill.points.len() + g.fill.triangles.len()) as u64;
            let ring: u64 = g.contours.iter().map(|c| c.len() as u64).sum();
            u64::from(front) * face + u64::from(back) * face + u64::from(sides) * 6 * ring
        })
        .sum();
    limits::check_geometry(cost)?;
    let mut b = Builder::default();
    if front {
        faces(&mut b, &lay, &cache, 0.0, false);
    }
    if back {
        faces(&mut b, &lay, &cache, -depth, true);
    }
    if sides && depth > 0.0 {
        side_walls(&mut b, &lay, &cache, depth);
    }
    let texcoords = if textured {
        let (o, s) = (Vec2::from(lay.origin), spec.size.max(f32::MIN_POSITIVE));
        b.positions.iter().map(|p| (p.truncate() - o) / s).collect()
    } else {
        Vec::new()
    };
    Ok(Mesh {
        positions: b.positions,
        normals: b.normals,
        texcoords,
        triangles: b.triangles,
        solid: false,
        ..Mesh::default()
    })
}

#[derive(Default)]
struct Builder {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
}

impl Builder {
    fn vertex(&mut self, p: Vec3, n: Vec3) -> u32 {
        self.positions.push(p);
        self.normals.push(n);
        self.positions.len() as u32 - 1
    }
}

fn place(p: [f32; 2], origin: [f32; 2], scale: [f32; 2]) -> Vec2 {
    Vec2::new(origin[0] + p[0] * scale[0], origin[1] + p[1] * scale[1])
}

/// Every glyph's filled outline at height `z`, facing +z (or −z, wound the
/// other way, when `flip`).
fn faces(b: &mut Builder, lay: &Layout, cache: &BTreeMap<u16, GlyphShape>, z: f32, flip: bool) {
    let n = if flip { Vec3::NEG_Z } else { Vec3::Z };
    for g in &lay.glyphs {
        let Some(shape) = cache.get(&g.glyph.0) else {
            continue;
        };
        let base = b.positions.len() as u32;
        for &p in &shape.fill.points {
            b.vertex(place(p, g.origin, g.scale).extend(z), n);
        }
        for &[i, j, k] in &shape.fill.triangles {
            b.triangles.push(if flip {
                [base + i, base + k, base + j]
            } else {
                [base + i, base + j, base + k]
            });
        }
    }
}

/// The walls between the front (z = 0) and the back (z = −depth): one flat
/// quad per outline segment, its normal pointing away from the glyph.
fn side_walls(b: &mut Builder, lay: &Layout, cache: &BTreeMap<u16, GlyphShape>, depth: f32) {
    for g in &lay.glyphs {
        let Some(shape) = cache.get(&g.glyph.0) else {
            continue;
        };
        // Which side of its contours the glyph fills: the largest contour
        // is an outer one; with it counter-clockwise the ink is on the left
        // of every segment (holes run the other way).
        let signed: Vec<f32> = shape.contours.iter().map(|c| signed_area(c)).collect();
        let outer = signed
            .iter()
            .copied()
            .reduce(|a, x| if x.abs() > a.abs() { x } else { a })
            .unwrap_or(1.0);
        let ink_left = outer > 0.0;
        // A mirrored placement (negative scale) flips the sides.
        let mirrored = (g.scale[0] < 0.0) != (g.scale[1] < 0.0);
        for c in &shape.contours {
            let m = c.len();
            for i in 0..m {
                let a = place(c[i], g.origin, g.scale);
                let bb = place(c[(i + 1) % m], g.origin, g.scale);
                let d = bb - a;
                let out = if ink_left != mirrored {
                    Vec2::new(d.y, -d.x)
                } else {
                    Vec2::new(-d.y, d.x)
                };
                let Some(nrm) = out.try_normalize() else {
                    continue;
                };
                let n = nrm.extend(0.0);
                let v0 = b.vertex(a.extend(0.0), n);
                let v1 = b.vertex(bb.extend(0.0), n);
                let v2 = b.vertex(bb.extend(-depth), n);
                let v3 = b.vertex(a.extend(-depth), n);
                // Counter-clockwise seen from outside (along `n`).
                let (t0, t1) = ([v0, v3, v2], [v0, v2, v1]);
                let check = (b.positions[t0[1] as usize] - b.positions[t0[0] as usize])
                    .cross(b.positions[t0[2] as usize] - b.positions[t0[0] as usize]);
                if check.dot(n) >= 0.0 {
                    b.triangles.push(t0);
                    b.triangles.push(t1);
                } else {
                    b.triangles.push([v0, v2, v3]);
                    b.triangles.push([v0, v1, v2]);
                }
            }
        }
    }
}

fn signed_area(c: &[[f32; 2]]) -> f32 {
    let m = c.len();
    (0..m)
        .map(|i| {
            let (a, b) = (c[i], c[(i + 1) % m]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f32>()
        / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{FontFamily, Justify};

    fn area(m: &Mesh) -> f32 {
        m.triangles
            .iter()
            .map(|t| {
                let p = |i: u32| m.positions[i as usize];
                (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).length() / 2.0
            })
            .sum()
    }

    fn spec(s: &str) -> TextSpec {
        TextSpec {
            strings: vec![s.into()],
            family: FontFamily::Sans,
            ..TextSpec::default()
        }
    }

    #[test]
    fn text_is_flat_facing_z_and_scales_with_size() {
        let m = text_mesh(&spec("Hello"), false).unwrap();
        assert!(!m.triangles.is_empty());
        assert!(m.positions.iter().all(|p| p.z == 0.0));
        assert!(m.normals.iter().all(|n| *n == Vec3::Z));
        // Front faces counter-clockwise seen from +z.
        for t in &m.triangles {
            let p = |i: u32| m.positions[i as usize];
            assert!((p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).z >= 0.0);
        }
        let mut big = spec("Hello");
        big.size = 3.0;
        let a1 = area(&m);
        let a3 = area(&text_mesh(&big, false).unwrap());
        assert!((a3 / a1 - 9.0).abs() < 1e-3, "{a1} {a3}");
        assert!(m.texcoords.is_empty());
    }

    #[test]
    fn texture_coordinates_start_at_the_first_string_origin() {
        let mut s = spec("HI");
        s.size = 2.0;
        s.justify = [Justify::Middle, Justify::First];
        let m = text_mesh(&s, true).unwrap();
        assert_eq!(m.texcoords.len(), m.positions.len());
        let (lo, _) = m.bounds().unwrap();
        let tmin = m.texcoords.iter().fold(Vec2::MAX, |a, t| a.min(*t));
        // 'H' starts a little right of its pen position (left bearing).
        assert!(tmin.x >= 0.0 && tmin.x < 0.2, "{tmin}");
        assert!(tmin.y.abs() < 1e-6);
        assert!(lo.x < 0.0);
    }

    #[test]
    fn text3_parts_build_front_back_and_sides() {
        let mut s = spec("O");
        let front_only = text_mesh(&s, false).unwrap();
        s.kind = TextKind::Text3 {
            front: true,
            sides: true,
            back: true,
            depth: 0.5,
        };
        let m = text_mesh(&s, false).unwrap();
        let (lo, hi) = m.bounds().unwrap();
        assert_eq!((lo.z, hi.z), (-0.5, 0.0));
        // Front and back have the same area; the sides add the outline
        // length × depth.
        let faces = 2.0 * area(&front_only);
        assert!(area(&m) > faces + 0.5);
        // Side normals point away from the ink: on the outer ring of 'O'
        // at its far left, the normal points to -x.
        let left = m
            .positions
            .iter()
            .zip(&m.normals)
            .filter(|(_, n)| n.z == 0.0)
            .min_by(|a, b| a.0.x.total_cmp(&b.0.x))
            .unwrap();
        assert!(left.1.x < -0.9, "{:?}", left.1);
        // Back faces face -z.
        assert!(m.normals.contains(&Vec3::NEG_Z));
    }

    #[test]
    fn same_text_same_mesh() {
        let s = spec("Determinism & 8O@");
        assert_eq!(text_mesh(&s, true).unwrap(), text_mesh(&s, true).unwrap());
    }

    #[test]
    fn long_texts_are_capped() {
        let s = spec(&"i".repeat(MAX_GLYPHS + 10));
        let m = text_mesh(&s, false).unwrap();
        let one = text_mesh(&spec("i"), false).unwrap();
        assert_eq!(m.triangles.len(), one.triangles.len() * MAX_GLYPHS);
    }
}
