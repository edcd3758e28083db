//! The X3D XML-encoding reader on arbitrary documents under an `<X3D>`
//! root: loads or fails with a message.
#![no_main]
mod harness;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let src = harness::wrapped(
        b"<?xml version='1.0'?>\n<X3D><Scene>",
        data,
        b"</Scene></X3D>",
    );
    harness::load_or_named_error(&src, "fuzz.x3d");
});
