//! `animed bench`: measure renderer, animation and editor speed on this machine.
//!
//! Each measurement is a [`Section`] in [`sections`]; to add one (e.g. the
//! editor's frame time) append an entry there — a name, a one-line summary
//! and a function that returns the lines to print.

use crate::render::job::{render_at, FrameSpec, Headlight};
use crate::render::{bench_scenes, render_color_into, Frame};
use crate::scene::Scene;
use std::time::{Duration, Instant};

/// Measure renderer, animation and editor speed on this machine.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Worker threads (0 = all cores).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Picture size, WIDTHxHEIGHT.
    #[arg(long, default_value = "1280x720", value_parser = super::render::parse_size)]
    pub size: (u32, u32),
    /// Run only the sections whose name contains this.
    #[arg(long)]
    pub only: Option<String>,
    /// Minimum time spent per measurement, in seconds.
    #[arg(long, default_value_t = 1.0)]
    pub seconds: f64,
}

/// One benchmark: `run` returns the lines it prints.
pub struct Section {
    pub name: &'static str,
    pub about: &'static str,
    pub run: fn(&Args) -> Result<Vec<String>, String>,
}

/// Every benchmark `animed bench` runs, in order.
pub fn sections() -> Vec<Section> {
    vec![
        Section {
            name: "pixels",
            about: "full-screen layers, 3-light per-pixel Blinn-Phong",
            run: bench_pixels,
        },
        Section {
            name: "textured",
            about: "full-screen layer, trilinear-textured 3-light Blinn-Phong, beside the untextured one (orthographic, then tilted in perspective)",
            run: bench_textured,
        },
        Section {
            name: "triangles",
            about: "100k small lit triangles covering the screen",
            run: bench_triangles,
        },
        Section {
            name: "demo",
            about: "the bundled demo scene",
            run: bench_demo,
        },
        Section {
            name: "aa",
            about: "anti-aliasing cost on the demo and the frame budgets",
            run: bench_aa,
        },
        Section {
            name: "textured100k",
            about: "the 100k-triangle textured frame budget alone (also printed by aa), for profiling",
            run: bench_textured100k,
        },
        Section {
            name: "stages",
            about: "one thread, stage by stage: setup, depth pass, shading pass, resolve",
            run: bench_stages,
        },
        Section {
            name: "split",
            about: "how the threads share a frame: per-thread band time and the wait at its end, old split beside new",
            run: bench_split,
        },
        Section {
            name: "animation",
            about: "track sampling and whole-scene evaluation (1000 tracks of each kind)",
            run: bench_animation,
        },
        Section {
            name: "skinning",
            about: "morph targets and skinning evaluated per pose (200k vertices)",
            run: bench_skinning,
        },
        Section {
            name: "editor",
            about: "editor frame on the demo scene: scene + grid + overlay + panels",
            run: bench_editor,
        },
    ]
}

/// Sampling speed of TCB vec3 and squad tracks and one `evaluate_into` of a
/// scene with 2000 tracks (see `anim::synthetic`).
fn bench_animation(args: &Args) -> Result<Vec<String>, String> {
    // Three figures share the time budget.
    let b = crate::anim::synthetic::bench_tracks(1000, args.seconds / 3.0);
    Ok(b.lines())
}

