//! Morph targets (spec §3.7.2.2) and skins (§3.7.3) → animed's model, one
//! to one: a primitive's `targets` become the mesh's [`Morphs`] (POSITION
//! and NORMAL deltas; TANGENT is not used by animed's shading), its
//! `JOINTS_n`/`WEIGHTS_n` sets become [`SkinWeights`] (more than four
//! influences: the four largest, renormalised, one warning), and a `skin`
//! becomes a [`Skin`] whose joints are the glTF joint nodes.

use super::accessor::read_f32;
use super::container::{Buffers, GltfError, Result};
use super::mesh::{here, vec3s};
use super::pointer::pointer;
use crate::anim::MAX_MORPH_TARGETS;
use crate::scene::{MorphTarget, Morphs, Skin, SkinWeights, MAX_JOINTS};
use glam::{Mat4, Vec3};
use gltf::Semantic;

/// The names in `mesh.extras.targetNames` (what Blender and three.js use).
pub fn target_names(mesh: &gltf::Mesh) -> Vec<String> {
    let Some(raw) = mesh.extras().as_ref() else {
        return Vec::new();
    };
    serde_json::from_str::<serde_json::Value>(raw.get())
        .ok()
        .and_then(|v| {
            Some(
                v.get("targetNames")?
                    .as_array()?
                    .iter()
                    .map(|n| n.as_str().unwrap_or_default().to_string())
                    .collect(),
            )
        })
        .unwrap_or_default()
}

/// The morph targets of a primitive with `n` vertices, or `None` without.
pub fn read_morphs(
    mesh_index: usize,
    prim: &gltf::Primitive,
    buffers: &Buffers,
    n: usize,
    default_weights: &[f32],
    warnings: &mut Vec<String>,
) -> Result<Option<Morphs>> {
    let at = here(mesh_index, prim.index());
    let mut targets = Vec::new();
    for (t, target) in prim.morph_targets().enumerate() {
        if t == MAX_MORPH_TARGETS {
            warnings.push(format!(
                "{at}/targets: {} morph targets; animed keeps the first {MAX_MORPH_TARGETS}",
                prim.morph_targets().count()
            ));
            break;
        }
        let tp = format!("{at}/targets/{t}");
        let read = |acc: Option<gltf::Accessor>, name: &str| -> Result<Vec<Vec3>> {
            let Some(acc) = acc else {
                return Ok(Vec::new());
            };
            if acc.dimensions() != gltf::accessor::Dimensions::Vec3 {
                return Err(GltfError::at(
                    format!("{tp}/{name}"),
                    format!("{name} must be a VEC3 accessor"),
                ));
            }
            let v = vec3s(
                &read_f32(&acc, buffers)
                    .map_err(|e| GltfError::at(format!("{tp}/{name}"), e.to_string()))?,
                3,
            );
            if v.len() != n {
                return Err(GltfError::at(
                    format!("{tp}/{name}"),
                    format!("{} values for {n} positions", v.len()),
                ));
            }
            Ok(v)
        };
        let mut positions = read(target.positions(), "POSITION")?;
        if positions.is_empty() {
            positions = vec![Vec3::ZERO; n];
        }
        let normals = read(target.normals(), "NORMAL")?;
        targets.push(MorphTarget::new(format!("target_{t}"), positions, normals));
    }
    if targets.is_empty() {
        return Ok(None);
    }
    let weights = &default_weights[..default_weights.len().min(targets.len())];
    Morphs::new(n, targets, weights.to_vec())
        .map(Some)
        .map_err(|e| GltfError::at(format!("{at}/targets"), e.to_string()))
}

