//! The glTF reader on arbitrary bytes: as a .glb (the first input byte
//! even) or as .gltf JSON; loads or fails with a message, never panics.
//! External references cannot be read (there is no file beside the input).
#![no_main]
mod harness;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    match data.split_first() {
        Some((b, rest)) if b % 2 == 0 => {
            // A valid GLB header around the rest, so the chunks get fuzzed.
            let len = ((rest.len() + 12) as u32).to_le_bytes();
            let header = [&b"glTF\x02\0\0\0"[..], &len[..]].concat();
            harness::load_or_named_error(&harness::wrapped(&header, rest, b""), "fuzz.glb");
        }
        Some((_, rest)) => harness::load_or_named_error(rest, "fuzz.gltf"),
        None => harness::load_or_named_error(data, "fuzz.gltf"),
    }
});
