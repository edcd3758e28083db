//! Writing an animated GIF: each frame carries its own palette (a local
//! colour table), the animation loops forever, and every frame after the
//! first stores only the rectangle whose source pixels changed (disposal
//! "keep"), which is what makes a GIF of an object moving over a still
//! background small — and keeps the still part from shimmering, since it is
//! not re-quantised.
//!
//! The file is written beside the target and renamed into place when the
//! last frame is in, so a reader never sees half a GIF.

use super::palette::Palette;
use crate::format::export::atomic::{Replace, TempFile};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

/// GIF frame delays are in hundredths of a second.
pub fn delay_centiseconds(step_seconds: f64) -> u16 {
    (step_seconds * 100.0).round().clamp(1.0, u16::MAX as f64) as u16
}

/// An animated GIF being written.
pub struct GifWriter {
    encoder: gif::Encoder<BufWriter<File>>,
    width: u16,
    height: u16,
    delay: u16,
    /// The previous frame's source pixels (`0x00RRGGBB`).
    previous: Option<Vec<u32>>,
    /// Removed if the writer is dropped before [`GifWriter::finish`].
    tmp: TempFile,
    path: PathBuf,
}

fn gif_side(v: u32, what: &str) -> Result<u16, String> {
    u16::try_from(v)
        .ok()
        .filter(|&v| v > 0)
        .ok_or_else(|| format!("a GIF's {what} must be 1..=65535 pixels (it is {v})"))
}

impl GifWriter {
    /// Starts `path` (through a temporary file beside it, removed on any
    /// failure) with `delay` hundredths of a second per frame.
    pub fn create(path: &Path, width: u32, height: u32, delay: u16) -> Result<GifWriter, String> {
        Self::create_with(path, width, height, delay, Replace::default())
    }

    /// [`GifWriter::create`], `how` saying whether a read-only file may be replaced.
    pub fn create_with(
        path: &Path,
        width: u32,
        height: u32,
        delay: u16,
        how: Replace,
    ) -> Result<GifWriter, String> {
        let (w, h) = (gif_side(width, "width")?, gif_side(height, "height")?);
        let (tmp, file) =
            TempFile::create(path, how).map_err(|e| format!("{}: {e}", path.display()))?;
        let err = |e: gif::EncodingError| format!("{}: {e}", path.display());
        let mut encoder = gif::Encoder::new(BufWriter::new(file), w, h, &[]).map_err(err)?;
        encoder.set_repeat(gif::Repeat::Infinite).map_err(err)?;
        Ok(GifWriter {
            encoder,
            width: w,
            height: h,
            delay,
            previous: None,
            tmp,
            path: path.to_path_buf(),
        })
    }

    /// Appends a frame: its source pixels, their `palette` indices.
    pub fn add(
        &mut self,
        pixels: Vec<u32>,
        indices: &[u8],
        palette: &Palette,
    ) -> Result<(), String> {
        let (w, h) = (self.width as usize, self.height as usize);
        if indices.len() != w * h || pixels.len() != w * h {
            return Err(format!(
                "GIF frame has {} pixels, expected {}",
                indices.len(),
                w * h
            ));
        }
        let rect = match &self.previous {
            None => [0, 0, w, h],
            Some(prev) => changed_rect(prev, &pixels, w, h),
        };
        let [x0, y0, x1, y1] = rect;
        let mut sub = Vec::with_capacity((x1 - x0) * (y1 - y0));
        for y in y0..y1 {
            sub.extend_from_slice(&indices[y * w + x0..y * w + x1]);
        }
        let frame = gif::Frame {
            delay: self.delay,
            dispose: gif::DisposalMethod::Keep,
            left: x0 as u16,
            top: y0 as u16,
            width: (x1 - x0) as u16,
            height: (y1 - y0) as u16,
            palette: Some(palette.to_rgb_bytes()),
            buffer: std::borrow::Cow::Owned(sub),
            ..gif::Frame::default()
        };
        self.encoder
            .write_frame(&frame)
            .map_err(|e| format!("{}: {e}", self.path.display()))?;
        self.previous = Some(pixels);
        Ok(())
    }

