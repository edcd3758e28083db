//! Unit tests of the VRML97 reader on small hand-written scenes.

use super::read;
use crate::anim::{Keys, Property, Repeat, TargetRef};
use crate::scene::{LightKind, NodeKind};
use glam::{Quat, Vec3};
use std::path::Path;

fn load(src: &str) -> crate::format::Loaded {
    read(src.as_bytes(), Path::new("t.wrl")).unwrap()
}

#[test]
fn demo_scene_has_its_parts() {
    let l = crate::format::demo().unwrap();
    let s = &l.scene;
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    for name in [
        "Ball", "Spinner", "SpotLamp", "Lamp", "Sun", "Main", "Ground", "Pyramid",
    ] {
        assert!(s.find_node(name).is_some(), "{name} missing");
    }
    assert_eq!(s.settings.headlight, Some(false));
    assert!((s.settings.background - Vec3::new(0.16, 0.2, 0.3)).length() < 1e-6);
    assert_eq!(s.settings.fps, 24.0);
    assert_eq!(s.settings.duration, 96.0);
    assert_eq!(s.animation.tracks.len(), 4);
    let cam = s.node(s.find_node("Main").unwrap()).camera().unwrap();
    assert_eq!(cam.description, "Main");
    assert!(cam.fov_smaller_side);
    assert!(s.meshes.iter().all(|m| !m.triangles.is_empty()));
    assert_eq!(
        s.info,
        vec![
            "animed demo",
            "A hand-written VRML97 scene bundled with animed."
        ]
    );
}

#[test]
fn transform_fields_and_scoped_directional_light() {
    let l = load(
        "#VRML V2.0 utf8\nDEF T Transform { translation 1 2 3 rotation 0 1 0 0.5 scale 2 2 2\n children [ DirectionalLight { direction 0 -1 0 } Shape { geometry Box {} } ] }",
    );
    let s = &l.scene;
    let t = s.node(s.find_node("T").unwrap());
    assert_eq!(t.transform.translation, Vec3::new(1.0, 2.0, 3.0));
    assert!(
        t.transform
            .rotation
            .angle_between(Quat::from_rotation_y(0.5))
            < 1e-5
    );
    assert_eq!(t.children.len(), 2);
    let light = s.node(t.children[0]).light().unwrap();
    assert!(light.scoped);
    assert_eq!(light.kind, LightKind::Directional);
    assert_eq!(light.direction, Vec3::new(0.0, -1.0, 0.0));
    assert!(matches!(s.node(t.children[1]).kind, NodeKind::Shape(_)));
}

#[test]
fn use_shares_mesh_and_material() {
    let l = load(
        "#VRML V2.0 utf8\nDEF S Shape { appearance Appearance { material DEF M Material { diffuseColor 1 0 0 } } geometry Sphere {} }\nTransform { translation 3 0 0 children USE S }",
    );
    let s = &l.scene;
    assert_eq!(s.meshes.len(), 1);
    assert_eq!(s.materials.len(), 1);
    assert_eq!(s.materials[0].name, "M");
    assert_eq!(s.materials[0].diffuse, Vec3::X);
    let shapes = s
        .nodes
        .iter()
        .filter(|n| matches!(n.kind, NodeKind::Shape(_)))
        .count();
    assert_eq!(shapes, 2);
}

