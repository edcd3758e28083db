use crate::anim::Pose;
use crate::scene::{Camera, CameraKind, NodeKind, Scene};
use glam::{Mat4, Quat, Vec3, Vec4};

/// Near/far used by [`View::from_camera`] when the camera gives none.
pub const DEFAULT_NEAR: f32 = 0.1;
pub const DEFAULT_FAR: f32 = 1000.0;

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
    ///
    /// The field of view applies to the smaller picture side (VRML97
    /// Viewpoint; Coin's default ADJUST_CAMERA viewport mapping does the same
    /// for Inventor cameras). Near/far come from the camera, else
    /// [`DEFAULT_NEAR`]/[`DEFAULT_FAR`]; use [`View::for_scene`] to fit them.
    pub fn from_camera(camera: &Camera, world: Mat4, aspect: f32) -> View {
        let near = camera.near.unwrap_or(DEFAULT_NEAR);
        let far = camera.far.unwrap_or(DEFAULT_FAR);
        Self::build(camera, world, aspect, near, far)
    }

    /// Like [`View::from_camera`], but near/far that the camera leaves open
    /// are fitted to the bounding sphere of the posed scene (as Coin's
    /// automatic clipping planes do), which keeps depth precision.
    pub fn for_scene(
        camera: &Camera,
        world: Mat4,
        aspect: f32,
        scene: &Scene,
        pose: &Pose,
    ) -> View {
        let eye_to_world = camera_matrix(camera, world);
        let (mut near, mut far) = (DEFAULT_NEAR, DEFAULT_FAR);
        if let Some((c, r)) = bounding_sphere(scene, pose) {
            let d = -(eye_to_world.inverse().transform_point3(c)).z;
            far = (d + r) * 1.01;
            near = (d - r) * 0.99;
            if near < far * 1e-3 {
                near = far * 1e-3;
            }
            if far <= near {
                far = near * 2.0;
            }
        }
        Self::build(
            camera,
            world,
            aspect,
            camera.near.unwrap_or(near),
            camera.far.unwrap_or(far),
        )
    }

    /// Frames the whole posed scene the way Coin's `viewAll` does: the
    /// bounding sphere of the scene's bounding box, seen down −z from its
    /// centre at distance r / sin(heightAngle/2), heightAngle 45°, near/far
    /// fitted to the sphere. An empty scene gives the VRML97 default view.
    pub fn view_all(scene: &Scene, pose: &Pose, aspect: f32) -> View {
        Self::build_view_all(bounding_sphere(scene, pose), aspect).0
    }

    /// The camera [`View::view_all`] builds (for the editor's orbit and for
    /// writers that want to save it), with the view.
    pub fn view_all_camera(scene: &Scene, pose: &Pose, aspect: f32) -> (View, Camera) {
        Self::build_view_all(bounding_sphere(scene, pose), aspect)
    }

    fn build_view_all(sphere: Option<(Vec3, f32)>, aspect: f32) -> (View, Camera) {
        let height_angle = std::f32::consts::FRAC_PI_4;
        let mut cam = Camera {
            kind: CameraKind::Perspective { height_angle },
            ..Camera::default()
        };
        if let Some((c, r)) = sphere {
            let r = r.max(1e-6);
            let d = r / libm::sinf(height_angle / 2.0);
            cam.position = c + Vec3::Z * d;
            cam.orientation = Quat::IDENTITY;
            cam.focal_distance = d;
            cam.near = Some(d - r);
            cam.far = Some(d + r);
        }
        (Self::from_camera(&cam, Mat4::IDENTITY, aspect), cam)
    }

    fn build(camera: &Camera, world: Mat4, aspect: f32, near: f32, far: f32) -> View {
        let m = camera_matrix(camera, world);
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        let near = if near > 0.0 { near } else { DEFAULT_NEAR };
        let far = if far > near { far } else { near * 2.0 };
        let proj = match camera.kind {
            CameraKind::Perspective { height_angle } => {
                let mut t = libm::tanf(height_angle.clamp(1e-4, 3.1) / 2.0);
                if aspect < 1.0 {
                    t /= aspect; // the angle spans the (smaller) width
                }
                perspective(t, aspect, near, far)
            }
            CameraKind::Orthographic { height } => {
                let mut h = height.abs().max(1e-9) / 2.0;
                if aspect < 1.0 {
                    h /= aspect;
                }
                orthographic(h * aspect, h, near, far)
            }
        };
        View {
            view: m.inverse(),
            proj,
            eye: m.transform_point3(Vec3::ZERO),
        }
    }

    /// The world-space direction the camera looks along (unit).
    pub fn forward(&self) -> Vec3 {
        self.view
            .inverse()
            .transform_vector3(Vec3::NEG_Z)
            .normalize_or_zero()
    }
}

