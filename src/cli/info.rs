//! `animed info`: describe a scene file: nodes, shapes, lights, cameras, tracks, warnings.

/// Describe a scene file: nodes, shapes, lights, cameras, tracks, warnings.
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed info: not built yet");
    2
}