/// Skinned and morphed vertices per second through `evaluate_into` (scenes
/// from `anim::synthetic_deform`), by median wall time and by CPU time (the
/// latter shows the work done on a busy machine), on `--threads` threads.
fn bench_skinning(args: &Args) -> Result<Vec<String>, String> {
    use crate::anim::synthetic_deform::{morphed_scene, skinned_scene, JOINTS};
    const N: usize = 200_000;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads)
        .build()
        .map_err(|e| e.to_string())?;
    let measure = |scene: Scene| -> Timing {
        let mut pose = crate::anim::Pose::default();
        let mut t = 0.0f32;
        pool.install(|| {
            time_it(args.seconds / 2.0, || {
                crate::anim::evaluate_into(&scene, t, &mut pose);
                std::hint::black_box(&pose.deformed);
                t += 0.013;
            })
        })
    };
    let rate = |d: Duration| N as f64 / d.as_secs_f64().max(1e-12) / 1e6;
    let line = |what: String, t: Timing| match t.cpu {
        Some(c) => format!(
            "{what}: {:.1} M vertices/s ({:.1} M vertices per CPU-second; {})",
            rate(t.wall),
            rate(c),
            t.describe()
        ),
        None => format!(
            "{what}: {:.1} M vertices/s ({})",
            rate(t.wall),
            t.describe()
        ),
    };
    Ok(vec![
        line(
            format!("skinned ({N} vertices, 4 influences, {JOINTS} joints, positions + normals)"),
            measure(skinned_scene(N)),
        ),
        line(
            format!("morphed ({N} vertices, 4 targets, positions + normals)"),
            measure(morphed_scene(N)),
        ),
    ])
}

pub fn run(args: Args) -> i32 {
    let threads = if args.threads == 0 {
        rayon::current_num_threads()
    } else {
        args.threads
    };
    println!(
        "animed bench: {}x{}, {threads} thread(s), release build: {}",
        args.size.0,
        args.size.1,
        !cfg!(debug_assertions)
    );
    let mut code = 0;
    for s in sections() {
        if args.only.as_deref().is_some_and(|o| !s.name.contains(o)) {
            continue;
        }
        println!("{} — {}", s.name, s.about);
        match (s.run)(&args) {
            Ok(lines) => lines.iter().for_each(|l| println!("  {l}")),
            Err(e) => {
                println!("  failed: {e}");
                code = 1;
            }
        }
    }
    code
}

/// Wall time and CPU time (all threads) of one run.
#[derive(Clone, Copy, Debug)]
pub struct Timing {
    /// Median wall-clock time of one run.
    pub wall: Duration,
    /// Mean CPU time of one run summed over all threads (Linux only): on a
    /// busy machine this shows the work done, which wall time hides.
    pub cpu: Option<Duration>,
}

impl Timing {
    /// "12.3 ms wall, 20.1 ms cpu".
    pub fn describe(&self) -> String {
        match self.cpu {
            Some(c) => format!(
                "{:.2} ms wall, {:.2} ms cpu",
                self.wall.as_secs_f64() * 1e3,
                c.as_secs_f64() * 1e3
            ),
            None => format!("{:.2} ms wall", self.wall.as_secs_f64() * 1e3),
        }
    }
}

/// Process CPU time (user + system) from /proc/self/stat, Linux only.
fn process_cpu() -> Option<Duration> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which is in parentheses): utime and
    // stime are fields 14 and 15 of the whole line, in clock ticks (USER_HZ,
    // 100 on Linux).
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = f.get(11)?.parse::<u64>().ok()? + f.get(12)?.parse::<u64>().ok()?;
    Some(Duration::from_millis(ticks * 10))
}

/// Runs `f` once to warm up, then repeatedly for at least `seconds` (and at
/// least 3 times).
pub fn time_it(seconds: f64, mut f: impl FnMut()) -> Timing {
    f();
    let mut times = Vec::new();
    let start = Instant::now();
    let cpu0 = process_cpu();
    while times.len() < 3 || start.elapsed().as_secs_f64() < seconds {
        let t = Instant::now();
        f();
        times.push(t.elapsed());
        if times.len() >= 1000 {
            break;
        }
    }
    let cpu = match (cpu0, process_cpu()) {
        (Some(a), Some(b)) => Some((b.saturating_sub(a)) / times.len() as u32),
        _ => None,
    };
    times.sort();
    Timing {
        wall: times[times.len() / 2],
        cpu,
    }
}

fn render_scene_time(scene: &Scene, args: &Args) -> Timing {
    render_scene_time_aa(scene, args, Headlight::Off, 1)
}

