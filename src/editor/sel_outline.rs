//! The selection outline: which pixels of the viewport layer are inside
//! the selection, touch it (the outline) or lie two pixels away (the dark
//! edge behind the outline), and those pixels of the layer with the
//! outline drawn in, kept until the layer or the selection changes.
//!
//! Classifying every viewport pixel by its 5×5 neighbourhood cost more
//! than half of an editor frame at 1280×720, and even a byte-per-pixel
//! separable dilation over the selection's box was a fifth of it. So the
//! selection is kept as bit rows over its bounding box grown by two
//! pixels, dilated 64 pixels at a time by shifts (rows) and ORs
//! (columns). The rings are the same as the neighbourhood test's, pixel
//! for pixel, and they are drawn once per layer and selection, not once
//! per window redraw.

use crate::render::Frame;
use crate::scene::NodeId;
use crate::ui::theme;
use rayon::prelude::*;

/// Where a pixel lies relative to the selection's silhouette.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ring {
    /// On the selection (tinted).
    Inside,
    /// Outside, touching it (the outline colour).
    Near,
    /// Outside, two pixels away (a dark edge behind the outline).
    Far,
}

/// The set cells of a grid as bit rows over their bounding box grown by
/// two cells (clamped to the grid): bit `i` of word `k` of row `r` is
/// cell (`x0 + 64k + i`, `y0 + r`).
pub struct Silhouette {
    /// The set cells' bounding box (x0, y0, x1, y1), inclusive.
    bounds: (usize, usize, usize, usize),
    x0: usize,
    y0: usize,
    /// Columns and rows of the grown box.
    w: usize,
    h: usize,
    /// Words per bit row.
    words: usize,
    bits: Vec<u64>,
}

impl Silhouette {
    /// The cells of the first `w` columns and `h` rows of a row-major
    /// grid (rows `stride` cells apart) for which `set` holds; `None`
    /// when none does.
    pub fn find<T: Sync>(
        cells: &[T],
        stride: usize,
        w: usize,
        h: usize,
        set: impl Fn(&T) -> bool + Sync,
    ) -> Option<Silhouette> {
        let bounds = set_bounds(cells, stride, w, h, &set)?;
        let (bx0, by0, bx1, by1) = bounds;
        let (x0, x1) = (bx0.saturating_sub(2), (bx1 + 2).min(w - 1));
        let (y0, y1) = (by0.saturating_sub(2), (by1 + 2).min(h - 1));
        let (gw, gh) = (x1 - x0 + 1, y1 - y0 + 1);
        let words = gw.div_ceil(64);
        let mut bits = vec![0u64; words * gh];
        let packed = bits
            .par_chunks_mut(words)
            .skip(by0 - y0)
            .take(by1 - by0 + 1);
        packed.enumerate().for_each(|(r, out)| {
            let y = by0 + r;
            let row = &cells[y * stride + bx0..=y * stride + bx1];
            for (i, c) in row.iter().enumerate() {
                let x = bx0 - x0 + i;
                out[x / 64] |= (set(c) as u64) << (x % 64);
            }
        });
        Some(Silhouette {
            bounds,
            x0,
            y0,
            w: gw,
            h: gh,
            words,
            bits,
        })
    }

    /// The set cells' bounding box (x0, y0, x1, y1), inclusive.
    pub fn bounds(&self) -> (usize, usize, usize, usize) {
        self.bounds
    }

    /// Calls `put(x, y, ring)` for every cell that is set, touches a set
    /// cell (8-neighbourhood) or lies at Chebyshev distance 2 from one;
    /// cells beyond the grid count as unset.
    #[cfg(test)]
    pub fn for_each_ring(&self, mut put: impl FnMut(usize, usize, Ring)) {
        let rows = self.dilate();
        for r in 0..self.h {
            self.row_runs(&rows, r, |x, n, ring| {
                (x..x + n).for_each(|x| put(x, self.y0 + r, ring));
            });
        }
    }

    /// The bits dilated along rows by 1 and 2 cells (shifts with the
    /// carry from the neighbouring word); bits past the box's last
    /// column are dropped by [`Silhouette::row_runs`].
    fn dilate(&self) -> Dilated {
        let words = self.words;
        let mut d1 = vec![0u64; self.bits.len()];
        let mut d2 = vec![0u64; self.bits.len()];
        for r in 0..self.h {
            let row = &self.bits[r * words..(r + 1) * words];
            for k in 0..words {
                let m = row[k];
                let lo = if k > 0 { row[k - 1] } else { 0 };
                let hi = if k + 1 < words { row[k + 1] } else { 0 };
                let one = m | m << 1 | lo >> 63 | m >> 1 | hi << 63;
                d1[r * words + k] = one;
                d2[r * words + k] = one | m << 2 | lo >> 62 | m >> 2 | hi << 62;
            }
        }
        Dilated { d1, d2 }
    }

