//! The orbit camera the editor viewport and the viewer turn with the mouse,
//! plus projection of world points to viewport pixels for the overlay.

use crate::render::View;
use glam::{Mat4, Vec3, Vec4};

/// Orbit camera: looks at `target` from `distance` away, turned by `yaw`
/// about +y and tilted by `pitch` (radians, positive looks down).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    pub target: Vec3,
    pub distance: f32,
    pub yaw: f32,
    pub pitch: f32,
    /// Vertical field of view in radians.
    pub fov_y: f32,
    /// Orthographic projection: the view volume is as tall as the
    /// perspective one at the target (numpad 5 toggles).
    pub ortho: bool,
}

impl Default for OrbitCamera {
    fn default() -> Self {
        OrbitCamera {
            target: Vec3::ZERO,
            distance: 10.0,
            yaw: 0.6,
            pitch: 0.45,
            fov_y: std::f32::consts::FRAC_PI_4,
            ortho: false,
        }
    }
}

/// Right-handed look-at (camera looks down −z).
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let f = (target - eye).normalize_or(Vec3::NEG_Z);
    let s = f.cross(up).normalize_or(Vec3::X);
    let u = s.cross(f);
    Mat4::from_cols(
        Vec4::new(s.x, u.x, -f.x, 0.0),
        Vec4::new(s.y, u.y, -f.y, 0.0),
        Vec4::new(s.z, u.z, -f.z, 0.0),
        Vec4::new(-s.dot(eye), -u.dot(eye), f.dot(eye), 1.0),
    )
}

/// OpenGL-style orthographic projection of the box ±hw × ±hh × [near, far].
pub fn orthographic(hw: f32, hh: f32, near: f32, far: f32) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(1.0 / hw.max(1e-9), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 1.0 / hh.max(1e-9), 0.0, 0.0),
        Vec4::new(0.0, 0.0, -2.0 / (far - near), 0.0),
        Vec4::new(0.0, 0.0, -(far + near) / (far - near), 1.0),
    )
}

/// OpenGL-style perspective: eye z in [-near, -far] maps to NDC z in [-1, 1].
pub fn perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let f = 1.0 / (fov_y * 0.5).tan();
    let nf = 1.0 / (near - far);
    Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, (far + near) * nf, -1.0),
        Vec4::new(0.0, 0.0, 2.0 * far * near * nf, 0.0),
    )
}

impl OrbitCamera {
    /// Unit vector from the target towards the eye.
    pub fn back(&self) -> Vec3 {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        Vec3::new(cp * sy, sp, cp * cy)
    }

    pub fn eye(&self) -> Vec3 {
        self.target + self.back() * self.distance
    }

    /// Near and far planes that keep a scene of `radius` around the target
    /// inside the depth range with good precision.
    fn planes(&self, radius: f32) -> (f32, f32) {
        let near = (self.distance * 0.01).max(1e-3);
        let far = self.distance + radius.max(self.distance) * 4.0 + 10.0;
        (near, far)
    }

    /// The renderer's view for a viewport of `w`×`h` pixels; `radius` is
    /// the scene's size (for the depth range).
    pub fn view(&self, w: u32, h: u32, radius: f32) -> View {
        let aspect = w.max(1) as f32 / h.max(1) as f32;
        let (near, far) = self.planes(radius);
        let eye = self.eye();
        // Straight down or up (top/bottom views) +y is the view direction:
        // the camera's own up vector (d back / d pitch) then; elsewhere +y,
        // exactly as before.
        let up = if self.pitch.abs() > 1.55 {
            let (sy, cy) = self.yaw.sin_cos();
            let (sp, cp) = self.pitch.sin_cos();
            Vec3::new(-sp * sy, cp, -sp * cy)
        } else {
            Vec3::Y
        };
        let proj = if self.ortho {
            let hh = self.distance * (self.fov_y * 0.5).tan();
            orthographic(hh * aspect, hh, near, far)
        } else {
            perspective(self.fov_y, aspect, near, far)
        };
        View {
            view: look_at(eye, self.target, up),
            proj,
            eye,
        }
    }

    /// An orbit camera that sees what `view` sees (less any roll): same
    /// eye, direction and vertical field of view, orbiting the point where
    /// the view direction passes the scene's centre (`sphere`).
    pub fn from_view(view: &View, sphere: Option<(Vec3, f32)>) -> OrbitCamera {
        let fwd = view.forward().normalize_or(Vec3::NEG_Z);
        let back = -fwd;
        let (centre, radius) = sphere.unwrap_or((view.eye + fwd * 10.0, 1.0));
        let along = (centre - view.eye).dot(fwd);
        let distance = if along > radius * 0.05 && along.is_finite() {
            along
        } else {
            radius.max(1e-3) * 2.0
        };
        // proj.y_axis.y = 1 / tan(fov_y / 2) for a perspective projection;
        // an orthographic one (w row = 0,0,0,1) gets the default 45°.
        let p = view.proj;
        let fov_y = if p.w_axis.w == 0.0 && p.y_axis.y > 0.0 {
            2.0 * (1.0 / p.y_axis.y).atan()
        } else {
            std::f32::consts::FRAC_PI_4
        };
        OrbitCamera {
            target: view.eye + fwd * distance,
            distance,
            yaw: back.x.atan2(back.z),
            pitch: back.y.clamp(-1.0, 1.0).asin().clamp(-1.55, 1.55),
            fov_y,
            ortho: false,
        }
    }

