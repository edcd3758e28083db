//! The parser's side of the ROUTE and IS checks (`syntax::events`): which
//! interface a node has — a built-in VRML97 node's (`node_table`), a PROTO
//! or EXTERNPROTO's as declared, a Script's own fields plus what it
//! declares — and the warnings, at the ROUTE statement or the IS field.
//! An X3D file (classic encoding) is checked against X3D's own node table
//! (`x3d_table`), by the node type the file wrote (before the reader's
//! rewrite maps it onto a VRML97 node). Both get a warning for a field
//! name their built-in node does not have.

use super::super::checks;
use super::super::events::{self, End};
use super::super::node_table::{self, Access, Entry};
use super::super::x3d_table;
use super::super::NodeRef;
use super::Parser;
use crate::format::lexer::Pos;
use std::rc::Rc;

pub use super::super::events::Typed;
use super::super::events::{owned, view};

impl Parser<'_> {
    /// Whether the field-level rules of this module apply.
    fn checks_interfaces(&self) -> bool {
        self.opts.vrml97
    }

    /// Keeps a PROTO or EXTERNPROTO interface (keyword, type, name) for the
    /// checks; declarations with an unknown keyword are left out.
    pub(super) fn record_interface(&mut self, name: &str, decls: &[(String, String, String)]) {
        let typed: Vec<Typed> = decls
            .iter()
            .filter_map(|(kw, ty, n)| Some((Access::from_keyword(kw)?, ty.clone(), n.clone())))
            .collect();
        self.scope()
            .interfaces
            .insert(name.to_string(), Rc::new(typed));
    }

    /// Records a Script's interface declaration `kw ty name` and returns
    /// its access and type (for an IS on it); `None` outside a Script.
    pub(super) fn declare(
        &mut self,
        kind: &str,
        kw: &str,
        ty: &str,
        name: &str,
    ) -> Option<(Access, String)> {
        let access = Access::from_keyword(kw)?;
        if !x3d_table::declares_fields(kind) {
            return None;
        }
        let decls = self.script_decls.last_mut()?;
        decls.push((access, ty.to_string(), name.to_string()));
        Some((access, ty.to_string()))
    }

    /// Files the interface the Script just read declared (popped from
    /// `script_decls`) under the node. Never inlined: `node_body`
    /// recurses once per nesting level.
    #[inline(never)]
    pub(super) fn keep_script_interface(&mut self, node: &NodeRef) {
        if let Some(d) = self.script_decls.pop().filter(|d| !d.is_empty()) {
            self.node_ifaces
                .insert(Rc::as_ptr(node), (node.clone(), Rc::new(d)));
        }
    }

    /// The interface of nodes of type `kind`: a PROTO or EXTERNPROTO in
    /// scope (nearest first), else a built-in node's (X3D's table in an
    /// X3D file).
    fn interface_of_kind(&self, kind: &str) -> Option<Vec<Typed>> {
        let declared = self
            .scopes
            .iter()
            .rev()
            .find_map(|s| s.interfaces.get(kind).cloned());
        match declared {
            Some(d) => Some(d.as_ref().clone()),
            None if self.opts.x3d => x3d_table::builtin(kind).as_deref().map(owned),
            None => node_table::builtin(kind).map(owned),
        }
    }

    /// The type the file wrote for `node` (an X3D node keeps it when the
    /// rewrite renamed it).
    fn written_kind<'n>(&'n self, node: &'n NodeRef) -> &'n str {
        match self.written_kinds.get(&Rc::as_ptr(node)) {
            Some((_, k)) => k,
            None => &node.kind,
        }
    }

    /// The message for a field named `field` in a built-in node of type
    /// `kind` (VRML97's §6 table, or X3D's in an X3D file) that has no
    /// such field, or has it as an event (which takes no value). Nodes
    /// that declare fields (Script, shaders) have their own names checked
    /// when declared; other nodes (vendor extensions) are not checked.
    pub(super) fn unknown_field(&self, kind: &str, field: &str) -> Option<String> {
        if x3d_table::declares_fields(kind) {
            return None;
        }
        if self.opts.x3d {
            return events::field_problem(kind, &x3d_table::builtin(kind)?, field);
        }
        let vrml = node_table::builtin(kind)?;
        let m = events::field_problem(kind, vrml, field)?;
        // Say so when the name is X3D's (a VRML97 file written with it).
        let x3d_only = events::member(vrml, field).is_none()
            && x3d_table::builtin(kind).is_some_and(|t| events::member(&t, field).is_some());
        Some(match x3d_only {
            true => format!("{m} (X3D's {kind} has it; VRML97's does not, §6)"),
            false => m,
        })
    }

    /// The type a built-in node of type `kind` gives its field (or
    /// exposedField) `field`: VRML97's table, or X3D's in an X3D file.
    /// `None` for events, other names and other nodes.
    pub(super) fn builtin_field_type(&self, kind: &str, field: &str) -> Option<&'static str> {
        let pick = |e: &Entry| {
            (e.2 == field && matches!(e.0, Access::Field | Access::Exposed)).then_some(e.1)
        };
        if self.opts.x3d {
            return x3d_table::builtin(kind)?.iter().find_map(pick);
        }
        node_table::builtin(kind)?.iter().find_map(pick)
    }

    /// The interface of one node: its type's, plus what a Script declares.
    fn interface_of(&self, node: &NodeRef) -> Option<Vec<Typed>> {
        let mut iface = self.interface_of_kind(self.written_kind(node))?;
        if let Some((_, d)) = self.node_ifaces.get(&Rc::as_ptr(node)) {
            iface.extend(d.iter().cloned());
        }
        Some(iface)
    }

    /// Warns about `ROUTE a.f TO b.g` (see `events::route_problems`) at
    /// the ROUTE statement.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    pub(super) fn check_route(
        &mut self,
        a: &str,
        from: &NodeRef,
        f: &str,
        b: &str,
        to: &NodeRef,
        g: &str,
        pos: Pos,
    ) {
        if !self.checks_interfaces() {
            return;
        }
        let (fi, ti) = (self.interface_of(from), self.interface_of(to));
        let (fv, tv) = (fi.as_deref().map(view), ti.as_deref().map(view));
        let problems = events::route_problems(
            &End {
                node: a,
                kind: self.written_kind(from),
                field: f,
                iface: fv.as_deref(),
            },
            &End {
                node: b,
                kind: self.written_kind(to),
                field: g,
                iface: tv.as_deref(),
            },
        );
        for m in problems {
            self.warn(pos, m);
        }
    }

    /// The message for `field IS iface` in a node of type `kind`, where the
    /// PROTO declares `iface` as `kw ty`; `own` is the field's declared
    /// access and type when a Script declares it.
    #[inline(never)]
    pub(super) fn is_mismatch(
        &self,
        kind: &str,
        field: &str,
        own: Option<(Access, String)>,
        kw: &str,
        ty: &str,
        iface: &str,
    ) -> Option<String> {
        let node: Option<Vec<Typed>> = match own {
            Some((a, t)) => Some(vec![(a, t, field.to_string())]),
            None => self.interface_of_kind(kind),
        };
        match (node, Access::from_keyword(kw)) {
            (Some(n), Some(access)) if self.checks_interfaces() => {
                events::is_problem(kind, &view(&n), field, (access, ty, iface))
            }
            _ => checks::is_type_mismatch(field, iface, ty),
        }
    }
}
