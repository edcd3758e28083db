//! Export → import → export through the VRML97 reader: every key survives
//! and the second export is byte-identical.
mod writers_common;

use animed::internals::format::save::{to_bytes, OutputFormat};
use animed::internals::format::{load_bytes, WriteOptions};
use animed::internals::scene::Scene;
use std::path::Path;

fn export(s: &Scene, f: OutputFormat) -> Vec<u8> {
    to_bytes(s, f, &WriteOptions::default()).0
}

fn reimport(bytes: &[u8], name: &str) -> Scene {
    let loaded = load_bytes(bytes, Path::new(name)).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        loaded.warnings.is_empty(),
        "warnings: {:#?}",
        loaded.warnings
    );
    loaded.scene
}

#[test]
fn demo_round_trips_byte_identical() {
    let s = writers_common::demo_scene();
    for f in [OutputFormat::Vrml97, OutputFormat::Vrml97Gz] {
        let a = export(&s, f);
        let t = reimport(&a, "demo.wrl");
        let b = export(&t, f);
        if a != b {
            std::fs::write("/tmp/rt_a.wrl", &a).unwrap();
            std::fs::write("/tmp/rt_b.wrl", &b).unwrap();
        }
        assert!(
            a == b,
            "re-export differs (see /tmp/rt_a.wrl, /tmp/rt_b.wrl)"
        );
        assert_eq!(t.settings, s.settings);
        assert_eq!(t.animation.tracks.len(), s.animation.tracks.len());
        for (x, y) in t.animation.tracks.iter().zip(&s.animation.tracks) {
            assert_eq!(x.keys, y.keys);
            assert_eq!(x.repeat, y.repeat);
            assert_eq!(x.target.property, y.target.property);
        }
    }
}

/// A file of primitives (read as meshes with default texture coordinates
/// and computed normals) converts to the same bytes the second time: the
/// writer leaves out texture coordinates no texture uses (a reader drops
/// them), and unit normals read back keep their bits.
#[test]
fn primitives_convert_to_a_fixed_point() {
    let src = "#VRML V2.0 utf8\n\
        Shape { geometry Box { } }\n\
        Transform { translation 3 0 0 children Shape { geometry Sphere { } } }\n\
        Transform { translation 6 0 0 children Shape { geometry Cone { } } }\n\
        Transform { translation 9 0 0 children Shape { geometry Cylinder { } } }\n";
    let s = reimport(src.as_bytes(), "prim.wrl");
    let a = export(&s, OutputFormat::Vrml97);
    let b = export(&reimport(&a, "a.wrl"), OutputFormat::Vrml97);
    let c = export(&reimport(&b, "b.wrl"), OutputFormat::Vrml97);
    let text = String::from_utf8_lossy(&a);
    assert!(
        !text.contains("texCoord"),
        "untextured: no texCoord\n{text}"
    );
    assert!(text.contains("normal Normal"), "{text}");
    if a != b || b != c {
        std::fs::write("/tmp/rt_prim_a.wrl", &a).unwrap();
        std::fs::write("/tmp/rt_prim_b.wrl", &b).unwrap();
        std::fs::write("/tmp/rt_prim_c.wrl", &c).unwrap();
    }
    assert!(a == b, "second export differs (/tmp/rt_prim_a.wrl, _b.wrl)");
    assert!(b == c, "third export differs (/tmp/rt_prim_b.wrl, _c.wrl)");
}
