//! Skins: a skeleton of ordinary scene nodes (so every key, handle and
//! export path works on joints) bound to a mesh by per-vertex joint indices
//! and weights, as in M3G `SkinnedMesh` and glTF 2.0 §3.7.3.
//!
//! A vertex's skinned position is Σ wᵢ · (jointWorldᵢ · inverseBindᵢ) · v
//! (linear blend skinning, at most four influences). The [`Skin`] (joints +
//! inverse bind matrices) hangs on the shape node (`Node::skin`); the
//! per-vertex influences live on the mesh ([`SkinWeights`]) because they are
//! vertex attributes like normals.

use super::{DeformError, NodeId};
use glam::Mat4;

/// Index of a skin in [`Scene::skins`](super::Scene::skins).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SkinId(pub u32);

/// Most joints one skin may name (joint indices are `u16`).
pub const MAX_JOINTS: usize = u16::MAX as usize;

/// An ordered list of joints and their inverse bind matrices.
///
/// Invariants ([`Skin::new`]): 1..=[`MAX_JOINTS`] joints; one finite inverse
/// bind matrix per joint.
#[derive(Clone, Debug, PartialEq)]
pub struct Skin {
    pub name: String,
    joints: Vec<NodeId>,
    inverse_bind: Vec<Mat4>,
    /// The skeleton's root when the file names one (glTF `skin.skeleton`);
    /// informative only, evaluation does not need it.
    pub skeleton: Option<NodeId>,
}

impl Skin {
    /// A skin over `joints`; an empty `inverse_bind` means identities
    /// (glTF's default).
    pub fn new(
        name: impl Into<String>,
        joints: Vec<NodeId>,
        mut inverse_bind: Vec<Mat4>,
    ) -> Result<Skin, DeformError> {
        if joints.is_empty() || joints.len() > MAX_JOINTS {
            return Err(DeformError(format!(
                "a skin needs 1 to {MAX_JOINTS} joints, got {}",
                joints.len()
            )));
        }
        if inverse_bind.is_empty() {
            inverse_bind = vec![Mat4::IDENTITY; joints.len()];
        }
        if inverse_bind.len() != joints.len() {
            return Err(DeformError(format!(
                "{} inverse bind matrices for {} joints",
                inverse_bind.len(),
                joints.len()
            )));
        }
        if let Some(i) = inverse_bind.iter().position(|m| !m.is_finite()) {
            return Err(DeformError(format!(
                "inverse bind matrix {i} is not finite"
            )));
        }
        Ok(Skin {
            name: name.into(),
            joints,
            inverse_bind,
            skeleton: None,
        })
    }

    pub fn joints(&self) -> &[NodeId] {
        &self.joints
    }

    /// The same skin with its joints (and skeleton root) renumbered by
    /// `map`; `None` when a joint has no new id (it was removed).
    pub fn with_joints_mapped(&self, map: impl Fn(NodeId) -> Option<NodeId>) -> Option<Skin> {
        Some(Skin {
            name: self.name.clone(),
            joints: self
                .joints
                .iter()
                .map(|&j| map(j))
                .collect::<Option<Vec<_>>>()?,
            inverse_bind: self.inverse_bind.clone(),
            skeleton: self.skeleton.and_then(&map),
        })
    }

    pub fn inverse_bind(&self) -> &[Mat4] {
        &self.inverse_bind
    }
}

/// Per-vertex joint influences of a mesh: up to four (joint index into the
/// skin's joint list, weight) pairs per vertex.
///
/// Invariants ([`SkinWeights::new`] / [`SkinWeights::from_influences`]):
/// weights finite and ≥ 0, each vertex's weights sum to 1 or are all zero
/// (a vertex with no influence stays where the unskinned mesh puts it);
/// unused slots have weight 0.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SkinWeights {
    joints: Vec<[u16; 4]>,
    weights: Vec<[f32; 4]>,
    /// Highest joint index used + 1 (0 without influences).
    joint_span: usize,
}

/// What [`SkinWeights::from_influences`] had to change.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct InfluenceReport {
    /// Vertices with more than four non-zero influences (kept the 4 largest).
    pub over_four: usize,
    /// Vertices whose weights summed to zero (they stay at the bind position).
    pub zero_sum: usize,
}

