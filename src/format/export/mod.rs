//! What every writer shares: the write plan (names, what to write), the
//! animated channels and their adaptive sampling, the key note, text output
//! helpers, texture urls and inline images, writer options/reports, and the
//! atomic save that picks a writer.
//!
//! Arrows: `save → {iv::write, vrml97::write} → {plan, channels, sampling,
//! keynote, text, textures, options}`; nothing here imports `save`.

pub mod channels;
pub mod keynote;
pub mod options;
pub mod plan;
pub mod sampling;
pub mod save;
pub(crate) mod text;
pub mod textures;

pub use options::{ChannelReport, InventorVersion, WriteOptions, WriteReport};
pub use save::{save, to_bytes, OutputFormat, SaveError};
