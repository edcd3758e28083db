//! Unit tests of the Inventor / VRML 1.0 texture nodes.

use super::read_nested;
use crate::format::Loaded;
use crate::scene::{
    ImageSource, Mesh, NodeKind, Scene, TexTransformOrder, Texture, TextureModel, Wrap,
};
use glam::{Vec2, Vec3};
use std::path::Path;

fn load_at(src: &str, path: &Path) -> Loaded {
    read_nested(src.as_bytes(), path, 0, false).unwrap()
}

fn load(src: &str) -> Loaded {
    load_at(src, Path::new("t.iv"))
}

/// The texture and mesh of the shape named `name`.
fn shape<'a>(s: &'a Scene, name: &str) -> (Option<&'a Texture>, &'a Mesh) {
    let id = s.find_node(name).unwrap();
    match &s.node(id).kind {
        NodeKind::Shape(sh) => (
            s.materials[sh.material.0 as usize].texture.as_ref(),
            &s.meshes[sh.mesh.0 as usize],
        ),
        _ => panic!("{name} is not a shape"),
    }
}

/// The texture coordinate at the vertex placed at `p`.
fn uv_at(m: &Mesh, p: Vec3) -> Vec2 {
    let k = m
        .positions
        .iter()
        .position(|q| (*q - p).length() < 1e-6)
        .unwrap_or_else(|| panic!("no vertex at {p}"));
    m.texcoords[k]
}

const IMAGE: &str = "Texture2 { image 2 2 3 0xff0000 0x00ff00 0x0000ff 0xffffff }";
const SQUARE: &str = "Coordinate3 { point [0 0 0, 2 0 0, 2 1 0, 0 1 0] }";

#[test]
fn inline_image_points_binding_and_index() {
    let l = load(&format!(
        "#Inventor V2.1 ascii\nSeparator {{ {IMAGE} {SQUARE}\n TextureCoordinate2 {{ point [0 0, 1 0, 1 1, 0 1, 0.5 0.5] }}\n DEF A IndexedFaceSet {{ coordIndex [0 1 2 3 -1] textureCoordIndex [4 1 2 3 -1] }}\n TextureCoordinateBinding {{ value PER_VERTEX }}\n DEF B IndexedFaceSet {{ coordIndex [3 0 1 2 -1] }}\n}}\nDEF C Cube {{}}"
    ));
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = &l.scene;
    assert_eq!(s.images.len(), 1);
    let img = &s.images[0];
    assert_eq!(
        (img.components(), img.source.clone()),
        (3, ImageSource::Inline)
    );
    // Rows are bottom-up in the file: the top-left texel is blue.
    assert_eq!(img.base().texel(0, 0), [0, 0, 255, 255]);
    let (t, m) = shape(s, "A");
    let t = t.expect("A is textured");
    assert_eq!(
        (t.model, t.wrap_s, t.wrap_t),
        (TextureModel::Modulate, Wrap::Repeat, Wrap::Repeat)
    );
    assert_eq!(uv_at(m, Vec3::ZERO), Vec2::splat(0.5));
    assert_eq!(uv_at(m, Vec3::new(2.0, 1.0, 0.0)), Vec2::ONE);
    // PER_VERTEX: the points in corner order, whatever the coordinates.
    let (_, m) = shape(s, "B");
    assert_eq!(uv_at(m, Vec3::new(0.0, 1.0, 0.0)), Vec2::ZERO);
    assert_eq!(uv_at(m, Vec3::new(2.0, 1.0, 0.0)), Vec2::new(0.0, 1.0));
    // The Separator restores: C is untextured.
    assert!(shape(s, "C").0.is_none());
}

#[test]
fn wrap_models_and_blend_colour() {
    let l = load(
        "#Inventor V2.1 ascii\nSeparator { Texture2 { image 1 1 1 0x80 wrapS CLAMP model DECAL } DEF A Cube {} }\nSeparator { Texture2 { image 1 1 2 0x80ff wrapT CLAMP model BLEND blendColor 0 1 0 } DEF B Sphere {} }",
    );
    let s = &l.scene;
    let a = shape(s, "A").0.unwrap();
    assert_eq!(
        (a.model, a.wrap_s, a.wrap_t),
        (TextureModel::Decal, Wrap::Clamp, Wrap::Repeat)
    );
    let (b, m) = shape(s, "B");
    let b = b.unwrap();
    assert_eq!(
        (b.model, b.wrap_s, b.wrap_t),
        (TextureModel::Blend, Wrap::Repeat, Wrap::Clamp)
    );
    assert_eq!(b.blend_color, Vec3::Y);
    // A textured sphere carries the default mapping.
    assert_eq!(m.texcoords.len(), m.positions.len());
}

