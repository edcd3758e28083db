//! animed: a keyframe animation editor and viewer for 3D scenes that needs
//! no GPU. See README.md ("Architecture") for how the modules fit together.

pub mod anim;
pub mod app;
pub mod cli;
pub mod editor;
pub mod format;
pub mod input;
pub mod output;
pub mod render;
pub mod scene;
pub mod ui;
pub mod viewer;
