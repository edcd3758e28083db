//! Export → import through the Inventor reader: every key survives.
//! (The Inventor reader rebuilds the node tree differently — a Separator
//! becomes an extra group — so re-export is not byte-identical yet.)
mod writers_common;

use animed::format::save::{to_bytes, OutputFormat};
use animed::format::{load_bytes, WriteOptions};
use animed::scene::Scene;
use std::path::Path;

fn export(s: &Scene) -> Vec<u8> {
    to_bytes(s, OutputFormat::Inventor, &WriteOptions::default()).0
}

#[test]
fn demo_keys_survive() {
    let s = writers_common::demo_scene();
    let a = export(&s);
    let loaded = load_bytes(&a, Path::new("demo.iv")).unwrap_or_else(|e| panic!("{e}"));
    assert!(loaded.warnings.is_empty(), "{:#?}", loaded.warnings);
    let t = loaded.scene;
    assert_eq!(t.settings, s.settings);
    assert_eq!(t.animation.tracks.len(), s.animation.tracks.len());
    for (x, y) in t.animation.tracks.iter().zip(&s.animation.tracks) {
        assert_eq!(x.keys, y.keys);
        assert_eq!(x.repeat, y.repeat);
        assert_eq!(x.target.property, y.target.property);
    }
}
