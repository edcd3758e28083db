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
}
