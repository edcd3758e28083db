//! The 3D viewport: renders the scene (cached until something that affects
//! it changes), the ground grid behind it, the selection outline, light
//! gizmos, and picking.

use super::manip::ARROW_PX;
use super::sel_outline::Outlined;
use super::{gizmo, ops, Editor, LayerKey};
use crate::input::camera::Projector;
use crate::render::{self, Frame, RenderOptions};
use crate::scene::{NodeId, NodeKind};
use crate::ui::{line, theme, Painter, Rect};
use glam::Vec3;
use rayon::prelude::*;

/// Gizmo size in pixels.
const GIZMO_PX: f32 = 18.0;
/// How close (pixels) a click must be to a light's centre to pick it.
const LIGHT_PICK_PX: f32 = 10.0;

impl Editor {
    /// Bounding sphere of the shown scene (depth range, grid size, snap
    /// step, where new lights go), cached per scene revision and frame.
    pub(super) fn scene_radius(&mut self) -> (Vec3, f32) {
        if let Some((rev, f, s)) = self.sphere {
            if rev == self.scene_rev && f == self.frame {
                return s;
            }
        }
        let pose = self.pose().clone();
        let s = ops::sphere(ops::scene_bounds(&self.scene, &pose));
        self.sphere = Some((self.scene_rev, self.frame, s));
        s
    }

    pub(super) fn projector(&mut self) -> Projector {
        let vp = self.layout().viewport;
        let (_, r) = self.scene_radius();
        let v = self.camera.view(vp.w.max(1) as u32, vp.h.max(1) as u32, r);
        Projector::new(&v, vp.x as f32, vp.y as f32, vp.w as f32, vp.h as f32)
    }

    /// The projector the handles are sized with: a selection smaller on
    /// screen than the handles gets them shrunk (not below 60 %) and kept
    /// off its own disc, so they never bury it and a press on the object
    /// still drags the object (issue 17 item 7). Lights (no pixels) and
    /// big objects keep full-size handles.
    pub(super) fn handle_projector(&mut self) -> Projector {
        let proj = self.projector();
        match self.selection_px_radius() {
            Some(r) if handle_scale(r) < 1.0 => proj.for_handles(handle_scale(r), r + 2.0),
            _ => proj,
        }
    }

    /// Whether a pixel id of the scene layer (`NodeId.0 + 1`, 0 = none)
    /// belongs to `sel`'s subtree: the selection's pixels, for its
    /// outline and its handle size.
    fn subtree_ids(&self, sel: NodeId) -> impl Fn(u32) -> bool + Sync {
        let mut mine = vec![false; self.scene.nodes.len() + 1];
        for id in ops::subtree(&self.scene, sel) {
            mine[id.0 as usize + 1] = true;
        }
        move |id| id != 0 && mine.get(id as usize) == Some(&true)
    }

    /// Half the larger side of the box around the selected subtree's
    /// visible pixels in the viewport layer (`None` when nothing is
    /// selected or none of it shows).
    fn selection_px_radius(&mut self) -> Option<f32> {
        self.update_layer();
        let (x0, y0, x1, y1) = self.layer.outlined.as_ref()?.bounds?;
        Some(((x1 - x0).max(y1 - y0) + 1) as f32 * 0.5)
    }

    /// How the viewport draws the scene (the onion copies too, so they
    /// line up with it): the view style override, the headlight unless the
    /// scene turns it off.
    pub(super) fn layer_options(&self, w: u32, h: u32) -> RenderOptions {
        RenderOptions {
            width: w,
            height: h,
            threads: 0,
            style_override: self.view_style,
            headlight: self.scene.settings.headlight.unwrap_or(true),
            background: self.scene.settings.background,
            sky: true,
            aa: self.aa,
        }
    }

    /// Sets the viewport's anti-aliasing (samples per pixel: 1, 4 or 8).
    pub fn set_aa(&mut self, samples: u32) {
        self.aa = samples;
    }

    /// Re-renders the viewport layer when its inputs changed, and outlines
    /// the selection in it when the layer or the selection changed.
    pub(super) fn update_layer(&mut self) {
        self.update_scene_layer();
        let sel = self.selection;
        if self.layer.outlined.as_ref().map(|o| o.node) != sel {
            self.layer.outlined =
                sel.map(|sel| Outlined::new(sel, &self.layer.frame, self.subtree_ids(sel)));
        }
    }

