//! Aiming at a handle by name (scripts' `drag-handle`, tests): a window
//! pixel where the named handle of the current tool can be grabbed (the
//! names are `manip/aim.rs`).

use crate::editor::manip::aim::parse;
use crate::editor::manip::geom::axis;
use crate::editor::manip::{Handle, Tool, ARROW_PX};
use crate::editor::Editor;

impl Editor {
    /// A window pixel where handle `name` of the current tool can be
    /// grabbed (the hit test there gives that handle), or `None` when the
    /// selection has no such handle in view.
    pub fn handle_pixel(&mut self, name: &str) -> Option<(f32, f32)> {
        let h = parse(self.viewport.handles.tool, name)?;
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
                let (a, b) = crate::editor::manip::translate::plane_axes(n);
                vec![proj.point(t.pivot + (axis(a) + axis(b)) * len)?]
            }
            Handle::Ring(_) | Handle::ViewRing => (0..63)
                .filter_map(|k| self.ring_pixel(h, k as f32 * 0.1))
                .collect(),
            Handle::ScaleAxis(i) => vec![self.scale_points()?[i as usize + 1]],
            Handle::Uniform => {
                let gap = self.handle_projector().gap_px();
                vec![crate::editor::manip::scale::centre_box(
                    &self.scale_points()?,
                    gap,
                )]
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
