//! SGI image files (`.rgb`, `.rgba`, `.bw`, `.sgi`, `.int`, `.inta`): the
//! texture format of Open Inventor's own data sets. No maintained crate
//! reads it, and it is small, so it is decoded here from the format's
//! description (Paul Haeberli, "The SGI Image File Format", version 1.00,
//! Silicon Graphics, 1988):
//!
//! * a 512-byte big-endian header: magic 474, storage (0 verbatim, 1 RLE),
//!   bytes per channel (1 or 2), dimension (1–3), x/y/z sizes, pixmin,
//!   pixmax, name, colormap id (0 = normal pixels; others are obsolete);
//! * channel planes one after another, each a stack of scanlines from the
//!   bottom row up;
//! * RLE: a table of scanline offsets and one of lengths (y·z entries each,
//!   channel-major), then packets: a count byte (low 7 bits; 0 ends the
//!   line) whose high bit says "copy the next `count` values" when set and
//!   "repeat the next value `count` times" when clear.
//!
//! Every offset and count is checked against the file before it is used,
//! and the image size against the caller's pixel budget before anything is
//! allocated, so a hostile header costs nothing.

/// A decoded SGI image: rows top to bottom (as the `image` crate returns
/// them), 4 bytes per pixel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SgiImage {
    pub width: u32,
    pub height: u32,
    /// Channels in the file (1 grey, 2 grey+alpha, 3 RGB, 4 RGBA); extra
    /// channels beyond four are ignored.
    pub components: u8,
    /// RGBA8, `width * height * 4` bytes. Grey is copied to R, G and B;
    /// alpha is 255 where the file has none.
    pub rgba: Vec<u8>,
}

const MAGIC: u16 = 474;
const HEADER: usize = 512;

/// True when `bytes` start like an SGI image (magic number 474).
pub fn is_sgi(bytes: &[u8]) -> bool {
    bytes.len() >= 2 && u16::from_be_bytes([bytes[0], bytes[1]]) == MAGIC
}

/// Decodes an SGI image. `max_pixels` bounds `width * height` before any
/// allocation; a larger image is an error naming the size.
pub fn decode(bytes: &[u8], max_pixels: u64) -> Result<SgiImage, String> {
    if bytes.len() < HEADER {
        return Err(format!(
            "SGI image: {} bytes, shorter than its 512-byte header",
            bytes.len()
        ));
    }
    if !is_sgi(bytes) {
        return Err("not an SGI image (magic number is not 474)".into());
    }
    let u16_at = |o: usize| u16::from_be_bytes([bytes[o], bytes[o + 1]]);
    let storage = bytes[2];
    let bpc = bytes[3] as usize;
    let dimension = u16_at(4);
    let (xs, ys, zs) = (u16_at(6) as usize, u16_at(8) as usize, u16_at(10) as usize);
    let colormap = u32::from_be_bytes([bytes[104], bytes[105], bytes[106], bytes[107]]);
    if storage > 1 {
        return Err(format!(
            "SGI image: unknown storage {storage} (0 verbatim, 1 RLE)"
        ));
    }
    if bpc != 1 && bpc != 2 {
        return Err(format!(
            "SGI image: {bpc} bytes per channel (1 or 2 allowed)"
        ));
    }
    if colormap != 0 {
        return Err(format!(
            "SGI image: colormap type {colormap} is not supported (only normal pixels)"
        ));
    }
    // Dimension 1 is one row of one channel, 2 one channel, 3 zsize channels.
    let (ys, zs) = match dimension {
        1 => (1, 1),
        2 => (ys, 1),
        3 => (ys, zs),
        d => return Err(format!("SGI image: dimension {d} (1, 2 or 3 allowed)")),
    };
    if xs == 0 || ys == 0 || zs == 0 {
        return Err(format!("SGI image: empty ({xs}x{ys}, {zs} channels)"));
    }
    let pixels = xs as u64 * ys as u64;
    if pixels > max_pixels {
        return Err(format!(
            "SGI image: {xs}x{ys} is {pixels} pixels, over the limit of {max_pixels}"
        ));
    }
    let channels = zs.min(4);
    let mut planes = vec![0u8; xs * ys * channels];
    let mut line = vec![0u16; xs];
    for z in 0..channels {
        for y in 0..ys {
            if storage == 0 {
                verbatim_line(bytes, bpc, xs, ys, z, y, &mut line)?;
            } else {
                rle_line(bytes, bpc, ys, zs, z, y, &mut line)?;
            }
            let plane = &mut planes[(z * ys + y) * xs..][..xs];
            for (dst, &v) in plane.iter_mut().zip(&line) {
                // Two-byte channels keep their high byte: 0..65535 → 0..255.
                *dst = if bpc == 2 { (v >> 8) as u8 } else { v as u8 };
            }
        }
    }
    let mut rgba = vec![0u8; xs * ys * 4];
    for y in 0..ys {
        // The file stores the bottom row first; callers want the top first.
        let row = ys - 1 - y;
        for x in 0..xs {
            let at = |z: usize| planes[(z * ys + y) * xs + x];
            let px = match channels {
                1 => [at(0), at(0), at(0), 255],
                2 => [at(0), at(0), at(0), at(1)],
                3 => [at(0), at(1), at(2), 255],
                _ => [at(0), at(1), at(2), at(3)],
            };
            rgba[(row * xs + x) * 4..][..4].copy_from_slice(&px);
        }
    }
    Ok(SgiImage {
        width: xs as u32,
        height: ys as u32,
        components: channels as u8,
        rgba,
    })
}

