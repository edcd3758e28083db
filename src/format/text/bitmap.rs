//! Inventor `Text2` labels as bitmaps: the glyphs rasterised once on a
//! pixel grid, and the inked pixels turned into quads one pixel high.
//!
//! Text2 is bitmap text: The Inventor Mentor (ch. 7) draws it "as 2D
//! text" at a constant pixel size, SGI's SoText2 and Coin's draw each glyph
//! as a bitmap (`glBitmap`, or an RGBA image) whose pixels sit on the
//! screen's pixel grid, with each glyph's origin on a whole pixel. A label
//! `size` pixels high is a few pixels per stroke, so drawing its outlines
//! as triangles sampled once per pixel drops every stroke thinner than a
//! pixel (the bars of a 10-pixel 'Z' vanish) and moves the strokes about
//! with the anchor's sub-pixel position. Here each glyph origin is put on
//! a whole pixel, each pixel's coverage is measured at [`SUB`]² points,
//! and a pixel is inked when at least [`INKED`] of them fall in the glyph;
//! the renderer (`render/label.rs`) draws one local pixel as one picture
//! pixel, so the quads land on whole pixels as the bitmap's pixels do.

use super::font::Font;
use super::layout::layout;
use crate::scene::{Mesh, TextSpec};
use glam::{Vec2, Vec3};

/// Coverage samples per pixel side.
pub const SUB: usize = 4;
/// Samples (of `SUB`²) a pixel needs in the glyph to be inked: a quarter,
/// so that a stroke a third of a pixel wide still inks its pixels.
pub const INKED: u16 = 4;
/// The most pixels a label's bitmap may span, and the most outline
/// crossings its sample rows may hold; larger labels keep their outline
/// triangles (`None`).
const MAX_PIXELS: usize = 1 << 20;
const MAX_CROSSINGS: usize = 1 << 22;

/// The mesh of a Text2 label whose `spec.size` is in pixels, built in
/// local units `unit` of them a pixel: quads over the inked pixels of its
/// bitmap, facing +z. `None` when the label is too large for a bitmap or
/// the load's geometry budget (the caller keeps the outline mesh, which
/// says so) or `unit` is not a positive number.
pub fn label_mesh(spec: &TextSpec, unit: f32, textured: bool) -> Option<Mesh> {
    if !(unit.is_finite() && unit > 0.0) {
        return None;
    }
    let (contours, origin) = outlines(spec);
    let grid = Grid::around(&contours)?;
    let counts = grid.coverage(&contours)?;
    // One quad (4 vertices, 2 triangles) per run of inked pixels, within
    // the load's geometry budget (`format::limits`).
    let runs = counts
        .chunks(grid.w)
        .map(|row| {
            (0..row.len())
                .filter(|&i| row[i] >= INKED && (i == 0 || row[i - 1] < INKED))
                .count() as u64
        })
        .sum::<u64>();
    crate::format::limits::check_geometry(6 * runs).ok()?;
    let mut b = Quads::default();
    for j in 0..grid.h {
        let row = &counts[j * grid.w..(j + 1) * grid.w];
        let mut i = 0;
        while i < grid.w {
            if row[i] < INKED {
                i += 1;
                continue;
            }
            let start = i;
            while i < grid.w && row[i] >= INKED {
                i += 1;
            }
            let (x0, x1) = ((grid.x0 + start as i64) as f32, (grid.x0 + i as i64) as f32);
            let y = (grid.y0 + j as i64) as f32;
            b.quad(x0, x1, y, y + 1.0);
        }
    }
    let texcoords = if textured {
        let (o, s) = (Vec2::from(origin), spec.size.max(f32::MIN_POSITIVE));
        b.positions.iter().map(|p| (p.truncate() - o) / s).collect()
    } else {
        Vec::new()
    };
    Some(Mesh {
        positions: b.positions.iter().map(|p| *p * unit).collect(),
        normals: vec![Vec3::Z; b.positions.len()],
        texcoords,
        triangles: b.triangles,
        solid: false,
        ..Mesh::default()
    })
}

/// The box of a Text2 label's bitmap in pixels from its anchor, (lower
/// left, upper right): the whole pixels its glyphs' outlines reach, as
/// Coin's SoText2 box is the union of its glyph bitmaps. `None` when
/// [`label_mesh`] would keep the outlines.
pub fn pixel_box(spec: &TextSpec) -> Option<([f32; 2], [f32; 2])> {
    let g = Grid::around(&outlines(spec).0)?;
    let lo = [g.x0 as f32, g.y0 as f32];
    Some((lo, [lo[0] + g.w as f32, lo[1] + g.h as f32]))
}

