//! Whether a field's untyped value fits the type its built-in node gives
//! it (ISO/IEC 14772-1 §5, the field types: SFBool is TRUE or FALSE,
//! SFString one quoted string, SFInt32 a whole number, SFVec3f three
//! numbers, an MF field any number of its single values, SFNode a node
//! or NULL…; X3D's classic encoding, ISO/IEC 19776-2, writes them the
//! same way). The parser reads values without types, so a word, a string
//! or a wrong count of numbers would otherwise be dropped or misread
//! without a word.

use super::Value;

/// How many numbers one value of the numeric type `base` (the name after
/// `SF`/`MF`) holds, and whether they must be whole; `None` for a type
/// that is not numbers.
fn numbers_per_value(base: &str) -> Option<(usize, bool)> {
    Some(match base {
        "Int32" => (1, true),
        "Float" | "Time" | "Double" => (1, false),
        "Vec2f" | "Vec2d" => (2, false),
        "Vec3f" | "Vec3d" | "Color" => (3, false),
        "Rotation" | "ColorRGBA" | "Vec4f" | "Vec4d" => (4, false),
        "Matrix3f" | "Matrix3d" => (9, false),
        "Matrix4f" | "Matrix4d" => (16, false),
        _ => return None,
    })
}

/// A short description of a value as written, for messages.
fn found(value: &Value) -> String {
    let count = |n: usize, one: &str, many: &str| match n {
        1 => format!("1 {one}"),
        n => format!("{n} {many}"),
    };
    match value {
        Value::Nums(n) if n.len() == 1 => format!("the number {}", n[0]),
        Value::Nums(n) => count(n.len(), "number", "numbers"),
        Value::Strs(s) if s.len() == 1 => format!("the string \"{}\"", s[0]),
        Value::Strs(s) => count(s.len(), "string", "strings"),
        Value::Words(w) => format!("'{}'", w.first().map_or("", String::as_str)),
        Value::Nodes(n) => count(n.len(), "node", "nodes"),
        Value::Is(name) => format!("IS {name}"),
        Value::Empty => "[ ]".into(),
    }
}

/// What a value of type `ty` is, for messages.
fn wanted(ty: &str) -> String {
    let (single, base) = (ty.starts_with("SF"), ty.get(2..).unwrap_or(""));
    match (base, numbers_per_value(base)) {
        ("Bool", _) if single => "TRUE or FALSE".into(),
        ("Bool", _) => "TRUE and FALSE words".into(),
        ("String", _) if single => "one quoted string".into(),
        ("String", _) => "quoted strings".into(),
        ("Node", _) if single => "a node or NULL".into(),
        ("Node", _) => "nodes".into(),
        (_, Some((1, true))) if single => "a whole number".into(),
        (_, Some((1, true))) => "whole numbers".into(),
        (_, Some((1, false))) if single => "a number".into(),
        (_, Some((1, false))) => "numbers".into(),
        (_, Some((k, _))) if single => format!("{k} numbers"),
        (_, Some((k, _))) => format!("numbers in groups of {k}"),
        _ => "a value of that type".into(),
    }
}

/// Whether `value` fits type `ty` (`SFBool`, `MFVec3f`…); `None` for a
/// type this module does not check (SFImage, MFImage and any other).
fn fits(ty: &str, value: &Value) -> Option<bool> {
    let single = ty.starts_with("SF");
    let base = ty.get(2..)?;
    let is_bool = |w: &String| w == "TRUE" || w == "FALSE";
    Some(match (base, value) {
        (_, Value::Is(_)) => true,
        (_, Value::Empty) => !single,
        ("Node", Value::Nodes(n)) => !single || n.len() <= 1,
        ("Node", _) => false,
        ("Bool", Value::Words(w)) => (!single || w.len() == 1) && w.iter().all(is_bool),
        ("Bool", _) => false,
        ("String", Value::Strs(s)) => !single || s.len() == 1,
        ("String", _) => false,
        ("Image", _) => return None,
        _ => {
            let (k, whole) = numbers_per_value(base)?;
            let Value::Nums(n) = value else {
                return Some(false);
            };
            let count = if single {
                n.len() == k
            } else {
                n.len() % k == 0
            };
            count && (!whole || n.iter().all(|x| x.fract() == 0.0))
        }
    })
}

