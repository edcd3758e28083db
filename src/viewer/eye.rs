//! Where the viewer looks from: one of the file's viewpoints (animated with
//! the scene), Coin-style view-all when the file has none, or a free orbit
//! camera once the user drags.

use crate::anim::Pose;
use crate::input::camera::OrbitCamera;
use crate::render::job::view_for;
use crate::render::View;
use crate::scene::{NodeId, Scene};
use glam::Vec3;

#[derive(Clone, Debug, PartialEq)]
pub enum Eye {
    /// Index into the viewer's camera list.
    Viewpoint(usize),
    ViewAll,
    Orbit(OrbitCamera),
}

impl Eye {
    /// The render view for a `w`×`h` picture of `pose`.
    pub fn view(&self, scene: &Scene, pose: &Pose, cameras: &[NodeId], w: u32, h: u32) -> View {
        let aspect = w.max(1) as f32 / h.max(1) as f32;
        match self {
            Eye::Viewpoint(i) => view_for(scene, pose, cameras.get(*i).copied(), aspect),
            Eye::ViewAll => view_for(scene, pose, None, aspect),
            Eye::Orbit(c) => {
                let radius = crate::render::bounding_sphere(scene, pose).map_or(1.0, |s| s.1);
                c.view(w, h, radius)
            }
        }
    }
}

/// An orbit camera that sees what `view` sees (less any roll): same eye,
/// direction and vertical field of view, orbiting the point where the view
/// direction passes the scene's centre (`sphere`).
pub fn orbit_from_view(view: &View, sphere: Option<(Vec3, f32)>) -> OrbitCamera {
    let fwd = view.forward().normalize_or(Vec3::NEG_Z);
    let back = -fwd;
    let (centre, radius) = sphere.unwrap_or((view.eye + fwd * 10.0, 1.0));
    let along = (centre - view.eye).dot(fwd);
    let distance = if along > radius * 0.05 && along.is_finite() {
        along
    } else {
        radius.max(1e-3) * 2.0
    };
    // proj.y_axis.y = 1 / tan(fov_y / 2) for a perspective projection; an
    // orthographic one (w row = 0,0,0,1) gets the default 45°.
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
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_orbit_camera_round_trips_through_its_view() {
        let c = OrbitCamera {
            target: Vec3::new(1.0, 2.0, -3.0),
            distance: 7.0,
            yaw: 0.8,
            pitch: -0.3,
            fov_y: 0.9,
        };
        let v = c.view(400, 300, 5.0);
        let back = orbit_from_view(&v, Some((c.target, 2.0)));
        assert!((back.target - c.target).length() < 1e-3, "{back:?}");
        assert!((back.distance - c.distance).abs() < 1e-3);
        assert!((back.yaw - c.yaw).abs() < 1e-4);
        assert!((back.pitch - c.pitch).abs() < 1e-4);
        assert!((back.fov_y - c.fov_y).abs() < 1e-4);
    }
}
