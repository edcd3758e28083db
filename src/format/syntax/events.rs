//! ROUTE and IS rules that need to know each node's fields (ISO/IEC
//! 14772-1): a ROUTE goes from an eventOut (or exposedField) to an eventIn
//! (or exposedField) of exactly the same type (§4.10.2, §5.1); `f IS g`
//! in a PROTO body connects a field and an interface declaration of the
//! same type whose kinds fit Table 4.4 of §4.8.3 (an interface
//! exposedField only to an exposedField; a field to a field or
//! exposedField; an eventIn to an eventIn or exposedField; an eventOut to
//! an eventOut or exposedField).
//!
//! Interfaces come from `node_table` for built-in nodes and from the
//! file for PROTOs, EXTERNPROTOs and Script nodes; a node whose
//! interface is unknown is not checked.

use super::node_table::{Access, Entry};

/// One interface entry: access, type, name.
pub type Decl<'a> = (Access, &'a str, &'a str);

/// One declaration of a file's interface (a PROTO's, a Script's): access,
/// type, name.
pub type Typed = (Access, String, String);

/// Borrowed view of typed declarations.
pub fn view(t: &[Typed]) -> Vec<Decl<'_>> {
    t.iter()
        .map(|(a, ty, n)| (*a, ty.as_str(), n.as_str()))
        .collect()
}

/// A built-in node's table entries as typed declarations.
pub fn owned(t: &[Entry]) -> Vec<Typed> {
    t.iter()
        .map(|(a, ty, n)| (*a, ty.to_string(), n.to_string()))
        .collect()
}

/// The access and type of `name` on a node with interface `iface`: a
/// declared field or event, or an exposedField's `set_x` (eventIn) or
/// `x_changed` (eventOut) (§4.7).
pub fn member<'a>(iface: &[Decl<'a>], name: &str) -> Option<(Access, &'a str)> {
    if let Some((a, ty, _)) = iface.iter().find(|d| d.2 == name) {
        return Some((*a, ty));
    }
    let exposed = |base: &str| {
        iface
            .iter()
            .find(|d| d.2 == base && d.0 == Access::Exposed)
            .map(|d| d.1)
    };
    if let Some(ty) = name.strip_prefix("set_").and_then(exposed) {
        return Some((Access::In, ty));
    }
    let ty = name.strip_suffix("_changed").and_then(exposed)?;
    Some((Access::Out, ty))
}

/// One side of a ROUTE: the DEF name as written, the node's type, the
/// field named, and the node's interface when it is known.
pub struct End<'a> {
    pub node: &'a str,
    pub kind: &'a str,
    pub field: &'a str,
    pub iface: Option<&'a [Decl<'a>]>,
}

/// The event type of one side of a ROUTE (`sends`: the from side), or
/// the message saying why it is not an event that can be used so.
fn event<'a>(end: &End<'a>, sends: bool) -> Result<Option<&'a str>, String> {
    let Some(iface) = end.iface else {
        return Ok(None);
    };
    let (node, kind, f) = (end.node, end.kind, end.field);
    let (want, side) = if sends {
        (Access::Out, "from")
    } else {
        (Access::In, "to")
    };
    match member(iface, f) {
        Some((a, ty)) if a == want || a == Access::Exposed => Ok(Some(ty)),
        Some((Access::Field, _)) => Err(format!(
            "ROUTE {side} {node}.{f}: '{f}' is a field of {kind}, not {} or exposedField; {} (§4.10.2)",
            want.with_article(),
            if sends {
                "it sends no events"
            } else {
                "it takes no events"
            }
        )),
        Some((a, _)) => Err(format!(
            "ROUTE {side} {node}.{f}: '{f}' is {} of {kind}; a ROUTE goes from an eventOut to an eventIn (§4.10.2)",
            a.with_article()
        )),
        None => Err(format!(
            "ROUTE {side} {node}.{f}: {kind} has no {} '{f}'",
            want.keyword()
        )),
    }
}

/// What is wrong with `ROUTE from TO to`, one message per problem.
pub fn route_problems(from: &End, to: &End) -> Vec<String> {
    let a = event(from, true);
    let b = event(to, false);
    let mut out = Vec::new();
    if let (Ok(Some(ta)), Ok(Some(tb))) = (&a, &b) {
        if ta != tb {
            out.push(format!(
                "ROUTE {}.{} TO {}.{}: {ta} to {tb}; a ROUTE connects events of the same type (§4.10.2)",
                from.node, from.field, to.node, to.field
            ));
        }
    }
    out.extend(a.err());
    out.extend(b.err());
    out
}

/// What is wrong with giving `field` a value in a node of type `kind`
/// with interface `iface`: a name the node does not have, or an event
/// (events take no value, §4.10.2).
pub fn field_problem(kind: &str, iface: &[Decl], field: &str) -> Option<String> {
    match member(iface, field) {
        Some((Access::Field | Access::Exposed, _)) => None,
        Some((a, _)) => Some(format!(
            "'{field}' is {} of {kind} and takes no value in a node body (§4.10.2)",
            a.with_article()
        )),
        None => Some(format!("{kind} has no field '{field}'")),
    }
}

