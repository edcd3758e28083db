//! Golden pictures of the renderer, from scenes built in code (and one OBJ
//! from the corpus). Each test names what it shows; `UPDATE_GOLDENS=1`
//! rewrites them (look at every one).

#[path = "common/golden.rs"]
mod golden;

use animed::internals::anim::evaluate;
use animed::internals::render::{render, Frame, RenderOptions, View};
use animed::internals::scene::{
    mesh_from_polygons, primitives, Camera, CameraKind, Light, LightKind, Material, Mesh, Node,
    NodeId, NodeKind, PolyOptions, RenderStyle, Scene, Shape, Transform,
};
use glam::{Quat, Vec3};

const W: u32 = 240;
const H: u32 = 180;

fn opts() -> RenderOptions {
    RenderOptions {
        width: W,
        height: H,
        headlight: false,
        background: Vec3::new(0.1, 0.1, 0.15),
        ..RenderOptions::default()
    }
}

fn add_shape(s: &mut Scene, name: &str, mesh: Mesh, material: Material, t: Transform) -> NodeId {
    let mesh = s.add_mesh(mesh);
    let material = s.add_material(material);
    s.add_node(
        None,
        Node::new(name, NodeKind::Shape(Shape { mesh, material })).with_transform(t),
    )
}

fn add_light(s: &mut Scene, light: Light) -> NodeId {
    s.add_node(None, Node::new("light", NodeKind::Light(light)))
}

fn at(x: f32, y: f32, z: f32) -> Transform {
    Transform::from_translation(Vec3::new(x, y, z))
}

fn matte(r: f32, g: f32, b: f32) -> Material {
    Material {
        diffuse: Vec3::new(r, g, b),
        ambient_intensity: 0.0,
        ..Material::default()
    }
}

/// A floor quad of side `size` at height `y`, facing +y.
fn floor(size: f32, y: f32) -> Mesh {
    let h = size / 2.0;
    let p = [
        Vec3::new(-h, y, h),
        Vec3::new(h, y, h),
        Vec3::new(h, y, -h),
        Vec3::new(-h, y, -h),
    ];
    // Subdivided so per-pixel lighting is not helped by vertex density.
    mesh_from_polygons(&p, &[vec![0, 1, 2, 3]], &PolyOptions::default()).unwrap()
}

/// Draws through the scene's first camera, or the default viewpoint.
fn draw(s: &Scene, o: &RenderOptions) -> Frame {
    let pose = evaluate(s, 0.0);
    let aspect = o.width as f32 / o.height as f32;
    let cam = pose.cameras.first();
    let view = match cam {
        Some((id, c)) => View::for_scene(c, pose.world[id.0 as usize], aspect, s, &pose),
        None => View::for_scene(&Camera::default(), glam::Mat4::IDENTITY, aspect, s, &pose),
    };
    render(s, &pose, &view, o)
}

fn camera(s: &mut Scene, position: Vec3, look_at: Vec3) {
    let dir = (look_at - position).normalize();
    let c = Camera {
        position,
        orientation: Quat::from_rotation_arc(Vec3::NEG_Z, dir),
        ..Camera::default()
    };
    s.add_node(None, Node::new("cam", NodeKind::Camera(c)));
}

fn directional(dir: Vec3) -> Light {
    let mut l = Light::new(LightKind::Directional);
    l.direction = dir;
    l
}

#[test]
fn light_directional() {
    let mut s = Scene::new();
    add_shape(
        &mut s,
        "ball",
        primitives::sphere(1.5),
        matte(0.9, 0.4, 0.3),
        at(0.0, 0.0, 0.0),
    );
    add_light(&mut s, directional(Vec3::new(-1.0, -1.0, -1.0)));
    golden::check("light_directional", &draw(&s, &opts()));
}

#[test]
fn light_point() {
    let mut s = Scene::new();
    camera(&mut s, Vec3::new(0.0, 4.0, 6.0), Vec3::ZERO);
    add_shape(
        &mut s,
        "floor",
        floor(8.0, 0.0),
        matte(0.8, 0.8, 0.8),
        at(0.0, 0.0, 0.0),
    );
    add_shape(
        &mut s,
        "box",
        primitives::box_mesh(Vec3::ONE),
        matte(0.3, 0.6, 0.9),
        at(-1.0, 0.5, 0.0),
    );
    let mut l = Light::new(LightKind::Point);
    l.location = Vec3::new(0.5, 1.5, 0.5);
    add_light(&mut s, l);
    golden::check("light_point", &draw(&s, &opts()));
}

