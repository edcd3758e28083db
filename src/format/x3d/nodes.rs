//! X3D nodes mapped onto the VRML97 nodes the scene builder knows, as each
//! node is parsed (classic) or read (XML): one builder serves VRML97 and
//! both X3D encodings.
//!
//! * Geometry (ISO/IEC 19775-1 §11.4 Rendering, §13.3 Geometry3D):
//!   IndexedTriangleSet, TriangleSet, (Indexed)TriangleFanSet,
//!   (Indexed)TriangleStripSet, (Indexed)QuadSet → IndexedFaceSet with the
//!   faces spelled out (strips alternate their winding, fans share their
//!   first vertex); per-vertex attributes follow the coordinates as in
//!   X3D, per-face ones count triangles (quads for the quad sets). Smooth
//!   normals are made when `normalPerVertex` is TRUE and none are given
//!   (creaseAngle π), flat ones otherwise. LineSet → IndexedLineSet.
//! * ColorRGBA → Color (alpha is not drawn: vertex colours are opaque here),
//!   CoordinateDouble → Coordinate, MultiTextureCoordinate and MultiTexture
//!   → their first member.
//! * Materials: PhysicalMaterial, UnlitMaterial and TwoSidedMaterial →
//!   Material through [`super::material`]; an X3D 4 material texture
//!   (baseTexture, diffuseTexture, emissiveTexture) becomes the
//!   Appearance's texture when the Appearance has none.
//! * Grouping: StaticGroup → Group; X3D's Switch and LOD `children` →
//!   VRML97's `choice` and `level`; H-Anim (ISO/IEC 19774) humanoids,
//!   joints, sites → Transform and segments → Group (each marked with a
//!   `hanim` field naming what it was), so characters load as joint
//!   hierarchies that `vrml97::hanim` then reads as skins and morphs.
//! * TextureBackground → Background (ImageTexture faces → the *Url fields).
//! * UNIT angle (§4.3.6): every angle field is converted to radians here;
//!   UNIT length is applied once to the whole scene by the reader.

use super::material;
use crate::format::lexer::Pos;
use crate::format::syntax::{AstNode, Field, NodeRef, Value, X3dHead};

type Warnings = Vec<(Pos, String)>;

/// The node rewrite the X3D readers run on every node (see the module doc).
pub fn rewrite(n: &mut AstNode, head: &X3dHead, warnings: &mut Warnings) {
    // A field still waiting for its PROTO instance's value: rewrite the
    // node once the value is bound (the PROTO expansion calls us again).
    if n.fields.iter().any(|f| matches!(f.value, Value::Is(_))) {
        return;
    }
    let angle = head.factor("angle");
    if angle != 1.0 {
        convert_angles(n, angle);
    }
    match n.kind.as_str() {
        "IndexedTriangleSet"
        | "TriangleSet"
        | "IndexedTriangleFanSet"
        | "TriangleFanSet"
        | "IndexedTriangleStripSet"
        | "TriangleStripSet"
        | "IndexedQuadSet"
        | "QuadSet" => face_set(n, warnings),
        "LineSet" => line_set(n),
        "ColorRGBA" => color_rgba(n, warnings),
        "CoordinateDouble" => n.kind = "Coordinate".into(),
        "MultiTextureCoordinate" => first_member(n, "texCoord", warnings),
        "MultiTexture" => first_member(n, "texture", warnings),
        "PhysicalMaterial" | "UnlitMaterial" | "TwoSidedMaterial" => {
            material::to_material(n, warnings)
        }
        "Appearance" => appearance(n),
        "StaticGroup" => n.kind = "Group".into(),
        "Switch" => rename(n, "children", "choice"),
        "LOD" => rename(n, "children", "level"),
        "HAnimHumanoid" => humanoid(n),
        "HAnimJoint" | "HAnimSite" => hanim(n, "Transform"),
        "HAnimSegment" => hanim(n, "Group"),
        "HAnimDisplacer" => mark_hanim(n),
        "TextureBackground" => texture_background(n),
        _ => {}
    }
}

fn take(n: &mut AstNode, name: &str) -> Option<Value> {
    let mut out = None;
    n.fields.retain(|f| {
        if f.name == name {
            out = Some(f.value.clone());
            false
        } else {
            true
        }
    });
    out
}

fn set(n: &mut AstNode, name: &str, value: Value) {
    n.fields.retain(|f| f.name != name);
    let pos = n.pos;
    n.fields.push(Field {
        name: name.into(),
        value,
        pos,
    });
}

