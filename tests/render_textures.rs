//! Golden pictures of textures and backgrounds, from small VRML97 scenes
//! written here (images generated in code): component counts, repeat vs
//! clamp, texture transform, the primitives' default mappings, Inventor
//! DECAL/BLEND, alpha, gradient and panorama backgrounds, a receding
//! checkerboard (mip-mapping: no moiré) and a magnified texture (bilinear).
//! `UPDATE_GOLDENS=1` rewrites them (look at every one).

#[path = "common/golden.rs"]
mod golden;

use animed::internals::format::load_bytes;
use animed::internals::render::job::{render_at, FrameSpec};
use animed::internals::render::Frame;
use animed::internals::scene::{Scene, TextureModel};
use glam::Vec3;
use std::path::{Path, PathBuf};

const W: u32 = 240;
const H: u32 = 180;

/// A scratch folder holding the generated images the scenes name.
fn images() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("animed-render-tex-{}", std::process::id()));
    if dir.join("rgba.png").exists() {
        return dir;
    }
    std::fs::create_dir_all(&dir).unwrap();
    // 8x8 checker of red and white with a blue top-left texel (orientation).
    image::RgbImage::from_fn(8, 8, |x, y| match (x, y) {
        (0, 0) => image::Rgb([0, 0, 255]),
        _ if (x + y) % 2 == 0 => image::Rgb([220, 40, 40]),
        _ => image::Rgb([240, 240, 240]),
    })
    .save(dir.join("checker.png"))
    .unwrap();
    // 64x64 black/white checker of 1-texel squares, for minification.
    image::GrayImage::from_fn(64, 64, |x, y| {
        image::Luma([if (x + y) % 2 == 0 { 255 } else { 0 }])
    })
    .save(dir.join("fine.png"))
    .unwrap();
    // A grey ramp (1 component) and its version with alpha (2 components).
    image::GrayImage::from_fn(16, 16, |x, _| image::Luma([(x * 16) as u8]))
        .save(dir.join("grey.png"))
        .unwrap();
    image::GrayAlphaImage::from_fn(16, 16, |x, y| {
        image::LumaA([
            (x * 16) as u8,
            if (x / 4 + y / 4) % 2 == 0 { 255 } else { 60 },
        ])
    })
    .save(dir.join("greyalpha.png"))
    .unwrap();
    // RGBA: an opaque green disc on a transparent square.
    image::RgbaImage::from_fn(32, 32, |x, y| {
        let (dx, dy) = (x as f32 - 15.5, y as f32 - 15.5);
        if dx * dx + dy * dy < 144.0 {
            image::Rgba([30, 200, 60, 255])
        } else {
            image::Rgba([255, 255, 0, 0])
        }
    })
    .save(dir.join("rgba.png"))
    .unwrap();
    for (name, rgb) in [
        ("front", [200, 60, 60]),
        ("back", [60, 200, 60]),
        ("left", [60, 60, 200]),
        ("right", [200, 200, 60]),
        ("top", [60, 200, 200]),
        ("bottom", [200, 60, 200]),
    ] {
        // Each face: its colour with a dark bar along its top edge.
        image::RgbImage::from_fn(16, 16, |_, y| {
            image::Rgb(if y < 3 { [20, 20, 20] } else { rgb })
        })
        .save(dir.join(format!("{name}.png")))
        .unwrap();
    }
    dir
}

fn load(src: &str) -> Scene {
    let path = images().join("scene.wrl");
    let l = load_bytes(src.as_bytes(), &path).unwrap();
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    l.scene
}

fn draw(scene: &Scene) -> Frame {
    let spec = FrameSpec {
        width: W,
        height: H,
        ..FrameSpec::default()
    };
    render_at(scene, &spec, 0.0).unwrap()
}

const HEAD: &str = "#VRML V2.0 utf8\nNavigationInfo { headlight FALSE }\nDirectionalLight { direction -0.3 -0.4 -1 }\nBackground { skyColor 0.1 0.1 0.15 }\nViewpoint { position 0 0 9.5 }\n";

