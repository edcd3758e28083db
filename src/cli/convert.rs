//! `animed convert`: convert between .iv, .wrl, .wrl.gz (and from .obj), keeping every key.

/// Convert between .iv, .wrl, .wrl.gz (and from .obj), keeping every key.
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed convert: not built yet");
    2
}
