use super::{Camera, Light, MaterialId, MeshId, NodeId, SkinId, Transform};

/// How an object is drawn (per object; the viewport may override globally).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RenderStyle {
    #[default]
    Filled,
    Lines,
    Points,
    Hidden,
}

/// A shape: shared mesh + material.
#[derive(Clone, Debug, PartialEq)]
pub struct Shape {
    pub mesh: MeshId,
    pub material: MaterialId,
}

#[derive(Clone, Debug, PartialEq)]
pub enum NodeKind {
    /// A grouping/transform node.
    Group,
    Shape(Shape),
    Light(Light),
    Camera(Camera),
}

/// One node of the tree: a transform, and what hangs on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    pub name: String,
    pub parent: Option<NodeId>,
    pub children: Vec<NodeId>,
    pub transform: Transform,
    pub visible: bool,
    pub style: RenderStyle,
    /// Width of the lines this shape draws, in pixels (Inventor's
    /// DrawStyle lineWidth); 0 = the renderer's default, 1 pixel as in
    /// OpenGL and Coin.
    pub line_width: f32,
    /// Side of the square each of its points covers, in pixels (DrawStyle
    /// pointSize); 0 = the default, 1 pixel.
    pub point_size: f32,
    pub kind: NodeKind,
    /// The skin that deforms this shape's mesh (its joints, not this node's
    /// transform, then place the vertices, as glTF §3.7.3 says).
    pub skin: Option<SkinId>,
}

impl Node {
    pub fn new(name: impl Into<String>, kind: NodeKind) -> Self {
        Node {
            name: name.into(),
            parent: None,
            children: Vec::new(),
            transform: Transform::default(),
            visible: true,
            style: RenderStyle::Filled,
            line_width: 0.0,
            point_size: 0.0,
            kind,
            skin: None,
        }
    }

    pub fn group(name: impl Into<String>) -> Self {
        Node::new(name, NodeKind::Group)
    }

    pub fn with_transform(mut self, t: Transform) -> Self {
        self.transform = t;
        self
    }

    pub fn light(&self) -> Option<&Light> {
        match &self.kind {
            NodeKind::Light(l) => Some(l),
            _ => None,
        }
    }

    pub fn camera(&self) -> Option<&Camera> {
        match &self.kind {
            NodeKind::Camera(c) => Some(c),
            _ => None,
        }
    }
}
