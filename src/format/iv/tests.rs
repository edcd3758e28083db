//! Unit tests of the Inventor / VRML 1.0 reader.

use super::read_nested;
use crate::format::Loaded;
use crate::scene::{CameraKind, NodeKind, RenderStyle};
use glam::{Mat4, Vec3};
use std::path::Path;

fn load(src: &str) -> Loaded {
    read_nested(src.as_bytes(), Path::new("t.iv"), 0, false).unwrap()
}

fn world(s: &crate::scene::Scene, id: crate::scene::NodeId) -> Mat4 {
    let mut m = Mat4::IDENTITY;
    let mut cur = Some(id);
    while let Some(c) = cur {
        m = s.node(c).transform.matrix() * m;
        cur = s.node(c).parent;
    }
    m
}

#[test]
fn properties_affect_later_siblings_and_separators_restore() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n Material { diffuseColor 1 0 0 }\n Translation { translation 1 0 0 }\n Separator { Material { diffuseColor 0 1 0 } Translation { translation 0 1 0 } DEF A Cube {} }\n DEF B Sphere {}\n Translation { translation 1 0 0 }\n DEF C Cone {}\n}",
    );
    let s = &l.scene;
    let find = |n: &str| s.find_node(n).unwrap();
    let pos = |n: &str| world(s, find(n)).transform_point3(Vec3::ZERO);
    assert_eq!(pos("A"), Vec3::new(1.0, 1.0, 0.0));
    assert_eq!(pos("B"), Vec3::new(1.0, 0.0, 0.0));
    assert_eq!(pos("C"), Vec3::new(2.0, 0.0, 0.0));
    let mat = |n: &str| match &s.node(find(n)).kind {
        NodeKind::Shape(sh) => s.materials[sh.material.0 as usize].diffuse,
        _ => panic!("not a shape"),
    };
    assert_eq!(mat("A"), Vec3::Y);
    assert_eq!(mat("B"), Vec3::X);
    assert_eq!(mat("C"), Vec3::X);
}

#[test]
fn named_transform_is_a_group_holding_later_siblings() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { DEF Arm Rotation { rotation 0 0 1 1.5 } Translation { translation 2 0 0 } DEF Hand Cube {} }",
    );
    let s = &l.scene;
    let arm = s.find_node("Arm").unwrap();
    let hand = s.find_node("Hand").unwrap();
    assert_eq!(s.node(hand).parent, Some(arm));
    let p = world(s, hand).transform_point3(Vec3::ZERO);
    assert!((p - Vec3::new(2.0 * 1.5f32.cos(), 2.0 * 1.5f32.sin(), 0.0)).length() < 1e-5);
}

#[test]
fn transform_separator_keeps_properties_but_not_transforms() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { TransformSeparator { Translation { translation 5 0 0 } BaseColor { rgb 0 0 1 } } DEF A Cube {} }",
    );
    let s = &l.scene;
    let a = s.find_node("A").unwrap();
    assert_eq!(world(s, a).transform_point3(Vec3::ZERO), Vec3::ZERO);
    let NodeKind::Shape(sh) = &s.node(a).kind else {
        panic!()
    };
    assert_eq!(s.materials[sh.material.0 as usize].diffuse, Vec3::Z);
}

#[test]
fn switch_group_drawstyle_info_and_camera() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n PerspectiveCamera { position 0 0 5 heightAngle 0.5 }\n Info { string \"hello \\\"there\\\"\" }\n Switch { whichChild 1 DEF No Cube {} DEF Yes Cube {} }\n DrawStyle { style LINES }\n DEF L Sphere {}\n}",
    );
    let s = &l.scene;
    assert!(s.find_node("No").is_none());
    assert!(s.find_node("Yes").is_some());
    assert_eq!(s.node(s.find_node("L").unwrap()).style, RenderStyle::Lines);
    assert_eq!(s.info, vec!["hello \"there\""]);
    let cam = s.nodes.iter().find_map(|n| n.camera()).unwrap();
    assert!(!cam.fov_smaller_side);
    assert_eq!(cam.kind, CameraKind::Perspective { height_angle: 0.5 });
}

