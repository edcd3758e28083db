//! glTF 2.0: `.gltf` (JSON with external or `data:` buffers) and `.glb`.
//!
//! The `gltf` crate parses and validates the JSON; the mapping onto
//! animed's scene model is ours, one job per file: `container` (GLB
//! chunks, parse, validation, buffers), `uri` (data: URIs, files beside),
//! `accessor` (typed, bounds-checked reads), `mesh` (primitives),
//! `material` (metallic-roughness ⇄ Phong, colour space), `lights` (light
//! units, cameras), `anim` (animations → clips), `pointer_anim`
//! (KHR_animation_pointer channels onto lights, cameras, materials), `texture` (base colour
//! textures, samplers, KHR_texture_transform), `read` (the node tree and
//! the entry point); the writer: `write`, `write_anim`, `write_pointer`
//! (KHR_animation_pointer channels), `write_texture`,
//! `bin`. Errors name the JSON pointer of the offending part.

mod accessor;
mod anim;
mod bin;
mod container;
mod deform;
mod lights;
mod material;
mod mesh;
mod pointer;
mod pointer_anim;
mod read;
mod texture;
mod uri;
mod write;
mod write_anim;
mod write_pointer;
mod write_texture;

pub use container::SUPPORTED_EXTENSIONS;
pub use material::{linear_from_srgb, pbr_from_phong, phong_from_pbr, srgb_from_linear, Pbr};
pub use read::{is_gltf, read, ReadOptions};

/// The scene as glTF JSON (`binary == false`, buffer embedded as a data:
/// URI) or as a .glb, and what the writer did (`convert --verbose`).
pub fn to_bytes(
    scene: &crate::scene::Scene,
    opts: &crate::format::WriteOptions,
    binary: bool,
) -> (Vec<u8>, crate::format::WriteReport) {
    write::write(scene, opts, binary)
}
