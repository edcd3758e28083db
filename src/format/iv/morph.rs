//! Morph targets read from Calculator engines: a Coordinate3 `point` (or a
//! Normal `vector`) connected from a Calculator whose expression is
//! `oA = A + a * B + b * C + …` adds each vector input times its weight to
//! the base values, which is the morph M = B + Σ wᵢ·Mᵢ. This is how
//! animed's writer carries a morph in Inventor (`write_morph`); the
//! engines themselves are not evaluated (the targets' weights come back as
//! the Calculator's numbers, their keys from the key note).
//!
//! Any other connection is left alone (the parser already said engines are
//! not evaluated). Counts are checked against the base: the numbers were
//! charged to the input budget when parsed, and at most
//! [`MAX_MORPH_TARGETS`] targets are kept.

use crate::anim::MAX_MORPH_TARGETS;
use crate::format::syntax::AstNode;
use glam::Vec3;

/// Longest chain of Calculators followed through their `A` inputs.
const MAX_CHAIN: usize = MAX_MORPH_TARGETS;

/// Targets a connected field carries.
#[derive(Debug, PartialEq)]
pub struct Targets {
    /// One offset per base value, per target.
    pub offsets: Vec<Vec<Vec3>>,
    /// The weights the Calculators hold (the morph's default weights).
    pub weights: Vec<f32>,
}

/// The targets field `field` of `node` is connected from, when it is the
/// `oA` output of such a Calculator chain (`Ok(None)` when the field is not
/// connected, or from something else). `count` is the number of base values:
/// every target must have that many.
pub fn targets(node: &AstNode, field: &str, count: usize) -> Result<Option<Targets>, String> {
    let Some((engine, "oA")) = node.connection(field) else {
        return Ok(None);
    };
    let mut chain = Vec::new();
    let mut calc = engine.clone();
    loop {
        let Some(terms) = terms(&calc) else {
            return Ok(None);
        };
        chain.push((calc.clone(), terms));
        if chain.len() > MAX_CHAIN {
            return Err(format!("more than {MAX_CHAIN} chained Calculators"));
        }
        match calc.connection("A") {
            Some((prev, "oA")) => calc = prev.clone(),
            Some(_) => return Ok(None),
            None => break,
        }
    }
    // The first Calculator (the end of the chain) adds the first targets.
    let mut out = Targets {
        offsets: Vec::new(),
        weights: Vec::new(),
    };
    for (calc, terms) in chain.iter().rev() {
        for (weight, vector) in terms {
            if out.offsets.len() == MAX_MORPH_TARGETS {
                return Err(format!(
                    "more than {MAX_MORPH_TARGETS} morph targets (animed's limit per mesh)"
                ));
            }
            let v = calc.nums(&vector.to_string()).unwrap_or(&[]);
            if v.len() != 3 * count {
                return Err(format!(
                    "morph target {} has {} values for the {count} of the base",
                    out.offsets.len(),
                    v.len() / 3
                ));
            }
            let offsets: Vec<Vec3> = v
                .chunks_exact(3)
                .map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32))
                .collect();
            if offsets.iter().any(|o| !o.is_finite()) {
                return Err(format!(
                    "morph target {} has a value that is not finite",
                    out.offsets.len()
                ));
            }
            out.offsets.push(offsets);
            let w = calc.f32(&weight.to_string(), 0.0);
            out.weights.push(if w.is_finite() { w } else { 0.0 });
        }
    }
    Ok(Some(out))
}

/// The (weight, vector) input pairs of a Calculator whose expression is
/// exactly `oA = A + w * V + …` (either order of each product), or None.
fn terms(calc: &AstNode) -> Option<Vec<(char, char)>> {
    if calc.kind != "Calculator" {
        return None;
    }
    let exprs = calc.strings("expression");
    let [expr] = exprs.as_slice() else {
        return None;
    };
    let compact: String = expr.chars().filter(|c| !c.is_whitespace()).collect();
    let rest = compact.strip_prefix("oA=A")?;
    if rest.is_empty() {
        return Some(Vec::new());
    }
    let mut out = Vec::new();
    for term in rest.strip_prefix('+')?.split('+') {
        let b = term.as_bytes();
        let (w, v) = match b {
            [x, b'*', y] if x.is_ascii_lowercase() => (*x, *y),
            [y, b'*', x] if x.is_ascii_lowercase() => (*x, *y),
            _ => return None,
        };
        let ok = (b'a'..=b'h').contains(&w) && (b'B'..=b'H').contains(&v);
        if !ok || out.iter().any(|&(_, u)| u == v as char) {
            return None;
        }
        out.push((w as char, v as char));
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::syntax::{parse, Options};

    fn coordinate(text: &str) -> crate::format::syntax::NodeRef {
        let parsed = parse(text.as_bytes(), Options::new(false));
        assert!(parsed.error.is_none(), "{:?}", parsed.error);
        parsed.roots[0].clone()
    }

    #[test]
    fn a_calculator_chain_gives_its_targets_in_order() {
        let c = coordinate(
            "Coordinate3 { point [ 0 0 0, 1 0 0 ] = Calculator {
               A [ ] = Calculator { A [ 0 0 0, 1 0 0 ] B [ 1 0 0, 1 0 0 ] a 0.5
                                    expression \"oA = A + a * B\" } .oA
               C [ 0 2 0, 0 2 0 ] b 0.25 expression \"oA = A + C*b\" } .oA }",
        );
        let t = targets(&c, "point", 2).unwrap().unwrap();
        assert_eq!(t.offsets, vec![vec![Vec3::X; 2], vec![Vec3::Y * 2.0; 2]]);
        assert_eq!(t.weights, vec![0.5, 0.25]);
    }

    #[test]
    fn other_connections_are_not_morphs_and_bad_counts_are_errors() {
        let other = coordinate(
            "Coordinate3 { point [ 0 0 0 ] = Calculator { A [ 1 1 1 ] expression \"oA = A * 2\" } .oA }",
        );
        assert_eq!(targets(&other, "point", 1), Ok(None));
        let plain = coordinate("Coordinate3 { point [ 0 0 0 ] }");
        assert_eq!(targets(&plain, "point", 1), Ok(None));
        let short = coordinate(
            "Coordinate3 { point [ 0 0 0, 1 1 1 ] = Calculator { A [ ] B [ 1 1 1 ] expression \"oA = A + a*B\" } .oA }",
        );
        let e = targets(&short, "point", 2).unwrap_err();
        assert!(e.contains("has 1 values for the 2"), "{e}");
    }
}
