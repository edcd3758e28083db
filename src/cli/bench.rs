//! `animed bench`: measure renderer, animation and editor speed on this machine.

/// Measure renderer, animation and editor speed on this machine.
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed bench: not built yet");
    2
}
