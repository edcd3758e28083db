//! The selection outline's rings: which pixels of a selection mask are
//! inside it, touch it (the outline), or lie two pixels away (the dark
//! edge behind the outline). Classifying every viewport pixel by looking
//! at its 5×5 neighbourhood cost more than half of an editor frame at
//! 1280×720, so this works only inside the mask's bounding box grown by
//! two pixels and finds the neighbourhoods by separable dilation on bit
//! rows (64 pixels a word): a row pass (3 and 5 wide, shifts carried
//! across words) then a column pass (rows ORed). The rings are the same
//! as the neighbourhood test's, pixel for pixel.

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

/// Calls `put(x, y, ring)` for every pixel of the `w`×`h` row-major `mask`
/// that is inside, touches (8-neighbourhood) or lies at Chebyshev distance
/// 2 from a set pixel; pixels beyond the image count as unset.
pub fn for_each_ring(mask: &[bool], w: usize, h: usize, mut put: impl FnMut(usize, usize, Ring)) {
    let Some((bx0, by0, bx1, by1)) = set_bounds(mask, w, w, h, |&m| m) else {
        return;
    };
    let (x0, x1) = (bx0.saturating_sub(2), (bx1 + 2).min(w - 1));
    let (y0, y1) = (by0.saturating_sub(2), (by1 + 2).min(h - 1));
    let rw = x1 - x0 + 1;
    let rows = y1 - y0 + 1;
    // 64 columns of the grown box per word, bit b of word i column
    // 64·i + b; the last word's bits past the box are never reported.
    let nw = rw.div_ceil(64);
    let last = if rw % 64 == 0 {
        !0
    } else {
        (1u64 << (rw % 64)) - 1
    };
    // Row pass: the set pixels, and whether one lies within 1 (near) or 2
    // (wide) columns — the row shifted by 1 and 2 each way, carrying
    // across words (columns outside the grown box hold no set pixel).
    let mut set = vec![0u64; nw * rows];
    let mut near = vec![0u64; nw * rows];
    let mut wide = vec![0u64; nw * rows];
    for ry in 0..rows {
        let src = &mask[(y0 + ry) * w + x0..(y0 + ry) * w + x1 + 1];
        let at = ry * nw..(ry + 1) * nw;
        let bits = &mut set[at.clone()];
        for (word, chunk) in bits.iter_mut().zip(src.chunks(64)) {
            *word = chunk
                .iter()
                .enumerate()
                .fold(0, |a, (b, &m)| a | (m as u64) << b);
        }
        for i in 0..nw {
            let m = bits[i];
            let lo = if i > 0 { bits[i - 1] } else { 0 };
            let hi = bits.get(i + 1).copied().unwrap_or(0);
            let n = m | (m << 1 | lo >> 63) | (m >> 1 | hi << 63);
            near[ry * nw + i] = n;
            wide[ry * nw + i] = n | (m << 2 | lo >> 62) | (m >> 2 | hi << 62);
        }
    }
    // Column pass: the row results of the rows within 1 (2) above and
    // below, ORed; rows outside the grown box hold no set pixel.
    let or_rows = |rows_of: &[u64], ry: usize, r: usize, i: usize| {
        (ry.saturating_sub(r)..=(ry + r).min(rows - 1)).fold(0, |a, y| a | rows_of[y * nw + i])
    };
    for ry in 0..rows {
        let y = y0 + ry;
        for i in 0..nw {
            let inside = set[ry * nw + i];
            let near_col = or_rows(&near, ry, 1, i);
            let wide_col = or_rows(&wide, ry, 2, i);
            let mut any = (inside | wide_col) & if i + 1 == nw { last } else { !0 };
            while any != 0 {
                let b = any.trailing_zeros();
                any &= any - 1;
                let ring = if inside >> b & 1 == 1 {
                    Ring::Inside
                } else if near_col >> b & 1 == 1 {
                    Ring::Near
                } else {
                    // Nothing within one pixel, so the set pixel within
                    // two lies exactly two away.
                    Ring::Far
                };
                put(x0 + i * 64 + b as usize, y, ring);
            }
        }
    }
}

/// The bounding box (x0, y0, x1, y1), inclusive, of the cells of the
/// first `w` columns and `h` rows of a row-major grid (rows `stride`
/// cells apart) for which `set` holds; found row by row, from each end
/// of the row, with no division per cell.
pub fn set_bounds<T>(
    cells: &[T],
    stride: usize,
    w: usize,
    h: usize,
    set: impl Fn(&T) -> bool,
) -> Option<(usize, usize, usize, usize)> {
    let mut b: Option<(usize, usize, usize, usize)> = None;
    for (y, row) in cells.chunks(stride.max(1)).take(h).enumerate() {
        let row = &row[..w.min(row.len())];
        let Some(first) = row.iter().position(&set) else {
            continue;
        };
        let last = row.iter().rposition(&set).unwrap_or(first);
        b = Some(match b {
            None => (first, y, last, y),
            Some((x0, y0, x1, _)) => (x0.min(first), y0, x1.max(last), y),
        });
    }
    b
}

#[cfg(test)]
mod tests {
    use super::{for_each_ring, set_bounds, Ring};

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
        for_each_ring(mask, w, h, |x, y, r| {
            assert!(out[y * w + x].replace(r).is_none(), "({x}, {y}) twice");
        });
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
        // Masks of several densities and shapes, touching the borders too,
        // some wider than a 64-pixel word (a fixed linear congruential
        // sequence: the same masks every run).
        let mut seed = 0x2545_f491_u32;
        let mut next = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed >> 8
        };
        for (w, h) in [
            (1, 1),
            (1, 7),
            (9, 1),
            (13, 11),
            (32, 5),
            (64, 3),
            (65, 4),
            (150, 6),
        ] {
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
}
