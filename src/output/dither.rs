//! Mapping true-colour frames onto a palette with ordered two-colour
//! dithering.
//!
//! Each distinct colour `c` gets a *plan* of [`PLAN`] palette colours whose
//! mean is close to `c`, built as in Knoll's pattern dithering (Adobe,
//! US patent 6,606,166, expired; described in Yliluoma's "Arbitrary-palette
//! positional dithering algorithm"): repeatedly take the palette colour
//! nearest to `c + e` and add what it missed to `e`. The plan is sorted by
//! luminance and a Bayer 8×8 threshold picks one entry per pixel, so every
//! 8×8 tile of a flat colour averages to the plan's mean, in any direction
//! of colour space (a mix of 3 or 4 palette colours where needed).
//!
//! The threshold depends only on the pixel position, so a still part of
//! the picture gets the same indices in every frame (no crawling noise as
//! with error diffusion) and flat colours compress well in the GIF's LZW.
//!
//! Everything is integer arithmetic, so the indices are the same everywhere.

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

/// Palette colours mixed per distinct colour (each is used on 4 of the 64
/// pixels of a Bayer tile).
pub const PLAN: usize = 16;

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

    /// Knoll's plan for `c`: [`PLAN`] indices sorted by luminance.
    fn plan(&self, c: [i32; 3]) -> [u8; PLAN] {
        let mut plan = [0u8; PLAN];
        let mut err = [0i32; 3];
        for slot in plan.iter_mut() {
            // Clamped so a colour outside the palette's hull cannot run away.
            let attempt = [0, 1, 2].map(|k| (c[k] + err[k]).clamp(0, 255));
            let (i, _) = self.nearest(attempt);
            let p = self.colour(i);
            for k in 0..3 {
                err[k] += c[k] - p[k];
            }
            *slot = i;
        }
        // Luminance (ITU-R BT.601 weights ×1000), ties by index.
        plan.sort_by_key(|&i| {
            let p = self.colour(i);
            (299 * p[0] + 587 * p[1] + 114 * p[2], i)
        });
        plan
    }

    /// Palette indices for a `width`-wide frame of `0x00RRGGBB` pixels.
    pub fn dither(&self, pixels: &[u32], width: usize) -> Vec<u8> {
        let mut cache: HashMap<u32, [u8; PLAN]> = HashMap::new();
        let width = width.max(1);
        pixels
            .iter()
            .enumerate()
            .map(|(i, &px)| {
                let plan = cache
                    .entry(px & 0x00ff_ffff)
                    .or_insert_with(|| self.plan(rgb(px)));
                let (x, y) = (i % width, i / width);
                plan[BAYER8[y & 7][x & 7] as usize * PLAN / 64]
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
        // it and its mean is close to the grey.
        let d = Ditherer::new(&grey_palette(&[0, 50, 100]));
        for v in 0..=100u32 {
            let idx = d.dither(&vec![v * 0x010101; 64], 8);
            let sum: u32 = idx.iter().map(|&i| [0, 50, 100][i as usize]).sum();
            let mean = sum as f64 / 64.0;
            // The plan's error is what is left in e after 16 steps, at most
            // half a palette step (25) spread over 16 entries.
            assert!(
                (mean - v as f64).abs() <= 25.0 / 16.0,
                "grey {v}: mean {mean}"
            );
            let (lo, hi) = ((v / 50).min(1) as u8, (v.div_ceil(50)).min(2) as u8);
            assert!(idx.iter().all(|&i| i == lo || i == hi), "grey {v}: {idx:?}");
        }
    }
}