    /// Calls `put(x, n, ring)` for each run of `n` cells of one ring in
    /// row `r` of the box (a run ends at a word's end too), left to
    /// right; rows are independent, so threads can share them.
    fn row_runs(&self, d: &Dilated, r: usize, mut put: impl FnMut(usize, usize, Ring)) {
        let (words, h) = (self.words, self.h);
        let last = match self.w % 64 {
            0 => u64::MAX,
            n => (1u64 << n) - 1,
        };
        let or_rows = |d: &[u64], reach: usize, k: usize| {
            (r.saturating_sub(reach)..=(r + reach).min(h - 1)).fold(0, |a, y| a | d[y * words + k])
        };
        for k in 0..words {
            let m = self.bits[r * words + k];
            // m ⊆ near ⊆ wide: set, touching, within two.
            let near = or_rows(&d.d1, 1, k);
            let mut wide = or_rows(&d.d2, 2, k);
            if k + 1 == words {
                wide &= last;
            }
            while wide != 0 {
                let i = wide.trailing_zeros();
                let bit = 1u64 << i;
                let (ring, same) = if m & bit != 0 {
                    (Ring::Inside, m)
                } else if near & bit != 0 {
                    (Ring::Near, near & !m & wide)
                } else {
                    // Nothing within one cell, so the set cell within
                    // two lies exactly two away.
                    (Ring::Far, wide & !near)
                };
                let n = (same >> i).trailing_ones();
                // Clear bits i..i + n (n may reach the word's end).
                wide &= !((u64::MAX >> (64 - n)) << i);
                put(self.x0 + 64 * k + i as usize, n as usize, ring);
            }
        }
    }
}

/// A silhouette's rows dilated by one and two cells (see
/// [`Silhouette::dilate`]).
struct Dilated {
    d1: Vec<u64>,
    d2: Vec<u64>,
}

/// The viewport layer's selection outline: a ring of the selection colour
/// with a dark ring beyond it (so it shows on light and dark backgrounds)
/// and an inside tinted only lightly, so the object's own colour stays
/// readable (issue 17 item 7); plus the selection's pixel box, which
/// sizes the handles. Only the rows of the selection's box grown by two
/// pixels are kept, drawn over the layer's rows as they are copied to the
/// window: a copy of the whole layer cost a frame-sized copy per layer
/// render and another per blit, even for a light, which has no pixels.
pub struct Outlined {
    pub node: NodeId,
    /// The selection's visible pixels' box (x0, y0, x1, y1), inclusive.
    pub bounds: Option<(usize, usize, usize, usize)>,
    /// The grown box's pixels with the outline drawn in.
    patch: Option<Patch>,
}

/// `w`×`h` pixels of the layer, row by row, from (`x0`, `y0`).
struct Patch {
    x0: usize,
    y0: usize,
    w: usize,
    h: usize,
    color: Vec<u32>,
}

impl Outlined {
    /// Outlines the pixels of `layer` whose id `mine` accepts.
    pub fn new(node: NodeId, layer: &Frame, mine: impl Fn(u32) -> bool + Sync) -> Outlined {
        let (w, h) = (layer.width as usize, layer.height as usize);
        let found = Silhouette::find(&layer.ids, w, w, h, |&id| mine(id));
        let patch = found.as_ref().map(|s| {
            let (x0, y0, pw, ph) = (s.x0, s.y0, s.w, s.h);
            let mut color = Vec::with_capacity(pw * ph);
            for y in y0..y0 + ph {
                color.extend_from_slice(&layer.color[y * w + x0..y * w + x0 + pw]);
            }
            let rows = s.dilate();
            color.par_chunks_mut(pw).enumerate().for_each(|(r, row)| {
                s.row_runs(&rows, r, |x, n, ring| {
                    let run = &mut row[x - x0..x - x0 + n];
                    match ring {
                        Ring::Inside => run
                            .iter_mut()
                            .for_each(|c| *c = theme::blend(*c, theme::SELECTED, 1, 8)),
                        Ring::Near => run.fill(theme::SELECTED),
                        Ring::Far => run
                            .iter_mut()
                            .for_each(|c| *c = theme::blend(*c, 0x000000, 1, 2)),
                    }
                });
            });
            Patch {
                x0,
                y0,
                w: pw,
                h: ph,
                color,
            }
        });
        Outlined {
            node,
            bounds: found.map(|s| s.bounds()),
            patch,
        }
    }

