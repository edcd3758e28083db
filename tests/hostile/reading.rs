//! Limits through the library: each passed limit is an error at the
//! offending node, naming the limit and how to raise it.

use super::gen;
use animed::internals::format::limits::Limits;
use animed::internals::format::{load, load_bytes_with, LoadError};
use std::path::{Path, PathBuf};

fn load_small(bytes: &[u8], name: &str, lim: Limits) -> Result<usize, LoadError> {
    load_bytes_with(bytes, Path::new(name), lim).map(|l| l.scene.nodes.len())
}

fn assert_limit(r: Result<usize, LoadError>, flag: &str, line: u32) {
    let e = r.expect_err("the limit must stop the load");
    let m = e.to_string();
    assert!(m.contains("input budget exceeded"), "{m}");
    assert!(m.contains(flag), "{m} should name {flag}");
    if line > 0 {
        assert_eq!(e.line, line, "{m}");
        assert!(e.column > 0, "{m}");
    }
}

/// Runs `f` on a thread with a 2 MiB stack (Rust's default for spawned
/// threads): deep inputs must fit it.
fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(f)
        .unwrap()
        .join()
        .expect("no stack overflow")
}

#[test]
fn a_1000_level_proto_chain_is_a_depth_error_not_a_stack_overflow() {
    let r = on_small_stack(|| load_small(&gen::proto_chain(1000), "chain.wrl", Limits::default()));
    assert_limit(r, "--max-depth", 0);
    // 51 levels (the old abort) load: 102 levels expanded.
    let r = on_small_stack(|| load_small(&gen::proto_chain(51), "c.wrl", Limits::default()));
    assert!(r.unwrap() >= 51);
}

#[test]
fn nesting_at_the_largest_depth_allowed_fits_a_2_mib_stack() {
    let deepest = animed::internals::format::limits::DEPTH_CEILING;
    let lim = Limits {
        max_depth: deepest,
        ..Limits::default()
    };
    let l2 = lim.clone();
    // Groups: parser, builder and drop each recurse once per level.
    let n = on_small_stack(move || {
        load_small(&gen::nested_groups(deepest as usize - 2), "deep.wrl", l2)
    });
    assert!(n.unwrap() as u64 >= deepest - 2);
    let r = on_small_stack(move || {
        load_small(&gen::nested_groups(deepest as usize + 5), "deep.wrl", lim)
    });
    assert_limit(r, "--max-depth", 0);
    // A PROTO chain at the ceiling (expanded depth close to it).
    let lim = Limits {
        max_depth: deepest,
        ..Limits::default()
    };
    let r = on_small_stack(move || {
        load_small(
            &gen::proto_chain(deepest as usize / 2 - 2),
            "chain.wrl",
            lim,
        )
    });
    assert!(r.is_ok(), "{r:?}");
    // Binary Inventor: the same ceiling, the same message.
    let l2 = Limits {
        max_depth: deepest,
        ..Limits::default()
    };
    let l3 = l2.clone();
    let n = on_small_stack(move || {
        load_small(
            &gen::binary_nested_separators(deepest as usize - 2),
            "deep.iv",
            l2,
        )
    });
    assert!(n.unwrap() as u64 >= deepest - 2);
    let r = on_small_stack(move || {
        load_small(
            &gen::binary_nested_separators(deepest as usize + 5),
            "deep.iv",
            l3,
        )
    });
    assert_limit(r, "--max-depth", 0);
}

#[test]
fn generated_geometry_is_asked_for_before_it_is_built() {
    let lim = Limits {
        max_geometry: 100_000,
        ..Limits::default()
    };
    assert_limit(
        load_small(&gen::extrusion(3000), "e.wrl", lim.clone()),
        "--max-geometry",
        2,
    );
    assert_limit(
        load_small(&gen::elevation_grid(200), "g.wrl", lim.clone()),
        "--max-geometry",
        2,
    );
    // Within the limit they load.
    assert!(load_small(&gen::extrusion(20), "e.wrl", lim).is_ok());
}

