//! Gzip detection by content (magic bytes 1f 8b) and bounded decompression.

use super::limits::{self, ReadError};

pub fn is_gzip(bytes: &[u8]) -> bool {
    bytes.len() >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b
}

/// Decompresses a gzip stream (all members); its output counts against the
/// running load's byte budget, so a gzip bomb stops there.
pub fn decompress(bytes: &[u8]) -> Result<Vec<u8>, String> {
    limits::read_all(flate2::read::MultiGzDecoder::new(bytes)).map_err(|e| match e {
        ReadError::Io(e) => format!("gzip data is corrupt: {e}"),
        e => format!("gzip output: {e}"),
    })
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
        assert_eq!(decompress(&z).unwrap(), b"#VRML V2.0 utf8\n");
    }

    #[test]
    fn size_limit_and_corruption_are_errors() {
        let z = gz(&[b' '; 10_000]);
        let small = limits::Limits {
            max_bytes: 100,
            ..Default::default()
        };
        let e = limits::scope_with(small, || decompress(&z).unwrap_err());
        assert!(
            e.contains("more than 100 bytes read") && e.contains("--max-bytes"),
            "{e}"
        );
        let mut bad = z.clone();
        let n = bad.len();
        bad[n - 6] ^= 0xff; // break the CRC
        assert!(decompress(&bad).unwrap_err().contains("corrupt"));
    }
}
