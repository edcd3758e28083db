//! The graph editor's channels: one curve per component of an animated
//! node property (translation x/y/z, a colour's r/g/b, a rotation's Euler
//! angles in degrees, a scalar, each morph target's weight), and how a
//! component's number is read from and written into a key's value.

use crate::anim::{
    Animation, Keys, Property, Target, TargetRef, Value, ValueKind, MAX_MORPH_TARGETS,
};
use crate::editor::fields::{euler_degrees, from_euler_degrees};
use crate::editor::keystrip::animated_properties;
use crate::scene::{MorphTarget, NodeId};

/// One curve of the graph: component `comp` of `node`'s `property` track.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Channel {
    pub node: NodeId,
    pub property: Property,
    pub comp: u8,
}

impl Channel {
    pub fn target(&self) -> Target {
        Target {
            of: TargetRef::Node(self.node),
            property: self.property,
        }
    }

    /// Short name: `translation.y`, `rotation.x`, `intensity`,
    /// `weights.2` (morph target 2).
    pub fn name(&self) -> String {
        let p = self.property.name();
        if self.is_weight() {
            return format!("{p}.{}", self.comp);
        }
        match components(self.property) {
            1 => p.to_string(),
            _ => {
                let letters = match self.property.kind() {
                    ValueKind::Color => ['r', 'g', 'b'],
                    _ => ['x', 'y', 'z'],
                };
                format!("{p}.{}", letters[self.comp as usize % 3])
            }
        }
    }

    /// What the channel list shows: the component first, so it survives
    /// a narrow list (`x Translation`, `Intensity`); a weight shows its
    /// morph target's name from `targets` (`nose_long`), or `target 2` as
    /// the morph panel names an unnamed one.
    pub fn label(&self, targets: &[MorphTarget]) -> String {
        let p = crate::editor::keystrip::row_name(self.property);
        if self.is_weight() {
            return match targets.get(self.comp as usize).map(|t| t.name.as_str()) {
                Some(name) if !name.is_empty() => name.to_string(),
                _ => format!("target {}", self.comp),
            };
        }
        match components(self.property) {
            1 => p.to_string(),
            _ => {
                let n = self.name();
                format!("{} {p}", n.rsplit('.').next().unwrap_or(""))
            }
        }
    }

    /// Curve colour: x/r red, y/g green, z/b blue (as the handles); one
    /// colour for scalars; morph weights cycle through six hues so that
    /// neighbouring targets differ.
    pub fn color(&self) -> u32 {
        if self.is_weight() {
            const HUES: [u32; 6] = [0xe0c050, 0x50c8d8, 0xd070d0, 0xf09050, 0x80d080, 0x9090f0];
            return HUES[self.comp as usize % HUES.len()];
        }
        if components(self.property) == 1 {
            return 0xe0c050;
        }
        [0xe85a5a, 0x6cd04c, 0x5a98f0][self.comp as usize % 3]
    }

    /// Rotation channels show Euler degrees (unwrapped along the curve).
    pub fn is_rotation(&self) -> bool {
        self.property.kind() == ValueKind::Rotation
    }

    /// One morph target's weight (component `comp` of the weights).
    pub fn is_weight(&self) -> bool {
        self.property.kind() == ValueKind::Weights
    }

    /// Parses `translation.y`, `rotation.x`, `color.g`, `intensity`,
    /// `weights.2` for node `node` (scripts).
    pub fn parse(node: NodeId, s: &str) -> Option<Channel> {
        let (p, c) = match s.rsplit_once('.') {
            Some((p, c)) => (p, Some(c)),
            None => (s, None),
        };
        let property = Property::parse(p)?;
        if property.kind() == ValueKind::Weights {
            let comp: u8 = c?.parse().ok()?;
            return ((comp as usize) < MAX_MORPH_TARGETS).then_some(Channel {
                node,
                property,
                comp,
            });
        }
        let n = components(property);
        let comp = match (c, n) {
            (None, 1) => 0,
            (Some(c), 3) => "xyzrgb".find(c.to_ascii_lowercase().as_str())? as u8 % 3,
            _ => return None,
        };
        (n > 0).then_some(Channel {
            node,
            property,
            comp,
        })
    }
}

/// How many curves a property of fixed shape has in the graph (0:
/// booleans, not drawn; morph weights: see [`curves`]).
fn components(p: Property) -> u8 {
    match p.kind() {
        ValueKind::Scalar => 1,
        ValueKind::Vec3 | ValueKind::Color | ValueKind::Rotation => 3,
        ValueKind::Bool | ValueKind::Weights => 0,
    }
}