#[test]
fn proto_with_is_and_defaults_and_routes_inside() {
    let l = load(
        r#"#VRML V2.0 utf8
PROTO Ball [ field SFColor col 0 1 0 field SFVec3f at 0 0 0 eventIn SFVec3f set_at ]
{ Transform { translation IS at set_translation IS set_at
    children Shape { appearance Appearance { material Material { diffuseColor IS col } } geometry Sphere {} } } }
DEF A Ball { at 1 0 0 }
DEF B Ball { col 1 0 0 }
DEF C TimeSensor { cycleInterval 2 loop TRUE }
DEF P PositionInterpolator { key [0 1] keyValue [0 0 0, 0 4 0] }
ROUTE C.fraction_changed TO P.set_fraction
ROUTE P.value_changed TO B.set_at
"#,
    );
    let s = &l.scene;
    let a = s.node(s.find_node("A").unwrap());
    assert_eq!(a.transform.translation, Vec3::X);
    let b_id = s.find_node("B").unwrap();
    assert_eq!(s.node(b_id).transform.translation, Vec3::ZERO);
    let greens = s.materials.iter().filter(|m| m.diffuse == Vec3::Y).count();
    let reds = s.materials.iter().filter(|m| m.diffuse == Vec3::X).count();
    assert_eq!((greens, reds), (1, 1));
    assert_eq!(s.animation.tracks.len(), 1);
    let t = &s.animation.tracks[0];
    assert_eq!(t.target.of, TargetRef::Node(b_id));
    assert_eq!(t.target.property, Property::Translation);
    assert_eq!(t.repeat, Repeat::Loop);
    let Keys::Vec3(k) = &t.keys else {
        panic!("vec3 keys")
    };
    assert_eq!(k.len(), 2);
    assert_eq!((k[0].frame, k[1].frame), (0.0, 48.0));
    assert_eq!(k[1].value, Vec3::new(0.0, 4.0, 0.0));
}

#[test]
fn keys_are_padded_to_the_cycle_and_jumps_kept() {
    let l = load(
        r#"#VRML V2.0 utf8
DEF T Transform {}
DEF C TimeSensor { cycleInterval 1 }
DEF S ScalarInterpolator { key [0.25 0.5 0.5 0.75] keyValue [1 2 3 4] }
DEF L PointLight {}
ROUTE C.fraction_changed TO S.set_fraction
ROUTE S.value_changed TO L.set_intensity
"#,
    );
    let t = &l.scene.animation.tracks[0];
    assert_eq!(t.repeat, Repeat::Constant);
    assert_eq!(t.target.property, Property::LightIntensity);
    let Keys::Scalar(k) = &t.keys else {
        panic!("scalar keys")
    };
    let frames: Vec<f32> = k.iter().map(|k| k.frame).collect();
    let values: Vec<f32> = k.iter().map(|k| k.value).collect();
    assert_eq!(values, vec![1.0, 1.0, 2.0, 3.0, 4.0, 4.0]);
    assert_eq!(frames[0], 0.0);
    assert_eq!(frames[1], 6.0);
    assert!(frames[2] < 12.0 && frames[2] > 11.99);
    assert_eq!(frames[3], 12.0);
    assert_eq!(frames[5], 24.0);
}

#[test]
fn color_interpolator_blends_in_hsv() {
    let l = load(
        r#"#VRML V2.0 utf8
DEF M Material {}
Shape { appearance Appearance { material USE M } geometry Box {} }
DEF C TimeSensor { cycleInterval 1 loop TRUE }
DEF I ColorInterpolator { key [0 1] keyValue [1 0 0, 0 0 1] }
ROUTE C.fraction_changed TO I.set_fraction
ROUTE I.value_changed TO M.set_diffuseColor
"#,
    );
    let t = &l.scene.animation.tracks[0];
    assert_eq!(
        t.target.of,
        TargetRef::Material(crate::scene::MaterialId(0))
    );
    let Keys::Vec3(k) = &t.keys else {
        panic!("vec3 keys")
    };
    // Red → blue the short way round the hue circle goes through magenta:
    // the middle key is (1, 0, 1), not RGB's (0.5, 0, 0.5).
    let mid = k.iter().find(|k| (k.frame - 12.0).abs() < 1e-4).unwrap();
    assert!(
        (mid.value - Vec3::new(1.0, 0.0, 1.0)).length() < 1e-5,
        "{:?}",
        mid.value
    );
}

