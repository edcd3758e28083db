//! The VRML97 writer, checked on scenes built in code.
mod writers_common;

use animed::internals::format::save::{to_bytes, OutputFormat};
use animed::internals::format::WriteOptions;
use animed::internals::scene::{Node, Scene};
use std::collections::HashSet;
use std::io::Read as _;

fn vrml(s: &Scene) -> String {
    let (b, _) = to_bytes(s, OutputFormat::Vrml97, &WriteOptions::default());
    String::from_utf8(b).unwrap()
}

/// Names after `DEF`.
fn defs(text: &str) -> Vec<String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    words
        .windows(2)
        .filter(|w| w[0] == "DEF")
        .map(|w| w[1].to_string())
        .collect()
}

#[test]
fn demo_scene_has_every_part_and_routes_to_defined_names() {
    let text = vrml(&writers_common::demo_scene());
    assert!(text.starts_with("#VRML V2.0 utf8\n"));
    for needle in [
        "WorldInfo {",
        "\"animed-keys 1\nfps 24\nduration 48\n",
        "Background { skyColor [ 0.1 0.1 0.2 ] }",
        "DEF Cam Viewpoint {",
        "description \"Front\"",
        "DEF Lamp PointLight {",
        "DEF Spot SpotLight {",
        "cutOffAngle 0.7853982",
        "DEF Spinner Transform {",
        "DEF Red Material {",
        "geometry DEF CubeMesh IndexedFaceSet {",
        "geometry USE CubeMesh",
        "DEF _animed_clock TimeSensor { cycleInterval 2 loop TRUE }",
        "OrientationInterpolator",
        "ColorInterpolator",
        "ScalarInterpolator",
        "ROUTE Blinker_scale.value_changed TO Blinker.set_scale",
        "ROUTE Lamp_intensity.value_changed TO Lamp.set_intensity",
        "ROUTE Red_diffuseColor.value_changed TO Red.set_diffuseColor",
        "ROUTE Cam_position.value_changed TO Cam.set_position",
        "ROUTE Spot_cutOffAngle.value_changed TO Spot.set_cutOffAngle",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
    let names: HashSet<String> = defs(&text).into_iter().collect();
    for line in text.lines().filter(|l| l.starts_with("ROUTE ")) {
        let w: Vec<&str> = line.split_whitespace().collect();
        for end in [w[1], w[3]] {
            let node = end.split('.').next().unwrap();
            assert!(names.contains(node), "{line}: {node} is not DEF'd");
        }
    }
}

#[test]
fn def_names_are_unique_even_when_the_scene_repeats_them() {
    let mut s = writers_common::demo_scene();
    s.add_node(None, Node::group("Spinner"));
    s.add_node(None, Node::group("Spinner"));
    s.add_node(None, Node::group("bad name!"));
    let text = vrml(&s);
    let d = defs(&text);
    let unique: HashSet<&String> = d.iter().collect();
    assert_eq!(unique.len(), d.len(), "{d:?}");
    assert!(d.contains(&"Spinner_1".to_string()));
    assert!(d.contains(&"Spinner_2".to_string()));
    assert!(d.contains(&"bad_name_".to_string()));
}

#[test]
fn writing_is_deterministic_and_gzip_holds_the_same_text() {
    let s = writers_common::demo_scene();
    let a = vrml(&s);
    assert_eq!(a, vrml(&s));
    let (gz, _) = to_bytes(&s, OutputFormat::Vrml97Gz, &WriteOptions::default());
    assert_eq!(&gz[..2], &[0x1f, 0x8b]);
    let mut text = String::new();
    flate2::read::GzDecoder::new(&gz[..])
        .read_to_string(&mut text)
        .unwrap();
    assert_eq!(text, a);
}

#[test]
fn interpolator_keys_run_from_0_to_1_and_match_their_values() {
    let text = vrml(&writers_common::demo_scene());
    // Every interpolator: key count == keyValue count, keys non-decreasing in [0, 1].
    let mut n = 0;
    for block in text.split("Interpolator {").skip(1) {
        let field = |name: &str| -> Vec<String> {
            let start = block.find(&format!("{name} [")).unwrap() + name.len() + 2;
            let end = start + block[start..].find(']').unwrap();
            block[start..end]
                .split(',')
                .map(|s| s.trim().to_string())
                .filter(|s| !s.is_empty())
                .collect()
        };
        let keys: Vec<f32> = field("key").iter().map(|k| k.parse().unwrap()).collect();
        let values = field("keyValue");
        assert_eq!(keys.len(), values.len());
        assert_eq!(keys[0], 0.0);
        assert_eq!(*keys.last().unwrap(), 1.0);
        assert!(keys.windows(2).all(|w| w[0] <= w[1]), "{keys:?}");
        n += 1;
    }
    assert_eq!(n, 7);
}

#[test]
fn hidden_node_plays_as_scale_zero() {
    let mut s = writers_common::demo_scene();
    s.animation.tracks.clear();
    let id = s.find_node("Spinner").unwrap();
    s.node_mut(id).visible = false;
    let text = vrml(&s);
    assert!(text.contains("hidden Spinner\n"));
    assert!(text.contains("ROUTE Spinner_scale.value_changed TO Spinner.set_scale"));
    let block = text
        .split("DEF Spinner_scale PositionInterpolator")
        .nth(1)
        .unwrap();
    assert!(block.contains("0 0 0,"));
}

#[test]
fn textures_are_written_as_image_and_pixel_textures_with_coordinates() {
    let dir = std::env::temp_dir().join(format!("animed-wtex-{}", std::process::id()));
    let tex_dir = dir.join("tex");
    std::fs::create_dir_all(&tex_dir).unwrap();
    let brick = tex_dir.join("brick.png");
    let scene = writers_common::textured_scene(&brick);
    // Saved into another folder: the url climbs to the file that was read.
    let out = dir.join("out").join("scene.wrl");
    std::fs::create_dir_all(out.parent().unwrap()).unwrap();
    let report = animed::internals::format::save(&scene, &out, &WriteOptions::default()).unwrap();
    let text = std::fs::read_to_string(&out).unwrap();
    for needle in [
        "texture ImageTexture {\n",
        "url \"../tex/brick.png\"",
        "repeatT FALSE",
        "textureTransform TextureTransform {",
        "center 0.5 0.5",
        "rotation 0.5",
        "scale 2 2",
        "texCoord TextureCoordinate {",
        "2 0,",
        "texture PixelTexture {",
        "image 2 1 4",
        "0xFF0000FF 0x0000FF80",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
    assert!(!text.contains("repeatS FALSE"), "{text}");
    // The untextured cube has no texture and no coordinates of its own.
    assert_eq!(text.matches("texCoord TextureCoordinate").count(), 2);
    // DECAL cannot be said in VRML97: the writer says so.
    assert!(
        report.warnings.iter().any(|w| w.contains("Decal")),
        "{:?}",
        report.warnings
    );
    // Written without a folder (to_bytes), the url stays as authored.
    assert!(vrml(&scene).contains("url \"brick.png\""));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn copy_textures_copies_each_file_once_and_points_the_output_at_the_copies() {
    let dir = std::env::temp_dir().join(format!("animed-ctex-{}", std::process::id()));
    let src = dir.join("src");
    std::fs::create_dir_all(&src).unwrap();
    let brick = src.join("brick.png");
    std::fs::write(&brick, b"not really a png").unwrap();
    let mut scene = writers_common::textured_scene(&brick);
    // A second image from another folder with the same file name.
    let mut other = scene.images[0].clone();
    let elsewhere = dir.join("elsewhere");
    std::fs::create_dir_all(&elsewhere).unwrap();
    std::fs::write(elsewhere.join("brick.png"), b"another").unwrap();
    other.source = animed::internals::scene::ImageSource::File {
        url: "brick.png".into(),
        path: elsewhere.join("brick.png"),
    };
    scene.add_image(other).unwrap();
    let copies = dir.join("out/textures");
    let copied =
        animed::internals::format::export::textures::copy_textures(&mut scene, &copies).unwrap();
    assert_eq!(copied.len(), 2);
    assert_eq!(
        std::fs::read(copies.join("brick.png")).unwrap(),
        b"not really a png"
    );
    assert_eq!(
        std::fs::read(copies.join("brick_2.png")).unwrap(),
        b"another"
    );
    let out = dir.join("out/scene.wrl");
    animed::internals::format::save(&scene, &out, &WriteOptions::default()).unwrap();
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.contains("url \"textures/brick.png\""), "{text}");
    // info lists the textures with their users.
    let loaded = animed::internals::format::Loaded {
        scene,
        warnings: Vec::new(),
    };
    let d = animed::internals::cli::info::describe(&loaded);
    let t = &d["textures"];
    assert_eq!(t.as_array().unwrap().len(), 3, "{t}");
    // In memory the url is the copy's path; `save` made it relative above.
    assert!(t[0]["url"]
        .as_str()
        .unwrap()
        .ends_with("out/textures/brick.png"));
    assert_eq!(t[0]["shapes"], serde_json::json!(["Tiled"]));
    assert_eq!(t[0]["materials"], serde_json::json!(["TiledMat"]));
    assert_eq!(t[1]["source"], "inline");
    assert_eq!(
        (t[1]["width"].as_u64(), t[1]["components"].as_u64()),
        (Some(2), Some(4))
    );
    assert_eq!(t[2]["shapes"], serde_json::json!([]));
    std::fs::remove_dir_all(&dir).ok();
}
