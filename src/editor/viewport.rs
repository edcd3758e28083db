//! The 3D viewport: renders the scene (cached until something that affects
//! it changes), the ground grid behind it, the selection outline, light
//! gizmos, and picking.

use super::{gizmo, ops, Editor, LayerKey};
use crate::input::camera::Projector;
use crate::render::{self, Frame, RenderOptions};
use crate::scene::{NodeId, NodeKind};
use crate::ui::{line, theme, Painter, Rect};
use glam::Vec3;

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

    /// Re-renders the viewport layer when its inputs changed.
    pub(super) fn update_layer(&mut self) {
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
        let mut frame = render::render(&self.scene, &pose, &view, &opts);
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
    }

    /// Forgets the cached viewport picture (benchmarks force re-renders).
    pub fn invalidate(&mut self) {
        self.layer.key = None;
    }

    /// Copies the viewport layer into `frame` and outlines the selection.
    pub(super) fn blit_viewport(&self, frame: &mut Frame, vp: Rect) {
        let lf = &self.layer.frame;
        let fw = frame.width as usize;
        let rows = vp.h.min(lf.height as i32).max(0) as usize;
        let n = vp.w.min(lf.width as i32).max(0) as usize;
        for y in 0..rows {
            let dst = (vp.y as usize + y) * fw + vp.x as usize;
            let src = y * lf.width as usize;
            frame.color[dst..dst + n].copy_from_slice(&lf.color[src..src + n]);
        }
        if let Some(sel) = self.selection {
            self.outline(frame, vp, sel);
        }
    }

    /// Paints the border pixels of the selected subtree's silhouette and
    /// tints its inside.
    fn outline(&self, frame: &mut Frame, vp: Rect, sel: NodeId) {
        let mut mine = vec![false; self.scene.nodes.len() + 1];
        for id in ops::subtree(&self.scene, sel) {
            mine[id.0 as usize + 1] = true;
        }
        let lf = &self.layer.frame;
        let (w, h) = (lf.width as usize, lf.height as usize);
        let ids = &lf.ids;
        let is = |i: usize| mine.get(ids[i] as usize).copied().unwrap_or(false);
        let fw = frame.width as usize;
        for y in 0..h.min(vp.h.max(0) as usize) {
            let row = y * w;
            for x in 0..w.min(vp.w.max(0) as usize) {
                let i = row + x;
                if ids[i] == 0 || !is(i) {
                    continue;
                }
                let edge = x == 0
                    || y == 0
                    || x + 1 == w
                    || y + 1 == h
                    || !is(i - 1)
                    || !is(i + 1)
                    || !is(i - w)
                    || !is(i + w);
                let o = (vp.y as usize + y) * fw + vp.x as usize + x;
                if edge {
                    frame.color[o] = theme::SELECTED;
                } else {
                    // A light orange tint inside.
                    let c = frame.color[o];
                    let mix = |s: u32, t: u32| (s * 3 + t) / 4;
                    let r = mix((c >> 16) & 255, 0xff);
                    let g = mix((c >> 8) & 255, 0x9a);
                    let b = mix(c & 255, 0x1f);
                    frame.color[o] = (r << 16) | (g << 8) | b;
                }
            }
        }
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

    /// A small xyz tripod in the viewport's lower-left corner.
    fn draw_axes(&self, p: &mut Painter, vp: Rect) {
        let v = crate::input::camera::look_at(self.camera.back(), Vec3::ZERO, Vec3::Y);
        let c = (vp.x as f32 + 22.0, vp.bottom() as f32 - 22.0);
        for (axis, color, name) in [
            (Vec3::X, 0xe05050, "x"),
            (Vec3::Y, 0x60c060, "y"),
            (Vec3::Z, 0x5080e0, "z"),
        ] {
            let d = v.transform_vector3(axis);
            let end = (c.0 + d.x * 15.0, c.1 - d.y * 15.0);
            p.line(c, end, color, 1.5);
            p.text(
                (end.0 + d.x * 5.0 - 3.0) as i32,
                (end.1 - d.y * 5.0 - 8.0) as i32,
                name,
                color,
            );
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
/// cover it. Spacing is a power of ten suited to the scene's size.
fn draw_grid(frame: &mut Frame, proj: &Projector, radius: f32) {
    let step = 10f32.powf((radius * 0.5).max(1e-3).log10().floor());
    let n = ((radius * 2.0 / step).ceil() as i32).clamp(2, 40);
    let ext = n as f32 * step;
    let (w, h) = (frame.width, frame.height);
    let ids = &frame.ids;
    let keep = |i: usize| ids[i] == 0;
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
                line::wu_line(&mut frame.color, (w, h), pa, pb, c, 0.8, &keep);
            }
        }
    }
}