fn rename(n: &mut AstNode, from: &str, to: &str) {
    if n.field(to).is_none() {
        for f in n.fields.iter_mut().filter(|f| f.name == from) {
            f.name = to.into();
        }
    }
}

fn ints(v: Option<&[f64]>) -> Vec<i64> {
    v.unwrap_or(&[])
        .iter()
        .map(|x| if x.is_finite() { *x as i64 } else { -1 })
        .collect()
}

/// Splits an index list at negative entries.
fn runs(index: &[i64]) -> Vec<Vec<i64>> {
    index
        .split(|i| *i < 0)
        .filter(|r| !r.is_empty())
        .map(|r| r.to_vec())
        .collect()
}

/// Consecutive runs of the given lengths over 0..; stops at `total`.
fn counted(counts: &[i64], total: usize) -> Vec<Vec<i64>> {
    let mut out = Vec::new();
    let mut at = 0i64;
    for &c in counts {
        if c <= 0 || at as usize >= total {
            continue;
        }
        let end = (at + c).min(total as i64);
        out.push((at..end).collect());
        at = end;
    }
    out
}

fn coord_count(n: &AstNode) -> usize {
    n.node("coord")
        .map(|c| c.effective())
        .and_then(|c| c.nums("point").map(|p| p.len() / 3))
        .unwrap_or(0)
}

fn fan(v: &[i64], out: &mut Vec<[i64; 3]>) {
    for i in 1..v.len().saturating_sub(1) {
        out.push([v[0], v[i], v[i + 1]]);
    }
}

fn strip(v: &[i64], out: &mut Vec<[i64; 3]>) {
    for i in 0..v.len().saturating_sub(2) {
        if i % 2 == 0 {
            out.push([v[i], v[i + 1], v[i + 2]]);
        } else {
            out.push([v[i + 1], v[i], v[i + 2]]);
        }
    }
}

/// The triangle and quad sets → IndexedFaceSet.
fn face_set(n: &mut AstNode, warnings: &mut Warnings) {
    let kind = n.kind.clone();
    let total = coord_count(n);
    let index = ints(n.nums("index"));
    let mut faces: Vec<Vec<i64>> = Vec::new();
    let mut tris: Vec<[i64; 3]> = Vec::new();
    let chunks = |idx: &[i64], k: usize, faces: &mut Vec<Vec<i64>>| -> bool {
        for c in idx.chunks(k) {
            if c.len() == k {
                faces.push(c.to_vec());
            }
        }
        !idx.len().is_multiple_of(k)
    };
    let leftover = match kind.as_str() {
        "IndexedTriangleSet" => chunks(&index, 3, &mut faces),
        "TriangleSet" => chunks(&(0..total as i64).collect::<Vec<_>>(), 3, &mut faces),
        "IndexedQuadSet" => chunks(&index, 4, &mut faces),
        "QuadSet" => chunks(&(0..total as i64).collect::<Vec<_>>(), 4, &mut faces),
        "IndexedTriangleFanSet" => {
            runs(&index).iter().for_each(|r| fan(r, &mut tris));
            false
        }
        "TriangleFanSet" => {
            let counts = ints(n.nums("fanCount"));
            counted(&counts, total)
                .iter()
                .for_each(|r| fan(r, &mut tris));
            false
        }
        "IndexedTriangleStripSet" => {
            runs(&index).iter().for_each(|r| strip(r, &mut tris));
            false
        }
        _ => {
            let counts = ints(n.nums("stripCount"));
            counted(&counts, total)
                .iter()
                .for_each(|r| strip(r, &mut tris));
            false
        }
    };
    if leftover {
        warnings.push((
            n.pos,
            format!("{kind}: the last incomplete face is ignored"),
        ));
    }
    faces.extend(tris.into_iter().map(|t| t.to_vec()));
    let mut coord_index = Vec::with_capacity(faces.len() * 4);
    for f in faces {
        coord_index.extend(f.iter().map(|&i| i as f64));
        coord_index.push(-1.0);
    }
    for f in ["index", "fanCount", "stripCount"] {
        take(n, f);
    }
    let smooth = n.bool("normalPerVertex", true) && n.node("normal").is_none();
    n.kind = "IndexedFaceSet".into();
    set(n, "coordIndex", Value::Nums(coord_index));
    let crease = if smooth { std::f64::consts::PI } else { 0.0 };
    set(n, "creaseAngle", Value::Nums(vec![crease]));
}