/// The joint influences of a primitive with `n` vertices (every
/// `JOINTS_n`/`WEIGHTS_n` pair), or `None` without.
pub fn read_skin_weights(
    mesh_index: usize,
    prim: &gltf::Primitive,
    buffers: &Buffers,
    n: usize,
    warnings: &mut Vec<String>,
) -> Result<Option<SkinWeights>> {
    let at = here(mesh_index, prim.index());
    let mut sets: Vec<(Vec<f32>, Vec<f32>)> = Vec::new();
    for set in 0.. {
        let (Some(j), Some(w)) = (
            prim.get(&Semantic::Joints(set)),
            prim.get(&Semantic::Weights(set)),
        ) else {
            break;
        };
        let attr = |name: &str| format!("{at}/attributes/{name}_{set}");
        if j.dimensions() != gltf::accessor::Dimensions::Vec4
            || w.dimensions() != gltf::accessor::Dimensions::Vec4
        {
            return Err(GltfError::at(
                attr("JOINTS"),
                "JOINTS_n and WEIGHTS_n must be VEC4 accessors",
            ));
        }
        let joints =
            read_f32(&j, buffers).map_err(|e| GltfError::at(attr("JOINTS"), e.to_string()))?;
        let weights =
            read_f32(&w, buffers).map_err(|e| GltfError::at(attr("WEIGHTS"), e.to_string()))?;
        for (name, v) in [("JOINTS", &joints), ("WEIGHTS", &weights)] {
            if v.len() != 4 * n {
                return Err(GltfError::at(
                    attr(name),
                    format!("{} values for {n} positions", v.len() / 4),
                ));
            }
        }
        if let Some(bad) = joints
            .iter()
            .find(|x| !(0.0..=MAX_JOINTS as f32).contains(*x) || x.fract() != 0.0)
        {
            return Err(GltfError::at(
                attr("JOINTS"),
                format!("joint index {bad} is not a whole number in 0..{MAX_JOINTS}"),
            ));
        }
        sets.push((joints, weights));
    }
    if sets.is_empty() {
        return Ok(None);
    }
    let (sw, report) = SkinWeights::from_influences(n, |v, out| {
        for (j, w) in &sets {
            for c in 0..4 {
                out.push((j[4 * v + c] as u16, w[4 * v + c]));
            }
        }
    })
    .map_err(|e| GltfError::at(format!("{at}/attributes/WEIGHTS_0"), e.to_string()))?;
    if report.over_four > 0 {
        warnings.push(format!(
            "{at}: {} vertices have more than 4 joint influences; kept the 4 largest and renormalised",
            report.over_four
        ));
    }
    if report.zero_sum > 0 {
        warnings.push(format!(
            "{at}: {} vertices have joint weights summing to 0; they stay at their bind position",
            report.zero_sum
        ));
    }
    Ok(Some(sw))
}

/// A glTF skin with its joints mapped to animed nodes (`joint_id(i)`:
/// the animed node of glTF node `i`, `None` when it is not in the loaded
/// scene).
pub fn read_skin(
    skin: &gltf::Skin,
    buffers: &Buffers,
    joint_id: &dyn Fn(usize) -> Option<crate::scene::NodeId>,
) -> Result<Skin> {
    let at = pointer(&[&"skins", &skin.index()]);
    let mut joints = Vec::new();
    for (k, j) in skin.joints().enumerate() {
        let id = joint_id(j.index()).ok_or_else(|| {
            GltfError::at(
                format!("{at}/joints/{k}"),
                format!("joint node {} is not in the loaded scene", j.index()),
            )
        })?;
        joints.push(id);
    }
    let ibm = match skin.inverse_bind_matrices() {
        Some(acc) => {
            if acc.dimensions() != gltf::accessor::Dimensions::Mat4 {
                return Err(GltfError::at(
                    format!("{at}/inverseBindMatrices"),
                    "inverseBindMatrices must be a MAT4 accessor",
                ));
            }
            let flat = read_f32(&acc, buffers)
                .map_err(|e| GltfError::at(format!("{at}/inverseBindMatrices"), e.to_string()))?;
            flat.chunks_exact(16)
                .map(|c| {
                    let mut a = [0f32; 16];
                    a.copy_from_slice(c);
                    Mat4::from_cols_array(&a)
                })
                .collect()
        }
        None => Vec::new(),
    };
    let mut s = Skin::new(skin.name().unwrap_or_default(), joints, ibm)
        .map_err(|e| GltfError::at(at.clone(), e.to_string()))?;
    s.skeleton = skin.skeleton().and_then(|n| joint_id(n.index()));
    Ok(s)
}
