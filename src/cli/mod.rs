//! The command line: one file per subcommand, each with its `Args` and `run`.

pub mod bench;
pub mod check;
pub mod clip_arg;
pub mod convert;
pub mod edit;
pub mod info;
mod info_deform;
pub mod key;
mod pipe;
pub mod recover;
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
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// The input budget of every load (README "Input limits"); each flag
/// overrides its `ANIMED_MAX_*` environment variable. Counts take K/M/G
/// (×1000) or Ki/Mi/Gi (×1024) suffixes.
#[derive(clap::Args, Debug, Default)]
pub struct LimitArgs {
    /// Most bytes one load reads: files, inlines, gzip output [default 256Mi]
    #[arg(long, global = true, value_name = "N", value_parser = amount)]
    pub max_bytes: Option<u64>,
    /// Most nodes one load makes, PROTO and USE copies included [default 1M]
    #[arg(long, global = true, value_name = "N", value_parser = amount)]
    pub max_nodes: Option<u64>,
    /// Deepest nesting: syntax, PROTO expansion and Inline files together [default 256, at most 1024]
    #[arg(long, global = true, value_name = "N", value_parser = amount)]
    pub max_depth: Option<u64>,
    /// Most vertices + triangles one load generates, per instance [default 16M]
    #[arg(long, global = true, value_name = "N", value_parser = amount)]
    pub max_geometry: Option<u64>,
    /// Most numbers (and strings) in one load's field values [default 32M]
    #[arg(long, global = true, value_name = "N", value_parser = amount)]
    pub max_numbers: Option<u64>,
}

fn amount(s: &str) -> Result<u64, String> {
    crate::format::limits::parse_amount(s)
}

impl LimitArgs {
    /// The environment's limits with the flags given applied on top.
    pub fn resolve(&self) -> Result<crate::format::limits::Limits, String> {
        use crate::format::limits::{Limit, Limits};
        let mut l = Limits::from_env()?;
        for (lim, v) in [
            (Limit::Bytes, self.max_bytes),
            (Limit::Nodes, self.max_nodes),
            (Limit::Depth, self.max_depth),
            (Limit::Geometry, self.max_geometry),
            (Limit::Numbers, self.max_numbers),
        ] {
            if let Some(v) = v {
                l.set(lim, v);
            }
        }
        Ok(l)
    }
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
    /// Convert between .iv, .wrl, .wrl.gz, .gltf, .glb, .x3dv, .x3d (and from .obj), keeping every key.
    Convert(convert::Args),
    /// Describe a scene file: nodes, shapes, lights, cameras, tracks, warnings.
    Info(info::Args),
    /// Print the value of an animated property at given times.
    Sample(sample::Args),
    /// Set, remove and list keys from the command line.
    Key(key::Args),
    /// Screenshot tests: render scenes and compare them with golden PNGs.
    Check(check::Args),
    /// List autosaved untitled work (`--list`), or recover one session.
    Recover(recover::Args),
}

/// Runs the CLI; returns the process exit code.
pub fn run() -> i32 {
    let cli = Cli::parse();
    match cli.limits.resolve() {
        Ok(l) => crate::format::limits::set_defaults(l),
        Err(e) => {
            eprintln!("animed: {e}");
            return 2;
        }
    }
    if !matches!(
        cli.command,
        None | Some(Command::Edit(_)) | Some(Command::View(_))
    ) {
        pipe::die_quietly_on_closed_pipe();
    }
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
        Some(Command::Recover(a)) => recover::run(a),
    }
}
