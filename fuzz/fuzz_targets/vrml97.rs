//! The VRML97 reader on arbitrary bodies: loads or fails with a message.
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let mut src = b"#VRML V2.0 utf8\n".to_vec();
    src.extend_from_slice(data);
    if let Err(e) = animed::format::load_bytes(&src, Path::new("fuzz.wrl")) {
        assert!(e.to_string().starts_with("fuzz.wrl:"));
    }
});
