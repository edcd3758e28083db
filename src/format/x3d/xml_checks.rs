//! The X3D XML encoding's share of the spec checks the classic parser
//! makes as it reads (`syntax::events`, with X3D's node table
//! `syntax::x3d_table`): attributes that name no field of their element's
//! node (or name an event, which takes no value), or whose numbers or
//! booleans do not fit the field's type; `<connect>` between a
//! node field and a ProtoDeclare field of another type, or of an access
//! the IS rules do not allow (ISO/IEC 19775-1, Concepts: PROTO definition
//! semantics, the same table as VRML97's table 4.4); ROUTEs between fields
//! of other types, or from/to a field that is not an event (Concepts:
//! route semantics); a child element whose explicit `containerField`
//! names no field of its parent, or a field that does not hold nodes, or
//! an event (ISO/IEC 19776-1: the child goes into the parent's SFNode or
//! MFNode field it names). Nodes whose interface is not known (vendor
//! extensions, components outside the table) are not checked.

use crate::format::lexer::Pos;
use crate::format::syntax::events::{self, owned, view, End, Typed};
use crate::format::syntax::node_table::Access;
use crate::format::syntax::{value_types, x3d_table};
use crate::format::syntax::{Field, Value};
use roxmltree::Node;
use std::rc::Rc;

/// A `<field name type accessType>` declaration (in a ProtoInterface or a
/// Script/shader node) as a typed interface entry; `None` when its access
/// or type is missing or not one X3D names.
pub(super) fn typed_decl(f: Node) -> Option<Typed> {
    let access = Access::from_keyword(f.attribute("accessType")?)?;
    let ty = f.attribute("type")?;
    let name = f.attribute("name")?;
    (ty.starts_with("SF") || ty.starts_with("MF")).then(|| (access, ty.into(), name.into()))
}

/// The interface of a built-in X3D node of type `kind`, with what it
/// declares itself (Script, shaders); `None` when the table does not know
/// the type.
pub(super) fn builtin(kind: &str, declared: &[Typed]) -> Option<Rc<Vec<Typed>>> {
    let mut iface = owned(&x3d_table::builtin(kind)?);
    iface.extend(declared.iter().cloned());
    Some(Rc::new(iface))
}

/// The attribute fields of an element of type `kind` that its node does
/// not have as a field (unknown names, or events), or whose numbers or
/// booleans do not fit the field's type (`value_types`), each with its
/// message.
pub(super) fn attribute_problems(kind: &str, fields: &[Field]) -> Vec<(Pos, String)> {
    if x3d_table::declares_fields(kind) {
        return Vec::new();
    }
    let Some(iface) = x3d_table::builtin(kind) else {
        return Vec::new();
    };
    let problem = |f: &Field| match events::field_problem(kind, &iface, &f.name) {
        Some(m) => Some(m),
        None => {
            let ty = iface.iter().find(|e| e.2 == f.name)?.1;
            value_types::xml_mismatch(kind, &f.name, ty, &f.value)
        }
    };
    fields
        .iter()
        .filter(|f| !matches!(f.value, Value::Nodes(_) | Value::Is(_)))
        .filter_map(|f| Some((f.pos, problem(f)?)))
        .collect()
}

/// What is wrong with a child element's explicit `containerField="name"`
/// under a parent element of type `kind` (with what the parent declares
/// itself, for Script and shaders): a name the parent does not have, a
/// field that holds no nodes, or an event. `None` when the parent's type
/// is not in the table.
pub(super) fn container_problem(kind: &str, declared: &[Typed], name: &str) -> Option<String> {
    let iface = builtin(kind, declared)?;
    let iface = view(&iface);
    let at = format!("containerField '{name}'");
    match events::member(&iface, name) {
        None => Some(format!("{at}: {kind} has no field '{name}'")),
        Some((_, ty)) if ty != "SFNode" && ty != "MFNode" => Some(format!(
            "{at}: '{name}' of {kind} is {ty}, not a field that holds nodes (SFNode or MFNode)"
        )),
        Some((a @ (Access::In | Access::Out), _)) => Some(format!(
            "{at}: '{name}' is {} of {kind}; a child node goes into a field",
            a.with_article()
        )),
        Some(_) => None,
    }
}

/// What is wrong with `<connect nodeField protoField>` in a node of type
/// `kind` with interface `node`, inside a ProtoDeclare whose interface is
/// `proto` (an undeclared protoField is the PROTO expansion's to report).
pub(super) fn connect_problem(
    kind: &str,
    node: &[Typed],
    node_field: &str,
    proto: &[Typed],
    proto_field: &str,
) -> Option<String> {
    let (a, ty, name) = proto.iter().find(|d| d.2 == proto_field)?;
    events::is_problem(kind, &view(node), node_field, (*a, ty, name))
}

/// One end of a ROUTE as the reader knows it: DEF name, the type the file
/// wrote, its interface when known, and the field named.
pub(super) struct RouteEnd<'a> {
    pub node: &'a str,
    pub kind: &'a str,
    pub iface: Option<&'a [Typed]>,
    pub field: &'a str,
}

/// What is wrong with a ROUTE from `from` to `to`, one message per
/// problem (see `events::route_problems`).
pub(super) fn route_problems(from: &RouteEnd, to: &RouteEnd) -> Vec<String> {
    let (fv, tv) = (from.iface.map(view), to.iface.map(view));
    events::route_problems(
        &End {
            node: from.node,
            kind: from.kind,
            field: from.field,
            iface: fv.as_deref(),
        },
        &End {
            node: to.node,
            kind: to.kind,
            field: to.field,
            iface: tv.as_deref(),
        },
    )
}