/// DrawStyle's lineWidth and pointSize reach the shapes after it, and a
/// face set keeps its polygons' outlines for LINES (a quad is 4 edges, not
/// the 5 of its two triangles); a triangle-only set keeps none.
#[test]
fn drawstyle_widths_and_polygon_outlines() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n DEF Thin Cube {}\n DrawStyle { style LINES lineWidth 2 pointSize 3.4 }\n Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 2 0 0 ] }\n DEF Quad IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1 ] }\n DEF Tri IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n}",
    );
    let s = &l.scene;
    let node = |name| s.node(s.find_node(name).unwrap());
    let mesh = |name| match &node(name).kind {
        NodeKind::Shape(sh) => &s.meshes[sh.mesh.0 as usize],
        _ => panic!(),
    };
    assert_eq!(
        (node("Thin").line_width, node("Thin").point_size),
        (0.0, 0.0)
    );
    let q = node("Quad");
    assert_eq!(
        (q.style, q.line_width, q.point_size),
        (RenderStyle::Lines, 2.0, 3.4)
    );
    let m = mesh("Quad");
    assert_eq!(m.triangles.len(), 2);
    let mut outline: Vec<[Vec3; 2]> = m
        .edges
        .iter()
        .map(|e| [m.positions[e[0] as usize], m.positions[e[1] as usize]])
        .collect();
    outline.sort_by(|a, b| a[0].to_array().partial_cmp(&b[0].to_array()).unwrap());
    assert_eq!(outline.len(), 4);
    assert_eq!(outline[0], [Vec3::ZERO, Vec3::X]);
    assert!(mesh("Tri").edges.is_empty());
    // A Cube's outline is its 6 squares.
    assert_eq!(mesh("Thin").edges.len(), 24);
}

/// A Sphere drawn as lines is Coin's latitude/longitude grid at the
/// Complexity in force (rotTransDragger.iv, lod.iv); the same sphere drawn
/// filled keeps the fine tessellation, and a Separator scopes Complexity.
#[test]
fn line_spheres_are_coins_grid_at_the_complexity() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n DEF Fine Sphere {}\n DrawStyle { style LINES }\n DEF Half Sphere { radius 2 }\n Separator { Complexity { value 0.2 } DEF Coarse Sphere {} }\n DEF Again Sphere {}\n}",
    );
    let s = &l.scene;
    let mesh = |name| match &s.node(s.find_node(name).unwrap()).kind {
        NodeKind::Shape(sh) => &s.meshes[sh.mesh.0 as usize],
        _ => panic!(),
    };
    let fine = mesh("Fine");
    assert!(fine.edges.is_empty() && fine.triangles.len() > 1000);
    // Default complexity 0.5: 15 slices, 14 bands (390 triangles in Coin).
    let half = mesh("Half");
    assert_eq!(half.triangles.len(), 390);
    assert_eq!(half.edges.len(), 15 * 14 + 15 * 13);
    assert!(half
        .positions
        .iter()
        .all(|p| (p.length() - 2.0).abs() < 1e-5));
    // 0.2: 6 slices, 5 bands.
    assert_eq!(mesh("Coarse").triangles.len(), 48);
    assert_eq!(mesh("Again").triangles.len(), 390);
}

/// whichChild −2 (SO_SWITCH_INHERIT) takes the last Switch's value, also
/// a sibling's, wrapped into range, as Coin's SoSwitch does; a Separator
/// scopes it. An open Cone is drawn two-sided (its inside shows).
#[test]
fn inherited_switch_values_and_open_primitives() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n Switch { whichChild 1 Info {} }\n Switch { whichChild -2 DEF A0 Cube {} DEF A1 Cube {} }\n Switch { whichChild -2 DEF B0 Cube {} }\n Separator { Switch { whichChild 0 Info {} } }\n Switch { whichChild -2 DEF C0 Cube {} DEF C1 Cube {} }\n DEF Open Cone { parts SIDES }\n DEF Closed Cone { parts (SIDES | BOTTOM) }\n}",
    );
    let s = &l.scene;
    let found = |n: &str| s.find_node(n).is_some();
    assert!(!found("A0") && found("A1"));
    // 1 wraps to 0 in a one-child switch.
    assert!(found("B0"));
    // The Separator's whichChild 0 stays inside it.
    assert!(!found("C0") && found("C1"));
    let solid = |n| mesh_is_solid(s, n);
    assert!(!solid("Open") && solid("Closed"));
}

