//! Aiming at a handle by name (scripts' `drag-handle`, tests): a window
//! pixel where the named handle of the current tool can be grabbed.
//!
//! Names: `x`, `y`, `z` (the arrow, ring or scale box of that axis, as the
//! tool has it), `yz`, `xz`, `xy` (move plane squares), `view` (the outer
//! rotate ring), `uniform` (the scale centre box), `body` (a pixel of the
//! selected object that is on no handle).

use super::geom::axis;
use super::{Handle, Tool, ARROW_PX};
use crate::editor::Editor;

/// The handle `name` means for `tool` (`None` for an unknown name or one
/// the tool does not have).
pub fn parse(tool: Tool, name: &str) -> Option<Handle> {
    let i = match name.to_ascii_lowercase().as_str() {
        "x" => 0,
        "y" => 1,
        "z" => 2,
        "yz" if tool == Tool::Translate => return Some(Handle::Plane(0)),
        "xz" | "zx" if tool == Tool::Translate => return Some(Handle::Plane(1)),
        "xy" | "yx" if tool == Tool::Translate => return Some(Handle::Plane(2)),
        "view" if tool == Tool::Rotate => return Some(Handle::ViewRing),
        "uniform" if tool == Tool::Scale => return Some(Handle::Uniform),
        "body" => return Some(Handle::Body),
        _ => return None,
    };
    Some(match tool {
        Tool::Translate => Handle::Axis(i),
        Tool::Rotate => Handle::Ring(i),
        Tool::Scale => Handle::ScaleAxis(i),
    })
}

impl Editor {
    /// A window pixel where handle `name` of the current tool can be
    /// grabbed (the hit test there gives that handle), or `None` when the
    /// selection has no such handle in view.
    pub fn handle_pixel(&mut self, name: &str) -> Option<(f32, f32)> {
        let h = parse(self.manip.tool, name)?;
        let hits = |ed: &mut Editor, p: (f32, f32)| ed.handle_at(p.0, p.1) == Some(h);
        let candidates: Vec<(f32, f32)> = match h {
            Handle::Axis(i) => {
                let p = self.handle_points()?;
                let (c, tip) = (p[0], p[i as usize + 1]);
                [0.6, 0.8, 0.4]
                    .iter()
                    .map(|t| (c.0 + (tip.0 - c.0) * t, c.1 + (tip.1 - c.1) * t))
                    .collect()
            }
            Handle::Plane(n) => {
                let t = self.target(Tool::Translate)?;
                let proj = self.projector();
                let len = proj.world_per_px(t.pivot) * ARROW_PX * 0.35;
                let (a, b) = super::translate::plane_axes(n);
                vec![proj.point(t.pivot + (axis(a) + axis(b)) * len)?]
            }
            Handle::Ring(_) | Handle::ViewRing => (0..63)
                .filter_map(|k| self.ring_pixel(h, k as f32 * 0.1))
                .collect(),
            Handle::ScaleAxis(i) => vec![self.scale_points()?[i as usize + 1]],
            Handle::Uniform => {
                let gap = self.handle_projector().gap_px();
                vec![super::scale::centre_box(&self.scale_points()?, gap)]
            }
            Handle::Body => return self.body_pixel(),
            Handle::Trackball => return None,
        };
        candidates.into_iter().find(|&p| hits(self, p))
    }

    /// A pixel of the selected object's body that is on no handle, looked
    /// for on growing circles round its pivot.
    fn body_pixel(&mut self) -> Option<(f32, f32)> {
        let sel = self.selection?;
        let t = self.target(Tool::Translate)?;
        let c = self.projector().point(t.pivot)?;
        for r in 2..60 {
            for k in 0..24 {
                let a = k as f32 / 24.0 * std::f32::consts::TAU;
                let p = (c.0 + a.cos() * r as f32, c.1 + a.sin() * r as f32);
                if self.pick_at(p.0, p.1) == Some(sel) && self.handle_at(p.0, p.1).is_none() {
                    return Some(p);
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_depend_on_the_tool() {
        assert_eq!(parse(Tool::Translate, "y"), Some(Handle::Axis(1)));
        assert_eq!(parse(Tool::Rotate, "Z"), Some(Handle::Ring(2)));
        assert_eq!(parse(Tool::Scale, "x"), Some(Handle::ScaleAxis(0)));
        assert_eq!(parse(Tool::Translate, "xz"), Some(Handle::Plane(1)));
        assert_eq!(parse(Tool::Rotate, "xz"), None);
        assert_eq!(parse(Tool::Rotate, "view"), Some(Handle::ViewRing));
        assert_eq!(parse(Tool::Scale, "uniform"), Some(Handle::Uniform));
        assert_eq!(parse(Tool::Scale, "body"), Some(Handle::Body));
        assert_eq!(parse(Tool::Translate, "w"), None);
    }
}
