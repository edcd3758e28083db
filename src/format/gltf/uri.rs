//! glTF URIs (spec §3.1.5): `data:` URIs with base64 payloads, and
//! relative references to files beside the `.gltf`, percent-decoded.
//! Absolute paths and other schemes are refused: a model file must not
//! make animed read arbitrary files or the network.

use std::path::{Path, PathBuf};

/// The bytes a URI names. `read_file` does the bounded file read.
pub fn resolve(
    uri: &str,
    base: &Path,
    read_file: &dyn Fn(&Path) -> Result<Vec<u8>, String>,
) -> Result<Vec<u8>, String> {
    if let Some(rest) = uri.strip_prefix("data:") {
        let (meta, payload) = rest
            .split_once(',')
            .ok_or("a data: URI without a comma before its payload")?;
        if !meta.ends_with(";base64") {
            return Err("only base64 data: URIs are supported".into());
        }
        return base64_decode(payload);
    }
    let path = file_path(uri, base)?;
    read_file(&path).map_err(|e| format!("{}: {e}", path.display()))
}

/// The file a relative URI names, resolved against `base`.
pub fn file_path(uri: &str, base: &Path) -> Result<PathBuf, String> {
    if uri.contains("://") || uri.starts_with('/') || uri.starts_with('\\') {
        return Err(format!(
            "`{uri}` is not a relative file reference (only files beside the .gltf and data: URIs are read)"
        ));
    }
    let decoded = percent_decode(uri)?;
    let rel = Path::new(&decoded);
    if rel.is_absolute() || rel.has_root() {
        return Err(format!("`{uri}` is an absolute path"));
    }
    Ok(base.join(rel))
}

/// `%20` → space etc.; invalid escapes or non-UTF-8 results are errors.
pub fn percent_decode(s: &str) -> Result<String, String> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' {
            let hex = b
                .get(i + 1..i + 3)
                .and_then(|h| std::str::from_utf8(h).ok())
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or_else(|| format!("`{s}` has a bad %-escape"))?;
            out.push(hex);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| format!("`{s}` does not decode to UTF-8"))
}

fn sextet(c: u8) -> Option<u32> {
    Some(match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' | b'-' => 62,
        b'/' | b'_' => 63,
        _ => return None,
    } as u32)
}

/// Standard base64 (RFC 4648 §4; the URL-safe letters are accepted too),
/// padding optional, ASCII whitespace ignored.
pub fn base64_decode(s: &str) -> Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(s.len() / 4 * 3 + 3);
    let mut acc = 0u32;
    let mut bits = 0u32;
    let mut padding = false;
    for &c in s.as_bytes() {
        if c == b'=' {
            padding = true;
            continue;
        }
        if c.is_ascii_whitespace() {
            continue;
        }
        if padding {
            return Err("base64 data continues after its padding".into());
        }
        let v = sextet(c).ok_or_else(|| {
            format!(
                "base64 data has the character {:?}",
                char::from(c).escape_default().to_string()
            )
        })?;
        acc = (acc << 6) | v;
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    Ok(out)
}

/// Standard base64 with padding, for the writer's data: URIs.
pub fn base64_encode(data: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::with_capacity(data.len().div_ceil(3) * 4);
    for c in data.chunks(3) {
        let n = (c[0] as u32) << 16
            | (*c.get(1).unwrap_or(&0) as u32) << 8
            | *c.get(2).unwrap_or(&0) as u32;
        for i in 0..4 {
            if i <= c.len() {
                s.push(A[(n >> (18 - 6 * i) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_round_trips_and_matches_rfc4648() {
        // RFC 4648 §10 test vectors.
        for (plain, enc) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64_encode(plain.as_bytes()), enc);
            assert_eq!(base64_decode(enc).unwrap(), plain.as_bytes());
        }
        let all: Vec<u8> = (0..=255).collect();
        assert_eq!(base64_decode(&base64_encode(&all)).unwrap(), all);
        assert!(base64_decode("Zm9v!").is_err());
        assert!(base64_decode("Zg==Zg").is_err());
    }

    #[test]
    fn uris_resolve_beside_the_file_only() {
        let base = Path::new("/models");
        assert_eq!(
            file_path("my%20mesh.bin", base).unwrap(),
            Path::new("/models/my mesh.bin")
        );
        assert!(file_path("/etc/passwd", base).is_err());
        assert!(file_path("http://x/y.bin", base).is_err());
        assert!(file_path("a%zz.bin", base).is_err());
        let read = |_: &Path| -> Result<Vec<u8>, String> { Err("never".into()) };
        assert_eq!(
            resolve("data:application/octet-stream;base64,AAEC", base, &read).unwrap(),
            vec![0, 1, 2]
        );
        assert!(resolve("data:text/plain,abc", base, &read).is_err());
    }
}
