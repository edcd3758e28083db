//! Golden pictures of corpus files read by the Inventor, VRML 1.0 and
//! VRML97 readers (copies in `tests/data/readers/`, licences in
//! `tests/data/LICENSES.md`), drawn the way `animed render` draws them.
//! Each was compared side by side with Coin 4 (pivy) before it was kept.

#[path = "common/golden.rs"]
mod golden;

use animed::internals::render::job::{render_at, FrameSpec, Headlight};
use std::path::Path;

fn draw(file: &str, time: f32) -> animed::internals::render::Frame {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/readers")
        .join(file);
    let loaded = animed::internals::format::load(&path).expect("test file loads");
    let spec = FrameSpec {
        width: 240,
        height: 180,
        viewpoint: None,
        style: None,
        background: Some(glam::Vec3::new(0.2, 0.2, 0.3)),
        headlight: Headlight::Auto,
        threads: 0,
        aa: 1,
    };
    render_at(&loaded.scene, &spec, time).expect("renders")
}

/// Inventor: Cube with PER_PART materials (blue front), MatrixTransforms.
#[test]
fn golden_inventor_simple_monitor() {
    golden::check("read_iv_simple_monitor", &draw("simpleMonitor.iv", 0.0));
}

/// VRML 1.0: Cone/Cylinder/Cube parts and per-part materials.
#[test]
fn golden_vrml1_materials_parts_primitives() {
    golden::check(
        "read_vrml1_materials_parts",
        &draw("materials_parts_primitives.wrl", 0.0),
    );
}

/// VRML97: an OrientationInterpolator on a box, at t = 1 s.
#[test]
fn golden_vrml97_orientation_interpolator_at_1s() {
    golden::check(
        "read_vrml97_alum_box_t1",
        &draw("orientation_interpolator_alum_box.wrl", 1.0),
    );
}

/// An Inventor file drawn at 160×120 on black.
fn draw_iv(src: &str, headlight: Headlight) -> animed::internals::render::Frame {
    let loaded =
        animed::internals::format::load_bytes(src.as_bytes(), Path::new("levels.iv")).unwrap();
    let spec = FrameSpec {
        width: 160,
        height: 120,
        viewpoint: None,
        style: None,
        background: Some(glam::Vec3::ZERO),
        headlight,
        threads: 0,
        aa: 1,
    };
    render_at(&loaded.scene, &spec, 0.0).expect("renders")
}

fn rgb(f: &animed::internals::render::Frame, x: usize, y: usize) -> [u8; 3] {
    let c = f.color[y * f.width as usize + x];
    [(c >> 16) as u8, (c >> 8) as u8, c as u8]
}

/// The centre pixel of an Inventor file drawn at 160×120 on black.
fn centre(src: &str, headlight: Headlight) -> [u8; 3] {
    rgb(&draw_iv(src, headlight), 80, 60)
}

/// Inventor's ambient term as Coin 4 draws it (each figure read from
/// Coin's picture of the same file through pivy, tests/coin_levels.py's
/// set-up): the material's ambientColor × the Environment's intensity and
/// colour, whatever the diffuse colour, and no ambient from the lights.
#[test]
fn inventor_ambient_levels_match_coin() {
    let quad = |env: &str, mat: &str, light: &str| {
        format!(
            "#Inventor V2.1 ascii\nSeparator {{ OrthographicCamera {{ position 0 0 5 height 2.2 }}\n\
             {env} {light} Material {{ {mat} }} Cube {{ width 2 height 2 depth 0.1 }} }}"
        )
    };
    // Only the ambient term: 0.8 × (1, 1, 0.5) × (0.5, 0.25, 1) = (0.4, 0.2, 0.4).
    let env = "Environment { ambientIntensity 0.8 ambientColor 1 1 0.5 }";
    let mat = "diffuseColor 0 0 0 ambientColor 0.5 0.25 1";
    assert_eq!(centre(&quad(env, mat, ""), Headlight::On), [102, 51, 102]);
    // The default 0.2 grey ambient on a red face: 0.04 in green and blue
    // too (VRML97's ambientIntensity × diffuse would give 0 there).
    let red = "diffuseColor 1 0 0 ambientColor 0.2 0.2 0.2";
    assert_eq!(centre(&quad("", red, ""), Headlight::On), [255, 10, 10]);
    assert_eq!(centre(&quad("", red, ""), Headlight::Off), [10, 10, 10]);
    // A light shining from behind adds no ambient of its own.
    let behind = "DirectionalLight { direction 0 0 1 }";
    let white_amb = "diffuseColor 1 0 0 ambientColor 1 1 1";
    assert_eq!(
        centre(&quad("", white_amb, behind), Headlight::Off),
        [51, 51, 51]
    );
}

