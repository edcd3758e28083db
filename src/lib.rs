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
//! Everything else (scene model, readers, renderer stages, editor) is in
//! [`internals`]: it works, but may change between versions. See README.md
//! ("Architecture") for how the modules fit together.
//!
//! Cargo features: `cli` (the `animed` binary, clap) and `window` (the
//! minifb window of the editor and viewer) are on by default;
//! `default-features = false` gives the library without either.

// The front door: every public item documented (the lint keeps it so).
#[deny(missing_docs)]
pub mod check;
#[deny(missing_docs)]
mod compare;
#[deny(missing_docs)]
mod error;
#[deny(missing_docs)]
mod front;
#[deny(missing_docs)]
mod picture;

pub use compare::{compare, Allowance, Comparison, Tolerance};
pub use error::{Error, ErrorKind, Location, Result};
pub use front::{demo_scene, load, load_with_warnings, render, RenderSpec, Style};
pub use picture::Image;
pub use render::job::Headlight;
pub use scene::Scene;

// The application's modules live under [`internals`]; the crate itself
// reaches them by their short root paths (`crate::scene`, ...) through the
// crate-private re-exports below, so only `animed::internals::…` is public.
pub(crate) use internals::{anim, editor, format, input, render, scene, ui};
#[cfg(feature = "window")]
pub(crate) use internals::{app, viewer};
#[cfg(feature = "cli")]
pub(crate) use internals::{cli, output};

/// The application's internals: the scene model, the animation maths, the
/// readers and writers, the renderer's stages, the editor, the viewer and
/// the command line. They work and are tested, but they are shaped for the
/// application and change between versions without notice; build on the
/// crate root ([`load`], [`render()`], [`compare()`], [`check`], [`Error`])
/// where you can. Reaching into them is fine for tools that track animed
/// closely.
#[path = "."]
pub mod internals {
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
}