fn render_scene_time_aa(scene: &Scene, args: &Args, headlight: Headlight, aa: u32) -> Timing {
    let (w, h) = args.size;
    let spec = FrameSpec {
        width: w,
        height: h,
        headlight,
        threads: args.threads,
        aa,
        ..FrameSpec::default()
    };
    let pose = crate::anim::evaluate(scene, 0.0);
    let aspect = w as f32 / h as f32;
    let view = crate::render::job::view_for(
        scene,
        &pose,
        crate::render::job::find_camera(scene, None).ok().flatten(),
        aspect,
    );
    let opts = crate::render::job::options_for(scene, &spec);
    // One frame reused, as a player or the editor does (and as llvmpipe
    // reuses its framebuffer); colour only, as `animed render` draws.
    let mut frame = Frame::new(w, h, opts.background);
    time_it(args.seconds, || {
        render_color_into(scene, &pose, &view, &opts, &mut frame);
        std::hint::black_box(&frame);
    })
}

fn bench_pixels(args: &Args) -> Result<Vec<String>, String> {
    let (w, h) = args.size;
    let mpix = w as f64 * h as f64 / 1e6;
    let aspect = w as f32 / h as f32;
    let mut out = Vec::new();
    for layers in [1usize, 8] {
        let timing = render_scene_time(&bench_scenes::layers(layers, aspect), args);
        let t = timing.wall.as_secs_f64();
        out.push(format!(
            "{layers} layer(s): {} per frame; {:.0} Mpix/s drawn, {:.0} Mpix/s shaded (once per visible pixel)",
            timing.describe(),
            layers as f64 * mpix / t,
            mpix / t
        ));
    }
    Ok(out)
}

/// The cost of texturing: one full-screen layer drawn untextured and with a
/// trilinear-sampled texture, measured in one run, and their ratio.
fn bench_textured(args: &Args) -> Result<Vec<String>, String> {
    let (w, h) = args.size;
    let mpix = w as f64 * h as f64 / 1e6;
    let aspect = w as f32 / h as f32;
    let plain = render_scene_time(&bench_scenes::layers(1, aspect), args);
    let textured = render_scene_time(&bench_scenes::layers_textured(1, aspect), args);
    let (tp, tt) = (plain.wall.as_secs_f64(), textured.wall.as_secs_f64());
    Ok(vec![
        format!(
            "untextured: {} per frame; {:.0} Mpix/s",
            plain.describe(),
            mpix / tp
        ),
        format!(
            "textured:   {} per frame; {:.0} Mpix/s",
            textured.describe(),
            mpix / tt
        ),
        format!(
            "texturing costs {:+.0} % over the untextured shading rate (goal: under 40 %)",
            (tt / tp - 1.0) * 100.0
        ),
        tilted_line(args),
    ])
}

/// The same comparison with the layer seen in perspective, tilted so the
/// mip level varies over the screen and 1/w over every triangle (the
/// orthographic layer above has one level pair and constant derivatives).
fn tilted_line(args: &Args) -> String {
    let plain = render_scene_time(&bench_scenes::layer_tilted(), args);
    let textured = render_scene_time(&bench_scenes::layer_tilted_textured(), args);
    let (tp, tt) = (plain.wall.as_secs_f64(), textured.wall.as_secs_f64());
    format!(
        "textured (perspective): untextured {}, textured {} per frame; costs {:+.0} %",
        plain.describe(),
        textured.describe(),
        (tt / tp - 1.0) * 100.0
    )
}

fn bench_triangles(args: &Args) -> Result<Vec<String>, String> {
    let aspect = args.size.0 as f32 / args.size.1 as f32;
    let scene = bench_scenes::small_triangles(100_000, aspect);
    let n = scene.meshes[0].triangles.len();
    let timing = render_scene_time(&scene, args);
    Ok(vec![format!(
        "{n} triangles: {} per frame; {:.2} Mtri/s (whole frame incl. shading every pixel)",
        timing.describe(),
        n as f64 / 1e6 / timing.wall.as_secs_f64()
    )])
}

