//! `animed recover`: the untitled sessions whose work was autosaved but
//! never saved (crashed, killed, closed), as the editor offers them at
//! start; list them, write one out, or open one in the editor.

use crate::editor::disk::{state_dir, untitled_sessions};
use crate::editor::recovery::session_lines;
use std::path::PathBuf;
use std::time::SystemTime;

/// List (or recover) autosaved untitled work.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Print every recoverable session, newest first: number, time, objects, file.
    #[arg(long)]
    pub list: bool,
    /// The session to recover (1 = newest, as `--list` numbers them).
    pub number: Option<usize>,
    /// Write that session's scene to this file (format from the extension)
    /// instead of opening it in the editor.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

pub fn run(args: Args) -> i32 {
    let dir = state_dir();
    let sessions = untitled_sessions(&dir);
    let Some(n) = args.number.filter(|_| !args.list) else {
        if sessions.is_empty() {
            println!("no autosaved untitled work in {}", dir.display());
            return 0;
        }
        for (line, s) in session_lines(&sessions, SystemTime::now())
            .iter()
            .zip(&sessions)
        {
            println!("{line}  {}", s.path.display());
        }
        return 0;
    };
    let Some(s) = n.checked_sub(1).and_then(|i| sessions.get(i)) else {
        eprintln!(
            "animed recover: no session {n} ({} listed by `animed recover --list`)",
            sessions.len()
        );
        return 1;
    };
    match &args.output {
        Some(out) => {
            let saved = crate::format::load(&s.path)
                .map_err(|e| e.to_string())
                .and_then(|l| {
                    crate::format::save(&l.scene, out, &Default::default())
                        .map_err(|e| e.to_string())
                });
            match saved {
                Ok(_) => {
                    println!(
                        "wrote {} (the copy {} is kept)",
                        out.display(),
                        s.path.display()
                    );
                    0
                }
                Err(e) => {
                    eprintln!("animed recover: {e}");
                    1
                }
            }
        }
        None => {
            let mut ed = crate::editor::Editor::new(crate::scene::Scene::new(), None, 1024, 640);
            super::edit::tell_places(&mut ed);
            ed.recover_untitled(&s.path);
            ed.set_view_memory(Some(super::edit::view_memory()));
            ed.set_aa(super::edit::WINDOW_AA);
            match crate::app::run(ed) {
                Ok(()) => 0,
                Err(msg) => {
                    eprintln!("animed: {msg}");
                    2
                }
            }
        }
    }
}