fn spot_scene(beam: f32, cut: f32, drop: f32) -> Scene {
    let mut s = Scene::new();
    camera(&mut s, Vec3::new(0.0, 5.0, 5.0), Vec3::ZERO);
    add_shape(
        &mut s,
        "floor",
        floor(8.0, 0.0),
        matte(0.9, 0.9, 0.8),
        at(0.0, 0.0, 0.0),
    );
    let mut l = Light::new(LightKind::Spot {
        beam_width: beam,
        cut_off_angle: cut,
        drop_off_rate: drop,
    });
    l.location = Vec3::new(0.0, 3.0, 0.0);
    l.direction = Vec3::NEG_Y;
    add_light(&mut s, l);
    s
}

#[test]
fn light_spot() {
    golden::check("light_spot", &draw(&spot_scene(0.3, 0.6, 0.0), &opts()));
}

/// beamWidth ≥ cutOffAngle: a hard-edged disc (the cone edge itself).
#[test]
fn spot_cone_edge() {
    golden::check("spot_cone_edge", &draw(&spot_scene(0.5, 0.5, 0.0), &opts()));
}

/// Inventor dropOffRate: a cos^(128·rate) falloff inside the cut-off.
#[test]
fn spot_drop_off_rate() {
    golden::check("spot_drop_off", &draw(&spot_scene(0.5, 0.7, 0.1), &opts()));
}

/// Point light with quadratic attenuation and a radius: brightness falls
/// off with distance and stops at the radius circle.
#[test]
fn attenuation_and_radius() {
    let mut s = Scene::new();
    camera(&mut s, Vec3::new(0.0, 7.0, 0.01), Vec3::ZERO);
    add_shape(
        &mut s,
        "floor",
        floor(8.0, 0.0),
        matte(1.0, 1.0, 1.0),
        at(0.0, 0.0, 0.0),
    );
    let mut l = Light::new(LightKind::Point);
    l.location = Vec3::new(0.0, 0.5, 0.0);
    l.attenuation = Vec3::new(0.0, 0.0, 1.0);
    l.radius = 2.5;
    add_light(&mut s, l);
    golden::check("attenuation_radius", &draw(&s, &opts()));
}

#[test]
fn specular_highlight() {
    let mut s = Scene::new();
    let m = Material {
        diffuse: Vec3::new(0.2, 0.3, 0.7),
        specular: Vec3::ONE,
        shininess: 0.4,
        ambient_intensity: 0.2,
        ..Material::default()
    };
    add_shape(
        &mut s,
        "ball",
        primitives::sphere(1.5),
        m,
        at(0.0, 0.0, 0.0),
    );
    let mut l = directional(Vec3::new(-0.5, -0.6, -1.0));
    l.ambient_intensity = 1.0;
    add_light(&mut s, l);
    golden::check("specular_highlight", &draw(&s, &opts()));
}

fn three_primitives() -> Scene {
    let mut s = three_primitives_unlit();
    add_light(&mut s, directional(Vec3::new(-1.0, -1.0, -2.0)));
    s
}

fn three_primitives_unlit() -> Scene {
    let mut s = Scene::new();
    add_shape(
        &mut s,
        "ball",
        primitives::sphere(1.0),
        matte(0.9, 0.5, 0.3),
        at(-2.2, 0.0, 0.0),
    );
    add_shape(
        &mut s,
        "cone",
        primitives::cone(1.0, 2.0, true, true),
        matte(0.4, 0.9, 0.4),
        at(0.0, 0.0, 0.0),
    );
    let mut t = at(2.2, 0.0, 0.0);
    t.rotation = Quat::from_rotation_x(0.5);
    add_shape(
        &mut s,
        "cyl",
        primitives::cylinder(0.8, 2.0, true, true, true),
        matte(0.4, 0.5, 1.0),
        t,
    );
    s
}

#[test]
fn style_lines() {
    let o = RenderOptions {
        style_override: Some(RenderStyle::Lines),
        ..opts()
    };
    golden::check("style_lines", &draw(&three_primitives(), &o));
}

#[test]
fn style_points() {
    let o = RenderOptions {
        style_override: Some(RenderStyle::Points),
        ..opts()
    };
    golden::check("style_points", &draw(&three_primitives(), &o));
}

/// Per-node styles: filled, lines, points; a hidden fourth object.
#[test]
fn styles_per_node() {
    let mut s = three_primitives();
    s.nodes[1].style = RenderStyle::Lines;
    s.nodes[2].style = RenderStyle::Points;
    add_shape(
        &mut s,
        "hidden",
        primitives::box_mesh(Vec3::splat(3.0)),
        matte(1.0, 0.0, 0.0),
        at(0.0, 0.0, 1.0),
    );
    let last = NodeId(s.nodes.len() as u32 - 1);
    s.node_mut(last).style = RenderStyle::Hidden;
    golden::check("styles_per_node", &draw(&s, &opts()));
}

