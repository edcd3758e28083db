//! `--animation NAME|INDEX`: which clip plays, shared by every command that
//! loads a scene.

use crate::scene::Scene;

/// The clip to play (flattened into each command's arguments).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct ClipArg {
    /// Play this animation clip: its name, or its 0-based index as `animed
    /// info` lists them (default: the file's first).
    #[arg(long, value_name = "NAME|INDEX")]
    pub animation: Option<String>,
}

impl ClipArg {
    /// Makes the chosen clip the playing one; without `--animation` the
    /// scene is left as loaded.
    pub fn apply(&self, scene: &mut Scene) -> Result<(), String> {
        match &self.animation {
            Some(spec) => scene.play_clip(spec),
            None => Ok(()),
        }
    }
}
