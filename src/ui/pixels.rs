//! The one place where the renderer's `0x00RRGGBB` pixels meet tiny-skia's
//! premultiplied RGBA bytes.
//!
//! The overlay is always drawn onto an *opaque* copy of the frame, so
//! premultiplied and straight colour coincide (alpha = 255) and the
//! conversion is a byte shuffle, exact in both directions.

use tiny_skia::Pixmap;

/// Which way [`convert`] copies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    FrameToPixmap,
    PixmapToFrame,
}

/// Copies between a frame's colour buffer and an equally sized pixmap.
/// Pixels of `color` are `0x00RRGGBB`; the pixmap holds opaque RGBA.
pub fn convert(color: &mut [u32], pixmap: &mut Pixmap, dir: Direction) {
    let data = pixmap.data_mut();
    debug_assert_eq!(data.len(), color.len() * 4);
    match dir {
        // As whole little-endian words (`0xAABBGGRR` is the bytes R, G,
        // B, A) over four-byte arrays: a byte swap and a shift per pixel,
        // which the compiler turns into a few lane operations for many
        // pixels at once (byte by byte over slices it did not).
        Direction::FrameToPixmap => {
            for (px, c) in data.as_chunks_mut::<4>().0.iter_mut().zip(color.iter()) {
                *px = (c.swap_bytes() >> 8 | 0xFF00_0000).to_le_bytes();
            }
        }
        Direction::PixmapToFrame => {
            for (px, c) in data.as_chunks::<4>().0.iter().zip(color.iter_mut()) {
                *c = (u32::from_le_bytes(*px) & 0x00FF_FFFF).swap_bytes() >> 8;
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
}
