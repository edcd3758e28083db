use crate::scene::Camera;
use glam::{Mat4, Vec3};

/// A camera ready for rasterising: world→eye and eye→clip matrices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub view: Mat4,
    pub proj: Mat4,
    /// Eye position in world space (for specular and the headlight).
    pub eye: Vec3,
}

impl View {
    /// The view of `camera` mounted on a node with world matrix `world`,
    /// for a picture of aspect ratio `aspect` (width / height).
    pub fn from_camera(camera: &Camera, world: Mat4, aspect: f32) -> View {
        let _ = (camera, world, aspect);
        View {
            view: Mat4::IDENTITY,
            proj: Mat4::IDENTITY,
            eye: Vec3::ZERO,
        }
    }
}
