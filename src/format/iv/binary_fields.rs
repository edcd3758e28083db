//! The field types of Inventor's built-in nodes, which a binary file does
//! not spell out: a value is raw words whose meaning depends on the field's
//! type, so the binary reader must know it (nodes that are not built in
//! carry their own field descriptions). Types as the Inventor Mentor's
//! file-format chapter and the node reference list them (Coin's node
//! headers agree); nodes this reader draws nothing for are listed too, so
//! a file using them can still be read past them.

/// How one field's value is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldType {
    /// `n` 32-bit floats.
    Floats(u8),
    /// `n` 32-bit integers.
    Ints(u8),
    /// 64-bit float (SFTime, SFDouble).
    Double,
    Bool,
    /// A name (SFEnum, SFName) stored as a string.
    Name,
    /// Names until an empty one (SFBitMask).
    BitMask,
    String,
    Node,
    Image,
    /// A count, then that many values of the single-value type.
    Multi(Single),
}

/// The single-value types a multiple-value field holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Single {
    Floats(u8),
    Ints(u8),
    Double,
    Bool,
    Name,
    String,
    Node,
}

impl FieldType {
    /// The type named `name` in a binary file's field descriptions
    /// (`SFVec3f`, `MFInt32`…).
    pub fn from_name(name: &str) -> Option<FieldType> {
        let (multi, rest) = match name.as_bytes().get(..2)? {
            b"SF" => (false, &name[2..]),
            b"MF" => (true, &name[2..]),
            _ => return None,
        };
        let one = match rest {
            "Float" => Single::Floats(1),
            "Vec2f" => Single::Floats(2),
            "Vec3f" | "Color" => Single::Floats(3),
            "Vec4f" | "Rotation" | "Plane" => Single::Floats(4),
            "Matrix" => Single::Floats(16),
            "Int32" | "UInt32" | "Short" | "UShort" | "Long" | "ULong" => Single::Ints(1),
            "Vec2s" | "Vec2i32" => Single::Ints(2),
            "Vec3s" | "Vec3i32" => Single::Ints(3),
            "Time" | "Double" => Single::Double,
            "Bool" => Single::Bool,
            "Enum" | "Name" => Single::Name,
            "String" => Single::String,
            "Node" => Single::Node,
            "BitMask" if !multi => return Some(FieldType::BitMask),
            "Image" if !multi => return Some(FieldType::Image),
            "Trigger" if !multi => return Some(FieldType::Ints(0)),
            _ => return None,
        };
        Some(if multi {
            FieldType::Multi(one)
        } else {
            match one {
                Single::Floats(n) => FieldType::Floats(n),
                Single::Ints(n) => FieldType::Ints(n),
                Single::Double => FieldType::Double,
                Single::Bool => FieldType::Bool,
                Single::Name => FieldType::Name,
                Single::String => FieldType::String,
                Single::Node => FieldType::Node,
            }
        })
    }
}

use FieldType::{BitMask, Image, String as Str};
use FieldType::{Bool, Double, Floats, Ints, Multi, Name, Node};

const MF_FLOAT: FieldType = Multi(Single::Floats(1));
const MF_VEC2: FieldType = Multi(Single::Floats(2));
const MF_VEC3: FieldType = Multi(Single::Floats(3));
const MF_INT: FieldType = Multi(Single::Ints(1));
const MF_STRING: FieldType = Multi(Single::String);
const VEC3: FieldType = Floats(3);
const ROTATION: FieldType = Floats(4);
const FLOAT: FieldType = Floats(1);
const INT: FieldType = Ints(1);

const SEPARATOR: &[(&str, FieldType)] = &[
    ("renderCaching", Name),
    ("boundingBoxCaching", Name),
    ("renderCulling", Name),
    ("pickCulling", Name),
];
const CAMERA: &[(&str, FieldType)] = &[
    ("viewportMapping", Name),
    ("position", VEC3),
    ("orientation", ROTATION),
    ("aspectRatio", FLOAT),
    ("nearDistance", FLOAT),
    ("farDistance", FLOAT),
    ("focalDistance", FLOAT),
];
const LIGHT: &[(&str, FieldType)] = &[("on", Bool), ("intensity", FLOAT), ("color", VEC3)];
const VERTEX_SHAPE: &[(&str, FieldType)] = &[("vertexProperty", Node)];
const INDEXED: &[(&str, FieldType)] = &[
    ("coordIndex", MF_INT),
    ("materialIndex", MF_INT),
    ("normalIndex", MF_INT),
    ("textureCoordIndex", MF_INT),
];
const NON_INDEXED: &[(&str, FieldType)] = &[("startIndex", INT)];
const ANIMATED: &[(&str, FieldType)] = &[("speed", FLOAT), ("on", Bool)];
const NONE: &[(&str, FieldType)] = &[];

/// Whether `kind` is a group (its children follow its fields).
pub fn is_group(kind: &str) -> bool {
    matches!(
        kind,
        "Group"
            | "Separator"
            | "Switch"
            | "TransformSeparator"
            | "LOD"
            | "LevelOfDetail"
            | "Array"
            | "MultipleCopy"
            | "Annotation"
            | "Selection"
            | "WWWAnchor"
            | "Blinker"
            | "LocateHighlight"
            | "PathSwitch"
    )
}

