//! Animation output: frame ranges rendered to PNG sequences or animated
//! GIFs, on all cores, deterministic, optionally split into shards for
//! several machines.
//!
//! - [`range`]: `--range START:STEP:COUNT` (seconds), `--frames A:B`, `--shard K/N`
//! - [`pattern`]: `frames/f_####.png` → `frames/f_0007.png`
//! - [`sequence`]: the driver (draw frames in parallel, write in order)
//! - [`palette`], [`dither`], [`gif`]: one median-cut palette for the whole
//!   animation, ordered two-colour dithering, GIF encoding
//! - [`pool`], [`progress`], [`png`]: threads, progress lines, atomic PNGs

pub mod dither;
pub mod gif;
pub mod palette;
pub mod pattern;
pub mod png;
pub mod pool;
pub mod progress;
pub mod range;
pub mod sequence;

pub use pattern::Pattern;
pub use progress::Mode as ProgressMode;
pub use range::{FrameRange, Shard};
pub use sequence::{OutputKind, SequenceJob};

use crate::render::job::{render_color_at, FrameSpec};
use crate::scene::Scene;
use std::path::Path;

/// The range arguments of `animed render`, as typed.
#[derive(Clone, Copy, Debug)]
pub struct RangeArgs<'a> {
    /// `--range START:STEP:COUNT` (seconds, seconds, frames).
    pub range: Option<&'a str>,
    /// `--frames A:B` (scene frames, inclusive).
    pub frames: Option<&'a str>,
    /// `--shard K/N`.
    pub shard: Option<&'a str>,
    /// `-o`: a pattern with `#`s, or a `.gif`.
    pub output: &'a Path,
}

impl RangeArgs<'_> {
    /// Whether any range argument was given (else it is a single frame).
    pub fn wanted(&self) -> bool {
        self.range.is_some() || self.frames.is_some() || self.shard.is_some()
    }
}

/// Memory the frames drawn at once may take together: frames are big
/// (colour, depth, ids, an RGBA copy: 16 bytes a pixel), so huge frames
/// are drawn fewer at a time, one at the least.
pub const FRAMES_IN_FLIGHT_BYTES: u64 = 1 << 30;

/// How many frames a range draws at once: `spec.threads` (0 = one per
/// core), capped so their buffers fit [`FRAMES_IN_FLIGHT_BYTES`].
pub fn frames_at_once(spec: &FrameSpec) -> usize {
    let asked = match spec.threads {
        0 => std::thread::available_parallelism().map_or(1, |n| n.get()),
        n => n,
    };
    let per_frame = (spec.width as u64 * spec.height as u64 * 16).max(1);
    let fit = (FRAMES_IN_FLIGHT_BYTES / per_frame).max(1) as usize;
    asked.min(fit)
}

/// `animed render --range/--frames [--shard] -o PATTERN`: checks the
/// arguments, then renders every frame of the range that belongs to the
/// shard as `spec` says (the picture `render --time t` gives), on
/// `spec.threads` frames at once (0 = one per core). Returns frames written.
pub fn render_range(scene: &Scene, spec: &FrameSpec, args: RangeArgs) -> Result<u32, String> {
    let range = match (args.range, args.frames) {
        (Some(r), None) => FrameRange::parse(r)?,
        (None, Some(f)) => FrameRange::from_frames(f, scene.settings.fps)?,
        (Some(_), Some(_)) => return Err("give --range or --frames, not both".into()),
        (None, None) => {
            return Err("--shard needs a range: --range START:STEP:COUNT or --frames A:B".into())
        }
    };
    let shard = args
        .shard
        .map(Shard::parse)
        .transpose()?
        .unwrap_or_default();
    let pattern = Pattern::from_path(args.output)?;
    let mut job = SequenceJob::new(range, shard, pattern)?;
    job.workers = frames_at_once(spec);
    job.progress = ProgressMode::detect();
    job.run(|t| render_color_at(scene, spec, t))
}