/// Whether the shape node `name` of `s` has a solid (culled) mesh.
fn mesh_is_solid(s: &crate::scene::Scene, name: &str) -> bool {
    match &s.node(s.find_node(name).unwrap()).kind {
        NodeKind::Shape(sh) => s.meshes[sh.mesh.0 as usize].solid,
        _ => panic!("{name} is not a shape"),
    }
}

/// Drawn as lines or points, a closed primitive is culled only where
/// ShapeHints says SOLID with a known ordering (Coin culls no primitive of
/// its own accord), so its back edges show otherwise; filled, it stays
/// solid (the same picture, and half the triangles drawn).
#[test]
fn primitives_as_lines_are_culled_only_under_solid_hints() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n DEF Filled Cube {}\n DrawStyle { style LINES }\n DEF Bare Cube {}\n DEF Grid Sphere {}\n ShapeHints { vertexOrdering COUNTERCLOCKWISE shapeType SOLID }\n DEF Hinted Cube {}\n DrawStyle { style POINTS }\n DEF Dots Cylinder {}\n ShapeHints { vertexOrdering UNKNOWN_ORDERING shapeType SOLID }\n DEF Unordered Cone {}\n}",
    );
    let s = &l.scene;
    let solid = |n| mesh_is_solid(s, n);
    assert!(solid("Filled") && solid("Hinted") && solid("Dots"));
    assert!(!solid("Bare") && !solid("Grid") && !solid("Unordered"));
}

/// Without a Coordinate3 the coordinates are Coin's default, one point at
/// the origin: a PointSet draws it and a LineSet's bounds hold it (Toolmaker
/// `newManips.iv` is framed on it in Coin).
#[test]
fn shapes_without_coordinates_use_the_origin() {
    let l = load("#Inventor V2.1 ascii\nSeparator {\n DEF P PointSet {}\n DEF L LineSet {}\n}");
    let s = &l.scene;
    let mesh = |n| match &s.node(s.find_node(n).unwrap()).kind {
        NodeKind::Shape(sh) => &s.meshes[sh.mesh.0 as usize],
        _ => panic!(),
    };
    assert_eq!(mesh("P").positions, vec![Vec3::ZERO]);
    assert_eq!(mesh("P").points, vec![0]);
    assert_eq!(mesh("L").positions, vec![Vec3::ZERO]);
    assert!(mesh("L").lines.is_empty());
}

/// Coin culls no primitive, so a closed one seen through its own
/// transparency or an RGBA texture with see-through texels shows its back
/// faces (castle `inlined_pixel_textures.wrl`); opaque ones stay culled.
#[test]
fn see_through_primitives_are_two_sided() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n DEF Opaque Sphere {}\n Separator { Material { transparency 0.5 } DEF Glass Sphere {} }\n Separator { Texture2 { image 1 2 4 0xFF0000FF 0x00FF0080 } DEF Holes Cube {} }\n Separator { Texture2 { image 1 2 3 0xFF0000 0x00FF00 } DEF Painted Cube {} }\n}",
    );
    let s = &l.scene;
    let solid = |n| mesh_is_solid(s, n);
    assert!(solid("Opaque") && solid("Painted"));
    assert!(!solid("Glass") && !solid("Holes"));
}

#[test]
fn indexed_face_set_with_per_face_materials_and_clockwise_hints() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n Material { diffuseColor [ 1 0 0, 0 1 0 ] }\n MaterialBinding { value PER_FACE }\n ShapeHints { vertexOrdering CLOCKWISE shapeType SOLID }\n Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 2 0 0 ] }\n IndexedFaceSet { coordIndex [ 0, 3, 2, 1, -1, 1, 2, 4, -1 ] }\n}",
    );
    let s = &l.scene;
    assert_eq!(s.meshes.len(), 1);
    let m = &s.meshes[0];
    assert_eq!(m.triangles.len(), 3);
    assert!(m.solid);
    // Clockwise input, flipped to counter-clockwise: normals face +z.
    for t in &m.triangles {
        let [a, b, c] = t.map(|i| m.positions[i as usize]);
        assert!((b - a).cross(c - a).z > 0.0);
    }
    let reds = m.colors.iter().filter(|c| **c == Vec3::X).count();
    let greens = m.colors.iter().filter(|c| **c == Vec3::Y).count();
    assert!(reds >= 4 && greens >= 3, "{:?}", m.colors);
}

