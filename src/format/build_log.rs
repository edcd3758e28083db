//! What a scene builder reports besides the scene: its warnings and the
//! first input limit it passed.
//!
//! The Inventor/VRML 1.0 and the VRML97 builders keep the same account in
//! the same way (warnings capped, some once per kind, the first limit
//! error kept and every later node refused), so it lives here once and both
//! delegate to it.

use crate::format::lexer::Pos;
use crate::format::limits::{self, LimitError};
use crate::format::{LoadError, Loaded};
use crate::scene::{Node, NodeKind, Scene};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// Most warnings one build keeps (a hostile file could make millions).
const MAX_WARNINGS: usize = 10_000;

/// `path:line:column: message`.
pub(crate) fn fmt_warning(path: &Path, pos: Pos, msg: &str) -> String {
    if pos.line == 0 {
        // A binary file's place: line 0, the byte offset in `column`.
        return format!("{}: byte {}: {}", path.display(), pos.column, msg);
    }
    format!("{}:{}:{}: {}", path.display(), pos.line, pos.column, msg)
}

/// A builder's warnings and its fatal input-limit error.
pub(crate) struct BuildLog {
    /// The file being built (warnings and errors name it).
    pub path: PathBuf,
    pub warnings: Vec<String>,
    /// Keys already warned about by [`BuildLog::warn_once`].
    warned: HashSet<String>,
    /// Set when an input limit was passed: nothing more is added.
    full: bool,
    /// The first input limit passed: the load fails with it.
    fatal: Option<LoadError>,
}

impl BuildLog {
    pub fn new(path: &Path) -> Self {
        BuildLog {
            path: path.to_path_buf(),
            warnings: Vec::new(),
            warned: HashSet::new(),
            full: false,
            fatal: None,
        }
    }

    /// Whether an input limit was passed (the builder adds nothing more).
    pub fn full(&self) -> bool {
        self.full
    }

    /// The scene with the warnings, or the input limit the build passed.
    pub fn finish(self, scene: Scene) -> Result<Loaded, LoadError> {
        if let Some(e) = self.fatal {
            return Err(e);
        }
        Ok(Loaded {
            scene,
            warnings: self.warnings,
        })
    }

    /// Ends the build with a passed input limit (the first one is kept).
    pub fn stop(&mut self, pos: Pos, e: LimitError) {
        self.full = true;
        if self.fatal.is_none() {
            self.fatal = Some(LoadError::new(
                &self.path,
                pos.line,
                pos.column,
                e.to_string(),
            ));
        }
    }

    /// Counts a new scene node against the budget (and its mesh in `scene`,
    /// once per instance); false, with the build stopped, when over.
    pub fn charge(&mut self, pos: Pos, scene: &Scene, node: &Node) -> bool {
        let geometry = match &node.kind {
            NodeKind::Shape(s) => scene
                .meshes
                .get(s.mesh.0 as usize)
                .map_or(0, |m| (m.positions.len() + m.triangles.len()) as u64),
            _ => 0,
        };
        match limits::charge_nodes(1).and_then(|()| limits::charge_geometry(geometry)) {
            Ok(()) => true,
            Err(e) => {
                self.stop(pos, e);
                false
            }
        }
    }

    /// A warning at `pos` (dropped beyond [`MAX_WARNINGS`]).
    pub fn warn(&mut self, pos: Pos, msg: &str) {
        if self.warnings.len() < MAX_WARNINGS {
            self.warnings.push(fmt_warning(&self.path, pos, msg));
        }
    }

    /// Warns once per `key` (e.g. once per unknown node type).
    pub fn warn_once(&mut self, key: &str, pos: Pos, msg: &str) {
        if self.warned.insert(key.to_string()) {
            self.warn(pos, msg);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pos(line: u32, column: u32) -> Pos {
        Pos { line, column }
    }

    #[test]
    fn warnings_are_positioned_and_once_per_key() {
        let mut log = BuildLog::new(Path::new("a.wrl"));
        log.warn(pos(1, 2), "one");
        log.warn_once("k", pos(3, 4), "two");
        log.warn_once("k", pos(5, 6), "three");
        let l = log.finish(Scene::new()).expect("no limit passed");
        assert_eq!(l.warnings, vec!["a.wrl:1:2: one", "a.wrl:3:4: two"]);
    }

    #[test]
    fn the_first_limit_passed_fails_the_build() {
        let mut log = BuildLog::new(Path::new("b.iv"));
        assert!(!log.full());
        let limit = |max| LimitError {
            limit: limits::Limit::Nodes,
            max,
        };
        log.stop(pos(7, 8), limit(11));
        log.stop(pos(9, 9), limit(22));
        assert!(log.full());
        let e = log.finish(Scene::new()).expect_err("a limit was passed");
        let msg = e.to_string();
        assert!(msg.starts_with("b.iv:7:8: "), "{msg}");
        assert!(msg.contains("more than 11 "), "{msg}");
    }
}
