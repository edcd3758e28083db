//! The command line: one file per subcommand, each with its `Args` and `run`.

use clap::{Parser, Subcommand};

/// animed — keyframe animation editor and viewer for 3D scenes, no GPU needed.
#[derive(Parser, Debug)]
#[command(name = "animed", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand, Debug)]
pub enum Command {}

/// Runs the CLI; returns the process exit code.
pub fn run() -> i32 {
    let cli = Cli::parse();
    match cli.command {
        None => {
            eprintln!("animed: the editor is not built yet; try `animed --help`");
            2
        }
    }
}