#[test]
fn primitives_lit_by_headlight() {
    let mut s = three_primitives_unlit();
    add_shape(
        &mut s,
        "box",
        primitives::box_mesh(Vec3::new(1.0, 0.6, 0.6)),
        matte(0.9, 0.9, 0.3),
        {
            let mut t = at(0.0, 1.8, 0.0);
            t.rotation = Quat::from_rotation_y(0.6) * Quat::from_rotation_x(0.4);
            t
        },
    );
    let o = RenderOptions {
        headlight: true,
        ..opts()
    };
    golden::check("primitives_headlight", &draw(&s, &o));
}

/// A floor running from far away to behind the camera: the triangles cross
/// the near plane and must be clipped, with perspective-correct colours.
#[test]
fn triangle_crossing_near_plane() {
    let mut s = Scene::new();
    camera(&mut s, Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 0.7, -3.0));
    let p = [
        Vec3::new(-3.0, 0.0, 5.0),
        Vec3::new(3.0, 0.0, 5.0),
        Vec3::new(3.0, 0.0, -30.0),
        Vec3::new(-3.0, 0.0, -30.0),
    ];
    let mut m = Mesh {
        positions: p.to_vec(),
        normals: vec![Vec3::Y; 4],
        colors: vec![
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(1.0, 1.0, 0.0),
        ],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        ..Mesh::default()
    };
    m.solid = false;
    add_shape(
        &mut s,
        "floor",
        m,
        Material {
            emissive: Vec3::splat(0.0),
            ambient_intensity: 0.0,
            ..Material::default()
        },
        at(0.0, 0.0, 0.0),
    );
    add_light(&mut s, directional(Vec3::NEG_Y));
    golden::check("near_plane_clip", &draw(&s, &opts()));
}

/// Two triangles passing through each other: the depth buffer splits them
/// along their intersection line.
#[test]
fn interpenetrating_triangles() {
    let mut s = Scene::new();
    let tri = |z0: f32, z1: f32, c: Material, s: &mut Scene, y: f32| {
        let m = Mesh {
            positions: vec![
                Vec3::new(-2.0, -1.5 + y, z0),
                Vec3::new(2.0, -1.5 + y, z1),
                Vec3::new(0.0, 1.5 + y, (z0 + z1) / 2.0),
            ],
            normals: vec![Vec3::Z; 3],
            triangles: vec![[0, 1, 2]],
            solid: false,
            ..Mesh::default()
        };
        add_shape(s, "tri", m, c, at(0.0, 0.0, 0.0));
    };
    tri(-1.0, 1.0, matte(1.0, 0.3, 0.2), &mut s, 0.0);
    tri(1.0, -1.0, matte(0.2, 0.5, 1.0), &mut s, 0.3);
    add_light(&mut s, directional(Vec3::NEG_Z));
    golden::check("interpenetrating", &draw(&s, &opts()));
}

/// Overlapping transparent boxes over an opaque sphere, blended back to front.
#[test]
fn transparency() {
    let mut s = Scene::new();
    add_shape(
        &mut s,
        "ball",
        primitives::sphere(1.0),
        matte(1.0, 1.0, 1.0),
        at(0.0, 0.0, -2.0),
    );
    let glass = |r: f32, g: f32, b: f32| Material {
        diffuse: Vec3::new(r, g, b),
        transparency: 0.5,
        ambient_intensity: 0.0,
        ..Material::default()
    };
    add_shape(
        &mut s,
        "red",
        primitives::box_mesh(Vec3::new(2.0, 2.0, 0.2)),
        glass(1.0, 0.1, 0.1),
        at(-0.6, 0.4, 0.0),
    );
    add_shape(
        &mut s,
        "green",
        primitives::box_mesh(Vec3::new(2.0, 2.0, 0.2)),
        glass(0.1, 1.0, 0.1),
        at(0.6, 0.4, 0.5),
    );
    add_shape(
        &mut s,
        "blue",
        primitives::box_mesh(Vec3::new(2.0, 2.0, 0.2)),
        glass(0.1, 0.1, 1.0),
        at(0.0, -0.6, 1.0),
    );
    add_light(&mut s, directional(Vec3::new(0.0, 0.0, -1.0)));
    golden::check("transparency", &draw(&s, &opts()));
}

