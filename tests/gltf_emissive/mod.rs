//! glTF emissive maps (issue 14 item 2: "emissive and its texture"):
//! `tests/data/gltf/emissive.gltf` (made by `make.py`) read into the
//! material's emissive slot with its sampler, texture transform and
//! texture coordinate set; KHR_materials_unlit read as an unlit material
//! (its base colour texture multiplying the base colour, vertex colours
//! drawn as they are, lights ignored); written back as `emissiveTexture` in .gltf and
//! .glb; and the ways a file can get it wrong, each a warning naming its
//! JSON pointer. The picture is `render_textures::gltf_emissive_maps`.

use animed::internals::format::{self, load_bytes, WriteOptions};
use animed::internals::scene::{Filter, MipMode, NodeKind, Scene, Texture, TextureModel};
use glam::{Vec2, Vec3};
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/gltf/emissive.gltf")
}

/// The material of the shape named `name`.
fn material<'a>(s: &'a Scene, name: &str) -> &'a animed::internals::scene::Material {
    let id = s.find_node(name).unwrap();
    let NodeKind::Shape(sh) = &s.node(id).kind else {
        panic!("{name} is not a shape")
    };
    &s.materials[sh.material.0 as usize]
}

fn emissive_map<'a>(s: &'a Scene, name: &str) -> &'a Texture {
    material(s, name)
        .emissive_texture
        .as_ref()
        .unwrap_or_else(|| panic!("{name} has no emissive map"))
}

#[test]
fn emissive_textures_are_read_with_sampler_transform_and_factor() {
    let l = format::load(&src()).unwrap();
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = &l.scene;
    let nearest = Filter {
        mag_nearest: true,
        min_nearest: true,
        mip: MipMode::None,
    };
    // Glow: only an emissive map (factor 1 → emissive white).
    let glow = material(s, "Glow");
    assert!(glow.texture.is_none());
    assert_eq!(glow.emissive, Vec3::ONE);
    let t = emissive_map(s, "Glow");
    assert_eq!(t.filter, nearest);
    let img = s.image(t.image).unwrap();
    // Top-left texel glows (255, 200, 40); its right neighbour is black.
    assert_eq!(img.base().texel(0, 0), [255, 200, 40, 255]);
    assert_eq!(img.base().texel(1, 0), [0, 0, 0, 255]);
    // LitAndGlow: a base colour texture and the same image as emissive map,
    // repeated twice (KHR_texture_transform scale [2, 2]) and tinted by
    // emissiveFactor [0.2, 0.6, 1] (linear → sRGB like every colour).
    let lit = material(s, "Lit");
    assert_eq!(
        lit.texture.as_ref().map(|t| t.model),
        Some(TextureModel::MultiplyDiffuse)
    );
    let t = emissive_map(s, "Lit");
    assert_eq!(t.image, emissive_map(s, "Glow").image, "one image, shared");
    let m = t.transform.matrix();
    let step = m.transform_point2(Vec2::ONE) - m.transform_point2(Vec2::ZERO);
    assert!((step - Vec2::splat(2.0)).length() < 1e-6, "{step}");
    let e = lit.emissive;
    let want = animed::internals::format::gltf::srgb_from_linear(Vec3::new(0.2, 0.6, 1.0));
    assert!((e - want).abs().max_element() < 1e-6, "{e} vs {want}");
    // Unlit: lighting off; base colour × base texture is the unlit colour
    // (the texture multiplies it), no emissive map; diffuse stays black.
    let unlit = material(s, "Unlit");
    assert!(unlit.unlit);
    assert_eq!(unlit.diffuse, Vec3::ZERO);
    assert_eq!(
        unlit.texture.as_ref().map(|t| t.model),
        Some(TextureModel::MultiplyDiffuse)
    );
    assert!(unlit.emissive_texture.is_none());
}

#[test]
fn emissive_maps_survive_gltf_and_glb_round_trips() {
    let a = format::load(&src()).unwrap().scene;
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_emissive");
    std::fs::create_dir_all(&dir).unwrap();
    for ext in ["gltf", "glb"] {
        let out = dir.join(format!("emissive.{ext}"));
        let report = format::save(&a, &out, &WriteOptions::default()).unwrap();
        assert!(report.warnings.is_empty(), "{:?}", report.warnings);
        let b = format::load(&out).unwrap();
        assert!(b.warnings.is_empty(), "{:?}", b.warnings);
        let b = b.scene;
        let (ua, ub) = (material(&a, "Unlit"), material(&b, "Unlit"));
        assert!(ub.unlit && ub.emissive == ua.emissive && ub.texture.is_some());
        for name in ["Glow", "Lit"] {
            let (ma, mb) = (material(&a, name), material(&b, name));
            assert_eq!(ma.emissive, mb.emissive, "{name}");
            assert_eq!(ma.diffuse, mb.diffuse, "{name}");
            let (ta, tb) = (emissive_map(&a, name), emissive_map(&b, name));
            assert_eq!(
                (ta.wrap_s, ta.wrap_t, ta.filter),
                (tb.wrap_s, tb.wrap_t, tb.filter),
                "{name}"
            );
            let (xa, xb) = (ta.transform.matrix(), tb.transform.matrix());
            for p in [Vec2::ZERO, Vec2::ONE, Vec2::new(0.3, 0.8)] {
                let d = xa.transform_point2(p) - xb.transform_point2(p);
                assert!(d.length() < 1e-5, "{name} {p}");
            }
            let (ia, ib) = (a.image(ta.image).unwrap(), b.image(tb.image).unwrap());
            assert_eq!(ia.base().pixels(), ib.base().pixels(), "{name}");
            assert_eq!(ma.texture.is_some(), mb.texture.is_some(), "{name}");
        }
        // Written again: the same bytes (export → import → export).
        let again = dir.join(format!("again.{ext}"));
        format::save(&b, &again, &WriteOptions::default()).unwrap();
        assert!(
            std::fs::read(&out).unwrap() == std::fs::read(&again).unwrap(),
            "{ext}: second export differs"
        );
    }
}

