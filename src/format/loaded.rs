use crate::scene::Scene;

/// A loaded scene plus what the reader could not fully use.
#[derive(Debug, Default)]
pub struct Loaded {
    pub scene: Scene,
    /// Non-fatal problems (unknown node, unsupported feature), each already
    /// formatted as `path:line:column: message`.
    pub warnings: Vec<String>,
}