    /// Writes the trailer, flushes the file to disk and moves it into
    /// place; on failure the old file stays and the temporary one goes.
    pub fn finish(self) -> Result<(), String> {
        let GifWriter {
            encoder, tmp, path, ..
        } = self;
        let file: Result<File, String> = encoder
            .into_inner()
            .map_err(|e| e.to_string())
            .and_then(|w| w.into_inner().map_err(|e| e.error().to_string()));
        file.and_then(|f| tmp.commit(f).map_err(|e| e.to_string()))
            .map_err(|e| format!("{}: {e}", path.display()))
    }
}

/// The smallest rectangle `[x0, y0, x1, y1)` holding every pixel that
/// differs; 1×1 at the origin when nothing does (a GIF frame cannot be empty).
fn changed_rect<T: PartialEq>(prev: &[T], cur: &[T], w: usize, h: usize) -> [usize; 4] {
    let row_differs = |y: usize| prev[y * w..(y + 1) * w] != cur[y * w..(y + 1) * w];
    let Some(y0) = (0..h).find(|&y| row_differs(y)) else {
        return [0, 0, 1, 1];
    };
    let y1 = (0..h).rev().find(|&y| row_differs(y)).map_or(h, |y| y + 1);
    let col_differs = |x: usize| (y0..y1).any(|y| prev[y * w + x] != cur[y * w + x]);
    let x0 = (0..w).find(|&x| col_differs(x)).unwrap_or(0);
    let x1 = (0..w).rev().find(|&x| col_differs(x)).map_or(w, |x| x + 1);
    [x0, y0, x1, y1]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn delays_round_to_hundredths() {
        assert_eq!(delay_centiseconds(0.04), 4);
        assert_eq!(delay_centiseconds(1.0 / 24.0), 4);
        assert_eq!(delay_centiseconds(1.0 / 30.0), 3);
        assert_eq!(delay_centiseconds(0.001), 1);
        assert_eq!(delay_centiseconds(1e9), u16::MAX);
    }

    #[test]
    fn changed_rect_is_tight() {
        let w = 5;
        let prev = vec![0u8; 20];
        let mut cur = prev.clone();
        assert_eq!(changed_rect(&prev, &cur, w, 4), [0, 0, 1, 1]);
        cur[w + 1] = 1; // (1,1)
        cur[2 * w + 3] = 1; // (3,2)
        assert_eq!(changed_rect(&prev, &cur, w, 4), [1, 1, 4, 3]);
    }

    #[test]
    fn writes_a_gif_that_decodes_to_the_frames() {
        use image::AnimationDecoder;
        let dir = std::env::temp_dir().join(format!("animed-gif-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("t.gif");
        let pal = Palette {
            colours: vec![[0, 0, 0], [255, 0, 0], [0, 0, 255]],
        };
        let mut g = GifWriter::create(&path, 4, 3, 5).unwrap();
        let f0 = vec![0u8; 12];
        let mut f1 = f0.clone();
        f1[5] = 1;
        let mut f2 = f1.clone();
        f2[11] = 2;
        let colours = |f: &[u8]| -> Vec<u32> { f.iter().map(|&i| i as u32).collect() };
        for f in [&f0, &f1, &f2, &f2] {
            g.add(colours(f), f, &pal).unwrap();
        }
        g.finish().unwrap();
        let names: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.contains("t.gif"))
            .collect();
        assert_eq!(names, ["t.gif"], "no temporary file is left");
        let dec = image::codecs::gif::GifDecoder::new(std::io::BufReader::new(
            File::open(&path).unwrap(),
        ))
        .unwrap();
        let frames = dec.into_frames().collect_frames().unwrap();
        assert_eq!(frames.len(), 4);
        for (fr, want) in frames.iter().zip([&f0, &f1, &f2, &f2]) {
            let (n, d) = fr.delay().numer_denom_ms();
            assert_eq!(n / d, 50);
            let got: Vec<u8> = fr
                .buffer()
                .pixels()
                .map(|p| {
                    let c = [p[0], p[1], p[2]];
                    pal.colours.iter().position(|&q| q == c).unwrap() as u8
                })
                .collect();
            assert_eq!(&got, want);
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn rejects_sizes_a_gif_cannot_hold() {
        let p = std::env::temp_dir().join("animed-never.gif");
        let e = GifWriter::create(&p, 70000, 10, 4).err().unwrap();
        assert!(e.contains("1..=65535"), "{e}");
    }
}
