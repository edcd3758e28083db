//! `animed key`: set, remove and list keys from the command line.

/// Set, remove and list keys from the command line.
#[derive(clap::Args, Debug)]
pub struct Args {}

pub fn run(_args: Args) -> i32 {
    eprintln!("animed key: not built yet");
    2
}
