//! Filled glyph outlines → triangles: contours with holes, by ear clipping
//! after bridging each hole into the contour around it.
//!
//! Outer contours are told from holes by their winding, as the TrueType
//! fill rule does (non-zero: holes wind against the outer contours; the
//! largest contour is always an outer one). Each hole joins the smallest
//! outer contour that holds it through a bridge to a vertex that sees it
//! (the rightmost hole vertex, a ray to the right, and the visible vertex
//! rule of D. Eberly, "Triangulation by Ear Clipping", 2002, §3). The
//! merged ring is then clipped ear by ear (Meisters' two-ears theorem).
//! Everything is exact f64 arithmetic in a fixed order, so the same glyph
//! always gives the same triangles.

/// Triangles over a point list, counter-clockwise (y up).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tessellation {
    pub points: Vec<[f32; 2]>,
    pub triangles: Vec<[u32; 3]>,
}

type P = (f64, f64);

fn cross(o: P, a: P, b: P) -> f64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

/// Twice the signed area (positive = counter-clockwise).
fn area2(c: &[P]) -> f64 {
    let n = c.len();
    (0..n)
        .map(|i| {
            let (a, b) = (c[i], c[(i + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum()
}

/// Even-odd point-in-polygon test (a point on an edge may go either way).
fn inside(c: &[P], p: P) -> bool {
    let n = c.len();
    let mut inn = false;
    let mut j = n - 1;
    for i in 0..n {
        let (a, b) = (c[i], c[j]);
        if (a.1 > p.1) != (b.1 > p.1) && p.0 < (b.0 - a.0) * (p.1 - a.1) / (b.1 - a.1) + a.0 {
            inn = !inn;
        }
        j = i;
    }
    inn
}

/// Triangulates filled contours (non-zero winding, holes wound against
/// their outer contour). Degenerate contours are dropped; a hole that no
/// outer contour holds is ignored.
pub fn tessellate(contours: &[Vec<[f32; 2]>]) -> Tessellation {
    let mut out = Tessellation::default();
    // Clean: no repeated neighbours, at least 3 points, some area.
    let mut rings: Vec<(Vec<P>, f64)> = Vec::new();
    for c in contours {
        let mut r: Vec<P> = Vec::with_capacity(c.len());
        for p in c {
            let q = (f64::from(p[0]), f64::from(p[1]));
            if r.last() != Some(&q) && q.0.is_finite() && q.1.is_finite() {
                r.push(q);
            }
        }
        while r.len() > 1 && r.first() == r.last() {
            r.pop();
        }
        if r.len() < 3 {
            continue;
        }
        let a = area2(&r);
        if a != 0.0 {
            rings.push((r, a));
        }
    }
    let Some(largest) = rings
        .iter()
        .map(|(_, a)| *a)
        .reduce(|x, y| if y.abs() > x.abs() { y } else { x })
    else {
        return out;
    };
    let outer_sign = largest.signum();
    let (outers, holes): (Vec<_>, Vec<_>) = rings
        .into_iter()
        .partition(|(_, a)| a.signum() == outer_sign);
    // Each hole goes to the smallest outer that contains its first point.
    let mut groups: Vec<(Vec<P>, Vec<Vec<P>>)> = outers
        .iter()
        .map(|(r, a)| {
            let mut r = r.clone();
            if *a < 0.0 {
                r.reverse(); // outer counter-clockwise
            }
            (r, Vec::new())
        })
        .collect();
    for (h, a) in holes {
        let owner = outers
            .iter()
            .enumerate()
            .filter(|(_, (o, _))| inside(o, h[0]))
            .min_by(|x, y| x.1 .1.abs().total_cmp(&y.1 .1.abs()))
            .map(|(i, _)| i);
        if let Some(i) = owner {
            let mut h = h;
            if a > 0.0 {
                h.reverse(); // hole clockwise
            }
            groups[i].1.push(h);
        }
    }
    for (outer, holes) in groups {
        let ring = bridge_holes(outer, holes);
        ear_clip(&ring, &mut out);
    }
    out
}

/// Splices every hole into the outer ring; returns one ring with the bridge
/// vertices repeated.
fn bridge_holes(outer: Vec<P>, mut holes: Vec<Vec<P>>) -> Vec<P> {
    let rightmost = |h: &[P]| {
        (0..h.len())
            .max_by(|&i, &j| h[i].0.total_cmp(&h[j].0).then(h[j].1.total_cmp(&h[i].1)))
            .unwrap_or(0)
    };
    // Rightmost holes first, so a bridge never crosses a hole not yet joined.
    holes.sort_by(|a, b| b[rightmost(b)].0.total_cmp(&a[rightmost(a)].0));
    let mut ring = outer;
    for h in holes {
        let mi = rightmost(&h);
        let m = h[mi];
        let Some(pi) = visible_vertex(&ring, m) else {
            continue; // should not happen for a hole inside its outer ring
        };
        let mut merged = Vec::with_capacity(ring.len() + h.len() + 2);
        merged.extend_from_slice(&ring[..=pi]);
        merged.extend((0..=h.len()).map(|k| h[(mi + k) % h.len()]));
        merged.extend_from_slice(&ring[pi..]);
        ring = merged;
    }
    ring
}

/// A vertex of `ring` that `m` (inside it) can see: where a ray from `m`
/// to +x first meets the ring, or a reflex vertex in the way (Eberly §3).
fn visible_vertex(ring: &[P], m: P) -> Option<usize> {
    let n = ring.len();
    let mut best: Option<(f64, usize)> = None; // (x of the hit, edge start)
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if (a.1 > m.1) == (b.1 > m.1) {
            continue;
        }
        let x = a.0 + (m.1 - a.1) * (b.0 - a.0) / (b.1 - a.1);
        if x >= m.0 && best.is_none_or(|(bx, _)| x < bx) {
            best = Some((x, i));
        }
    }
    // A vertex lying on the ray nearer than any crossing (the ring only
    // touches the ray there) is seen directly along the ray.
    let touch = (0..n)
        .filter(|&k| ring[k].1 == m.1 && ring[k].0 >= m.0)
        .min_by(|&a, &b| ring[a].0.total_cmp(&ring[b].0));
    if let Some(k) = touch {
        if best.is_none_or(|(bx, _)| ring[k].0 <= bx) {
            return Some(k);
        }
    }
    let (x, i) = best?;
    let (ia, ib) = (i, (i + 1) % n);
    let hit = (x, m.1);
    if ring[ia] == hit {
        return Some(ia);
    }
    if ring[ib] == hit {
        return Some(ib);
    }
    let p = if ring[ia].0 > ring[ib].0 { ia } else { ib };
    // Reflex vertices inside the triangle (m, hit, ring[p]) may hide p; the
    // one at the smallest angle to the ray is visible.
    let (tp, th) = (ring[p], hit);
    let tri_ccw = cross(m, th, tp) > 0.0;
    let mut choice = p;
    let mut best_key = (f64::INFINITY, f64::INFINITY);
    for k in 0..n {
        if k == p {
            continue;
        }
        let q = ring[k];
        let prev = ring[(k + n - 1) % n];
        let next = ring[(k + 1) % n];
        if cross(prev, q, next) > 0.0 || q == tp {
            continue; // convex (ring is counter-clockwise)
        }
        let (d1, d2, d3) = if tri_ccw {
            (cross(m, th, q), cross(th, tp, q), cross(tp, m, q))
        } else {
            (cross(m, tp, q), cross(tp, th, q), cross(th, m, q))
        };
        if d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0 && q.0 >= m.0 {
            let dx = q.0 - m.0;
            let dy = (q.1 - m.1).abs();
            let len = (dx * dx + dy * dy).sqrt();
            // Smaller angle to the ray = larger cosine; then nearer.
            let key = (-(dx / len.max(f64::MIN_POSITIVE)), len);
            if key < best_key {
                best_key = key;
                choice = k;
            }
        }
    }
    if best_key.0.is_finite() {
        // Compare with p itself: keep p when it is at a smaller angle.
        let dx = tp.0 - m.0;
        let len = (dx * dx + (tp.1 - m.1).powi(2)).sqrt();
        if -(dx / len.max(f64::MIN_POSITIVE)) < best_key.0 {
            choice = p;
        }
    }
    Some(choice)
}

/// Ear clipping of one counter-clockwise ring (with repeated bridge
/// vertices) into `out`.
fn ear_clip(ring: &[P], out: &mut Tessellation) {
    let base = out.points.len() as u32;
    out.points
        .extend(ring.iter().map(|p| [p.0 as f32, p.1 as f32]));
    let mut idx: Vec<usize> = (0..ring.len()).collect();
    let mut start = 0;
    while idx.len() > 3 {
        let m = idx.len();
        let is_ear = |i: usize, strict: bool| {
            let (a, b, c) = (idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]);
            let (pa, pb, pc) = (ring[a], ring[b], ring[c]);
            if cross(pa, pb, pc) <= 0.0 {
                return false;
            }
            idx.iter().all(|&q| {
                let pq = ring[q];
                if q == a || q == b || q == c || pq == pa || pq == pb || pq == pc {
                    return true;
                }
                let (d1, d2, d3) = (cross(pa, pb, pq), cross(pb, pc, pq), cross(pc, pa, pq));
                if strict {
                    !(d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0)
                } else {
                    !(d1 > 0.0 && d2 > 0.0 && d3 > 0.0)
                }
            })
        };
        let found = (0..m)
            .map(|k| (start + k) % m)
            .find(|&i| is_ear(i, true))
            .or_else(|| (0..m).map(|k| (start + k) % m).find(|&i| is_ear(i, false)));
        let i = match found {
            Some(i) => i,
            None => {
                // Degenerate rest (collinear or crossing edges): drop one
                // vertex without a triangle so the loop always ends.
                idx.remove(start % m);
                continue;
            }
        };
        let (a, b, c) = (idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]);
        out.triangles
            .push([base + a as u32, base + b as u32, base + c as u32]);
        idx.remove(i);
        start = if i == 0 { 0 } else { i - 1 };
    }
    if idx.len() == 3 && cross(ring[idx[0]], ring[idx[1]], ring[idx[2]]) > 0.0 {
        out.triangles.push([
            base + idx[0] as u32,
            base + idx[1] as u32,
            base + idx[2] as u32,
        ]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::text::font::Font;
    use crate::scene::FontFamily;

    fn tri_area(t: &Tessellation) -> f64 {
        t.triangles
            .iter()
            .map(|&[a, b, c]| {
                let p = |i: u32| {
                    let q = t.points[i as usize];
                    (f64::from(q[0]), f64::from(q[1]))
                };
                cross(p(a), p(b), p(c)) / 2.0
            })
            .sum()
    }

    /// The filled area of contours under the non-zero rule when holes wind
    /// against outers: |Σ signed areas|.
    fn outline_area(c: &[Vec<[f32; 2]>]) -> f64 {
        c.iter()
            .map(|r| {
                let p: Vec<P> = r
                    .iter()
                    .map(|q| (f64::from(q[0]), f64::from(q[1])))
                    .collect();
                area2(&p) / 2.0
            })
            .sum::<f64>()
            .abs()
    }

    fn square(x: f32, y: f32, s: f32, ccw: bool) -> Vec<[f32; 2]> {
        let mut v = vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
        if !ccw {
            v.reverse();
        }
        v
    }

    #[test]
    fn square_with_two_holes_has_the_area_of_the_ring() {
        let c = vec![
            square(0.0, 0.0, 10.0, true),
            square(1.0, 1.0, 3.0, false),
            square(6.0, 5.0, 3.0, false),
        ];
        let t = tessellate(&c);
        assert!(
            (tri_area(&t) - (100.0 - 9.0 - 9.0)).abs() < 1e-9,
            "{}",
            tri_area(&t)
        );
        assert!(t.triangles.iter().all(|&[a, b, c]| {
            let p = |i: u32| {
                (
                    f64::from(t.points[i as usize][0]),
                    f64::from(t.points[i as usize][1]),
                )
            };
            cross(p(a), p(b), p(c)) > 0.0
        }));
    }

    #[test]
    fn clockwise_outer_as_in_truetype_works_too() {
        let c = vec![square(0.0, 0.0, 4.0, false), square(1.0, 1.0, 2.0, true)];
        let t = tessellate(&c);
        assert!((tri_area(&t) - 12.0).abs() < 1e-9);
    }

    #[test]
    fn o_and_8_triangulate_to_their_outline_area() {
        let f = Font::new(FontFamily::Sans, false, false);
        for ch in ['O', '8', 'B', 'e', 'g', '%', '@'] {
            let c = f.outline(f.glyph(ch));
            let t = tessellate(&c);
            let (want, got) = (outline_area(&c), tri_area(&t));
            assert!(want > 0.05, "{ch}: {want}");
            assert!(
                (got - want).abs() < 1e-6 * want.max(1.0),
                "{ch}: {got} vs {want}"
            );
        }
        // 'O' is a ring: clearly less than its outer contour alone.
        let c = f.outline(f.glyph('O'));
        let outer = outline_area(&c[..1]).max(outline_area(&c[1..]));
        assert!(tri_area(&tessellate(&c)) < 0.6 * outer);
    }

    #[test]
    fn every_ascii_glyph_of_every_face_fills_exactly_its_outline() {
        for fam in [FontFamily::Serif, FontFamily::Sans, FontFamily::Typewriter] {
            for (bold, italic) in [(false, false), (true, false), (false, true), (true, true)] {
                let f = Font::new(fam, bold, italic);
                for ch in '!'..='~' {
                    let c = f.outline(f.glyph(ch));
                    let t = tessellate(&c);
                    let (want, got) = (outline_area(&c), tri_area(&t));
                    assert!(
                        (got - want).abs() < 1e-5,
                        "{fam:?} bold={bold} italic={italic} {ch:?}: {got} vs {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn same_input_same_triangles() {
        let f = Font::new(FontFamily::Serif, true, true);
        let c = f.outline(f.glyph('&'));
        assert_eq!(tessellate(&c), tessellate(&c));
    }

    #[test]
    fn degenerate_input_does_not_panic() {
        let _ = tessellate(&[]);
        let _ = tessellate(&[vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]]);
        let _ = tessellate(&[vec![[0.0, 0.0], [f32::NAN, 1.0], [2.0, 0.0], [1.0, 3.0]]]);
        // A bow tie (self-crossing).
        let t = tessellate(&[vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]]);
        assert!(t.triangles.len() <= 2);
    }
}
