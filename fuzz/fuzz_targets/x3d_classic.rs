//! The X3D classic-encoding reader on arbitrary bodies: loads or fails with
//! a message.
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::path::Path;

/// The input budget, smaller than the defaults so that every run is quick.
fn limits() -> animed::format::limits::Limits {
    animed::format::limits::Limits {
        max_bytes: 4 << 20,
        max_nodes: 100_000,
        max_depth: 256,
        max_geometry: 1_000_000,
        max_numbers: 1_000_000,
    }
}

fuzz_target!(|data: &[u8]| {
    let mut src = b"#X3D V4.0 utf8\n".to_vec();
    src.extend_from_slice(data);
    if let Err(e) = animed::format::load_bytes_with(&src, Path::new("fuzz.x3dv"), limits()) {
        assert!(e.to_string().starts_with("fuzz.x3dv:"));
    }
});
