//! H-Anim humanoids (ISO/IEC 19774: the H-Anim 1.1 VRML97 PROTOs
//! Humanoid/Joint/Segment/Site/Displacer and X3D's HAnimHumanoid/HAnimJoint/
//! HAnimSegment/HAnimSite/HAnimDisplacer) as skins over their joints.
//!
//! The builder has already made the joints ordinary Transforms (the PROTO
//! bodies say so in VRML97; `x3d::nodes` maps X3D's nodes), so a character
//! plays as a rigid hierarchy. This pass, run once the tree is built, adds
//! what makes it a character in the scene model:
//! * every humanoid becomes a [`Skin`] over its joints (the `joints` list,
//!   or the Joint nodes of its skeleton in tree order), so the joints are
//!   known as joints (`Scene::is_joint`) and the skeleton root is named;
//! * a skinned humanoid (`skinCoord` + per-joint `skinCoordIndex` /
//!   `skinCoordWeight`) binds the shapes that draw `skinCoord` to that
//!   skin: each joint's inverse bind matrix is inverse(joint world at rest)
//!   · (skin shape world at rest), so at rest the skin is where the file
//!   puts it and each vertex then follows Σ w·(joint now · joint at rest⁻¹),
//!   the linear blend skinning of ISO/IEC 19774-1 §4.9.2 (in glTF's
//!   terms, which `anim::skinning` evaluates);
//! * a Displacer (`coordIndex` + `displacements`, X3D's `weight`) on a
//!   Segment's `coord` (or a skinned Joint's, on `skinCoord`) becomes a
//!   morph target of the meshes drawing those points, its default weight
//!   the displacer's `weight` (1 in H-Anim 1.1, which has none).

use super::build::Builder;
use super::geometry;
use crate::format::lexer::Pos;
use crate::format::syntax::{AstNode, NodeRef, Value};
use crate::scene::{MeshId, MorphTarget, Morphs, NodeId, NodeKind, Scene, Skin, SkinWeights};
use glam::{Mat4, Vec3};
use std::collections::HashSet;
use std::rc::Rc;

/// The H-Anim role of a parsed node: the PROTO name (VRML97) or the X3D
/// node type `x3d::nodes` recorded before mapping it.
fn role(n: &AstNode) -> Option<&str> {
    let kind = match n.value("hanim") {
        Some(Value::Words(w)) => w.first().map(String::as_str)?,
        _ if n.proto.is_some() => n.kind.as_str(),
        _ => return None,
    };
    Some(kind.strip_prefix("HAnim").unwrap_or(kind))
        .filter(|k| matches!(*k, "Humanoid" | "Joint" | "Segment" | "Site" | "Displacer"))
}

/// Every node reachable from `roots` (fields and PROTO bodies), each once,
/// in file order; iterative, so deep files cost no stack.
fn all_nodes(roots: &[NodeRef]) -> Vec<NodeRef> {
    let mut seen: HashSet<*const AstNode> = HashSet::new();
    let mut out = Vec::new();
    let mut stack: Vec<NodeRef> = roots.iter().rev().cloned().collect();
    while let Some(n) = stack.pop() {
        if !seen.insert(Rc::as_ptr(&n)) {
            continue;
        }
        let mut below: Vec<NodeRef> = Vec::new();
        for f in &n.fields {
            if let Value::Nodes(ns) = &f.value {
                below.extend(ns.iter().cloned());
            }
        }
        if let Some(p) = &n.proto {
            below.push(p.root.clone());
        }
        stack.extend(below.into_iter().rev());
        out.push(n);
    }
    out
}

/// Adds the skins (and displacer morphs) of every humanoid in the file.
pub fn import(b: &mut Builder, roots: &[NodeRef]) {
    let nodes = all_nodes(roots);
    for h in nodes.iter().filter(|n| role(n) == Some("Humanoid")) {
        humanoid(b, h);
    }
    for s in nodes.iter().filter(|n| role(n) == Some("Segment")) {
        if let Some(coord) = s.node("coord").map(|c| c.effective()) {
            displacers(b, s, &coord);
        }
    }
}

