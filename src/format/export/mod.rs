//! What every writer shares: the write plan (names, what to write), the
//! animated channels and their adaptive sampling, the key note, text output
//! helpers, texture urls and inline images, face-set vertices in the order
//! readers number them (`vertex_order`), warnings for what a format cannot
//! hold (`dropped`), writer options/reports, the
//! atomic save that picks a writer, and `atomic`: replacing a file safely
//! (identity kept, full disk caught, no temporary left, advisory edit lock,
//! changed-since-read stamp).
//!
//! Arrows: `save → {iv::write, vrml97::write} → {plan, channels, sampling,
//! keynote, text, textures, vertex_order, options, dropped}`; nothing here imports `save`.

pub mod atomic;
pub mod channels;
pub mod dropped;
pub mod keynote;
pub mod options;
pub mod plan;
pub mod sampling;
pub mod save;
pub(crate) mod text;
pub mod textures;
pub mod vertex_order;

pub use options::{ChannelReport, InventorVersion, WriteOptions, WriteReport};
pub use save::{save, to_bytes, OutputFormat, SaveError};