/// How many curves node `id`'s `property` track has: morph weights one per
/// target (as many as its widest key holds), other kinds [`components`].
fn curves(anim: &Animation, id: NodeId, property: Property) -> u8 {
    if property.kind() != ValueKind::Weights {
        return components(property);
    }
    let target = Target {
        of: TargetRef::Node(id),
        property,
    };
    match anim.track(target).map(|t| &t.keys) {
        Some(Keys::Weights(keys)) => keys.iter().map(|k| k.value.len() as u8).max(),
        _ => None,
    }
    .unwrap_or(0)
}

/// The channels of node `id`'s animated properties, in property order.
pub fn channels_of(anim: &Animation, id: NodeId) -> Vec<Channel> {
    animated_properties(anim, id)
        .into_iter()
        .flat_map(|property| {
            (0..curves(anim, id, property)).map(move |comp| Channel {
                node: id,
                property,
                comp,
            })
        })
        .collect()
}

/// Component `comp` of `v` (rotations: Euler degrees, not unwrapped).
pub fn component(v: Value, comp: u8) -> Option<f32> {
    Some(match v {
        Value::Scalar(x) if comp == 0 => x,
        Value::Vec3(x) => x[comp as usize % 3],
        Value::Rotation(q) => euler_degrees(q)[comp as usize % 3],
        Value::Weights(w) => *w.as_slice().get(comp as usize)?,
        _ => return None,
    })
}

/// `v` with component `comp` set to `x`. A rotation's Euler angle is set
/// and turned back into a quaternion on the same side of the sphere as
/// the old one, so the slerp/squad path between keys keeps its direction.
pub fn with_component(v: Value, comp: u8, x: f32) -> Value {
    match v {
        Value::Scalar(_) if comp == 0 => Value::Scalar(x),
        Value::Vec3(mut a) => {
            a[comp as usize % 3] = x;
            Value::Vec3(a)
        }
        Value::Rotation(q) => {
            let mut e = euler_degrees(q);
            e[comp as usize % 3] = x;
            let r = from_euler_degrees(e);
            Value::Rotation(if r.dot(q) < 0.0 { -r } else { r })
        }
        Value::Weights(mut w) => {
            if let Some(c) = w.as_mut_slice().get_mut(comp as usize) {
                *c = x;
            }
            Value::Weights(w)
        }
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Quat, Vec3};

    #[test]
    fn names_parse_back() {
        let n = NodeId(3);
        for p in [
            Property::Translation,
            Property::LightColor,
            Property::Rotation,
        ] {
            for comp in 0..3 {
                let c = Channel {
                    node: n,
                    property: p,
                    comp,
                };
                assert_eq!(Channel::parse(n, &c.name()), Some(c), "{}", c.name());
            }
        }
        let i = Channel::parse(n, "intensity").unwrap();
        assert_eq!((i.property, i.comp), (Property::LightIntensity, 0));
        assert_eq!(Channel::parse(n, "visible"), None);
        assert_eq!(Channel::parse(n, "translation.w"), None);
    }

    #[test]
    fn rotation_component_keeps_the_quaternion_side() {
        let q = -Quat::from_rotation_y(0.5);
        let v = with_component(Value::Rotation(q), 1, 40.0);
        let Value::Rotation(r) = v else { panic!() };
        assert!(r.dot(q) > 0.0, "same hemisphere as the old key");
        assert!((component(v, 1).unwrap() - 40.0).abs() < 1e-3);
        let v = with_component(Value::Vec3(Vec3::ONE), 2, 5.0);
        assert_eq!(v, Value::Vec3(Vec3::new(1.0, 1.0, 5.0)));
    }

    #[test]
    fn weights_are_one_channel_per_target() {
        let n = NodeId(5);
        let c = Channel::parse(n, "weights.7").expect("a weight channel");
        assert_eq!((c.property, c.comp), (Property::MorphWeights, 7));
        assert_eq!(c.name(), "weights.7");
        assert_eq!(Channel::parse(n, &c.name()), Some(c));
        assert_eq!(Channel::parse(n, "weights"), None);
        assert_eq!(Channel::parse(n, "weights.x"), None);
        assert_eq!(Channel::parse(n, "weights.64"), None);
        let w = crate::anim::Weights::from_slice(&[0.1, 0.2, 0.3]).unwrap();
        let v = with_component(Value::Weights(w), 1, 0.9);
        assert_eq!(component(v, 1), Some(0.9));
        assert_eq!(component(v, 0), Some(0.1));
        assert_eq!(component(v, 3), None, "past the targets");
        assert_eq!(with_component(v, 5, 1.0), v, "past the targets: unchanged");
        let named = [MorphTarget::new("smile", vec![], vec![])];
        assert_eq!(Channel { comp: 0, ..c }.label(&named), "smile");
        assert_eq!(Channel { comp: 1, ..c }.label(&named), "target 1");
        assert_ne!(
            Channel { comp: 0, ..c }.color(),
            Channel { comp: 1, ..c }.color()
        );
    }
}