/// Loads emissive.gltf with its JSON changed by `edit` from a scratch
/// folder (so image files named by the edit are missing) and asserts a
/// warning `PATH: want…`.
fn warns(tag: &str, edit: impl Fn(&mut serde_json::Value), want: &str) -> Scene {
    let mut doc: serde_json::Value =
        serde_json::from_slice(&std::fs::read(src()).unwrap()).unwrap();
    edit(&mut doc);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_emissive_bad");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{tag}.gltf"));
    let l = load_bytes(&serde_json::to_vec(&doc).unwrap(), &path).expect("loads with warnings");
    let want = format!("{}: {want}", path.display());
    assert!(
        l.warnings.iter().any(|w| w.starts_with(&want)),
        "no warning starting {want:?} in {:?}",
        l.warnings
    );
    l.scene
}

#[test]
fn wrong_texcoord_sets_and_missing_images_are_warnings_with_json_pointers() {
    // The emissive map reads another set than the base colour texture:
    // meshes keep one set, so it is left out, said at the material.
    let s = warns(
        "two_sets",
        |d| d["materials"][1]["emissiveTexture"]["texCoord"] = 1.into(),
        "/materials/1/emissiveTexture: the emissive texture reads TEXCOORD_1",
    );
    assert!(material(&s, "Lit").emissive_texture.is_none());
    assert!(material(&s, "Lit").texture.is_some());
    // A set the primitive does not have: said at the primitive, drawn plain.
    warns(
        "no_set",
        |d| d["materials"][0]["emissiveTexture"]["texCoord"] = 3.into(),
        "/meshes/0/primitives/0: the material's texture reads TEXCOORD_3",
    );
    // An image that is not there: said at the image; Glow and Unlit lose
    // their maps and nothing panics.
    let s = warns(
        "missing",
        |d| d["images"][0] = serde_json::json!({ "uri": "nowhere.png" }),
        "/images/0: cannot read texture 'image0'",
    );
    assert!(material(&s, "Glow").emissive_texture.is_none());
    assert!(material(&s, "Unlit").texture.is_none());
}

/// KHR_materials_unlit with COLOR_0 from a file animed did not write (no
/// `extras`): the vertex colours are the colour, lights or not — they were
/// lit and had the base colour added as emission before. A VRML97 face
/// set without Material but with a Color node is the same thing, so it
/// makes the file; through .glb with extras it stays unlit too.
#[test]
fn unlit_vertex_colours_are_drawn_as_they_are() {
    use animed::internals::render::job::{render_at, FrameSpec, Headlight};
    let wrl = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet {\n  coord Coordinate { point [-1 -1 0, 1 -1 0, 1 1 0, -1 1 0] }\n  coordIndex [0 1 2 3 -1]\n  color Color { color [0.2 0.6 0.4, 0.2 0.6 0.4, 0.2 0.6 0.4, 0.2 0.6 0.4] }\n} }\n";
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_unlit_colours");
    std::fs::create_dir_all(&dir).unwrap();
    let a = load_bytes(wrl.as_bytes(), &dir.join("quad.wrl"))
        .unwrap()
        .scene;
    let gltf = dir.join("quad.gltf");
    format::save(&a, &gltf, &WriteOptions::default()).unwrap();
    let mut doc: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&gltf).unwrap()).unwrap();
    assert!(doc["materials"][0]["extensions"]["KHR_materials_unlit"].is_object());
    assert_eq!(doc["materials"][0]["extras"]["animed"]["unlit"], true);
    doc["materials"][0]
        .as_object_mut()
        .unwrap()
        .remove("extras");
    let foreign = load_bytes(&serde_json::to_vec(&doc).unwrap(), &gltf)
        .unwrap()
        .scene;
    let glb = dir.join("quad.glb");
    format::save(&a, &glb, &WriteOptions::default()).unwrap();
    let own = format::load(&glb).unwrap().scene;
    for (tag, s) in [("foreign .gltf", &foreign), ("animed .glb", &own)] {
        assert!(s.materials.iter().all(|m| m.unlit), "{tag}: not unlit");
        for headlight in [Headlight::On, Headlight::Off] {
            let spec = FrameSpec {
                width: 64,
                height: 48,
                headlight,
                ..FrameSpec::default()
            };
            let f = render_at(s, &spec, 0.0).unwrap();
            let c = f.color[24 * 64 + 32];
            let got = [(c >> 16) & 255, (c >> 8) & 255, c & 255].map(|v| v as i32);
            let want = [51, 153, 102];
            assert!(
                got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1),
                "{tag}, headlight {headlight:?}: {got:?} vs {want:?}"
            );
        }
    }
}
