//! The X3D spec checks (`syntax::x3d_table`, `xml_checks`) on both
//! encodings: each bad file is flagged at the offending statement, and
//! valid ROUTEs to nodes the reader rewrites are not.

use super::{read_classic, read_xml};
use std::path::Path;

fn warnings_of(name: &str, bytes: &[u8]) -> Vec<String> {
    let path = Path::new(name);
    let loaded = if name.ends_with(".x3d") {
        read_xml(bytes, path)
    } else {
        read_classic(bytes, path)
    };
    loaded.expect("loads").warnings
}

/// Asserts one warning at `name:at: ` that contains `what`.
fn flagged(warnings: &[String], name: &str, at: &str, what: &str) {
    let want = format!("{name}:{at}: ");
    assert!(
        warnings
            .iter()
            .any(|w| w.starts_with(&want) && w.contains(what)),
        "no '{want}…{what}' in {warnings:#?}"
    );
}

#[test]
fn classic_routes_and_fields_are_checked_against_x3ds_table() {
    let name = "route-type-mismatch.x3dv";
    let w = warnings_of(
        name,
        include_bytes!("../../../tests/data/x3d_bad/route-type-mismatch.x3dv"),
    );
    flagged(&w, name, "7:1", "SFFloat to SFVec3f");
    flagged(&w, name, "8:1", "'bboxSize' is a field of Transform");
    assert_eq!(w.len(), 2, "{w:#?}");
    let name = "unknown-field.x3dv";
    let w = warnings_of(
        name,
        include_bytes!("../../../tests/data/x3d_bad/unknown-field.x3dv"),
    );
    flagged(&w, name, "5:13", "Transform has no field 'translate'");
    flagged(&w, name, "6:14", "'isActive' is an eventOut of TimeSensor");
    assert_eq!(w.len(), 2, "{w:#?}");
}

#[test]
fn xml_attributes_connects_and_routes_are_checked() {
    let name = "route-to-field.x3d";
    let w = warnings_of(
        name,
        include_bytes!("../../../tests/data/x3d_bad/route-to-field.x3d"),
    );
    flagged(
        &w,
        name,
        "15:11",
        "set_middle is an eventIn but bboxCenter is a field of Group",
    );
    flagged(&w, name, "16:11", "children is MFNode but shown is SFBool");
    flagged(&w, name, "24:3", "Transform has no field 'rotate'");
    flagged(&w, name, "28:3", "'bboxCenter' is a field of Transform");
    assert_eq!(spec_checks(&w).len(), 4, "{w:#?}");
}

/// A child's explicit containerField must name a field of its parent
/// that holds nodes; each bad one is flagged at the attribute.
#[test]
fn xml_container_fields_name_node_fields_of_the_parent() {
    let name = "container-field.x3d";
    let w = warnings_of(
        name,
        include_bytes!("../../../tests/data/x3d_bad/container-field.x3d"),
    );
    flagged(
        &w,
        name,
        "9:12",
        "containerField 'kids': Transform has no field 'kids'",
    );
    flagged(
        &w,
        name,
        "10:12",
        "'translation' of Transform is SFVec3f, not a field that holds nodes",
    );
    flagged(
        &w,
        name,
        "11:20",
        "'addChildren' is an eventIn of Transform",
    );
    let checks: Vec<_> = w.iter().filter(|m| m.contains("containerField")).collect();
    assert_eq!(checks.len(), 3, "{w:#?}");
}

/// Numbers and booleans in attributes must fit the field's type; strings
/// (unquoted in XML) and empty lists are not flagged.
#[test]
fn xml_attribute_numbers_and_booleans_fit_their_types() {
    let xml = br#"<X3D profile="Immersive" version="4.0"><Scene>
<Transform translation="1 2" bboxSize="1 1 1"/>
<TimeSensor loop="1" cycleInterval="2"/>
<TimeSensor loop="true" description="3"/>
<Switch whichChoice="0.5"/>
<Shape><IndexedFaceSet coordIndex="" colorIndex="0 1 -1"/></Shape>
</Scene></X3D>"#;
    let name = "types.x3d";
    let w = warnings_of(name, xml);
    flagged(
        &w,
        name,
        "2:1",
        "'translation' of Transform is SFVec3f and takes 3 numbers",
    );
    flagged(
        &w,
        name,
        "3:1",
        "'loop' of TimeSensor is SFBool and takes true or false",
    );
    flagged(
        &w,
        name,
        "5:1",
        "'whichChoice' of Switch is SFInt32 and takes a whole number",
    );
    let checks: Vec<_> = w.iter().filter(|m| m.contains("(§5)")).collect();
    assert_eq!(checks.len(), 3, "{w:#?}");
}

/// The warnings that are not the scene builder's (which says what it does
/// not animate or know: not spec checks).
fn spec_checks(warnings: &[String]) -> Vec<&String> {
    warnings
        .iter()
        .filter(|m| !m.contains("is not supported; not imported") && !m.contains("unknown node"))
        .collect()
}

/// PhysicalMaterial's `metallic`, Switch's `children` and ColorRGBA's
/// MFColorRGBA exist only under the names the file wrote; the reader maps
/// those nodes onto VRML97's, and the checks must not see the new names.
#[test]
fn valid_routes_to_rewritten_nodes_pass() {
    let xml = include_bytes!("../../../tests/data/x3d/routes_to_x3d_nodes.x3d");
    let w = warnings_of("ok.x3d", xml);
    // The builder does not animate `metallic` nor know IntegerSequencer;
    // the ROUTEs through both are valid X3D and are not flagged.
    assert_eq!(w.len(), 2, "{w:#?}");
    assert!(spec_checks(&w).is_empty(), "{w:#?}");
    let classic = b"#X3D V4.0 utf8
PROFILE Immersive
DEF T TimeSensor { loop TRUE }
DEF S ScalarInterpolator { key [0 1] keyValue [0 1] }
DEF W Switch { whichChoice 0 children Shape {
  appearance Appearance { material DEF M PhysicalMaterial { baseColor 1 0 0 } }
  geometry DEF I IndexedTriangleSet { index [0 1 2]
    color DEF C ColorRGBA { color [1 0 0 1, 0 1 0 1, 0 0 1 1] }
    coord Coordinate { point [0 0 0, 1 0 0, 0 1 0] } } } }
ROUTE T.fraction_changed TO S.set_fraction
ROUTE S.value_changed TO M.metallic
ROUTE C.color_changed TO C.set_color
ROUTE W.children_changed TO W.addChildren
";
    let w = warnings_of("ok.x3dv", classic);
    assert!(spec_checks(&w).is_empty(), "{w:#?}");
}