/// Eye→world matrix of a camera on a node.
fn camera_matrix(camera: &Camera, world: Mat4) -> Mat4 {
    world * Mat4::from_rotation_translation(camera.orientation.normalize(), camera.position)
}

/// OpenGL-style perspective (clip z in −w..w) from tan(half vertical angle).
fn perspective(tan_half: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let f = 1.0 / tan_half;
    Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, (far + near) / (near - far), -1.0),
        Vec4::new(0.0, 0.0, 2.0 * far * near / (near - far), 0.0),
    )
}

/// OpenGL-style orthographic projection of the box ±hw × ±hh × [near, far].
fn orthographic(hw: f32, hh: f32, near: f32, far: f32) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(1.0 / hw, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 1.0 / hh, 0.0, 0.0),
        Vec4::new(0.0, 0.0, -2.0 / (far - near), 0.0),
        Vec4::new(0.0, 0.0, -(far + near) / (far - near), 1.0),
    )
}

/// World-space bounding box of every visible shape in the pose.
pub fn scene_bounds(scene: &Scene, pose: &Pose) -> Option<(Vec3, Vec3)> {
    let mut out: Option<(Vec3, Vec3)> = None;
    for (i, node) in scene.nodes.iter().enumerate() {
        let NodeKind::Shape(shape) = &node.kind else {
            continue;
        };
        if !pose.visible.get(i).copied().unwrap_or(node.visible) {
            continue;
        }
        let Some(mesh) = scene.meshes.get(shape.mesh.0 as usize) else {
            continue;
        };
        let Some((lo, hi)) = mesh.bounds() else {
            continue;
        };
        let world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
        for k in 0..8 {
            let c = Vec3::new(
                if k & 1 == 0 { lo.x } else { hi.x },
                if k & 2 == 0 { lo.y } else { hi.y },
                if k & 4 == 0 { lo.z } else { hi.z },
            );
            let p = world.transform_point3(c);
            if !p.is_finite() {
                continue;
            }
            out = Some(match out {
                Some((a, b)) => (a.min(p), b.max(p)),
                None => (p, p),
            });
        }
    }
    out
}

/// The sphere circumscribing [`scene_bounds`] (centre, radius).
pub fn bounding_sphere(scene: &Scene, pose: &Pose) -> Option<(Vec3, f32)> {
    scene_bounds(scene, pose).map(|(lo, hi)| ((lo + hi) * 0.5, (hi - lo).length() * 0.5))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{primitives, Material, Node, Shape};

    fn project(v: &View, p: Vec3) -> Vec3 {
        v.proj.project_point3(v.view.transform_point3(p))
    }

    #[test]
    fn default_viewpoint_sees_origin_at_centre() {
        let v = View::from_camera(&Camera::default(), Mat4::IDENTITY, 4.0 / 3.0);
        let c = project(&v, Vec3::ZERO);
        assert!(c.x.abs() < 1e-6 && c.y.abs() < 1e-6);
        // 45° vertical: a point at height tan(22.5°)·10 is at the top edge.
        let top = project(
            &v,
            Vec3::new(0.0, std::f32::consts::FRAC_PI_8.tan() * 10.0, 0.0),
        );
        assert!((top.y - 1.0).abs() < 1e-4, "{top}");
        assert_eq!(v.eye, Vec3::new(0.0, 0.0, 10.0));
    }

    #[test]
    fn fov_applies_to_the_smaller_side() {
        let v = View::from_camera(&Camera::default(), Mat4::IDENTITY, 0.5);
        let right = project(
            &v,
            Vec3::new(std::f32::consts::FRAC_PI_8.tan() * 10.0, 0.0, 0.0),
        );
        assert!((right.x - 1.0).abs() < 1e-4, "{right}");
    }

    #[test]
    fn view_all_follows_coin() {
        let mut s = Scene::new();
        let mesh = s.add_mesh(primitives::box_mesh(Vec3::new(2.0, 2.0, 2.0)));
        let material = s.add_material(Material::default());
        s.add_node(
            None,
            Node::new("b", NodeKind::Shape(Shape { mesh, material })),
        );
        let pose = crate::anim::evaluate(&s, 0.0);
        let (v, cam) = View::view_all_camera(&s, &pose, 1.0);
        let r = 3f32.sqrt();
        let d = r / (std::f32::consts::FRAC_PI_8).sin();
        assert!((cam.position - Vec3::new(0.0, 0.0, d)).length() < 1e-4);
        assert!((cam.near.unwrap() - (d - r)).abs() < 1e-4);
        // The sphere's silhouette touches the top edge: the tangent ray from
        // the eye makes the half angle 22.5° with the axis.
        let tangent_y = r * (std::f32::consts::FRAC_PI_8).cos();
        let tangent_z = d - r * (std::f32::consts::FRAC_PI_8).sin();
        let p = project(&v, Vec3::new(0.0, tangent_y, d - tangent_z));
        assert!((p.y - 1.0).abs() < 1e-3, "{p}");
    }
}
