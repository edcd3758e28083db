//! The Inventor / VRML 1.0 readers on arbitrary bodies: the first input byte
//! picks the header — ASCII Inventor, VRML 1.0, or binary Inventor (whose
//! reader walks counts and offsets, the likeliest place for a bad bound).
#![no_main]
mod harness;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // Binary headers are padded to a word boundary, as Coin writes them.
    let (header, body): (&[u8], &[u8]) = match data.split_first() {
        Some((b, rest)) if b % 4 == 0 => (b"#Inventor V2.1 ascii\n", rest),
        Some((b, rest)) if b % 4 == 1 => (b"#VRML V1.0 ascii\n", rest),
        Some((b, rest)) if b % 4 == 2 => (b"#Inventor V2.0 binary  \n", rest),
        Some((_, rest)) => (b"#Inventor V2.1 binary  \n", rest),
        None => (b"#Inventor V2.1 ascii\n", data),
    };
    harness::load_or_named_error(&harness::wrapped(header, body, b""), "fuzz.iv");
});
