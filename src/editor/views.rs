//! Standard views (numpad 1/3/7 and, with Ctrl, their opposites; 5 for
//! orthographic/perspective; 0 to look through the scene's camera and
//! back) and the per-file memory of the view. The view is an editor
//! setting, never written into the scene: it is kept in a small text file
//! in the state folder, one line per scene file.

use crate::input::OrbitCamera;
use std::f32::consts::{FRAC_PI_2, PI};
use std::path::{Path, PathBuf};

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

/// The per-file view memory: `path<TAB>tx ty tz distance yaw pitch fov ortho`
/// lines, newest last, at most [`KEEP`].
pub const KEEP: usize = 200;

fn line_of(scene: &Path, c: &OrbitCamera) -> String {
    format!(
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
    )
}

fn parse(rest: &str) -> Option<OrbitCamera> {
    let v: Vec<f32> = rest
        .split_whitespace()
        .map(|t| t.parse::<f32>().ok().filter(|x| x.is_finite()))
        .collect::<Option<_>>()?;
    let [tx, ty, tz, distance, yaw, pitch, fov_y, ortho] = v[..] else {
        return None;
    };
    Some(OrbitCamera {
        target: glam::Vec3::new(tx, ty, tz),
        distance: distance.clamp(1e-3, 1e6),
        yaw,
        pitch: pitch.clamp(-FRAC_PI_2, FRAC_PI_2),
        fov_y: fov_y.clamp(0.01, 3.0),
        ortho: ortho != 0.0,
    })
}

/// The remembered view of `scene` (an absolute path) in `memory`.
pub fn recall(memory: &Path, scene: &Path) -> Option<OrbitCamera> {
    let text = std::fs::read_to_string(memory).ok()?;
    let key = scene.display().to_string();
    text.lines()
        .rev()
        .find_map(|l| l.split_once('\t').filter(|(p, _)| *p == key).map(|x| x.1))
        .and_then(parse)
}

/// Remembers `camera` for `scene`, replacing its older line.
pub fn remember(memory: &Path, scene: &Path, camera: &OrbitCamera) -> Result<(), String> {
    let key = scene.display().to_string();
    let old = std::fs::read_to_string(memory).unwrap_or_default();
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
    text += &line_of(scene, camera);
    text.push('\n');
    if let Some(d) = memory.parent() {
        std::fs::create_dir_all(d).map_err(|e| format!("{}: {e}", d.display()))?;
    }
    let tmp: PathBuf = memory.with_extension("tmp");
    std::fs::write(&tmp, text).map_err(|e| format!("{}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, memory).map_err(|e| format!("{}: {e}", memory.display()))
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
        let d = std::env::temp_dir().join(format!("animed-views-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        let mem = d.join("views");
        let a = Path::new("/x/a.wrl");
        let b = Path::new("/x/b wrl.iv");
        assert_eq!(recall(&mem, a), None);
        let ca = OrbitCamera {
            yaw: 1.25,
            ortho: true,
            ..OrbitCamera::default()
        };
        let cb = OrbitCamera {
            distance: 3.5,
            ..OrbitCamera::default()
        };
        remember(&mem, a, &ca).unwrap();
        remember(&mem, b, &cb).unwrap();
        remember(&mem, a, &ca).unwrap();
        assert_eq!(recall(&mem, a), Some(ca));
        assert_eq!(recall(&mem, b), Some(cb));
        let text = std::fs::read_to_string(&mem).unwrap();
        assert_eq!(text.lines().count(), 2, "one line per file: {text}");
        std::fs::remove_dir_all(&d).unwrap();
    }
}
