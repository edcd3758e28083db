//! Gzip detection by content (magic bytes 1f 8b) and bounded decompression.

use std::io::Read;

/// Largest decompressed size accepted (a gzip bomb stops here).
pub const MAX_DECOMPRESSED: u64 = 512 * 1024 * 1024;

pub fn is_gzip(bytes: &[u8]) -> bool {
    bytes.len() >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b
}

/// Decompresses a gzip stream (all members), failing past `limit` bytes.
pub fn decompress(bytes: &[u8], limit: u64) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    let mut dec = flate2::read::MultiGzDecoder::new(bytes).take(limit + 1);
    dec.read_to_end(&mut out)
        .map_err(|e| format!("gzip data is corrupt: {e}"))?;
    if out.len() as u64 > limit {
        return Err(format!(
            "decompressed file is larger than {} MiB",
            limit / (1024 * 1024)
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn gz(data: &[u8]) -> Vec<u8> {
        let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
        e.write_all(data).unwrap();
        e.finish().unwrap()
    }

    #[test]
    fn round_trip_and_detection() {
        let z = gz(b"#VRML V2.0 utf8\n");
        assert!(is_gzip(&z));
        assert!(!is_gzip(b"#VRML"));
        assert_eq!(decompress(&z, 100).unwrap(), b"#VRML V2.0 utf8\n");
    }

    #[test]
    fn size_limit_and_corruption_are_errors() {
        let z = gz(&[b' '; 10_000]);
        assert!(decompress(&z, 100).unwrap_err().contains("larger"));
        let mut bad = z.clone();
        let n = bad.len();
        bad[n - 6] ^= 0xff; // break the CRC
        assert!(decompress(&bad, 1 << 20).unwrap_err().contains("corrupt"));
    }
}
