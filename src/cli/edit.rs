//! `animed edit`: open the editor (the default with no subcommand).

/// Open the editor (the default with no subcommand).
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed edit: not built yet");
    2
}

/// `animed` with no arguments: the editor on the bundled demo scene.
pub fn run_default() -> i32 {
    eprintln!("animed: the editor is not built yet; `animed render` renders the demo scene");
    2
}
