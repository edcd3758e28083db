//! The X3D classic-encoding reader on arbitrary bodies: loads or fails with
//! a message.
#![no_main]
mod harness;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    harness::load_or_named_error(
        &harness::wrapped(b"#X3D V4.0 utf8\n", data, b""),
        "fuzz.x3dv",
    );
});
