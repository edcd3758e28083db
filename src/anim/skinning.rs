//! The deformation kernels: morph-target blending (M3G: M = B + Σ wᵢ·Mᵢ)
//! and linear blend skinning (glTF 2.0 §3.7.3.3: v' = Σ wᵢ·Jᵢ·v with
//! Jᵢ = jointWorldᵢ · inverseBindᵢ).
//!
//! Both run in parallel over fixed chunks of vertices. Every vertex's
//! arithmetic is the same whatever chunk or thread computes it (targets are
//! summed in their order, influences in slot order), so the output has the
//! same bytes for any thread count.

use glam::{Mat3A, Mat4, Vec3, Vec3A, Vec4};
use rayon::prelude::*;

/// Vertices per parallel work item (small enough to balance 2 threads on a
/// few-thousand-vertex character, large enough to amortise scheduling).
const CHUNK: usize = 2048;

/// One morph target's contribution: its weight and deltas.
pub struct MorphInput<'a> {
    pub weight: f32,
    pub positions: &'a [Vec3],
    /// Empty when the target does not move normals.
    pub normals: &'a [Vec3],
}

/// `out_p = base_p + Σ wᵢ·dpᵢ`; `out_n = normalise(base_n + Σ wᵢ·dnᵢ)` when
/// normals are given (`base_n` empty: `out_n` is left empty). Targets with
/// weight 0 are skipped (adding 0·d changes nothing but −0.0 signs).
pub fn morph(
    base_p: &[Vec3],
    base_n: &[Vec3],
    targets: &[MorphInput],
    out_p: &mut Vec<Vec3>,
    out_n: &mut Vec<Vec3>,
) {
    let n = base_p.len();
    out_p.clear();
    out_p.extend_from_slice(base_p);
    let with_normals = base_n.len() == n;
    out_n.clear();
    if with_normals {
        out_n.extend_from_slice(base_n);
    }
    let live: Vec<&MorphInput> = targets
        .iter()
        .filter(|t| t.weight != 0.0 && t.positions.len() == n)
        .collect();
    if live.is_empty() {
        return;
    }
    out_p
        .par_chunks_mut(CHUNK)
        .enumerate()
        .for_each(|(c, chunk)| {
            let start = c * CHUNK;
            for t in &live {
                let d = &t.positions[start..start + chunk.len()];
                for (p, d) in chunk.iter_mut().zip(d) {
                    *p += *d * t.weight;
                }
            }
        });
    if with_normals && live.iter().any(|t| t.normals.len() == n) {
        out_n
            .par_chunks_mut(CHUNK)
            .enumerate()
            .for_each(|(c, chunk)| {
                let start = c * CHUNK;
                for t in live.iter().filter(|t| t.normals.len() == n) {
                    let d = &t.normals[start..start + chunk.len()];
                    for (v, d) in chunk.iter_mut().zip(d) {
                        *v += *d * t.weight;
                    }
                }
                for v in chunk.iter_mut() {
                    *v = v.normalize_or_zero();
                }
            });
    }
}

/// A joint's matrices for skinning: the position matrix and the normal
/// matrix (inverse transpose of its upper 3×3, so non-uniform scale bends
/// normals correctly).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointMatrix {
    pub position: Mat4,
    pub normal: Mat3A,
}

impl JointMatrix {
    pub fn new(m: Mat4) -> JointMatrix {
        let inv = Mat3A::from_mat4(m).inverse().transpose();
        JointMatrix {
            position: m,
            normal: if inv.is_finite() { inv } else { Mat3A::ZERO },
        }
    }
}

/// Linear blend skinning of positions (and normals when `normals` has one per
/// position). `joints[i]` / `weights[i]` are vertex i's four influences;
/// `matrices` must cover every joint index used (callers pad). A vertex whose
/// weights are all zero uses `rest` (where the unskinned mesh would be).
#[allow(clippy::too_many_arguments)]
pub fn skin(
    positions: &[Vec3],
    normals: &[Vec3],
    joints: &[[u16; 4]],
    weights: &[[f32; 4]],
    matrices: &[JointMatrix],
    rest: &JointMatrix,
    out_p: &mut Vec<Vec3>,
    out_n: &mut Vec<Vec3>,
) {
    let n = positions.len().min(joints.len()).min(weights.len());
    out_p.clear();
    out_p.resize(n, Vec3::ZERO);
    let with_normals = normals.len() >= n && !normals.is_empty();
    out_n.clear();
    if with_normals {
        out_n.resize(n, Vec3::ZERO);
    }
    let get = |j: u16| matrices.get(j as usize).unwrap_or(rest);
    // The blended position matrix of vertex v (rest for all-zero weights).
    let blend_p = |v: usize| -> Mat4 {
        let (j, w) = (joints[v], weights[v]);
        if w == [0.0; 4] {
            return rest.position;
        }
        let m = [get(j[0]), get(j[1]), get(j[2]), get(j[3])];
        blend4(
            [m[0].position, m[1].position, m[2].position, m[3].position],
            w,
        )
    };
    if !with_normals {
        out_p
            .par_chunks_mut(CHUNK)
            .enumerate()
            .for_each(|(c, chunk)| {
                for (k, out) in chunk.iter_mut().enumerate() {
                    let v = c * CHUNK + k;
                    *out = blend_p(v).transform_point3(positions[v]);
                }
            });
        return;
    }
    out_p
        .par_chunks_mut(CHUNK)
        .zip(out_n.par_chunks_mut(CHUNK))
        .enumerate()
        .for_each(|(c, (chunk_p, chunk_n))| {
            for (k, (op, on)) in chunk_p.iter_mut().zip(chunk_n.iter_mut()).enumerate() {
                let v = c * CHUNK + k;
                let (j, w) = (joints[v], weights[v]);
                let (mp, mn) = if w == [0.0; 4] {
                    (rest.position, rest.normal)
                } else {
                    let m = [get(j[0]), get(j[1]), get(j[2]), get(j[3])];
                    (
                        blend4(
                            [m[0].position, m[1].position, m[2].position, m[3].position],
                            w,
                        ),
                        m[0].normal * w[0]
                            + m[1].normal * w[1]
                            + m[2].normal * w[2]
                            + m[3].normal * w[3],
                    )
                };
                *op = mp.transform_point3(positions[v]);
                *on = Vec3::from(mn * Vec3A::from(normals[v])).normalize_or_zero();
            }
        });
}

/// Σ wᵢ·Mᵢ column by column.
#[inline]
fn blend4(m: [Mat4; 4], w: [f32; 4]) -> Mat4 {
    let col = |c: usize| -> Vec4 {
        m[0].col(c) * w[0] + m[1].col(c) * w[1] + m[2].col(c) * w[2] + m[3].col(c) * w[3]
    };
    Mat4::from_cols(col(0), col(1), col(2), col(3))
}