    /// Re-renders the scene and the grid when their inputs changed.
    fn update_scene_layer(&mut self) {
        let vp = self.layout().viewport;
        let (w, h) = (vp.w.max(1) as u32, vp.h.max(1) as u32);
        let key = LayerKey {
            rev: self.scene_rev,
            frame: self.frame,
            camera: self.camera,
            w,
            h,
            grid: self.show_grid,
            style: self.view_style,
            aa: self.aa,
        };
        if self.layer.key == Some(key) {
            return;
        }
        let (_, radius) = self.scene_radius();
        let view = self.camera.view(w, h, radius);
        let opts = self.layer_options(w, h);
        let pose = self.pose().clone();
        // Into the last layer's buffers: a new 1280×720 frame with depth and
        // ids costs its zero-fill and page faults on every redraw.
        let mut frame = std::mem::replace(&mut self.layer.frame, Frame::new(0, 0, Vec3::ZERO));
        render::render_into(&self.scene, &pose, &view, &opts, &mut frame);
        if frame.width != w || frame.height != h {
            // A renderer that returned another size: keep the layout sane.
            frame = Frame::new(w, h, opts.background);
        }
        if self.show_grid {
            let proj = Projector::new(&view, 0.0, 0.0, w as f32, h as f32);
            draw_grid(&mut frame, &proj, radius);
        }
        self.layer.frame = frame;
        self.layer.key = Some(key);
        self.layer.outlined = None;
    }

    /// Forgets the cached viewport picture (benchmarks force re-renders).
    pub fn invalidate(&mut self) {
        self.layer.key = None;
    }

    /// The part of the viewport `vp` the layer covers, and what row `y`
    /// of it shows: the layer, with the selection outlined.
    pub(super) fn viewport_rows(&self, vp: Rect) -> (Rect, impl Fn(usize, &mut [u32]) + Sync + '_) {
        let lf = &self.layer.frame;
        let outlined = self
            .layer
            .outlined
            .as_ref()
            .filter(|o| Some(o.node) == self.selection);
        let rows = vp.h.min(lf.height as i32).max(0);
        let n = vp.w.min(lf.width as i32).max(0);
        let lw = lf.width as usize;
        let row = move |y: usize, out: &mut [u32]| {
            out.copy_from_slice(&lf.color[y * lw..y * lw + out.len()]);
            if let Some(o) = outlined {
                o.draw_over(y, out);
            }
        };
        (Rect::new(vp.x, vp.y, n, rows), row)
    }

    /// Copies the viewport layer, with the selection outlined, into `frame`.
    pub(super) fn blit_viewport(&self, frame: &mut Frame, vp: Rect) {
        let (r, row) = self.viewport_rows(vp);
        let fw = frame.width as usize;
        if fw == 0 || r.w == 0 {
            return;
        }
        let (x0, n) = (r.x as usize, r.w as usize);
        // Row by row on the threads.
        frame
            .color
            .par_chunks_mut(fw)
            .skip(r.y as usize)
            .take(r.h as usize)
            .enumerate()
            .for_each(|(y, window_row)| row(y, &mut window_row[x0..x0 + n]));
    }

    /// Light gizmos and the axis indicator, clipped to the viewport.
    pub(super) fn draw_viewport_overlay(&mut self, p: &mut Painter) {
        let vp = self.layout().viewport;
        let proj = self.projector();
        let pose = self.pose().clone();
        p.set_clip(Some(vp));
        for (id, light) in &pose.lights {
            let world = pose.world[id.0 as usize];
            let anchor = gizmo::anchor(light, &world);
            let size = proj.world_per_px(anchor) * GIZMO_PX;
            let selected = self.selection == Some(*id);
            let color = if selected {
                theme::SELECTED
            } else if light.on {
                theme::rgb(light.color * 0.6 + Vec3::splat(0.4))
            } else {
                theme::LIGHT_OFF
            };
            for (a, b) in gizmo::segments(light, &world, size) {
                if let Some((pa, pb)) = proj.segment(a, b) {
                    p.line(pa, pb, color, if selected { 2.0 } else { 1.2 });
                }
            }
            if let Some(c) = proj.point(anchor) {
                p.fill_circle(c, 2.5, color);
            }
        }
        self.draw_axes(p, vp);
        p.set_clip(None);
    }

