//! `animed render`: render a scene (or the bundled demo) to PNG.
//!
//! Structure for other outputs (PNG sequences, GIF, shards): [`prepare`]
//! turns the arguments into a [`Job`] (loaded scene + [`FrameSpec`] + time);
//! `render::job::render_color_at(&job.scene, &job.spec, t)` draws any frame of it;
//! [`save_png_atomic`] writes one. `run` is just those three in a row.

use crate::format::{self, LoadError, Loaded};
use crate::render::job::{render_color_at, FrameSpec, Headlight};
use crate::render::Frame;
use crate::scene::{RenderStyle, Scene};
use glam::Vec3;
use std::path::{Path, PathBuf};

/// Render a scene (or the bundled demo) to PNG.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Scene file (.wrl, .wrl.gz, .iv, .obj). Without it: the bundled demo scene.
    pub file: Option<PathBuf>,
    /// Output PNG.
    #[arg(short, long, default_value = "out.png")]
    pub output: PathBuf,
    /// Picture size, WIDTHxHEIGHT.
    #[arg(long, default_value = "640x480", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Camera to look through: a viewpoint description or camera node name
    /// (default: the first camera; with none, frame the whole scene).
    #[arg(long)]
    pub viewpoint: Option<String>,
    /// Draw every object as filled, lines, points (overrides the file).
    #[arg(long, value_parser = parse_style)]
    pub style: Option<RenderStyle>,
    /// Background colour r,g,b in 0..1 (default: the scene's; a file's VRML97 Background gradient or panorama is drawn unless --bg is given, which overrides it).
    #[arg(long, value_parser = parse_rgb)]
    pub bg: Option<Vec3>,
    /// Headlight: on, off or auto (VRML97: NavigationInfo.headlight; other
    /// formats: on).
    #[arg(long, default_value = "auto", value_parser = parse_headlight)]
    pub headlight: Headlight,
    /// Worker threads (0 = all cores, at most 256); the picture is the same for any count.
    #[arg(long, default_value_t = 0, value_parser = parse_threads)]
    pub threads: usize,
    /// Anti-aliasing: samples per pixel, 1 (off), 4 or 8.
    #[arg(long, default_value_t = 1, value_parser = parse_aa)]
    pub aa: u32,
    /// Time in seconds at which to evaluate the animation.
    #[arg(long, conflicts_with = "frame")]
    pub time: Option<f32>,
    /// Frame number at which to evaluate the animation (uses the scene's fps).
    #[arg(long)]
    pub frame: Option<f32>,
    /// Render a range: START:STEP:COUNT in seconds (frame i at START + i·STEP).
    /// -o is then a pattern whose run of # becomes the zero-padded frame
    /// index (frames/f_####.png), or a .gif (looping, STEP per frame).
    #[arg(long, conflicts_with_all = ["time", "frame", "frames"])]
    pub range: Option<String>,
    /// Render scene frames A..=B (inclusive, at the scene's fps), as --range.
    #[arg(long, conflicts_with_all = ["time", "frame"])]
    pub frames: Option<String>,
    /// With --range/--frames: render only frame indices i with i mod N = K
    /// (K/N, K from 0), to spread a range over machines.
    #[arg(long)]
    pub shard: Option<String>,
    #[command(flatten)]
    pub clip: super::clip_arg::ClipArg,
}

/// A loaded scene and everything needed to draw frames of it.
pub struct Job {
    pub scene: Scene,
    pub spec: FrameSpec,
    /// Seconds (from `--time`, or `--frame` / fps; 0 by default).
    pub time: f32,
    pub output: PathBuf,
    /// Name of the input for messages ("assets/demo.wrl" for the demo).
    pub source: PathBuf,
}

/// Loads `file`, or the bundled demo when `None`.
pub fn load_scene(file: Option<&Path>) -> Result<Loaded, LoadError> {
    match file {
        Some(p) => format::load(p),
        None => format::demo(),
    }
}

/// Loads the scene and resolves the arguments; warnings go to stderr.
/// Errors are ready to print (`path:line:column: message` for bad files).
pub fn prepare(args: &Args) -> Result<Job, String> {
    let loaded = match args.file.as_deref() {
        Some(p) => args.clip.load(p),
        None => format::demo(),
    }
    .map_err(|e| e.to_string())?;
    for w in &loaded.warnings {
        eprintln!("warning: {w}");
    }
    let mut scene = loaded.scene;
    args.clip.apply(&mut scene)?;
    let (width, height) = args.size;
    let time = match (args.time, args.frame) {
        (Some(t), _) => t,
        (None, Some(f)) => f / scene.settings.fps.max(1e-6),
        (None, None) => 0.0,
    };
    if !time.is_finite() {
        return Err(format!("time {time} is not a finite number"));
    }
    let spec = FrameSpec {
        width,
        height,
        viewpoint: args.viewpoint.clone(),
        style: args.style,
        background: args.bg,
        headlight: args.headlight,
        threads: args.threads,
        aa: args.aa,
    };
    // Fail early on a bad --viewpoint, before any frame is drawn.
    crate::render::job::find_camera(&scene, spec.viewpoint.as_deref())?;
    Ok(Job {
        scene,
        spec,
        time,
        output: args.output.clone(),
        source: args
            .file
            .clone()
            .unwrap_or_else(|| PathBuf::from("assets/demo.wrl")),
    })
}