#[test]
fn syntax_error_has_position_and_message() {
    let e = read(
        b"#VRML V2.0 utf8\nTransform { translation 1 2 3 ]",
        Path::new("x.wrl"),
    )
    .unwrap_err();
    assert_eq!((e.line, e.column), (2, 31));
    assert!(e.to_string().starts_with("x.wrl:2:31: "), "{e}");
}

#[test]
fn error_after_good_nodes_keeps_them_with_a_warning() {
    let l = load("#VRML V2.0 utf8\nDEF A Transform {}\nTransform { children [ Box { ] }");
    assert!(l.scene.find_node("A").is_some());
    assert!(
        l.warnings.iter().any(|w| w.starts_with("t.wrl:3:")),
        "{:?}",
        l.warnings
    );
}

#[test]
fn unknown_nodes_script_and_externproto_are_warned() {
    let l = load(
        r#"#VRML V2.0 utf8
EXTERNPROTO Foo [ field SFFloat x ] "foo.wrl#Foo"
Foo { x 1 }
Script { url "javascript: function f() {}" eventIn SFBool go field SFNode n NULL }
Frobnicate { a 1 b [ 2 3 ] c Box {} }
Shape { geometry Box {} }
"#,
    );
    let w = l.warnings.join("\n");
    assert!(w.contains("EXTERNPROTO Foo"), "{w}");
    assert!(w.contains("Script"), "{w}");
    assert!(w.contains("unknown node 'Frobnicate'"), "{w}");
    assert_eq!(l.scene.meshes.len(), 1);
}

/// A field a built-in node (§6) does not have is flagged where it is
/// written; the fields §6 gives them, a PROTO's declared fields, a
/// Script's own and declared fields and an unknown node's fields are not.
#[test]
fn unknown_fields_of_builtin_nodes_are_warned_where_written() {
    let l = load(
        r#"#VRML V2.0 utf8
PROTO P [ field SFFloat size 1 ] { Box {} }
Transform { translation 1 0 0 scaleOrientation 0 0 1 0 bboxSize 1 1 1
  children [ Shape { appearance Appearance { material Material { shininess 0.5 } }
                     geometry Sphere { radius 2 } }
             P { size 2 } ] }
DEF S Script { url "x.js" directOutput TRUE field SFInt32 n 3 eventIn SFBool go }
Frobnicate { colour 1 }
Transform { translate 1 0 0 children Shape { geometry Cone { radius 1 } } }
Viewpoint { centerOfRotation 0 1 0 }
"#,
    );
    let checks: Vec<&String> = l
        .warnings
        .iter()
        .filter(|w| w.contains("has no field"))
        .collect();
    assert_eq!(
        checks,
        [
            "t.wrl:9:13: Transform has no field 'translate'",
            "t.wrl:9:62: Cone has no field 'radius'",
            "t.wrl:10:13: Viewpoint has no field 'centerOfRotation' \
             (X3D's Viewpoint has it; VRML97's does not, §6)",
        ],
        "{:#?}",
        l.warnings
    );
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    let mut s = String::from("#VRML V2.0 utf8\n");
    for _ in 0..5000 {
        s.push_str("Group { children [ ");
    }
    let e = read(s.as_bytes(), Path::new("d.wrl")).unwrap_err();
    assert!(
        e.message.contains("levels of nesting") && e.message.contains("--max-depth"),
        "{e}"
    );
}

#[test]
fn switch_shows_only_the_chosen_child() {
    let l = load(
        "#VRML V2.0 utf8\nDEF S Switch { whichChoice 1 choice [ DEF A Group {} DEF B Group {} ] }",
    );
    let s = &l.scene;
    assert!(!s.node(s.find_node("A").unwrap()).visible);
    assert!(s.node(s.find_node("B").unwrap()).visible);
}

#[test]
fn bindables_and_lights_in_hidden_switch_choices_are_skipped() {
    let l = load(
        "#VRML V2.0 utf8\nSwitch { whichChoice 1 choice [ Group { children [ Background { skyColor 1 0 0 } PointLight {} Viewpoint { description \"No\" } ] } Background { skyColor 0 1 0 } ] }",
    );
    let s = &l.scene;
    assert_eq!(s.settings.background, Vec3::Y);
    assert!(s
        .nodes
        .iter()
        .all(|n| n.light().is_none() && n.camera().is_none()));
}

