//! The command line: one file per subcommand, each with its `Args` and `run`.

pub mod bench;
pub mod check;
pub mod clip_arg;
pub mod convert;
pub mod edit;
pub mod info;
pub mod key;
pub mod render;
pub mod sample;
pub mod view;

use clap::{Parser, Subcommand};

/// animed — keyframe animation editor and viewer for 3D scenes, no GPU needed.
#[derive(Parser, Debug)]
#[command(name = "animed", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render a scene (or the bundled demo) to PNG, a PNG sequence or a GIF.
    Render(render::Args),
    /// Measure renderer, animation and editor speed on this machine.
    Bench(bench::Args),
    /// Open the editor (the default with no subcommand).
    Edit(edit::Args),
    /// Play a file's animation in a window.
    View(view::Args),
    /// Convert between .iv, .wrl, .wrl.gz (and from .obj), keeping every key.
    Convert(convert::Args),
    /// Describe a scene file: nodes, shapes, lights, cameras, tracks, warnings.
    Info(info::Args),
    /// Print the value of an animated property at given times.
    Sample(sample::Args),
    /// Set, remove and list keys from the command line.
    Key(key::Args),
    /// Screenshot tests: render scenes and compare them with golden PNGs.
    Check(check::Args),
}

/// Runs the CLI; returns the process exit code.
pub fn run() -> i32 {
    let cli = Cli::parse();
    match cli.command {
        None => edit::run_default(),
        Some(Command::Render(a)) => render::run(a),
        Some(Command::Bench(a)) => bench::run(a),
        Some(Command::Edit(a)) => edit::run(a),
        Some(Command::View(a)) => view::run(a),
        Some(Command::Convert(a)) => convert::run(a),
        Some(Command::Info(a)) => info::run(a),
        Some(Command::Sample(a)) => sample::run(a),
        Some(Command::Key(a)) => key::run(a),
        Some(Command::Check(a)) => check::run_cli(a),
    }
}
