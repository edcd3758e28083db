//! The Inventor writer, checked on scenes built in code.
mod writers_common;

use animed::format::save::{to_bytes, OutputFormat};
use animed::format::{InventorVersion, WriteOptions};
use animed::scene::Scene;

fn iv(s: &Scene, version: InventorVersion) -> (String, animed::format::WriteReport) {
    let opts = WriteOptions {
        inventor_version: version,
        ..Default::default()
    };
    let (b, r) = to_bytes(s, OutputFormat::Inventor, &opts);
    (String::from_utf8(b).unwrap(), r)
}

#[test]
fn v2_has_scene_engines_and_note() {
    let s = writers_common::demo_scene();
    let (text, report) = iv(&s, InventorVersion::V2_1);
    assert!(text.starts_with("#Inventor V2.1 ascii\n"));
    for needle in [
        "Info { string \"animed-keys 1\nfps 24\n",
        "DEF Lamp PointLight {",
        "DEF Spot SpotLight {",
        "DEF Cam PerspectiveCamera {",
        "DEF Spinner Transform {",
        "DEF Red Material {",
        "DEF Cube IndexedFaceSet {",
        "DEF _coords Coordinate3 {",
        "USE _coords",
        "USE _normals",
        "index 0 = DEF _animed_clock Calculator {",
        "a 0 = ElapsedTime { } .timeOut",
        "expression \"oa = floor(fmod(a * 24 + 0.001, 48))\"",
        "index 0 = USE _animed_clock .oa",
        "type MFRotation",
        "type MFColor",
        "scaleFactor 0.6 0.6 0.6 = SelectOne {",
    ] {
        assert!(text.contains(needle), "missing {needle:?}");
    }
    // The clock is defined once; every other engine uses it.
    assert_eq!(text.matches("DEF _animed_clock").count(), 1);
    assert_eq!(text.matches("= SelectOne {").count(), report.channels.len());
    // Each SelectOne holds one value per frame 0..=48.
    assert!(report.channels.iter().all(|c| c.written_keys == 49));
    // Lights come before the shapes they light.
    assert!(text.find("DEF Lamp").unwrap() < text.find("DEF Spinner").unwrap());
}

#[test]
fn v1_is_a_still_scene_with_the_note() {
    let mut s = writers_common::demo_scene();
    let id = s.find_node("Spinner").unwrap();
    s.node_mut(id).visible = false;
    let (text, report) = iv(&s, InventorVersion::V1_0);
    assert!(text.starts_with("#Inventor V1.0 ascii\n"));
    for absent in ["SelectOne", "Calculator", "ElapsedTime", "BaseColor"] {
        assert!(!text.contains(absent), "{absent} is not Inventor 1.0");
    }
    assert!(text.contains("track node Spinner rotation constant"));
    assert!(
        text.contains(
            "  Switch {\n    whichChild -1\n    Separator {\n      DEF Spinner Transform"
        ),
        "{text}"
    );
    assert!(report
        .warnings
        .iter()
        .any(|w| w.contains("1.0 cannot play")));
}