    /// A small xyz tripod in the viewport's lower-left corner, turned by
    /// the viewport's own view matrix (the same up vector the scene is drawn
    /// with, so straight down in the top view +x still points right).
    fn draw_axes(&self, p: &mut Painter, vp: Rect) {
        let v = self
            .camera
            .view(vp.w.max(1) as u32, vp.h.max(1) as u32, 1.0)
            .view;
        let c = (vp.x as f32 + 22.0, vp.bottom() as f32 - 22.0);
        let dirs = corner_axes(&v);
        for ((d, color), name) in dirs
            .into_iter()
            .zip([0xe05050, 0x60c060, 0x5080e0])
            .zip(["x", "y", "z"])
        {
            let end = (c.0 + d.0 * 15.0, c.1 + d.1 * 15.0);
            p.line(c, end, color, 1.5);
            let (x, y) = tripod_label(end, d, vp);
            p.text(x, y, name, color);
        }
    }

    /// The node under window pixel (x, y): a light gizmo near the point,
    /// else the object drawn there (resolved to its named object).
    pub fn pick_at(&mut self, x: f32, y: f32) -> Option<NodeId> {
        let vp = self.layout().viewport;
        if !vp.contains(x, y) {
            return None;
        }
        let proj = self.projector();
        let pose = self.pose().clone();
        let mut best: Option<(f32, NodeId)> = None;
        for (id, light) in &pose.lights {
            let anchor = gizmo::anchor(light, &pose.world[id.0 as usize]);
            if let Some(c) = proj.point(anchor) {
                let d = ((c.0 - x).powi(2) + (c.1 - y).powi(2)).sqrt();
                if d <= LIGHT_PICK_PX && best.is_none_or(|(bd, _)| d < bd) {
                    best = Some((d, *id));
                }
            }
        }
        if let Some((_, id)) = best {
            return Some(id);
        }
        // The active skeleton's joints (`rig/view.rs`) before the meshes.
        if let Some(j) = self.pick_joint(x, y) {
            return Some(j);
        }
        self.update_layer();
        let lf = &self.layer.frame;
        let (lx, ly) = ((x as i32 - vp.x), (y as i32 - vp.y));
        if lx < 0 || ly < 0 || lx >= lf.width as i32 || ly >= lf.height as i32 {
            return None;
        }
        let id = lf.ids[(ly * lf.width as i32 + lx) as usize];
        if id == 0 || id as usize > self.scene.nodes.len() {
            return None;
        }
        let node = NodeId(id - 1);
        if matches!(self.scene.node(node).kind, NodeKind::Light(_)) {
            return Some(node);
        }
        Some(ops::pick_target(&self.scene, node))
    }
}

/// Ground grid (y = 0) drawn only over background pixels, so objects
/// cover it. Spacing is a power of ten suited to the scene's size. Its
/// long lines were a tenth of the editor frame on one thread, waiting
/// after the scene's render; drawn in bands of rows they share the
/// threads, with the same pixels (`line::wu_line_in`).
fn draw_grid(frame: &mut Frame, proj: &Projector, radius: f32) {
    let step = 10f32.powf((radius * 0.5).max(1e-3).log10().floor());
    let n = ((radius * 2.0 / step).ceil() as i32).clamp(2, 40);
    let ext = n as f32 * step;
    let mut lines = Vec::with_capacity(4 * n as usize + 2);
    for i in -n..=n {
        let t = i as f32 * step;
        let (cx, cz) = if i == 0 {
            (theme::GRID_AXIS_X, theme::GRID_AXIS_Z)
        } else {
            (theme::GRID, theme::GRID)
        };
        // Line along x (at z = t) and along z (at x = t).
        for (a, b, c) in [
            (Vec3::new(-ext, 0.0, t), Vec3::new(ext, 0.0, t), cx),
            (Vec3::new(t, 0.0, -ext), Vec3::new(t, 0.0, ext), cz),
        ] {
            if let Some((pa, pb)) = proj.segment(a, b) {
                lines.push((pa, pb, c));
            }
        }
    }
    let (w, h) = (frame.width, frame.height);
    let band_rows = h.div_ceil(GRID_BANDS).max(1);
    let ids = &frame.ids;
    let keep = |i: usize| ids[i] == 0;
    let band_len = (band_rows * w).max(1) as usize;
    frame
        .color
        .par_chunks_mut(band_len)
        .enumerate()
        .for_each(|(k, pixels)| {
            let r0 = k as u32 * band_rows;
            let band = line::Band {
                width: w,
                height: h,
                rows: r0..r0 + band_rows,
            };
            for &(pa, pb, c) in &lines {
                line::wu_line_in(pixels, &band, pa, pb, c, 0.8, keep);
            }
        });
}

