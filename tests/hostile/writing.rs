//! Writers never produce what the reader rejects, and their output grows
//! linearly with the scene.

use super::gen;
use animed::internals::format::{load, load_bytes, save, SaveError, WriteOptions};
use std::path::{Path, PathBuf};

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("animed-hostile-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn counts(s: &animed::internals::scene::Scene) -> (usize, usize) {
    let shapes = s
        .nodes
        .iter()
        .filter(|n| matches!(n.kind, animed::internals::scene::NodeKind::Shape(_)))
        .count();
    (s.nodes.len(), shapes)
}

#[test]
fn a_deep_chain_of_translations_writes_files_that_read_back() {
    let dir = temp_dir("wdeep");
    // 200 levels: the old .wrl writer nested each twice (400 > 256).
    let src = load_bytes(&gen::nested_separators(200), Path::new("chain.iv")).unwrap();
    let (_, shapes) = counts(&src.scene);
    for name in ["out.wrl", "out.iv", "out.wrl.gz"] {
        let f = dir.join(name);
        save(&src.scene, &f, &WriteOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        let back = load(&f).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(counts(&back.scene).1, shapes, "{name}");
        assert!(
            back.scene.nodes.len() >= 200,
            "{name}: {} nodes",
            back.scene.nodes.len()
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_scene_too_deep_to_read_back_is_refused_not_written() {
    let dir = temp_dir("wrefuse");
    let src = load_bytes(&gen::vrml1_sibling_groups(300), Path::new("v1.wrl")).unwrap();
    let f = dir.join("out.wrl");
    std::fs::write(&f, b"old").unwrap();
    match save(&src.scene, &f, &WriteOptions::default()) {
        Err(e @ SaveError::TooDeep { .. }) => {
            let m = e.to_string();
            assert!(
                m.contains("--max-depth") && m.contains("levels deep"),
                "{m}"
            );
        }
        Err(e) => panic!("{e}"),
        // Written: then it must read back.
        Ok(_) => {
            load(&f).expect("a written file reads back");
        }
    }
    if std::fs::read(&f).unwrap() == b"old" {
        let left = std::fs::read_dir(&dir).unwrap().count();
        assert_eq!(left, 1, "no temporary file left");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn output_size_grows_linearly_with_depth() {
    let size = |n: usize, ext: &str| {
        let s = load_bytes(&gen::nested_separators(n), Path::new("c.iv")).unwrap();
        let (b, _) = animed::internals::format::save::to_bytes(
            &s.scene,
            animed::internals::format::OutputFormat::from_path(Path::new(ext)).unwrap(),
            &WriteOptions::default(),
        );
        b.len() as f64
    };
    for ext in ["x.wrl", "x.iv"] {
        let (a, b) = (size(50, ext), size(200, ext));
        // 4× the scene: linear growth gives ~4×, quadratic ~16×.
        assert!(b / a < 5.0, "{ext}: {a} → {b} bytes");
    }
}

/// The deepest parent chain in the scene.
fn scene_depth(s: &animed::internals::scene::Scene) -> usize {
    (0..s.nodes.len())
        .map(|i| {
            let mut d = 0;
            let mut p = s.nodes[i].parent;
            while let Some(id) = p {
                d += 1;
                p = s.nodes[id.0 as usize].parent;
            }
            d
        })
        .max()
        .unwrap_or(0)
}

#[test]
fn sibling_chains_stay_shallow_and_write_back_on_a_small_stack() {
    // graz.wrl in the corpus has 4,167 sibling DEF'd Groups; each used to
    // nest the rest, and writing the 4,108-deep scene overflowed a 2 MiB
    // stack. Named Groups now nest nothing after them unless a named
    // transform inside moves what follows, and chains of named transforms
    // stop nesting at a bounded depth.
    let run = || {
        let dir = temp_dir("wchain");
        for (tag, bytes) in [
            ("groups", gen::vrml1_sibling_groups(3000)),
            ("transforms", gen::vrml1_sibling_transforms(3000)),
        ] {
            let src = load_bytes(&bytes, Path::new("v1.wrl")).unwrap();
            let (_, shapes) = counts(&src.scene);
            assert_eq!(shapes, 3000, "{tag}");
            assert!(
                scene_depth(&src.scene) <= 130,
                "{tag}: {}",
                scene_depth(&src.scene)
            );
            for name in ["out.wrl", "out.iv"] {
                let f = dir.join(name);
                save(&src.scene, &f, &WriteOptions::default())
                    .unwrap_or_else(|e| panic!("{tag} {name}: {e}"));
                let back = load(&f).unwrap_or_else(|e| panic!("{tag} {name}: {e}"));
                assert_eq!(counts(&back.scene).1, 3000, "{tag} {name}");
            }
        }
        std::fs::remove_dir_all(&dir).unwrap();
    };
    std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(run)
        .unwrap()
        .join()
        .expect("fits a 2 MiB stack");
}
