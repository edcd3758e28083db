use super::geometry::Geometry;
use crate::anim::Pose;
use crate::scene::{Camera, CameraKind, NodeId, NodeKind, Scene, TextKind};
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
            // Not nearer than far / 2000: a deep scene (a 1000 m path seen
            // from its start) keeps what lies a metre ahead, as the
            // reference viewers' automatic planes do.
            if near < far * 5e-4 {
                near = far * 5e-4;
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
    /// sphere around the scene's bounding box as Coin's bounding-box action
    /// merges it ([`super::coin_bounds`]; radius r), a default camera
    /// (heightAngle 45°, looking down −z) moved back from the sphere's centre
    /// by `r' / tan(heightAngle/2)` with `r' = r / min(aspect, 1)`, near and
    /// far at that distance ∓ r. That distance is what Coin 4.0 (Debian's
    /// libcoin80) computes: probed with pivy, a scene with bounding radius
    /// 3.316 got its camera 8.006 from the centre, near 4.690, far 11.322.
    /// (`r / sin(heightAngle/2)`, the tangent distance, frames ~6 % smaller;
    /// the sphere's silhouette is slightly cropped, as in Coin.)
    /// An empty scene gives the VRML97 default view.
    pub fn view_all(scene: &Scene, pose: &Pose, aspect: f32) -> View {
        Self::build_view_all(coin_sphere(scene, pose, None), aspect).0
    }

    /// [`View::view_all`] framed once per file: the camera comes from
    /// `start` (the pose at time 0, as Coin and castle-model-viewer frame a
    /// file when they open it), so every time, frame, range and shard of an
    /// animated file sees from the same place; only near and far widen to
    /// hold `now` as well (Coin's automatic clipping planes do the same).
    /// For a still scene (`now` = `start`) it is exactly `view_all`.
    pub fn view_all_from_start(scene: &Scene, start: &Pose, now: &Pose, aspect: f32) -> View {
        Self::view_all_from_start_in(scene, start, now, aspect, None)
    }

    /// [`View::view_all_from_start`] for a picture `width`×`height` pixels:
    /// Inventor `Text2` labels then count in the box as Coin counts them
    /// (their pixel rectangles, [`super::coin_bounds`]), not by their
    /// anchors alone.
    pub fn view_all_for_picture(
        scene: &Scene,
        start: &Pose,
        now: &Pose,
        width: u32,
        height: u32,
    ) -> View {
        let aspect = width.max(1) as f32 / height.max(1) as f32;
        Self::view_all_from_start_in(scene, start, now, aspect, Some((width, height)))
    }

    fn view_all_from_start_in(
        scene: &Scene,
        start: &Pose,
        now: &Pose,
        aspect: f32,
        picture: Option<(u32, u32)>,
    ) -> View {
        let (view, mut cam) = Self::build_view_all(coin_sphere(scene, start, picture), aspect);
        let (Some((c, r)), Some(near), Some(far)) =
            (bounding_sphere(scene, now), cam.near, cam.far)
        else {
            return view;
        };
        // The view-all camera looks down −z from `cam.position`.
        let d = cam.position.z - c.z;
        let (n, f) = (near.min(d - r), far.max(d + r));
        if (n, f) == (near, far) {
            return view;
        }
        cam.far = Some(f);
        cam.near = Some(n.max(f * 1e-3));
        Self::from_camera(&cam, Mat4::IDENTITY, aspect)
    }

    /// The distance [`View::view_all`] puts the camera from the sphere's
    /// centre.
    pub fn view_all_distance(radius: f32, height_angle: f32, aspect: f32) -> f32 {
        let r = radius / if aspect < 1.0 { aspect } else { 1.0 };
        r / libm::tanf(height_angle / 2.0)
    }

    /// The camera [`View::view_all`] builds (for the editor's orbit and for
    /// writers that want to save it), with the view.
    pub fn view_all_camera(scene: &Scene, pose: &Pose, aspect: f32) -> (View, Camera) {
        Self::build_view_all(coin_sphere(scene, pose, None), aspect)
    }

    fn build_view_all(sphere: Option<(Vec3, f32)>, aspect: f32) -> (View, Camera) {
        let height_angle = std::f32::consts::FRAC_PI_4;
        let mut cam = Camera {
            kind: CameraKind::Perspective { height_angle },
            ..Camera::default()
        };
        if let Some((c, r)) = sphere {
            let r = r.max(1e-6);
            let d = Self::view_all_distance(r, height_angle, aspect);
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

/// World-space bounds of each visible shape's drawn (deformed) vertices,
/// in node order: every drawn vertex is taken to world space, so the box is
/// exact (not a box of a transformed box).
pub fn shape_bounds(scene: &Scene, pose: &Pose) -> Vec<(NodeId, Vec3, Vec3)> {
    let mut out = Vec::new();
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
        let world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
        let geo = Geometry::of(mesh, pose, NodeId(i as u32), world);
        let world_points: Vec<Vec3>;
        let pts = if geo.world == Mat4::IDENTITY {
            geo.positions
        } else {
            world_points = geo
                .positions
                .iter()
                .map(|p| geo.world.transform_point3(*p))
                .collect();
            &world_points
        };
        if let Some((lo, hi)) = points_bounds(pts) {
            out.push((NodeId(i as u32), lo, hi));
        }
    }
    out
}

/// World-space bounding box of every visible shape in the pose.
pub fn scene_bounds(scene: &Scene, pose: &Pose) -> Option<(Vec3, Vec3)> {
    bounds_in(scene, pose, None)
}

/// [`scene_bounds`] for a picture `width`×`height` pixels: Inventor Text2
/// labels count by their pixel rectangles, as view-all of that picture
/// counts them ([`View::view_all_for_picture`]), not by their anchors
/// alone. What the editor frames its viewport with.
pub fn scene_bounds_for_picture(
    scene: &Scene,
    pose: &Pose,
    width: u32,
    height: u32,
) -> Option<(Vec3, Vec3)> {
    bounds_in(scene, pose, Some((width, height)))
}

fn bounds_in(scene: &Scene, pose: &Pose, picture: Option<(u32, u32)>) -> Option<(Vec3, Vec3)> {
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
        let world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
        // Deformed shapes: the bounds of the pose's vertices.
        let geo = Geometry::of(mesh, pose, NodeId(i as u32), world);
        // An Inventor Text2 label is drawn at a pixel size, not a scene
        // size: without a picture only its anchor counts; with one, its
        // pixel rectangle as view-all sees it (a world box).
        let label = mesh.text.as_deref().filter(|t| t.kind == TextKind::Text2);
        let Some((lo, hi, world)) = (match (label, picture) {
            (Some(t), Some(px)) => super::coin_bounds::label_world(t, geo.positions, geo.world, px)
                .map(|(lo, hi)| (lo, hi, Mat4::IDENTITY)),
            (Some(_), None) => Some((Vec3::ZERO, Vec3::ZERO, geo.world)),
            (None, _) => points_bounds(geo.positions).map(|(lo, hi)| (lo, hi, geo.world)),
        }) else {
            continue;
        };
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

/// The sphere circumscribing the scene's box as Coin merges it
/// ([`super::coin_bounds`]): what view-all frames.
fn coin_sphere(scene: &Scene, pose: &Pose, picture: Option<(u32, u32)>) -> Option<(Vec3, f32)> {
    super::coin_bounds::coin_scene_bounds(scene, pose, picture)
        .map(|(lo, hi)| ((lo + hi) * 0.5, (hi - lo).length() * 0.5))
}

/// Axis-aligned bounds of finite points, `None` when there are none.
pub fn points_bounds(points: &[Vec3]) -> Option<(Vec3, Vec3)> {
    let mut it = points.iter().filter(|p| p.is_finite());
    let first = *it.next()?;
    Some(it.fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))))
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
        // Coin 4.0: r / tan(heightAngle / 2) = r · (1 + √2) for 45°.
        let d = r * (1.0 + 2f32.sqrt());
        assert!((cam.position - Vec3::new(0.0, 0.0, d)).length() < 1e-4);
        assert!((cam.near.unwrap() - (d - r)).abs() < 1e-4);
        assert!((cam.far.unwrap() - (d + r)).abs() < 1e-4);
        // The sphere's centre-plane cross-section exactly fills the height.
        let p = project(&v, Vec3::new(0.0, r, 0.0));
        assert!((p.y - 1.0).abs() < 1e-4, "{p}");
        // A tall picture moves the camera back by 1/aspect.
        let (_, tall) = View::view_all_camera(&s, &pose, 0.5);
        assert!((tall.position.z - 2.0 * d).abs() < 1e-3);
    }

    /// Numbers Coin 4.0 printed for `cam.viewAll` (pivy, 320×240) on a scene
    /// whose bounding box is (-2,-1.5,-1.5)..(2,1.5,2.857008): camera at
    /// z 8.684045, near 4.689537, far 11.321545.
    #[test]
    fn view_all_matches_coin_probe() {
        let mut s = Scene::new();
        let lo = Vec3::new(-2.0, -1.5, -1.5);
        let hi = Vec3::new(2.0, 1.5, 2.857_008);
        let mesh = s.add_mesh(crate::scene::Mesh {
            positions: vec![lo, hi],
            points: vec![0, 1],
            ..Default::default()
        });
        let material = s.add_material(Material::default());
        s.add_node(
            None,
            Node::new("b", NodeKind::Shape(Shape { mesh, material })),
        );
        let pose = crate::anim::evaluate(&s, 0.0);
        let (_, cam) = View::view_all_camera(&s, &pose, 320.0 / 240.0);
        assert!(
            (cam.position.z - 8.684_045).abs() < 1e-3,
            "{}",
            cam.position
        );
        assert!((cam.near.unwrap() - 4.689_537).abs() < 1e-3);
        assert!((cam.far.unwrap() - 11.321_545).abs() < 1e-3);
    }
}