/// A scratch folder with a 2x2 RGB PNG `ok.png`, a broken `broken.png`.
fn texture_dir(tag: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("animed-vrml-tex-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    image::RgbImage::from_pixel(2, 2, image::Rgb([200, 100, 50]))
        .save(dir.join("ok.png"))
        .unwrap();
    std::fs::write(dir.join("broken.png"), b"\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR").unwrap();
    dir
}

fn first_shape(s: &crate::scene::Scene) -> (&crate::scene::Mesh, &crate::scene::Material) {
    let shape = s
        .nodes
        .iter()
        .find_map(|n| match &n.kind {
            NodeKind::Shape(sh) => Some(sh),
            _ => None,
        })
        .unwrap();
    (
        &s.meshes[shape.mesh.0 as usize],
        &s.materials[shape.material.0 as usize],
    )
}

#[test]
fn image_texture_url_list_coordinates_and_transform() {
    use crate::scene::{TexTransformOrder, TextureModel, Wrap};
    let dir = texture_dir("a");
    let src = "#VRML V2.0 utf8\nShape { appearance Appearance { material Material {}\n texture ImageTexture { url [\"missing.png\" \"broken.png\" \"ok.png\"] repeatS FALSE }\n textureTransform TextureTransform { translation 0.5 0 rotation 1 scale 2 3 center 0.5 0.5 } }\n geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] } coordIndex [0 1 2 3 -1]\n texCoord TextureCoordinate { point [0 0, 1 0, 1 1, 0 1] } texCoordIndex [3 2 1 0 -1] } }";
    let l = read(src.as_bytes(), &dir.join("t.wrl")).unwrap();
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = &l.scene;
    assert_eq!(s.images.len(), 1);
    assert_eq!(s.images[0].components(), 3);
    assert_eq!(s.images[0].base().texel(0, 0), [200, 100, 50, 255]);
    let (m, mat) = first_shape(s);
    let t = mat.texture.as_ref().unwrap();
    assert_eq!((t.wrap_s, t.wrap_t), (Wrap::Clamp, Wrap::Repeat));
    assert_eq!(t.model, TextureModel::Vrml97);
    assert_eq!(t.transform.order, TexTransformOrder::Vrml97);
    assert_eq!(t.transform.scale, glam::Vec2::new(2.0, 3.0));
    assert_eq!(t.transform.rotation, 1.0);
    // texCoordIndex reverses the corners: position (0,0,0) gets (0,1).
    assert_eq!(m.texcoords.len(), m.positions.len());
    let k = m.positions.iter().position(|p| *p == Vec3::ZERO).unwrap();
    assert_eq!(m.texcoords[k], glam::Vec2::new(0.0, 1.0));
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn missing_texture_warns_and_draws_untextured() {
    let dir = texture_dir("b");
    let src = "#VRML V2.0 utf8\nShape { appearance Appearance { material Material {}\n  texture ImageTexture { url [\"missing.png\" \"broken.png\"] } }\n geometry Box {} }";
    let path = dir.join("t.wrl");
    let l = read(src.as_bytes(), &path).unwrap();
    assert_eq!(l.warnings.len(), 2, "{:?}", l.warnings);
    let want = format!(
        "{}:3:11: cannot read texture 'missing.png': file not found",
        path.display()
    );
    assert!(l.warnings[0].starts_with(&want), "{:?}", l.warnings);
    assert!(
        l.warnings[1].contains("cannot read texture 'broken.png': "),
        "{:?}",
        l.warnings
    );
    let (_, mat) = first_shape(&l.scene);
    assert!(mat.texture.is_none());
    assert!(l.scene.images.is_empty());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn pixel_texture_without_material_is_unlit_with_default_mapping() {
    use crate::scene::TextureModel;
    let src = "#VRML V2.0 utf8\nShape { appearance Appearance { texture PixelTexture { image 2 1 1 0x00 0xFF } }\n geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 4 0 0, 4 2 0, 0 2 0] } coordIndex [0 1 2 3] } }";
    let l = load(src);
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let (m, mat) = first_shape(&l.scene);
    let t = mat.texture.as_ref().unwrap();
    assert_eq!(t.model, TextureModel::Replace);
    assert_eq!(l.scene.images[0].components(), 1);
    assert_eq!(
        l.scene.images[0].base().pixels(),
        &[[0, 0, 0, 255], [255; 4]]
    );
    // Bounding box 4 x 2: s along x 0..1, t along y 0..0.5.
    let k = m
        .positions
        .iter()
        .position(|p| *p == Vec3::new(4.0, 2.0, 0.0))
        .unwrap();
    assert_eq!(m.texcoords[k], glam::Vec2::new(1.0, 0.5));
    // A bad inline image is a warning and no texture.
    let l = load("#VRML V2.0 utf8\nShape { appearance Appearance { texture PixelTexture { image 2 2 3 0xFF } } geometry Box {} }");
    assert_eq!(l.warnings.len(), 1, "{:?}", l.warnings);
    assert!(
        l.warnings[0]
            .contains("cannot read texture 'PixelTexture': image is 2x2 but has only 1 pixels"),
        "{:?}",
        l.warnings
    );
    assert!(first_shape(&l.scene).1.texture.is_none());
}

#[test]
fn background_gradient_is_kept() {
    let l = load("#VRML V2.0 utf8\nBackground { skyColor [0 0 1, 1 1 1] skyAngle [1.5] groundColor [0 1 0, 0 0.5 0] groundAngle [1.2] }\nBackground { skyColor 1 0 0 }");
    let sky = l.scene.settings.sky.as_ref().unwrap();
    assert_eq!(sky.sky_color, vec![Vec3::Z, Vec3::ONE]);
    assert_eq!(sky.sky_angle, vec![1.5]);
    assert_eq!(sky.ground_angle, vec![1.2]);
    assert_eq!(l.scene.settings.background, Vec3::Z);
    // A one-colour Background stays a flat colour.
    let l = load("#VRML V2.0 utf8\nBackground { skyColor 1 0 0 }");
    assert!(l.scene.settings.sky.is_none());
    assert_eq!(l.scene.settings.background, Vec3::X);
}

#[test]
fn textured_primitives_get_the_default_mapping_and_untextured_ones_none() {
    let l = load("#VRML V2.0 utf8\nShape { appearance Appearance { texture PixelTexture { image 1 1 3 0xFF0000 } } geometry Sphere {} }\nShape { geometry Sphere {} }");
    let meshes = &l.scene.meshes;
    assert_eq!(meshes.len(), 2);
    assert_eq!(meshes[0].texcoords.len(), meshes[0].positions.len());
    assert!(meshes[1].texcoords.is_empty());
}

#[test]
fn coloured_face_set_without_material_is_unlit_and_written_without_one() {
    // A floor seen edge-on by the headlight: lit it would be black; unlit
    // (§4.14.2 table 4.5) it shows its Color node's yellow exactly.
    let src = "#VRML V2.0 utf8\nViewpoint { position 0 1 4 }\nShape { geometry IndexedFaceSet {\n coord Coordinate { point [-2 0 2, 2 0 2, 2 0 -2, -2 0 -2] } coordIndex [0 1 2 3]\n colorPerVertex FALSE color Color { color [1 1 0] } solid FALSE } }";
    let l = load(src);
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    assert!(first_shape(&l.scene).1.unlit);
    let yellow = |scene: &crate::scene::Scene| {
        let img = crate::render(scene, &crate::RenderSpec::new(40, 30)).unwrap();
        img.pixel(20, 25)
    };
    assert_eq!(yellow(&l.scene), [255, 255, 0]);
    // Written back as an Appearance without Material, which reads unlit.
    let (text, _) = super::write::write(&l.scene, &Default::default());
    assert!(!text.contains("Material"), "{text}");
    let again = load(&text);
    assert!(first_shape(&again.scene).1.unlit);
    assert_eq!(yellow(&again.scene), [255, 255, 0]);
    // Inventor says it with LightModel BASE_COLOR (what Coin draws unlit).
    let (iv, _) = crate::format::iv::write::write(&l.scene, &Default::default());
    assert!(iv.contains("LightModel { model BASE_COLOR }"), "{iv}");
    // With a Material the same floor is lit (and black edge-on).
    let lit = load(&src.replace(
        "Shape { geometry",
        "Shape { appearance Appearance { material Material {} } geometry",
    ));
    assert!(!first_shape(&lit.scene).1.unlit);
    assert_ne!(yellow(&lit.scene), [255, 255, 0]);
}

#[test]
fn sensors_started_by_an_event_get_their_own_clip() {
    let src = "#VRML V2.0 utf8
DEF Spin Transform { children [ DEF Touch TouchSensor {} Shape { geometry Box {} } ] }
DEF Slide Transform { translation 5 0 0 children Shape { geometry Sphere {} } }
DEF Clock TimeSensor { cycleInterval 2 loop TRUE }
DEF Once TimeSensor { cycleInterval 1 }
DEF R OrientationInterpolator { key [0 1] keyValue [0 1 0 0, 0 1 0 3] }
DEF P PositionInterpolator { key [0 1] keyValue [5 0 0, 5 4 0] }
ROUTE Clock.fraction_changed TO R.set_fraction
ROUTE R.value_changed TO Spin.set_rotation
ROUTE Touch.touchTime TO Once.set_startTime
ROUTE Once.fraction_changed TO P.set_fraction
ROUTE P.value_changed TO Slide.set_translation";
    let l = load(src);
    // Only the TouchSensor itself is unknown to animed.
    assert_eq!(l.warnings.len(), 1, "{:?}", l.warnings);
    assert!(l.warnings[0].contains("TouchSensor is not supported"));
    let s = &l.scene;
    let names: Vec<&str> = s.clips.names().collect();
    assert_eq!(names, ["at load", "Once"]);
    // At load only the looping Clock plays; Slide keeps its translation.
    assert_eq!(s.animation.tracks.len(), 1);
    assert_eq!(s.animation.tracks[0].target.property, Property::Rotation);
    let slide = s.find_node("Slide").unwrap();
    let pose = crate::anim::evaluate(s, 0.5);
    assert_eq!(
        pose.world[slide.0 as usize].w_axis.truncate(),
        Vec3::new(5.0, 0.0, 0.0)
    );
    // The touch clip moves it when played.
    let mut s = l.scene.clone();
    s.play_clip_index(s.find_clip("Once").unwrap()).unwrap();
    let pose = crate::anim::evaluate(&s, 1.0);
    assert_eq!(
        pose.world[slide.0 as usize].w_axis.truncate(),
        Vec3::new(5.0, 4.0, 0.0)
    );
    // A looping sensor that runs forever (stopTime <= startTime) plays at
    // load whatever restarts it; one that stopped does not.
    let looping = load(&src.replace(
        "DEF Once TimeSensor { cycleInterval 1 }",
        "DEF Once TimeSensor { cycleInterval 1 loop TRUE }",
    ));
    assert!(looping.scene.clips.is_empty());
    assert_eq!(looping.scene.animation.tracks.len(), 2);
    let stopped = load(&src.replace(
        "DEF Once TimeSensor { cycleInterval 1 }",
        "DEF Once TimeSensor { cycleInterval 1 loop TRUE startTime -1 }",
    ));
    assert_eq!(
        stopped.scene.clips.names().collect::<Vec<_>>(),
        ["at load", "Once"]
    );
}
