//! Every byte string lexes to tokens or a positioned error, never a panic.
#![no_main]
use animed::internals::format::lexer::{read_header, Lexer, Tok};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let _ = read_header(data);
    let mut l = Lexer::new(data);
    for _ in 0..data.len() + 2 {
        match l.next_token() {
            Ok(t) if t.tok == Tok::Eof => break,
            Ok(_) => {}
            Err(e) => {
                assert!(e.pos.line >= 1 && e.pos.column >= 1);
                break;
            }
        }
    }
});