/// An 8-sided prism from polygons: crease 0 shows flat facets, crease 0.9
/// (above the 45° between sides) smooths the sides but keeps the caps sharp.
fn prism(crease: f32) -> Scene {
    let n = 8;
    let mut pos = Vec::new();
    for k in 0..n {
        let t = std::f32::consts::TAU * k as f32 / n as f32;
        pos.push(Vec3::new(libm::sinf(t), -1.0, libm::cosf(t)));
        pos.push(Vec3::new(libm::sinf(t), 1.0, libm::cosf(t)));
    }
    let mut faces = Vec::new();
    for k in 0..n as u32 {
        let j = (k + 1) % n as u32;
        faces.push(vec![2 * k, 2 * j, 2 * j + 1, 2 * k + 1]);
    }
    faces.push((0..n as u32).rev().map(|k| 2 * k).collect());
    faces.push((0..n as u32).map(|k| 2 * k + 1).collect());
    let mesh = mesh_from_polygons(
        &pos,
        &faces,
        &PolyOptions {
            crease_angle: crease,
            ..PolyOptions::default()
        },
    )
    .unwrap();
    let mut s = Scene::new();
    let mut t = at(0.0, 0.0, 0.0);
    t.rotation = Quat::from_rotation_x(0.5) * Quat::from_rotation_y(0.2);
    t.scale = Vec3::splat(1.4);
    add_shape(&mut s, "prism", mesh, matte(0.8, 0.7, 0.5), t);
    add_light(&mut s, directional(Vec3::new(-1.0, -0.5, -1.0)));
    s
}

#[test]
fn normals_faceted() {
    golden::check("normals_faceted", &draw(&prism(0.0), &opts()));
}

#[test]
fn normals_crease_smooth() {
    golden::check("normals_crease", &draw(&prism(0.9), &opts()));
}

/// A non-solid (two-sided) plane seen from its back is lit on that side;
/// a solid one facing away is culled.
#[test]
fn two_sided_and_culling() {
    let mut s = Scene::new();
    let quad = |solid: bool| {
        let mut m = floor(2.0, 0.0);
        m.solid = solid;
        m
    };
    let mut t = at(-1.2, 0.0, 0.0);
    t.rotation = Quat::from_rotation_x(-1.2); // its front (+y) turns away
    add_shape(&mut s, "open", quad(false), matte(0.9, 0.6, 0.2), t);
    let mut t = at(1.2, 0.0, 0.0);
    t.rotation = Quat::from_rotation_x(-1.2);
    add_shape(&mut s, "solid", quad(true), matte(0.2, 0.6, 0.9), t);
    add_light(&mut s, directional(Vec3::new(0.0, -0.3, -1.0)));
    golden::check("two_sided_culling", &draw(&s, &opts()));
}

/// Orthographic camera and per-vertex colours on lines and points without
/// normals (unlit, as VRML97 IndexedLineSet/PointSet).
#[test]
fn orthographic_lines_points_unlit() {
    let mut s = Scene::new();
    let c = Camera {
        kind: CameraKind::Orthographic { height: 4.0 },
        position: Vec3::new(0.0, 0.0, 5.0),
        ..Camera::default()
    };
    s.add_node(None, Node::new("cam", NodeKind::Camera(c)));
    let mut ring = Vec::new();
    let mut colors = Vec::new();
    for k in 0..24 {
        let t = std::f32::consts::TAU * k as f32 / 24.0;
        ring.push(Vec3::new(1.5 * libm::cosf(t), 1.5 * libm::sinf(t), 0.0));
        colors.push(Vec3::new(k as f32 / 24.0, 1.0 - k as f32 / 24.0, 0.5));
    }
    let mut lines = Mesh {
        positions: ring.clone(),
        colors: colors.clone(),
        ..Mesh::default()
    };
    lines.lines = (0..24u32).map(|k| [k, (k + 1) % 24]).collect();
    add_shape(
        &mut s,
        "ring",
        lines,
        Material::default(),
        at(0.0, 0.0, 0.0),
    );
    let pts = Mesh {
        positions: ring.iter().map(|p| *p * 0.6).collect(),
        colors,
        points: (0..24).collect(),
        ..Mesh::default()
    };
    add_shape(&mut s, "dots", pts, Material::default(), at(0.0, 0.0, 0.0));
    let cube = primitives::box_mesh(Vec3::splat(0.8));
    let mut t = at(0.0, 0.0, 0.0);
    t.rotation = Quat::from_rotation_y(0.7) * Quat::from_rotation_x(0.5);
    add_shape(&mut s, "cube", cube, matte(0.9, 0.9, 0.9), t);
    let o = RenderOptions {
        headlight: true,
        ..opts()
    };
    let plain = draw(&s, &o);
    golden::check("ortho_lines_points", &plain);
    // The same with 4x multisampling: edges of the cube, the ring and the
    // dots get in-between colours (zoom in on the golden to see them).
    let aa = draw(&s, &RenderOptions { aa: 4, ..o });
    golden::check("ortho_lines_points_aa4", &aa);
    let distinct = |f: &Frame| {
        let mut c = f.color.clone();
        c.sort_unstable();
        c.dedup();
        c.len()
    };
    assert!(
        distinct(&aa) > distinct(&plain) * 3 / 2,
        "AA adds edge shades: {} vs {} colours",
        distinct(&aa),
        distinct(&plain)
    );
    // Interior pixels keep their colour: a pixel in the middle of the cube
    // and one of the background are the same with and without AA.
    let mid = (H / 2 * W + W / 2) as usize;
    assert_eq!(aa.color[mid], plain.color[mid]);
    assert_eq!(aa.color[0], plain.color[0]);
}

