//! VRML97 rules the untyped parser can check as it reads (ISO/IEC 14772-1
//! §4.8 PROTO, §4.9 EXTERNPROTO, §5 field types, §6.40 Script), so files
//! that break them are flagged with a position instead of loading silently.
//! Rules that need every built-in node's field types (ROUTE type checks,
//! ROUTEs from/to plain fields, IS kinds) are in `events.rs`, with the
//! table in `node_table.rs`; the node/non-node IS check here stays for X3D
//! and for nodes whose interface is unknown.

use super::Value;

/// Built-in VRML97/X3D fields and events that hold nodes (SFNode or
/// MFNode) in every node that has them. An IS that binds one of them to a
/// non-node interface field (or the reverse) is a type mismatch. (`color`
/// is left out: a node in IndexedFaceSet, a colour in the lights and Fog.)
const NODE_FIELDS: &[&str] = &[
    "children",
    "addChildren",
    "removeChildren",
    "appearance",
    "geometry",
    "material",
    "texture",
    "textureTransform",
    "coord",
    "normal",
    "texCoord",
    "fontStyle",
    "choice",
    "level",
    "proxy",
    "source",
    "skin",
    "skeleton",
    "joints",
    "segments",
    "sites",
];

/// Whether an interface type (`SFBool`, `MFNode`…) holds nodes.
fn is_node_type(ty: &str) -> bool {
    ty == "SFNode" || ty == "MFNode"
}

/// The message for `field IS iface` when their types cannot match, given
/// the interface field's declared type.
pub(super) fn is_type_mismatch(field: &str, iface: &str, iface_type: &str) -> Option<String> {
    let field_holds_nodes = NODE_FIELDS.contains(&field);
    (field_holds_nodes != is_node_type(iface_type)).then(|| {
        format!(
            "'{field} IS {iface}': {iface} is {iface_type}, but {field} {} (§4.8.3: IS connects fields of the same type)",
            if field_holds_nodes {
                "holds nodes"
            } else {
                "does not hold nodes"
            }
        )
    })
}

/// Clashing names in a PROTO or EXTERNPROTO interface: a name declared
/// twice, or an eventIn `set_x` / eventOut `x_changed` beside an
/// exposedField `x`, which already has those events (§4.8.3, §5.1).
pub(super) fn interface_conflicts(decls: &[(String, String)]) -> Vec<String> {
    let mut out = Vec::new();
    for (i, (kw, name)) in decls.iter().enumerate() {
        if decls[..i].iter().any(|(_, n)| n == name) {
            out.push(format!("interface declares '{name}' twice"));
        }
        if kw == "exposedField" || kw == "inputOutput" {
            for (k2, n2) in decls {
                let implied = (*n2 == format!("set_{name}")
                    && (k2 == "eventIn" || k2 == "inputOnly"))
                    || (*n2 == format!("{name}_changed")
                        && (k2 == "eventOut" || k2 == "outputOnly"));
                if implied {
                    out.push(format!(
                        "{k2} '{n2}' clashes with exposedField '{name}', which already has it"
                    ));
                }
            }
        }
    }
    out
}

/// Whether a field name given in a node body is an event (which takes no
/// value): the `set_x` / `x_changed` events of exposed fields and Group's
/// `addChildren` / `removeChildren` (§4.10.2, §6.21).
pub(super) fn is_event_name(field: &str) -> bool {
    (field.starts_with("set_") && field.len() > 4)
        || (field.ends_with("_changed") && field.len() > 8)
        || field == "addChildren"
        || field == "removeChildren"
}

/// Built-in VRML97 fields that hold numbers in every node that has them
/// (SFFloat, SFTime, SFInt32 and the numeric vectors, §5). A string or a
/// bare word there would otherwise be dropped and the default used without
/// a word, so the reader says so at the value's own position.
const NUMBER_FIELDS: &[&str] = &[
    "ambientIntensity",
    "beamWidth",
    "bottomRadius",
    "center",
    "creaseAngle",
    "cutOffAngle",
    "cycleInterval",
    "fieldOfView",
    "height",
    "intensity",
    "radius",
    "rotation",
    "scale",
    "shininess",
    "spacing",
    "speed",
    "startTime",
    "stopTime",
    "translation",
    "transparency",
    "visibilityLimit",
    "whichChoice",
];

/// The message for a built-in number field given a string or a word.
pub(super) fn number_field_mismatch(field: &str, value: &Value) -> Option<String> {
    if !NUMBER_FIELDS.contains(&field) {
        return None;
    }
    let found = match value {
        Value::Strs(s) => format!("the string \"{}\"", s.first().map_or("", String::as_str)),
        Value::Words(w) => format!("'{}'", w.first().map_or("", String::as_str)),
        _ => return None,
    };
    Some(format!(
        "'{field}' takes numbers, found {found}; the default is used (§5)"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decls(v: &[(&str, &str)]) -> Vec<(String, String)> {
        v.iter()
            .map(|(k, n)| (k.to_string(), n.to_string()))
            .collect()
    }

    #[test]
    fn exposed_fields_own_their_events() {
        let c = interface_conflicts(&decls(&[("eventIn", "set_foo"), ("exposedField", "foo")]));
        assert_eq!(c.len(), 1, "{c:?}");
        let c = interface_conflicts(&decls(&[
            ("exposedField", "foo"),
            ("eventOut", "foo_changed"),
        ]));
        assert_eq!(c.len(), 1, "{c:?}");
        let c = interface_conflicts(&decls(&[("field", "a"), ("eventIn", "a")]));
        assert!(c[0].contains("twice"));
        assert!(interface_conflicts(&decls(&[
            ("field", "foo"),
            ("eventIn", "set_foo"),
            ("exposedField", "bar")
        ]))
        .is_empty());
    }

    #[test]
    fn is_types_must_agree_on_nodes() {
        assert!(is_type_mismatch("children", "val", "SFBool").is_some());
        assert!(is_type_mismatch("children", "kids", "MFNode").is_none());
        assert!(is_type_mismatch("translation", "t", "SFVec3f").is_none());
        assert!(is_type_mismatch("on", "n", "SFNode").is_some());
    }

    #[test]
    fn number_fields_refuse_strings_and_words() {
        let m = number_field_mismatch("cycleInterval", &Value::Strs(vec!["x".into()]));
        assert!(m.unwrap().contains("the string \"x\""));
        assert!(number_field_mismatch("radius", &Value::Words(vec!["TRUE".into()])).is_some());
        assert!(number_field_mismatch("radius", &Value::Nums(vec![1.0])).is_none());
        assert!(number_field_mismatch("radius", &Value::Is("r".into())).is_none());
        assert!(number_field_mismatch("url", &Value::Strs(vec!["a".into()])).is_none());
    }

    #[test]
    fn event_names() {
        assert!(is_event_name("set_children"));
        assert!(is_event_name("translation_changed"));
        assert!(is_event_name("addChildren"));
        assert!(!is_event_name("set_"));
        assert!(!is_event_name("children"));
    }
}
