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

/// Triangles of the shapes that are drawn: a shape counts when it and
/// every group above it are visible (the pose's rule), so a hidden shape
/// written as a hidden Transform around the shape counts the same.
fn scene_triangles(s: &animed::internals::scene::Scene) -> usize {
    let drawn = |mut id| loop {
        let n = s.node(id);
        if !n.visible {
            return false;
        }
        match n.parent {
            Some(p) => id = p,
            None => return true,
        }
    };
    s.walk()
        .into_iter()
        .filter_map(|id| match &s.node(id).kind {
            animed::internals::scene::NodeKind::Shape(sh) if drawn(id) => {
                s.meshes.get(sh.mesh.0 as usize).map(|m| m.triangles.len())
            }
            _ => None,
        })
        .sum()
}

/// `path:line:column: message` with line and column from 1 — or, for a
/// compressed stream that does not decompress (no text position exists),
/// `path: gzip …`. Readers print an unknown position as `path: message`,
/// never as a fake `path:0:0:`.
fn is_positioned(msg: &str, path: &Path) -> bool {
    let Some(rest) = msg.strip_prefix(&format!("{}:", path.display())) else {
        return false;
    };
    if rest.starts_with(" gzip") {
        return true;
    }
    let mut parts = rest.splitn(3, ':');
    let line = parts.next().unwrap_or("");
    let col = parts.next().unwrap_or("");
    let message = parts.next().unwrap_or("");
    line.parse::<u32>().is_ok_and(|l| l > 0)
        && col.parse::<u32>().is_ok_and(|c| c > 0)
        && message.len() > 2
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
        let r = std::panic::catch_unwind(|| animed::internals::format::load(&path));
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

/// What an export → import must keep: shapes, triangles, lights, cameras,
/// tracks and their keys (the key note carries them).
#[derive(Debug, PartialEq)]
struct Summary {
    nodes: usize,
    shapes: usize,
    triangles: usize,
    lights: usize,
    cameras: usize,
    tracks: usize,
    keys: usize,
}

fn summary(s: &animed::internals::scene::Scene) -> Summary {
    use animed::internals::scene::NodeKind;
    let count = |f: &dyn Fn(&NodeKind) -> bool| s.nodes.iter().filter(|n| f(&n.kind)).count();
    let keys = s.animation.tracks.iter().map(|t| t.keys.len()).sum();
    Summary {
        nodes: s.nodes.len(),
        shapes: count(&|k| matches!(k, NodeKind::Shape(_))),
        triangles: scene_triangles(s),
        lights: count(&|k| matches!(k, NodeKind::Light(_))),
        cameras: count(&|k| matches!(k, NodeKind::Camera(_))),
        tracks: s.animation.tracks.len(),
        keys,
    }
}

/// Every corpus file that loads is written as .wrl and as .iv, read back,
/// written and read again: the first import keeps the original's shapes,
/// triangles, lights, cameras, tracks and keys, the second equals the
/// first in every count (nodes included: export is a fixed point), and
/// every written file reads back (never deeper than the reader's limit).
#[test]
fn corpus_round_trips_through_both_writers() {
    use animed::internals::format::{load_bytes, save::to_bytes, OutputFormat, WriteOptions};
    let dir = shared_dir().join("corpus");
    let manifest = dir.join("MANIFEST.tsv");
    let Ok(text) = std::fs::read_to_string(&manifest) else {
        eprintln!(
            "\n\n!!!!!!!! CORPUS NOT FOUND at {} — corpus ROUND-TRIP test did NOT run.\n\
             !!!!!!!! Set ANIMED_SHARED=/path/to/shared to run it.\n\n",
            manifest.display()
        );
        return;
    };
    let t0 = Instant::now();
    let only = std::env::var("CORPUS_ONLY").ok();
    let opts = WriteOptions::default();
    let (mut tried, mut failures, mut node_diffs) = (0, Vec::new(), Vec::new());
    let mut biggest_ratio = (0.0f64, String::new());
    for line in text.lines().skip(1) {
        let rel = line.split('\t').next().unwrap_or("");
        if rel.is_empty() || only.as_ref().is_some_and(|o| !rel.contains(o.as_str())) {
            continue;
        }
        let path = dir.join(rel);
        let t_file = Instant::now();
        let Ok(original) = animed::internals::format::load(&path) else {
            continue;
        };
        tried += 1;
        let want = summary(&original.scene);
        let in_size = std::fs::metadata(&path)
            .map(|m| m.len())
            .unwrap_or(1)
            .max(1);
        for (ext, format) in [
            ("wrl", OutputFormat::Vrml97),
            ("iv", OutputFormat::Inventor),
        ] {
            let name = Path::new(rel).with_extension(ext);
            let (bytes, _) = to_bytes(&original.scene, format, &opts);
            let ratio = bytes.len() as f64 / in_size as f64;
            if ratio > biggest_ratio.0 {
                biggest_ratio = (ratio, format!("{rel} → .{ext}"));
            }
            let first = match load_bytes(&bytes, &name) {
                Ok(l) => l,
                Err(e) => {
                    failures.push(format!("{rel} → .{ext}: does not read back: {e}"));
                    continue;
                }
            };
            let got = summary(&first.scene);
            let kept = |s: &Summary| (s.shapes, s.triangles, s.lights, s.cameras, s.tracks, s.keys);
            if kept(&got) != kept(&want) {
                failures.push(format!("{rel} → .{ext}: {want:?} became {got:?}"));
                continue;
            }
            if got.nodes != want.nodes {
                node_diffs.push(format!(
                    "{rel} → .{ext}: {} → {} nodes",
                    want.nodes, got.nodes
                ));
            }
            let (again, _) = to_bytes(&first.scene, format, &opts);
            match load_bytes(&again, &name) {
                Ok(second) if summary(&second.scene) == got => {}
                Ok(second) => failures.push(format!(
                    "{rel} → .{ext} twice: {got:?} became {:?}",
                    summary(&second.scene)
                )),
                Err(e) => failures.push(format!("{rel} → .{ext} twice: {e}")),
            }
        }
        if t_file.elapsed().as_secs_f64() > 2.0 {
            println!("  slow: {rel} {:.1} s", t_file.elapsed().as_secs_f64());
        }
    }
    println!(
        "\ncorpus round trip: {tried} files × 2 formats in {:.1} s; largest output/input size ratio {:.1} ({})",
        t0.elapsed().as_secs_f64(),
        biggest_ratio.0,
        biggest_ratio.1
    );
    for d in &node_diffs {
        println!("  node count changes on the first export (then stable): {d}");
    }
    assert!(
        only.is_some() || tried > 100,
        "only {tried} corpus files loaded"
    );
    // Known differences, found by this test when it first ran (session 4)
    // and not fixed yet; each is a real export defect to fix in a writer or
    // reader. The test fails when a file not listed here fails, and when a
    // listed file passes (then take it off the list), so the list stays true.
    // None left.
    // Healed in session 5: empty shapes (a face set without faces, a
    // PointSet without points) are written as an empty IndexedFaceSet so
    // they stay shapes; hidden shapes (Switch alternatives) written as a
    // hidden Transform around the shape count as hidden (`scene_triangles`
    // follows the pose's rule: hidden when any group above is).
    // Healed in session 6: morph targets (warbird: two CoordinateInterpolators
    // of 11 keys, read as 11 one-hot targets each) go into .iv as Calculator
    // engines that the Inventor reader reads back as the same targets, so
    // the key note's 22 weights keys fit them again.
    const KNOWN: &[&str] = &[];
    let (known, new): (Vec<&String>, Vec<&String>) = failures
        .iter()
        .partition(|f| KNOWN.iter().any(|k| f.contains(k)));
    if !known.is_empty() {
        println!(
            "\n!!! {} KNOWN round-trip differences (listed in this test, not fixed yet):",
            known.len()
        );
        for f in &known {
            println!("  {f}");
        }
    }
    let healed: Vec<&&str> = KNOWN
        .iter()
        .filter(|k| only.is_none() && !failures.iter().any(|f| f.contains(**k)))
        .collect();
    assert!(
        healed.is_empty(),
        "these files round-trip now; take them off KNOWN: {healed:?}"
    );
    assert!(
        new.is_empty(),
        "{} round-trip failures:\n{}",
        new.len(),
        new.iter()
            .map(|f| f.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    );
}