#[test]
fn unknown_node_with_fields_declaration_is_skipped_with_warning() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { MyNode { fields [ SFFloat size, MFNode kids ] size 2 kids [ Cube {} ] } Cube {} }",
    );
    assert_eq!(l.scene.meshes.len(), 1);
    assert!(l
        .warnings
        .iter()
        .any(|w| w.contains("unknown node 'MyNode' (declared with fields")));
}

#[test]
fn vrml1_header_and_strips() {
    let l = read_nested(
        b"#VRML V1.0 ascii\nSeparator { Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0, 1 1 0 ] } TriangleStripSet { numVertices 4 } }",
        Path::new("t.wrl"),
        0,
        true,
    )
    .unwrap();
    let m = &l.scene.meshes[0];
    assert_eq!(m.triangles.len(), 2);
    for t in &m.triangles {
        let [a, b, c] = t.map(|i| m.positions[i as usize]);
        assert!((b - a).cross(c - a).z > 0.0, "strip winding kept");
    }
    assert_eq!(l.scene.format, crate::scene::SourceFormat::Vrml1);
}

#[test]
fn rotor_spins_once_per_period_and_loops() {
    let l =
        load("#Inventor V2.1 ascii\nSeparator { Rotor { rotation 0 1 0 0 speed 0.5 } Cube {} }");
    let s = &l.scene;
    assert_eq!(s.animation.tracks.len(), 1);
    let t = &s.animation.tracks[0];
    assert_eq!(t.repeat, crate::anim::Repeat::Loop);
    let frames = t.keys.frames();
    // 0.5 turns per second: one turn in 2 s = 48 frames at 24 fps.
    assert_eq!(frames.first(), Some(&0.0));
    assert_eq!(frames.last(), Some(&48.0));
    assert_eq!(s.settings.duration, 48.0);
    let crate::anim::Keys::Rotation(k) = &t.keys else {
        panic!()
    };
    let quarter = k.iter().find(|k| k.frame == 12.0).unwrap().value;
    assert!(quarter.angle_between(glam::Quat::from_rotation_y(std::f32::consts::FRAC_PI_2)) < 1e-5);
}

#[test]
fn engine_connections_are_read_and_ignored() {
    let l = load(
        "#Inventor V2.0 ascii\nSeparator { DEF C Crank { size 1 } RivetHinge { origin = USE C . endPoint hingePoint 2 2 0 } Translation { translation 1 0 0 = ElapsedTime { speed 2 }.timeOut } DEF A Cube {} }",
    );
    assert!(l.scene.find_node("A").is_some());
    assert!(l.warnings.iter().any(|w| w.contains("connections")));
}

#[test]
fn named_groups_pass_their_transforms_on_without_nesting_what_follows() {
    let l = load(
        "#VRML V1.0 ascii\nSeparator {\n DEF G1 Group { Translation { translation 1 0 0 } }\n DEF G2 Group { Translation { translation 0 1 0 } DEF A Cube {} }\n DEF B Sphere {}\n DEF T Transform { translation 0 0 1 }\n DEF G3 Group { Translation { translation 1 0 0 } }\n DEF C Cone {}\n}",
    );
    let s = &l.scene;
    let find = |n: &str| s.find_node(n).unwrap();
    let pos = |n: &str| world(s, find(n)).transform_point3(Vec3::ZERO);
    assert_eq!(pos("A"), Vec3::new(1.0, 1.0, 0.0));
    assert_eq!(pos("B"), Vec3::new(1.0, 1.0, 0.0));
    assert_eq!(pos("C"), Vec3::new(2.0, 1.0, 1.0));
    // B follows G2 but is not its child; C follows the named transform T.
    let parent = |n: &str| s.node(find(n)).parent;
    assert_eq!(parent("B"), parent("G1"));
    assert_eq!(parent("C"), Some(find("T")));
}