    pub fn orbit(&mut self, dx: f32, dy: f32) {
        self.yaw -= dx * 0.01;
        self.pitch = (self.pitch + dy * 0.01).clamp(-1.55, 1.55);
    }

    /// Moves the target in the view plane so the scene follows the mouse
    /// (`h` = viewport height in pixels).
    pub fn pan(&mut self, dx: f32, dy: f32, h: f32) {
        let world_per_px = 2.0 * self.distance * (self.fov_y * 0.5).tan() / h.max(1.0);
        let back = self.back();
        let right = Vec3::Y.cross(back).normalize_or(Vec3::X);
        let up = back.cross(right);
        self.target += (-right * dx + up * dy) * world_per_px;
    }

    /// Wheel zoom: each notch moves 15% closer (positive) or further.
    pub fn zoom(&mut self, notches: f32) {
        self.distance = (self.distance * 0.85f32.powf(notches)).clamp(1e-3, 1e6);
    }

    /// Looks at a sphere so that it fills the view.
    pub fn frame_sphere(&mut self, center: Vec3, radius: f32) {
        self.target = center;
        let r = radius.max(1e-3);
        self.distance = r / (self.fov_y * 0.5).sin() * 1.1;
    }
}

/// Maps world points to viewport pixels for a given view.
#[derive(Clone, Copy, Debug)]
pub struct Projector {
    pub view: Mat4,
    pub proj: Mat4,
    /// Viewport origin and size in window pixels.
    pub x: f32,
    pub y: f32,
    pub w: f32,
    pub h: f32,
    near: f32,
    /// Multiplies [`Projector::world_per_px`]: handles on a small object
    /// are drawn smaller so they do not hide it ([`Projector::for_handles`]).
    px_scale: f32,
    /// Pixels around the pivot that handles leave empty (the small
    /// object's own disc), 0 normally.
    gap_px: f32,
}

impl Projector {
    pub fn new(v: &View, x: f32, y: f32, w: f32, h: f32) -> Projector {
        // Recover the near plane from the projection (OpenGL form).
        // Perspective: p22 = (f+n)/(n-f), p32 = 2fn/(n-f) ⇒ n = p32/(p22-1).
        // Orthographic: p22 = -2/(f-n), p32 = -(f+n)/(f-n) ⇒ n = (p32+1)/p22.
        let p22 = v.proj.z_axis.z;
        let p32 = v.proj.w_axis.z;
        let near = if is_ortho(&v.proj) {
            if p22.abs() > 1e-12 {
                ((p32 + 1.0) / p22).abs()
            } else {
                1e-3
            }
        } else if (p22 - 1.0).abs() > 1e-9 {
            (p32 / (p22 - 1.0)).abs()
        } else {
            1e-3
        };
        Projector {
            view: v.view,
            proj: v.proj,
            x,
            y,
            w,
            h,
            near: near.max(1e-5),
            px_scale: 1.0,
            gap_px: 0.0,
        }
    }

    /// The factor set by [`Projector::for_handles`] (1 unless shrunk).
    pub fn px_scale(&self) -> f32 {
        self.px_scale
    }

    /// The empty disc around the pivot set by [`Projector::for_handles`].
    pub fn gap_px(&self) -> f32 {
        self.gap_px
    }

    /// This projector as the editor's handles use it on a small object:
    /// every constant-screen-size gizmo drawn `scale` times as large, and
    /// nothing drawn or grabbed within `gap_px` of the pivot.
    pub fn for_handles(mut self, scale: f32, gap_px: f32) -> Projector {
        self.px_scale = scale;
        self.gap_px = gap_px.max(0.0);
        self
    }

    fn eye_to_px(&self, e: Vec3) -> (f32, f32) {
        let c = self.proj * e.extend(1.0);
        let ndc = c.truncate() / c.w;
        (
            self.x + (ndc.x + 1.0) * 0.5 * self.w,
            self.y + (1.0 - ndc.y) * 0.5 * self.h,
        )
    }

    /// Pixel position of a world point, or `None` when it is behind the eye.
    pub fn point(&self, p: Vec3) -> Option<(f32, f32)> {
        let e = self.view.transform_point3(p);
        (e.z < -self.near).then(|| self.eye_to_px(e))
    }