/// The first scene node built for an AST node.
fn scene_node(b: &Builder, n: &NodeRef) -> Option<NodeId> {
    b.instances.get(&Rc::as_ptr(n))?.first().copied()
}

/// A node's world matrix from the transforms as read (the rest pose).
fn rest_world(scene: &Scene, id: NodeId) -> Mat4 {
    let mut m = Mat4::IDENTITY;
    let mut at = Some(id);
    while let Some(i) = at {
        let n = scene.node(i);
        m = n.transform.matrix() * m;
        at = n.parent;
    }
    m
}

/// The humanoid's joints: its `joints` list, else the Joint nodes under
/// its skeleton (`skeleton` in X3D, `humanoidBody` in H-Anim 1.1).
fn joint_nodes(h: &NodeRef) -> Vec<NodeRef> {
    let listed: Vec<NodeRef> = h.nodes("joints").to_vec();
    if !listed.is_empty() {
        return listed;
    }
    let mut roots: Vec<NodeRef> = h.nodes("skeleton").to_vec();
    roots.extend(h.nodes("humanoidBody").iter().cloned());
    all_nodes(&roots)
        .into_iter()
        .filter(|n| role(n) == Some("Joint"))
        .collect()
}

fn humanoid(b: &mut Builder, h: &NodeRef) {
    let name = h
        .def
        .clone()
        .or_else(|| h.strings("name").into_iter().next())
        .unwrap_or_else(|| "humanoid".into());
    let mut joints: Vec<(NodeRef, NodeId)> = Vec::new();
    for j in joint_nodes(h) {
        match scene_node(b, &j) {
            Some(id) if !joints.iter().any(|(_, k)| *k == id) => joints.push((j, id)),
            Some(_) => {}
            None => b.warn(
                j.pos,
                "H-Anim joint is not part of the humanoid's skeleton; left out of its skin",
            ),
        }
    }
    if joints.is_empty() {
        b.warn(
            h.pos,
            "H-Anim humanoid without joints; read as plain groups",
        );
        return;
    }
    for (j, id) in &joints {
        if b.scene.node(*id).name.is_empty() {
            if let Some(n) = j.strings("name").into_iter().find(|n| !n.is_empty()) {
                b.scene.node_mut(*id).name = n;
            }
        }
    }
    let ids: Vec<NodeId> = joints.iter().map(|(_, id)| *id).collect();
    let rest: Vec<Mat4> = ids.iter().map(|&j| rest_world(&b.scene, j)).collect();
    // The skeleton's root: the first joint none of the others holds.
    let root = ids
        .iter()
        .copied()
        .find(|&j| !ids.iter().any(|&k| k != j && is_under(&b.scene, j, k)));
    let body = scene_node(b, h).map_or(Mat4::IDENTITY, |id| rest_world(&b.scene, id));

    let skinned = skin_shapes(b, h, &joints, &rest, &name, root);
    if !skinned {
        // A skeleton only: the joints known as such, nothing deformed.
        add_skin(b, h.pos, &name, &ids, &rest, body, root);
    }
    // Joint displacers move the skin's own points.
    if let Some(coord) = h.node("skinCoord").map(|c| c.effective()) {
        for (j, _) in &joints {
            displacers(b, j, &coord);
        }
    }
}

/// Whether `node` lies under `ancestor`.
fn is_under(scene: &Scene, node: NodeId, ancestor: NodeId) -> bool {
    let mut at = scene.node(node).parent;
    while let Some(p) = at {
        if p == ancestor {
            return true;
        }
        at = scene.node(p).parent;
    }
    false
}

/// Adds a skin whose inverse bind matrices take `shape_world` space to
/// each joint's rest space; returns its id.
fn add_skin(
    b: &mut Builder,
    pos: Pos,
    name: &str,
    joints: &[NodeId],
    rest: &[Mat4],
    shape_world: Mat4,
    root: Option<NodeId>,
) -> Option<crate::scene::SkinId> {
    let ibm: Vec<Mat4> = rest.iter().map(|r| r.inverse() * shape_world).collect();
    let made = Skin::new(name, joints.to_vec(), ibm).and_then(|mut s| {
        s.skeleton = root;
        b.scene.add_skin(s)
    });
    match made {
        Ok(id) => Some(id),
        Err(e) => {
            b.warn(pos, &format!("H-Anim humanoid not read as a skin: {e}"));
            None
        }
    }
}

