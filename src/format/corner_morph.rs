//! Morph targets between two builds of one polygon set: the base points
//! and the same faces over moved points (a CoordinateInterpolator key, an
//! Inventor Calculator target). The mesh builder welds corners into
//! vertices by value, so two builds may number their vertices differently;
//! following each base vertex's first face corner into the other build
//! (not matching by position) pairs them.

use crate::scene::{Mesh, MorphTarget};

/// The first face corner of every vertex of a base build.
pub struct Corners {
    first: Vec<usize>,
    corners: usize,
}

impl Corners {
    /// `corners`: the output vertex of each face corner of the base build
    /// (`polygons::build_textured_corners`), `vertices` its vertex count.
    pub fn new(vertices: usize, corners: &[u32]) -> Corners {
        let mut first = vec![usize::MAX; vertices];
        for (c, &v) in corners.iter().enumerate() {
            if let Some(f) = first.get_mut(v as usize) {
                if *f == usize::MAX {
                    *f = c;
                }
            }
        }
        Corners {
            first,
            corners: corners.len(),
        }
    }

    /// The target moving `base` onto `key` (the same faces built from moved
    /// points, `key_corners` its corners): position offsets, and normal
    /// offsets when both builds have normals.
    pub fn target(
        &self,
        name: String,
        base: &Mesh,
        key: &Mesh,
        key_corners: &[u32],
    ) -> Result<MorphTarget, String> {
        if key_corners.len() != self.corners {
            return Err(format!("{name} makes a different mesh"));
        }
        let at = |v: usize| -> Result<usize, String> {
            let c = self.first.get(v).copied().unwrap_or(usize::MAX);
            key_corners
                .get(c.min(key_corners.len().saturating_sub(1)))
                .map(|&k| k as usize)
                .filter(|&k| k < key.positions.len())
                .ok_or_else(|| format!("{name} makes a different mesh"))
        };
        let mut dp = Vec::with_capacity(base.positions.len());
        for (v, p) in base.positions.iter().enumerate() {
            dp.push(key.positions[at(v)?] - *p);
        }
        let with_normals =
            base.normals.len() == base.positions.len() && key.normals.len() == key.positions.len();
        let mut dn = Vec::new();
        if with_normals {
            dn.reserve(base.normals.len());
            for (v, n) in base.normals.iter().enumerate() {
                dn.push(key.normals[at(v)?] - *n);
            }
        }
        Ok(MorphTarget::new(name, dp, dn))
    }
}