#[test]
fn line_sets_are_unlit_in_the_diffuse_colour_and_per_part_colours_each_segment() {
    // Lines carry no normals: Inventor draws them in their base colour.
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { Material { diffuseColor 1 0.5 0 }\n Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n DEF L IndexedLineSet { coordIndex [ 0 1 2 -1 ] }\n DEF F IndexedFaceSet { coordIndex [ 0 1 2 -1 ] } }",
    );
    let s = &l.scene;
    let mat = |n: &str| match &s.node(s.find_node(n).unwrap()).kind {
        NodeKind::Shape(sh) => s.materials[sh.material.0 as usize].clone(),
        _ => panic!("not a shape"),
    };
    assert_eq!(mat("L").emissive, Vec3::new(1.0, 0.5, 0.0));
    assert_eq!(mat("L").diffuse, Vec3::ZERO);
    assert_eq!(mat("F").diffuse, Vec3::new(1.0, 0.5, 0.0));
    assert_eq!(mat("F").emissive, Vec3::ZERO);
    // axis.iv: two polylines, three segments, PER_PART = one colour each
    // (PER_FACE would colour per polyline: the Y axis drawn red).
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { IndexedLineSet { vertexProperty VertexProperty {\n vertex [ 0 0 0, 1 0 0, 0 1 0, 0 0 1 ]\n orderedRGBA [ 0xff0000ff, 0xff00ff, 0xffff ] materialBinding PER_PART }\n coordIndex [ 1, 0, 2, -1, 0, 3 ] } }",
    );
    let m = &l.scene.meshes[0];
    assert_eq!(m.lines.len(), 3);
    let colour_of = |a: Vec3, b: Vec3| {
        let seg = m
            .lines
            .iter()
            .find(|l| {
                let (p, q) = (m.positions[l[0] as usize], m.positions[l[1] as usize]);
                (p == a && q == b) || (p == b && q == a)
            })
            .expect("segment");
        (m.colors[seg[0] as usize], m.colors[seg[1] as usize])
    };
    assert_eq!(colour_of(Vec3::ZERO, Vec3::X), (Vec3::X, Vec3::X));
    assert_eq!(colour_of(Vec3::ZERO, Vec3::Y), (Vec3::Y, Vec3::Y));
    assert_eq!(colour_of(Vec3::ZERO, Vec3::Z), (Vec3::Z, Vec3::Z));
}

#[test]
fn array_and_multiple_copy_make_one_separated_group_per_copy() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n DEF A Array { numElements1 3 separation1 2 0 0 origin CENTER Material { diffuseColor 1 0 0 } DEF S Sphere {} }\n DEF C Cube {}\n MultipleCopy { matrix [ 1 0 0 0 0 1 0 0 0 0 1 0 0 7 0 1 ] DEF K Cone {} }\n}",
    );
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = &l.scene;
    let spheres: Vec<Vec3> = s
        .walk()
        .into_iter()
        .filter(|&id| s.node(id).name == "S")
        .map(|id| world(s, id).transform_point3(Vec3::ZERO))
        .collect();
    assert_eq!(
        spheres,
        vec![
            Vec3::new(-2.0, 0.0, 0.0),
            Vec3::ZERO,
            Vec3::new(2.0, 0.0, 0.0)
        ]
    );
    let a = s.find_node("A").unwrap();
    assert_eq!(s.node(a).children.len(), 3);
    // Each copy is separated: the red Material stays inside.
    let c = s.find_node("C").unwrap();
    match &s.node(c).kind {
        NodeKind::Shape(sh) => {
            assert_eq!(
                s.materials[sh.material.0 as usize].diffuse,
                Vec3::splat(0.8)
            )
        }
        _ => panic!("not a shape"),
    }
    let k = s.find_node("K").unwrap();
    assert_eq!(
        world(s, k).transform_point3(Vec3::ZERO),
        Vec3::new(0.0, 7.0, 0.0)
    );
}

