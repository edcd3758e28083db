//! The one place where the renderer's `0x00RRGGBB` pixels meet tiny-skia's
//! premultiplied RGBA bytes.
//!
//! The overlay is always drawn onto an *opaque* copy of the frame, so
//! premultiplied and straight colour coincide (alpha = 255) and the
//! conversion is a byte shuffle, exact in both directions.

use rayon::prelude::*;
use tiny_skia::Pixmap;

/// Which way [`convert`] copies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    FrameToPixmap,
    PixmapToFrame,
}

/// Copies between a frame's colour buffer and an equally sized pixmap.
/// Pixels of `color` are `0x00RRGGBB`; the pixmap holds opaque RGBA.
/// Two of these run every editor frame over the whole window, so whole
/// pixels move as words (R and B swapped by shifts), which the compiler
/// vectorises, in chunks shared by the threads; a pixmap whose bytes are
/// not word-aligned (never seen: tiny-skia itself views them as pixels)
/// goes byte by byte.
pub fn convert(color: &mut [u32], pixmap: &mut Pixmap, dir: Direction) {
    let data = pixmap.data_mut();
    debug_assert_eq!(data.len(), color.len() * 4);
    match bytemuck::try_cast_slice_mut::<u8, u32>(data) {
        Ok(words) => {
            let chunks = words.par_chunks_mut(CHUNK).zip(color.par_chunks_mut(CHUNK));
            match dir {
                Direction::FrameToPixmap => chunks.for_each(|(words, color)| {
                    for (w, &c) in words.iter_mut().zip(color.iter()) {
                        *w = u32::to_le(swap(c) | 0xff00_0000);
                    }
                }),
                Direction::PixmapToFrame => chunks.for_each(|(words, color)| {
                    for (&w, c) in words.iter().zip(color.iter_mut()) {
                        *c = swap(u32::from_le(w)) & 0x00ff_ffff;
                    }
                }),
            }
        }
        Err(_) => by_bytes(color, data, dir),
    }
}

/// [`convert`] from the frame to the pixmap, except in rectangle `r`
/// (x, y, w, h, inside the frame's `width` columns), whose pixels
/// `row(y, out)` writes instead (row `y` of `r`, as `0x00RRGGBB`): the
/// editor's viewport goes from its layer straight into the pixmap,
/// rather than into the frame and then, converted, into the pixmap.
pub fn convert_with(
    color: &[u32],
    width: usize,
    pixmap: &mut Pixmap,
    (x0, y0, w, h): (usize, usize, usize, usize),
    row: impl Fn(usize, &mut [u32]) + Sync,
) {
    let data = pixmap.data_mut();
    debug_assert_eq!(data.len(), color.len() * 4);
    let Ok(words) = bytemuck::try_cast_slice_mut::<u8, u32>(data) else {
        let mut color = color.to_vec();
        for (y, r) in color.chunks_mut(width.max(1)).skip(y0).take(h).enumerate() {
            row(y, &mut r[x0..x0 + w]);
        }
        return by_bytes(&mut color, data, Direction::FrameToPixmap);
    };
    let to_pixmap = |out: &mut [u32], from: &[u32]| {
        for (o, &c) in out.iter_mut().zip(from) {
            *o = u32::to_le(swap(c) | 0xff00_0000);
        }
    };
    let rows = words
        .par_chunks_mut(width.max(1))
        .zip(color.par_chunks(width.max(1)));
    rows.enumerate().for_each(|(y, (out, from))| {
        if !(y0..y0 + h).contains(&y) {
            return to_pixmap(out, from);
        }
        let (left, rest) = out.split_at_mut(x0);
        let (mid, right) = rest.split_at_mut(w);
        to_pixmap(left, &from[..x0]);
        row(y - y0, mid);
        for o in mid.iter_mut() {
            *o = u32::to_le(swap(*o) | 0xff00_0000);
        }
        to_pixmap(right, &from[x0 + w..]);
    });
}