    /// Draws the outline over `row`, a copy of the start of the layer's
    /// row `y` (as much of it as the window shows).
    pub fn draw_over(&self, y: usize, row: &mut [u32]) {
        let Some(p) = &self.patch else { return };
        if y < p.y0 || y >= p.y0 + p.h || p.x0 >= row.len() {
            return;
        }
        let n = p.w.min(row.len() - p.x0);
        let src = &p.color[(y - p.y0) * p.w..][..n];
        row[p.x0..p.x0 + n].copy_from_slice(src);
    }
}

/// The bounding box (x0, y0, x1, y1), inclusive, of the cells of the
/// first `w` columns and `h` rows of a row-major grid (rows `stride`
/// cells apart) for which `set` holds; found row by row, from each end
/// of the row, with no division per cell.
fn set_bounds<T: Sync>(
    cells: &[T],
    stride: usize,
    w: usize,
    h: usize,
    set: impl Fn(&T) -> bool + Sync,
) -> Option<(usize, usize, usize, usize)> {
    // Each row's first and last set cell, rows shared by the threads.
    let spans: Vec<Option<(usize, usize)>> = cells
        .par_chunks(stride.max(1))
        .take(h)
        .map(|row| {
            let row = &row[..w.min(row.len())];
            let first = row.iter().position(&set)?;
            Some((first, row.iter().rposition(&set).unwrap_or(first)))
        })
        .collect();
    let mut b: Option<(usize, usize, usize, usize)> = None;
    for (y, span) in spans.into_iter().enumerate() {
        let Some((first, last)) = span else { continue };
        b = Some(match b {
            None => (first, y, last, y),
            Some((x0, y0, x1, _)) => (x0.min(first), y0, x1.max(last), y),
        });
    }
    b
}

#[cfg(test)]
mod tests {
    use super::{set_bounds, Outlined, Ring, Silhouette};
    use crate::render::Frame;
    use crate::scene::NodeId;
    use crate::ui::theme;

    /// The neighbourhood test the rings replace, one pixel at a time.
    fn by_neighbourhood(mask: &[bool], w: usize, h: usize, x: usize, y: usize) -> Option<Ring> {
        if mask[y * w + x] {
            return Some(Ring::Inside);
        }
        let at = |dx: i32, dy: i32| {
            let (nx, ny) = (x as i32 + dx, y as i32 + dy);
            nx >= 0
                && ny >= 0
                && (nx as usize) < w
                && (ny as usize) < h
                && mask[ny as usize * w + nx as usize]
        };
        let within = |r: i32| (-r..=r).any(|dy| (-r..=r).any(|dx| at(dx, dy)));
        if within(1) {
            Some(Ring::Near)
        } else if within(2) {
            Some(Ring::Far)
        } else {
            None
        }
    }

    fn rings(mask: &[bool], w: usize, h: usize) -> Vec<Option<Ring>> {
        let mut out = vec![None; w * h];
        if let Some(s) = Silhouette::find(mask, w, w, h, |&m| m) {
            s.for_each_ring(|x, y, r| {
                assert!(out[y * w + x].replace(r).is_none(), "({x}, {y}) twice");
            });
        }
        out
    }

    #[test]
    fn the_outline_lies_outside_the_silhouette() {
        // A 2×2 selected square in an 8×8 mask at (3, 3).
        let (w, h) = (8, 8);
        let mut mask = vec![false; w * h];
        for (x, y) in [(3, 3), (4, 3), (3, 4), (4, 4)] {
            mask[y * w + x] = true;
        }
        let r = rings(&mask, w, h);
        let at = |x: usize, y: usize| r[y * w + x];
        assert_eq!(at(3, 3), Some(Ring::Inside));
        assert_eq!(at(2, 3), Some(Ring::Near));
        assert_eq!(at(5, 5), Some(Ring::Near));
        assert_eq!(at(1, 4), Some(Ring::Far));
        assert_eq!(at(6, 6), Some(Ring::Far));
        assert_eq!(at(0, 0), None);
        assert_eq!(at(7, 3), None);
    }

