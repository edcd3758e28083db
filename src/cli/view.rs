//! `animed view`: play a file's animation in a window.

/// Play a file's animation in a window.
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed view: not built yet");
    2
}