/// What is wrong with `field IS name` in a node of type `kind` with
/// interface `node`, where the PROTO declares `name` as `decl`.
pub fn is_problem(kind: &str, node: &[Decl], field: &str, decl: Decl) -> Option<String> {
    let (ia, ity, name) = decl;
    let Some((fa, fty)) = member(node, field) else {
        return Some(format!(
            "'{field} IS {name}': {kind} has no field or event '{field}'"
        ));
    };
    if fty != ity {
        return Some(format!(
            "'{field} IS {name}': {field} is {fty} but {name} is {ity} (§4.8.3: IS connects fields of the same type)"
        ));
    }
    let fits = match ia {
        Access::Exposed => fa == Access::Exposed,
        _ => fa == ia || fa == Access::Exposed,
    };
    (!fits).then(|| {
        format!(
            "'{field} IS {name}': {name} is {} but {field} is {} of {kind} (§4.8.3, table 4.4)",
            ia.with_article(),
            fa.with_article()
        )
    })
}

#[cfg(test)]
mod tests {
    use super::super::node_table::builtin;
    use super::*;

    fn end<'a>(node: &'a str, kind: &'a str, field: &'a str) -> End<'a> {
        End {
            node,
            kind,
            field,
            iface: builtin(kind),
        }
    }

    #[test]
    fn exposed_fields_have_set_and_changed_events() {
        let t = builtin("Transform").unwrap();
        assert_eq!(member(t, "set_translation"), Some((Access::In, "SFVec3f")));
        assert_eq!(
            member(t, "rotation_changed"),
            Some((Access::Out, "SFRotation"))
        );
        assert_eq!(member(t, "bboxSize_changed"), None, "a field has no events");
    }

    #[test]
    fn good_routes_pass() {
        for (a, ak, f, b, bk, g) in [
            (
                "T",
                "TimeSensor",
                "fraction_changed",
                "P",
                "PositionInterpolator",
                "set_fraction",
            ),
            (
                "P",
                "PositionInterpolator",
                "value_changed",
                "X",
                "Transform",
                "set_translation",
            ),
            (
                "P",
                "PositionInterpolator",
                "value_changed",
                "X",
                "Transform",
                "translation",
            ),
            (
                "S",
                "TouchSensor",
                "touchTime",
                "T",
                "TimeSensor",
                "startTime",
            ),
            (
                "S",
                "Switch",
                "whichChoice_changed",
                "Q",
                "Switch",
                "set_whichChoice",
            ),
        ] {
            let p = route_problems(&end(a, ak, f), &end(b, bk, g));
            assert!(p.is_empty(), "{a}.{f} → {b}.{g}: {p:?}");
        }
    }

    #[test]
    fn plain_fields_unknown_events_and_type_mismatches_are_named() {
        let p = route_problems(
            &end("T", "TimeSensor", "fraction_changed"),
            &end("X", "Transform", "bboxSize"),
        );
        assert_eq!(p.len(), 1, "{p:?}");
        assert!(p[0].contains("'bboxSize' is a field of Transform"), "{p:?}");
        let p = route_problems(
            &end("T", "TimeSensor", "fraction_changed"),
            &end("X", "Transform", "set_translation"),
        );
        assert!(p[0].contains("SFFloat to SFVec3f"), "{p:?}");
        let p = route_problems(
            &end("T", "TimeSensor", "fraction"),
            &end("X", "Transform", "set_fraction"),
        );
        assert_eq!(p.len(), 2, "{p:?}");
        assert!(p[0].contains("TimeSensor has no eventOut 'fraction'"));
        assert!(p[1].contains("Transform has no eventIn 'set_fraction'"));
        let p = route_problems(
            &end("P", "PositionInterpolator", "set_fraction"),
            &end("T", "TimeSensor", "isActive"),
        );
        assert!(
            p[0].contains("is an eventIn of PositionInterpolator"),
            "{p:?}"
        );
        assert!(p[1].contains("is an eventOut of TimeSensor"), "{p:?}");
        // Unknown interfaces are not checked.
        let unknown = End {
            node: "H",
            kind: "Humanoid",
            field: "anything",
            iface: None,
        };
        assert!(route_problems(&unknown, &end("X", "Transform", "translation")).is_empty());
    }

    #[test]
    fn is_follows_table_4_4() {
        let g = builtin("Group").unwrap();
        let t = builtin("Transform").unwrap();
        let b = builtin("Box").unwrap();
        use Access::*;
        assert!(is_problem("Group", g, "children", (Exposed, "MFNode", "kids")).is_none());
        assert!(
            is_problem("Group", g, "children", (Exposed, "SFBool", "val"))
                .unwrap()
                .contains("MFNode but val is SFBool")
        );
        assert!(is_problem("Transform", t, "set_translation", (In, "SFVec3f", "t")).is_none());
        assert!(is_problem("Transform", t, "translation", (In, "SFVec3f", "t")).is_none());
        assert!(is_problem("Transform", t, "translation", (Field, "SFVec3f", "t")).is_none());
        // An interface exposedField to a plain field, or an eventOut to an
        // eventIn, does not fit.
        assert!(is_problem("Box", b, "size", (Exposed, "SFVec3f", "s")).is_some());
        assert!(is_problem("Transform", t, "set_translation", (Out, "SFVec3f", "t")).is_some());
        assert!(is_problem("Box", b, "radius", (Field, "SFFloat", "r"))
            .unwrap()
            .contains("Box has no field or event 'radius'"));
    }
}
