//! The one list of animatable properties and their value types.

use super::Weights;
use crate::scene::{MaterialId, NodeId};
use glam::{Quat, Vec3};

/// What kind of value a property holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ValueKind {
    Scalar,
    Vec3,
    /// RGB 0..1 (interpolated like a Vec3).
    Color,
    Rotation,
    Bool,
    /// Morph-target weights: a vector of N (the mesh's target count).
    Weights,
}

/// A sampled or keyed value.
///
/// `Weights` holds its vector inline (see `weights.rs`) so that `Value`
/// stays `Copy` for every caller; the enum is therefore ~270 bytes, which
/// costs nothing measurable where values are passed (a track sample writes
/// only its variant).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    Scalar(f32),
    Vec3(Vec3),
    Rotation(Quat),
    Bool(bool),
    Weights(Weights),
}

macro_rules! properties {
    ($($var:ident => $name:literal, $kind:ident, $owner:ident;)*) => {
        /// Every property a track can drive. `name()` is the suffix used in
        /// `NAME.property` on the command line and in the export note.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Property { $($var,)* }

        impl Property {
            pub const ALL: &'static [Property] = &[$(Property::$var,)*];
            pub fn name(self) -> &'static str {
                match self { $(Property::$var => $name,)* }
            }
            pub fn kind(self) -> ValueKind {
                match self { $(Property::$var => ValueKind::$kind,)* }
            }
            /// Which kind of target owns this property: "node", "light",
            /// "camera", "shape" (a shape node's mesh) or "material".
            pub fn owner(self) -> &'static str {
                match self { $(Property::$var => stringify!($owner),)* }
            }
        }
    };
}

properties! {
    Translation => "translation", Vec3, node;
    Rotation => "rotation", Rotation, node;
    Scale => "scale", Vec3, node;
    Visibility => "visible", Bool, node;
    LightOn => "on", Bool, light;
    LightIntensity => "intensity", Scalar, light;
    LightColor => "color", Color, light;
    LightLocation => "location", Vec3, light;
    LightDirection => "direction", Vec3, light;
    LightCutOff => "cutOffAngle", Scalar, light;
    LightBeamWidth => "beamWidth", Scalar, light;
    LightDropOff => "dropOffRate", Scalar, light;
    CameraPosition => "position", Vec3, camera;
    CameraOrientation => "orientation", Rotation, camera;
    CameraFov => "fieldOfView", Scalar, camera;
    Diffuse => "diffuseColor", Color, material;
    Emissive => "emissiveColor", Color, material;
    Specular => "specularColor", Color, material;
    Transparency => "transparency", Scalar, material;
    Shininess => "shininess", Scalar, material;
    MorphWeights => "weights", Weights, shape;
}

impl Property {
    /// Parses a property name (case-insensitive; a few aliases accepted).
    pub fn parse(s: &str) -> Option<Property> {
        let l = s.to_ascii_lowercase();
        let alias = match l.as_str() {
            "position" | "translation" | "pos" => None,
            "visibility" => Some(Property::Visibility),
            "colour" => Some(Property::LightColor),
            "diffuse" => Some(Property::Diffuse),
            "emissive" => Some(Property::Emissive),
            "specular" => Some(Property::Specular),
            "fov" => Some(Property::CameraFov),
            "morph" | "morphweights" => Some(Property::MorphWeights),
            _ => None,
        };
        alias.or_else(|| {
            Property::ALL
                .iter()
                .copied()
                .find(|p| p.name().eq_ignore_ascii_case(&l))
        })
    }
}

/// What a track's property belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TargetRef {
    Node(NodeId),
    Material(MaterialId),
}

/// A property of a node (transform, light or camera fields) or a material.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Target {
    pub of: TargetRef,
    pub property: Property,
}
