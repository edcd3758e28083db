use super::{Morphs, SkinWeights, TextSpec};
use glam::{Vec2, Vec3};

/// Geometry ready to draw: indexed triangles, lines and points over one
/// vertex array. Readers unweld vertices where normals or colours differ per
/// face, so every attribute here is per vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub name: String,
    pub positions: Vec<Vec3>,
    /// Per-vertex unit normals; same length as `positions` (may be empty for
    /// meshes that only hold lines/points).
    pub normals: Vec<Vec3>,
    /// Per-vertex colours (replace the material's diffuse), empty if none.
    pub colors: Vec<Vec3>,
    /// Per-vertex texture coordinates (s right, t up, as VRML), same length
    /// as `positions`, or empty when the mesh has none.
    pub texcoords: Vec<Vec2>,
    /// Counter-clockwise triangles (front faces CCW seen from outside).
    pub triangles: Vec<[u32; 3]>,
    pub lines: Vec<[u32; 2]>,
    pub points: Vec<u32>,
    /// The polygons' outline edges, what a face set drawn as lines shows
    /// (Inventor's DrawStyle LINES draws each polygon's boundary, not the
    /// diagonals triangulation adds). Empty when the triangles' own edges
    /// are the outline (every face a triangle).
    pub edges: Vec<[u32; 2]>,
    /// Solid shapes are back-face culled; others are lit on both sides.
    pub solid: bool,
    /// Morph targets and their default weights (animated per shape as
    /// `NAME.weights`); `None` for a rigid mesh.
    pub morph: Option<Box<Morphs>>,
    /// Joint influences per vertex when the mesh is skinned (the skin itself
    /// is `Node::skin` of the shape); `None` otherwise.
    pub skin_weights: Option<Box<SkinWeights>>,
    /// The strings and font style this mesh was built from, for a Text
    /// node (VRML97 Text, VRML 1.0 AsciiText, Inventor Text2/Text3):
    /// writers write the node again instead of the triangles.
    pub text: Option<Box<TextSpec>>,
}

impl Mesh {
    /// Whether drawing this mesh needs a deformation pass (morph or skin).
    pub fn deforms(&self) -> bool {
        self.morph.is_some() || self.skin_weights.is_some()
    }

    /// Axis-aligned bounds of the positions, or `None` when empty.
    pub fn bounds(&self) -> Option<(Vec3, Vec3)> {
        let mut it = self.positions.iter();
        let first = *it.next()?;
        Some(it.fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))))
    }
}
