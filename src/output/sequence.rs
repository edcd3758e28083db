//! Rendering a range of frames to a PNG sequence or an animated GIF.
//!
//! The driver does not know how a frame is drawn: it takes a function from
//! time (seconds) to [`Frame`], so the CLI passes "load + camera + render at
//! t" and tests pass whatever they like. Frames are drawn on `workers`
//! threads, whole frames each, and every frame is a pure function of its
//! time, so the output is the same bytes for any worker count and any
//! `--shard` split.

use super::dither::Ditherer;
use super::gif::{delay_centiseconds, GifWriter};
use super::palette::{median_cut, Histogram};
use super::pattern::{create_parent, Pattern};
use super::pool::ordered_map;
use super::progress::{Mode, Progress};
use super::range::{FrameRange, Shard};
use crate::render::Frame;

/// What kind of file(s) a pattern asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputKind {
    /// One PNG per frame (`#` in the name).
    PngSequence,
    /// One looping animated GIF.
    Gif,
}

/// A checked request for a range of frames.
#[derive(Clone, Debug)]
pub struct SequenceJob {
    pub range: FrameRange,
    pub shard: Shard,
    pub pattern: Pattern,
    pub kind: OutputKind,
    /// Frames drawn at once (each on its own thread).
    pub workers: usize,
    pub progress: Mode,
}

impl SequenceJob {
    /// Checks that the pattern, range and shard go together.
    pub fn new(range: FrameRange, shard: Shard, pattern: Pattern) -> Result<SequenceJob, String> {
        let kind = match pattern.extension().as_deref() {
            Some("gif") => OutputKind::Gif,
            Some("png") => OutputKind::PngSequence,
            _ => {
                return Err(format!(
                    "output {pattern:?} must end in .png (a PNG per frame, with # for the \
                     frame number) or .gif (one animated GIF)",
                    pattern = pattern.to_string()
                ))
            }
        };
        match kind {
            OutputKind::Gif => {
                if pattern.has_index() {
                    return Err(format!(
                        "output {:?}: a GIF is one file; remove the '#'",
                        pattern.to_string()
                    ));
                }
                if shard.n > 1 {
                    return Err(
                        "--shard cannot split a GIF (it is one file): render a PNG sequence \
                         in shards, then assemble it"
                            .to_string(),
                    );
                }
            }
            OutputKind::PngSequence => pattern.check_count(range.count)?,
        }
        Ok(SequenceJob {
            range,
            shard,
            pattern,
            kind,
            workers: 1,
            progress: Mode::Quiet,
        })
    }

    /// Runs the job; `render(t)` draws the frame at `t` seconds.
    /// Returns how many frames were written.
    pub fn run<F>(&self, render: F) -> Result<u32, String>
    where
        F: Fn(f32) -> Result<Frame, String> + Sync,
    {
        match self.kind {
            OutputKind::PngSequence => self.run_png(&render),
            OutputKind::Gif => self.run_gif(&render),
        }
    }

    fn run_png<F>(&self, render: &F) -> Result<u32, String>
    where
        F: Fn(f32) -> Result<Frame, String> + Sync,
    {
        let indices = self.shard.indices(self.range.count);
        let label = if self.shard.n > 1 {
            format!("render shard {}/{}", self.shard.k, self.shard.n)
        } else {
            "render".to_string()
        };
        let mut progress = Progress::new(label, indices.len() as u32, self.progress);
        let work = |&i: &u32| -> Result<String, String> {
            let t = self.range.time(i);
            let path = self.pattern.expand(i);
            create_parent(&path)?;
            let frame = render(t)?;
            super::png::save_atomic(&frame, &path)
                .map_err(|e| format!("frame {i} (t={t} s) not written, stopping: {e}"))?;
            Ok(format!("frame {i} t={t} s -> {}", path.display()))
        };
        ordered_map(&indices, self.workers, 4 * self.workers, work, |_, r| {
            progress.frame_done(&r?);
            Ok(())
        })?;
        let n = indices.len() as u32;
        progress.finish(&format!("wrote {n} frames"));
        Ok(n)
    }

    fn run_gif<F>(&self, render: &F) -> Result<u32, String>
    where
        F: Fn(f32) -> Result<Frame, String> + Sync,
    {
        let path = self.pattern.expand(0);
        create_parent(&path)?;
        let indices: Vec<u32> = (0..self.range.count).collect();
        let n = indices.len() as u32;
        let mut progress = Progress::new("gif", n, self.progress);
        let mut writer: Option<GifWriter> = None;
        let mut size: Option<(u32, u32)> = None;
        // Each frame: draw, median-cut its own palette, dither (in
        // parallel); then append in order.
        ordered_map(
            &indices,
            self.workers,
            2 * self.workers,
            |&i| {
                let frame = render(self.range.time(i))?;
                let palette = median_cut(&Histogram::of_pixels(&frame.color), 256);
                let idx = Ditherer::new(&palette).dither(&frame.color, frame.width as usize);
                Ok::<_, String>((frame, palette, idx))
            },
            |i, r| {
                let (frame, palette, idx) = r?;
                check_size(&mut size, &frame)?;
                let w = match &mut writer {
                    Some(w) => w,
                    None => writer.insert(GifWriter::create(
                        &path,
                        frame.width,
                        frame.height,
                        delay_centiseconds(self.range.step),
                    )?),
                };
                w.add(frame.color, &idx, &palette)?;
                progress.frame_done(&format!("frame {i} t={} s", self.range.time(i as u32)));
                Ok(())
            },
        )?;
        writer.ok_or("no frames to write")?.finish()?;
        progress.finish(&format!("wrote {} ({n} frames)", path.display()));
        Ok(n)
    }
}

fn check_size(size: &mut Option<(u32, u32)>, f: &Frame) -> Result<(), String> {
    match *size {
        None => {
            *size = Some((f.width, f.height));
            Ok(())
        }
        Some(s) if s == (f.width, f.height) => Ok(()),
        Some(s) => Err(format!(
            "frames differ in size: {}x{} after {}x{}",
            f.width, f.height, s.0, s.1
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn job(range: &str, shard: Shard, out: &str) -> Result<SequenceJob, String> {
        SequenceJob::new(
            FrameRange::parse(range).unwrap(),
            shard,
            Pattern::parse(out).unwrap(),
        )
    }

    #[test]
    fn pattern_and_kind_must_agree() {
        assert_eq!(
            job("0:1:3", Shard::default(), "f_#.png").unwrap().kind,
            OutputKind::PngSequence
        );
        assert_eq!(
            job("0:1:3", Shard::default(), "a.GIF").unwrap().kind,
            OutputKind::Gif
        );
        let e = job("0:1:3", Shard::default(), "f_#.jpg").unwrap_err();
        assert!(e.contains("must end in .png"), "{e}");
        let e = job("0:1:3", Shard::default(), "f_#.gif").unwrap_err();
        assert!(e.contains("remove the '#'"), "{e}");
        let e = job("0:1:3", Shard { k: 0, n: 2 }, "a.gif").unwrap_err();
        assert!(e.contains("cannot split a GIF"), "{e}");
        let e = job("0:1:3", Shard::default(), "f.png").unwrap_err();
        assert!(e.contains("has no '#'"), "{e}");
        assert!(job("0:1:1", Shard::default(), "f.png").is_ok());
    }
}