/// Every glyph outline of `spec` in pixels, each glyph's origin on a
/// whole pixel, and the layout's origin (the texture origin).
fn outlines(spec: &TextSpec) -> (Vec<Vec<[f32; 2]>>, [f32; 2]) {
    let font = Font::new(spec.family, spec.bold, spec.italic);
    let lay = layout(spec, &font);
    let mut contours: Vec<Vec<[f32; 2]>> = Vec::new();
    for p in lay.glyphs.iter().take(super::MAX_GLYPHS) {
        let o = [p.origin[0].round(), p.origin[1].round()];
        for c in font.outline(p.glyph) {
            let pts: Vec<[f32; 2]> = c
                .iter()
                .map(|q| [o[0] + q[0] * p.scale[0], o[1] + q[1] * p.scale[1]])
                .collect();
            if pts.iter().all(|q| q[0].is_finite() && q[1].is_finite()) {
                contours.push(pts);
            }
        }
    }
    (contours, lay.origin)
}

/// The pixels a bitmap spans: columns `x0..x0 + w`, rows `y0..y0 + h`
/// (y up, pixel (x, y) covering [x, x + 1) × [y, y + 1)).
struct Grid {
    x0: i64,
    y0: i64,
    w: usize,
    h: usize,
}

impl Grid {
    /// The whole pixels around every contour point; `None` for no points
    /// or a bitmap over [`MAX_PIXELS`].
    fn around(contours: &[Vec<[f32; 2]>]) -> Option<Grid> {
        let pts = contours.iter().flatten();
        let (mut lo, mut hi) = ([f32::INFINITY; 2], [f32::NEG_INFINITY; 2]);
        for p in pts {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if lo[0] > hi[0] || lo[1] > hi[1] {
            return None;
        }
        let (x0, y0) = (lo[0].floor() as i64, lo[1].floor() as i64);
        let w = (hi[0].ceil() as i64 - x0).max(1) as usize;
        let h = (hi[1].ceil() as i64 - y0).max(1) as usize;
        (w.checked_mul(h)? <= MAX_PIXELS).then_some(Grid { x0, y0, w, h })
    }

    /// How many of each pixel's `SUB`² samples lie in the glyphs (nonzero
    /// winding over all contours, so overlapping glyphs are their union);
    /// row-major from the bottom row. `None` past [`MAX_CROSSINGS`].
    fn coverage(&self, contours: &[Vec<[f32; 2]>]) -> Option<Vec<u16>> {
        let rows = self.h * SUB;
        let sub = SUB as f32;
        // Sample row r lies at y = y0 + (r + 0.5) / SUB: every edge adds
        // its crossing of each sample row it spans, with its direction.
        let mut crossings: Vec<Vec<(f32, i32)>> = vec![Vec::new(); rows];
        let mut total = 0usize;
        for c in contours {
            for k in 0..c.len() {
                let (a, b) = (c[k], c[(k + 1) % c.len()]);
                if a[1] == b[1] {
                    continue;
                }
                let (dir, lo, hi) = if a[1] < b[1] { (1, a, b) } else { (-1, b, a) };
                // Rows whose sample y is in [lo.y, hi.y).
                let r0 = ((lo[1] - self.y0 as f32) * sub - 0.5).ceil().max(0.0) as usize;
                let r1 =
                    (((hi[1] - self.y0 as f32) * sub - 0.5).ceil().max(0.0) as usize).min(rows);
                for (r, row) in crossings.iter_mut().enumerate().take(r1).skip(r0) {
                    let y = self.y0 as f32 + (r as f32 + 0.5) / sub;
                    let t = (y - lo[1]) / (hi[1] - lo[1]);
                    row.push((lo[0] + t * (hi[0] - lo[0]), dir));
                }
                total += r1.saturating_sub(r0);
                if total > MAX_CROSSINGS {
                    return None;
                }
            }
        }
        let mut counts = vec![0u16; self.w * self.h];
        let cols = (self.w * SUB) as i64;
        for (r, row) in crossings.iter_mut().enumerate() {
            row.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.1.cmp(&q.1)));
            let line = &mut counts[(r / SUB) * self.w..(r / SUB + 1) * self.w];
            let mut wind = 0;
            for k in 0..row.len() {
                wind += row[k].1;
                if wind == 0 || k + 1 == row.len() {
                    continue;
                }
                // Samples at x = x0 + (s + 0.5) / SUB inside [xa, xb).
                let first =
                    |x: f32| (((x - self.x0 as f32) * sub - 0.5).ceil() as i64).clamp(0, cols);
                for s in first(row[k].0)..first(row[k + 1].0) {
                    line[s as usize / SUB] += 1;
                }
            }
        }
        Some(counts)
    }
}

