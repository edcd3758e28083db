//! Ending quietly when the reader of our output goes away.
//!
//! Rust starts programs with SIGPIPE ignored, so a `println!` into a closed
//! pipe (`animed info x | head`) returns EPIPE and panics with "failed
//! printing to stdout". Text tools on Unix instead die of SIGPIPE, which the
//! shell treats as a normal end of a pipeline. The commands that print
//! restore that default; the window commands keep Rust's choice, so a closed
//! display connection stays an error message rather than a silent death.

/// Restores the default SIGPIPE action for this process (Unix only).
pub fn die_quietly_on_closed_pipe() {
    #[cfg(unix)]
    // SAFETY: `signal` with SIG_DFL installs no handler code; it only resets
    // the action, before any thread that could be writing is started.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}
