//! Record mode and keying: how a value change on the selection becomes a
//! key at the current frame, K (insert keys), and jumping between keys.
//!
//! The panel and the handles edit the *posed* node (its animated properties
//! replaced by their values at the current frame), so what the user sees is
//! what they change. In record mode the change and the key it makes are one
//! undoable [`Command::Group`] of the node change and a
//! [`Command::SetAnimation`].

use super::fields::FieldId;
use crate::anim::{Animation, Property, Target, TargetRef, Value};
use crate::scene::{LightKind, Node, NodeId, NodeKind};

/// The animatable property a panel field edits (`None` for names and
/// settings).
pub fn field_property(id: FieldId) -> Option<Property> {
    Some(match id {
        FieldId::Translation(_) => Property::Translation,
        FieldId::Rotation(_) => Property::Rotation,
        FieldId::Scale(_) => Property::Scale,
        FieldId::LightIntensity => Property::LightIntensity,
        FieldId::LightColor(_) => Property::LightColor,
        FieldId::LightLocation(_) => Property::LightLocation,
        FieldId::LightDirection(_) => Property::LightDirection,
        FieldId::LightCutOff => Property::LightCutOff,
        _ => return None,
    })
}

/// The value of `p` stored in a node (`None` when the node lacks it, e.g.
/// a light property on a group).
pub fn read_property(n: &Node, p: Property) -> Option<Value> {
    let t = &n.transform;
    match (p, &n.kind) {
        (Property::Translation, _) => Some(Value::Vec3(t.translation)),
        (Property::Rotation, _) => Some(Value::Rotation(t.rotation)),
        (Property::Scale, _) => Some(Value::Vec3(t.scale)),
        (Property::LightOn, NodeKind::Light(l)) => Some(Value::Bool(l.on)),
        (Property::LightIntensity, NodeKind::Light(l)) => Some(Value::Scalar(l.intensity)),
        (Property::LightColor, NodeKind::Light(l)) => Some(Value::Vec3(l.color)),
        (Property::LightLocation, NodeKind::Light(l)) => Some(Value::Vec3(l.location)),
        (Property::LightDirection, NodeKind::Light(l)) => Some(Value::Vec3(l.direction)),
        (Property::LightCutOff, NodeKind::Light(l)) => match l.kind {
            LightKind::Spot { cut_off_angle, .. } => Some(Value::Scalar(cut_off_angle)),
            _ => None,
        },
        _ => None,
    }
}

/// Writes `v` into the node's field for `p` (ignored when the types or the
/// node kind do not match).
pub fn write_property(n: &mut Node, p: Property, v: Value) {
    let t = &mut n.transform;
    match (p, v, &mut n.kind) {
        (Property::Translation, Value::Vec3(x), _) => t.translation = x,
        (Property::Rotation, Value::Rotation(q), _) => t.rotation = q,
        (Property::Scale, Value::Vec3(x), _) => t.scale = x,
        (Property::LightOn, Value::Bool(b), NodeKind::Light(l)) => l.on = b,
        (Property::LightIntensity, Value::Scalar(x), NodeKind::Light(l)) => l.intensity = x,
        (Property::LightColor, Value::Vec3(c), NodeKind::Light(l)) => l.color = c,
        (Property::LightLocation, Value::Vec3(x), NodeKind::Light(l)) => l.location = x,
        (Property::LightDirection, Value::Vec3(x), NodeKind::Light(l)) => l.direction = x,
        (Property::LightCutOff, Value::Scalar(x), NodeKind::Light(l)) => {
            if let LightKind::Spot { cut_off_angle, .. } = &mut l.kind {
                *cut_off_angle = x;
            }
        }
        _ => {}
    }
}

/// `n` with every property animated in `anim` replaced by its value at
/// `frame` (what the viewport shows).
pub fn posed(anim: &Animation, id: NodeId, n: &Node, frame: f32) -> Node {
    let mut out = n.clone();
    for t in anim.tracks_of(TargetRef::Node(id)) {
        write_property(&mut out, t.target.property, t.sample(frame));
    }
    out
}

