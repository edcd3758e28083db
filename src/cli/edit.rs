//! `animed edit`: open the editor (the default with no subcommand), or run
//! a headless session script and write a screenshot.

use crate::editor::{script, Editor};
use std::path::PathBuf;

/// Open the editor (the default with no subcommand).
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Scene file to open (.iv, .wrl, .wrl.gz, .obj); default: the demo scene.
    pub file: Option<PathBuf>,
    /// Run this session script without a window (see README, "Editor").
    #[arg(long)]
    pub script: Option<PathBuf>,
    /// Write the final frame (scene + overlay) to this PNG; runs without a window.
    #[arg(long)]
    pub screenshot: Option<PathBuf>,
    /// Window / screenshot size, WxH.
    #[arg(long, default_value = "1024x640", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Seconds between autosaves of unsaved work to the recovery copy
    /// (0: off). Default: $ANIMED_AUTOSAVE_SECS, else 30.
    #[arg(long, value_name = "SECS")]
    pub autosave_secs: Option<f64>,
    /// Anti-aliasing of the viewport: samples per pixel, 1 (off), 4 or 8.
    /// Default: 4 in the window, 1 for --script/--screenshot.
    #[arg(long, value_parser = super::render::parse_aa)]
    pub aa: Option<u32>,
}

/// The autosave interval: the flag, else `$ANIMED_AUTOSAVE_SECS`, else 30 s.
fn autosave_interval(flag: Option<f64>) -> Result<Option<f64>, String> {
    let secs = match flag {
        Some(s) => s,
        None => match std::env::var("ANIMED_AUTOSAVE_SECS") {
            Ok(v) => v
                .trim()
                .parse::<f64>()
                .map_err(|_| format!("ANIMED_AUTOSAVE_SECS: '{v}' is not a number of seconds"))?,
            Err(_) => crate::editor::recovery::DEFAULT_INTERVAL,
        },
    };
    if !secs.is_finite() || secs < 0.0 {
        return Err(format!("autosave interval {secs} is not 0 or more seconds"));
    }
    Ok((secs > 0.0).then_some(secs))
}

/// Parses `WxH` (each 16..=4096).
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("'{s}' is not WxH"))?;
    let p = |v: &str| -> Result<u32, String> {
        v.trim()
            .parse::<u32>()
            .ok()
            .filter(|n| (16..=4096).contains(n))
            .ok_or_else(|| format!("'{v}' is not a size from 16 to 4096"))
    };
    Ok((p(w)?, p(h)?))
}

fn make_editor(file: Option<&PathBuf>, (w, h): (u32, u32)) -> Result<Editor, String> {
    match file {
        None => Ok(Editor::with_demo(w, h)),
        Some(path) => {
            let stamp = crate::format::export::atomic::Stamp::of(path);
            let loaded = crate::format::load(path).map_err(|e| e.to_string())?;
            for warning in &loaded.warnings {
                eprintln!("warning: {warning}");
            }
            let mut ed = Editor::new(loaded.scene, Some(path.clone()), w, h);
            // A save onto the file checks nobody changed it since.
            ed.set_disk_stamp(stamp);
            ed.say_opened(path, loaded.warnings.len());
            // A crash left newer work beside the file: ask.
            ed.check_recovery();
            Ok(ed)
        }
    }
}

pub fn run(args: Args) -> i32 {
    let made = autosave_interval(args.autosave_secs).and_then(|secs| {
        let mut ed = make_editor(args.file.as_ref(), args.size)?;
        ed.set_autosave_interval(secs);
        tell_places(&mut ed);
        Ok(ed)
    });
    let mut ed = match made {
        Ok(e) => e,
        Err(msg) => {
            eprintln!("animed edit: {msg}");
            return 1;
        }
    };
    if args.script.is_none() && args.screenshot.is_none() {
        // Untitled work a crash left behind is offered like a file's.
        ed.offer_untitled(&crate::editor::disk::state_dir());
        ed.set_view_memory(Some(view_memory()));
        ed.set_aa(args.aa.unwrap_or(WINDOW_AA));
        return window(ed);
    }
    ed.set_aa(args.aa.unwrap_or(1));
    if let Some(path) = &args.script {
        let text = match std::fs::read_to_string(path) {
            Ok(t) => t,
            Err(e) => {
                eprintln!("animed edit: {}: {e}", path.display());
                return 1;
            }
        };
        if let Err(e) = script::run(&mut ed, &text, path) {
            eprintln!("animed edit: {e}");
            return 1;
        }
    }
    if ed.status().error {
        eprintln!("animed edit: status: {}", ed.status().text);
    }
    if let Some(out) = &args.screenshot {
        let frame = ed.render_frame();
        if let Err(e) = frame.save_png(out) {
            eprintln!("animed edit: {}: {e}", out.display());
            return 1;
        }
    }
    0
}

/// What the shell tells the editor about this process, which the editor
/// never reads itself: the working directory (the file browser starts
/// there when no file is open), `$HOME` (a typed `~/`) and the state
/// folder (copies of untitled work, `disk::state_dir`), the process id
/// (the untitled copy's name) and the wall clock ("Autosaved at …").
pub fn tell_places(ed: &mut Editor) {
    if let Ok(dir) = std::env::current_dir() {
        ed.set_start_dir(&dir);
    }
    ed.set_home(crate::editor::disk::home().as_deref());
    ed.set_state_dir(&crate::editor::disk::state_dir());
    // The process's id and the clock are the shell's to give too.
    ed.set_pid(std::process::id());
    ed.set_wall_clock(std::time::SystemTime::now());
}

/// Anti-aliasing samples per pixel of the editor window by default.
pub const WINDOW_AA: u32 = 4;

fn window(ed: Editor) -> i32 {
    match crate::app::run(ed) {
        Ok(()) => 0,
        Err(msg) => {
            eprintln!("animed: {msg}");
            2
        }
    }
}

/// `animed` with no arguments: the editor on the bundled demo scene.
pub fn run_default() -> i32 {
    let mut ed = Editor::with_demo(1024, 640);
    tell_places(&mut ed);
    match autosave_interval(None) {
        Ok(secs) => ed.set_autosave_interval(secs),
        Err(msg) => {
            eprintln!("animed: {msg}");
            return 1;
        }
    }
    ed.offer_untitled(&crate::editor::disk::state_dir());
    ed.set_view_memory(Some(view_memory()));
    ed.set_aa(WINDOW_AA);
    window(ed)
}

/// Where the window's editor remembers each file's view.
pub fn view_memory() -> std::path::PathBuf {
    crate::editor::disk::state_dir().join("views")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("320x240"), Ok((320, 240)));
        assert!(parse_size("320").is_err());
        assert!(parse_size("0x10").is_err());
        assert!(parse_size("99999x10").is_err());
    }

    #[test]
    fn autosave_flag_wins_and_zero_is_off() {
        assert_eq!(autosave_interval(Some(5.0)), Ok(Some(5.0)));
        assert_eq!(autosave_interval(Some(0.0)), Ok(None));
        assert!(autosave_interval(Some(-1.0)).is_err());
        assert!(autosave_interval(Some(f64::NAN)).is_err());
    }
}
