//! The scene model: the single source of truth that readers fill, the
//! animation evaluates, the renderer draws and writers save.
//!
//! Nodes live in an arena (`Scene::nodes`) addressed by [`NodeId`]; a node's
//! place in the tree is `parent` + `children`. Meshes and materials are shared
//! by id (images too, [`ImageId`]) so that DEF/USE in the files maps onto sharing here.

mod background;
mod clips;
mod image;
mod light;
mod material;
mod mesh;
mod morph;
mod node;
pub mod normals;
pub mod primitives;
mod skin;
mod text;
mod texture;
mod transform;

pub use background::{Background, Face};
pub use clips::{Clip, ClipRef, Clips};
pub use image::{
    check_size as check_image_size, Image, ImageError, ImageId, ImageSource, MipLevel,
    MAX_IMAGE_PIXELS, MAX_IMAGE_SIDE, MAX_SCENE_IMAGE_PIXELS,
};
pub use light::{Camera, CameraKind, Light, LightKind};
pub use material::Material;
pub use mesh::Mesh;
pub use morph::{MorphTarget, Morphs};
pub use node::{Node, NodeKind, RenderStyle, Shape};
pub use normals::{
    mesh_from_polygons, mesh_from_polygons_corners, mesh_from_polygons_textured, Binding,
    MeshError, PolyOptions, TexCoords,
};
pub use skin::{InfluenceReport, Skin, SkinId, SkinWeights, MAX_JOINTS};
pub use text::{FontFamily, Justify, TextKind, TextSpec};
pub use texture::{Filter, MipMode, TexTransform, TexTransformOrder, Texture, TextureModel, Wrap};
pub use transform::Transform;

use crate::anim::Animation;
use glam::Vec3;

/// Index of a node in [`Scene::nodes`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct NodeId(pub u32);

/// Index of a mesh in [`Scene::meshes`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct MeshId(pub u32);

/// Index of a material in [`Scene::materials`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct MaterialId(pub u32);

/// Why morph targets or a skin could not be built (an invariant of
/// [`Morphs`], [`Skin`] or [`SkinWeights`] does not hold).
#[derive(Clone, Debug, PartialEq)]
pub struct DeformError(pub String);

impl std::fmt::Display for DeformError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for DeformError {}

/// Scene-wide settings: timing and what the background looks like.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Frames per second; key times are in frames.
    pub fps: f32,
    /// Length of the animation in frames (playback loops over 0..=duration).
    pub duration: f32,
    /// Background colour, linear 0..1 RGB.
    pub background: Vec3,
    /// A file's sky/ground gradient and panorama (VRML97 Background);
    /// `background` is then its first sky colour, for flat fills.
    pub sky: Option<Box<Background>>,
    /// `None` = the format's default (VRML97: NavigationInfo.headlight, default on;
    /// Inventor/VRML1/OBJ: on, as examiner viewers do).
    pub headlight: Option<bool>,
    /// Global ambient light (linear RGB): OpenGL's light-model ambient,
    /// which Inventor and VRML 1.0 files get (0.2 grey by default, an
    /// Inventor `Environment` sets it); VRML97, X3D and glTF have none (0).
    /// The renderer lights every lit surface with it as an ambient-only light.
    pub ambient: Vec3,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            fps: 24.0,
            duration: 96.0,
            background: Vec3::ZERO,
            sky: None,
            headlight: None,
            ambient: Vec3::ZERO,
        }
    }
}

/// Which file format a scene came from (decides defaults such as the headlight).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SourceFormat {
    #[default]
    Native,
    Inventor,
    Vrml1,
    Vrml97,
    /// X3D, classic (.x3dv) or XML (.x3d) encoding.
    X3d,
    Obj,
    Gltf,
}

/// A whole scene: node tree, shared resources, settings and animation.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    pub nodes: Vec<Node>,
    pub roots: Vec<NodeId>,
    pub meshes: Vec<Mesh>,
    pub materials: Vec<Material>,
    /// Decoded images shared by the materials' textures (one copy each).
    pub images: Vec<Image>,
    /// Skins (joints + inverse bind matrices), bound to shapes by `Node::skin`.
    pub skins: Vec<Skin>,
    pub settings: Settings,
    /// The playing clip's tracks (see [`Clips`] for the others).
    pub animation: Animation,
    /// Clip names and order, and the clips that are not playing.
    pub clips: Clips,
    pub format: SourceFormat,
    /// Free text from WorldInfo/Info nodes that is not animed's own key note.
    pub info: Vec<String>,
}