#[test]
fn base_color_shapes_are_unlit_and_stay_so_through_the_writer() {
    use crate::format::export::{InventorVersion, WriteOptions};
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { LightModel { model BASE_COLOR }\n Material { diffuseColor 0 0 1 }\n DEF Q IndexedFaceSet { vertexProperty VertexProperty {\n vertex [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ]\n orderedRGBA [ 0xff0000ff, 0x00ff00ff, 0x0000ffff, 0xffffffff ] materialBinding PER_VERTEX }\n coordIndex [ 0 1 2 3 -1 ] }\n DEF C Cube {} }\nDEF P Sphere {}",
    );
    let s = &l.scene;
    let mesh = |s: &crate::scene::Scene, n: &str| match &s.node(s.find_node(n).unwrap()).kind {
        NodeKind::Shape(sh) => (
            s.meshes[sh.mesh.0 as usize].clone(),
            s.materials[sh.material.0 as usize].clone(),
        ),
        _ => panic!("not a shape"),
    };
    // Unlit: no normals (the renderer then draws the colours as they are).
    let (q, _) = mesh(s, "Q");
    assert!(q.normals.is_empty());
    assert_eq!(q.colors.len(), q.positions.len());
    assert!(q.colors.contains(&Vec3::new(1.0, 0.0, 0.0)));
    let (c, cm) = mesh(s, "C");
    assert!(c.normals.is_empty());
    assert_eq!(cm.emissive, Vec3::Z);
    // Outside the Separator: lit again.
    assert!(!mesh(s, "P").0.normals.is_empty());
    let opts = WriteOptions {
        inventor_version: InventorVersion::V2_1,
        ..Default::default()
    };
    let (text, _) = crate::format::iv::write::write(s, &opts);
    let back = load(&text);
    let (q2, _) = mesh(&back.scene, "Q");
    assert!(q2.normals.is_empty(), "{text}");
    assert_eq!(q2.colors.len(), q.colors.len());
    let (c2, cm2) = mesh(&back.scene, "C");
    assert!(c2.normals.is_empty());
    assert_eq!(cm2.emissive, Vec3::Z, "{text}");
    assert!(!mesh(&back.scene, "P").0.normals.is_empty(), "{text}");
}

#[test]
fn node_kits_read_as_the_groups_they_expand_to() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n DEF K SeparatorKit {\n  childList NodeKitListPart { containerTypeName \"Group\" childList [\n   ShapeKit { shape DEF S Cube {} transform Transform { translation 0 3 0 }\n    appearance AppearanceKit { material Material { diffuseColor 1 0 0 } } } ] }\n  transform Transform { translation 2 0 0 } }\n DEF C Sphere {}\n}",
    );
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = &l.scene;
    let find = |n: &str| s.find_node(n).unwrap();
    // The kit's transform comes before its child list; the shape kit's
    // transform before its shape.
    assert_eq!(
        world(s, find("S")).transform_point3(Vec3::ZERO),
        Vec3::new(2.0, 3.0, 0.0)
    );
    let diffuse = |n: &str| match &s.node(find(n)).kind {
        NodeKind::Shape(sh) => s.materials[sh.material.0 as usize].diffuse,
        _ => panic!("not a shape"),
    };
    assert_eq!(diffuse("S"), Vec3::X);
    // Kits keep their state: the sphere after them is default grey at the origin.
    assert_eq!(diffuse("C"), Vec3::splat(0.8));
    assert_eq!(world(s, find("C")).transform_point3(Vec3::ZERO), Vec3::ZERO);
    assert!(s.node(find("K")).children.len() == 1);
}

#[test]
fn inventor_and_vrml1_light_with_a_global_ambient_an_environment_sets() {
    let plain = load("#Inventor V2.1 ascii\nSeparator { Cube {} }");
    assert_eq!(plain.scene.settings.ambient, Vec3::splat(0.2));
    let v1 = read_nested(
        b"#VRML V1.0 ascii\nSeparator { Cube {} }",
        Path::new("t.wrl"),
        0,
        true,
    )
    .unwrap();
    assert_eq!(v1.scene.settings.ambient, Vec3::splat(0.2));
    let env = load(
        "#Inventor V2.1 ascii\nSeparator { Environment { ambientIntensity 0.5 ambientColor 1 0 0.5 } Cube {} }",
    );
    assert_eq!(env.scene.settings.ambient, Vec3::new(0.5, 0.0, 0.25));
}

/// Coin's ambient term is the material's first ambientColor (whole, not
/// its mean) times the Environment's; BASE_COLOR and line sets without
/// normals are unlit and have none.
#[test]
fn materials_keep_inventors_ambient_colour() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n DEF A Cube {}\n Material { ambientColor [0.5 0.25 1, 1 1 1] diffuseColor [0 0 0, 1 1 1] }\n DEF B Cube {}\n LightModel { model BASE_COLOR }\n DEF C Cube {}\n}",
    );
    let s = &l.scene;
    let mat = |n: &str| match &s.node(s.find_node(n).unwrap()).kind {
        NodeKind::Shape(sh) => s.materials[sh.material.0 as usize].clone(),
        _ => panic!("{n} is not a shape"),
    };
    assert_eq!(mat("A").ambient_color, Some(Vec3::splat(0.2)), "default");
    assert_eq!(mat("B").ambient_color, Some(Vec3::new(0.5, 0.25, 1.0)));
    assert!(
        (mat("B").ambient_intensity - 1.75 / 3.0).abs() < 1e-6,
        "the mean"
    );
    assert_eq!(mat("C").ambient_color, None, "unlit");
}