/// Pixels per chunk of [`convert`]: a few chunks per thread for a window,
/// each big enough that handing it to a thread costs next to nothing.
const CHUNK: usize = 1 << 16;

/// `0x00RRGGBB` <-> the little-endian word of the bytes [R, G, B, A],
/// `0xAABBGGRR`: the low and high colour bytes trade places both ways.
fn swap(c: u32) -> u32 {
    (c & 0xff00_ff00) | (c >> 16 & 0xff) | (c & 0xff) << 16
}

/// [`convert`] one byte at a time.
fn by_bytes(color: &mut [u32], data: &mut [u8], dir: Direction) {
    match dir {
        Direction::FrameToPixmap => {
            for (px, c) in data.chunks_exact_mut(4).zip(color.iter()) {
                px.copy_from_slice(&[(c >> 16) as u8, (c >> 8) as u8, *c as u8, 255]);
            }
        }
        Direction::PixmapToFrame => {
            for (px, c) in data.chunks_exact(4).zip(color.iter_mut()) {
                *c = ((px[0] as u32) << 16) | ((px[1] as u32) << 8) | px[2] as u32;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_exact() {
        let mut pm = Pixmap::new(3, 1).unwrap();
        let orig = vec![0x00123456, 0x00ff0001, 0x00000000];
        let mut c = orig.clone();
        convert(&mut c, &mut pm, Direction::FrameToPixmap);
        assert_eq!(&pm.data()[0..4], &[0x12, 0x34, 0x56, 255]);
        let mut back = vec![0u32; 3];
        convert(&mut back, &mut pm, Direction::PixmapToFrame);
        assert_eq!(back, orig);
    }

    #[test]
    fn words_and_bytes_agree() {
        let orig: Vec<u32> = (0..64u32)
            .map(|i| i.wrapping_mul(0x9e37_79b9) & 0xff_ffff)
            .collect();
        let mut pm = Pixmap::new(8, 8).unwrap();
        let mut c = orig.clone();
        convert(&mut c, &mut pm, Direction::FrameToPixmap);
        let mut bytes = vec![0u8; 256];
        by_bytes(&mut c, &mut bytes, Direction::FrameToPixmap);
        assert_eq!(pm.data(), &bytes[..]);
        let (mut a, mut b) = (vec![0u32; 64], vec![0u32; 64]);
        convert(&mut a, &mut pm, Direction::PixmapToFrame);
        by_bytes(&mut b, &mut bytes, Direction::PixmapToFrame);
        assert_eq!((&a, &b), (&orig, &orig));
    }

    #[test]
    fn a_rectangle_written_in_place_is_the_frame_with_it_copied_in() {
        let (w, h) = (37usize, 11usize);
        let frame: Vec<u32> = (0..(w * h) as u32)
            .map(|i| i.wrapping_mul(0x9e37_79b9) & 0xff_ffff)
            .collect();
        let inset: Vec<u32> = (0..(w * h) as u32)
            .map(|i| i.wrapping_mul(0x85eb_ca6b) & 0xff_ffff)
            .collect();
        for r in [(3, 2, 20, 7), (0, 0, w, h), (36, 10, 1, 1), (5, 4, 0, 3)] {
            let (x0, y0, rw, rh) = r;
            let mut copied = frame.clone();
            for y in 0..rh {
                let at = (y0 + y) * w + x0;
                copied[at..at + rw].copy_from_slice(&inset[y * w..y * w + rw]);
            }
            let mut want = Pixmap::new(w as u32, h as u32).unwrap();
            convert(&mut copied, &mut want, Direction::FrameToPixmap);
            let mut got = Pixmap::new(w as u32, h as u32).unwrap();
            convert_with(&frame, w, &mut got, r, |y, out| {
                out.copy_from_slice(&inset[y * w..y * w + out.len()]);
            });
            assert!(got.data() == want.data(), "{r:?}");
        }
    }
}