/// Quads in pixel units, counter-clockwise seen from +z.
#[derive(Default)]
struct Quads {
    positions: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
}

impl Quads {
    fn quad(&mut self, x0: f32, x1: f32, y0: f32, y1: f32) {
        let n = self.positions.len() as u32;
        self.positions.extend([
            Vec3::new(x0, y0, 0.0),
            Vec3::new(x1, y0, 0.0),
            Vec3::new(x1, y1, 0.0),
            Vec3::new(x0, y1, 0.0),
        ]);
        self.triangles.push([n, n + 1, n + 2]);
        self.triangles.push([n, n + 2, n + 3]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{FontFamily, TextKind};

    fn label(s: &str, size: f32, family: FontFamily) -> TextSpec {
        TextSpec {
            kind: TextKind::Text2,
            strings: vec![s.into()],
            family,
            size,
            ..TextSpec::default()
        }
    }

    /// The inked pixels of a label mesh built one unit a pixel, as a set
    /// of (x, y) of their lower-left corners.
    fn pixels(m: &Mesh) -> std::collections::BTreeSet<(i64, i64)> {
        let mut out = std::collections::BTreeSet::new();
        for q in m.positions.chunks(4) {
            let (x0, x1, y) = (q[0].x as i64, q[1].x as i64, q[0].y as i64);
            assert_eq!(
                (q[2].y - q[0].y, q[0].x.fract(), q[1].x.fract()),
                (1.0, 0.0, 0.0)
            );
            out.extend((x0..x1).map(|x| (x, y)));
        }
        out
    }

    /// A 10-pixel serif 'Z' keeps its bars: its top and bottom rows are
    /// inked across most of its width (point sampling drops them).
    #[test]
    fn thin_strokes_keep_their_pixels() {
        let m = label_mesh(&label("Z", 10.0, FontFamily::Serif), 1.0, false).unwrap();
        let px = pixels(&m);
        let top = px.iter().map(|p| p.1).max().unwrap();
        let bottom = px.iter().map(|p| p.1).min().unwrap();
        let width = |y| px.iter().filter(|p| p.1 == y).count();
        assert!(width(top) >= 4 && width(bottom) >= 4, "{px:?}");
        // Cap height 0.66 em: 7 rows, from the baseline up.
        assert_eq!((bottom, top), (0, 6), "{px:?}");
    }

    /// Quads lie on whole pixels, face +z, are wound counter-clockwise,
    /// and scale with `unit`; the same label gives the same mesh.
    #[test]
    fn quads_sit_on_whole_pixels_and_scale_with_the_unit() {
        let spec = label("Hello, wörld", 20.0, FontFamily::Sans);
        let m = label_mesh(&spec, 1.0, true).unwrap();
        assert!(!pixels(&m).is_empty());
        assert_eq!(m.texcoords.len(), m.positions.len());
        assert!(m.normals.iter().all(|n| *n == Vec3::Z));
        for t in &m.triangles {
            let p = |i: u32| m.positions[i as usize];
            assert!((p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).z > 0.0);
        }
        let half = label_mesh(&spec, 0.5, true).unwrap();
        assert!(m
            .positions
            .iter()
            .zip(&half.positions)
            .all(|(a, b)| *a * 0.5 == *b));
        assert_eq!(label_mesh(&spec, 1.0, true).unwrap(), m);
        assert!(label_mesh(&spec, 0.0, true).is_none());
        assert!(label_mesh(&spec, f32::NAN, true).is_none());
    }

    /// The inked area follows the glyphs' area: within a pixel per
    /// outline pixel of the exact area, for a large label.
    #[test]
    fn ink_follows_the_outline_area() {
        let spec = label("O", 100.0, FontFamily::Sans);
        let px = pixels(&label_mesh(&spec, 1.0, false).unwrap()).len() as f32;
        let exact = super::super::text_mesh(&spec, false).unwrap();
        let area: f32 = exact
            .triangles
            .iter()
            .map(|t| {
                let p = |i: u32| exact.positions[i as usize];
                (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).length() / 2.0
            })
            .sum();
        // The ring's outline is about 2π(36 + 28) ≈ 400 pixels long.
        assert!((px - area).abs() < 400.0, "{px} {area}");
        assert!(px > area, "a quarter-covered pixel is inked: {px} {area}");
    }

    /// Labels too large for a bitmap say so (the caller keeps outlines).
    #[test]
    fn huge_labels_fall_back() {
        assert!(label_mesh(&label("W", 5000.0, FontFamily::Serif), 1.0, false).is_none());
    }
}
