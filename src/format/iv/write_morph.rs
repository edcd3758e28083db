//! Morph targets in an Inventor file, written so that Coin plays them and
//! our reader gets the targets back.
//!
//! Inventor has no morph node, but its `Calculator` engine works on
//! multiple-value fields element by element (an input with fewer values
//! repeats its last one; Coin's `SoCalculator` documents it), so
//! `oA = A + a * B + b * C + …` with the base points in `A`, a target's
//! offsets in `B`, `C`… and its weights in `a`, `b`… is the morph
//! M = B + Σ wᵢ·Mᵢ (M3G, glTF) for every vertex at once. A Calculator has
//! eight vector inputs, so seven targets go in one and longer lists chain:
//! each Calculator's `A` is connected from the one before. The Coordinate3
//! (and the Normal, when targets move normals) keeps the base values and is
//! connected from the last Calculator's `oA`.
//!
//! A weight that changes is a `SelectOne` over its value at every frame,
//! indexed by the writer's frame clock, like every other animated field of
//! the file (so the morph steps at the scene's frame rate); one that does
//! not is a plain number. The reader (`iv::morph`) reads the targets and
//! these numbers (the default weights) back; the key note keeps the keys.

use crate::anim::{Property, TargetRef, Value};
use crate::format::export::text::{num, rows, vec3, Out};
use crate::scene::{Morphs, NodeId, Scene};
use glam::Vec3;
use std::fmt::Write as _;

/// Targets one Calculator adds (vector inputs B..H, weights a..g).
const PER_CALCULATOR: usize = 7;
const VECTORS: [char; 8] = ['A', 'B', 'C', 'D', 'E', 'F', 'G', 'H'];
const SCALARS: [char; 8] = ['a', 'b', 'c', 'd', 'e', 'f', 'g', 'h'];

/// One target's weight as the file gives it.
pub enum Weight {
    Constant(f32),
    /// The value at frames 0, 1, … (the writer's clock index), played by a
    /// SelectOne DEF'd as `name` where first written and USEd after (the
    /// Normal's chain shares the Coordinate3's weights).
    PerFrame {
        values: Vec<f32>,
        name: String,
        written: bool,
    },
}

/// The weights of shape `node`'s targets at frames `0..frames`: the mesh's
/// defaults, replaced target by target by the weights tracks that drive
/// the shape (its own, or its parent group's), later tracks winning, as
/// `anim::evaluate` applies them. Constant over time → [`Weight::Constant`];
/// `name` names the SelectOne of a changing one.
pub fn weights(
    scene: &Scene,
    node: NodeId,
    morphs: &Morphs,
    frames: usize,
    name: &mut dyn FnMut() -> String,
) -> Vec<Weight> {
    let parent = scene.node(node).parent;
    let drives =
        |of: TargetRef| of == TargetRef::Node(node) || parent.map(TargetRef::Node) == Some(of);
    let tracks: Vec<_> = scene
        .animation
        .tracks
        .iter()
        .filter(|t| t.target.property == Property::MorphWeights && drives(t.target.of))
        .collect();
    let defaults = morphs.default_weights();
    let mut per_target = vec![Vec::with_capacity(frames); defaults.len()];
    for f in 0..frames {
        let mut w = defaults.to_vec();
        for t in &tracks {
            if let Value::Weights(k) = t.sample(f as f32) {
                for (o, v) in w.iter_mut().zip(k.as_slice()) {
                    *o = *v;
                }
            }
        }
        for (list, v) in per_target.iter_mut().zip(w) {
            list.push(v);
        }
    }
    per_target
        .into_iter()
        .zip(defaults)
        .map(|(list, &d)| {
            if tracks.is_empty() || list.iter().all(|v| v.to_bits() == list[0].to_bits()) {
                Weight::Constant(list.first().copied().unwrap_or(d))
            } else {
                Weight::PerFrame {
                    values: list,
                    name: name(),
                    written: false,
                }
            }
        })
        .collect()
}

/// Writes `field [ base ] = Calculator { … } .oA`: the base values and the
/// chain of Calculators adding `offsets[i]` × weight i. `clock` writes the
/// `index` line of a per-frame SelectOne (the writer's frame clock).
pub fn connected_field(
    out: &mut Out,
    field: &str,
    base: &[Vec3],
    offsets: &[&[Vec3]],
    weights: &mut [Weight],
    clock: &mut dyn FnMut(&mut Out),
) {
    let groups = offsets.len().div_ceil(PER_CALCULATOR);
    out.line(&format!("{field} ["));
    out.depth += 1;
    for r in rows(base, 4, |v| vec3(*v), ",") {
        out.line(&r);
    }
    out.depth -= 1;
    out.open("] = Calculator");
    calculator(out, groups.max(1) - 1, base, offsets, weights, clock);
    out.close("} .oA");
}

/// The body of the Calculator adding group `g`'s targets (and, through
/// `A`, every earlier group's).
fn calculator(
    out: &mut Out,
    g: usize,
    base: &[Vec3],
    offsets: &[&[Vec3]],
    weights: &mut [Weight],
    clock: &mut dyn FnMut(&mut Out),
) {
    if g == 0 {
        out.list("A", rows(base, 4, |v| vec3(*v), ","));
    } else {
        out.line("A [ ] = Calculator {");
        out.depth += 1;
        calculator(out, g - 1, base, offsets, weights, clock);
        out.close("} .oA");
    }
    let first = g * PER_CALCULATOR;
    let last = (first + PER_CALCULATOR).min(offsets.len());
    let mut expression = String::from("oA = A");
    for (k, i) in (first..last).enumerate() {
        let (v, s) = (VECTORS[k + 1], SCALARS[k]);
        out.list(&v.to_string(), rows(offsets[i], 4, |v| vec3(*v), ","));
        match &mut weights[i] {
            Weight::Constant(w) => out.line(&format!("{s} {}", num(*w))),
            Weight::PerFrame {
                values,
                name,
                written: true,
            } => out.line(&format!("{s} {} = USE {name} .output", num(values[0]))),
            Weight::PerFrame {
                values,
                name,
                written,
            } => {
                *written = true;
                out.line(&format!("{s} {} = DEF {name} SelectOne {{", num(values[0])));
                out.depth += 1;
                out.line("type MFFloat");
                out.list("input", rows(values, 8, |v| num(*v), ","));
                clock(out);
                out.close("} .output");
            }
        }
        let _ = write!(expression, " + {s} * {v}");
    }
    out.line(&format!("expression \"{expression}\""));
}