/// The message for `field` of a built-in node of type `kind`, whose type
/// is `ty`, given `value`; `None` when it fits or is not checked.
pub(super) fn mismatch(kind: &str, field: &str, ty: &str, value: &Value) -> Option<String> {
    if fits(ty, value)? {
        return None;
    }
    let numeric = numbers_per_value(ty.get(2..).unwrap_or("")).is_some();
    let takes = if numeric && !matches!(value, Value::Nums(_)) {
        // A word or a string where numbers belong.
        "numbers".to_string()
    } else {
        wanted(ty)
    };
    Some(format!(
        "'{field}' of {kind} is {ty} and takes {takes}, found {} (§5)",
        found(value)
    ))
}

/// The same check for an attribute of X3D's XML encoding (ISO/IEC
/// 19776-1), for the numeric and boolean types only: there an SFString is
/// written unquoted, so a string's shape cannot be told, and an empty
/// attribute is an empty list.
pub(crate) fn xml_mismatch(kind: &str, field: &str, ty: &str, value: &Value) -> Option<String> {
    let base = ty.get(2..)?;
    if base != "Bool" && numbers_per_value(base).is_none() {
        return None;
    }
    let value = match value {
        Value::Strs(s) if s.iter().all(|s| s.trim().is_empty()) => Value::Empty,
        // XML writes `true` and `false` (the reader takes either case).
        Value::Words(w) => Value::Words(w.iter().map(|w| w.to_uppercase()).collect()),
        v => v.clone(),
    };
    let m = mismatch(kind, field, ty, &value)?;
    Some(
        m.replace("TRUE or FALSE", "true or false")
            .replace("TRUE and FALSE", "true and false"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nums(n: &[f64]) -> Value {
        Value::Nums(n.to_vec())
    }

    fn words(w: &[&str]) -> Value {
        Value::Words(w.iter().map(|s| s.to_string()).collect())
    }

    #[test]
    fn values_of_the_right_shape_fit() {
        for (ty, v) in [
            ("SFVec3f", nums(&[1.0, 2.0, 3.0])),
            ("MFVec3f", nums(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0])),
            ("MFVec3f", Value::Empty),
            ("SFRotation", nums(&[0.0, 1.0, 0.0, 1.5])),
            ("SFInt32", nums(&[-1.0])),
            ("MFInt32", nums(&[0.0, 1.0, 2.0, -1.0])),
            ("SFBool", words(&["TRUE"])),
            ("MFString", Value::Strs(vec!["a".into(), "b".into()])),
            ("SFString", Value::Strs(vec!["a".into()])),
            ("SFNode", Value::Nodes(Vec::new())),
            ("SFFloat", Value::Is("x".into())),
        ] {
            assert_eq!(mismatch("N", "f", ty, &v), None, "{ty} {v:?}");
        }
        // Not checked.
        assert_eq!(mismatch("N", "f", "SFImage", &words(&["x"])), None);
        assert_eq!(mismatch("N", "f", "SFWhatever", &words(&["x"])), None);
    }

    #[test]
    fn wrong_shapes_are_named() {
        let m = |ty, v| mismatch("Transform", "f", ty, &v).expect("flagged");
        assert_eq!(
            m("SFVec3f", nums(&[1.0])),
            "'f' of Transform is SFVec3f and takes 3 numbers, found the number 1 (§5)"
        );
        assert!(m("MFVec2f", nums(&[1.0, 2.0, 3.0])).contains("in groups of 2, found 3 numbers"));
        assert!(m("SFInt32", nums(&[1.5])).contains("a whole number, found the number 1.5"));
        assert!(m("SFBool", nums(&[1.0])).contains("TRUE or FALSE, found the number 1"));
        assert!(m("SFBool", words(&["YES"])).contains("found 'YES'"));
        assert!(m("SFString", nums(&[3.0])).contains("one quoted string, found the number 3"));
        assert!(m("MFString", words(&["EXAMINE"])).contains("quoted strings, found 'EXAMINE'"));
        assert!(m("SFTime", words(&["TRUE"])).contains("takes numbers, found 'TRUE'"));
        assert!(m("SFNode", nums(&[1.0])).contains("a node or NULL"));
        assert!(m("SFColor", Value::Empty).contains("found [ ]"));
    }
}