fn bench_demo(args: &Args) -> Result<Vec<String>, String> {
    let demo = crate::format::demo().map_err(|e| e.to_string())?.scene;
    let (w, h) = args.size;
    let spec = FrameSpec {
        width: w,
        height: h,
        threads: args.threads,
        ..FrameSpec::default()
    };
    let mut err = None;
    let t = time_it(args.seconds, || {
        // Includes animation evaluation and camera choice, like a played frame.
        if let Err(e) = render_at(&demo, &spec, 1.0) {
            err = Some(e);
        }
    });
    if let Some(e) = err {
        return Err(e);
    }
    Ok(vec![format!(
        "{w}x{h}: {} per frame ({:.0} frames/s)",
        t.describe(),
        1.0 / t.wall.as_secs_f64()
    )])
}

/// What 4× multisampling costs on the demo (as a ratio to no AA, measured
/// in one run), and the frame budgets of issue 15: the editor frame on the
/// demo with 4× AA (8 ms) and a 100k-triangle textured scene without AA
/// (60 frames/s).
fn bench_aa(args: &Args) -> Result<Vec<String>, String> {
    let (w, h) = args.size;
    let demo = crate::format::demo().map_err(|e| e.to_string())?.scene;
    let mut out = Vec::new();
    let t1 = render_scene_time_aa(&demo, args, Headlight::Auto, 1);
    let t4 = render_scene_time_aa(&demo, args, Headlight::Auto, 4);
    let t8 = render_scene_time_aa(&demo, args, Headlight::Auto, 8);
    let ratio = |t: &Timing| t.wall.as_secs_f64() / t1.wall.as_secs_f64();
    out.push(format!("demo {w}x{h} without AA: {}", t1.describe()));
    out.push(format!(
        "demo {w}x{h} 8x AA: {} = {:.2}x",
        t8.describe(),
        ratio(&t8)
    ));
    out.push(format!(
        "demo {w}x{h} 4x AA: {} = cost of 4x AA {:.2}x",
        t4.describe(),
        ratio(&t4)
    ));
    let mut ed = crate::editor::bench::setup(w, h);
    ed.set_aa(4);
    let mut frame = crate::render::Frame::new(w, h, glam::Vec3::ZERO);
    let full = time_it(args.seconds, || {
        ed.invalidate();
        ed.draw(&mut frame);
    });
    out.push(format!(
        "budget: editor frame on the demo with 4x AA: {} (budget 8 ms)",
        full.describe()
    ));
    out.extend(bench_textured100k(args)?);
    Ok(out)
}

/// The frame budget of a 100k-triangle textured scene without AA (issue
/// 15: 60 frames/s at 1280×720).
fn bench_textured100k(args: &Args) -> Result<Vec<String>, String> {
    let (w, h) = args.size;
    let scene = bench_scenes::small_triangles_textured(100_000, w as f32 / h as f32);
    let t = render_scene_time(&scene, args);
    Ok(vec![format!(
        "budget: 100k-triangle textured scene (trilinear, 3 lights) without AA: {} = {:.0} frames/s (budget 60)",
        t.describe(),
        1.0 / t.wall.as_secs_f64()
    )])
}

/// Each stage of the pipeline alone on one thread (`render::stages`), in
/// CPU ms per frame, for the scenes the other sections draw: where a
/// frame's time goes, without a profiler. The shading pass needs its
/// tile's depth pass, so it is measured with it and the depth pass
/// subtracted.
fn bench_stages(args: &Args) -> Result<Vec<String>, String> {
    use crate::render::stages::Stages;
    let (w, h) = args.size;
    let aspect = w as f32 / h as f32;
    let demo = crate::format::demo().map_err(|e| e.to_string())?.scene;
    let scenes = [
        ("1 layer", bench_scenes::layers(1, aspect), 1),
        ("textured", bench_scenes::layers_textured(1, aspect), 1),
        (
            "100k triangles",
            bench_scenes::small_triangles(100_000, aspect),
            1,
        ),
        ("demo", demo.clone(), 1),
        ("demo 4x AA", demo, 4),
    ];
    let mut out = Vec::new();
    for (name, scene, aa) in scenes {
        let pose = crate::anim::evaluate(&scene, 0.0);
        let camera = crate::render::job::find_camera(&scene, None).ok().flatten();
        let view = crate::render::job::view_for(&scene, &pose, camera, aspect);
        let spec = FrameSpec {
            width: w,
            height: h,
            threads: 1,
            aa,
            ..FrameSpec::default()
        };
        let opts = crate::render::job::options_for(&scene, &spec);
        let mut s = Stages::new(&scene, &pose, &view, &opts);
        let share = args.seconds / 4.0;
        let ms = |t: Timing| t.cpu.unwrap_or(t.wall).as_secs_f64() * 1e3;
        let setup = ms(time_it(share, || s.setup(&scene, &pose)));
        let raster = ms(time_it(share, || s.raster()));
        let both = ms(time_it(share, || s.raster_and_shade()));
        let resolve = ms(time_it(share, || s.resolve()));
        out.push(format!(
            "{name}: setup {setup:.2} ms, depth pass {raster:.2} ms, shading pass {:.2} ms, resolve {resolve:.2} ms (CPU ms per frame)",
            both - raster
        ));
    }
    Ok(out)
}

