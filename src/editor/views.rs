//! Standard views (numpad 1/3/7 and, with Ctrl, their opposites; 5 for
//! orthographic/perspective; 0 to look through the scene's camera and
//! back) and the per-file memory of the view. The view is an editor
//! setting, never written into the scene: it is kept in a small text file
//! in the state folder, one line per scene file. These are the rules (the
//! lines, on text); reading and writing the file is the shell's
//! (`disk.rs`).

use crate::input::OrbitCamera;
use std::f32::consts::{FRAC_PI_2, PI};
use std::path::Path;

/// A view command (the View menu's items and the numpad keys).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewCmd {
    Front,
    Back,
    Right,
    Left,
    Top,
    Bottom,
    /// Orthographic ⇄ perspective (numpad 5).
    Ortho,
    /// Through the scene's camera, and back (numpad 0).
    Camera,
    FrameSelected,
    FrameAll,
}

impl ViewCmd {
    /// Every command in View-menu order.
    pub const ALL: [ViewCmd; 10] = [
        ViewCmd::Front,
        ViewCmd::Back,
        ViewCmd::Right,
        ViewCmd::Left,
        ViewCmd::Top,
        ViewCmd::Bottom,
        ViewCmd::Ortho,
        ViewCmd::Camera,
        ViewCmd::FrameSelected,
        ViewCmd::FrameAll,
    ];

    pub fn label(self) -> &'static str {
        match self {
            ViewCmd::Front => "Front",
            ViewCmd::Back => "Back",
            ViewCmd::Right => "Right",
            ViewCmd::Left => "Left",
            ViewCmd::Top => "Top",
            ViewCmd::Bottom => "Bottom",
            ViewCmd::Ortho => "Orthographic / perspective",
            ViewCmd::Camera => "Through the scene camera",
            ViewCmd::FrameSelected => "Frame selected",
            ViewCmd::FrameAll => "Frame all",
        }
    }

    pub fn shortcut(self) -> &'static str {
        match self {
            ViewCmd::Front => "Num 1",
            ViewCmd::Back => "Ctrl+Num 1",
            ViewCmd::Right => "Num 3",
            ViewCmd::Left => "Ctrl+Num 3",
            ViewCmd::Top => "Num 7",
            ViewCmd::Bottom => "Ctrl+Num 7",
            ViewCmd::Ortho => "Num 5",
            ViewCmd::Camera => "Num 0",
            ViewCmd::FrameSelected => "F",
            ViewCmd::FrameAll => "Home",
        }
    }

    /// The numpad key's command (`ctrl`: the opposite side).
    pub fn from_numpad(n: u8, ctrl: bool) -> Option<ViewCmd> {
        Some(match (n, ctrl) {
            (1, false) => ViewCmd::Front,
            (1, true) => ViewCmd::Back,
            (3, false) => ViewCmd::Right,
            (3, true) => ViewCmd::Left,
            (7, false) => ViewCmd::Top,
            (7, true) => ViewCmd::Bottom,
            (5, _) => ViewCmd::Ortho,
            (0, _) => ViewCmd::Camera,
            _ => return None,
        })
    }

    /// Yaw and pitch of an axis view (the orbit camera's angles: the eye
    /// is on +z at yaw 0, pitch 0), `None` for the other commands.
    pub fn angles(self) -> Option<(f32, f32)> {
        Some(match self {
            ViewCmd::Front => (0.0, 0.0),
            ViewCmd::Back => (PI, 0.0),
            ViewCmd::Right => (FRAC_PI_2, 0.0),
            ViewCmd::Left => (-FRAC_PI_2, 0.0),
            ViewCmd::Top => (0.0, FRAC_PI_2),
            ViewCmd::Bottom => (0.0, -FRAC_PI_2),
            _ => return None,
        })
    }
}

/// What is remembered per file: the orbit camera, and the timeline's
/// zoom and preview range (each `None` when unset).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Memo {
    pub camera: OrbitCamera,
    /// Frames at the key strip's ends once zoomed or panned.
    pub zoom: Option<(f32, f32)>,
    /// The preview range playback loops over.
    pub preview: Option<(f32, f32)>,
}

/// The per-file view memory: `path<TAB>tx ty tz distance yaw pitch fov
/// ortho [zoom a b] [preview a b]` lines, newest last, at most [`KEEP`].
/// Lines written before the timeline was remembered (camera only) still
/// read.
pub const KEEP: usize = 200;

fn line_of(scene: &Path, m: &Memo) -> String {
    let c = &m.camera;
    let mut line = format!(
        "{}\t{} {} {} {} {} {} {} {}",
        scene.display(),
        c.target.x,
        c.target.y,
        c.target.z,
        c.distance,
        c.yaw,
        c.pitch,
        c.fov_y,
        u8::from(c.ortho)
    );
    for (word, range) in [("zoom", m.zoom), ("preview", m.preview)] {
        if let Some((a, b)) = range {
            line += &format!(" {word} {a} {b}");
        }
    }
    line
}

/// A remembered frame range: finite, in order, not empty.
fn range(a: &str, b: &str) -> Option<(f32, f32)> {
    let (a, b) = (a.parse::<f32>().ok()?, b.parse::<f32>().ok()?);
    (a.is_finite() && b.is_finite() && b > a).then_some((a, b))
}

