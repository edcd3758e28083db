//! The worst cases through the binary with the default limits, under a
//! 3 GiB address-space cap and a timeout; peak RSS must stay ≤ 1.5 GB.

use super::gen;
use std::path::{Path, PathBuf};
use std::process::Command;

/// 3 GiB, in KiB for `ulimit -v`.
const ADDRESS_CAP_KB: u64 = 3 << 20;
/// 1.5 GB, in KiB as `/usr/bin/time` reports it.
const PEAK_LIMIT_KB: u64 = 1_500_000;

struct Run {
    code: i32,
    stderr: String,
    peak_kb: u64,
    secs: f64,
}

fn run_capped(file: &Path) -> Run {
    let time = Path::new("/usr/bin/time");
    assert!(
        time.exists(),
        "HOSTILE SUITE NEEDS /usr/bin/time (GNU time) to measure peak memory: install it"
    );
    let t = std::time::Instant::now();
    let out = Command::new("timeout")
        .arg("120")
        .arg(time)
        .args(["-f", "PEAK_KB=%M"])
        .args([
            "sh",
            "-c",
            &format!("ulimit -v {ADDRESS_CAP_KB} && exec \"$0\" info \"$1\""),
        ])
        .arg(env!("CARGO_BIN_EXE_animed"))
        .arg(file)
        .output()
        .expect("run timeout + /usr/bin/time + animed");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let peak_kb = stderr
        .lines()
        .find_map(|l| l.strip_prefix("PEAK_KB="))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or_else(|| panic!("no peak memory figure in: {stderr}"));
    Run {
        code: out.status.code().unwrap_or(-1),
        stderr,
        peak_kb,
        secs: t.elapsed().as_secs_f64(),
    }
}

fn temp_dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("animed-hostile-mem-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn worst_cases_stay_within_memory_and_time() {
    let dir = temp_dir();
    // (name, bytes, what the error must name; "" = loads)
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("extrusion3000.wrl", gen::extrusion(3000), "--max-geometry"),
        ("elevation.wrl", gen::elevation_grid(3000), "--max-geometry"),
        (
            "use_doubling.wrl",
            gen::def_use_doubling(40),
            "--max-geometry",
        ),
        ("proto_doubling.wrl", gen::proto_doubling(40), "--max-nodes"),
        ("proto_chain.wrl", gen::proto_chain(1000), "--max-depth"),
        (
            "numbers.wrl.gz",
            gen::gzip_numbers(4, 10_000_000),
            "--max-numbers",
        ),
        ("bomb.wrl.gz", gen::gzip_bomb(300), "--max-bytes"),
        ("strings.wrl", gen::many_strings(9_000_000), "--max-numbers"),
        ("fields.iv", gen::many_fields(3_000_000), "--max-numbers"),
        ("deep.wrl", gen::nested_groups(250), ""),
    ];
    let mut report = String::new();
    let mut worst = 0;
    for (name, bytes, want) in cases {
        let f = dir.join(name);
        std::fs::write(&f, &bytes).unwrap();
        let r = run_capped(&f);
        report += &format!(
            "{name:20} {:>9} bytes  exit {}  peak {:>8} KiB  {:.1} s\n",
            bytes.len(),
            r.code,
            r.peak_kb,
            r.secs
        );
        if want.is_empty() {
            assert_eq!(r.code, 0, "{name}: {}", r.stderr);
        } else {
            assert_eq!(r.code, 1, "{name}: {}", r.stderr);
            assert!(r.stderr.contains(want), "{name}: {}", r.stderr);
            assert!(!r.stderr.contains("panicked"), "{name}: {}", r.stderr);
        }
        assert!(
            r.peak_kb <= PEAK_LIMIT_KB,
            "{name}: peak RSS {} KiB > {PEAK_LIMIT_KB}",
            r.peak_kb
        );
        worst = worst.max(r.peak_kb);
        std::fs::remove_file(&f).unwrap();
    }
    eprintln!(
        "hostile inputs under ulimit -v {ADDRESS_CAP_KB} KiB:\n{report}worst peak {worst} KiB"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