/// Two red line sets, 5 px wide, at y = ±0.5 (rows 33 and 87).
fn line_pair(normals: &str) -> String {
    format!(
        "#Inventor V2.1 ascii\nSeparator {{ OrthographicCamera {{ position 0 0 5 height 2.2 }}\n\
         DrawStyle {{ lineWidth 5 }} Material {{ diffuseColor 1 0 0 }}\n\
         Coordinate3 {{ point [-1 0.5 0, 1 0.5 0, -1 -0.5 0, 1 -0.5 0] }}\n\
         {normals} IndexedLineSet {{ coordIndex [0 1 -1 2 3 -1] }} }}"
    )
}

/// Inventor line sets with normals are lit, those without are drawn in
/// their diffuse colour; each figure is Coin 4's for the same file (pivy):
/// the upper line's normal faces the headlight (1 + the 0.04 ambient), the
/// lower one's is turned 53° away (0.6 + 0.04).
#[test]
fn inventor_line_sets_with_normals_are_lit_like_coin() {
    let normals = "Normal { vector [0 0 1, 0 0 1, 0.8 0 0.6, 0.8 0 0.6] }";
    for (binding, lower) in [
        ("", [163, 10, 10]),
        ("NormalBinding { value PER_VERTEX }", [163, 10, 10]),
        ("NormalBinding { value PER_PART }", [255, 10, 10]),
        ("NormalBinding { value OVERALL }", [255, 10, 10]),
    ] {
        let f = draw_iv(&line_pair(&format!("{normals} {binding}")), Headlight::On);
        assert_eq!(rgb(&f, 80, 33), [255, 10, 10], "{binding}");
        assert_eq!(rgb(&f, 80, 87), lower, "{binding}");
    }
    let f = draw_iv(&line_pair(""), Headlight::On);
    assert_eq!(rgb(&f, 80, 33), [255, 0, 0], "no normals: unlit");
    assert_eq!(rgb(&f, 80, 87), [255, 0, 0], "no normals: unlit");
}

/// Inventor point sets with normals are lit, those without are drawn in
/// their diffuse colour; each figure is Coin 4's for the same file (pivy,
/// pointSize 9, the file's light from the viewer): a normal facing the
/// light gives 1 + the 0.04 ambient, one turned 53° away 0.6 + 0.04, one
/// turned 37° away 0.8 + 0.04. Normals count from the first whatever the
/// `startIndex`; OVERALL gives every point the first; DEFAULT is per point.
#[test]
fn inventor_point_sets_with_normals_are_lit_like_coin() {
    let src = "#Inventor V2.1 ascii\nSeparator { OrthographicCamera { position 0 0 5 height 4 }\n\
         DirectionalLight { direction 0 0 -1 } DrawStyle { pointSize 9 }\n\
         Material { diffuseColor 1 0 0 }\n\
         Separator { Normal { vector [0 0 1, 0.8 0 0.6, 0 0.6 0.8, 0 0 1] }\n\
           NormalBinding { value PER_VERTEX }\n\
           Coordinate3 { point [9 9 9, -1.5 1 0, -0.5 1 0, 0.5 1 0] } PointSet { startIndex 1 } }\n\
         Separator { Normal { vector [0.8 0 0.6, 0 0 1] } NormalBinding { value OVERALL }\n\
           Coordinate3 { point [-1.5 -1 0, -0.5 -1 0] } PointSet {} }\n\
         Separator { Normal { vector [0.8 0 0.6, 0 0 1] }\n\
           Coordinate3 { point [0.5 -1 0, 1.5 -1 0] } PointSet {} }\n\
         Separator { Coordinate3 { point [0 0 0] } PointSet {} } }";
    let f = draw_iv(src, Headlight::Off);
    // World (x, y) to the pixel: 160×120, an orthographic view 4 high.
    let at = |x: f32, y: f32| rgb(&f, (80.0 + x * 30.0) as usize, (60.0 - y * 30.0) as usize);
    assert_eq!(at(-1.5, 1.0), [255, 10, 10], "PER_VERTEX from startIndex");
    assert_eq!(at(-0.5, 1.0), [163, 10, 10]);
    assert_eq!(at(0.5, 1.0), [214, 10, 10]);
    assert_eq!(at(-1.5, -1.0), [163, 10, 10], "OVERALL");
    assert_eq!(at(-0.5, -1.0), [163, 10, 10], "OVERALL");
    assert_eq!(at(0.5, -1.0), [163, 10, 10], "DEFAULT");
    assert_eq!(at(1.5, -1.0), [255, 10, 10], "DEFAULT");
    assert_eq!(at(0.0, 0.0), [255, 0, 0], "no normals: unlit");
}

