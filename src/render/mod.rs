//! The CPU rasteriser: clipping, fixed-point edge functions, per-pixel
//! VRML97 lighting, deterministic tiled threading.
//!
//! API contract used by the CLI, the editor and the viewer:
//! `render(scene, pose, view, opts) -> Frame`.
//!
//! Pipeline (one file per stage; `stages` runs them one at a time for the
//! per-stage benchmarks):
//! `prepare` (gather shapes/lights, transform, `clip`, project, cull, snap to
//! the fixed-point grid) → binning into [`raster::TILE`]×[`raster::TILE_H`] tiles →
//! `raster::draw_tile` per tile on the thread pool (depth pass, then one
//! `shade` call per visible pixel, then lines/points, then transparent
//! triangles back to front) → copy tiles into the [`Frame`].
//! Every pixel belongs to exactly one tile and every tile draws its
//! primitives in scene order, so the bytes never depend on the thread count.

mod background;
pub mod band_trace;
pub mod bench_scenes;
mod binning;
mod blend_samples;
mod block_planes;
mod clip;
mod coin_bounds;
mod depth_blocks;
mod fragment;
mod frame;
mod geometry;
mod in_place;
pub mod job;
mod label;
mod lanes;
mod log2_lanes;
mod narrow_depth;
mod prepare;
mod raster;
mod samples;
mod shade;
mod shading;
mod simd;
pub mod stages;
mod stroke_faces;
mod surface;
#[cfg(test)]
mod test_rng;
mod texel_block;
mod texel_fetch;
mod texel_filter;
mod texture;
mod texture_lanes;
mod tri_gradients;
mod trilinear16;
mod view;

pub use frame::{pack_rgb, Frame};
pub use shade::{ShadeMaterial, WorldLight};
pub use view::{bounding_sphere, scene_bounds, scene_bounds_for_picture, shape_bounds, View};

use crate::anim::Pose;
use crate::scene::{RenderStyle, Scene};
use glam::Vec3;
use rayon::prelude::*;
use std::sync::{Arc, Mutex, OnceLock};

/// Everything about a render that is not the scene or the camera.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderOptions {
    pub width: u32,
    pub height: u32,
    /// Worker threads (0 = all cores). The output never depends on it.
    pub threads: usize,
    /// Draw every object in this style instead of its own.
    pub style_override: Option<RenderStyle>,
    /// A directional light at the camera looking along the view direction.
    pub headlight: bool,
    pub background: Vec3,
    /// Draw the scene's own gradient/panorama background (VRML97
    /// Background) instead of the flat `background`, when it has one.
    pub sky: bool,
    /// Multisample anti-aliasing: 1 (off), 4 or 8 samples per pixel (other
    /// values round down to one of these). Depth and coverage per sample,
    /// shading once per pixel per triangle, box-filter resolve.
    pub aa: u32,
}

impl RenderOptions {
    /// Samples per pixel: 1, 4 or 8.
    pub fn samples(&self) -> usize {
        match self.aa {
            0..=3 => 1,
            4..=7 => 4,
            _ => 8,
        }
    }
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 320,
            height: 240,
            threads: 0,
            style_override: None,
            headlight: true,
            background: Vec3::ZERO,
            sky: false,
            aa: 1,
        }
    }
}

/// Largest picture side accepted; bigger requests are clamped so a typo
/// cannot allocate gigabytes.
pub const MAX_SIDE: u32 = 16384;
/// Largest picture area (64 Mpix, 768 MB of frame buffers); taller
/// requests are cut to this many rows.
pub const MAX_PIXELS: u64 = 1 << 26;

/// Draws `pose` of `scene` seen through `view`.
pub fn render(scene: &Scene, pose: &Pose, view: &View, opts: &RenderOptions) -> Frame {
    let mut frame = Frame::new(0, 0, opts.background);
    render_into(scene, pose, view, opts, &mut frame);
    frame
}

/// [`render`] into an existing frame, reusing its buffers when the size
/// stays the same (a new 1280×720 frame costs its page faults every time;
/// players and editors draw many frames).
pub fn render_into(
    scene: &Scene,
    pose: &Pose,
    view: &View,
    opts: &RenderOptions,
    frame: &mut Frame,
) {
    render_frame(scene, pose, view, opts, frame, true);
}

/// [`render_into`] for callers that want only the picture (`animed render`,
/// the library's `render`, the benchmarks): the same colour bytes, but the
/// frame's `depth` and `ids` come back empty. Writing them out is a third
/// of a one-layer frame's memory traffic (8 of every pixel's 12 bytes) that
/// nobody reads there; the editor, which picks with ids, keeps them.
pub fn render_color_into(
    scene: &Scene,
    pose: &Pose,
    view: &View,
    opts: &RenderOptions,
    frame: &mut Frame,
) {
    render_frame(scene, pose, view, opts, frame, false);
}

/// Draws into `frame`, with its depth and id buffers when `depth_and_ids`.
fn render_frame(
    scene: &Scene,
    pose: &Pose,
    view: &View,
    opts: &RenderOptions,
    frame: &mut Frame,
    depth_and_ids: bool,
) {
    let mut opts = opts.clone();
    opts.width = opts.width.min(MAX_SIDE);
    opts.height = opts.height.min(MAX_SIDE);
    if opts.width as u64 * opts.height as u64 > MAX_PIXELS {
        opts.height = (MAX_PIXELS / opts.width as u64) as u32;
    }
    // Every pixel is written by its tile, so resized buffers need no fill.
    frame.fit(opts.width, opts.height, depth_and_ids);
    if opts.width == 0 || opts.height == 0 {
        return;
    }
    let pool = thread_pool(opts.threads);
    let mut scratch = FrameScratch::take();
    pool.install(|| {
        prepare::prepare(scene, pose, view, &opts, &mut scratch.prepared);
        draw(&scratch.prepared, &mut scratch.bins, &opts, view.eye, frame);
    });
    scratch.give_back();
}

