//! animed: a keyframe animation editor and viewer for 3D scenes that needs
//! no GPU, and a library for deterministic screenshot tests.
//!
//! # The front door
//!
//! Everything a screenshot test needs is at the crate root:
//! [`load`] a scene, [`render`] it as a [`RenderSpec`] says into an
//! [`Image`], [`compare`] that with a golden within a [`Tolerance`] (the
//! [`Comparison`] carries a diff picture), and [`check::verify`] to do the
//! golden-file bookkeeping (write `NAME.actual.png` / `NAME.diff.png` on
//! failure, accept with `update`). Every fallible function returns the one
//! [`Error`] type.
//!
//! ```
//! use animed::{compare, render, RenderSpec, Tolerance};
//! let scene = animed::load("assets/demo.wrl")?;
//! let picture = render(&scene, &RenderSpec::new(80, 60).at(0.5))?;
//! let same = render(&scene, &RenderSpec::new(80, 60).at(0.5).threads(1))?;
//! assert!(compare(&picture, &same, &Tolerance::exact()).passed);
//! # Ok::<(), animed::Error>(())
//! ```
//!
//! The rendering is deterministic: the same input gives the same pixels for
//! any thread count, debug or release, and with or without
//! `-C target-cpu=x86-64-v3` on x86-64 (see README, "Determinism").
//!
//! The other public modules are the application's internals (scene model,
//! readers, renderer stages, editor); they work but may change between
//! versions. See README.md ("Architecture") for how they fit together.
//!
//! Cargo features: `cli` (the `animed` binary, clap) and `window` (the
//! minifb window of the editor and viewer) are on by default;
//! `default-features = false` gives the library without either.

pub mod check;
mod compare;
mod error;
mod front;
mod picture;

pub use compare::{compare, Allowance, Comparison, Tolerance};
pub use error::{Error, ErrorKind, Location, Result};
pub use front::{demo_scene, load, load_with_warnings, render, RenderSpec, Style};
pub use picture::Image;
pub use render::job::Headlight;
pub use scene::Scene;

pub mod anim;
#[cfg(feature = "window")]
pub mod app;
#[cfg(feature = "cli")]
pub mod cli;
pub mod editor;
pub mod format;
pub mod input;
pub mod output;
pub mod render;
pub mod scene;
pub mod ui;
pub mod viewer;
