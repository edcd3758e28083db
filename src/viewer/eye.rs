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
            // Framed as `animed render` frames this picture size (Text2
            // labels by their pixel rectangles, from the start pose).
            Eye::ViewAll => {
                View::view_all_for_picture(scene, &crate::anim::evaluate(scene, 0.0), pose, w, h)
            }
            Eye::Orbit(c) => {
                let radius = crate::render::bounding_sphere(scene, pose).map_or(1.0, |s| s.1);
                c.view(w, h, radius)
            }
        }
    }
}

/// An orbit camera that sees what `view` sees (less any roll); see
/// [`OrbitCamera::from_view`].
pub fn orbit_from_view(view: &View, sphere: Option<(Vec3, f32)>) -> OrbitCamera {
    OrbitCamera::from_view(view, sphere)
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
            ortho: false,
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
