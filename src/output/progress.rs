//! Progress of a long render on stderr: a redrawn bar on a terminal, one
//! plain line per frame otherwise (logs, CI, job runners).

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

/// Counts finished frames and reports them.
pub struct Progress {
    label: String,
    total: u32,
    done: u32,
    started: Instant,
    last_draw: Option<Instant>,
    mode: Mode,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// A bar redrawn in place (stderr is a terminal).
    Bar,
    /// One line per frame.
    Lines,
    /// Nothing (tests, `--quiet`).
    Quiet,
}

impl Mode {
    /// A bar when stderr is a terminal, else plain lines.
    pub fn detect() -> Mode {
        if std::io::stderr().is_terminal() {
            Mode::Bar
        } else {
            Mode::Lines
        }
    }
}

impl Progress {
    pub fn new(label: impl Into<String>, total: u32, mode: Mode) -> Progress {
        Progress {
            label: label.into(),
            total,
            done: 0,
            started: Instant::now(),
            last_draw: None,
            mode,
        }
    }

    /// Starts a new stage (e.g. the second pass of a GIF) with its own count.
    pub fn stage(&mut self, label: impl Into<String>, total: u32) {
        self.finish_bar();
        self.label = label.into();
        self.total = total;
        self.done = 0;
        self.started = Instant::now();
        self.last_draw = None;
    }

    /// One more frame is done; `what` says which (index, time, file).
    pub fn frame_done(&mut self, what: &str) {
        self.done += 1;
        match self.mode {
            Mode::Quiet => {}
            Mode::Lines => eprintln!("{}: {}/{} {what}", self.label, self.done, self.total),
            Mode::Bar => {
                let now = Instant::now();
                let due = self
                    .last_draw
                    .is_none_or(|t| now - t >= Duration::from_millis(100));
                if due || self.done == self.total {
                    self.last_draw = Some(now);
                    eprint!("\r{}", self.bar_line());
                    let _ = std::io::stderr().flush();
                }
            }
        }
    }

    fn bar_line(&self) -> String {
        const WIDTH: usize = 30;
        let frac = if self.total == 0 {
            1.0
        } else {
            self.done as f64 / self.total as f64
        };
        let filled = ((frac * WIDTH as f64) as usize).min(WIDTH);
        let secs = self.started.elapsed().as_secs_f64();
        let fps = if secs > 0.0 {
            self.done as f64 / secs
        } else {
            0.0
        };
        let eta = if fps > 0.0 {
            format!("{:.0}s left", (self.total - self.done) as f64 / fps)
        } else {
            String::from("…")
        };
        format!(
            "{} [{}{}] {}/{} {:.1} fps {eta}   ",
            self.label,
            "#".repeat(filled),
            "-".repeat(WIDTH - filled),
            self.done,
            self.total,
            fps
        )
    }

    fn finish_bar(&mut self) {
        if self.mode == Mode::Bar && self.last_draw.is_some() {
            eprintln!();
        }
        self.last_draw = None;
    }

    /// Ends the report with a summary line: frames, seconds, frames/second.
    pub fn finish(mut self, summary: &str) {
        self.finish_bar();
        if self.mode != Mode::Quiet {
            let secs = self.started.elapsed().as_secs_f64();
            eprintln!(
                "{}: {summary} in {secs:.2} s ({:.2} frames/s)",
                self.label,
                self.done as f64 / secs.max(1e-9)
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bar_shows_counts_and_fill() {
        let mut p = Progress::new("render", 4, Mode::Quiet);
        p.frame_done("x");
        p.frame_done("y");
        let line = p.bar_line();
        assert!(
            line.starts_with("render [###############---------------] 2/4"),
            "{line}"
        );
    }
}
