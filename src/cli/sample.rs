//! `animed sample`: print the value of an animated property at given times.

/// Print the value of an animated property at given times.
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed sample: not built yet");
    2
}
