//! `animed view`: play a file's animation in a window.

use crate::render::job::Headlight;
use crate::viewer::{Viewer, ViewerOptions};
use std::path::PathBuf;

/// Play a file's animation in a window (real time at the file's fps,
/// looping). Space pauses, Left/Right step a frame, PageUp/PageDown cycle
/// the file's viewpoints, H toggles the headlight, S the stats, Home goes
/// back to the viewpoint, Esc/Q quits. Drag to orbit (Shift or right
/// button: pan), wheel to zoom, click or drag the bar to scrub.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Scene file (.wrl, .wrl.gz, .iv, .obj); default: the bundled demo.
    pub file: Option<PathBuf>,
    /// Start at this viewpoint (its description or node name).
    #[arg(long)]
    pub viewpoint: Option<String>,
    /// Show the render time and the frame rate actually shown.
    #[arg(long)]
    pub stats: bool,
    /// Window size, WxH.
    #[arg(long, default_value = "800x600", value_parser = crate::cli::edit::parse_size)]
    pub size: (u32, u32),
    /// Headlight at start: on, off or auto (the file's NavigationInfo).
    #[arg(long, default_value = "auto", value_parser = parse_headlight)]
    pub headlight: Headlight,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

fn parse_headlight(s: &str) -> Result<Headlight, String> {
    Headlight::parse(s).ok_or_else(|| format!("headlight {s:?} is not on, off or auto"))
}

pub fn run(args: Args) -> i32 {
    match view(args) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("animed view: {e}");
            1
        }
    }
}

fn view(args: Args) -> Result<(), String> {
    let mut loaded = match &args.file {
        Some(p) => crate::format::load(p),
        None => crate::format::demo(),
    }
    .map_err(|e| e.to_string())?;
    for w in &loaded.warnings {
        eprintln!("warning: {w}");
    }
    args.clip.apply(&mut loaded.scene)?;
    let title = args.file.as_ref().map_or("demo".to_string(), |p| {
        p.file_name()
            .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into())
    });
    let opts = ViewerOptions {
        width: args.size.0,
        height: args.size.1,
        viewpoint: args.viewpoint,
        headlight: args.headlight,
        stats: args.stats,
        title,
    };
    let viewer = Viewer::new(loaded.scene, &opts)?;
    if std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none() {
        return Err("cannot open a window: no display (DISPLAY is not set). \
             `animed view` needs an X display; without one, render the animation \
             with `animed render FILE --range START:STEP:COUNT -o frames/f_####.png` \
             (or `-o anim.gif`)"
            .to_string());
    }
    crate::app::run(viewer)
}