/// A unit quad at x offset `x` with `appearance`, texture coordinates 0..1.
fn quad(x: f32, appearance: &str) -> String {
    format!(
        "Transform {{ translation {x} 0 0 children Shape {{ appearance Appearance {{ {appearance} }}\n geometry IndexedFaceSet {{ coord Coordinate {{ point [-0.9 -0.9 0, 0.9 -0.9 0, 0.9 0.9 0, -0.9 0.9 0] }} coordIndex [0 1 2 3] texCoord TextureCoordinate {{ point [0 0, 1 0, 1 1, 0 1] }} }} }} }}\n"
    )
}

#[test]
fn texture_component_counts() {
    // Left to right: 1 (intensity × diffuse), 2 (… with alpha), 3 (RGB
    // replaces the orange diffuse), 4 (RGBA). All lit.
    let mat = "material Material { diffuseColor 1 0.6 0.2 }";
    let src = [
        quad(
            -3.0,
            &format!("{mat} texture ImageTexture {{ url \"grey.png\" }}"),
        ),
        quad(
            -1.0,
            &format!("{mat} texture ImageTexture {{ url \"greyalpha.png\" }}"),
        ),
        quad(
            1.0,
            &format!("{mat} texture ImageTexture {{ url \"checker.png\" }}"),
        ),
        quad(
            3.0,
            &format!("{mat} texture ImageTexture {{ url \"rgba.png\" }}"),
        ),
    ]
    .concat();
    let s = load(&format!("{HEAD}{src}"));
    let comps: Vec<u8> = s.images.iter().map(|i| i.components()).collect();
    assert_eq!(comps, vec![1, 2, 3, 4]);
    golden::check("tex_components", &draw(&s));
}

#[test]
fn texture_repeat_clamp_and_transform() {
    // Coordinates -0.5..1.5: repeating (left), clamped (middle), and a
    // TextureTransform rotating and scaling about the centre (right).
    let q = |x: f32, tex: &str, tt: &str| {
        format!(
            "Transform {{ translation {x} 0 0 children Shape {{ appearance Appearance {{ material Material {{}} texture ImageTexture {{ url \"checker.png\" {tex} }} {tt} }}\n geometry IndexedFaceSet {{ coord Coordinate {{ point [-0.9 -0.9 0, 0.9 -0.9 0, 0.9 0.9 0, -0.9 0.9 0] }} coordIndex [0 1 2 3] texCoord TextureCoordinate {{ point [-0.5 -0.5, 1.5 -0.5, 1.5 1.5, -0.5 1.5] }} }} }} }}\n"
        )
    };
    let src = [
        q(-2.0, "", ""),
        q(0.0, "repeatS FALSE repeatT FALSE", ""),
        q(
            2.0,
            "",
            "textureTransform TextureTransform { rotation 0.5 scale 0.5 0.5 center 0.5 0.5 translation 0.25 0 }",
        ),
    ]
    .concat();
    golden::check(
        "tex_repeat_clamp_transform",
        &draw(&load(&format!("{HEAD}{src}"))),
    );
}

#[test]
fn texture_primitive_default_mappings() {
    let app = "appearance Appearance { material Material {} texture ImageTexture { url \"checker.png\" } }";
    let src = format!(
        "{HEAD}Transform {{ rotation 1 1 0 0.5 children [\
         Transform {{ translation -3 0 0 children Shape {{ {app} geometry Box {{ size 1.4 1.4 1.4 }} }} }}\
         Transform {{ translation -1 0 0 children Shape {{ {app} geometry Sphere {{ radius 0.8 }} }} }}\
         Transform {{ translation 1 0 0 children Shape {{ {app} geometry Cylinder {{ radius 0.7 height 1.4 }} }} }}\
         Transform {{ translation 3 0 0 children Shape {{ {app} geometry Cone {{ bottomRadius 0.7 height 1.4 }} }} }} ] }}"
    );
    golden::check("tex_primitives", &draw(&load(&src)));
}

