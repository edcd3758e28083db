//! `animed render`: render a scene (or the bundled demo) to png, a png sequence or a gif.

/// Render a scene (or the bundled demo) to PNG, a PNG sequence or a GIF.
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed render: not built yet");
    2
}