/// The type of field `field` of built-in node `kind`, when known.
pub fn field_type(kind: &str, field: &str) -> Option<FieldType> {
    let (own, inherited) = fields(kind)?;
    own.iter()
        .chain(inherited)
        .find(|(n, _)| *n == field)
        .map(|&(_, t)| t)
}

/// A node type's fields: (name, type) pairs.
type Fields = &'static [(&'static str, FieldType)];

/// A built-in node's own fields and those it inherits.
fn fields(kind: &str) -> Option<(Fields, Fields)> {
    Some(match kind {
        "Group"
        | "TransformSeparator"
        | "Shape"
        | "TextureCoordinateDefault"
        | "TextureCoordinateEnvironment"
        | "TextureCoordinateSphere"
        | "TextureCoordinateCylinder"
        | "TextureCoordinateCube" => (NONE, NONE),
        "Separator" | "Annotation" => (SEPARATOR, NONE),
        "Selection" => (&[("policy", Name)], SEPARATOR),
        "LocateHighlight" => (
            &[("color", VEC3), ("style", Name), ("mode", Name)],
            SEPARATOR,
        ),
        "WWWAnchor" => (
            &[
                ("name", Str),
                ("description", Str),
                ("map", Name),
                ("color", VEC3),
                ("style", Name),
                ("mode", Name),
            ],
            SEPARATOR,
        ),
        "Switch" | "PathSwitch" => (&[("whichChild", INT)], NONE),
        "Blinker" => (&[("whichChild", INT)], ANIMATED),
        "LOD" => (&[("range", MF_FLOAT), ("center", VEC3)], NONE),
        "LevelOfDetail" => (&[("screenArea", MF_FLOAT)], NONE),
        "Array" => (
            &[
                ("origin", Name),
                ("numElements1", INT),
                ("numElements2", INT),
                ("numElements3", INT),
                ("separation1", VEC3),
                ("separation2", VEC3),
                ("separation3", VEC3),
            ],
            NONE,
        ),
        "MultipleCopy" => (&[("matrix", Multi(Single::Floats(16)))], NONE),
        "Coordinate3" => (&[("point", MF_VEC3)], NONE),
        "Coordinate4" => (&[("point", Multi(Single::Floats(4)))], NONE),
        "Normal" => (&[("vector", MF_VEC3)], NONE),
        "NormalBinding" | "MaterialBinding" | "TextureCoordinateBinding" => {
            (&[("value", Name)], NONE)
        }
        "Material" => (
            &[
                ("ambientColor", MF_VEC3),
                ("diffuseColor", MF_VEC3),
                ("specularColor", MF_VEC3),
                ("emissiveColor", MF_VEC3),
                ("shininess", MF_FLOAT),
                ("transparency", MF_FLOAT),
            ],
            NONE,
        ),
        "BaseColor" => (&[("rgb", MF_VEC3)], NONE),
        "PackedColor" => (&[("orderedRGBA", MF_INT)], NONE),
        "LightModel" => (&[("model", Name)], NONE),
        "DrawStyle" => (
            &[
                ("style", Name),
                ("pointSize", FLOAT),
                ("lineWidth", FLOAT),
                ("linePattern", INT),
            ],
            NONE,
        ),
        "ShapeHints" => (
            &[
                ("vertexOrdering", Name),
                ("shapeType", Name),
                ("faceType", Name),
                ("creaseAngle", FLOAT),
            ],
            NONE,
        ),
        "Complexity" => (
            &[("type", Name), ("value", FLOAT), ("textureQuality", FLOAT)],
            NONE,
        ),
        "Environment" => (
            &[
                ("ambientIntensity", FLOAT),
                ("ambientColor", VEC3),
                ("attenuation", VEC3),
                ("fogType", Name),
                ("fogColor", VEC3),
                ("fogVisibility", FLOAT),
            ],
            NONE,
        ),
        "Transform" => (
            &[
                ("translation", VEC3),
                ("rotation", ROTATION),
                ("scaleFactor", VEC3),
                ("scaleOrientation", ROTATION),
                ("center", VEC3),
            ],
            NONE,
        ),
        "Translation" => (&[("translation", VEC3)], NONE),
        "Rotation" => (&[("rotation", ROTATION)], NONE),
        "RotationXYZ" => (&[("axis", Name), ("angle", FLOAT)], NONE),
        "Scale" => (&[("scaleFactor", VEC3)], NONE),
        "MatrixTransform" => (&[("matrix", Floats(16))], NONE),
        "ResetTransform" => (&[("whatToReset", BitMask)], NONE),
        "Units" => (&[("units", Name)], NONE),
        "Rotor" => (&[("rotation", ROTATION)], ANIMATED),
        "Pendulum" => (
            &[
                ("rotation", ROTATION),
                ("rotation0", ROTATION),
                ("rotation1", ROTATION),
            ],
            ANIMATED,
        ),
        "Shuttle" => (
            &[
                ("translation", VEC3),
                ("translation0", VEC3),
                ("translation1", VEC3),
            ],
            ANIMATED,
        ),
        "Cube" => (
            &[("width", FLOAT), ("height", FLOAT), ("depth", FLOAT)],
            NONE,
        ),
        "Sphere" => (&[("radius", FLOAT)], NONE),
        "Cone" => (
            &[
                ("parts", BitMask),
                ("bottomRadius", FLOAT),
                ("height", FLOAT),
            ],
            NONE,
        ),
        "Cylinder" => (
            &[("parts", BitMask), ("radius", FLOAT), ("height", FLOAT)],
            NONE,
        ),
        "IndexedFaceSet" | "IndexedLineSet" | "IndexedTriangleStripSet" => (INDEXED, VERTEX_SHAPE),
        "FaceSet" | "LineSet" | "TriangleStripSet" => (&[("numVertices", MF_INT)], NON_INDEXED),
        "PointSet" => (&[("numPoints", INT)], NON_INDEXED),
        "QuadMesh" => (
            &[
                ("verticesPerColumn", INT),
                ("verticesPerRow", INT),
                ("vertexProperty", Node),
            ],
            NON_INDEXED,
        ),
        "VertexProperty" => (
            &[
                ("vertex", MF_VEC3),
                ("texCoord", MF_VEC2),
                ("normal", MF_VEC3),
                ("normalBinding", Name),
                ("orderedRGBA", MF_INT),
                ("materialBinding", Name),
            ],
            NONE,
        ),
        "Info" => (&[("string", Str)], NONE),
        "Label" => (&[("label", Name)], NONE),
        "PerspectiveCamera" => (&[("heightAngle", FLOAT)], CAMERA),
        "OrthographicCamera" => (&[("height", FLOAT)], CAMERA),
        "DirectionalLight" => (&[("direction", VEC3)], LIGHT),
        "PointLight" => (&[("location", VEC3)], LIGHT),
        "SpotLight" => (
            &[
                ("location", VEC3),
                ("direction", VEC3),
                ("dropOffRate", FLOAT),
                ("cutOffAngle", FLOAT),
            ],
            LIGHT,
        ),
        "Texture2" => (
            &[
                ("filename", Str),
                ("image", Image),
                ("wrapS", Name),
                ("wrapT", Name),
                ("model", Name),
                ("blendColor", VEC3),
            ],
            NONE,
        ),
        "Texture2Transform" => (
            &[
                ("translation", Floats(2)),
                ("rotation", FLOAT),
                ("scaleFactor", Floats(2)),
                ("center", Floats(2)),
            ],
            NONE,
        ),
        "TextureCoordinate2" | "ProfileCoordinate2" => (&[("point", MF_VEC2)], NONE),
        "TextureCoordinatePlane" => (&[("directionS", VEC3), ("directionT", VEC3)], NONE),
        "Font" => (&[("name", Name), ("size", FLOAT)], NONE),
        "FontStyle" => (
            &[
                ("name", Name),
                ("size", FLOAT),
                ("family", Name),
                ("style", BitMask),
            ],
            NONE,
        ),
        "Text2" => (
            &[
                ("string", MF_STRING),
                ("spacing", FLOAT),
                ("justification", Name),
            ],
            NONE,
        ),
        "Text3" => (
            &[
                ("string", MF_STRING),
                ("spacing", FLOAT),
                ("justification", Name),
                ("parts", BitMask),
            ],
            NONE,
        ),
        "AsciiText" => (
            &[
                ("string", MF_STRING),
                ("spacing", FLOAT),
                ("justification", Name),
                ("width", MF_FLOAT),
            ],
            NONE,
        ),
        "LinearProfile" => (&[("index", MF_INT), ("linkage", Name)], NONE),
        "PickStyle" => (&[("style", Name)], NONE),
        "File" => (&[("name", Str)], NONE),
        "WWWInline" => (
            &[
                ("name", Str),
                ("bboxCenter", VEC3),
                ("bboxSize", VEC3),
                ("alternateRep", Node),
            ],
            NONE,
        ),
        "ElapsedTime" => (
            &[
                ("timeIn", Double),
                ("speed", FLOAT),
                ("on", Bool),
                ("pause", Bool),
            ],
            NONE,
        ),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inherited_fields_and_type_names_resolve() {
        assert_eq!(field_type("Coordinate3", "point"), Some(MF_VEC3));
        assert_eq!(field_type("SpotLight", "intensity"), Some(FLOAT));
        assert_eq!(field_type("IndexedFaceSet", "vertexProperty"), Some(Node));
        assert_eq!(field_type("Coordinate3", "vector"), None);
        assert_eq!(field_type("NoSuchNode", "point"), None);
        assert_eq!(FieldType::from_name("MFVec3f"), Some(MF_VEC3));
        assert_eq!(FieldType::from_name("SFBitMask"), Some(BitMask));
        assert_eq!(FieldType::from_name("SFTime"), Some(Double));
        assert_eq!(FieldType::from_name("XFVec3f"), None);
    }
}
