//! `--animation NAME|INDEX` (which clip plays) and `--scene N` (which of a
//! glTF file's scenes loads), shared by every command that loads a scene.

use crate::format::{self, LoadError, LoadOptions, Loaded};
use crate::scene::Scene;
use std::path::Path;

/// The clip to play (flattened into each command's arguments).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct ClipArg {
    /// Play this animation clip: its name, or its 0-based index as `animed
    /// info` lists them (default: the file's first).
    #[arg(long, value_name = "NAME|INDEX")]
    pub animation: Option<String>,
    /// glTF files with several scenes: load scene N (0-based; default: the
    /// file's own choice). Loading names the others.
    #[arg(long, value_name = "N")]
    pub scene: Option<usize>,
}

impl ClipArg {
    /// Loads `path` with `--scene`.
    pub fn load(&self, path: &Path) -> Result<Loaded, LoadError> {
        format::load_with_options(path, &LoadOptions { scene: self.scene })
    }

    /// Makes the chosen clip the playing one; without `--animation` the
    /// scene is left as loaded.
    pub fn apply(&self, scene: &mut Scene) -> Result<(), String> {
        match &self.animation {
            Some(spec) => scene.play_clip(spec),
            None => Ok(()),
        }
    }
}
