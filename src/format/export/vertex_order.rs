//! A face set's vertices in the order a reader numbers them.
//!
//! Our readers (and most others) number the vertices of an
//! `IndexedFaceSet` as the corners first use them and drop points no face
//! uses. A mesh built in memory (a primitive, an editor shape, a glTF
//! mesh) may list its vertices in another order, so its first export and
//! the export of that file re-read would differ. Writing the vertices in
//! first-use order makes export → import → export a fixed point from the
//! first write.

use crate::scene::Mesh;

/// `mesh`'s faces with their vertices renumbered in first-use order and
/// unused ones left out (positions and the per-vertex normals, colours and
/// texture coordinates that have one entry per position), or `None` when
/// the mesh already is in that order.
pub fn first_use_order(mesh: &Mesh) -> Option<Mesh> {
    let n = mesh.positions.len();
    let mut new_of_old = vec![u32::MAX; n];
    let mut old_of_new: Vec<u32> = Vec::with_capacity(n);
    let mut triangles = Vec::with_capacity(mesh.triangles.len());
    for t in &mesh.triangles {
        let mut out = [0u32; 3];
        for (k, &v) in t.iter().enumerate() {
            let slot = new_of_old.get_mut(v as usize)?;
            if *slot == u32::MAX {
                *slot = old_of_new.len() as u32;
                old_of_new.push(v);
            }
            out[k] = *slot;
        }
        triangles.push(out);
    }
    let in_order =
        old_of_new.len() == n && old_of_new.iter().enumerate().all(|(i, &v)| i == v as usize);
    if in_order {
        return None;
    }
    let pick = |list: &[glam::Vec3]| -> Vec<glam::Vec3> {
        if list.len() == n {
            old_of_new.iter().map(|&v| list[v as usize]).collect()
        } else {
            list.to_vec()
        }
    };
    let texcoords = if mesh.texcoords.len() == n {
        old_of_new
            .iter()
            .map(|&v| mesh.texcoords[v as usize])
            .collect()
    } else {
        mesh.texcoords.clone()
    };
    Some(Mesh {
        name: mesh.name.clone(),
        positions: pick(&mesh.positions),
        normals: pick(&mesh.normals),
        colors: pick(&mesh.colors),
        texcoords,
        triangles,
        solid: mesh.solid,
        ..Mesh::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Vec2, Vec3};

    #[test]
    fn renumbers_by_first_use_and_drops_unused_points() {
        let m = Mesh {
            positions: vec![Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE],
            normals: vec![Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE],
            texcoords: vec![Vec2::X, Vec2::Y, Vec2::ZERO, Vec2::ONE],
            triangles: vec![[2, 0, 1]],
            solid: true,
            ..Mesh::default()
        };
        let r = first_use_order(&m).expect("out of order");
        assert_eq!(r.positions, vec![Vec3::Z, Vec3::X, Vec3::Y]);
        assert_eq!(r.normals, r.positions);
        assert_eq!(r.texcoords, vec![Vec2::ZERO, Vec2::X, Vec2::Y]);
        assert_eq!(r.triangles, vec![[0, 1, 2]]);
        assert!(r.solid);
        // Already in order: nothing to do.
        assert!(first_use_order(&r).is_none());
    }

    #[test]
    fn out_of_range_indices_are_left_alone() {
        let m = Mesh {
            positions: vec![Vec3::X],
            triangles: vec![[0, 0, 5]],
            ..Mesh::default()
        };
        assert!(first_use_order(&m).is_none());
    }
}