/// Binds the shapes drawing `skinCoord` to skins over `joints`; false when
/// the humanoid is not skinned (or its skin could not be bound).
fn skin_shapes(
    b: &mut Builder,
    h: &NodeRef,
    joints: &[(NodeRef, NodeId)],
    rest: &[Mat4],
    name: &str,
    root: Option<NodeId>,
) -> bool {
    let Some(coord) = h.node("skinCoord").map(|c| c.effective()) else {
        return false;
    };
    let points = coord.nums("point").map_or(0, |p| p.len() / 3);
    // Each point's (joint, weight) influences, from the joints' lists.
    let mut influences: Vec<Vec<(u16, f32)>> = vec![Vec::new(); points];
    for (ji, (j, _)) in joints.iter().enumerate() {
        let index = j.nums("skinCoordIndex").unwrap_or(&[]);
        let weight = j.nums("skinCoordWeight").unwrap_or(&[]);
        if !index.is_empty() && weight.len() != index.len() {
            b.warn(
                j.pos,
                &format!(
                    "H-Anim joint has {} skinCoordWeight values for {} skinCoordIndex values; missing weights count as 1",
                    weight.len(),
                    index.len()
                ),
            );
        }
        for (k, &i) in index.iter().enumerate() {
            let w = weight.get(k).copied().unwrap_or(1.0);
            let ok = i >= 0.0 && (i as usize) < points && w.is_finite() && w >= 0.0;
            if !ok {
                b.warn_once(
                    "hanim-skin-index",
                    j.pos,
                    "H-Anim skinCoordIndex past the skinCoord points or a bad weight; skipped",
                );
                continue;
            }
            if w > 0.0 {
                influences[i as usize].push((ji as u16, w as f32));
            }
        }
    }
    let users = b.coord_users.get(&Rc::as_ptr(&coord)).cloned();
    let Some(users) = users.filter(|u| !u.is_empty()) else {
        b.warn(
            h.pos,
            "H-Anim skinCoord is drawn by no IndexedFaceSet; the humanoid is read unskinned",
        );
        return false;
    };
    let ids: Vec<NodeId> = joints.iter().map(|(_, id)| *id).collect();
    let mut bound = false;
    for (geom, textured, mesh) in users {
        if bind_mesh(b, &geom, textured, mesh, &influences).is_err() {
            continue;
        }
        // One skin per distinct shape placement (the bind matrices hold it).
        let shapes = shapes_of(&b.scene, mesh);
        let mut made: Vec<(Mat4, crate::scene::SkinId)> = Vec::new();
        for s in shapes {
            let world = rest_world(&b.scene, s);
            let skin = match made.iter().find(|(w, _)| *w == world) {
                Some((_, k)) => Some(*k),
                None => {
                    let k = add_skin(b, h.pos, name, &ids, rest, world, root);
                    if let Some(k) = k {
                        made.push((world, k));
                    }
                    k
                }
            };
            b.scene.node_mut(s).skin = skin;
            bound |= skin.is_some();
        }
    }
    bound
}

/// Gives one mesh its per-vertex influences from the per-point ones.
fn bind_mesh(
    b: &mut Builder,
    geom: &NodeRef,
    textured: bool,
    mesh: MeshId,
    influences: &[Vec<(u16, f32)>],
) -> Result<(), ()> {
    let fail = |b: &mut Builder, e: String| {
        b.warn(geom.pos, &format!("H-Anim skin not bound: {e}"));
    };
    let of_vertex = match geometry::ifs_vertex_points(geom, textured) {
        Ok(v) => v,
        Err(e) => {
            fail(b, e);
            return Err(());
        }
    };
    if of_vertex.len() != b.scene.meshes[mesh.0 as usize].positions.len() {
        fail(b, "its mesh was built differently".into());
        return Err(());
    }
    let made = SkinWeights::from_influences(of_vertex.len(), |v, out| {
        if let Some(inf) = influences.get(of_vertex[v] as usize) {
            out.extend_from_slice(inf);
        }
    });
    match made {
        Ok((w, report)) => {
            if report.over_four > 0 {
                let msg = format!(
                    "{} skin vertices have more than 4 joint influences; the 4 largest are kept",
                    report.over_four
                );
                b.warn(geom.pos, &msg);
            }
            b.scene.meshes[mesh.0 as usize].skin_weights = Some(Box::new(w));
            Ok(())
        }
        Err(e) => {
            fail(b, e.to_string());
            Err(())
        }
    }
}

