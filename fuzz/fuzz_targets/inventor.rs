//! The Inventor / VRML 1.0 reader on arbitrary bodies (the first input byte
//! picks the header).
#![no_main]
mod harness;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let (header, body): (&[u8], &[u8]) = match data.split_first() {
        Some((b, rest)) if b % 2 == 0 => (b"#Inventor V2.1 ascii\n", rest),
        Some((_, rest)) => (b"#VRML V1.0 ascii\n", rest),
        None => (b"#Inventor V2.1 ascii\n", data),
    };
    harness::load_or_named_error(&harness::wrapped(header, body, b""), "fuzz.iv");
});
