//! Binning: the primitives touching each tile, in drawing order.
//!
//! Why in two parallel steps: a 100k-triangle frame makes about 130k
//! (triangle, tile) pairs, and one thread making them was a serial
//! stretch of every frame (4 % of a one-thread frame; with two threads
//! the other one waited). Opaque triangles go first into chunks, each
//! sorting its triangles by the tile rows they reach (with the tile
//! columns they cover); then each tile row appends the chunks' lists in
//! chunk order to its own tiles. A tile's list is then in triangle order
//! whatever the thread count, as one serial pass would make it.
//! Transparent triangles, lines and points (few in any scene) keep the
//! serial pass. The opaque boxes come from set-up's compact list
//! (`prepare::TriBox`), not from the triangles themselves.

use super::prepare::Prepared;
use super::raster::{Bin, TILE, TILE_H};
use rayon::prelude::*;

/// Opaque triangles per chunk of the first step.
const CHUNK: usize = 8192;

/// A triangle reaching a tile row: its index, the first and last tile
/// column its box covers, and whether its item is textured.
#[derive(Clone, Copy, Debug)]
struct Reach {
    i: u32,
    tx0: u16,
    tx1: u16,
    textured: bool,
}

/// The tiles' bins of a frame and the working lists that make them (kept
/// between frames, like the rest of a frame's scratch memory).
#[derive(Default)]
pub struct Bins {
    /// Row-major, `tiles_x` per row.
    pub tiles: Vec<Bin>,
    pub tiles_x: i32,
    /// Per chunk of opaque triangles, per tile row: the triangles of the
    /// chunk reaching it, in order.
    rows: Vec<Vec<Vec<Reach>>>,
}

/// Bins the prepared primitives into the `TILE`×`TILE_H` tiles of a
/// `w`×`h` frame (each list in drawing order).
pub fn bin_tiles(p: &Prepared, bins: &mut Bins, w: i32, h: i32) {
    let tiles_x = (w + TILE - 1) / TILE;
    let tiles_y = ((h + TILE_H - 1) / TILE_H) as usize;
    bins.tiles_x = tiles_x;
    bins.tiles
        .resize_with(tiles_x as usize * tiles_y, Bin::default);
    // Set-up keeps each opaque triangle's box and texture flag beside it
    // (`TriBox`): read here, they are 1 MB of a 100k-triangle frame.
    let boxes = &p.opaque_boxes;
    let chunks = boxes.len().div_ceil(CHUNK);
    if bins.rows.len() < chunks {
        bins.rows.resize_with(chunks, Vec::new);
    }
    bins.rows[..chunks]
        .par_iter_mut()
        .zip(boxes.par_chunks(CHUNK))
        .enumerate()
        .for_each(|(c, (rows, boxes))| {
            rows.resize_with(tiles_y, Vec::new);
            for r in rows.iter_mut() {
                r.clear();
            }
            for (k, t) in boxes.iter().enumerate() {
                // Boxes are clamped to the frame and never empty (`prepare`).
                let b = t.bbox.map(i32::from);
                let reach = Reach {
                    i: (c * CHUNK + k) as u32,
                    tx0: (b[0] / TILE) as u16,
                    tx1: ((b[2] - 1) / TILE) as u16,
                    textured: t.textured,
                };
                for r in &mut rows[(b[1] / TILE_H) as usize..=((b[3] - 1) / TILE_H) as usize] {
                    r.push(reach);
                }
            }
        });
    let chunk_rows = &bins.rows[..chunks];
    bins.tiles
        .par_chunks_mut(tiles_x as usize)
        .enumerate()
        .for_each(|(ty, row)| {
            for b in row.iter_mut() {
                b.clear();
            }
            for rows in chunk_rows {
                for r in &rows[ty] {
                    for bin in &mut row[r.tx0 as usize..=r.tx1 as usize] {
                        bin.textured |= r.textured;
                        bin.opaque.push(r.i);
                    }
                }
            }
        });
    let transparent = p.transparent.iter().map(|t| t.bbox);
    bin_serial(&mut bins.tiles, tiles_x, transparent, |b| {
        &mut b.transparent
    });
    let lines = p.lines.iter().map(|l| l.bbox);
    bin_serial(&mut bins.tiles, tiles_x, lines, |b| &mut b.lines);
    let points = p.points.iter().map(|q| q.bbox);
    bin_serial(&mut bins.tiles, tiles_x, points, |b| &mut b.points);
}