fn value(bytes: &[u8], at: usize, bpc: usize) -> Option<u16> {
    if bpc == 1 {
        bytes.get(at).map(|&b| b as u16)
    } else {
        Some(u16::from_be_bytes([*bytes.get(at)?, *bytes.get(at + 1)?]))
    }
}

fn verbatim_line(
    bytes: &[u8],
    bpc: usize,
    xs: usize,
    ys: usize,
    z: usize,
    y: usize,
    line: &mut [u16],
) -> Result<(), String> {
    let start = HEADER + ((z * ys + y) * xs) * bpc;
    for (x, v) in line.iter_mut().enumerate() {
        *v = value(bytes, start + x * bpc, bpc).ok_or_else(|| {
            format!(
                "SGI image: truncated: channel {z} row {y} needs {} bytes, the file has {}",
                start + xs * bpc,
                bytes.len()
            )
        })?;
    }
    Ok(())
}

fn rle_line(
    bytes: &[u8],
    bpc: usize,
    ys: usize,
    zs: usize,
    z: usize,
    y: usize,
    line: &mut [u16],
) -> Result<(), String> {
    let entry = z * ys + y;
    let table = |t: usize| -> Result<usize, String> {
        let o = HEADER + (t * ys * zs + entry) * 4;
        bytes
            .get(o..o + 4)
            .map(|b| u32::from_be_bytes([b[0], b[1], b[2], b[3]]) as usize)
            .ok_or_else(|| "SGI image: truncated RLE offset table".to_string())
    };
    let (start, len) = (table(0)?, table(1)?);
    let end = start
        .checked_add(len)
        .filter(|&e| e <= bytes.len())
        .ok_or_else(|| format!("SGI image: RLE row {y} of channel {z} lies outside the file"))?;
    let run = &bytes[start..end];
    let bad = || format!("SGI image: corrupt RLE data in row {y} of channel {z}");
    let (mut i, mut x) = (0usize, 0usize);
    loop {
        let head = value(run, i, bpc).ok_or_else(bad)?;
        i += bpc;
        let count = (head & 0x7f) as usize;
        if count == 0 {
            break;
        }
        if x + count > line.len() {
            return Err(bad());
        }
        if head & 0x80 != 0 {
            for v in &mut line[x..x + count] {
                *v = value(run, i, bpc).ok_or_else(bad)?;
                i += bpc;
            }
        } else {
            let v = value(run, i, bpc).ok_or_else(bad)?;
            i += bpc;
            line[x..x + count].fill(v);
        }
        x += count;
    }
    // A short row leaves the rest of the line as the previous row had it:
    // clear it so the output never depends on an earlier row.
    line[x..].fill(0);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header(storage: u8, bpc: u8, dim: u16, x: u16, y: u16, z: u16) -> Vec<u8> {
        let mut h = vec![0u8; HEADER];
        h[0..2].copy_from_slice(&MAGIC.to_be_bytes());
        h[2] = storage;
        h[3] = bpc;
        h[4..6].copy_from_slice(&dim.to_be_bytes());
        h[6..8].copy_from_slice(&x.to_be_bytes());
        h[8..10].copy_from_slice(&y.to_be_bytes());
        h[10..12].copy_from_slice(&z.to_be_bytes());
        h
    }

    #[test]
    fn verbatim_rgb_rows_come_out_top_first() {
        // 2x2 RGB; file rows bottom-up: bottom row red, green; top row blue, white.
        let mut f = header(0, 1, 3, 2, 2, 3);
        let r = [255, 0, 0, 255];
        let g = [0, 255, 0, 255];
        let b = [0, 0, 255, 255];
        for plane in [r, g, b] {
            f.extend_from_slice(&plane);
        }
        let img = decode(&f, 1 << 20).unwrap();
        assert_eq!((img.width, img.height, img.components), (2, 2, 3));
        #[rustfmt::skip]
        let want = [0, 0, 255, 255,  255, 255, 255, 255,   // top: blue, white
                    255, 0, 0, 255,  0, 255, 0, 255]; // bottom: red, green
        assert_eq!(img.rgba, want);
    }

    #[test]
    fn rle_grey_alpha_with_runs_and_copies() {
        // 4x1, two channels. Grey: run of 3 x 10, then copy [200]. Alpha: copy 4.
        let grey = [0x03u8, 10, 0x81, 200, 0x00];
        let alpha = [0x84u8, 1, 2, 3, 4, 0x00];
        let mut f = header(1, 1, 3, 4, 1, 2);
        let data0 = HEADER + 2 * 2 * 4;
        let starts = [data0 as u32, (data0 + grey.len()) as u32];
        let lens = [grey.len() as u32, alpha.len() as u32];
        for v in starts.iter().chain(&lens) {
            f.extend_from_slice(&v.to_be_bytes());
        }
        f.extend_from_slice(&grey);
        f.extend_from_slice(&alpha);
        let img = decode(&f, 100).unwrap();
        assert_eq!(img.components, 2);
        assert_eq!(
            img.rgba,
            [10, 10, 10, 1, 10, 10, 10, 2, 10, 10, 10, 3, 200, 200, 200, 4]
        );
    }

    #[test]
    fn two_bytes_per_channel_keep_the_high_byte() {
        let mut f = header(0, 2, 2, 1, 1, 1);
        f.extend_from_slice(&0xABCDu16.to_be_bytes());
        let img = decode(&f, 1).unwrap();
        assert_eq!(img.rgba, [0xAB, 0xAB, 0xAB, 255]);
    }

    #[test]
    fn hostile_headers_are_errors_without_allocation() {
        // 65535 x 65535 x 4 would be 17 GB: refused by the budget first.
        let f = header(0, 1, 3, 65535, 65535, 4);
        let e = decode(&f, 16384 * 16384).unwrap_err();
        assert!(e.contains("over the limit"), "{e}");
        // Truncated verbatim data.
        let mut f = header(0, 1, 3, 4, 4, 3);
        f.extend_from_slice(&[1, 2, 3]);
        assert!(decode(&f, 100).unwrap_err().contains("truncated"));
        // RLE offsets pointing outside the file.
        let mut f = header(1, 1, 2, 4, 1, 1);
        f.extend_from_slice(&9999u32.to_be_bytes());
        f.extend_from_slice(&5u32.to_be_bytes());
        assert!(decode(&f, 100).unwrap_err().contains("outside the file"));
        // A run longer than the row.
        let mut f = header(1, 1, 2, 2, 1, 1);
        let d = (HEADER + 8) as u32;
        f.extend_from_slice(&d.to_be_bytes());
        f.extend_from_slice(&3u32.to_be_bytes());
        f.extend_from_slice(&[0x05, 7, 0]);
        assert!(decode(&f, 100).unwrap_err().contains("corrupt RLE"));
        // Short file, wrong magic, bad fields.
        assert!(decode(&[1, 218], 10).is_err());
        assert!(decode(&[0u8; 600], 10).unwrap_err().contains("magic"));
        assert!(decode(&header(2, 1, 3, 1, 1, 1), 10).is_err());
        assert!(decode(&header(0, 3, 3, 1, 1, 1), 10).is_err());
        assert!(decode(&header(0, 1, 7, 1, 1, 1), 10).is_err());
        assert!(decode(&header(0, 1, 3, 0, 1, 1), 10).is_err());
    }

    #[test]
    fn decodes_every_prefix_of_a_valid_file_without_panicking() {
        let mut f = header(0, 1, 3, 3, 2, 4);
        f.extend((0..24).map(|i| i as u8 * 10));
        assert!(decode(&f, 100).is_ok());
        for n in 0..f.len() {
            assert!(decode(&f[..n], 100).is_err());
        }
    }

    #[test]
    fn brick_matches_imagemagick_pixel_for_pixel() {
        // brick.rgb: an RLE RGB texture from SGI's Inventor data set;
        // brick_imagemagick.png: the same file converted by ImageMagick
        // (`convert brick.rgb -depth 8 PNG32:brick_imagemagick.png`), an
        // independent decoder.
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/textures");
        let ours = decode(&std::fs::read(dir.join("brick.rgb")).unwrap(), 1 << 20).unwrap();
        let theirs = image::open(dir.join("brick_imagemagick.png"))
            .unwrap()
            .to_rgba8();
        assert_eq!((ours.width, ours.height, ours.components), (128, 128, 3));
        assert_eq!(ours.rgba, theirs.into_raw());
    }
}
