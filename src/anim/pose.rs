use super::deform::{self, Deformed};
use super::skinning::JointMatrix;
use super::{Property, TargetRef, Value, Weights};
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
    /// Morph weights per shape node whose mesh has morph targets, in node
    /// order (the mesh's defaults unless a `weights` track drives them).
    pub weights: Vec<(NodeId, Weights)>,
    /// Per skin (indexed like `Scene::skins`): each joint's
    /// `jointWorld · inverseBind` and its normal matrix.
    pub joints: Vec<Vec<JointMatrix>>,
    /// Deformed geometry per shape node whose mesh is morphed or skinned, in
    /// node order.
    pub deformed: Vec<(NodeId, Deformed)>,
}

impl Pose {
    /// The animated light of node `id` (lights are kept in node order).
    pub fn light(&self, id: NodeId) -> Option<&Light> {
        find(&self.lights, id)
    }
    /// The animated camera of node `id`.
    pub fn camera(&self, id: NodeId) -> Option<&Camera> {
        find(&self.cameras, id)
    }
    /// The morph weights of shape node `id`, when its mesh has targets.
    pub fn weights(&self, id: NodeId) -> Option<&Weights> {
        find(&self.weights, id)
    }
    /// The deformed geometry of shape node `id`, when its mesh deforms.
    pub fn deformed(&self, id: NodeId) -> Option<&Deformed> {
        find(&self.deformed, id)
    }
}

/// Binary search (evaluate keeps node order), then a linear scan for poses
/// built by hand in another order.
fn find<T>(items: &[(NodeId, T)], id: NodeId) -> Option<&T> {
    match items.binary_search_by_key(&id, |(n, _)| *n) {
        Ok(j) => Some(&items[j].1),
        Err(_) => items.iter().find(|(n, _)| *n == id).map(|(_, v)| v),
    }
}

/// Evaluates every track of `scene` at `time` seconds (key frame =
/// `time · fps`), leaving the scene untouched.
pub fn evaluate(scene: &Scene, time: f32) -> Pose {
    let mut pose = Pose::default();
    evaluate_into(scene, time, &mut pose);
    pose
}

/// [`evaluate`] into an existing pose, reusing its buffers: after the first
/// call with a scene of the same shape it allocates nothing. Tracks apply in
/// order, so the last track on a property wins; a track whose property does
/// not fit its target (a light property on a group, say) is ignored.
pub fn evaluate_into(scene: &Scene, time: f32, pose: &mut Pose) {
    let frame = time * scene.settings.fps;
    let nodes = &scene.nodes;
    let n = nodes.len();

    pose.transforms.clear();
    pose.transforms.extend(nodes.iter().map(|n| n.transform));
    // Own visibility first; the tree walk below folds in the ancestors'.
    pose.visible.clear();
    pose.visible.extend(nodes.iter().map(|n| n.visible));
    sync(&mut pose.lights, nodes.iter().map(|n| n.light()));
    sync(&mut pose.cameras, nodes.iter().map(|n| n.camera()));
    pose.materials.clone_from(&scene.materials);
    deform::default_weights(scene, &mut pose.weights);

    for track in &scene.animation.tracks {
        let p = track.target.property;
        match track.target.of {
            TargetRef::Node(id) => {
                let i = id.0 as usize;
                if i >= n {
                    continue;
                }
                match p.owner() {
                    "shape" => {
                        let Value::Weights(w) = track.sample(frame) else {
                            continue;
                        };
                        // A group's weights drive its morphed child shapes
                        // (a glTF node with several primitives).
                        let own = std::slice::from_ref(&id);
                        let ids = if pose.weights.binary_search_by_key(&id, |(n, _)| *n).is_ok() {
                            own
                        } else {
                            &nodes[i].children[..]
                        };
                        for c in ids {
                            if let Ok(j) = pose.weights.binary_search_by_key(c, |(n, _)| *n) {
                                apply_weights(&mut pose.weights[j].1, &w);
                            }
                        }
                    }
                    "light" => {
                        if let Ok(j) = pose.lights.binary_search_by_key(&id, |(n, _)| *n) {
                            apply_light(p, track.sample(frame), &mut pose.lights[j].1);
                        }
                    }
                    "camera" => {
                        if let Ok(j) = pose.cameras.binary_search_by_key(&id, |(n, _)| *n) {
                            apply_camera(p, track.sample(frame), &mut pose.cameras[j].1);
                        }
                    }
                    _ => apply_node(
                        p,
                        track.sample(frame),
                        &mut pose.transforms[i],
                        &mut pose.visible[i],
                    ),
                }
            }
            TargetRef::Material(id) => {
                if let Some(m) = pose.materials.get_mut(id.0 as usize) {
                    apply_material(p, track.sample(frame), m);
                }
            }
        }
    }

    pose.world.clear();
    pose.world
        .extend(pose.transforms.iter().map(|t| t.matrix()));
    // Readers add parents before children, so arena order visits parents
    // first; otherwise fall back to the explicit pre-order walk.
    let ordered = nodes
        .iter()
        .enumerate()
        .all(|(i, nd)| nd.parent.is_none_or(|p| (p.0 as usize) < i));
    if ordered {
        for i in 0..n {
            combine(nodes, pose, i);
        }
    } else {
        for id in scene.walk() {
            combine(nodes, pose, id.0 as usize);
        }
    }
    deform::deform(scene, pose);
}

/// Keyed weights replace the defaults target by target; a key with fewer
/// weights than the mesh has targets leaves the rest at their defaults, and
/// extra keyed weights are ignored.
fn apply_weights(out: &mut Weights, keyed: &Weights) {
    let n = out.len().min(keyed.len());
    out.as_mut_slice()[..n].copy_from_slice(&keyed.as_slice()[..n]);
}

/// Folds the parent's world matrix and visibility into node `i`.
#[inline]
fn combine(nodes: &[crate::scene::Node], pose: &mut Pose, i: usize) {
    if let Some(p) = nodes[i].parent {
        let p = p.0 as usize;
        if p < nodes.len() && p != i {
            pose.world[i] = pose.world[p] * pose.world[i];
            pose.visible[i] = pose.visible[p] && pose.visible[i];
        }
    }
}

/// Makes `out` hold `(id, value)` for every node that has one, in node order,
/// reusing its elements (and their strings) where it can.
fn sync<'a, T: Clone + 'a>(out: &mut Vec<(NodeId, T)>, items: impl Iterator<Item = Option<&'a T>>) {
    let mut j = 0;
    for (i, item) in items.enumerate() {
        if let Some(v) = item {
            let id = NodeId(i as u32);
            if j < out.len() {
                out[j].0 = id;
                out[j].1.clone_from(v);
            } else {
                out.push((id, v.clone()));
            }
            j += 1;
        }
    }
    out.truncate(j);
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