/// Appends each primitive's index to the bins its box touches.
fn bin_serial(
    bins: &mut [Bin],
    tiles_x: i32,
    boxes: impl Iterator<Item = [i32; 4]>,
    pick: fn(&mut Bin) -> &mut Vec<u32>,
) {
    for (i, b) in boxes.enumerate() {
        let (tx0, ty0) = (b[0] / TILE, b[1] / TILE_H);
        let (tx1, ty1) = ((b[2] - 1) / TILE, (b[3] - 1) / TILE_H);
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                pick(&mut bins[(ty * tiles_x + tx) as usize]).push(i as u32);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::internals::render::test_rng::XorShift;
    use crate::render::prepare::{Item, Tri, TriBox};
    use crate::render::shade::ShadeMaterial;
    use crate::render::tri_gradients::Gradients;
    use crate::scene::Material;

    /// The serial pass this file replaces, for the opaque lists.
    fn serial(p: &Prepared, tiles_x: i32, tiles_y: i32) -> Vec<(Vec<u32>, bool)> {
        let mut out = vec![(Vec::new(), false); (tiles_x * tiles_y) as usize];
        for (i, t) in p.opaque.iter().enumerate() {
            let b = t.bbox;
            for ty in b[1] / TILE_H..=(b[3] - 1) / TILE_H {
                for tx in b[0] / TILE..=(b[2] - 1) / TILE {
                    let bin = &mut out[(ty * tiles_x + tx) as usize];
                    bin.0.push(i as u32);
                    bin.1 |= p.items[t.item as usize].textured;
                }
            }
        }
        out
    }

    /// Seeded boxes of every size over frames of several sizes, more
    /// triangles than one chunk holds, textured and untextured items: the
    /// two-step binning gives every tile the serial pass's list and
    /// texture flag, frame after frame in the same buffers.
    #[test]
    fn parallel_bins_are_the_serial_bins() {
        let mut rng = XorShift::new(0x2545_F491_4F6C_DD1D);
        let mut next = |n: i32| (rng.next_u64() % n as u64) as i32;
        let mut bins = Bins::default();
        let mut textured_tiles = 0;
        for (w, h, count) in [
            (1280, 720, 3 * CHUNK + 17),
            (333, 97, 500),
            (64, 32, 9),
            (700, 400, 0),
        ] {
            let mut p = Prepared::default();
            for textured in [false, true] {
                p.items.push(Item {
                    id: 1,
                    material: ShadeMaterial::new(&Material::default()),
                    lights: Vec::new(),
                    unlit: true,
                    surface_strokes: false,
                    textured,
                    texture: None,
                    emissive: None,
                });
            }
            for _ in 0..count {
                let (x0, y0) = (next(w), next(h));
                let big = next(50) == 0;
                let (dx, dy) = if big {
                    (next(w) + 1, next(h) + 1)
                } else {
                    (next(12) + 1, next(12) + 1)
                };
                let bbox = [x0, y0, (x0 + dx).min(w), (y0 + dy).min(h)];
                let t = Tri {
                    x: [0; 3],
                    y: [0; 3],
                    z: [0.5; 3],
                    base: Default::default(),
                    d1: Default::default(),
                    d2: Default::default(),
                    item: (next(7) == 0) as u32,
                    bbox,
                    grad: Gradients::default(),
                };
                p.opaque.push(t);
                p.opaque_boxes
                    .push(TriBox::of_box(&t.bbox, p.items[t.item as usize].textured));
            }
            bin_tiles(&p, &mut bins, w, h);
            let (tx, ty) = ((w + TILE - 1) / TILE, (h + TILE_H - 1) / TILE_H);
            assert_eq!(bins.tiles_x, tx);
            assert_eq!(bins.tiles.len(), (tx * ty) as usize);
            for (bin, (list, textured)) in bins.tiles.iter().zip(serial(&p, tx, ty)) {
                assert_eq!(bin.opaque, list, "{w}x{h}");
                assert_eq!(bin.textured, textured);
                textured_tiles += textured as usize;
            }
        }
        assert!(textured_tiles > 100, "{textured_tiles}");
    }
}
