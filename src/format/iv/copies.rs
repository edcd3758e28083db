//! Where Inventor's `Array` and `MultipleCopy` draw their children: one
//! matrix per copy (the Inventor Mentor, ch. 3 "SoArray and
//! SoMultipleCopy"; Coin's SoArray/SoMultipleCopy). Each copy is traversed
//! like a Separator, so the builder makes one group per copy.

use crate::format::syntax::AstNode;
use glam::{Mat4, Vec3};

/// Most copies one node makes (a hostile `numElements1 1e9` is cut here;
/// the node budget bounds what the copies then build).
pub const MAX_COPIES: usize = 65_536;

/// The matrix of every copy `n` (an `Array` or `MultipleCopy`) makes, in
/// traversal order, and whether the list was cut at [`MAX_COPIES`].
pub fn copies(n: &AstNode) -> (Vec<Mat4>, bool) {
    match n.kind.as_str() {
        "MultipleCopy" => {
            let nums = n.nums("matrix").unwrap_or(&[]);
            let all: Vec<Mat4> = nums
                .chunks_exact(16)
                .map(|c| {
                    let mut a = [0.0f32; 16];
                    for (d, s) in a.iter_mut().zip(c) {
                        *d = *s as f32;
                    }
                    // Inventor writes matrices row by row with the
                    // translation in the last row: glam's column order.
                    Mat4::from_cols_array(&a)
                })
                .collect();
            let cut = all.len() > MAX_COPIES;
            (all.into_iter().take(MAX_COPIES).collect(), cut)
        }
        _ => array(n),
    }
}

/// SoArray: `numElements1..3` copies `separation1..3` apart, the block
/// placed by `origin` (FIRST: the first copy at the origin, CENTER: the
/// block centred on it, LAST: the last copy at it).
fn array(n: &AstNode) -> (Vec<Mat4>, bool) {
    let count = |f: &str| n.num(f).unwrap_or(1.0).clamp(0.0, MAX_COPIES as f64) as usize;
    let counts = [
        count("numElements1"),
        count("numElements2"),
        count("numElements3"),
    ];
    let seps = [
        n.vec3("separation1", Vec3::X),
        n.vec3("separation2", Vec3::Y),
        n.vec3("separation3", Vec3::Z),
    ];
    let span: Vec3 = (0..3)
        .map(|k| seps[k] * counts[k].saturating_sub(1) as f32)
        .sum();
    let shift = match n.words("origin").first().map(String::as_str) {
        Some("CENTER") => span * 0.5,
        Some("LAST") => span,
        _ => Vec3::ZERO,
    };
    let total = counts.iter().fold(1usize, |a, &c| a.saturating_mul(c));
    let mut out = Vec::new();
    'all: for k in 0..counts[2] {
        for j in 0..counts[1] {
            for i in 0..counts[0] {
                if out.len() == MAX_COPIES {
                    break 'all;
                }
                let at = seps[0] * i as f32 + seps[1] * j as f32 + seps[2] * k as f32 - shift;
                out.push(Mat4::from_translation(at));
            }
        }
    }
    (out, total > MAX_COPIES)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::syntax::{parse, Options};

    fn first(src: &str) -> (Vec<Mat4>, bool) {
        let p = parse(src.as_bytes(), Options::new(false));
        copies(&p.roots[0])
    }

    #[test]
    fn array_places_copies_by_origin() {
        let (m, cut) = first(
            "#Inventor V2.1 ascii\nArray { numElements1 3 separation1 2 0 0 numElements2 2 separation2 0 5 0 origin CENTER Cube {} }",
        );
        assert!(!cut);
        let at: Vec<Vec3> = m.iter().map(|m| m.w_axis.truncate()).collect();
        assert_eq!(
            at,
            vec![
                Vec3::new(-2.0, -2.5, 0.0),
                Vec3::new(0.0, -2.5, 0.0),
                Vec3::new(2.0, -2.5, 0.0),
                Vec3::new(-2.0, 2.5, 0.0),
                Vec3::new(0.0, 2.5, 0.0),
                Vec3::new(2.0, 2.5, 0.0),
            ]
        );
        let (m, _) = first("#Inventor V2.1 ascii\nArray { numElements1 2 origin LAST Cube {} }");
        assert_eq!(m[0].w_axis.truncate(), Vec3::new(-1.0, 0.0, 0.0));
        assert_eq!(m[1].w_axis.truncate(), Vec3::ZERO);
    }

    #[test]
    fn multiple_copy_reads_row_major_matrices_and_huge_arrays_are_cut() {
        let (m, _) = first(
            "#Inventor V2.1 ascii\nMultipleCopy { matrix [ 1 0 0 0  0 1 0 0  0 0 1 0  4 5 6 1, 2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1 ] Cube {} }",
        );
        assert_eq!(m.len(), 2);
        assert_eq!(m[0].w_axis.truncate(), Vec3::new(4.0, 5.0, 6.0));
        assert_eq!(m[1].transform_point3(Vec3::ONE), Vec3::splat(2.0));
        let (m, cut) = first(
            "#Inventor V2.1 ascii\nArray { numElements1 1000000000 numElements2 1000000000 Cube {} }",
        );
        assert!(cut);
        assert_eq!(m.len(), MAX_COPIES);
    }
}