pub fn run(args: Args) -> i32 {
    let range = crate::output::RangeArgs {
        range: args.range.as_deref(),
        frames: args.frames.as_deref(),
        shard: args.shard.as_deref(),
        output: &args.output,
    };
    if range.wanted() {
        let result = prepare(&args)
            .and_then(|job| crate::output::render_range(&job.scene, &job.spec, range));
        if let Err(e) = result {
            eprintln!("animed render: {e}");
            return 1;
        }
        return 0;
    }
    let result = prepare(&args).and_then(|job| {
        let frame = render_color_at(&job.scene, &job.spec, job.time)?;
        save_png_atomic(&frame, &job.output)
    });
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("animed render: {e}");
            1
        }
    }
}

/// Writes `frame` as PNG next to `path`, then renames it into place, so a
/// reader never sees a half-written file (one implementation with the
/// sequence writer, so both give the same bytes).
pub fn save_png_atomic(frame: &Frame, path: &Path) -> Result<(), String> {
    crate::output::png::save_atomic(frame, path)
}

/// Parses `WIDTHxHEIGHT` (each side 1..=16384, at most 64 Mpix).
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("size {s:?} is not WIDTHxHEIGHT"))?;
    let side = |v: &str| -> Result<u32, String> {
        let n: u32 = v
            .trim()
            .parse()
            .map_err(|_| format!("size {s:?}: {v:?} is not a whole number"))?;
        if n == 0 || n > crate::render::MAX_SIDE {
            return Err(format!(
                "size {s:?}: each side must be 1..={}",
                crate::render::MAX_SIDE
            ));
        }
        Ok(n)
    };
    let (w, h) = (side(w)?, side(h)?);
    if w as u64 * h as u64 > crate::render::MAX_PIXELS {
        return Err(format!(
            "size {s:?}: more than {} pixels",
            crate::render::MAX_PIXELS
        ));
    }
    Ok((w, h))
}

pub fn parse_style(s: &str) -> Result<RenderStyle, String> {
    match s.to_ascii_lowercase().as_str() {
        "filled" | "fill" => Ok(RenderStyle::Filled),
        "lines" | "line" | "wireframe" => Ok(RenderStyle::Lines),
        "points" | "point" => Ok(RenderStyle::Points),
        "hidden" => Ok(RenderStyle::Hidden),
        _ => Err(format!("style {s:?} is not filled, lines or points")),
    }
}

/// Most `--threads`: more only costs memory and start-up time.
pub const MAX_THREADS: usize = 256;

/// A `--threads` count: 0 (all cores) ..= [`MAX_THREADS`].
pub fn parse_threads(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(n) if n <= MAX_THREADS => Ok(n),
        _ => Err(format!(
            "threads {s:?} is not a count from 0 (all cores) to {MAX_THREADS}"
        )),
    }
}

/// Parses `r,g,b` with components in 0..1.
pub fn parse_rgb(s: &str) -> Result<Vec3, String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != 3 {
        return Err(format!("colour {s:?} is not r,g,b"));
    }
    let mut c = [0.0f32; 3];
    for (k, p) in parts.iter().enumerate() {
        let v: f32 = p
            .trim()
            .parse()
            .map_err(|_| format!("colour {s:?}: {p:?} is not a number"))?;
        if !(0.0..=1.0).contains(&v) {
            return Err(format!("colour {s:?}: components must be in 0..1"));
        }
        c[k] = v;
    }
    Ok(Vec3::from_array(c))
}

pub fn parse_headlight(s: &str) -> Result<Headlight, String> {
    Headlight::parse(s).ok_or_else(|| format!("headlight {s:?} is not on, off or auto"))
}

/// `--aa`: 1, 4 or 8 samples per pixel.
pub fn parse_aa(s: &str) -> Result<u32, String> {
    match s.trim() {
        "1" => Ok(1),
        "4" => Ok(4),
        "8" => Ok(8),
        _ => Err(format!("'{s}' is not 1, 4 or 8 samples per pixel")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_arguments() {
        assert_eq!(parse_size("320x240"), Ok((320, 240)));
        assert!(parse_size("0x10").is_err());
        assert!(parse_size("99999x10").is_err());
        assert!(parse_size("16384x16384").is_err());
        assert_eq!(parse_size("8192x8192"), Ok((8192, 8192)));
        assert!(parse_size("abc").is_err());
        assert_eq!(parse_rgb("0,0.5,1"), Ok(Vec3::new(0.0, 0.5, 1.0)));
        assert!(parse_rgb("0,2,1").is_err());
        assert!(parse_rgb("0,1").is_err());
        assert_eq!(parse_style("LINES"), Ok(RenderStyle::Lines));
        assert!(parse_style("dots").is_err());
        assert_eq!(parse_headlight("off"), Ok(Headlight::Off));
    }
}
