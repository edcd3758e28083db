//! The Inventor / VRML 1.0 reader on arbitrary bodies (the first input byte
//! picks the header).
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::path::Path;

/// The input budget, smaller than the defaults so that every run is quick
/// (the defaults' memory bound is checked by `tests/hostile.rs`); libFuzzer
/// itself caps memory too (`fuzz/run.sh`: -rss_limit_mb / -malloc_limit_mb).
fn limits() -> animed::internals::format::limits::Limits {
    animed::internals::format::limits::Limits {
        max_bytes: 4 << 20,
        max_nodes: 100_000,
        max_depth: 256,
        max_geometry: 1_000_000,
        max_numbers: 1_000_000,
    }
}

fuzz_target!(|data: &[u8]| {
    let (header, body): (&[u8], &[u8]) = match data.split_first() {
        Some((b, rest)) if b % 2 == 0 => (b"#Inventor V2.1 ascii\n", rest),
        Some((_, rest)) => (b"#VRML V1.0 ascii\n", rest),
        None => (b"#Inventor V2.1 ascii\n", data),
    };
    let mut src = header.to_vec();
    src.extend_from_slice(body);
    if let Err(e) = animed::internals::format::load_bytes_with(&src, Path::new("fuzz.iv"), limits()) {
        assert!(e.to_string().starts_with("fuzz.iv:"));
    }
});
