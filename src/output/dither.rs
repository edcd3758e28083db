//! Mapping true-colour frames onto a palette with ordered two-colour
//! dithering.
//!
//! Each pixel colour `c` has a nearest palette colour `p1` and a partner
//! `p2` on the other side of `c`: the colour whose segment `p1 → p2` passes
//! closest to `c` (plus a small penalty on the segment's length, so near
//! partners win). With `t` = the position of `c` projected onto the
//! segment, a Bayer 8×8 threshold picks `p2` on a fraction `t` of the
//! pixels, so areas of smooth shading keep their average colour. This is
//! the two-colour case of Yliluoma's positional dithering; the threshold
//! depends only on the pixel position, so a still part of the picture gets
//! the same indices in every frame (no crawling noise as with error
//! diffusion), and flat colours compress well in the GIF's LZW.
//!
//! The search is integer; the partner cost is a short f64 sum in a fixed
//! order (no fused multiply-add), so the indices are the same everywhere.

use super::palette::Palette;
use std::collections::HashMap;

/// The 8×8 Bayer matrix (values 0..64).
const BAYER8: [[u8; 8]; 8] = [
    [0, 32, 8, 40, 2, 34, 10, 42],
    [48, 16, 56, 24, 50, 18, 58, 26],
    [12, 44, 4, 36, 14, 46, 6, 38],
    [60, 28, 52, 20, 62, 30, 54, 22],
    [3, 35, 11, 43, 1, 33, 9, 41],
    [51, 19, 59, 27, 49, 17, 57, 25],
    [15, 47, 7, 39, 13, 45, 5, 37],
    [63, 31, 55, 23, 61, 29, 53, 21],
];

/// A palette prepared for fast nearest-colour search.
pub struct Ditherer {
    /// Palette colours sorted by green, with their palette index.
    by_green: Vec<([i32; 3], u8)>,
    /// Palette colours by index.
    colours: Vec<[i32; 3]>,
}

/// How one colour is drawn: `p1`, or `p2` where the threshold is below `t`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Mix {
    p1: u8,
    p2: u8,
    /// t = num / den.
    num: i64,
    den: i64,
}

fn rgb(c: u32) -> [i32; 3] {
    [
        ((c >> 16) & 0xff) as i32,
        ((c >> 8) & 0xff) as i32,
        (c & 0xff) as i32,
    ]
}

fn dist2(a: [i32; 3], b: [i32; 3]) -> i64 {
    (0..3).map(|k| ((a[k] - b[k]) as i64).pow(2)).sum()
}

impl Ditherer {
    pub fn new(palette: &Palette) -> Ditherer {
        assert!(
            !palette.colours.is_empty() && palette.colours.len() <= 256,
            "a palette has 1..=256 colours"
        );
        let mut by_green: Vec<([i32; 3], u8)> = palette
            .colours
            .iter()
            .enumerate()
            .map(|(i, c)| ([c[0] as i32, c[1] as i32, c[2] as i32], i as u8))
            .collect();
        let colours = by_green.iter().map(|&(c, _)| c).collect();
        by_green.sort_by_key(|&(c, i)| (c[1], i));
        Ditherer { by_green, colours }
    }

    /// Palette index nearest to `c` (components may lie outside 0..255);
    /// ties go to the lower index. Searches outward from `c`'s green and
    /// stops once the green difference alone exceeds the best distance.
    pub fn nearest(&self, c: [i32; 3]) -> (u8, i64) {
        let v = &self.by_green;
        let start = v.partition_point(|&(p, _)| p[1] < c[1]);
        let mut best = (i64::MAX, u8::MAX);
        let consider = |best: &mut (i64, u8), k: usize| -> bool {
            let (p, i) = v[k];
            let dg = (p[1] - c[1]) as i64;
            if dg * dg > best.0 {
                return false;
            }
            let d = dist2(p, c);
            if (d, i) < *best {
                *best = (d, i);
            }
            true
        };
        let mut up = start;
        while up < v.len() && consider(&mut best, up) {
            up += 1;
        }
        let mut down = start;
        while down > 0 && consider(&mut best, down - 1) {
            down -= 1;
        }
        (best.1, best.0)
    }

    fn colour(&self, index: u8) -> [i32; 3] {
        self.colours[index as usize]
    }

