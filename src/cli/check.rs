//! `animed check`: screenshot tests from the command line. A thin shell
//! over the library's [`crate::check`]: parse the arguments into a
//! [`Suite`] (from a TOML file, or one case from flags), [`run`] it, print
//! the table, write the reports, exit 0 / 1 / 2.

use crate::check::{run, Case, Options, Suite, When};
use crate::cli::render::{parse_headlight, parse_rgb, parse_size, parse_style};
use crate::compare::{Allowance, Tolerance};
use crate::front::RenderSpec;
use crate::render::job::Headlight;
use crate::scene::RenderStyle;
use glam::Vec3;
use std::path::{Path, PathBuf};

/// Render scenes and compare them with golden PNGs.
///
/// `animed check SUITE.toml` runs a suite (see README, "Screenshot tests");
/// `animed check FILE --golden G.png [render options]` checks one picture.
/// Exit 0 = all match, 1 = some differ or have no golden, 2 = bad input.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// A suite (.toml), or a scene file when --golden is given.
    pub input: PathBuf,
    /// Golden PNG to compare one scene file with (instead of a suite).
    #[arg(long)]
    pub golden: Option<PathBuf>,
    /// Folder for NAME.actual.png and NAME.diff.png.
    #[arg(long, default_value = "target/animed-check")]
    pub out: PathBuf,
    /// Accept the actual pictures: overwrite failing goldens, create
    /// missing ones (also ANIMED_UPDATE=1). Matching goldens are untouched.
    #[arg(long)]
    pub update: bool,
    /// Write a report: JUnit XML (.xml) or JSON (.json). May be repeated.
    #[arg(long)]
    pub report: Vec<PathBuf>,
    /// With --golden: the shot's name (default: the golden's file stem).
    #[arg(long)]
    pub name: Option<String>,
    /// With --golden: picture size WIDTHxHEIGHT (default 320x240).
    #[arg(long, value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// With --golden: camera description or node name.
    #[arg(long)]
    pub viewpoint: Option<String>,
    /// With --golden: filled, lines, points or hidden for every object.
    #[arg(long, value_parser = parse_style)]
    pub style: Option<RenderStyle>,
    /// With --golden: background r,g,b in 0..1.
    #[arg(long, value_parser = parse_rgb)]
    pub bg: Option<Vec3>,
    /// With --golden: headlight on, off or auto.
    #[arg(long, value_parser = parse_headlight)]
    pub headlight: Option<Headlight>,
    /// With --golden: worker threads (0 = all cores); never changes the picture.
    #[arg(long)]
    pub threads: Option<usize>,
    /// With --golden: the animation clip to play, by name or 0-based index
    /// (default: the file's first).
    #[arg(long, value_name = "NAME|INDEX")]
    pub animation: Option<String>,
    /// With --golden: time in seconds (default 0).
    #[arg(long, conflicts_with = "frame")]
    pub time: Option<f32>,
    /// With --golden: scene frame number (uses the scene's fps).
    #[arg(long)]
    pub frame: Option<f32>,
    /// With --golden: largest channel difference (0..255) a pixel may have
    /// and still count as equal (default 0).
    #[arg(long)]
    pub channel: Option<u8>,
    /// With --golden: number of pixels allowed beyond --channel (default 0).
    #[arg(long, conflicts_with = "fraction")]
    pub pixels: Option<u64>,
    /// With --golden: fraction (0..1) of pixels allowed beyond --channel.
    #[arg(long)]
    pub fraction: Option<f64>,
    /// With --golden: pass when the mean SSIM is at least this (0..1),
    /// instead of the per-pixel test.
    #[arg(long)]
    pub ssim: Option<f64>,
}