#[test]
fn one_transform_is_kept_two_are_baked() {
    let l = load(&format!(
        "#Inventor V2.1 ascii\n{IMAGE} {SQUARE}\nTexture2Transform {{ translation 0.5 0 scaleFactor 2 2 center 0.5 0.5 rotation 0.25 }}\nDEF A FaceSet {{}}\nTexture2Transform {{ translation 0 1 }}\nDEF B FaceSet {{}}"
    ));
    let s = &l.scene;
    let (a, ma) = shape(s, "A");
    let a = a.unwrap();
    assert_eq!(a.transform.order, TexTransformOrder::Inventor);
    assert_eq!(a.transform.translation, Vec2::new(0.5, 0.0));
    assert_eq!(a.transform.scale, Vec2::splat(2.0));
    assert_eq!(a.transform.rotation, 0.25);
    let (b, mb) = shape(s, "B");
    assert!(b.unwrap().transform.is_identity());
    // B's coordinates are A's transform applied after the new one.
    let m = a.transform.matrix();
    for p in [Vec3::ZERO, Vec3::new(2.0, 1.0, 0.0)] {
        let want = m.transform_point2(uv_at(ma, p) + Vec2::new(0.0, 1.0));
        assert!((uv_at(mb, p) - want).length() < 1e-5, "{p}");
    }
}

#[test]
fn default_mapping_plane_function_and_switching_off() {
    let l = load(&format!(
        "#Inventor V2.1 ascii\n{IMAGE}\nCoordinate3 {{ point [9 9 9, 0 0 0, 0 1 0, 0 1 2, 0 0 2] }}\nDEF A FaceSet {{ startIndex 1 }}\nTextureCoordinatePlane {{ directionS 0 0 0.5 directionT 0 2 0 }}\nDEF B FaceSet {{ startIndex 1 }}\nTextureCoordinateDefault {{}}\nTexture2 {{}}\nDEF C FaceSet {{ startIndex 1 }}"
    ));
    let s = &l.scene;
    // Box of the used points only (not 9 9 9): z is longest (s), y second,
    // t on s's scale.
    let (_, a) = shape(s, "A");
    assert_eq!(uv_at(a, Vec3::new(0.0, 1.0, 2.0)), Vec2::new(1.0, 0.5));
    assert_eq!(uv_at(a, Vec3::ZERO), Vec2::ZERO);
    let (_, b) = shape(s, "B");
    assert_eq!(uv_at(b, Vec3::new(0.0, 1.0, 2.0)), Vec2::new(1.0, 2.0));
    // An empty Texture2 switches texturing off: no texture, no coordinates.
    let (c, cm) = shape(s, "C");
    assert!(c.is_none() && cm.texcoords.is_empty());
}

#[test]
fn ties_go_to_the_later_axis_like_sgi_inventor() {
    // A flat 1x1 square in x and z: SGI picks s = z, t = x.
    let l = load(&format!(
        "#Inventor V2.1 ascii\n{IMAGE}\nCoordinate3 {{ point [0 0 0, 0 0 1, 1 0 1, 1 0 0] }}\nDEF A FaceSet {{}}"
    ));
    let (_, a) = shape(&l.scene, "A");
    assert_eq!(uv_at(a, Vec3::new(1.0, 0.0, 0.0)), Vec2::new(0.0, 1.0));
    assert_eq!(uv_at(a, Vec3::new(0.0, 0.0, 1.0)), Vec2::new(1.0, 0.0));
}

#[test]
fn quad_mesh_points_count_from_start_index() {
    let l = load(&format!(
        "#Inventor V2.1 ascii\n{IMAGE}\nCoordinate3 {{ point [9 9 9, 0 0 0, 1 0 0, 0 1 0, 1 1 0] }}\nTextureCoordinate2 {{ point [0 0, 1 0, 0 1, 1 1] }}\nDEF A QuadMesh {{ startIndex 1 verticesPerRow 2 verticesPerColumn 2 }}"
    ));
    let (_, a) = shape(&l.scene, "A");
    assert_eq!(uv_at(a, Vec3::new(1.0, 0.0, 0.0)), Vec2::new(1.0, 0.0));
    assert_eq!(uv_at(a, Vec3::new(0.0, 1.0, 0.0)), Vec2::new(0.0, 1.0));
}

#[test]
fn missing_file_warns_and_falls_back_to_the_inline_image() {
    let dir = std::env::temp_dir().join(format!("animed-iv-tex-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let src = "#Inventor V2.1 ascii\nSeparator { Texture2 { filename \"nothere.png\" image 1 1 3 0xff0000 } DEF A Cube {} }\nSeparator { Texture2 { filename \"gone.rgb\" } DEF B Cube {} }";
    let l = load_at(src, &dir.join("scene.iv"));
    assert_eq!(l.warnings.len(), 2, "{:?}", l.warnings);
    assert!(
        l.warnings[0].contains("scene.iv:2:13: cannot read texture 'nothere.png'"),
        "{}",
        l.warnings[0]
    );
    assert!(l.warnings[1].contains("cannot read texture 'gone.rgb'"));
    let s = &l.scene;
    assert!(shape(s, "A").0.is_some(), "inline fallback");
    assert!(shape(s, "B").0.is_none(), "untextured");
    // A file that exists is read relative to the scene file.
    image::RgbImage::from_pixel(2, 1, image::Rgb([1, 2, 3]))
        .save(dir.join("here.png"))
        .unwrap();
    let l = load_at(
        "#Inventor V2.1 ascii\nTexture2 { filename \"here.png\" } DEF A Cube {}",
        &dir.join("scene.iv"),
    );
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let img = &l.scene.images[0];
    assert!(matches!(&img.source, ImageSource::File { url, .. } if url == "here.png"));
    let _ = std::fs::remove_dir_all(&dir);
}