    fn mix(&self, c: [i32; 3]) -> Mix {
        let (p1, d1) = self.nearest(c);
        let single = Mix {
            p1,
            p2: p1,
            num: 0,
            den: 1,
        };
        if d1 == 0 {
            return single;
        }
        let a = self.colour(p1);
        let ca = [0, 1, 2].map(|k| (c[k] - a[k]) as i64);
        // Partner: the colour q on c's side of p1 whose segment p1→q passes
        // closest to c, plus a sixteenth of the segment's squared length so
        // that of two partners on the same line the nearer one wins (less
        // noise per pixel). Ties go to the lower index.
        let mut best: Option<(f64, u8, i64, i64)> = None;
        for (qi, &q) in self.colours.iter().enumerate() {
            let qa = [0, 1, 2].map(|k| (q[k] - a[k]) as i64);
            let den: i64 = qa.iter().map(|v| v * v).sum();
            let num: i64 = (0..3).map(|k| ca[k] * qa[k]).sum();
            if qi == p1 as usize || den == 0 || num <= 0 {
                continue;
            }
            let t = (num as f64 / den as f64).min(1.0);
            let off: f64 = (0..3)
                .map(|k| (ca[k] as f64 - t * qa[k] as f64).powi(2))
                .sum();
            let cost = off + den as f64 / 16.0;
            if best.is_none_or(|(bc, _, _, _)| cost < bc) {
                best = Some((cost, qi as u8, num.min(den), den));
            }
        }
        match best {
            Some((_, p2, num, den)) => Mix { p1, p2, num, den },
            None => single,
        }
    }

    /// Palette indices for a `width`-wide frame of `0x00RRGGBB` pixels.
    pub fn dither(&self, pixels: &[u32], width: usize) -> Vec<u8> {
        let mut cache: HashMap<u32, Mix> = HashMap::new();
        let width = width.max(1);
        pixels
            .iter()
            .enumerate()
            .map(|(i, &px)| {
                let m = *cache
                    .entry(px & 0x00ff_ffff)
                    .or_insert_with(|| self.mix(rgb(px)));
                let (x, y) = (i % width, i / width);
                let b = BAYER8[y & 7][x & 7] as i64;
                // Choose p2 when t > (b + ½) / 64, in integers.
                if m.num * 128 > (2 * b + 1) * m.den {
                    m.p2
                } else {
                    m.p1
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey_palette(levels: &[u8]) -> Palette {
        Palette {
            colours: levels.iter().map(|&v| [v, v, v]).collect(),
        }
    }

    #[test]
    fn nearest_matches_a_brute_force_search() {
        let p = Palette {
            colours: (0..200u32)
                .map(|i| {
                    let h = i.wrapping_mul(2654435761);
                    [(h >> 24) as u8, (h >> 16) as u8, (h >> 8) as u8]
                })
                .collect(),
        };
        let d = Ditherer::new(&p);
        for j in 0..2000u32 {
            let h = j.wrapping_mul(0x9e3779b9) ^ 0x5bd1e995;
            let c = [
                (h & 0xff) as i32,
                ((h >> 8) & 0xff) as i32,
                ((h >> 16) & 0xff) as i32,
            ];
            let brute = p
                .colours
                .iter()
                .enumerate()
                .map(|(i, q)| (dist2([q[0] as i32, q[1] as i32, q[2] as i32], c), i as u8))
                .min()
                .unwrap();
            assert_eq!(d.nearest(c), (brute.1, brute.0), "colour {c:?}");
        }
    }

    #[test]
    fn palette_colours_map_to_themselves() {
        let p = grey_palette(&[0, 100, 200]);
        let d = Ditherer::new(&p);
        let px = [0u32, 100 * 0x010101, 200 * 0x010101, 0];
        assert_eq!(d.dither(&px, 2), vec![0, 1, 2, 0]);
    }

    #[test]
    fn dithering_keeps_the_average_of_flat_areas() {
        // Grey 25 between palette greys 0 and 100: t = 0.25, so a quarter
        // of an 8×8 block should be 100 (average 25 exactly).
        let d = Ditherer::new(&grey_palette(&[0, 100, 255]));
        let px = vec![25 * 0x010101u32; 64];
        let idx = d.dither(&px, 8);
        let ones = idx.iter().filter(|&&i| i == 1).count();
        assert_eq!(ones, 16);
        assert!(idx.iter().all(|&i| i == 0 || i == 1));
    }

    #[test]
    fn a_grey_ramp_dithers_between_its_neighbours() {
        // Every grey 0..=100 drawn as a flat 8×8 block over palette greys
        // {0, 50, 100}: each block uses only the two palette greys around
        // it and its mean is within 1 of the grey.
        let d = Ditherer::new(&grey_palette(&[0, 50, 100]));
        for v in 0..=100u32 {
            let idx = d.dither(&vec![v * 0x010101; 64], 8);
            let sum: u32 = idx.iter().map(|&i| [0, 50, 100][i as usize]).sum();
            let mean = sum as f64 / 64.0;
            assert!((mean - v as f64).abs() <= 1.0, "grey {v}: mean {mean}");
            let (lo, hi) = ((v / 50).min(1) as u8, (v.div_ceil(50)).min(2) as u8);
            assert!(idx.iter().all(|&i| i == lo || i == hi), "grey {v}: {idx:?}");
        }
    }
}
