//! `animed render --range/--frames/--shard` end to end: sharded output is
//! the unsharded output byte for byte, a sequence frame is the single-frame
//! render at the same time byte for byte, a GIF decodes to the PNG frames
//! within the palette bound, and bad arguments fail with a clear message.

use animed::internals::output::FrameRange;
use image::AnimationDecoder;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SIZE: &str = "96x72";

fn animed(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(args)
        .output()
        .expect("run animed")
}

fn ok(args: &[&str]) -> String {
    let out = animed(args);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(out.status.success(), "animed {args:?} failed:\n{err}");
    err
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("animed-out-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn s(p: &Path) -> &str {
    p.to_str().expect("temp paths are UTF-8")
}

/// File name → bytes of every file in `dir`.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("output folder exists")
        .map(|e| {
            let e = e.expect("dir entry");
            (
                e.file_name().to_string_lossy().to_string(),
                std::fs::read(e.path()).expect("read frame"),
            )
        })
        .collect();
    v.sort();
    v
}

#[test]
fn sharded_output_equals_unsharded_byte_for_byte() {
    let d = tmp("shard");
    let all = d.join("all/f_##.png");
    let log = ok(&[
        "render",
        "--range",
        "0:0.3:8",
        "--size",
        SIZE,
        "-o",
        s(&all),
    ]);
    // Not a terminal: one plain line per frame, then a summary.
    assert!(log.contains("render: 8/8 frame"), "{log}");
    assert!(log.contains("wrote 8 frames"), "{log}");
    let unsharded = files(&d.join("all"));
    let names: Vec<&str> = unsharded.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "f_00.png", "f_01.png", "f_02.png", "f_03.png", "f_04.png", "f_05.png", "f_06.png",
            "f_07.png"
        ]
    );
    let sharded = d.join("sharded/f_##.png");
    for k in 0..3 {
        let shard = format!("{k}/3");
        ok(&[
            "render",
            "--range",
            "0:0.3:8",
            "--size",
            SIZE,
            "--shard",
            &shard,
            "-o",
            s(&sharded),
        ]);
        // Shard k wrote exactly the indices ≡ k mod 3 so far.
        let have = files(&d.join("sharded")).len();
        assert_eq!(have, (0..8).filter(|i| i % 3 <= k).count());
    }
    let sharded = files(&d.join("sharded"));
    assert_eq!(sharded.len(), unsharded.len());
    for (a, b) in unsharded.iter().zip(&sharded) {
        assert_eq!(a.0, b.0);
        assert!(
            a.1 == b.1,
            "{} differs between sharded and unsharded output",
            a.0
        );
    }
    // The frames are not all the same picture (the demo animates).
    assert!(unsharded[0].1 != unsharded[4].1);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_sequence_frame_is_the_single_frame_render_at_its_time() {
    let d = tmp("single");
    let range = "0.1:0.35:9";
    ok(&[
        "render",
        "--range",
        range,
        "--size",
        SIZE,
        "-o",
        s(&d.join("seq/f_#.png")),
        "--threads",
        "2",
    ]);
    let r = FrameRange::parse(range).unwrap();
    for i in [0u32, 4, 8] {
        // f32's Display prints the shortest text that reads back as the
        // same f32, so --time gets exactly the sequence's time.
        let t = r.time(i).to_string();
        let single = d.join(format!("single_{i}.png"));
        ok(&[
            "render",
            "--time",
            &t,
            "--size",
            SIZE,
            "-o",
            s(&single),
            "--threads",
            "1",
        ]);
        let a = std::fs::read(d.join(format!("seq/f_{i}.png"))).unwrap();
        let b = std::fs::read(&single).unwrap();
        assert!(a == b, "frame {i} (t={t}) differs from render --time {t}");
    }
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn frames_a_to_b_are_scene_frames_at_the_scene_fps() {
    // The demo runs at 24 fps: --frames 12:14 is t = 0.5, 0.541…, 0.583… s.
    let d = tmp("frames");
    let log = ok(&[
        "render",
        "--frames",
        "12:14",
        "--size",
        SIZE,
        "-o",
        s(&d.join("f_#.png")),
    ]);
    assert_eq!(files(&d).len(), 3);
    assert!(log.contains("frame 0 t=0.5 s"), "{log}");
    let t2 = ((12.0f64 + 2.0) / 24.0) as f32;
    assert!(log.contains(&format!("frame 2 t={t2} s")), "{log}");
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn a_gif_decodes_to_the_png_frames_within_the_palette_bound() {
    let d = tmp("gif");
    let (range, size) = ("0:0.5:6", "160x120");
    ok(&[
        "render",
        "--range",
        range,
        "--size",
        size,
        "-o",
        s(&d.join("a.gif")),
    ]);
    ok(&[
        "render",
        "--range",
        range,
        "--size",
        size,
        "-o",
        s(&d.join("png/f_#.png")),
    ]);
    let file = std::io::BufReader::new(std::fs::File::open(d.join("a.gif")).unwrap());
    let frames = image::codecs::gif::GifDecoder::new(file)
        .unwrap()
        .into_frames()
        .collect_frames()
        .unwrap();
    assert_eq!(frames.len(), 6);
    for (i, f) in frames.iter().enumerate() {
        // Delay = STEP (0.5 s).
        let (n, den) = f.delay().numer_denom_ms();
        assert_eq!(n / den, 500);
        let png = image::open(d.join(format!("png/f_{i}.png")))
            .unwrap()
            .to_rgba8();
        let (mean, block) = errors(&png, f.buffer());
        eprintln!("frame {i}: mean {mean:.3}, worst 8x8 block {block:.3}");
        assert!(
            mean <= MAX_MEAN_ERR && block <= MAX_BLOCK_ERR,
            "frame {i}: {mean} {block}"
        );
    }
    std::fs::remove_dir_all(&d).unwrap();
}

/// The bound for rendered frames (README "Rendering animations"): mean
/// absolute channel error and worst 8×8-block mean error, in levels of 255
/// (measured on these frames: at most 0.51 and 1.84).
const MAX_MEAN_ERR: f64 = 1.0;
const MAX_BLOCK_ERR: f64 = 3.0;

fn errors(a: &image::RgbaImage, b: &image::RgbaImage) -> (f64, f64) {
    assert_eq!(a.dimensions(), b.dimensions());
    let (w, h) = a.dimensions();
    let mut total = 0.0;
    for (p, q) in a.pixels().zip(b.pixels()) {
        for k in 0..3 {
            total += (p[k] as f64 - q[k] as f64).abs();
        }
    }
    let mut worst: f64 = 0.0;
    for by in (0..h).step_by(8) {
        for bx in (0..w).step_by(8) {
            for k in 0..3 {
                let (mut sa, mut sb, mut n) = (0.0, 0.0, 0.0);
                for y in by..(by + 8).min(h) {
                    for x in bx..(bx + 8).min(w) {
                        sa += a.get_pixel(x, y)[k] as f64;
                        sb += b.get_pixel(x, y)[k] as f64;
                        n += 1.0;
                    }
                }
                worst = worst.max(((sa - sb) / n).abs());
            }
        }
    }
    (total / (w * h * 3) as f64, worst)
}

#[test]
fn bad_arguments_fail_with_a_clear_message() {
    let d = tmp("bad");
    let seq = d.join("f_#.png");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["--range", "0:0:5", "-o", s(&seq)],
            "STEP must be more than 0",
        ),
        (vec!["--range", "0:1", "-o", s(&seq)], "START:STEP:COUNT"),
        (vec!["--range", "0:1:5", "-o", "plain.png"], "has no '#'"),
        (
            vec!["--range", "0:1:500", "-o", "f_##.png"],
            "needs 3 digits",
        ),
        (
            vec!["--range", "0:1:3", "--shard", "3/3", "-o", s(&seq)],
            "K must be 0..=2",
        ),
        (
            vec!["--shard", "0/2", "-o", s(&seq)],
            "--shard needs a range",
        ),
        (
            vec!["--range", "0:1:3", "--shard", "0/2", "-o", "a.gif"],
            "cannot split a GIF",
        ),
        (
            vec!["--range", "0:1:3", "-o", "f_#.jpg"],
            "must end in .png",
        ),
        (vec!["--range", "0:1:3", "-o", "f_#_#.png"], "2 runs of '#'"),
        (vec!["--frames", "5:2", "-o", s(&seq)], "before the first"),
        (
            vec!["--range", "0:1:3", "--time", "2", "-o", s(&seq)],
            "cannot be used with",
        ),
    ];
    for (args, want) in cases {
        let mut all = vec!["render", "--size", SIZE];
        all.extend(&args);
        let out = animed(&all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} should fail");
        assert!(err.contains(want), "{args:?}: expected {want:?} in:\n{err}");
        assert!(!err.contains("panicked"), "{args:?} panicked:\n{err}");
    }
    assert!(!d.exists(), "a failed command wrote files");
}