impl Scene {
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a node under `parent` (or as a root) and returns its id.
    pub fn add_node(&mut self, parent: Option<NodeId>, mut node: Node) -> NodeId {
        let id = NodeId(self.nodes.len() as u32);
        node.parent = parent;
        node.children.clear();
        self.nodes.push(node);
        match parent {
            Some(p) => self.nodes[p.0 as usize].children.push(id),
            None => self.roots.push(id),
        }
        id
    }

    pub fn add_mesh(&mut self, mesh: Mesh) -> MeshId {
        self.meshes.push(mesh);
        MeshId(self.meshes.len() as u32 - 1)
    }

    pub fn add_material(&mut self, material: Material) -> MaterialId {
        self.materials.push(material);
        MaterialId(self.materials.len() as u32 - 1)
    }

    /// Adds an image, refusing it when the scene's images would exceed
    /// [`MAX_SCENE_IMAGE_PIXELS`] together. A clone of an image already
    /// held (an inlined file used twice) returns the held one's id.
    pub fn add_image(&mut self, image: Image) -> Result<ImageId, ImageError> {
        if let Some(i) = self
            .images
            .iter()
            .position(|i| i.same_pixels(&image) && *i == image)
        {
            return Ok(ImageId(i as u32));
        }
        let held: u64 = self.images.iter().map(Image::pixel_count).sum();
        if held + image.pixel_count() > MAX_SCENE_IMAGE_PIXELS {
            return Err(ImageError(format!(
                "image {}x{} would take the scene's images past the budget of {} pixels",
                image.width(),
                image.height(),
                MAX_SCENE_IMAGE_PIXELS
            )));
        }
        self.images.push(image);
        Ok(ImageId(self.images.len() as u32 - 1))
    }

    /// Adds a skin after checking that its joints exist; returns its id.
    pub fn add_skin(&mut self, skin: Skin) -> Result<SkinId, DeformError> {
        if let Some(j) = skin
            .joints()
            .iter()
            .find(|j| j.0 as usize >= self.nodes.len())
        {
            return Err(DeformError(format!(
                "skin joint node {} does not exist",
                j.0
            )));
        }
        self.skins.push(skin);
        Ok(SkinId(self.skins.len() as u32 - 1))
    }

    pub fn skin(&self, id: SkinId) -> Option<&Skin> {
        self.skins.get(id.0 as usize)
    }

    /// Renumbers skin joints after the node arena changed (`map(old id)` →
    /// new id, `None` = removed; `Node::skin` of the nodes already in
    /// `self.nodes` refer to the old skin list): a skin that lost a joint is
    /// dropped and the shapes it deformed become rigid; the others are
    /// renumbered in `Node::skin`.
    pub fn remap_skins(&mut self, map: impl Fn(NodeId) -> Option<NodeId>) {
        let mut new_id = Vec::with_capacity(self.skins.len());
        let mut kept = Vec::with_capacity(self.skins.len());
        for s in &self.skins {
            match s.with_joints_mapped(&map) {
                Some(s) => {
                    new_id.push(Some(SkinId(kept.len() as u32)));
                    kept.push(s);
                }
                None => new_id.push(None),
            }
        }
        self.skins = kept;
        for n in &mut self.nodes {
            n.skin = n
                .skin
                .and_then(|k| new_id.get(k.0 as usize).copied().flatten());
        }
    }

    /// Whether node `id` is a joint of any skin.
    pub fn is_joint(&self, id: NodeId) -> bool {
        self.skins.iter().any(|s| s.joints().contains(&id))
    }

    pub fn image(&self, id: ImageId) -> Option<&Image> {
        self.images.get(id.0 as usize)
    }

    pub fn node(&self, id: NodeId) -> &Node {
        &self.nodes[id.0 as usize]
    }

    pub fn node_mut(&mut self, id: NodeId) -> &mut Node {
        &mut self.nodes[id.0 as usize]
    }

    /// Finds a node by name (first match in arena order).
    pub fn find_node(&self, name: &str) -> Option<NodeId> {
        self.nodes
            .iter()
            .position(|n| n.name == name)
            .map(|i| NodeId(i as u32))
    }

    /// Finds a material by name.
    pub fn find_material(&self, name: &str) -> Option<MaterialId> {
        self.materials
            .iter()
            .position(|m| m.name == name)
            .map(|i| MaterialId(i as u32))
    }

    /// Node ids in depth-first pre-order (parents before children).
    pub fn walk(&self) -> Vec<NodeId> {
        let mut out = Vec::with_capacity(self.nodes.len());
        let mut stack: Vec<NodeId> = self.roots.iter().rev().copied().collect();
        while let Some(id) = stack.pop() {
            out.push(id);
            stack.extend(self.node(id).children.iter().rev().copied());
        }
        out
    }

    /// Duration of the animation in seconds.
    pub fn duration_seconds(&self) -> f32 {
        self.settings.duration / self.settings.fps.max(1e-6)
    }
}
