//! Morph targets of a mesh (M3G `MorphingMesh`, glTF `primitive.targets`):
//! per-target position deltas and optional normal deltas, blended as
//! M = B + Σ wᵢ·Mᵢ with weights that may leave [0, 1].
//!
//! The weights themselves are animated on the shape (`NAME.weights`); the
//! mesh holds the targets and the default weights used when nothing keys
//! them (glTF `mesh.weights`). Invariants are checked by [`Morphs::new`].

use super::DeformError;
use crate::anim::MAX_MORPH_TARGETS;
use glam::Vec3;

/// One morph target: displacements added to the base mesh, scaled by its weight.
#[derive(Clone, Debug, PartialEq)]
pub struct MorphTarget {
    pub name: String,
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
}

impl MorphTarget {
    /// A target with position deltas and (possibly empty) normal deltas.
    pub fn new(name: impl Into<String>, positions: Vec<Vec3>, normals: Vec<Vec3>) -> MorphTarget {
        MorphTarget {
            name: name.into(),
            positions,
            normals,
        }
    }

    /// Position deltas, one per base vertex.
    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }

    /// Normal deltas, one per base vertex, or empty.
    pub fn normals(&self) -> &[Vec3] {
        &self.normals
    }
}

/// The morph targets of one mesh and their default weights.
///
/// Invariants: 1..=[`MAX_MORPH_TARGETS`] targets; every target has one
/// position delta per base vertex and either no normal deltas or one per
/// base vertex; all deltas and weights finite; one default weight per target.
#[derive(Clone, Debug, PartialEq)]
pub struct Morphs {
    targets: Vec<MorphTarget>,
    weights: Vec<f32>,
}

impl Morphs {
    /// Checks the invariants above for a base mesh of `vertex_count`
    /// vertices. Missing default weights are zero (glTF's default).
    pub fn new(
        vertex_count: usize,
        targets: Vec<MorphTarget>,
        mut default_weights: Vec<f32>,
    ) -> Result<Morphs, DeformError> {
        if targets.is_empty() || targets.len() > MAX_MORPH_TARGETS {
            return Err(DeformError(format!(
                "a mesh needs 1 to {MAX_MORPH_TARGETS} morph targets, got {}",
                targets.len()
            )));
        }
        for (i, t) in targets.iter().enumerate() {
            if t.positions.len() != vertex_count {
                return Err(DeformError(format!(
                    "morph target {i} has {} positions for {vertex_count} vertices",
                    t.positions.len()
                )));
            }
            if !t.normals.is_empty() && t.normals.len() != vertex_count {
                return Err(DeformError(format!(
                    "morph target {i} has {} normals for {vertex_count} vertices",
                    t.normals.len()
                )));
            }
            if !t.positions.iter().chain(&t.normals).all(|v| v.is_finite()) {
                return Err(DeformError(format!(
                    "morph target {i} has a delta that is not a finite number"
                )));
            }
        }
        if default_weights.len() > targets.len() {
            return Err(DeformError(format!(
                "{} default weights for {} morph targets",
                default_weights.len(),
                targets.len()
            )));
        }
        if !default_weights.iter().all(|w| w.is_finite()) {
            return Err(DeformError(
                "a default morph weight is not a finite number".into(),
            ));
        }
        default_weights.resize(targets.len(), 0.0);
        Ok(Morphs {
            targets,
            weights: default_weights,
        })
    }

    pub fn targets(&self) -> &[MorphTarget] {
        &self.targets
    }

    /// Weights used when no track keys them, one per target.
    pub fn default_weights(&self) -> &[f32] {
        &self.weights
    }

    pub fn len(&self) -> usize {
        self.targets.len()
    }

    pub fn is_empty(&self) -> bool {
        self.targets.is_empty()
    }

    /// The targets for a mesh whose vertex `k` is the old vertex `src[k]`
    /// (readers unweld vertices for flat normals); normal deltas are kept
    /// only when `keep_normals`. Indices past the old vertex count give zero
    /// deltas.
    pub fn remap(&self, src: &[u32], keep_normals: bool) -> Morphs {
        let pick = |v: &[Vec3]| -> Vec<Vec3> {
            src.iter()
                .map(|&i| v.get(i as usize).copied().unwrap_or(Vec3::ZERO))
                .collect()
        };
        Morphs {
            targets: self
                .targets
                .iter()
                .map(|t| MorphTarget {
                    name: t.name.clone(),
                    positions: pick(&t.positions),
                    normals: if keep_normals && !t.normals.is_empty() {
                        pick(&t.normals)
                    } else {
                        Vec::new()
                    },
                })
                .collect(),
            weights: self.weights.clone(),
        }
    }

    /// Renames the targets from `names` (in order); empty or missing names
    /// keep the current ones.
    pub fn set_names(&mut self, names: &[String]) {
        for (t, n) in self.targets.iter_mut().zip(names) {
            if !n.is_empty() {
                t.name.clone_from(n);
            }
        }
    }

    /// Whether any target moves normals.
    pub fn has_normal_deltas(&self) -> bool {
        self.targets.iter().any(|t| !t.normals.is_empty())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constructor_checks_counts_and_pads_weights() {
        let t = MorphTarget::new("a", vec![Vec3::X; 3], vec![]);
        let m = Morphs::new(3, vec![t.clone(), t.clone()], vec![0.5]).unwrap();
        assert_eq!(m.default_weights(), &[0.5, 0.0]);
        assert!(Morphs::new(4, vec![t.clone()], vec![]).is_err());
        assert!(Morphs::new(3, vec![], vec![]).is_err());
        assert!(Morphs::new(3, vec![t.clone()], vec![1.0, 2.0]).is_err());
        let bad = MorphTarget::new("n", vec![Vec3::X; 3], vec![Vec3::Y; 2]);
        assert!(Morphs::new(3, vec![bad], vec![]).is_err());
        let nan = MorphTarget::new("n", vec![Vec3::NAN; 3], vec![]);
        assert!(Morphs::new(3, vec![nan], vec![]).is_err());
    }
}