/// How `--threads` threads share the bands of a one-layer frame (the
/// `pixels` scene) and the 100k-triangle frame: per frame, the band time
/// of the busiest and the least busy thread and how long the first thread
/// to finish waited for the last (medians over the frames of one run),
/// for rayon's default split ("runs") and one band per job ("bands"),
/// measured alternately so both see the same machine.
fn bench_split(args: &Args) -> Result<Vec<String>, String> {
    use crate::render::band_trace::{self, Split};
    let aspect = args.size.0 as f32 / args.size.1 as f32;
    let scenes = [
        ("1 layer", bench_scenes::layers(1, aspect)),
        (
            "100k triangles",
            bench_scenes::small_triangles(100_000, aspect),
        ),
    ];
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let mut out = Vec::new();
    for (name, scene) in &scenes {
        let mut splits: [Vec<Split>; 2] = [Vec::new(), Vec::new()];
        // Four alternating turns of each split.
        let turn = Args {
            seconds: args.seconds / 8.0,
            ..args.clone()
        };
        for _ in 0..4 {
            for (coarse, got) in [true, false].into_iter().zip(splits.iter_mut()) {
                band_trace::record(true, coarse);
                render_scene_time(scene, &turn);
                let frames = band_trace::take();
                // The first frame is the warm-up.
                got.extend(frames.iter().skip(1).filter_map(|f| band_trace::split(f)));
            }
        }
        band_trace::record(false, false);
        for (what, mut got) in ["runs", "bands"].into_iter().zip(splits) {
            if got.is_empty() {
                continue;
            }
            let n = got.len();
            let median = |got: &mut Vec<Split>, f: fn(&Split) -> Duration| {
                got.sort_by_key(f);
                ms(f(&got[n / 2]))
            };
            let wall = median(&mut got, |s| s.wall);
            let busiest = median(&mut got, |s| s.busiest);
            let idlest = median(&mut got, |s| s.idlest);
            let tail = median(&mut got, |s| s.tail);
            got.sort_by_key(|s| s.bands);
            let bands = got[n / 2].bands;
            out.push(format!(
                "{name}, {what}: {wall:.2} ms to draw; per thread {busiest:.2} / {idlest:.2} ms of bands ({} / {} bands); the first done waits {tail:.2} ms (medians of {n} frames)",
                bands.0, bands.1
            ));
        }
    }
    Ok(out)
}

/// The editor's frame time: a full redraw (scene render, grid, outline,
/// gizmos, panels) and an overlay-only redraw over the cached scene picture.
fn bench_editor(args: &Args) -> Result<Vec<String>, String> {
    let (w, h) = args.size;
    let mut ed = crate::editor::bench::setup(w, h);
    let mut frame = crate::render::Frame::new(w, h, glam::Vec3::ZERO);
    let full = time_it(args.seconds, || {
        ed.invalidate();
        ed.draw(&mut frame);
    });
    let overlay = time_it(args.seconds, || ed.draw(&mut frame));
    Ok(vec![
        format!("editor frame (scene + overlay): {}", full.describe()),
        format!("overlay only (scene cached): {}", overlay.describe()),
    ])
}