/// A line or point is lit by its normal as given, not one turned towards
/// the eye: a normal facing away from the light gets the ambient term
/// only. Each figure is Coin 4's for the same file (pivy, the file's light
/// from the viewer): facing it, diffuse (1, 0.5, 0.2) + the 0.4 × 0.2
/// ambient; facing away, that ambient alone.
#[test]
fn line_and_point_normals_facing_away_get_ambient_only_like_coin() {
    let src = "#Inventor V2.1 ascii\nSeparator { OrthographicCamera { position 0 0 5 height 4 }\n\
         DirectionalLight { direction 0 0 -1 } DrawStyle { lineWidth 6 pointSize 8 }\n\
         Material { diffuseColor 1 0.5 0.2 ambientColor 0.4 0.4 0.4 }\n\
         Separator { Coordinate3 { point [-1.5 1 0, 1.5 1 0, -1.5 0.5 0, 1.5 0.5 0] }\n\
           Normal { vector [0 0 1, 0 0 1, 0 0 -1, 0 0 -1] } NormalBinding { value PER_VERTEX }\n\
           LineSet { numVertices [2, 2] } }\n\
         Separator { Coordinate3 { point [-1 -0.5 0, 1 -0.5 0] }\n\
           Normal { vector [0 0 1, 0 0 -1] } NormalBinding { value PER_VERTEX }\n\
           PointSet {} } }";
    let f = draw_iv(src, Headlight::Off);
    let at = |x: f32, y: f32| rgb(&f, (80.0 + x * 30.0) as usize, (60.0 - y * 30.0) as usize);
    assert_eq!(at(0.0, 1.0), [255, 148, 71], "line facing the light");
    assert_eq!(at(0.0, 0.5), [20, 20, 20], "line facing away: ambient only");
    assert_eq!(at(-1.0, -0.5), [255, 148, 71], "point facing the light");
    assert_eq!(
        at(1.0, -0.5),
        [20, 20, 20],
        "point facing away: ambient only"
    );
}

/// A lit point set: a disc of points carrying a hemisphere's normals, lit
/// from the upper left (bright there, fading to the 0.2 × 0.2 ambient at
/// the lower right), beside the same disc without normals (flat, in its
/// diffuse colour).
#[test]
fn golden_inventor_lit_point_set() {
    let mut pts = Vec::new();
    let mut nrm = Vec::new();
    for j in -6..=6 {
        for i in -6..=6 {
            let (x, y) = (i as f32 / 6.0, j as f32 / 6.0);
            let r2 = x * x + y * y;
            if r2 <= 1.0 {
                // Leaning towards the viewer: a hemisphere seen from the
                // front.
                let n = glam::Vec3::new(x, y, (1.0 - r2).sqrt() + 0.5).normalize();
                pts.push(format!("{x:.4} {y:.4} 0"));
                nrm.push(format!("{:.4} {:.4} {:.4}", n.x, n.y, n.z));
            }
        }
    }
    let (pts, nrm) = (pts.join(", "), nrm.join(", "));
    let src = format!(
        "#Inventor V2.1 ascii\nSeparator {{ OrthographicCamera {{ position 0 0 5 height 3.2 }}\n\
         DirectionalLight {{ direction 1 -1 -1 }}\n\
         DrawStyle {{ pointSize 4 }} Material {{ diffuseColor 0.3 0.8 1 }}\n\
         Coordinate3 {{ point [{pts}] }}\n\
         Separator {{ Transform {{ translation -1.1 0 0 }} Normal {{ vector [{nrm}] }} PointSet {{}} }}\n\
         Separator {{ Transform {{ translation 1.1 0 0 }} PointSet {{}} }} }}"
    );
    golden::check("read_iv_lit_point_set", &draw_iv(&src, Headlight::Off));
}

/// A lit line set: a ring of polylines whose normals point outwards and
/// towards the viewer, lit by a light from the upper left (bright there,
/// dark below right, the 0.2 × 0.2 ambient where the light does not
/// reach), beside the same ring without normals (flat, in its diffuse
/// colour).
#[test]
fn golden_inventor_lit_line_set() {
    let ring = |n: usize| {
        let mut pts = Vec::new();
        let mut nrm = Vec::new();
        for k in 0..=n {
            let a = k as f32 / n as f32 * std::f32::consts::TAU;
            pts.push(format!("{:.4} {:.4} 0", a.cos(), a.sin()));
            nrm.push(format!("{:.4} {:.4} 1.5", a.cos(), a.sin()));
        }
        (pts.join(", "), nrm.join(", "))
    };
    let (pts, nrm) = ring(32);
    let src = format!(
        "#Inventor V2.1 ascii\nSeparator {{ OrthographicCamera {{ position 0 0 5 height 3.2 }}\n\
         DirectionalLight {{ direction 1 -1 -0.3 }}\n\
         DrawStyle {{ lineWidth 3 }} Material {{ diffuseColor 1 0.8 0.2 }}\n\
         Coordinate3 {{ point [{pts}] }}\n\
         Separator {{ Transform {{ translation -1.1 0 0 }} Normal {{ vector [{nrm}] }}\n\
           LineSet {{ numVertices 33 }} }}\n\
         Separator {{ Transform {{ translation 1.1 0 0 }} LineSet {{ numVertices 33 }} }} }}"
    );
    golden::check("read_iv_lit_line_set", &draw_iv(&src, Headlight::Off));
}