/// LineSet (§11.4.8) → IndexedLineSet.
fn line_set(n: &mut AstNode) {
    let counts = ints(n.nums("vertexCount"));
    let total = coord_count(n);
    let mut idx = Vec::new();
    for r in counted(&counts, total) {
        idx.extend(r.iter().map(|&i| i as f64));
        idx.push(-1.0);
    }
    take(n, "vertexCount");
    n.kind = "IndexedLineSet".into();
    set(n, "coordIndex", Value::Nums(idx));
}

fn color_rgba(n: &mut AstNode, warnings: &mut Warnings) {
    let rgba = n.nums("color").unwrap_or(&[]).to_vec();
    if rgba.chunks_exact(4).any(|c| c[3] < 1.0) {
        warnings.push((
            n.pos,
            "ColorRGBA: alpha is not drawn (vertex colours are opaque in animed)".into(),
        ));
    }
    let rgb: Vec<f64> = rgba
        .chunks_exact(4)
        .flat_map(|c| [c[0], c[1], c[2]])
        .collect();
    n.kind = "Color".into();
    set(n, "color", Value::Nums(rgb));
}

/// MultiTextureCoordinate / MultiTexture → their first member.
fn first_member(n: &mut AstNode, field: &str, warnings: &mut Warnings) {
    let members = n.nodes(field).to_vec();
    let Some(first) = members.first().map(|m| m.effective()) else {
        return;
    };
    if members.len() > 1 {
        warnings.push((
            n.pos,
            format!(
                "{}: only the first of {} members is used",
                n.kind,
                members.len()
            ),
        ));
    }
    n.kind = first.kind.clone();
    n.fields = first.fields.clone();
}

/// An X3D 4 material texture becomes the Appearance's texture.
fn appearance(n: &mut AstNode) {
    if n.node("texture").is_some() {
        return;
    }
    let Some(m) = n.node("material").map(|m| m.effective()) else {
        return;
    };
    let tex: Option<NodeRef> = ["baseTexture", "diffuseTexture", "emissiveTexture"]
        .iter()
        .find_map(|f| m.node(f).cloned());
    if let Some(t) = tex {
        set(n, "texture", Value::Nodes(vec![t]));
    }
}

/// HAnimHumanoid (ISO/IEC 19774-1 §6.3.5) → a Transform over its
/// skeleton, skin and viewpoints (the joints/segments/sites lists repeat
/// nodes of the skeleton and are not followed).
fn humanoid(n: &mut AstNode) {
    let mut children = Vec::new();
    for f in ["skeleton", "humanoidBody", "skin", "viewpoints"] {
        children.extend(n.nodes(f).iter().cloned());
    }
    hanim(n, "Transform");
    set(n, "children", Value::Nodes(children));
}

/// An H-Anim node becomes `kind`, remembering what it was in a `hanim`
/// field: `vrml97::hanim` reads humanoids, joints and displacers as skins
/// and morphs once the tree is built.
fn hanim(n: &mut AstNode, kind: &str) {
    mark_hanim(n);
    n.kind = kind.into();
}

fn mark_hanim(n: &mut AstNode) {
    let was = Value::Words(vec![n.kind.clone()]);
    set(n, "hanim", was);
}

/// TextureBackground (§24.4.4) → Background with url fields.
fn texture_background(n: &mut AstNode) {
    n.kind = "Background".into();
    for face in ["front", "back", "left", "right", "top", "bottom"] {
        let Some(t) = take(n, &format!("{face}Texture")) else {
            continue;
        };
        if let Value::Nodes(ns) = t {
            if let Some(img) = ns.first().map(|t| t.effective()) {
                let urls = img.strings("url");
                if !urls.is_empty() {
                    set(n, &format!("{face}Url"), Value::Strs(urls));
                }
            }
        }
    }
}

/// UNIT angle: the angle fields of a node, from the file's unit to radians.
fn convert_angles(n: &mut AstNode, f: f64) {
    let kind = n.kind.clone();
    for field in n.fields.iter_mut() {
        let Value::Nums(v) = &mut field.value else {
            continue;
        };
        let every_4th = match (kind.as_str(), field.name.as_str()) {
            ("TextureTransform", "rotation") => false,
            (_, "rotation" | "scaleOrientation") => true,
            ("Viewpoint" | "OrthoViewpoint" | "Extrusion", "orientation") => true,
            (k, "keyValue") if k.ends_with("OrientationInterpolator") => true,
            (_, "beamWidth" | "cutOffAngle" | "creaseAngle" | "skyAngle" | "groundAngle") => false,
            ("Viewpoint", "fieldOfView") => false,
            _ => continue,
        };
        if every_4th {
            for c in v.chunks_exact_mut(4) {
                c[3] *= f;
            }
        } else {
            v.iter_mut().for_each(|x| *x *= f);
        }
    }
}
