//! What every reader target shares: a small input budget, and the one rule
//! that a failed load names the file it was given.

use std::path::Path;

/// The input budget, smaller than the defaults so that every run is quick
/// (the defaults' memory bound is checked by `tests/hostile.rs`); libFuzzer
/// itself caps memory too (`fuzz/run.sh`: -rss_limit_mb / -malloc_limit_mb).
pub fn limits() -> animed::internals::format::limits::Limits {
    animed::internals::format::limits::Limits {
        max_bytes: 4 << 20,
        max_nodes: 100_000,
        max_depth: 256,
        max_geometry: 1_000_000,
        max_numbers: 1_000_000,
    }
}

/// Loads `src` as if read from `name`: it loads, or fails with a message
/// that starts with the file's name (a position or JSON pointer follows).
pub fn load_or_named_error(src: &[u8], name: &str) {
    if let Err(e) = animed::internals::format::load_bytes_with(src, Path::new(name), limits()) {
        assert!(e.to_string().starts_with(name), "{e}");
    }
}

/// `body` after `header` (and before `footer`), as one file.
pub fn wrapped(header: &[u8], body: &[u8], footer: &[u8]) -> Vec<u8> {
    let mut v = Vec::with_capacity(header.len() + body.len() + footer.len());
    v.extend_from_slice(header);
    v.extend_from_slice(body);
    v.extend_from_slice(footer);
    v
}