/// NormalBinding OVERALL with a normal given lights the whole shape with
/// that normal (Coin draws castle's vrml_1/normals.wrl so), faces and
/// line sets alike; line sets with normals are lit, without them unlit.
#[test]
fn overall_normals_are_the_first_normal_everywhere() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator {\n Coordinate3 { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] }\n DEF U IndexedLineSet { coordIndex [0 1 2] }\n Normal { vector [0 0.6 0.3, 1 0 0] } NormalBinding { value OVERALL }\n DEF F IndexedFaceSet { coordIndex [0 1 2 3] }\n DEF L IndexedLineSet { coordIndex [0 1 2] }\n}",
    );
    let s = &l.scene;
    let mesh = |n: &str| match &s.node(s.find_node(n).unwrap()).kind {
        NodeKind::Shape(sh) => s.meshes[sh.mesh.0 as usize].clone(),
        _ => panic!("{n} is not a shape"),
    };
    let want = Vec3::new(0.0, 0.6, 0.3).normalize();
    for n in ["F", "L"] {
        let m = mesh(n);
        assert_eq!(m.normals.len(), m.positions.len(), "{n}");
        assert!(
            m.normals
                .iter()
                .all(|v| (v.normalize() - want).length() < 1e-5),
            "{n}: {:?}",
            m.normals
        );
    }
    assert!(mesh("U").normals.is_empty(), "no normals yet: unlit");
}

/// A `File` node's nodes are traversed in the including file's state: the
/// Material before each `File` (or USE of it) colours what the file draws,
/// as Coin draws chessboard.iv's pieces; a file that does not load is a
/// warning naming it, and so is a problem inside an included file.
#[test]
fn file_nodes_draw_in_the_including_state() {
    let dir = std::env::temp_dir().join(format!("animed-iv-file-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("piece.iv"),
        "#Inventor V2.1 ascii\nSeparator { DEF Piece Cube {} Bogus {} }\n",
    )
    .unwrap();
    let main = dir.join("board.iv");
    let src = "#Inventor V2.1 ascii\nSeparator {\n Material { diffuseColor 1 0 0 }\n DEF P File { name \"piece.iv\" }\n Material { diffuseColor 0 1 0 }\n USE P\n File { name \"missing.iv\" }\n}\n";
    let l = read_nested(src.as_bytes(), &main, 0, false).unwrap();
    let s = &l.scene;
    let colours: Vec<Vec3> = s
        .nodes
        .iter()
        .filter_map(|n| match &n.kind {
            NodeKind::Shape(sh) => Some(s.materials[sh.material.0 as usize].diffuse),
            _ => None,
        })
        .collect();
    assert_eq!(colours, [Vec3::X, Vec3::Y]);
    let w = l.warnings.join("\n");
    assert!(w.contains("piece.iv:2:"), "{w}");
    assert!(w.contains("missing.iv"), "{w}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Inventor's own draggers and NURBS nodes are valid nodes
/// animed does not draw: "not supported" (which `info --strict` does not
/// count), where a made-up node is "unknown".
#[test]
fn standard_nodes_not_drawn_are_unsupported_not_unknown() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { TrackballDragger { } IndexedNurbsSurface { } \
         NurbsSurface { } Crank { } Cube { } }\n",
    );
    for k in ["TrackballDragger", "IndexedNurbsSurface", "NurbsSurface"] {
        let w = l
            .warnings
            .iter()
            .find(|w| w.contains(&format!(" {k} ")))
            .unwrap_or_else(|| panic!("{k}: {:?}", l.warnings));
        assert!(w.contains("is not supported; skipped"), "{w}");
        assert!(!crate::format::warn_kind::breaks_the_spec(w), "{w}");
    }
    let w = l.warnings.iter().find(|w| w.contains("Crank")).unwrap();
    assert!(w.contains("unknown node 'Crank' skipped"), "{w}");
    assert!(crate::format::warn_kind::breaks_the_spec(w), "{w}");
}
