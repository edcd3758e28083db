//! The graph editor's channels: one curve per component of an animated
//! node property (translation x/y/z, a colour's r/g/b, a rotation's Euler
//! angles in degrees, a scalar), and how a component's number is read from
//! and written into a key's value.

use crate::anim::{Animation, Property, Target, TargetRef, Value, ValueKind};
use crate::editor::fields::{euler_degrees, from_euler_degrees};
use crate::editor::keystrip::animated_properties;
use crate::scene::NodeId;

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

    /// Short name: `translation.y`, `rotation.x`, `intensity`.
    pub fn name(&self) -> String {
        let p = self.property.name();
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
    /// a narrow list (`x Translation`, `Intensity`).
    pub fn label(&self) -> String {
        let p = crate::editor::keystrip::row_name(self.property);
        match components(self.property) {
            1 => p.to_string(),
            _ => {
                let n = self.name();
                format!("{} {p}", n.rsplit('.').next().unwrap_or(""))
            }
        }
    }

    /// Curve colour: x/r red, y/g green, z/b blue (as the handles); one
    /// colour for scalars.
    pub fn color(&self) -> u32 {
        if components(self.property) == 1 {
            return 0xe0c050;
        }
        [0xe85a5a, 0x6cd04c, 0x5a98f0][self.comp as usize % 3]
    }

    /// Rotation channels show Euler degrees (unwrapped along the curve).
    pub fn is_rotation(&self) -> bool {
        self.property.kind() == ValueKind::Rotation
    }

    /// Parses `translation.y`, `rotation.x`, `color.g`, `intensity` for
    /// node `node` (scripts).
    pub fn parse(node: NodeId, s: &str) -> Option<Channel> {
        let (p, c) = match s.rsplit_once('.') {
            Some((p, c)) => (p, Some(c)),
            None => (s, None),
        };
        let property = Property::parse(p)?;
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

/// How many curves a property has in the graph (0: booleans, not drawn).
pub fn components(p: Property) -> u8 {
    match p.kind() {
        ValueKind::Scalar => 1,
        ValueKind::Vec3 | ValueKind::Color | ValueKind::Rotation => 3,
        // Booleans are not drawn; morph weights have their own panel.
        ValueKind::Bool | ValueKind::Weights => 0,
    }
}

/// The channels of node `id`'s animated properties, in property order.
pub fn channels_of(anim: &Animation, id: NodeId) -> Vec<Channel> {
    animated_properties(anim, id)
        .into_iter()
        .flat_map(|property| {
            (0..components(property)).map(move |comp| Channel {
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
}