/// The per-frame working memory (prepared primitives and tile bins), kept
/// in a small pool between renders: a 100k-triangle frame fills tens of
/// megabytes, and allocating them afresh costs page faults every frame.
/// Contents never carry over (everything is cleared before use).
#[derive(Default)]
struct FrameScratch {
    prepared: prepare::Prepared,
    bins: binning::Bins,
}

static SCRATCH: Mutex<Vec<FrameScratch>> = Mutex::new(Vec::new());

impl FrameScratch {
    fn take() -> FrameScratch {
        // A poisoned lock only means another render panicked; the pool is fine.
        let mut pool = SCRATCH.lock().unwrap_or_else(|e| e.into_inner());
        pool.pop().unwrap_or_default()
    }

    fn give_back(self) {
        let mut pool = SCRATCH.lock().unwrap_or_else(|e| e.into_inner());
        // Concurrent renders (editor + onion copies) each keep one.
        if pool.len() < 4 {
            pool.push(self);
        }
    }
}

/// Bins the prepared primitives into tiles, draws the tiles in parallel and
/// copies them into `frame`.
fn draw(
    p: &prepare::Prepared,
    bins: &mut binning::Bins,
    opts: &RenderOptions,
    eye: Vec3,
    frame: &mut Frame,
) {
    let (w, h) = (opts.width as i32, opts.height as i32);
    binning::bin_tiles(p, bins, w, h);
    let (tiles_x, bins) = (bins.tiles_x, &bins.tiles);
    // Bands of one tile row each run in parallel; a band draws its tiles left
    // to right straight into its rows of the frame.
    let band = raster::TILE_H as usize * w as usize;
    let background = opts.background;
    let clock = band_trace::frame_start();
    // A colour-only frame has no depth or ids: its bands get empty slices,
    // which the resolve leaves alone.
    let n_bands = frame.color.len().div_ceil(band);
    let mut depth: Vec<&mut [f32]> = frame.depth.chunks_mut(band).collect();
    let mut ids: Vec<&mut [u32]> = frame.ids.chunks_mut(band).collect();
    depth.resize_with(n_bands, Default::default);
    ids.resize_with(n_bands, Default::default);
    let bands = frame
        .color
        .par_chunks_mut(band)
        .zip(depth)
        .zip(ids)
        .enumerate();
    /// A band's index and its rows of the colour, depth and id buffers.
    type Band<'a> = (usize, ((&'a mut [u32], &'a mut [f32]), &'a mut [u32]));
    let draw_band = |(ty, ((color, depth), ids)): Band| {
        let started = clock.map(|_| std::time::Instant::now());
        let ty = ty as i32;
        // Tile buffers are kept per worker thread between bands and
        // frames (all their contents are reset or overwritten per tile).
        thread_local! {
            static SCRATCH: std::cell::RefCell<Option<raster::Scratch>> =
                const { std::cell::RefCell::new(None) };
        }
        let mut scratch = SCRATCH
            .with(|s| s.borrow_mut().take())
            .filter(|s| s.samples() == opts.samples())
            .unwrap_or_else(|| raster::Scratch::new(opts.samples()));
        let mut target = raster::Target {
            color,
            depth,
            ids,
            stride: w as usize,
            y0: ty * raster::TILE_H,
        };
        for tx in 0..tiles_x {
            let rect = [
                tx * raster::TILE,
                ty * raster::TILE_H,
                ((tx + 1) * raster::TILE).min(w),
                ((ty + 1) * raster::TILE_H).min(h),
            ];
            let bin = &bins[(ty * tiles_x + tx) as usize];
            raster::draw_tile(p, bin, rect, background, eye, &mut scratch, &mut target);
        }
        SCRATCH.with(|s| *s.borrow_mut() = Some(scratch));
        if let (Some(frame), Some(started)) = (clock, started) {
            band_trace::band_done(frame, started);
        }
    };
    if band_trace::coarse() {
        bands.for_each(draw_band);
    } else {
        // One band per job: a thread that runs out of work takes the next
        // single band, so the threads finish within one band of each other
        // (rayon's default split hands out runs of up to six consecutive
        // bands, and the last run decided when the frame was done).
        bands.with_max_len(1).for_each(draw_band);
    }
}

/// A rayon pool per requested thread count, built once and reused (the
/// editor renders every frame; building a pool each time costs more than a
/// small frame).
fn thread_pool(threads: usize) -> Arc<rayon::ThreadPool> {
    type Pools = Mutex<Vec<(usize, Arc<rayon::ThreadPool>)>>;
    static POOLS: OnceLock<Pools> = OnceLock::new();
    let pools = POOLS.get_or_init(|| Mutex::new(Vec::new()));
    // A poisoned lock only means another render panicked; the pools are fine.
    let mut pools = pools.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, p)) = pools.iter().find(|(n, _)| *n == threads) {
        return p.clone();
    }
    let pool = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            // Building a pool fails only when the OS refuses to spawn threads;
            // nothing sensible can be drawn then.
            .expect("cannot start render threads"),
    );
    pools.push((threads, pool.clone()));
    pool
}