impl Args {
    /// Names of render/tolerance flags that only make sense with --golden.
    fn single_case_flags(&self) -> Vec<&'static str> {
        let mut v = Vec::new();
        let mut flag = |set: bool, name: &'static str| {
            if set {
                v.push(name);
            }
        };
        flag(self.name.is_some(), "--name");
        flag(self.size.is_some(), "--size");
        flag(self.viewpoint.is_some(), "--viewpoint");
        flag(self.style.is_some(), "--style");
        flag(self.bg.is_some(), "--bg");
        flag(self.headlight.is_some(), "--headlight");
        flag(self.threads.is_some(), "--threads");
        flag(self.animation.is_some(), "--animation");
        flag(self.time.is_some(), "--time");
        flag(self.frame.is_some(), "--frame");
        flag(self.channel.is_some(), "--channel");
        flag(self.pixels.is_some(), "--pixels");
        flag(self.fraction.is_some(), "--fraction");
        flag(self.ssim.is_some(), "--ssim");
        v
    }
}

/// The one case `animed check FILE --golden G.png …` describes.
fn single_case(args: &Args, golden: &Path) -> Result<Suite, String> {
    let name = match &args.name {
        Some(n) => n.clone(),
        None => golden
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "check".into()),
    };
    let (w, h) = args.size.unwrap_or((320, 240));
    let mut spec = RenderSpec::new(w, h);
    spec.viewpoint = args.viewpoint.clone();
    spec.style = args.style;
    spec.background = args.bg.map(|c| c.to_array());
    spec.headlight = args.headlight.unwrap_or_default();
    spec.threads = args.threads.unwrap_or(0);
    spec.clip = args.animation.clone();
    let mut tolerance = Tolerance::exact();
    if let Some(c) = args.channel {
        tolerance.channel = c;
    }
    if let Some(n) = args.pixels {
        tolerance.pixels = Allowance::Count(n);
    }
    if let Some(f) = args.fraction {
        if !(0.0..=1.0).contains(&f) {
            return Err(format!("--fraction {f} is not in 0..1"));
        }
        tolerance.pixels = Allowance::Fraction(f);
    }
    if let Some(s) = args.ssim {
        if !(0.0..=1.0).contains(&s) {
            return Err(format!("--ssim {s} is not in 0..1"));
        }
        tolerance.ssim = Some(s);
    }
    let when = match (args.time, args.frame) {
        (_, Some(f)) if !f.is_finite() => return Err(format!("--frame {f} is not a number")),
        (_, Some(f)) => When::Frame(f),
        (Some(t), _) if !t.is_finite() => return Err(format!("--time {t} is not a number")),
        (Some(t), _) => When::Time(t),
        (None, None) => When::Time(0.0),
    };
    Ok(Suite::single(Case::new(
        name,
        args.input.clone(),
        spec,
        when,
        golden.to_path_buf(),
        tolerance,
    )))
}

/// Runs `animed check`; returns the exit code.
pub fn run_cli(args: Args) -> i32 {
    let suite = match &args.golden {
        Some(g) => single_case(&args, g),
        None => {
            let flags = args.single_case_flags();
            if !flags.is_empty() {
                Err(format!(
                    "{} only apply with --golden; in a suite set them per case",
                    flags.join(", ")
                ))
            } else if args.input.extension().and_then(|e| e.to_str()) != Some("toml") {
                Err(format!(
                    "{}: give a suite (.toml), or a scene file with --golden G.png",
                    args.input.display()
                ))
            } else {
                Suite::load(&args.input).map_err(|e| e.to_string())
            }
        }
    };
    let suite = match suite {
        Ok(s) => s,
        Err(e) => {
            eprintln!("animed check: {e}");
            return 2;
        }
    };
    let mut options = Options::new(&args.out);
    options.update |= args.update;
    let report = run(&suite, &options);
    print!("{}", report.table());
    let mut code = report.exit_code();
    for path in &args.report {
        if let Err(e) = report.write(path) {
            eprintln!("animed check: {e}");
            code = 2;
        }
    }
    if code == 1 && !options.update {
        println!(
            "look at the .diff.png (and .actual.png) files in {}; if the new pictures are \
             right, accept them with --update (or ANIMED_UPDATE=1)",
            options.out_dir.display()
        );
    }
    code
}
