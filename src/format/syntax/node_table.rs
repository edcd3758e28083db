//! Every built-in VRML97 node's interface: each field and event with its
//! access (field, exposedField, eventIn, eventOut) and type, written from
//! the node reference of ISO/IEC 14772-1:1997 §6 (§6.2 Anchor … §6.54
//! WorldInfo). What ROUTE and IS checks (`events.rs`) look fields up in.
//!
//! An exposedField `x` also has the eventIn `set_x` and the eventOut
//! `x_changed` (§4.7: an exposedField is a field with an implicit eventIn
//! and eventOut); those are not listed here but derived in `events.rs`.
//! Script's own fields are `url`, `directOutput` and `mustEvaluate`; its
//! declared interface comes from the file.

/// How a field or event of a node may be used (§4.7, §5.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// `field` (X3D `initializeOnly`): a value, no events.
    Field,
    /// `exposedField` (X3D `inputOutput`): a value with set_/_changed events.
    Exposed,
    /// `eventIn` (X3D `inputOnly`).
    In,
    /// `eventOut` (X3D `outputOnly`).
    Out,
}

impl Access {
    /// The access an interface declaration keyword names (VRML97 or X3D
    /// spelling).
    pub fn from_keyword(kw: &str) -> Option<Access> {
        Some(match kw {
            "field" | "initializeOnly" => Access::Field,
            "exposedField" | "inputOutput" => Access::Exposed,
            "eventIn" | "inputOnly" => Access::In,
            "eventOut" | "outputOnly" => Access::Out,
            _ => return None,
        })
    }

    /// The VRML97 keyword, for messages.
    pub fn keyword(self) -> &'static str {
        match self {
            Access::Field => "field",
            Access::Exposed => "exposedField",
            Access::In => "eventIn",
            Access::Out => "eventOut",
        }
    }

    /// The keyword with its article ("a field", "an eventIn").
    pub fn with_article(self) -> &'static str {
        match self {
            Access::Field => "a field",
            Access::Exposed => "an exposedField",
            Access::In => "an eventIn",
            Access::Out => "an eventOut",
        }
    }
}

use Access::{Exposed as X, Field as F, In as I, Out as O};

/// One field or event: access, type, name.
pub type Entry = (Access, &'static str, &'static str);

const GROUP_EVENTS: [Entry; 5] = [
    (I, "MFNode", "addChildren"),
    (I, "MFNode", "removeChildren"),
    (X, "MFNode", "children"),
    (F, "SFVec3f", "bboxCenter"),
    (F, "SFVec3f", "bboxSize"),
];

