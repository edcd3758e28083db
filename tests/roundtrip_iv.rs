//! Export → import → export through the Inventor reader: every key survives
//! and the second export is byte-identical.
mod writers_common;

use animed::internals::format::save::{to_bytes, OutputFormat};
use animed::internals::format::{load_bytes, WriteOptions};
use animed::internals::scene::Scene;
use std::path::Path;

fn export(s: &Scene) -> Vec<u8> {
    to_bytes(s, OutputFormat::Inventor, &WriteOptions::default()).0
}

#[test]
fn demo_round_trips_byte_identical() {
    let s = writers_common::demo_scene();
    let a = export(&s);
    let loaded = load_bytes(&a, Path::new("demo.iv")).unwrap_or_else(|e| panic!("{e}"));
    assert!(loaded.warnings.is_empty(), "{:#?}", loaded.warnings);
    let t = loaded.scene;
    let b = export(&t);
    if a != b {
        std::fs::write("/tmp/rt_a.iv", &a).unwrap();
        std::fs::write("/tmp/rt_b.iv", &b).unwrap();
    }
    assert!(a == b, "re-export differs (see /tmp/rt_a.iv, /tmp/rt_b.iv)");
    assert_eq!(t.settings, s.settings);
    assert_eq!(t.animation.tracks.len(), s.animation.tracks.len());
    for (x, y) in t.animation.tracks.iter().zip(&s.animation.tracks) {
        assert_eq!(x.keys, y.keys);
        assert_eq!(x.repeat, y.repeat);
        assert_eq!(x.target.property, y.target.property);
    }
}