#[test]
fn texture_inventor_models_and_alpha() {
    // DECAL and BLEND are Inventor models; set them on materials read from
    // VRML97 so one picture shows MODULATE, DECAL, BLEND and an alpha
    // texture drawn over a red bar behind it.
    let mat = "material Material { diffuseColor 0.3 0.5 1 }";
    let src = [
        quad(-3.0, &format!("{mat} texture ImageTexture {{ url \"checker.png\" }}")),
        quad(-1.0, &format!("{mat} texture ImageTexture {{ url \"rgba.png\" }}")),
        quad(1.0, &format!("{mat} texture ImageTexture {{ url \"grey.png\" }}")),
        quad(3.0, &format!("{mat} texture ImageTexture {{ url \"greyalpha.png\" }}")),
        "Transform { translation 0 0 -1 children Shape { appearance Appearance { material Material { diffuseColor 1 0 0 } } geometry Box { size 9 0.5 0.1 } } }\n".to_string(),
    ]
    .concat();
    let mut s = load(&format!("{HEAD}{src}"));
    let models = [
        TextureModel::Modulate,
        TextureModel::Decal,
        TextureModel::Blend,
        TextureModel::Vrml97,
    ];
    let textured: Vec<usize> = (0..s.materials.len())
        .filter(|&i| s.materials[i].texture.is_some())
        .collect();
    assert_eq!(textured.len(), 4);
    for (i, m) in textured.into_iter().zip(models) {
        let t = s.materials[i].texture.as_mut().unwrap();
        t.model = m;
        t.blend_color = Vec3::new(1.0, 1.0, 0.0);
    }
    golden::check("tex_decal_blend_alpha", &draw(&s));
}

#[test]
fn texture_receding_checkerboard_and_magnified() {
    // A floor of the fine checker repeated 40 times: far away it must turn
    // grey (mip-mapped), not moiré. Beside it, the 8x8 checker magnified on
    // a small quad: smooth bilinear steps.
    let src =         "#VRML V2.0 utf8\nNavigationInfo { headlight FALSE }\nBackground { skyColor 0.1 0.1 0.15 }\nViewpoint { position 0 1 4 orientation 1 0 0 -0.15 }\n\
         Shape { appearance Appearance { texture ImageTexture { url \"fine.png\" } }\n geometry IndexedFaceSet { coord Coordinate { point [-20 0 4, 20 0 4, 20 0 -200, -20 0 -200] } coordIndex [0 1 2 3] texCoord TextureCoordinate { point [0 0, 40 0, 40 204, 0 204] } } }\n\
         Transform { translation 1.2 1.3 0 children Shape { appearance Appearance { texture ImageTexture { url \"checker.png\" } }\n geometry IndexedFaceSet { coord Coordinate { point [-0.5 -0.5 0, 0.5 -0.5 0, 0.5 0.5 0, -0.5 0.5 0] } coordIndex [0 1 2 3] texCoord TextureCoordinate { point [0 0, 0.25 0, 0.25 0.25, 0 0.25] } } } }\n";
    let f = draw(&load(src));
    // The far floor (just below the horizon) averages to mid grey with
    // little spread: no moiré.
    let row = (H / 2 - 12) as usize;
    let px: Vec<f32> = (40..200)
        .map(|x| (f.color[row * W as usize + x] >> 8 & 0xFF) as f32)
        .collect();
    let mean = px.iter().sum::<f32>() / px.len() as f32;
    let spread = px.iter().map(|p| (p - mean).abs()).fold(0.0, f32::max);
    assert!(spread < 40.0, "far floor varies by {spread} around {mean}");
    golden::check("tex_mipmap_and_magnified", &f);
}