/// Bands of rows the grid is drawn in: a few per thread, so a band
/// crossed by the horizon's many lines does not leave a thread waiting.
const GRID_BANDS: u32 = 8;

/// Handle size factor for a selection `r_px` pixels in radius: full size
/// (arrows [`ARROW_PX`] long) once the arrows reach no further than 2.5
/// radii, shrinking with the object below that, never under 60 % (still
/// easy to grab).
fn handle_scale(r_px: f32) -> f32 {
    (r_px * 2.5 / ARROW_PX).clamp(0.6, 1.0)
}

/// Screen directions (x right, y down; length ≤ 1) of the world axes
/// Where an arm's letter goes: beyond the arm's end, except that a
/// letter that would cross the viewport's bottom edge (an arm pointing
/// down, as z does in the top view) sits beside the arm's end instead, so
/// it is never cut off.
fn tripod_label(end: (f32, f32), d: (f32, f32), vp: Rect) -> (i32, i32) {
    let x = (end.0 + d.0 * 5.0 - 3.0) as i32;
    let y = (end.1 + d.1 * 5.0 - 8.0) as i32;
    // The font's letters end 12 rows below the text's top.
    let lowest = vp.bottom() - 13;
    match y > lowest {
        true => (x.max((end.0 + 4.0) as i32), lowest),
        false => (x, y),
    }
}

/// x, y, z under the view matrix `view`: the corner tripod's arms.
fn corner_axes(view: &glam::Mat4) -> [(f32, f32); 3] {
    [Vec3::X, Vec3::Y, Vec3::Z].map(|a| {
        let d = view.transform_vector3(a);
        (d.x, -d.y)
    })
}

#[cfg(test)]
mod tests {
    use super::{corner_axes, handle_scale, tripod_label, ARROW_PX};
    use crate::ui::Rect;

    #[test]
    fn tripod_letters_stay_inside_the_viewport() {
        let vp = Rect::new(0, 20, 300, 200);
        let c = (22.0, vp.bottom() as f32 - 22.0);
        // Straight down (z in the top view): beside the arm, above the edge.
        let end = (c.0, c.1 + 15.0);
        let (x, y) = tripod_label(end, (0.0, 1.0), vp);
        assert!(y + 12 < vp.bottom(), "{y}");
        assert!(x as f32 > end.0, "beside the arm: {x}");
        // Up or sideways: beyond the arm's end as before.
        assert_eq!(tripod_label((c.0, c.1 - 15.0), (0.0, -1.0), vp), (19, 170));
        assert_eq!(tripod_label((c.0 + 15.0, c.1), (1.0, 0.0), vp), (39, 190));
    }

    #[test]
    fn handles_shrink_on_small_objects_only() {
        assert_eq!(handle_scale(200.0), 1.0);
        assert_eq!(handle_scale(ARROW_PX / 2.5), 1.0);
        assert!((handle_scale(20.0) - 50.0 / ARROW_PX).abs() < 1e-6);
        assert_eq!(handle_scale(2.0), 0.6);
    }
    use crate::editor::views::ViewCmd;
    use crate::input::OrbitCamera;

    #[test]
    fn the_corner_tripod_agrees_with_the_standard_views() {
        // Top view (looking down −y): +x right, −z up on screen.
        // Front view (looking down −z): +x right, +y up.
        for (cmd, x_right, up_axis, up_sign) in [
            (ViewCmd::Top, 1.0, 2, -1.0),
            (ViewCmd::Front, 1.0, 1, 1.0),
            (ViewCmd::Bottom, 1.0, 2, 1.0),
        ] {
            let mut cam = OrbitCamera::default();
            let (yaw, pitch) = cmd.angles().unwrap();
            cam.yaw = yaw;
            cam.pitch = pitch;
            let a = corner_axes(&cam.view(100, 100, 1.0).view);
            assert!((a[0].0 - x_right).abs() < 1e-4, "{cmd:?}: x {:?}", a[0]);
            // Screen y grows downwards: "up" is a negative screen y.
            assert!(
                (a[up_axis].1 + up_sign).abs() < 1e-4,
                "{cmd:?}: axis {up_axis} {:?}",
                a[up_axis]
            );
        }
    }
}