/// The built-in nodes, in the order of §6.
const NODES: &[(&str, &[Entry])] = &[
    (
        "Anchor",
        &[
            GROUP_EVENTS[0],
            GROUP_EVENTS[1],
            GROUP_EVENTS[2],
            GROUP_EVENTS[3],
            GROUP_EVENTS[4],
            (X, "SFString", "description"),
            (X, "MFString", "parameter"),
            (X, "MFString", "url"),
        ],
    ),
    (
        "Appearance",
        &[
            (X, "SFNode", "material"),
            (X, "SFNode", "texture"),
            (X, "SFNode", "textureTransform"),
        ],
    ),
    (
        "AudioClip",
        &[
            (X, "SFString", "description"),
            (X, "SFBool", "loop"),
            (X, "SFFloat", "pitch"),
            (X, "SFTime", "startTime"),
            (X, "SFTime", "stopTime"),
            (X, "MFString", "url"),
            (O, "SFTime", "duration_changed"),
            (O, "SFBool", "isActive"),
        ],
    ),
    (
        "Background",
        &[
            (I, "SFBool", "set_bind"),
            (X, "MFFloat", "groundAngle"),
            (X, "MFColor", "groundColor"),
            (X, "MFString", "backUrl"),
            (X, "MFString", "bottomUrl"),
            (X, "MFString", "frontUrl"),
            (X, "MFString", "leftUrl"),
            (X, "MFString", "rightUrl"),
            (X, "MFString", "topUrl"),
            (X, "MFFloat", "skyAngle"),
            (X, "MFColor", "skyColor"),
            (O, "SFBool", "isBound"),
        ],
    ),
    (
        "Billboard",
        &[
            GROUP_EVENTS[0],
            GROUP_EVENTS[1],
            GROUP_EVENTS[2],
            GROUP_EVENTS[3],
            GROUP_EVENTS[4],
            (X, "SFVec3f", "axisOfRotation"),
        ],
    ),
    ("Box", &[(F, "SFVec3f", "size")]),
    (
        "Collision",
        &[
            GROUP_EVENTS[0],
            GROUP_EVENTS[1],
            GROUP_EVENTS[2],
            GROUP_EVENTS[3],
            GROUP_EVENTS[4],
            (X, "SFBool", "collide"),
            (F, "SFNode", "proxy"),
            (O, "SFTime", "collideTime"),
        ],
    ),
    ("Color", &[(X, "MFColor", "color")]),
    (
        "ColorInterpolator",
        &[
            (I, "SFFloat", "set_fraction"),
            (X, "MFFloat", "key"),
            (X, "MFColor", "keyValue"),
            (O, "SFColor", "value_changed"),
        ],
    ),
    (
        "Cone",
        &[
            (F, "SFFloat", "bottomRadius"),
            (F, "SFFloat", "height"),
            (F, "SFBool", "side"),
            (F, "SFBool", "bottom"),
        ],
    ),
    ("Coordinate", &[(X, "MFVec3f", "point")]),
    (
        "CoordinateInterpolator",
        &[
            (I, "SFFloat", "set_fraction"),
            (X, "MFFloat", "key"),
            (X, "MFVec3f", "keyValue"),
            (O, "MFVec3f", "value_changed"),
        ],
    ),
    (
        "Cylinder",
        &[
            (F, "SFBool", "bottom"),
            (F, "SFFloat", "height"),
            (F, "SFFloat", "radius"),
            (F, "SFBool", "side"),
            (F, "SFBool", "top"),
        ],
    ),
    (
        "CylinderSensor",
        &[
            (X, "SFBool", "autoOffset"),
            (X, "SFFloat", "diskAngle"),
            (X, "SFBool", "enabled"),
            (X, "SFFloat", "maxAngle"),
            (X, "SFFloat", "minAngle"),
            (X, "SFFloat", "offset"),
            (O, "SFBool", "isActive"),
            (O, "SFRotation", "rotation_changed"),
            (O, "SFVec3f", "trackPoint_changed"),
        ],
    ),
    (
        "DirectionalLight",
        &[
            (X, "SFFloat", "ambientIntensity"),
            (X, "SFColor", "color"),
            (X, "SFVec3f", "direction"),
            (X, "SFFloat", "intensity"),
            (X, "SFBool", "on"),
        ],
    ),
    (
        "ElevationGrid",
        &[
            (I, "MFFloat", "set_height"),
            (X, "SFNode", "color"),
            (X, "SFNode", "normal"),
            (X, "SFNode", "texCoord"),
            (F, "MFFloat", "height"),
            (F, "SFBool", "ccw"),
            (F, "SFBool", "colorPerVertex"),
            (F, "SFFloat", "creaseAngle"),
            (F, "SFBool", "normalPerVertex"),
            (F, "SFBool", "solid"),
            (F, "SFInt32", "xDimension"),
            (F, "SFFloat", "xSpacing"),
            (F, "SFInt32", "zDimension"),
            (F, "SFFloat", "zSpacing"),
        ],
    ),
    (
        "Extrusion",
        &[
            (I, "MFVec2f", "set_crossSection"),
            (I, "MFRotation", "set_orientation"),
            (I, "MFVec2f", "set_scale"),
            (I, "MFVec3f", "set_spine"),
            (F, "SFBool", "beginCap"),
            (F, "SFBool", "ccw"),
            (F, "SFBool", "convex"),
            (F, "SFFloat", "creaseAngle"),
            (F, "MFVec2f", "crossSection"),
            (F, "SFBool", "endCap"),
            (F, "MFRotation", "orientation"),
            (F, "MFVec2f", "scale"),
            (F, "SFBool", "solid"),
            (F, "MFVec3f", "spine"),
        ],
    ),
    (
        "Fog",
        &[
            (X, "SFColor", "color"),
            (X, "SFString", "fogType"),
            (X, "SFFloat", "visibilityRange"),
            (I, "SFBool", "set_bind"),
            (O, "SFBool", "isBound"),
        ],
    ),
    (
        "FontStyle",
        &[
            (F, "MFString", "family"),
            (F, "SFBool", "horizontal"),
            (F, "MFString", "justify"),
            (F, "SFString", "language"),
            (F, "SFBool", "leftToRight"),
            (F, "SFFloat", "size"),
            (F, "SFFloat", "spacing"),
            (F, "SFString", "style"),
            (F, "SFBool", "topToBottom"),
        ],
    ),
    ("Group", &GROUP_EVENTS),
    (
        "ImageTexture",
        &[
            (X, "MFString", "url"),
            (F, "SFBool", "repeatS"),
            (F, "SFBool", "repeatT"),
        ],
    ),
    (
        "IndexedFaceSet",
        &[
            (I, "MFInt32", "set_colorIndex"),
            (I, "MFInt32", "set_coordIndex"),
            (I, "MFInt32", "set_normalIndex"),
            (I, "MFInt32", "set_texCoordIndex"),
            (X, "SFNode", "color"),
            (X, "SFNode", "coord"),
            (X, "SFNode", "normal"),
            (X, "SFNode", "texCoord"),
            (F, "SFBool", "ccw"),
            (F, "MFInt32", "colorIndex"),
            (F, "SFBool", "colorPerVertex"),
            (F, "SFBool", "convex"),
            (F, "MFInt32", "coordIndex"),
            (F, "SFFloat", "creaseAngle"),
            (F, "MFInt32", "normalIndex"),
            (F, "SFBool", "normalPerVertex"),
            (F, "SFBool", "solid"),
            (F, "MFInt32", "texCoordIndex"),
        ],
    ),
    (
        "IndexedLineSet",
        &[
            (I, "MFInt32", "set_colorIndex"),
            (I, "MFInt32", "set_coordIndex"),
            (X, "SFNode", "color"),
            (X, "SFNode", "coord"),
            (F, "MFInt32", "colorIndex"),
            (F, "SFBool", "colorPerVertex"),
            (F, "MFInt32", "coordIndex"),
        ],
    ),
    (
        "Inline",
        &[
            (X, "MFString", "url"),
            (F, "SFVec3f", "bboxCenter"),
            (F, "SFVec3f", "bboxSize"),
        ],
    ),
    (
        "LOD",
        &[
            (X, "MFNode", "level"),
            (F, "SFVec3f", "center"),
            (F, "MFFloat", "range"),
        ],
    ),
    (
        "Material",
        &[
            (X, "SFFloat", "ambientIntensity"),
            (X, "SFColor", "diffuseColor"),
            (X, "SFColor", "emissiveColor"),
            (X, "SFFloat", "shininess"),
            (X, "SFColor", "specularColor"),
            (X, "SFFloat", "transparency"),
        ],
    ),
    (
        "MovieTexture",
        &[
            (X, "SFBool", "loop"),
            (X, "SFFloat", "speed"),
            (X, "SFTime", "startTime"),
            (X, "SFTime", "stopTime"),
            (X, "MFString", "url"),
            (F, "SFBool", "repeatS"),
            (F, "SFBool", "repeatT"),
            (O, "SFTime", "duration_changed"),
            (O, "SFBool", "isActive"),
        ],
    ),
    (
        "NavigationInfo",
        &[
            (I, "SFBool", "set_bind"),
            (X, "MFFloat", "avatarSize"),
            (X, "SFBool", "headlight"),
            (X, "SFFloat", "speed"),
            (X, "MFString", "type"),
            (X, "SFFloat", "visibilityLimit"),
            (O, "SFBool", "isBound"),
        ],
    ),
    ("Normal", &[(X, "MFVec3f", "vector")]),
    (
        "NormalInterpolator",
        &[
            (I, "SFFloat", "set_fraction"),
            (X, "MFFloat", "key"),
            (X, "MFVec3f", "keyValue"),
            (O, "MFVec3f", "value_changed"),
        ],
    ),
    (
        "OrientationInterpolator",
        &[
            (I, "SFFloat", "set_fraction"),
            (X, "MFFloat", "key"),
            (X, "MFRotation", "keyValue"),
            (O, "SFRotation", "value_changed"),
        ],
    ),
    (
        "PixelTexture",
        &[
            (X, "SFImage", "image"),
            (F, "SFBool", "repeatS"),
            (F, "SFBool", "repeatT"),
        ],
    ),
    (
        "PlaneSensor",
        &[
            (X, "SFBool", "autoOffset"),
            (X, "SFBool", "enabled"),
            (X, "SFVec2f", "maxPosition"),
            (X, "SFVec2f", "minPosition"),
            (X, "SFVec3f", "offset"),
            (O, "SFBool", "isActive"),
            (O, "SFVec3f", "trackPoint_changed"),
            (O, "SFVec3f", "translation_changed"),
        ],
    ),
    (
        "PointLight",
        &[
            (X, "SFFloat", "ambientIntensity"),
            (X, "SFVec3f", "attenuation"),
            (X, "SFColor", "color"),
            (X, "SFFloat", "intensity"),
            (X, "SFVec3f", "location"),
            (X, "SFBool", "on"),
            (X, "SFFloat", "radius"),
        ],
    ),
    (
        "PointSet",
        &[(X, "SFNode", "color"), (X, "SFNode", "coord")],
    ),
    (
        "PositionInterpolator",
        &[
            (I, "SFFloat", "set_fraction"),
            (X, "MFFloat", "key"),
            (X, "MFVec3f", "keyValue"),
            (O, "SFVec3f", "value_changed"),
        ],
    ),
    (
        "ProximitySensor",
        &[
            (X, "SFVec3f", "center"),
            (X, "SFVec3f", "size"),
            (X, "SFBool", "enabled"),
            (O, "SFBool", "isActive"),
            (O, "SFVec3f", "position_changed"),
            (O, "SFRotation", "orientation_changed"),
            (O, "SFTime", "enterTime"),
            (O, "SFTime", "exitTime"),
        ],
    ),
    (
        "ScalarInterpolator",
        &[
            (I, "SFFloat", "set_fraction"),
            (X, "MFFloat", "key"),
            (X, "MFFloat", "keyValue"),
            (O, "SFFloat", "value_changed"),
        ],
    ),
    (
        "Script",
        &[
            (X, "MFString", "url"),
            (F, "SFBool", "directOutput"),
            (F, "SFBool", "mustEvaluate"),
        ],
    ),
    (
        "Shape",
        &[(X, "SFNode", "appearance"), (X, "SFNode", "geometry")],
    ),
    (
        "Sound",
        &[
            (X, "SFVec3f", "direction"),
            (X, "SFFloat", "intensity"),
            (X, "SFVec3f", "location"),
            (X, "SFFloat", "maxBack"),
            (X, "SFFloat", "maxFront"),
            (X, "SFFloat", "minBack"),
            (X, "SFFloat", "minFront"),
            (X, "SFFloat", "priority"),
            (X, "SFNode", "source"),
            (F, "SFBool", "spatialize"),
        ],
    ),
    ("Sphere", &[(F, "SFFloat", "radius")]),
    (
        "SphereSensor",
        &[
            (X, "SFBool", "autoOffset"),
            (X, "SFBool", "enabled"),
            (X, "SFRotation", "offset"),
            (O, "SFBool", "isActive"),
            (O, "SFRotation", "rotation_changed"),
            (O, "SFVec3f", "trackPoint_changed"),
        ],
    ),
    (
        "SpotLight",
        &[
            (X, "SFFloat", "ambientIntensity"),
            (X, "SFVec3f", "attenuation"),
            (X, "SFFloat", "beamWidth"),
            (X, "SFColor", "color"),
            (X, "SFFloat", "cutOffAngle"),
            (X, "SFVec3f", "direction"),
            (X, "SFFloat", "intensity"),
            (X, "SFVec3f", "location"),
            (X, "SFBool", "on"),
            (X, "SFFloat", "radius"),
        ],
    ),
    (
        "Switch",
        &[(X, "MFNode", "choice"), (X, "SFInt32", "whichChoice")],
    ),
    (
        "Text",
        &[
            (X, "MFString", "string"),
            (X, "SFNode", "fontStyle"),
            (X, "MFFloat", "length"),
            (X, "SFFloat", "maxExtent"),
        ],
    ),
    ("TextureCoordinate", &[(X, "MFVec2f", "point")]),
    (
        "TextureTransform",
        &[
            (X, "SFVec2f", "center"),
            (X, "SFFloat", "rotation"),
            (X, "SFVec2f", "scale"),
            (X, "SFVec2f", "translation"),
        ],
    ),
    (
        "TimeSensor",
        &[
            (X, "SFTime", "cycleInterval"),
            (X, "SFBool", "enabled"),
            (X, "SFBool", "loop"),
            (X, "SFTime", "startTime"),
            (X, "SFTime", "stopTime"),
            (O, "SFTime", "cycleTime"),
            (O, "SFFloat", "fraction_changed"),
            (O, "SFBool", "isActive"),
            (O, "SFTime", "time"),
        ],
    ),
    (
        "TouchSensor",
        &[
            (X, "SFBool", "enabled"),
            (O, "SFVec3f", "hitNormal_changed"),
            (O, "SFVec3f", "hitPoint_changed"),
            (O, "SFVec2f", "hitTexCoord_changed"),
            (O, "SFBool", "isActive"),
            (O, "SFBool", "isOver"),
            (O, "SFTime", "touchTime"),
        ],
    ),
    (
        "Transform",
        &[
            GROUP_EVENTS[0],
            GROUP_EVENTS[1],
            GROUP_EVENTS[2],
            GROUP_EVENTS[3],
            GROUP_EVENTS[4],
            (X, "SFVec3f", "center"),
            (X, "SFRotation", "rotation"),
            (X, "SFVec3f", "scale"),
            (X, "SFRotation", "scaleOrientation"),
            (X, "SFVec3f", "translation"),
        ],
    ),
    (
        "Viewpoint",
        &[
            (I, "SFBool", "set_bind"),
            (X, "SFFloat", "fieldOfView"),
            (X, "SFBool", "jump"),
            (X, "SFRotation", "orientation"),
            (X, "SFVec3f", "position"),
            (F, "SFString", "description"),
            (O, "SFTime", "bindTime"),
            (O, "SFBool", "isBound"),
        ],
    ),
    (
        "VisibilitySensor",
        &[
            (X, "SFVec3f", "center"),
            (X, "SFBool", "enabled"),
            (X, "SFVec3f", "size"),
            (O, "SFTime", "enterTime"),
            (O, "SFTime", "exitTime"),
            (O, "SFBool", "isActive"),
        ],
    ),
    (
        "WorldInfo",
        &[(F, "MFString", "info"), (F, "SFString", "title")],
    ),
];

/// The interface of built-in VRML97 node `kind`, or `None` for any other
/// name (PROTOs, X3D or vendor nodes).
pub fn builtin(kind: &str) -> Option<&'static [Entry]> {
    NODES.iter().find(|(k, _)| *k == kind).map(|(_, e)| *e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_54_nodes_of_section_6_with_unique_fields() {
        assert_eq!(NODES.len(), 54);
        for (kind, entries) in NODES {
            for (i, e) in entries.iter().enumerate() {
                assert!(
                    !entries[..i].iter().any(|d| d.2 == e.2),
                    "{kind}.{} twice",
                    e.2
                );
                assert!(
                    e.1.starts_with("SF") || e.1.starts_with("MF"),
                    "{kind}.{}",
                    e.2
                );
            }
        }
        let t = builtin("TimeSensor").unwrap();
        assert!(t.contains(&(O, "SFFloat", "fraction_changed")));
        assert!(builtin("Humanoid").is_none());
    }
}
