//! Loads every file of the shared corpus (`$ANIMED_SHARED/corpus`, falling
//! back to `CARGO_MANIFEST_DIR/../shared/corpus`).
//!
//! Asserts: nothing panics; every failure is a `path:line:column: message`;
//! at least 95% of the Inventor/VRML files that Coin reads load. Prints the
//! counts per format and the files whose triangle count differs from Coin's.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

fn shared_dir() -> PathBuf {
    match std::env::var_os("ANIMED_SHARED") {
        Some(d) => PathBuf::from(d),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared"),
    }
}

#[derive(Default)]
struct Counts {
    files: usize,
    loaded: usize,
    failed: usize,
    panicked: usize,
    coin_reads: usize,
    coin_reads_loaded: usize,
    tris_match: usize,
    tris_compared: usize,
}

/// Coin's triangle count from `tris/lines/points`.
fn coin_tris(col: &str) -> Option<usize> {
    col.split('/').next()?.trim().parse().ok()
}

fn scene_triangles(s: &animed::scene::Scene) -> usize {
    s.walk()
        .into_iter()
        .filter_map(|id| match &s.node(id).kind {
            animed::scene::NodeKind::Shape(sh) if s.node(id).visible => {
                s.meshes.get(sh.mesh.0 as usize).map(|m| m.triangles.len())
            }
            _ => None,
        })
        .sum()
}

/// `path:line:column: message` with numeric line and column.
fn is_positioned(msg: &str, path: &Path) -> bool {
    let Some(rest) = msg.strip_prefix(&format!("{}:", path.display())) else {
        return false;
    };
    let mut parts = rest.splitn(3, ':');
    let line = parts.next().unwrap_or("");
    let col = parts.next().unwrap_or("");
    let message = parts.next().unwrap_or("");
    line.parse::<u32>().is_ok() && col.parse::<u32>().is_ok() && message.len() > 2
}

#[test]
fn corpus_loads() {
    let dir = shared_dir().join("corpus");
    let manifest = dir.join("MANIFEST.tsv");
    let Ok(text) = std::fs::read_to_string(&manifest) else {
        eprintln!(
            "\n\n!!!!!!!! CORPUS NOT FOUND at {} — corpus test did NOT run.\n\
             !!!!!!!! Set ANIMED_SHARED=/path/to/shared to run it.\n\n",
            manifest.display()
        );
        return;
    };
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split('\t').collect();
    let col = |name: &str| header.iter().position(|h| *h == name);
    let c_features = col("features").expect("features column");
    let (c_path, c_format, c_coin, c_tris) = (
        col("path").expect("path column"),
        col("format").expect("format column"),
        col("coin_reads").expect("coin_reads column"),
        col("coin_tris_lines_points").expect("coin_tris_lines_points column"),
    );
    let only = std::env::var("CORPUS_ONLY").ok();
    let mut counts: BTreeMap<String, Counts> = BTreeMap::new();
    let mut bad_messages = Vec::new();
    let mut panics = Vec::new();
    let mut misses = Vec::new();
    let mut tri_diffs = Vec::new();
    let mut slow = Vec::new();
    // Keep the output readable: panics are reported by us, not the hook.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    for line in lines {
        let f: Vec<&str> = line.split('\t').collect();
        if f.len() <= c_coin.max(c_format).max(c_path).max(c_tris) {
            continue;
        }
        let rel = f[c_path];
        if let Some(o) = &only {
            if !rel.contains(o.as_str()) {
                continue;
            }
        }
        let format = f[c_format].to_string();
        let coin_yes = f[c_coin] == "yes";
        let path = dir.join(rel);
        let c = counts.entry(format.clone()).or_default();
        c.files += 1;
        if coin_yes {
            c.coin_reads += 1;
        }
        let t0 = Instant::now();
        let r = std::panic::catch_unwind(|| animed::format::load(&path));
        let dt = t0.elapsed().as_secs_f64();
        if dt > 2.0 {
            slow.push(format!("{dt:.1}s {rel}"));
        }
        match r {
            Err(_) => {
                c.panicked += 1;
                panics.push(rel.to_string());
            }
            Ok(Ok(loaded)) => {
                c.loaded += 1;
                if coin_yes {
                    c.coin_reads_loaded += 1;
                    // Primitives are tessellated differently by every viewer:
                    // compare only files made of explicit polygons.
                    let primitive = f[c_features].split(',').any(|n| {
                        matches!(
                            n,
                            "Box"
                                | "Sphere"
                                | "Cone"
                                | "Cylinder"
                                | "Cube"
                                | "Text"
                                | "AsciiText"
                                | "Text2"
                                | "Text3"
                                | "Extrusion"
                        )
                    });
                    if let (Some(want), false) = (coin_tris(f[c_tris]), primitive) {
                        c.tris_compared += 1;
                        let got = scene_triangles(&loaded.scene);
                        if got == want {
                            c.tris_match += 1;
                        } else {
                            tri_diffs.push(format!("{rel}: animed {got}, Coin {want}"));
                        }
                    }
                }
            }
            Ok(Err(e)) => {
                c.failed += 1;
                let msg = e.to_string();
                if !is_positioned(&msg, &path) {
                    bad_messages.push(msg.clone());
                }
                if coin_yes {
                    misses.push(msg);
                }
            }
        }
    }
    std::panic::set_hook(hook);

    println!("\ncorpus: {}", dir.display());
    println!(
        "{:<10} {:>5} {:>7} {:>7} {:>8} {:>11} {:>13} {:>12}",
        "format",
        "files",
        "loaded",
        "failed",
        "panicked",
        "coin reads",
        "coin→loaded",
        "tris = Coin"
    );
    for (fmt, c) in &counts {
        println!(
            "{:<10} {:>5} {:>7} {:>7} {:>8} {:>11} {:>13} {:>7}/{:<4}",
            fmt,
            c.files,
            c.loaded,
            c.failed,
            c.panicked,
            c.coin_reads,
            c.coin_reads_loaded,
            c.tris_match,
            c.tris_compared
        );
    }
    for m in &misses {
        println!("  Coin reads, animed fails: {m}");
    }
    for t in &tri_diffs {
        println!("  triangles differ: {t}");
    }
    for s in &slow {
        println!("  slow: {s}");
    }
    assert!(panics.is_empty(), "panicked on: {panics:#?}");
    assert!(
        bad_messages.is_empty(),
        "errors without path:line:column: {bad_messages:#?}"
    );
    let (reads, loaded) = counts
        .iter()
        .filter(|(f, _)| f.as_str() != "OBJ")
        .fold((0, 0), |(r, l), (_, c)| {
            (r + c.coin_reads, l + c.coin_reads_loaded)
        });
    if only.is_none() {
        assert!(
            reads > 0,
            "no file in the manifest is marked coin_reads=yes"
        );
        assert!(
            loaded * 100 >= reads * 95,
            "only {loaded} of {reads} files that Coin reads load"
        );
    }
}