#[test]
fn instancing_through_use_and_proto_counts_every_copy() {
    let lim = Limits {
        max_geometry: 1_000_000,
        ..Limits::default()
    };
    assert_limit(
        load_small(&gen::def_use_doubling(40), "u.wrl", lim.clone()),
        "--max-geometry",
        0,
    );
    assert_limit(
        load_small(&gen::proto_doubling(40), "p.wrl", Limits::default()),
        "--max-nodes",
        0,
    );
    let lim = Limits {
        max_nodes: 1000,
        ..Limits::default()
    };
    assert_limit(
        load_small(&gen::def_use_doubling(12), "u.wrl", lim),
        "--max-nodes",
        0,
    );
}

#[test]
fn numbers_strings_and_fields_count_against_one_budget() {
    let lim = Limits {
        max_numbers: 100_000,
        ..Limits::default()
    };
    assert_limit(
        load_small(&gen::gzip_numbers(3, 50_000), "n.wrl.gz", lim.clone()),
        "--max-numbers",
        0,
    );
    assert_limit(
        load_small(&gen::many_strings(30_000), "s.wrl", lim.clone()),
        "--max-numbers",
        2,
    );
    assert_limit(
        load_small(&gen::many_fields(10_000), "f.iv", lim),
        "--max-numbers",
        2,
    );
}

#[test]
fn gzip_output_counts_as_bytes_read() {
    let lim = Limits {
        max_bytes: 1 << 20,
        ..Limits::default()
    };
    let e = load_small(&gen::gzip_bomb(4), "bomb.wrl.gz", lim).unwrap_err();
    assert!(e.to_string().contains("--max-bytes"), "{e}");
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("animed-hostile-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn devices_and_fifos_are_refused_as_files_and_as_inlines() {
    let e = load(Path::new("/dev/zero")).unwrap_err().to_string();
    assert!(e.contains("not a regular file (a device)"), "{e}");
    let dir = temp_dir("fifo");
    let fifo = dir.join("pipe.wrl");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(
        made.map(|s| s.success()).unwrap_or(false),
        "mkfifo is needed for this test"
    );
    // Would block forever if opened as a file.
    let e = load(&fifo).unwrap_err().to_string();
    assert!(e.contains("(a FIFO)"), "{e}");
    for target in ["/dev/zero", "pipe.wrl"] {
        let f = dir.join("inl.wrl");
        std::fs::write(&f, gen::inline_of(target)).unwrap();
        let l = load(&f).expect("a bad inline is a warning");
        let w = l.warnings.join("\n");
        assert!(w.contains("not a regular file"), "{w}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_inline_used_many_times_pays_for_every_copy() {
    let dir = temp_dir("inl");
    std::fs::write(dir.join("a.wrl"), gen::def_use_doubling(8)).unwrap();
    let f = dir.join("many.wrl");
    std::fs::write(&f, gen::inline_many("a.wrl", 500)).unwrap();
    let lim = Limits {
        max_nodes: 20_000,
        ..Limits::default()
    };
    let e = animed::internals::format::load_with(&f, lim)
        .unwrap_err()
        .to_string();
    assert!(e.contains("--max-nodes"), "{e}");
    // Inlines nest: the included file's depth adds to the includer's.
    std::fs::write(dir.join("deep.wrl"), gen::nested_groups(20)).unwrap();
    let outer = dir.join("outer.wrl");
    let mut s = String::from_utf8(gen::nested_groups(0)).unwrap();
    s = s.replace("Shape { geometry Box {} }", "Inline { url \"deep.wrl\" }");
    std::fs::write(&outer, s).unwrap();
    let lim = Limits {
        max_depth: 15,
        ..Limits::default()
    };
    let e = animed::internals::format::load_with(&outer, lim)
        .unwrap_err()
        .to_string();
    assert!(e.contains("--max-depth"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_larger_than_the_budget_is_not_read() {
    let dir = temp_dir("big");
    let f = dir.join("big.wrl");
    // Sparse: costs no disk, and is refused from its size alone.
    let file = std::fs::File::create(&f).unwrap();
    file.set_len(3 << 30).unwrap();
    let t = std::time::Instant::now();
    let e = load(&f).unwrap_err().to_string();
    assert!(e.contains("--max-bytes"), "{e}");
    assert!(t.elapsed().as_secs() < 5, "refused without reading");
    std::fs::remove_dir_all(&dir).unwrap();
}
