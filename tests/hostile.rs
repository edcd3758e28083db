//! Hostile inputs, generated (see `hostile/gen.rs`): each must end in a
//! clear `path:line:column` error naming the limit it passed (or load),
//! never a panic, abort, hang or unbounded allocation.
//!
//! `reading` checks the messages through the library with small limits;
//! `memory` runs the binary on the worst cases with the DEFAULT limits
//! under `ulimit -v` 3 GiB and a timeout, and asserts peak RSS ≤ 1.5 GB
//! (measured with `/usr/bin/time`; run with `--nocapture` to see figures).

#[path = "hostile/gen.rs"]
mod gen;
#[path = "hostile/holes.rs"]
mod holes;
#[path = "hostile/memory.rs"]
mod memory;
#[path = "hostile/reading.rs"]
mod reading;
#[path = "hostile/saving.rs"]
mod saving;
#[path = "hostile/writing.rs"]
mod writing;