/// The shape nodes drawing `mesh`.
fn shapes_of(scene: &Scene, mesh: MeshId) -> Vec<NodeId> {
    (0..scene.nodes.len())
        .map(|i| NodeId(i as u32))
        .filter(|&id| matches!(&scene.node(id).kind, NodeKind::Shape(s) if s.mesh == mesh))
        .collect()
}

/// The displacers of `owner` (a Segment over its `coord`, or a Joint over
/// the humanoid's `skinCoord`) as morph targets of the meshes drawing
/// `coord`.
fn displacers(b: &mut Builder, owner: &NodeRef, coord: &NodeRef) {
    let list: Vec<NodeRef> = owner
        .nodes("displacers")
        .iter()
        .filter(|d| role(d) == Some("Displacer"))
        .cloned()
        .collect();
    if list.is_empty() {
        return;
    }
    let points = coord.nums("point").map_or(0, |p| p.len() / 3);
    let users = b.coord_users.get(&Rc::as_ptr(coord)).cloned();
    let Some(users) = users.filter(|u| !u.is_empty()) else {
        b.warn(
            owner.pos,
            "H-Anim displacers move points no IndexedFaceSet draws; skipped",
        );
        return;
    };
    // Per displacer: name, default weight, per-point displacement.
    let mut per_point: Vec<(String, f32, Vec<Vec3>)> = Vec::new();
    for d in &list {
        let index = d.nums("coordIndex").unwrap_or(&[]);
        let moves = d.nums("displacements").unwrap_or(&[]);
        let mut delta = vec![Vec3::ZERO; points];
        for (k, &i) in index.iter().enumerate() {
            let (Some(m), true) = (
                moves.get(3 * k..3 * k + 3),
                i >= 0.0 && (i as usize) < points,
            ) else {
                b.warn_once(
                    "hanim-displacer",
                    d.pos,
                    "H-Anim displacer index past its points or without a displacement; skipped",
                );
                continue;
            };
            delta[i as usize] = Vec3::new(m[0] as f32, m[1] as f32, m[2] as f32);
        }
        let name = d
            .strings("name")
            .into_iter()
            .find(|s| !s.is_empty())
            .or_else(|| d.def.clone())
            .unwrap_or_else(|| format!("displacer_{}", per_point.len()));
        let weight = d.num("weight").unwrap_or(1.0) as f32;
        per_point.push((name, weight, delta));
    }
    for (geom, textured, mesh) in users {
        let m = &b.scene.meshes[mesh.0 as usize];
        if m.morph.is_some() {
            b.warn(
                owner.pos,
                "H-Anim displacers on a mesh that already morphs; skipped",
            );
            continue;
        }
        let of_vertex = match geometry::ifs_vertex_points(&geom, textured) {
            Ok(v) if v.len() == m.positions.len() => v,
            _ => {
                b.warn(owner.pos, "H-Anim displacers: mesh not followed; skipped");
                continue;
            }
        };
        let targets: Vec<MorphTarget> = per_point
            .iter()
            .map(|(name, _, delta)| {
                let dp = of_vertex
                    .iter()
                    .map(|&p| delta.get(p as usize).copied().unwrap_or(Vec3::ZERO))
                    .collect();
                MorphTarget::new(name.clone(), dp, Vec::new())
            })
            .collect();
        let weights: Vec<f32> = per_point.iter().map(|(_, w, _)| *w).collect();
        match Morphs::new(of_vertex.len(), targets, weights) {
            Ok(m) => b.scene.meshes[mesh.0 as usize].morph = Some(Box::new(m)),
            Err(e) => b.warn(owner.pos, &format!("H-Anim displacers not read: {e}")),
        }
    }
}