/// A scoped DirectionalLight lights only its siblings' subtrees.
#[test]
fn scoped_directional_light() {
    let mut s = Scene::new();
    let lit = s.add_node(None, Node::group("lit").with_transform(at(-1.3, 0.0, 0.0)));
    let unlit = s.add_node(None, Node::group("unlit").with_transform(at(1.3, 0.0, 0.0)));
    for (g, name) in [(lit, "a"), (unlit, "b")] {
        let mesh = s.add_mesh(primitives::sphere(1.0));
        let material = s.add_material(matte(0.9, 0.9, 0.9));
        s.add_node(
            Some(g),
            Node::new(name, NodeKind::Shape(Shape { mesh, material })),
        );
    }
    let mut l = directional(Vec3::new(-1.0, -1.0, -1.0));
    l.scoped = true;
    s.add_node(Some(lit), Node::new("sun", NodeKind::Light(l)));
    let mut dim = directional(Vec3::new(1.0, 0.0, -1.0));
    dim.intensity = 0.2;
    add_light(&mut s, dim);
    golden::check("scoped_light", &draw(&s, &opts()));
}

fn shared_dir() -> std::path::PathBuf {
    std::env::var_os("ANIMED_SHARED")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared"))
}

/// An OBJ with an MTL file from the corpus (copied into tests/data), its
/// `map_Kd oakbark.jpg` drawn on the `vt` coordinates (looked at beside
/// view3dscene 4.2: same bark).
#[test]
fn obj_with_mtl() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/oak_leafless.obj");
    let loaded = animed::internals::format::load(&path).unwrap();
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    let s = loaded.scene;
    // The MTL's Ks 0.5 and Ns 96 arrived.
    let m = s
        .find_material("oakstamm2")
        .expect("material from oak5.mtl");
    assert_eq!(s.materials[m.0 as usize].specular, Vec3::splat(0.5));
    assert!((s.materials[m.0 as usize].shininess - 0.75).abs() < 1e-6);
    let pose = evaluate(&s, 0.0);
    let view = View::view_all(&s, &pose, W as f32 / H as f32);
    let o = RenderOptions {
        headlight: true,
        ..opts()
    };
    golden::check("obj_oak_mtl", &render(&s, &pose, &view, &o));
    // Same file still matches its corpus original, when the corpus is there.
    let original = shared_dir().join(
        "corpus/castle-engine-demo-models/shadow_maps/castle_with_trees/opengameart.org/jkm_oaktree/models/oak_leafless.obj",
    );
    match std::fs::read(&original) {
        Ok(bytes) => assert_eq!(bytes, std::fs::read(&path).unwrap()),
        Err(_) => eprintln!(
            "\n*** NOTE: corpus not found at {} (set ANIMED_SHARED); compared only the copy ***\n",
            original.display()
        ),
    }
}

/// The id buffer names the node drawn at each pixel.
#[test]
fn id_buffer_names_nodes() {
    let s = three_primitives();
    let f = draw(&s, &opts());
    let centre_row = (H / 2) as usize * W as usize;
    let ids: std::collections::BTreeSet<u32> = f.ids[centre_row..centre_row + W as usize]
        .iter()
        .copied()
        .collect();
    // Background 0 plus the three shapes (nodes 0, 1, 2 → ids 1, 2, 3).
    assert_eq!(ids.into_iter().collect::<Vec<_>>(), vec![0, 1, 2, 3]);
    assert_eq!(f.ids[0], 0);
    assert_eq!(f.depth[0], 1.0);
    assert!(f.depth[centre_row + W as usize / 2] < 1.0);
}