/// The properties K keys on a node: the transform of an object, the light
/// fields of a light.
pub fn keyable(n: &Node) -> Vec<Property> {
    match &n.kind {
        NodeKind::Light(l) => {
            let mut v = vec![
                Property::LightOn,
                Property::LightIntensity,
                Property::LightColor,
            ];
            if l.kind != LightKind::Directional {
                v.push(Property::LightLocation);
            }
            if l.kind != LightKind::Point {
                v.push(Property::LightDirection);
            }
            v
        }
        _ => vec![Property::Translation, Property::Rotation, Property::Scale],
    }
}

/// Every key frame on `id`'s tracks (all tracks when `id` is `None`),
/// sorted, without duplicates.
pub fn key_frames(anim: &Animation, id: Option<NodeId>) -> Vec<f32> {
    let mut v: Vec<f32> = anim
        .tracks
        .iter()
        .filter(|t| id.is_none_or(|i| t.target.of == TargetRef::Node(i)))
        .flat_map(|t| t.keys.frames())
        .collect();
    v.sort_by(f32::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() <= crate::anim::KEY_EPS);
    v
}

/// `anim` with keys at `frame` for `props` of node `id` holding the values
/// in `n`. Errors name the property.
pub fn with_keys(
    anim: &Animation,
    id: NodeId,
    n: &Node,
    props: &[Property],
    frame: f32,
) -> Result<Animation, String> {
    let mut out = anim.clone();
    for &p in props {
        let Some(v) = read_property(n, p) else {
            continue;
        };
        let target = Target {
            of: TargetRef::Node(id),
            property: p,
        };
        out.set_key(target, frame, v)
            .map_err(|e| format!("cannot key {}: {e}", p.name()))?;
    }
    Ok(out)
}

/// A value change on an animated property made outside record mode: shown
/// (over the animation) until the frame changes or K keys it, as in
/// Blender. It is only valid while the node still holds `node` (undo takes
/// it away) and the frame is `frame`.
#[derive(Clone, Debug)]
pub struct Pending {
    pub id: NodeId,
    pub props: Vec<Property>,
    pub frame: f32,
    pub node: Box<Node>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Light, Scene};
    use glam::Vec3;

    #[test]
    fn posed_node_takes_animated_values() {
        let mut s = Scene::new();
        let id = s.add_node(None, Node::group("a"));
        let t = Target {
            of: TargetRef::Node(id),
            property: Property::Translation,
        };
        s.animation
            .set_key(t, 0.0, Value::Vec3(Vec3::ZERO))
            .unwrap();
        s.animation
            .set_key(t, 10.0, Value::Vec3(Vec3::new(10.0, 0.0, 0.0)))
            .unwrap();
        // Two keys: with TCB defaults and one-sided ends the midpoint of a
        // straight two-key segment is the midpoint of the values.
        let n = posed(&s.animation, id, s.node(id), 5.0);
        assert!((n.transform.translation.x - 5.0).abs() < 1e-4);
        assert_eq!(s.node(id).transform.translation.x, 0.0);
    }

    #[test]
    fn light_keys_cover_light_fields() {
        let n = Node::new("l", NodeKind::Light(Light::new(LightKind::Point)));
        let p = keyable(&n);
        assert!(p.contains(&Property::LightLocation));
        assert!(!p.contains(&Property::LightDirection));
        assert!(!p.contains(&Property::Translation));
    }

    #[test]
    fn key_frames_sorted_unique() {
        let mut s = Scene::new();
        let a = s.add_node(None, Node::group("a"));
        let b = s.add_node(None, Node::group("b"));
        for (id, f) in [(a, 10.0), (a, 2.0), (b, 5.0)] {
            for p in [Property::Translation, Property::Scale] {
                let t = Target {
                    of: TargetRef::Node(id),
                    property: p,
                };
                s.animation.set_key(t, f, Value::Vec3(Vec3::ONE)).unwrap();
            }
        }
        assert_eq!(key_frames(&s.animation, Some(a)), vec![2.0, 10.0]);
        assert_eq!(key_frames(&s.animation, None), vec![2.0, 5.0, 10.0]);
    }
}
