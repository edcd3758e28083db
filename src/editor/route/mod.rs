//! The [`Editor`](super::Editor)'s methods that route events to the editor's parts and
//! apply what they return. Nothing outside this folder imports it, so the
//! parts below never depend on the editor that holds them.

mod aim;
mod browser;
mod create;
mod dialog;
mod faces;
mod files;
mod graph;
mod input;
mod intents;
mod keyedit;
mod keyprops;
mod keystrip;
mod manip;
mod onion;
mod panel;
mod record;
mod recovery;
mod side;
mod time_field;
mod timeline;
mod viewport;
mod views;
