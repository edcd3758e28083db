use super::{Property, TargetRef, Value};
use crate::scene::{Camera, CameraKind, Light, LightKind, Material, NodeId, Scene, Transform};
use glam::Mat4;

/// The scene's animatable state at one time. The scene is never mutated;
/// the renderer draws a `Pose`.
#[derive(Clone, Debug, Default)]
pub struct Pose {
    /// Local transform per node (after animation).
    pub transforms: Vec<Transform>,
    /// World matrix per node.
    pub world: Vec<Mat4>,
    /// Effective visibility per node (hidden if any ancestor is hidden).
    pub visible: Vec<bool>,
    /// Animated light per light node.
    pub lights: Vec<(NodeId, Light)>,
    /// Animated camera per camera node.
    pub cameras: Vec<(NodeId, Camera)>,
    /// Animated materials, indexed like `Scene::materials`.
    pub materials: Vec<Material>,
}

impl Pose {
    pub fn light(&self, id: NodeId) -> Option<&Light> {
        self.lights.iter().find(|(n, _)| *n == id).map(|(_, l)| l)
    }
    pub fn camera(&self, id: NodeId) -> Option<&Camera> {
        self.cameras.iter().find(|(n, _)| *n == id).map(|(_, c)| c)
    }
}

/// Evaluates every track of `scene` at `time` seconds.
pub fn evaluate(scene: &Scene, time: f32) -> Pose {
    let frame = time * scene.settings.fps;
    let n = scene.nodes.len();
    let mut transforms: Vec<Transform> = scene.nodes.iter().map(|n| n.transform).collect();
    let mut own_visible: Vec<bool> = scene.nodes.iter().map(|n| n.visible).collect();
    let mut lights: Vec<Option<Light>> = scene.nodes.iter().map(|n| n.light().cloned()).collect();
    let mut cameras: Vec<Option<Camera>> =
        scene.nodes.iter().map(|n| n.camera().cloned()).collect();
    let mut materials = scene.materials.clone();

    for track in &scene.animation.tracks {
        let v = track.sample(frame);
        match track.target.of {
            TargetRef::Node(id) => {
                let i = id.0 as usize;
                if i >= n {
                    continue;
                }
                apply_node(
                    track.target.property,
                    v,
                    &mut transforms[i],
                    &mut own_visible[i],
                );
                if let Some(l) = lights[i].as_mut() {
                    apply_light(track.target.property, v, l);
                }
                if let Some(c) = cameras[i].as_mut() {
                    apply_camera(track.target.property, v, c);
                }
            }
            TargetRef::Material(id) => {
                if let Some(m) = materials.get_mut(id.0 as usize) {
                    apply_material(track.target.property, v, m);
                }
            }
        }
    }

    let mut world = vec![Mat4::IDENTITY; n];
    let mut visible = vec![true; n];
    for id in scene.walk() {
        let i = id.0 as usize;
        let (pw, pv) = match scene.nodes[i].parent {
            Some(p) => (world[p.0 as usize], visible[p.0 as usize]),
            None => (Mat4::IDENTITY, true),
        };
        world[i] = pw * transforms[i].matrix();
        visible[i] = pv && own_visible[i];
    }

    Pose {
        transforms,
        world,
        visible,
        lights: lights
            .into_iter()
            .enumerate()
            .filter_map(|(i, l)| l.map(|l| (NodeId(i as u32), l)))
            .collect(),
        cameras: cameras
            .into_iter()
            .enumerate()
            .filter_map(|(i, c)| c.map(|c| (NodeId(i as u32), c)))
            .collect(),
        materials,
    }
}

fn apply_node(p: Property, v: Value, t: &mut Transform, visible: &mut bool) {
    match (p, v) {
        (Property::Translation, Value::Vec3(x)) => t.translation = x,
        (Property::Rotation, Value::Rotation(q)) => t.rotation = q,
        (Property::Scale, Value::Vec3(x)) => t.scale = x,
        (Property::Visibility, Value::Bool(b)) => *visible = b,
        _ => {}
    }
}

fn apply_light(p: Property, v: Value, l: &mut Light) {
    match (p, v) {
        (Property::LightOn, Value::Bool(b)) => l.on = b,
        (Property::LightIntensity, Value::Scalar(x)) => l.intensity = x,
        (Property::LightColor, Value::Vec3(c)) => l.color = c,
        (Property::LightLocation, Value::Vec3(x)) => l.location = x,
        (Property::LightDirection, Value::Vec3(x)) => l.direction = x,
        (prop, Value::Scalar(x)) => {
            if let LightKind::Spot {
                beam_width,
                cut_off_angle,
                drop_off_rate,
            } = &mut l.kind
            {
                match prop {
                    Property::LightCutOff => *cut_off_angle = x,
                    Property::LightBeamWidth => *beam_width = x,
                    Property::LightDropOff => *drop_off_rate = x,
                    _ => {}
                }
            }
        }
        _ => {}
    }
}

fn apply_camera(p: Property, v: Value, c: &mut Camera) {
    match (p, v) {
        (Property::CameraPosition, Value::Vec3(x)) => c.position = x,
        (Property::CameraOrientation, Value::Rotation(q)) => c.orientation = q,
        (Property::CameraFov, Value::Scalar(x)) => {
            if let CameraKind::Perspective { height_angle } = &mut c.kind {
                *height_angle = x;
            }
        }
        _ => {}
    }
}

fn apply_material(p: Property, v: Value, m: &mut Material) {
    match (p, v) {
        (Property::Diffuse, Value::Vec3(c)) => m.diffuse = c,
        (Property::Emissive, Value::Vec3(c)) => m.emissive = c,
        (Property::Specular, Value::Vec3(c)) => m.specular = c,
        (Property::Transparency, Value::Scalar(x)) => m.transparency = x,
        (Property::Shininess, Value::Scalar(x)) => m.shininess = x,
        _ => {}
    }
}
