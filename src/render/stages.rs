//! The frame pipeline one stage at a time, for the per-stage benchmarks
//! (`cargo bench --bench render`): a regression in one stage shows there
//! instead of hiding in a whole-frame average.
//!
//! Each stage runs over every tile of the frame on the calling thread:
//! setup (`prepare` + binning), raster (the depth pass), shade (the depth
//! pass and the shading pass it needs: the shading pass reads what the
//! depth pass of the same tile left) and resolve (samples → frame pixels).
//! Drawing a frame through [`super::render_into`] does the same work, on
//! the thread pool and with lines, points and transparent triangles.

use super::binning::{self, Bins};
use super::prepare::{self, Prepared};
use super::raster::{self, Rect, Scratch, Target, TILE, TILE_H};
use super::{Frame, RenderOptions, View};
use crate::anim::Pose;
use crate::scene::Scene;

/// A prepared frame and the buffers its stages work in.
pub struct Stages {
    prepared: Prepared,
    bins: Bins,
    opts: RenderOptions,
    view: View,
    scratch: Scratch,
    frame: Frame,
    /// Each tile's `flat` marks from the last shading stage, for the
    /// resolve (under multisampling it resolves flat blocks from their
    /// first sample plane only).
    flats: Vec<Vec<bool>>,
}

impl Stages {
    /// Sets up `pose` of `scene` through `view` (running [`Stages::setup`]
    /// once) with buffers for `opts`' size and samples.
    pub fn new(scene: &Scene, pose: &Pose, view: &View, opts: &RenderOptions) -> Stages {
        let mut s = Stages {
            prepared: Prepared::default(),
            bins: Bins::default(),
            opts: opts.clone(),
            view: *view,
            scratch: Scratch::new(opts.samples()),
            frame: Frame::new(opts.width, opts.height, opts.background),
            flats: Vec::new(),
        };
        s.setup(scene, pose);
        s
    }

    /// Triangle setup: transform, clip, project, planes; then binning.
    pub fn setup(&mut self, scene: &Scene, pose: &Pose) {
        prepare::prepare(scene, pose, &self.view, &self.opts, &mut self.prepared);
        let (w, h) = (self.opts.width as i32, self.opts.height as i32);
        binning::bin_tiles(&self.prepared, &mut self.bins, w, h);
    }

    /// Every tile's rectangle and bin index.
    fn tiles(&self) -> Vec<(Rect, usize)> {
        let (w, h) = (self.opts.width as i32, self.opts.height as i32);
        let mut out = Vec::new();
        for ty in 0..(h + TILE_H - 1) / TILE_H {
            for tx in 0..self.bins.tiles_x {
                let rect = [
                    tx * TILE,
                    ty * TILE_H,
                    ((tx + 1) * TILE).min(w),
                    ((ty + 1) * TILE_H).min(h),
                ];
                out.push((rect, (ty * self.bins.tiles_x + tx) as usize));
            }
        }
        out
    }

    /// The depth pass of every tile.
    pub fn raster(&mut self) {
        for (rect, bin) in self.tiles() {
            raster::depth_tile(
                &self.prepared,
                &self.bins.tiles[bin],
                rect,
                &mut self.scratch,
                false,
            );
        }
    }

    /// The depth pass and the shading pass of every tile.
    pub fn raster_and_shade(&mut self) {
        let (bg, eye) = (self.opts.background, self.view.eye);
        let tiles = self.tiles();
        self.flats.resize(tiles.len(), Vec::new());
        for (k, (rect, bin)) in tiles.into_iter().enumerate() {
            raster::depth_tile(
                &self.prepared,
                &self.bins.tiles[bin],
                rect,
                &mut self.scratch,
                false,
            );
            raster::shade_tile(
                &self.prepared,
                &self.bins.tiles[bin],
                rect,
                bg,
                eye,
                &mut self.scratch,
            );
            let flat = &mut self.flats[k];
            flat.clear();
            flat.extend_from_slice(self.scratch.flat_mut());
        }
    }

    /// The resolve of every tile (from whatever the tile buffers hold: the
    /// cost does not depend on the values, only on each tile's `flat` marks,
    /// which are the tile's own after [`Stages::raster_and_shade`]).
    pub fn resolve(&mut self) {
        let stride = self.opts.width as usize;
        for (k, (rect, _)) in self.tiles().into_iter().enumerate() {
            if let Some(flat) = self.flats.get(k) {
                self.scratch.flat_mut().copy_from_slice(flat);
            }
            let y0 = rect[1];
            let from = y0 as usize * stride;
            let to = (rect[3] as usize * stride).min(self.frame.color.len());
            let mut target = Target {
                color: &mut self.frame.color[from..to],
                depth: &mut self.frame.depth[from..to],
                ids: &mut self.frame.ids[from..to],
                stride,
                y0,
            };
            raster::resolve_tile(rect, &self.scratch, &mut target);
        }
    }

    /// The frame the resolve writes.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }
}