#[test]
fn background_gradient_and_panorama() {
    // Sky blue → red → white, ground brown → green up to 1.3 rad.
    let sky = "Background { skyColor [0 0 1, 1 0 0, 1 1 1] skyAngle [1.2, 1.57] groundColor [0.5 0.3 0, 0 1 0] groundAngle [1.3] }";
    let src = format!("#VRML V2.0 utf8\nViewpoint {{ position 0 0 0 fieldOfView 1.6 orientation 1 0 0 0.3 }}\n{sky}\n");
    golden::check("bg_gradient", &draw(&load(&src)));
    // Six faces seen looking to the front-left and a little up: front (red),
    // left (blue) and top (cyan) show, each upright with its dark bar up.
    let pano = "Background { skyColor 0.2 0.2 0.2 frontUrl \"front.png\" backUrl \"back.png\" leftUrl \"left.png\" rightUrl \"right.png\" topUrl \"top.png\" bottomUrl \"bottom.png\" }";
    let src = format!("#VRML V2.0 utf8\nViewpoint {{ position 0 0 0 fieldOfView 1.6 orientation 0.3 0.9 0 0.8 }}\n{pano}\n");
    let s = load(&src);
    assert_eq!(s.images.len(), 6);
    golden::check("bg_panorama", &draw(&s));
    // --bg (a spec background) overrides the file's gradient.
    let spec = FrameSpec {
        width: 40,
        height: 30,
        background: Some(Vec3::new(0.0, 1.0, 0.0)),
        ..FrameSpec::default()
    };
    let f = render_at(&s, &spec, 0.0).unwrap();
    assert!(f.color.iter().all(|&c| c == 0x00FF00), "--bg must win");
}

#[test]
fn sgi_rgb_texture() {
    // The Inventor corpus' SGI image (tests/data/textures/brick.rgb) on a
    // VRML97 box.
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/textures/brick.rgb");
    let src = format!(
        "{HEAD}Transform {{ rotation 1 1 0 0.6 children Shape {{ appearance Appearance {{ material Material {{}} texture ImageTexture {{ url \"{}\" }} }} geometry Box {{ size 2.5 2.5 2.5 }} }} }}\n",
        data.display()
    );
    let s = load(&src);
    assert_eq!(s.images.len(), 1);
    golden::check("tex_sgi_rgb", &draw(&s));
}

/// Loads a file from `tests/data/` with no warnings and draws it with its
/// own camera and lights.
fn draw_file(rel: &str) -> Frame {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(rel);
    let l = animed::internals::format::load(&path).unwrap();
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    draw(&l.scene)
}

#[test]
fn inventor_texture_nodes() {
    // tests/data/textures/inventor.iv, top row: Cube, Cylinder with a
    // Texture2Transform (×2, turned), Cone with BLEND towards yellow, Sphere
    // (default mappings; inline 8x8 checker, blue marker texel top-left);
    // bottom row: QuadMesh (bounding-box mapping), a clamped DECAL quad with
    // TextureCoordinate2 -0.5..1.5, an orange sphere with
    // TextureCoordinatePlane (MODULATE). Compared side by side with Coin 4
    // (pivy, same size and camera): silhouette IoU 0.995, mean colour
    // difference inside the shared silhouette 1.8 % of full scale.
    golden::check("tex_inventor_nodes", &draw_file("textures/inventor.iv"));
}

#[test]
fn gltf_base_color_textures() {
    // tests/data/gltf/textured.gltf: left, a 2x2 PNG from a buffer view
    // (red, green / blue, white, magnified: bilinear); right, the RGBA file
    // beside it, clamped, BLEND, KHR_texture_transform taking its right
    // half (cyan over dark grey; at its left edge bilinear filtering
    // reaches half into the half-transparent yellow/magenta column).
    golden::check("gltf_textured", &draw_file("gltf/textured.gltf"));
}

