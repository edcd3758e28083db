//! Inventor node kits (`ShapeKit`, `SeparatorKit`, `AppearanceKit`,
//! `WrapperKit`, `SceneKit`…) read as the groups they expand to.
//!
//! A kit is a Separator-like group whose parts are node-valued fields
//! (`material Material {…}`, `shape Cube {}`, `childList NodeKitListPart
//! {…}`). The Inventor Toolmaker's catalogs (ch. 7) traverse the parts in
//! catalog order: state parts (appearance, transform…) first, then the
//! shape and child list, so a kit draws as a Separator holding its parts in
//! that order. Parts this reader does not name go in file order before the
//! shape and children.

use crate::format::syntax::{AstNode, NodeRef, Value};

/// Catalog order of the parts animed knows (SoSeparatorKit, SoShapeKit,
/// SoAppearanceKit, SoBaseKit, SoWrapperKit, SoSceneKit): what is
/// traversed first comes first.
const PART_ORDER: &[&str] = &[
    "callbackList",
    "pickStyle",
    "appearance",
    "lightModel",
    "environment",
    "drawStyle",
    "material",
    "complexity",
    "texture2",
    "font",
    "units",
    "transform",
    "texture2Transform",
    "materialBinding",
    "normalBinding",
    "textureCoordinateBinding",
    "shapeHints",
    "coordinate3",
    "coordinate4",
    "normal",
    "textureCoordinate2",
    "textureCoordinateFunction",
    "profileCoordinates",
    "profileList",
    "localTransform",
    "contents",
    "cameraList",
    "lightList",
    "shape",
    "childList",
];

/// Whether `kind` is a node kit (or a kit's list part) read as a group.
pub fn is_kit(kind: &str) -> bool {
    kind.ends_with("Kit") || kind == "NodeKitListPart"
}

/// Whether the kit keeps its state to itself (a `topSeparator`, as
/// SeparatorKit, ShapeKit, WrapperKit, SceneKit, LightKit, CameraKit):
/// an AppearanceKit sets state for what follows it in its parent kit, and
/// a list part is traversed in place.
pub fn separates(kind: &str) -> bool {
    !matches!(kind, "AppearanceKit" | "NodeKitListPart")
}

/// The nodes a kit traverses, in order: its parts by [`PART_ORDER`], the
/// unnamed ones in file order before `shape`/`childList`; a list part
/// (`NodeKitListPart`) gives its `childList` (its `containerNode` only
/// decides the group type, a Separator or Group, which the builder's own
/// scoping of the kit already gives).
pub fn parts(n: &AstNode) -> Vec<NodeRef> {
    // Known parts at even ranks; unknown ones just before `shape`.
    let shape = 2 * (PART_ORDER.len() - 2);
    let rank = |name: &str| {
        PART_ORDER
            .iter()
            .position(|p| *p == name)
            .map_or(shape - 1, |i| 2 * i)
    };
    let mut fields: Vec<(usize, usize, &Vec<NodeRef>)> = n
        .fields
        .iter()
        .enumerate()
        .filter(|(_, f)| !AstNode::is_connection(f))
        .filter_map(|(i, f)| match &f.value {
            Value::Nodes(v) if n.kind != "NodeKitListPart" || f.name == "childList" => {
                Some((rank(&f.name), i, v))
            }
            _ => None,
        })
        .collect();
    fields.sort_by_key(|&(r, i, _)| (r, i));
    fields
        .into_iter()
        .flat_map(|(_, _, v)| v.iter().cloned())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::syntax::{parse, Options};

    #[test]
    fn parts_come_in_catalog_order() {
        let p = parse(
            b"#Inventor V2.1 ascii\nShapeKit { shape Cube {} transform Transform {} appearance AppearanceKit { material Material {} } }",
            Options::new(false),
        );
        let kinds: Vec<String> = parts(&p.roots[0]).iter().map(|n| n.kind.clone()).collect();
        assert_eq!(kinds, vec!["AppearanceKit", "Transform", "Cube"]);
        assert!(is_kit("SeparatorKit") && is_kit("NodeKitListPart") && !is_kit("Kitten"));
        assert!(separates("ShapeKit") && !separates("AppearanceKit"));
    }
}