    #[test]
    fn rings_match_the_neighbourhood_test_on_any_mask() {
        // Masks of several densities and shapes, touching the borders too
        // (a fixed linear congruential sequence: the same masks every run).
        let mut seed = 0x2545_f491_u32;
        let mut next = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed >> 8
        };
        for (w, h) in [(1, 1), (1, 7), (9, 1), (13, 11), (32, 5), (66, 4), (130, 5)] {
            for density in [0, 2, 20, 128, 250] {
                let mask: Vec<bool> = (0..w * h).map(|_| next() % 256 < density).collect();
                let got = rings(&mask, w, h);
                for y in 0..h {
                    for x in 0..w {
                        let want = by_neighbourhood(&mask, w, h, x, y);
                        assert_eq!(got[y * w + x], want, "{w}x{h} d{density} ({x}, {y})");
                    }
                }
            }
        }
    }

    #[test]
    fn an_empty_mask_has_no_rings() {
        assert!(rings(&[false; 12], 4, 3).iter().all(Option::is_none));
        assert!(rings(&[], 0, 0).is_empty());
    }

    #[test]
    fn bounds_keep_to_the_first_w_columns_and_h_rows() {
        // 4 columns of a 6-cell stride, 3 of 4 rows; 9 marks a set cell.
        #[rustfmt::skip]
        let cells = [
            0, 0, 0, 0, 9, 9,
            0, 0, 9, 0, 0, 9,
            0, 9, 0, 0, 0, 0,
            9, 9, 9, 9, 9, 9,
        ];
        let set = |&c: &u32| c == 9;
        assert_eq!(set_bounds(&cells, 6, 4, 3, set), Some((1, 1, 2, 2)));
        assert_eq!(set_bounds(&cells, 6, 4, 4, set), Some((0, 1, 3, 3)));
        assert_eq!(set_bounds(&cells, 6, 2, 1, set), None);
        assert_eq!(set_bounds(&cells[..0], 6, 4, 3, set), None);
    }

    /// A layer of seeded random colours whose ids are 0..4 (3 and 4 the
    /// selection's), in patches so the silhouette has edges.
    fn layer(w: u32, h: u32, seed: u32) -> Frame {
        let mut f = Frame::new(w, h, glam::Vec3::ZERO);
        let mut s = seed;
        let mut next = || {
            s = s.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            s >> 8
        };
        for c in f.color.iter_mut() {
            *c = next() & 0xff_ffff;
        }
        let (cx, cy) = (next() % w, next() % h);
        for y in 0..h {
            for x in 0..w {
                let near = x.abs_diff(cx) < w / 3 && y.abs_diff(cy) < h / 3;
                f.ids[(y * w + x) as usize] = if near { next() % 5 } else { 0 };
            }
        }
        // At least one pixel of the selection.
        f.ids[(cy * w + cx) as usize] = 4;
        f
    }

    /// The outline drawn over a whole copy of the layer, as before only
    /// the box was kept.
    fn whole(layer: &Frame, mine: impl Fn(u32) -> bool + Sync) -> Vec<u32> {
        let w = layer.width as usize;
        let mut color = layer.color.clone();
        if let Some(s) = Silhouette::find(&layer.ids, w, w, layer.height as usize, |&i| mine(i)) {
            s.for_each_ring(|x, y, ring| {
                let c = &mut color[y * w + x];
                *c = match ring {
                    Ring::Inside => theme::blend(*c, theme::SELECTED, 1, 8),
                    Ring::Near => theme::SELECTED,
                    Ring::Far => theme::blend(*c, 0x000000, 1, 2),
                };
            });
        }
        color
    }

    #[test]
    fn the_box_drawn_over_the_rows_is_the_whole_outlined_layer() {
        let mine = |id: u32| id >= 3;
        for (w, h, seed) in [(70u32, 9u32, 1u32), (130, 40, 2), (5, 5, 3), (64, 64, 4)] {
            let layer = layer(w, h, seed);
            let want = whole(&layer, mine);
            assert_ne!(want, layer.color, "{w}x{h}: something is outlined");
            let o = Outlined::new(NodeId(0), &layer, mine);
            // Rows as wide as the layer, and rows cut short by the window.
            for shown in [w as usize, w as usize * 2 / 3] {
                for y in 0..h as usize {
                    let mut row = layer.color[y * w as usize..][..shown].to_vec();
                    o.draw_over(y, &mut row);
                    assert_eq!(row, want[y * w as usize..][..shown], "{w}x{h} row {y}");
                }
            }
        }
    }

    #[test]
    fn a_selection_with_no_pixels_keeps_the_rows() {
        let layer = layer(40, 10, 5);
        let o = Outlined::new(NodeId(0), &layer, |id| id == 99);
        assert_eq!(o.bounds, None);
        for y in 0..10 {
            let mut row = layer.color[y * 40..][..40].to_vec();
            o.draw_over(y, &mut row);
            assert_eq!(row, layer.color[y * 40..][..40]);
        }
    }
}
