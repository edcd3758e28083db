//! The glTF reader on arbitrary bytes: as a .glb (the first input byte
//! even) or as .gltf JSON; loads or fails with a message, never panics.
//! External references cannot be read (there is no file beside the input).
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let (name, body) = match data.split_first() {
        Some((b, rest)) if b % 2 == 0 => {
            // A valid GLB header around the rest, so the chunks get fuzzed.
            let mut v = b"glTF\x02\0\0\0".to_vec();
            v.extend_from_slice(&((rest.len() + 12) as u32).to_le_bytes());
            v.extend_from_slice(rest);
            ("fuzz.glb", v)
        }
        Some((_, rest)) => ("fuzz.gltf", rest.to_vec()),
        None => ("fuzz.gltf", Vec::new()),
    };
    if let Err(e) = animed::internals::format::load_bytes(&body, Path::new(name)) {
        assert!(e.to_string().starts_with(name));
    }
});
