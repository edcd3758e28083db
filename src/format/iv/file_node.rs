//! Inventor's `File` node: the nodes of the file it names are its
//! children, traversed with the including file's state. SoFile is a group
//! whose children come from another file, so a Material set before it
//! colours what that file draws (Coin and SGI Inventor draw the chess
//! pieces of data/models/chess/chessboard.iv, files without a Material of
//! their own, in the gold or silver set before each `File`). VRML 1.0's
//! `WWWInline` and VRML97's `Inline` keep their files apart and graft them
//! (`format::inline`); so does a `File` naming anything but an ASCII
//! Inventor or VRML 1.0 file, or one that does not load (with its warning).

use super::build::{Builder, Cursor};
use super::state::State;
use crate::format::build_log::fmt_warning;
use crate::format::lexer::{self, Pos};
use crate::format::syntax::{self, NodeRef, Options, Parsed};
use crate::format::{gzip, inline, limits};
use crate::scene::{Node, NodeId};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// Files parsed for `File` nodes, by path (`None`: graft it instead), so a
/// file a scene names many times is read and warned about once.
pub type Files = HashMap<PathBuf, Option<Rc<Parsed>>>;

impl Builder {
    /// A `File` node: a group holding the named file's nodes, built in the
    /// current state (and leaving it changed, as a Group does).
    pub(super) fn file(&mut self, n: &NodeRef, st: &mut State, cur: &mut Cursor, name: String) {
        let Some(id) = self.add(n.pos, cur, Node::group(name)) else {
            return;
        };
        let urls = n.strings("name");
        let found = inline::resolve(&self.log.path, &urls)
            .filter(|_| self.depth < inline::MAX_DEPTH)
            .and_then(|file| Some((self.parsed_file(&file, n.pos)?, file)));
        let Some((parsed, file)) = found else {
            if limits::tripped().is_none() {
                self.graft(n.pos, &urls, id);
            }
            return;
        };
        // Warnings and texture names inside are the included file's.
        let path = std::mem::replace(&mut self.log.path, file.clone());
        let base = self.loader.set_base(&file);
        self.depth += 1;
        let mut inner = cur.inside(id, cur.separated);
        for root in &parsed.roots {
            self.node(root, st, &mut inner);
        }
        self.depth -= 1;
        self.loader.set_base(&base);
        self.log.path = path;
    }

    /// The scene of the file `urls` names, loaded apart and grafted under
    /// `id` (`WWWInline`, and a `File` that is not ASCII Inventor); a
    /// passed input limit ends the build.
    pub(super) fn graft(&mut self, at: Pos, urls: &[String], id: NodeId) {
        let r = inline::load_into(
            &mut self.scene,
            &mut self.log.warnings,
            &mut self.inlines,
            &self.log.path,
            at,
            urls,
            id,
            self.depth,
            self.build_depth,
        );
        if let Err(e) = r {
            self.stop(at, e);
        }
    }

    /// `file` parsed, once per path: `None` when it does not read, is not
    /// ASCII Inventor or VRML 1.0, or fails before its first node.
    fn parsed_file(&mut self, file: &Path, at: Pos) -> Option<Rc<Parsed>> {
        if let Some(p) = self.files.get(file) {
            return p.clone();
        }
        let p = self.read_parsed(file, at).map(Rc::new);
        self.files.insert(file.to_path_buf(), p.clone());
        p
    }

    fn read_parsed(&mut self, file: &Path, at: Pos) -> Option<Parsed> {
        let bytes = limits::read_file(file).ok()?;
        let bytes = if gzip::is_gzip(&bytes) {
            gzip::decompress(&bytes).ok()?
        } else {
            bytes
        };
        let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(&bytes);
        match lexer::read_header(bytes).ok()? {
            lexer::Header::Inventor1 | lexer::Header::Inventor2 | lexer::Header::Vrml1 => {}
            _ => return None,
        }
        let parsed = syntax::parse(bytes, Options::new(false));
        if let Some(e) = limits::tripped() {
            self.stop(at, e);
            return None;
        }
        if let Some((pos, msg)) = &parsed.error {
            if parsed.roots.is_empty() {
                return None;
            }
            let msg = format!("{msg} (the rest of the file is skipped)");
            self.log.warnings.push(fmt_warning(file, *pos, &msg));
        }
        for (pos, msg) in &parsed.warnings {
            self.log.warnings.push(fmt_warning(file, *pos, msg));
        }
        Some(parsed)
    }
}