impl SkinWeights {
    /// Four influences per vertex, renormalised so that each vertex's
    /// weights sum to 1 (all-zero vertices stay zero).
    pub fn new(joints: Vec<[u16; 4]>, weights: Vec<[f32; 4]>) -> Result<SkinWeights, DeformError> {
        if joints.len() != weights.len() {
            return Err(DeformError(format!(
                "{} joint index sets for {} weight sets",
                joints.len(),
                weights.len()
            )));
        }
        let mut out = SkinWeights {
            joints,
            weights,
            joint_span: 0,
        };
        for (v, w) in out.weights.iter_mut().enumerate() {
            if w.iter().any(|x| !x.is_finite() || *x < 0.0) {
                return Err(DeformError(format!(
                    "vertex {v} has a skin weight that is negative or not finite"
                )));
            }
            normalise(w);
        }
        out.joint_span = span(&out.joints, &out.weights);
        Ok(out)
    }

    /// Builds the influences from any number of (joint, weight) pairs per
    /// vertex (glTF JOINTS_n/WEIGHTS_n sets): keeps the four largest weights
    /// (ties: the earlier pair), sums duplicate joints first, renormalises.
    /// `influences(v, out)` appends vertex `v`'s pairs to `out`.
    pub fn from_influences(
        vertex_count: usize,
        mut influences: impl FnMut(usize, &mut Vec<(u16, f32)>),
    ) -> Result<(SkinWeights, InfluenceReport), DeformError> {
        let mut report = InfluenceReport::default();
        let mut joints = Vec::with_capacity(vertex_count);
        let mut weights = Vec::with_capacity(vertex_count);
        let mut pairs: Vec<(u16, f32)> = Vec::new();
        for v in 0..vertex_count {
            pairs.clear();
            influences(v, &mut pairs);
            if pairs.iter().any(|(_, w)| !w.is_finite() || *w < 0.0) {
                return Err(DeformError(format!(
                    "vertex {v} has a skin weight that is negative or not finite"
                )));
            }
            // Merge repeated joints, drop zero weights.
            let mut merged: Vec<(u16, f32)> = Vec::with_capacity(pairs.len());
            for &(j, w) in pairs.iter() {
                if w == 0.0 {
                    continue;
                }
                match merged.iter_mut().find(|(k, _)| *k == j) {
                    Some(m) => m.1 += w,
                    None => merged.push((j, w)),
                }
            }
            if merged.len() > 4 {
                report.over_four += 1;
                // Stable: equal weights keep their file order.
                merged.sort_by(|a, b| b.1.total_cmp(&a.1));
                merged.truncate(4);
            }
            let mut j4 = [0u16; 4];
            let mut w4 = [0f32; 4];
            for (slot, (j, w)) in merged.iter().enumerate() {
                j4[slot] = *j;
                w4[slot] = *w;
            }
            if !normalise(&mut w4) {
                report.zero_sum += 1;
            }
            joints.push(j4);
            weights.push(w4);
        }
        let joint_span = span(&joints, &weights);
        Ok((
            SkinWeights {
                joints,
                weights,
                joint_span,
            },
            report,
        ))
    }

    /// The influences for a mesh whose vertex `k` is the old vertex
    /// `src[k]`; indices past the old count get no influence.
    pub fn remap(&self, src: &[u32]) -> SkinWeights {
        let joints: Vec<[u16; 4]> = src
            .iter()
            .map(|&i| self.joints.get(i as usize).copied().unwrap_or([0; 4]))
            .collect();
        let weights: Vec<[f32; 4]> = src
            .iter()
            .map(|&i| self.weights.get(i as usize).copied().unwrap_or([0.0; 4]))
            .collect();
        let joint_span = span(&joints, &weights);
        SkinWeights {
            joints,
            weights,
            joint_span,
        }
    }

    pub fn joints(&self) -> &[[u16; 4]] {
        &self.joints
    }

    pub fn weights(&self) -> &[[f32; 4]] {
        &self.weights
    }

    pub fn len(&self) -> usize {
        self.joints.len()
    }

    pub fn is_empty(&self) -> bool {
        self.joints.is_empty()
    }

    /// Highest joint index with a non-zero weight, plus one: a skin bound to
    /// this mesh needs at least this many joints.
    pub fn joint_span(&self) -> usize {
        self.joint_span
    }

    /// The largest number of non-zero influences on one vertex (0..=4).
    pub fn max_influences(&self) -> usize {
        self.weights
            .iter()
            .map(|w| w.iter().filter(|x| **x > 0.0).count())
            .max()
            .unwrap_or(0)
    }
}