fn parse(rest: &str) -> Option<Memo> {
    let words: Vec<&str> = rest.split_whitespace().collect();
    let (cam, mut extra) = (words.get(..8)?, &words[8..]);
    let v: Vec<f32> = cam
        .iter()
        .map(|t| t.parse::<f32>().ok().filter(|x| x.is_finite()))
        .collect::<Option<_>>()?;
    let [tx, ty, tz, distance, yaw, pitch, fov_y, ortho] = v[..] else {
        return None;
    };
    let mut memo = Memo {
        camera: OrbitCamera {
            target: glam::Vec3::new(tx, ty, tz),
            distance: distance.clamp(1e-3, 1e6),
            yaw,
            pitch: pitch.clamp(-FRAC_PI_2, FRAC_PI_2),
            fov_y: fov_y.clamp(0.01, 3.0),
            ortho: ortho != 0.0,
        },
        zoom: None,
        preview: None,
    };
    // Unknown or broken trailing words are skipped, never an error: the
    // camera alone is still worth recalling.
    while let [word, a, b, rest @ ..] = extra {
        match *word {
            "zoom" => memo.zoom = range(a, b),
            "preview" => memo.preview = range(a, b),
            _ => {}
        }
        extra = rest;
    }
    Some(memo)
}

/// The remembered view of `scene` (an absolute path) in the memory's
/// `text` (the newest line wins).
pub fn recall_in(text: &str, scene: &Path) -> Option<Memo> {
    let key = scene.display().to_string();
    text.lines()
        .rev()
        .find_map(|l| l.split_once('\t').filter(|(p, _)| *p == key).map(|x| x.1))
        .and_then(parse)
}

/// The memory's text after remembering `memo` for `scene` in `old`: its
/// older line goes, the new one is last, at most [`KEEP`] lines stay.
pub fn remember_in(old: &str, scene: &Path, memo: &Memo) -> String {
    let key = scene.display().to_string();
    let mut lines: Vec<&str> = old
        .lines()
        .filter(|l| l.split_once('\t').is_some_and(|(p, _)| p != key))
        .collect();
    let skip = lines.len().saturating_sub(KEEP - 1);
    lines.drain(..skip);
    let mut text = lines.join("\n");
    if !text.is_empty() {
        text.push('\n');
    }
    text += &line_of(scene, memo);
    text.push('\n');
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numpad_keys_name_the_views() {
        assert_eq!(ViewCmd::from_numpad(1, false), Some(ViewCmd::Front));
        assert_eq!(ViewCmd::from_numpad(7, true), Some(ViewCmd::Bottom));
        assert_eq!(ViewCmd::from_numpad(2, false), None);
        assert_eq!(ViewCmd::Right.angles(), Some((FRAC_PI_2, 0.0)));
    }

    #[test]
    fn views_are_remembered_per_file() {
        let a = Path::new("/x/a.wrl");
        let b = Path::new("/x/b wrl.iv");
        assert_eq!(recall_in("", a), None);
        let ca = Memo {
            camera: OrbitCamera {
                yaw: 1.25,
                ortho: true,
                ..OrbitCamera::default()
            },
            zoom: Some((12.5, 40.0)),
            preview: Some((20.0, 30.0)),
        };
        let cb = Memo {
            camera: OrbitCamera {
                distance: 3.5,
                ..OrbitCamera::default()
            },
            zoom: None,
            preview: None,
        };
        let mut text = remember_in("", a, &ca);
        text = remember_in(&text, b, &cb);
        text = remember_in(&text, a, &ca);
        assert_eq!(recall_in(&text, a), Some(ca));
        assert_eq!(recall_in(&text, b), Some(cb));
        assert_eq!(text.lines().count(), 2, "one line per file: {text}");
        assert!(text.lines().last().unwrap().starts_with("/x/a.wrl\t"));
        // At most KEEP lines: the oldest go first.
        let mut many = String::new();
        for i in 0..KEEP + 5 {
            many = remember_in(&many, Path::new(&format!("/f{i}.wrl")), &cb);
        }
        assert_eq!(many.lines().count(), KEEP);
        assert_eq!(recall_in(&many, Path::new("/f4.wrl")), None);
        assert_eq!(recall_in(&many, Path::new("/f5.wrl")), Some(cb));
    }

    #[test]
    fn old_camera_only_lines_and_broken_ranges_still_recall_the_camera() {
        let old = parse("1 2 3 4 0.5 0.25 0.8 1").unwrap();
        assert_eq!(old.camera.target, glam::Vec3::new(1.0, 2.0, 3.0));
        assert!(old.camera.ortho);
        assert_eq!((old.zoom, old.preview), (None, None));
        // An empty, reversed or non-finite range is dropped, the rest kept.
        let m = parse("0 0 0 4 0 0 0.8 0 zoom 9 3 preview 2 8 junk").unwrap();
        assert_eq!((m.zoom, m.preview), (None, Some((2.0, 8.0))));
        let m = parse("0 0 0 4 0 0 0.8 0 zoom NaN 3").unwrap();
        assert_eq!(m.zoom, None);
        assert_eq!(parse("0 0 0 4 0 0 0.8"), None, "too short");
    }
}