#[test]
fn gltf_sampler_modes() {
    // tests/data/gltf/sampler_modes.gltf: left, a 4x4 texture of distinct
    // colours, NEAREST, MIRRORED_REPEAT across u = 0..2: hard-edged texel
    // squares, the right half the mirror image of the left; right, a yellow
    // plus cut out of a 4x4 RGBA texture by alphaMode MASK (the corners are
    // not drawn at all).
    let f = draw_file("gltf/sampler_modes.gltf");
    golden::check("gltf_sampler_modes", &f);
    let (w, h) = (f.width as usize, f.height as usize);
    let px = |x: usize, y: usize| f.color[y * w + x];
    let id = |x: usize, y: usize| f.ids[y * w + x];
    // The left quad's drawn columns, and its mirror symmetry (nearest
    // texels: whole colours, so mirrored pixels match exactly, away from
    // the quad's own edges).
    let row = h / 2;
    let cols: Vec<usize> = (0..w / 2).filter(|&x| id(x, row) != 0).collect();
    let (a, b) = (cols[0], *cols.last().unwrap());
    let mut same = 0;
    for x in a + 2..(a + b) / 2 - 1 {
        let m = a + b - x;
        same += (px(x, row) == px(m, row)) as usize;
    }
    assert!(
        same * 10 >= ((a + b) / 2 - 1 - (a + 2)) * 9,
        "mirror symmetric: {same}"
    );
    // NEAREST: colour changes come as a few hard jumps at texel edges (4
    // texels, mirrored: 6 inner edges; red steps by 60 per texel), not as
    // bilinear ramps.
    let red = |x: usize| (px(x, row) >> 16 & 0xFF) as i32;
    let steps: Vec<i32> = (a + 2..b - 2)
        .map(|x| (red(x + 1) - red(x)).abs())
        .collect();
    let jumps = steps.iter().filter(|&&d| d > 20).count();
    let small = steps.iter().filter(|&&d| d <= 2).count();
    assert!((5..=8).contains(&jumps), "{jumps} hard edges");
    assert_eq!(small + jumps, steps.len(), "{steps:?}");
    // MASK: the plus's centre is drawn, its corners are background.
    let right: Vec<usize> = (w / 2..w).filter(|&x| id(x, row) != 0).collect();
    let (c0, c1) = (right[0], *right.last().unwrap());
    let cx = (c0 + c1) / 2;
    let quarter = (c1 - c0) / 8;
    assert_ne!(id(cx, row), 0);
    let top = (0..h).find(|&y| id(cx, y) != 0).unwrap();
    assert_eq!(id(c0 + quarter, top + quarter), 0, "corner cut out");
    assert_eq!(id(c1 - quarter, top + quarter), 0, "corner cut out");
}

/// Every textured shape's texture coordinate after its texture transform,
/// per vertex, with the image's pixels and wraps: what a round trip must
/// keep.
/// (image name, pixels, clamp s, clamp t, mapped coordinates).
type TextureSummary = (String, Vec<[u8; 4]>, bool, bool, Vec<glam::Vec2>);

fn texture_summary(s: &Scene) -> Vec<TextureSummary> {
    let mut out = Vec::new();
    for id in s.walk() {
        let node = s.node(id);
        let animed::internals::scene::NodeKind::Shape(sh) = &node.kind else {
            continue;
        };
        let Some(t) = &s.materials[sh.material.0 as usize].texture else {
            continue;
        };
        let mesh = &s.meshes[sh.mesh.0 as usize];
        let m = t.transform.matrix();
        let mut uv: Vec<glam::Vec2> = mesh
            .texcoords
            .iter()
            .map(|c| m.transform_point2(*c))
            .collect();
        uv.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        uv.dedup_by(|a, b| (*a - *b).length() < 1e-4);
        let img = s.image(t.image).unwrap();
        out.push((
            img.name.clone(),
            img.base().pixels().to_vec(),
            t.wrap_s == animed::internals::scene::Wrap::Clamp,
            t.wrap_t == animed::internals::scene::Wrap::Clamp,
            uv,
        ));
    }
    out
}

