//! `animed convert`: convert between .iv, .wrl, .wrl.gz, .gltf, .glb (and from .obj), keeping every key.

use crate::format::export::atomic::{EditLock, Replace};
use crate::format::{self, InventorVersion, OutputFormat, WriteOptions};
use std::path::PathBuf;

/// Convert between .iv, .wrl, .wrl.gz, .gltf, .glb (and from .obj), keeping every key.
///
/// The output format follows OUT's extension. Animation is written twice:
/// as interpolators/engines other viewers play, and as the animed key note
/// that `animed` reads back exactly.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input scene (.wrl, .wrl.gz, .iv, .obj, …; detected by content).
    pub input: PathBuf,
    /// Output file: .wrl, .wrl.gz (or .wrz), .iv, .gltf or .glb.
    pub output: PathBuf,
    /// Position tolerance of the sampled interpolators, as a fraction of the
    /// scene's bounding-box diagonal (also the relative scale tolerance).
    #[arg(long, default_value_t = 0.001)]
    pub tolerance: f32,
    /// Rotation / direction / angle tolerance of the sampled interpolators, in degrees.
    #[arg(long, default_value_t = 0.1)]
    pub angle_tolerance: f32,
    /// Inventor text version for .iv output: 2.1 (animated) or 1.0 (still scene).
    #[arg(long, default_value = "2.1", value_parser = ["2.1", "1.0"])]
    pub inventor_version: String,
    /// X3D output: write exactly-expressible spline and squad tracks as
    /// SplinePositionInterpolator / SplineScalarInterpolator /
    /// SquadOrientationInterpolator (view3dscene 4.2 does not play them)
    /// instead of sampled linear interpolators.
    #[arg(long)]
    pub x3d_splines: bool,
    /// Print key counts per animated field and what the format could not hold.
    #[arg(long, short)]
    pub verbose: bool,
    /// Replace OUTPUT even if it is read-only.
    #[arg(long)]
    pub force: bool,
    /// Copy every texture file into DIR (created if missing) and make the
    /// output refer to the copies. Without it, textures are referenced where
    /// they are, by their path relative to OUT; nothing is copied.
    #[arg(long, value_name = "DIR")]
    pub copy_textures: Option<PathBuf>,
}

pub fn run(args: Args) -> i32 {
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        eprintln!("animed convert: --tolerance must be a positive number");
        return 2;
    }
    if !(args.angle_tolerance.is_finite() && args.angle_tolerance > 0.0) {
        eprintln!("animed convert: --angle-tolerance must be a positive number");
        return 2;
    }
    if OutputFormat::from_path(&args.output).is_none() {
        eprintln!(
            "animed convert: {}: cannot tell the output format from the name (use .wrl, .wrl.gz, .iv, .gltf, .glb, .x3dv or .x3d)",
            args.output.display()
        );
        return 2;
    }
    // Held from the read to the replace: a `key` or another `convert` on
    // OUTPUT waits instead of being overwritten.
    let _lock = match EditLock::acquire(&args.output) {
        Ok(l) => l,
        Err(e) => {
            eprintln!(
                "animed convert: {}: cannot lock for editing: {e}",
                args.output.display()
            );
            return 1;
        }
    };
    let mut loaded = match format::load(&args.input) {
        Ok(l) => l,
        Err(e) => {
            eprintln!("{e}");
            return 1;
        }
    };
    for w in &loaded.warnings {
        eprintln!("warning: {w}");
    }
    let opts = WriteOptions {
        x3d_splines: args.x3d_splines,
        tolerance: args.tolerance,
        angle_tolerance: args.angle_tolerance,
        inventor_version: if args.inventor_version == "1.0" {
            InventorVersion::V1_0
        } else {
            InventorVersion::V2_1
        },
    };
    if let Some(dir) = &args.copy_textures {
        match format::export::textures::copy_textures(&mut loaded.scene, dir) {
            Ok(copied) if args.verbose => {
                for (from, to) in copied {
                    println!("copied {} -> {}", from.display(), to.display());
                }
            }
            Ok(_) => {}
            Err(e) => {
                eprintln!("animed convert: {e}");
                return 1;
            }
        }
    }
    let how = Replace { force: args.force };
    let report = match format::save::save_with(&loaded.scene, &args.output, &opts, how) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("animed convert: {e}");
            return 1;
        }
    };
    for w in &report.warnings {
        eprintln!("warning: {w}");
    }
    if args.verbose {
        print!("{}", describe(&report));
    }
    0
}

/// The key-count table `--verbose` prints.
pub fn describe(report: &format::WriteReport) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    if report.channels.is_empty() {
        s.push_str("no animated fields\n");
        return s;
    }
    let _ = writeln!(
        s,
        "{:<32} {:>8} {:>8} {:>10}",
        "field", "authored", "written", "per-frame"
    );
    for c in &report.channels {
        let _ = writeln!(
            s,
            "{:<32} {:>8} {:>8} {:>10}",
            c.name, c.authored_keys, c.written_keys, c.per_frame_keys
        );
    }
    let (w, p) = (report.written_keys(), report.per_frame_keys());
    let _ = writeln!(
        s,
        "{:<32} {:>8} {:>8} {:>10}",
        "total",
        report.authored_keys(),
        w,
        p
    );
    if p > 0 {
        let _ = writeln!(
            s,
            "written keys are {:.1}% of per-frame baking ({:.1}x fewer)",
            100.0 * w as f64 / p as f64,
            p as f64 / w.max(1) as f64
        );
    }
    s
}
