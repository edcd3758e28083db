//! The Inventor writer, checked on scenes built in code.
mod writers_common;

use animed::internals::format::save::{to_bytes, OutputFormat};
use animed::internals::format::{InventorVersion, WriteOptions};
use animed::internals::scene::Scene;

fn iv(s: &Scene, version: InventorVersion) -> (String, animed::internals::format::WriteReport) {
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

#[test]
fn textures_are_texture2_state_with_the_transform_baked_into_coordinates() {
    let scene = writers_common::textured_scene(std::path::Path::new("brick.png"));
    let (text, report) = iv(&scene, InventorVersion::V2_1);
    for needle in [
        "Texture2 {\n",
        "filename \"brick.png\"",
        "wrapT CLAMP",
        "model DECAL",
        "image 2 1 4",
        "0xFF0000FF 0x0000FF80",
        "TextureCoordinate2 {",
        "TextureCoordinateBinding { value PER_VERTEX_INDEXED }",
        // The untextured cube switches texturing off rather than inheriting.
        "Texture2 { }",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
    // Texture2Transform accumulates in Inventor, so it is baked instead:
    // the first point of the turned, scaled quad is the transform of (0, 0).
    assert!(!text.contains("Texture2Transform"), "{text}");
    let t = match &scene.materials[0].texture {
        Some(t) => t.transform,
        None => unreachable!(),
    };
    let p = t.matrix().transform_point2(glam::Vec2::ZERO);
    let first = text
        .split("TextureCoordinate2 {")
        .nth(1)
        .and_then(|s| s.split('[').nth(1))
        .and_then(|s| s.split(',').next())
        .unwrap();
    let xy: Vec<f32> = first
        .split_whitespace()
        .map(|w| w.parse().unwrap())
        .collect();
    assert!(
        (xy[0] - p.x).abs() < 1e-6 && (xy[1] - p.y).abs() < 1e-6,
        "{first} vs {p}"
    );
    // The file texture replaces a grey diffuse colour in VRML97 terms, which
    // MODULATE cannot say: one warning.
    assert_eq!(report.warnings.len(), 1, "{:?}", report.warnings);
    assert!(report.warnings[0].contains("MODULATE"));
    // A scene without textures writes no texture state at all.
    let (plain, _) = iv(&writers_common::demo_scene(), InventorVersion::V2_1);
    assert!(!plain.contains("Texture2"));
}

/// Inventor 1.0 / VRML 1.0 have no `TextureCoordinateBinding`: the 1.0
/// file binds its coordinates with `textureCoordIndex` instead, and reads
/// back with the same texture coordinates as the 2.1 file.
#[test]
fn v1_binds_texture_coordinates_by_index_not_by_a_binding_node() {
    use animed::internals::format::load_bytes;
    let scene = writers_common::textured_scene(std::path::Path::new("brick.png"));
    let (v1, _) = iv(&scene, InventorVersion::V1_0);
    let (v2, _) = iv(&scene, InventorVersion::V2_1);
    assert!(!v1.contains("TextureCoordinateBinding"), "{v1}");
    assert!(v1.contains("textureCoordIndex ["), "{v1}");
    let coords = |text: &str| {
        let l = load_bytes(text.as_bytes(), std::path::Path::new("t.iv")).unwrap();
        let mut all: Vec<Vec<[u32; 2]>> = l
            .scene
            .meshes
            .iter()
            .map(|m| {
                m.texcoords
                    .iter()
                    .map(|c| [c.x.to_bits(), c.y.to_bits()])
                    .collect()
            })
            .filter(|t: &Vec<[u32; 2]>| !t.is_empty())
            .collect();
        all.sort();
        all
    };
    let (a, b) = (coords(&v1), coords(&v2));
    assert!(!a.is_empty(), "no texture coordinates read back from\n{v1}");
    assert_eq!(a, b);
}

/// A morphed cube (two targets, a TCB-free linear weights track): the .iv
/// carries the targets as Calculator engines, reads back with the same
/// targets and default weights, and the key note's keys fit them again.
#[test]
fn morph_targets_go_through_calculators_and_come_back() {
    use animed::internals::anim::Weights;
    use animed::internals::anim::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track};
    use animed::internals::format::load_bytes;
    use animed::internals::scene::{MorphTarget, Morphs, Node, NodeKind, Shape};
    use glam::Vec3;
    let mut s = Scene::new();
    let mut mesh = writers_common::cube("Box");
    let n = mesh.positions.len();
    // Ten targets: two Calculators chained.
    let targets: Vec<MorphTarget> = (0..10)
        .map(|i| {
            MorphTarget::new(
                format!("t{i}"),
                vec![Vec3::Y * (i + 1) as f32; n],
                Vec::new(),
            )
        })
        .collect();
    let defaults: Vec<f32> = (0..10).map(|i| i as f32 / 20.0).collect();
    mesh.morph = Some(Box::new(Morphs::new(n, targets, defaults.clone()).unwrap()));
    let mesh = s.add_mesh(mesh);
    let material = s.add_material(Default::default());
    let id = s.add_node(
        None,
        Node::new("Box", NodeKind::Shape(Shape { mesh, material })),
    );
    let w = |v: &[f32]| Weights::from_slice(v).unwrap();
    let mut one = vec![0.0; 10];
    one[9] = 1.0;
    s.animation.tracks.push(Track {
        target: Target {
            of: TargetRef::Node(id),
            property: Property::MorphWeights,
        },
        repeat: Repeat::Constant,
        keys: Keys::Weights(vec![
            Key::new(0.0, w(&defaults)).with_interp(Interp::Linear),
            Key::new(24.0, w(&one)).with_interp(Interp::Linear),
        ]),
    });
    s.settings.duration = 24.0;
    let (text, _) = iv(&s, InventorVersion::V2_1);
    assert!(
        text.contains("point [") && text.contains("] = Calculator {"),
        "{text}"
    );
    assert!(
        text.contains("A [ ] = Calculator {"),
        "two Calculators chained"
    );
    assert!(
        text.contains("expression \"oA = A + a * B + b * C + c * D"),
        "{text}"
    );
    assert!(text.contains("= DEF _animed_weight SelectOne {"), "{text}");
    let back = load_bytes(text.as_bytes(), std::path::Path::new("m.iv")).unwrap();
    let m = back
        .scene
        .meshes
        .iter()
        .find_map(|m| m.morph.as_ref())
        .expect("a morph");
    assert_eq!(m.len(), 10);
    assert_eq!(m.default_weights(), &defaults[..]);
    // Each target moves every vertex by its own offset (ids follow the file).
    for (i, t) in m.targets().iter().enumerate() {
        assert!(
            t.positions().iter().all(|d| *d == Vec3::Y * (i + 1) as f32),
            "target {i}"
        );
    }
    let t = &back.scene.animation.tracks;
    assert_eq!(t.len(), 1);
    assert_eq!(
        t[0].keys.len(),
        2,
        "the note's keys fit the targets read back"
    );
}

/// Inventor's global ambient: 0.2 grey by default (not written), another
/// value as an Environment, a scene without one (VRML97's) as
/// `ambientIntensity 0`; every case reads back as it was, and a .wrl keeps
/// it in the key note.
#[test]
fn the_global_ambient_goes_through_environment_and_the_key_note() {
    use animed::internals::format::load_bytes;
    use glam::Vec3;
    for (ambient, line) in [
        (Vec3::splat(0.2), None),
        (
            Vec3::ZERO,
            Some("Environment { ambientIntensity 0 ambientColor 1 1 1 }"),
        ),
        (
            Vec3::new(0.5, 0.0, 0.25),
            Some("Environment { ambientIntensity 1 ambientColor 0.5 0 0.25 }"),
        ),
    ] {
        let mut s = writers_common::demo_scene();
        s.settings.ambient = ambient;
        let (text, _) = iv(&s, InventorVersion::V2_1);
        match line {
            Some(l) => assert!(text.contains(l), "{ambient}: {l}"),
            None => assert!(!text.contains("Environment"), "{ambient}"),
        }
        let back = load_bytes(text.as_bytes(), std::path::Path::new("a.iv")).unwrap();
        assert_eq!(back.scene.settings.ambient, ambient);
        let (wrl, _) = to_bytes(&s, OutputFormat::Vrml97, &WriteOptions::default());
        let back = load_bytes(&wrl, std::path::Path::new("a.wrl")).unwrap();
        assert_eq!(back.scene.settings.ambient, ambient);
    }
}

/// Inventor's ambient colour is written as it was read (Coin lights with
/// the whole colour, not the mean the VRML97 writer keeps as an
/// intensity); a material without one writes the grey of its intensity.
#[test]
fn ambient_colours_go_through_as_read() {
    use animed::internals::format::load_bytes;
    use glam::Vec3;
    let src = "#Inventor V2.1 ascii\nSeparator { Material { ambientColor 0.5 0.25 1 } Cube {} }";
    let a = load_bytes(src.as_bytes(), std::path::Path::new("a.iv")).unwrap();
    let (text, _) = iv(&a.scene, InventorVersion::V2_1);
    assert!(text.contains("ambientColor 0.5 0.25 1"), "{text}");
    let back = load_bytes(text.as_bytes(), std::path::Path::new("b.iv")).unwrap();
    let want = Some(Vec3::new(0.5, 0.25, 1.0));
    assert!(back.scene.materials.iter().any(|m| m.ambient_color == want));
    let mut s = writers_common::demo_scene();
    for m in &mut s.materials {
        m.ambient_color = None;
        m.ambient_intensity = 0.3;
    }
    let (text, _) = iv(&s, InventorVersion::V2_1);
    assert!(text.contains("ambientColor 0.3 0.3 0.3"), "{text}");
}