#[test]
fn textures_survive_read_write_read() {
    // An Inventor file with inline images and a texture transform, and the
    // OBJ whose MTL names a JPEG beside it: each written as .wrl and .iv
    // (and the OBJ as .gltf) and read back keeps images, wraps and mapped
    // coordinates; file textures stay references (relative urls).
    let dir = std::env::temp_dir().join(format!("animed-tex-roundtrip-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    for (src, outs) in [
        ("textures/inventor.iv", &["wrl", "iv"][..]),
        ("oak_leafless.obj", &["wrl", "iv", "gltf"][..]),
    ] {
        let a = animed::internals::format::load(&data.join(src))
            .unwrap()
            .scene;
        let want = texture_summary(&a);
        assert!(!want.is_empty(), "{src} has textures");
        for ext in outs {
            let out = dir.join(format!("out.{ext}"));
            animed::internals::format::save(
                &a,
                &out,
                &animed::internals::format::WriteOptions::default(),
            )
            .unwrap();
            let b = animed::internals::format::load(&out)
                .unwrap_or_else(|e| panic!("{src} → {ext}: {e}"));
            let got = texture_summary(&b.scene);
            assert_eq!(got.len(), want.len(), "{src} → {ext}");
            for (g, w) in got.iter().zip(&want) {
                assert_eq!((&g.1, g.2, g.3), (&w.1, w.2, w.3), "{src} → {ext}: {}", w.0);
                // The same set of mapped coordinates (vertex order and
                // welding may differ between formats).
                let covers = |a: &[glam::Vec2], b: &[glam::Vec2]| {
                    a.iter()
                        .all(|p| b.iter().any(|q| (*p - *q).length() < 1e-3))
                };
                assert!(
                    covers(&g.4, &w.4),
                    "{src} → {ext}: {} gained coordinates",
                    w.0
                );
                // Except the cone's two seam-apex corners (s just outside
                // 0..1, zero-area triangles the VRML97 reader drops).
                let kept: Vec<glam::Vec2> =
                    w.4.iter()
                        .copied()
                        .filter(|p| (-1e-3..=1.0 + 1e-3).contains(&p.x) || p.y.fract() != 0.0)
                        .collect();
                assert!(
                    covers(&kept, &g.4),
                    "{src} → {ext}: {} lost coordinates: {:?}",
                    w.0,
                    kept.iter()
                        .filter(|p| !g.4.iter().any(|q| (**p - *q).length() < 1e-3))
                        .take(5)
                        .collect::<Vec<_>>()
                );
            }
            if src.ends_with(".obj") && *ext != "gltf" {
                let text = std::fs::read_to_string(&out).unwrap();
                let rel = animed::internals::format::export::textures::relative_url(
                    &dir,
                    &data.join("oakbark.jpg"),
                );
                assert!(text.contains(&format!("\"{rel}\"")), "{ext} names {rel}");
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// glTF emissive maps in a dim scene (tests/data/gltf/emissive.gltf, one
/// directional light of 1 lux = intensity 1/π, no headlight): left, a
/// glowing checker as emissiveTexture on a near-black lit material;
/// middle, a grey checker base colour texture lit dimly plus the glowing
/// checker repeated twice (KHR_texture_transform) and tinted blue; right,
/// KHR_materials_unlit with the glowing checker as base colour texture,
/// tinted by baseColorFactor [1, 0.5, 0.5]. Emission is added to the lit
/// colour before the clamp (glTF 2.0 §3.9.3, Appendix B), checked on
/// pixels: with the light off a glowing texel is exactly the texel and a
/// dark one black; with it on the glowing texel is the dark texel's lit
/// colour plus the texel. view3dscene 4.2 draws the left and right quads
/// alike (it ignores KHR_texture_transform on the emissive texture).
#[test]
fn gltf_emissive_maps() {
    use animed::internals::format::gltf::srgb_from_linear;
    use animed::internals::render::job::Headlight;
    use animed::internals::scene::NodeKind;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/gltf/emissive.gltf");
    let mut scene = animed::internals::format::load(&path).unwrap().scene;
    let spec = FrameSpec {
        width: W,
        height: H,
        headlight: Headlight::Off,
        ..FrameSpec::default()
    };
    let on = render_at(&scene, &spec, 0.0).unwrap();
    golden::check("gltf_emissive", &on);
    let sun = scene.find_node("Sun").unwrap();
    if let NodeKind::Light(l) = &mut scene.nodes[sun.0 as usize].kind {
        l.on = false;
    }
    let off = render_at(&scene, &spec, 0.0).unwrap();
    // The pixel at the centre of texel (i, j) of the 4x4 checker on `name`.
    let at = |f: &Frame, name: &str, i: usize, j: usize| -> [i32; 3] {
        let id = scene.find_node(name).unwrap().0 + 1;
        let w = f.width as usize;
        let px: Vec<(usize, usize)> = (0..f.ids.len())
            .filter(|&k| f.ids[k] == id)
            .map(|k| (k % w, k / w))
            .collect();
        let (x0, x1) = (
            px.iter().map(|p| p.0).min().unwrap(),
            px.iter().map(|p| p.0).max().unwrap(),
        );
        let (y0, y1) = (
            px.iter().map(|p| p.1).min().unwrap(),
            px.iter().map(|p| p.1).max().unwrap(),
        );
        let x = x0 + (x1 - x0) * (2 * i + 1) / 8;
        let y = y0 + (y1 - y0) * (2 * j + 1) / 8;
        let c = f.color[y * w + x];
        [
            (c >> 16) as i32 & 255,
            (c >> 8) as i32 & 255,
            c as i32 & 255,
        ]
    };
    // Light off: emission only. Texel (0, 0) glows (255, 200, 40) × 1.
    assert_eq!(at(&off, "Glow", 0, 0), [255, 200, 40]);
    assert_eq!(at(&off, "Glow", 1, 0), [0, 0, 0]);
    // Texel (3, 3) is (255, 80, 220).
    assert_eq!(at(&off, "Glow", 3, 3), [255, 80, 220]);
    // Light on: the dark texel shows the lit base colour, the glowing one
    // that plus the texel (then clamped).
    let dark = at(&on, "Glow", 1, 0);
    assert!(dark[0] > 0 && dark == [dark[0]; 3], "{dark:?}");
    let glow = at(&on, "Glow", 0, 0);
    for (c, t) in [(1, 200), (2, 40)] {
        assert!(
            (glow[c] - (dark[c] + t)).abs() <= 1,
            "{glow:?} = {dark:?} + texel"
        );
    }
    assert_eq!(glow[0], 255);
    // Unlit: sRGB(baseColorFactor) × texel, with or without the light.
    let f = srgb_from_linear(Vec3::new(1.0, 0.5, 0.5));
    let want = [255.0 * f.x, 200.0 * f.y, 40.0 * f.z].map(|x| x.round() as i32);
    for frame in [&on, &off] {
        let got = at(frame, "Unlit", 0, 0);
        assert!(
            got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1),
            "{got:?} vs {want:?}"
        );
        assert_eq!(at(frame, "Unlit", 1, 0), [0, 0, 0]);
    }
}

/// Broken or missing texture images are warnings at the statement that
/// names them (the MTL line, or the glTF image's JSON pointer), the model
/// still loads, draws untextured, and nothing panics.
#[test]
fn broken_texture_images_are_placed_warnings() {
    let dir = std::env::temp_dir().join(format!("animed-bad-tex-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("broken.png"), b"\x89PNG\r\n\x1a\nGARBAGE").unwrap();
    std::fs::write(
        dir.join("tri.mtl"),
        "# test\nnewmtl plain\nKd 1 0 0\nnewmtl m\nKd 1 1 1\n  map_Kd broken.png\nmap_d missing.png\n",
    )
    .unwrap();
    let obj = dir.join("tri.obj");
    let obj_text = "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n";
    let loaded = load_bytes(obj_text.as_bytes(), &obj).expect("loads despite bad images");
    let mtl = dir.join("tri.mtl");
    let want = [
        format!(
            "{}:6:3: material \"m\": cannot read texture 'broken.png'",
            mtl.display()
        ),
        format!(
            "{}:7:1: material \"m\": cannot read texture 'missing.png'",
            mtl.display()
        ),
    ];
    for w in &want {
        assert!(
            loaded
                .warnings
                .iter()
                .any(|got| got.starts_with(w.as_str())),
            "no warning starting {w:?} in {:?}",
            loaded.warnings
        );
    }
    assert!(loaded.scene.materials.iter().all(|m| m.texture.is_none()));
    let frame = draw(&loaded.scene);
    assert!(
        frame.color.iter().any(|&p| p != frame.color[0]),
        "the triangle is drawn"
    );

    // A missing library: the OBJ's own mtllib line.
    let lost = load_bytes(b"v 0 0 0\nmtllib gone.mtl\n", &dir.join("lost.obj")).unwrap();
    assert!(
        lost.warnings.iter().any(|w| w.starts_with(&format!(
            "{}:2:1: cannot read material library",
            dir.join("lost.obj").display()
        ))),
        "{:?}",
        lost.warnings
    );

    // glTF: an image that does not decode names its JSON pointer, no fake 0:0.
    let gltf = dir.join("bad.gltf");
    let json = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/gltf/textured.gltf"),
    )
    .unwrap();
    let mut doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    doc["images"][0] = serde_json::json!({"uri": "data:image/png;base64,iVBORw0KGgpHQVJCQUdF"});
    let loaded = load_bytes(doc.to_string().as_bytes(), &gltf).expect("loads");
    assert!(
        loaded.warnings.iter().any(|w| w.starts_with(&format!(
            "{}: /images/0: cannot read texture",
            gltf.display()
        ))),
        "{:?}",
        loaded.warnings
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A mesh without normals is drawn unlit, and keeps its texture: without
/// a Material (VRML97's unlit REPLACE) the picture is the same whether the
/// quads carry normals or not, for the opaque lane pass (RGB checker) and
/// the transparent pass (RGBA disc) alike. The renderer used to drop the
/// texture coordinates of meshes without normals (flat white quads).
#[test]
fn unlit_meshes_without_normals_keep_their_texture() {
    let src = [
        quad(-1.0, "texture ImageTexture { url \"checker.png\" }"),
        quad(1.0, "texture ImageTexture { url \"rgba.png\" }"),
    ]
    .concat();
    let mut s = load(&format!("{HEAD}{src}"));
    let with_normals = draw(&s);
    assert!(s.meshes.iter().all(|m| !m.normals.is_empty()));
    for m in &mut s.meshes {
        m.normals.clear();
    }
    let without = draw(&s);
    let count = |f: &Frame, want: fn([u32; 3]) -> bool| {
        f.color
            .iter()
            .filter(|&&c| want([c >> 16 & 0xFF, c >> 8 & 0xFF, c & 0xFF]))
            .count()
    };
    // The checker's red and white texels and the disc's green, unlit (the
    // magnified checker is bilinear, so no texel colour is exact).
    let red: fn([u32; 3]) -> bool = |[r, g, b]| r > 180 && g < 110 && b < 110;
    let white: fn([u32; 3]) -> bool = |[r, g, b]| r > 200 && g > 200 && b > 200;
    let green: fn([u32; 3]) -> bool = |[r, g, b]| g > 180 && r < 60 && b < 90;
    for (name, want) in [("red", red), ("white", white), ("green", green)] {
        assert!(count(&without, want) > 50, "{name}: texture missing");
    }
    assert!(with_normals.color == without.color, "unlit texture differs");
}