/// Scales `w` to sum to 1; returns false (and leaves zeros) when the sum is 0.
fn normalise(w: &mut [f32; 4]) -> bool {
    let sum = w[0] + w[1] + w[2] + w[3];
    if sum.is_nan() || sum <= 0.0 || !sum.is_finite() {
        *w = [0.0; 4];
        return false;
    }
    if sum != 1.0 {
        for x in w.iter_mut() {
            *x /= sum;
        }
    }
    true
}

fn span(joints: &[[u16; 4]], weights: &[[f32; 4]]) -> usize {
    joints
        .iter()
        .zip(weights)
        .flat_map(|(j, w)| {
            j.iter()
                .zip(w)
                .filter(|(_, w)| **w > 0.0)
                .map(|(j, _)| *j as usize + 1)
        })
        .max()
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn more_than_four_keeps_the_largest_and_renormalises() {
        let (s, r) = SkinWeights::from_influences(2, |v, out| {
            if v == 0 {
                out.extend([(0, 0.1), (1, 0.3), (2, 0.05), (3, 0.2), (4, 0.25), (5, 0.1)]);
            } else {
                out.extend([(7, 0.0), (2, 0.0)]);
            }
        })
        .unwrap();
        assert_eq!(r.over_four, 1);
        assert_eq!(r.zero_sum, 1);
        // 0.3, 0.25, 0.2, then the first of the two 0.1s (joint 0).
        assert_eq!(s.joints()[0], [1, 4, 3, 0]);
        let w = s.weights()[0];
        let total = 0.3 + 0.25 + 0.2 + 0.1;
        for (got, want) in w
            .iter()
            .zip([0.3 / total, 0.25 / total, 0.2 / total, 0.1 / total])
        {
            assert!((got - want).abs() < 1e-6, "{w:?}");
        }
        assert_eq!(s.weights()[1], [0.0; 4]);
        assert_eq!(s.joint_span(), 5);
        assert_eq!(s.max_influences(), 4);
    }

    #[test]
    fn duplicate_joints_are_summed_and_bad_weights_refused() {
        let (s, _) =
            SkinWeights::from_influences(1, |_, out| out.extend([(3, 0.25), (3, 0.25), (1, 0.5)]))
                .unwrap();
        assert_eq!(s.joints()[0][..2], [3, 1]);
        assert_eq!(s.weights()[0], [0.5, 0.5, 0.0, 0.0]);
        assert!(SkinWeights::from_influences(1, |_, out| out.push((0, -1.0))).is_err());
        assert!(SkinWeights::new(vec![[0; 4]], vec![[f32::NAN, 0.0, 0.0, 0.0]]).is_err());
        assert!(SkinWeights::new(vec![[0; 4]], vec![]).is_err());
    }

    #[test]
    fn scene_remap_drops_skins_that_lost_a_joint() {
        use crate::scene::{Node, Scene};
        let mut s = Scene::new();
        let a = s.add_node(None, Node::group("a"));
        let b = s.add_node(None, Node::group("b"));
        let c = s.add_node(None, Node::group("c"));
        let k0 = s
            .add_skin(Skin::new("0", vec![a, b], vec![]).unwrap())
            .unwrap();
        let k1 = s
            .add_skin(Skin::new("1", vec![c], vec![]).unwrap())
            .unwrap();
        s.node_mut(a).skin = Some(k0);
        s.node_mut(c).skin = Some(k1);
        // Remove node b: a stays 0, c becomes 1.
        s.remap_skins(|n| match n.0 {
            0 => Some(NodeId(0)),
            2 => Some(NodeId(1)),
            _ => None,
        });
        assert_eq!(s.skins.len(), 1);
        assert_eq!(s.skins[0].joints(), &[NodeId(1)]);
        assert_eq!(s.node(a).skin, None);
        assert_eq!(s.node(c).skin, Some(SkinId(0)));
    }

    #[test]
    fn skin_checks_matrix_count() {
        let j = vec![NodeId(0), NodeId(1)];
        assert_eq!(
            Skin::new("s", j.clone(), vec![])
                .unwrap()
                .inverse_bind()
                .len(),
            2
        );
        assert!(Skin::new("s", j.clone(), vec![Mat4::IDENTITY]).is_err());
        assert!(Skin::new("s", vec![], vec![]).is_err());
        assert!(Skin::new("s", j, vec![Mat4::NAN, Mat4::IDENTITY]).is_err());
    }
}