    /// A world segment clipped against the near plane, in pixels.
    pub fn segment(&self, a: Vec3, b: Vec3) -> Option<((f32, f32), (f32, f32))> {
        let mut ea = self.view.transform_point3(a);
        let mut eb = self.view.transform_point3(b);
        let z = -self.near * 1.001;
        if ea.z > z && eb.z > z {
            return None;
        }
        if ea.z > z {
            let t = (z - eb.z) / (ea.z - eb.z);
            ea = eb + (ea - eb) * t;
        } else if eb.z > z {
            let t = (z - ea.z) / (eb.z - ea.z);
            eb = ea + (eb - ea) * t;
        }
        Some((self.eye_to_px(ea), self.eye_to_px(eb)))
    }

    /// Pixels per world unit at distance of world point `p` (for sizing
    /// gizmos that keep a constant screen size).
    pub fn world_per_px(&self, p: Vec3) -> f32 {
        let fy = self.proj.y_axis.y.max(1e-6);
        // An orthographic view has the same scale at every depth
        // (p11 = 1/half-height); a perspective one grows with depth.
        if is_ortho(&self.proj) {
            return self.px_scale * 2.0 / (fy * self.h.max(1.0));
        }
        let e = self.view.transform_point3(p);
        let depth = (-e.z).max(self.near);
        self.px_scale * 2.0 * depth / (fy * self.h.max(1.0))
    }
}

/// Whether `proj` is orthographic: its w row is (0, 0, 0, 1), where a
/// perspective projection's is (0, 0, −1, 0).
pub fn is_ortho(proj: &Mat4) -> bool {
    proj.z_axis.w == 0.0 && proj.w_axis.w == 1.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn target_projects_to_the_viewport_centre() {
        let cam = OrbitCamera {
            target: Vec3::new(1.0, 2.0, 3.0),
            ..OrbitCamera::default()
        };
        let v = cam.view(200, 100, 5.0);
        let p = Projector::new(&v, 10.0, 20.0, 200.0, 100.0);
        let (x, y) = p.point(cam.target).unwrap();
        assert!(
            (x - 110.0).abs() < 1e-3 && (y - 70.0).abs() < 1e-3,
            "{x} {y}"
        );
        // Behind the eye: nothing.
        assert!(p.point(cam.eye() + cam.back()).is_none());
    }

    #[test]
    fn up_is_up_on_screen() {
        let cam = OrbitCamera::default();
        let v = cam.view(100, 100, 5.0);
        let p = Projector::new(&v, 0.0, 0.0, 100.0, 100.0);
        let a = p.point(Vec3::ZERO).unwrap();
        let b = p.point(Vec3::Y).unwrap();
        assert!(b.1 < a.1);
    }

    #[test]
    fn segment_crossing_the_eye_plane_is_clipped() {
        let cam = OrbitCamera::default();
        let v = cam.view(100, 100, 5.0);
        let p = Projector::new(&v, 0.0, 0.0, 100.0, 100.0);
        let behind = cam.eye() + cam.back() * 5.0;
        let (a, b) = p.segment(Vec3::ZERO, behind).unwrap();
        assert!(a.0.is_finite() && b.0.is_finite() && b.1.is_finite());
        assert!(p.segment(behind, behind + Vec3::X).is_none());
    }

    #[test]
    fn orthographic_scale_does_not_grow_with_depth() {
        // The orthographic volume is as tall as the perspective one at the
        // target, so both give the same pixel size there; further away only
        // the perspective one grows (handles sized from it stay small).
        let mut cam = OrbitCamera::default();
        let persp = Projector::new(&cam.view(200, 100, 5.0), 0.0, 0.0, 200.0, 100.0);
        cam.ortho = true;
        let ortho = Projector::new(&cam.view(200, 100, 5.0), 0.0, 0.0, 200.0, 100.0);
        let at = |p: &Projector, q: Vec3| p.world_per_px(q);
        let t = cam.target;
        assert!((at(&persp, t) - at(&ortho, t)).abs() < 1e-5 * at(&persp, t));
        let far = t - cam.back() * 20.0;
        assert!(at(&persp, far) > 2.0 * at(&persp, t));
        assert_eq!(at(&ortho, far), at(&ortho, t));
        // The near plane is recovered from either projection.
        assert!(
            (ortho.near - persp.near).abs() < 1e-4,
            "{} {}",
            ortho.near,
            persp.near
        );
    }

    #[test]
    fn framing_fits_the_sphere() {
        let mut cam = OrbitCamera::default();
        cam.frame_sphere(Vec3::new(5.0, 0.0, 0.0), 2.0);
        assert_eq!(cam.target, Vec3::new(5.0, 0.0, 0.0));
        // The sphere's silhouette half-angle is inside the half fov.
        let half = (2.0 / cam.distance).asin();
        assert!(half < cam.fov_y * 0.5);
    }
}
