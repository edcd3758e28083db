//! Drawing one screen tile: fixed-point edge functions with the top-left
//! fill rule, a depth pass that keeps the nearest triangle per pixel, then
//! one shading call per visible pixel; lines and points; transparent
//! triangles blended back to front. A tile owns its pixels, so tiles can run
//! on any thread in any order and the picture stays the same.

use super::clip::ATTRS;
use super::prepare::{Item, Line, Point, Prepared, Tri, SUBPIXEL};
use super::shade::{shade, shade_batch, Batch, LANES};
use glam::Vec3;

/// Tile edge in pixels.
pub const TILE: i32 = 64;

/// A rectangle of pixels: `[x0, y0, x1, y1)`.
pub type Rect = [i32; 4];

/// Indices (into [`Prepared`]) of the primitives touching one tile, in order.
#[derive(Clone, Debug, Default)]
pub struct Bin {
    pub opaque: Vec<u32>,
    pub transparent: Vec<u32>,
    pub lines: Vec<u32>,
    pub points: Vec<u32>,
}

/// Per-thread working buffers for one tile, reused from tile to tile (every
/// entry is reset before use, so reuse never changes a picture).
#[derive(Default)]
pub struct Scratch {
    color: Vec<Vec3>,
    depth: Vec<f32>,
    ids: Vec<u32>,
    winner: Vec<u32>,
    bary: Vec<[f32; 2]>,
}

/// Where a tile's finished pixels go: rows of the frame starting at row
/// `y0`, `stride` pixels apart.
pub struct Target<'a> {
    pub color: &'a mut [u32],
    pub depth: &'a mut [f32],
    pub ids: &'a mut [u32],
    pub stride: usize,
    pub y0: i32,
}

const NONE: u32 = u32::MAX;

/// Edge functions of a triangle stepped across a rectangle. `e[k]` is the
/// (biased) edge function opposite vertex k at the current pixel centre;
/// a pixel is inside when all three are ≥ 0.
struct Edges {
    row: [i64; 3],
    step_x: [i64; 3],
    step_y: [i64; 3],
    inv_area: f32,
}

impl Edges {
    fn new(t: &Tri, x0: i32, y0: i32) -> Edges {
        let (px, py) = (
            x0 as i64 * SUBPIXEL + SUBPIXEL / 2,
            y0 as i64 * SUBPIXEL + SUBPIXEL / 2,
        );
        let mut row = [0; 3];
        let mut step_x = [0; 3];
        let mut step_y = [0; 3];
        for k in 0..3 {
            let (a, b) = ((k + 1) % 3, (k + 2) % 3);
            let (dx, dy) = (t.x[b] - t.x[a], t.y[b] - t.y[a]);
            // Top-left rule: pixels exactly on an edge belong to the triangle
            // only if the edge is a top or a left edge (for this orientation:
            // horizontal going right, or going up).
            let top_left = (dy == 0 && dx > 0) || dy < 0;
            let bias = if top_left { 0 } else { -1 };
            row[k] = dx * (py - t.y[a]) - dy * (px - t.x[a]) + bias;
            step_x[k] = -dy * SUBPIXEL;
            step_y[k] = dx * SUBPIXEL;
        }
        let area = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
        Edges {
            row,
            step_x,
            step_y,
            inv_area: 1.0 / area as f32,
        }
    }
}

/// Calls `f(x, y, b1, b2)` for every pixel of `rect` that the triangle
/// covers; `b1`, `b2` are the screen-space barycentric weights of vertices 1
/// and 2.
#[inline]
pub fn for_each_pixel(t: &Tri, rect: Rect, mut f: impl FnMut(i32, i32, f32, f32)) {
    let x0 = t.bbox[0].max(rect[0]);
    let y0 = t.bbox[1].max(rect[1]);
    let x1 = t.bbox[2].min(rect[2]);
    let y1 = t.bbox[3].min(rect[3]);
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let mut ed = Edges::new(t, x0, y0);
    for y in y0..y1 {
        let mut e = ed.row;
        for x in x0..x1 {
            if (e[0] | e[1] | e[2]) >= 0 {
                f(x, y, e[1] as f32 * ed.inv_area, e[2] as f32 * ed.inv_area);
            }
            for (e, s) in e.iter_mut().zip(ed.step_x) {
                *e += s;
            }
        }
        for (r, s) in ed.row.iter_mut().zip(ed.step_y) {
            *r += s;
        }
    }
}

#[inline]
fn depth_at(t: &Tri, b1: f32, b2: f32) -> f32 {
    t.z[0] + b1 * (t.z[1] - t.z[0]) + b2 * (t.z[2] - t.z[0])
}

/// Perspective-correct attributes from screen-space weights.
#[inline]
fn attrs_at(t: &Tri, b1: f32, b2: f32) -> [f32; ATTRS] {
    let p0 = (1.0 - b1 - b2) * t.inv_w[0];
    let p1 = b1 * t.inv_w[1];
    let p2 = b2 * t.inv_w[2];
    let s = 1.0 / (p0 + p1 + p2);
    let (p0, p1, p2) = (p0 * s, p1 * s, p2 * s);
    let mut out = [0.0; ATTRS];
    for (k, o) in out.iter_mut().enumerate() {
        *o = p0 * t.attr[0][k] + p1 * t.attr[1][k] + p2 * t.attr[2][k];
    }
    out
}

/// Colour of a fragment with attributes `a` of `item`.
#[inline]
fn shade_attrs(item: &Item, a: &[f32; ATTRS], back: bool, eye: Vec3) -> Vec3 {
    let color = Vec3::new(a[6], a[7], a[8]);
    if item.unlit {
        return color;
    }
    let p = Vec3::new(a[0], a[1], a[2]);
    let mut n = Vec3::new(a[3], a[4], a[5]);
    if back {
        n = -n; // two-sided lighting: light the side we see
    }
    shade(&item.material, color, &item.lights, p, n, eye)
}

/// Draws every primitive of `bin` into the tile `rect`.
pub fn draw_tile(
    p: &Prepared,
    bin: &Bin,
    rect: Rect,
    background: Vec3,
    eye: Vec3,
    scratch: &mut Scratch,
    target: &mut Target,
) {
    let tw = (rect[2] - rect[0]) as usize;
    let n = tw * (rect[3] - rect[1]) as usize;
    let at = |x: i32, y: i32| (y - rect[1]) as usize * tw + (x - rect[0]) as usize;
    let Scratch {
        color,
        depth,
        ids,
        winner,
        bary,
    } = scratch;
    reset(color, n, background);
    reset(depth, n, 1.0);
    reset(ids, n, 0);
    reset(winner, n, NONE);
    reset(bary, n, [0.0; 2]);

    // 1. Depth pass: nearest opaque triangle per pixel (first wins on ties).
    {
        // Plain slices: the loop then keeps their pointers in registers.
        let (depth, winner, bary) = (&mut depth[..n], &mut winner[..n], &mut bary[..n]);
        for &ti in &bin.opaque {
            let t = &p.opaque[ti as usize];
            for_each_pixel(t, rect, |x, y, b1, b2| {
                let z = depth_at(t, b1, b2);
                let i = at(x, y);
                if z < depth[i] && z >= 0.0 {
                    depth[i] = z;
                    winner[i] = ti;
                    bary[i] = [b1, b2];
                }
            });
        }
    }
    // 2. Shade each visible pixel once, in batches of pixels of one item.
    let mut batch = Batch::default();
    let mut batch_item = NONE;
    let mut shaded = [Vec3::ZERO; LANES];
    let mut flush = |batch: &mut Batch, item: u32, color: &mut [Vec3]| {
        if batch.len == 0 {
            return;
        }
        let it = &p.items[item as usize];
        shade_batch(&it.material, &it.lights, eye, batch, &mut shaded);
        for k in 0..batch.len {
            color[batch.dest[k] as usize] = shaded[k];
        }
        batch.len = 0;
    };
    for i in 0..n {
        let ti = winner[i];
        if ti == NONE {
            continue;
        }
        let t = &p.opaque[ti as usize];
        let item = &p.items[t.item as usize];
        ids[i] = item.id;
        let a = attrs_at(t, bary[i][0], bary[i][1]);
        let c = Vec3::new(a[6], a[7], a[8]);
        if item.unlit {
            color[i] = c;
            continue;
        }
        if t.item != batch_item || batch.len == LANES {
            flush(&mut batch, batch_item, color);
            batch_item = t.item;
        }
        let mut nrm = Vec3::new(a[3], a[4], a[5]);
        if t.back {
            nrm = -nrm;
        }
        batch.push(i as u32, Vec3::new(a[0], a[1], a[2]), nrm, c);
    }
    flush(&mut batch, batch_item, color);
    // 3. Lines and points, depth-tested and shaded as they come.
    for &li in &bin.lines {
        let l = &p.lines[li as usize];
        let item = &p.items[l.item as usize];
        for_each_line_pixel(l, rect, |x, y, z, a| {
            let i = at(x, y);
            if z < depth[i] && z >= 0.0 {
                depth[i] = z;
                color[i] = shade_attrs(item, &facing(a, eye), false, eye);
                ids[i] = item.id;
            }
        });
    }
    for &pi in &bin.points {
        let pt: &Point = &p.points[pi as usize];
        let item = &p.items[pt.item as usize];
        let c = shade_attrs(item, &facing(pt.attr, eye), false, eye);
        for y in pt.bbox[1].max(rect[1])..pt.bbox[3].min(rect[3]) {
            for x in pt.bbox[0].max(rect[0])..pt.bbox[2].min(rect[2]) {
                let i = at(x, y);
                if pt.z < depth[i] && pt.z >= 0.0 {
                    depth[i] = pt.z;
                    color[i] = c;
                    ids[i] = item.id;
                }
            }
        }
    }
    // 4. Transparent triangles, already sorted back to front; they test but
    // do not write depth.
    for &ti in &bin.transparent {
        let t = &p.transparent[ti as usize];
        let item = &p.items[t.item as usize];
        let alpha = item.material.alpha;
        for_each_pixel(t, rect, |x, y, b1, b2| {
            let z = depth_at(t, b1, b2);
            let i = at(x, y);
            if z < depth[i] && z >= 0.0 {
                let a = attrs_at(t, b1, b2);
                let c = shade_attrs(item, &a, t.back, eye);
                color[i] = c * alpha + color[i] * (1.0 - alpha);
                ids[i] = item.id;
            }
        });
    }
    // 5. Into the frame.
    for (row, y) in (rect[1]..rect[3]).enumerate() {
        let dst = (y - target.y0) as usize * target.stride + rect[0] as usize;
        let src = row * tw;
        for k in 0..tw {
            target.color[dst + k] = super::frame::pack_rgb(color[src + k]);
        }
        target.depth[dst..dst + tw].copy_from_slice(&depth[src..src + tw]);
        target.ids[dst..dst + tw].copy_from_slice(&ids[src..src + tw]);
    }
}

fn reset<T: Copy>(v: &mut Vec<T>, n: usize, value: T) {
    v.clear();
    v.resize(n, value);
}

/// Lines and points have no "side": turn their normal towards the eye.
fn facing(mut a: [f32; ATTRS], eye: Vec3) -> [f32; ATTRS] {
    let p = Vec3::new(a[0], a[1], a[2]);
    let n = Vec3::new(a[3], a[4], a[5]);
    if n.dot(eye - p) < 0.0 {
        for v in &mut a[3..6] {
            *v = -*v;
        }
    }
    a
}

/// Calls `f(x, y, depth, attrs)` for the pixels of a 1-pixel-wide line in
/// `rect`: one pixel per column (x-major) or per row (y-major), whose centre
/// column/row lies in the half-open span of the segment. Each pixel is a
/// function of the segment alone, so tiles agree at their borders.
pub fn for_each_line_pixel(l: &Line, rect: Rect, mut f: impl FnMut(i32, i32, f32, [f32; ATTRS])) {
    let (dx, dy) = (l.x[1] - l.x[0], l.y[1] - l.y[0]);
    let x_major = dx.abs() >= dy.abs();
    // Major axis coordinates of the ends, the other axis, and the span.
    let (m0, m1, o0, od) = if x_major {
        (l.x[0], l.x[1], l.y[0], dy)
    } else {
        (l.y[0], l.y[1], l.x[0], dx)
    };
    let dm = m1 - m0;
    let (lo, hi) = if dm >= 0.0 { (m0, m1) } else { (m1, m0) };
    let (r_lo, r_hi) = if x_major {
        (rect[0], rect[2])
    } else {
        (rect[1], rect[3])
    };
    // Pixels whose centre c = k + 0.5 satisfies lo ≤ c < hi.
    let first = ((lo - 0.5).ceil() as i32).max(r_lo);
    let last = ((hi - 0.5).ceil() as i32).min(r_hi);
    if dm == 0.0 {
        // A degenerate segment: one pixel.
        let (x, y) = (l.x[0].floor() as i32, l.y[0].floor() as i32);
        if x >= rect[0] && x < rect[2] && y >= rect[1] && y < rect[3] {
            f(x, y, l.z[0], l.attr[0]);
        }
        return;
    }
    for k in first..last {
        let t = (k as f32 + 0.5 - m0) / dm;
        let o = (o0 + t * od).floor() as i32;
        let (x, y) = if x_major { (k, o) } else { (o, k) };
        if x < rect[0] || x >= rect[2] || y < rect[1] || y >= rect[3] {
            continue;
        }
        let z = l.z[0] + t * (l.z[1] - l.z[0]);
        // Perspective-correct weight of the second end.
        let w1 = t * l.inv_w[1];
        let w0 = (1.0 - t) * l.inv_w[0];
        let s = w1 / (w0 + w1);
        let mut a = [0.0; ATTRS];
        for (j, v) in a.iter_mut().enumerate() {
            *v = l.attr[0][j] + s * (l.attr[1][j] - l.attr[0][j]);
        }
        f(x, y, z, a);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri(pts: [(f32, f32); 3]) -> Tri {
        let fx = |v: f32| (v * SUBPIXEL as f32).round() as i64;
        let mut t = Tri {
            x: pts.map(|p| fx(p.0)),
            y: pts.map(|p| fx(p.1)),
            z: [0.5; 3],
            inv_w: [1.0; 3],
            attr: [[0.0; ATTRS]; 3],
            item: 0,
            back: false,
            bbox: [0, 0, 64, 64],
        };
        let area = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
        if area < 0 {
            t.x.swap(1, 2);
            t.y.swap(1, 2);
        }
        t
    }

    fn coverage(tris: &[Tri]) -> Vec<u32> {
        let mut hits = vec![0u32; 64 * 64];
        for t in tris {
            for_each_pixel(t, [0, 0, 64, 64], |x, y, _, _| {
                hits[(y * 64 + x) as usize] += 1
            });
        }
        hits
    }

    #[test]
    fn shared_edges_cover_every_pixel_exactly_once() {
        // A square split along its diagonal, with edges through pixel centres.
        let a = tri([(4.5, 4.5), (20.5, 4.5), (20.5, 20.5)]);
        let b = tri([(4.5, 4.5), (20.5, 20.5), (4.5, 20.5)]);
        let hits = coverage(&[a, b]);
        assert!(hits.iter().all(|&h| h <= 1), "overlap on a shared edge");
        // Top and left edges are in, bottom and right out: 16×16 pixels.
        assert_eq!(hits.iter().sum::<u32>(), 16 * 16);
        assert_eq!(hits[4 * 64 + 4], 1);
        assert_eq!(hits[20 * 64 + 20], 0);
    }

    #[test]
    fn fan_around_a_point_covers_each_pixel_once() {
        // Eight triangles around an off-grid centre, vertices at sub-pixel
        // positions: the square they tile is covered without gaps or overlaps.
        let c = (31.3, 29.7);
        let ring = [
            (10.25, 10.5),
            (31.3, 10.5),
            (52.75, 10.5),
            (52.75, 29.7),
            (52.75, 50.125),
            (31.3, 50.125),
            (10.25, 50.125),
            (10.25, 29.7),
        ];
        let tris: Vec<Tri> = (0..8)
            .map(|k| tri([c, ring[k], ring[(k + 1) % 8]]))
            .collect();
        let hits = coverage(&tris);
        assert!(hits.iter().all(|&h| h <= 1));
        // Pixel centres x+0.5 in [10.25, 52.75) → x = 10..=52 (43 columns);
        // y+0.5 in [10.5, 50.125) → y = 10..=49 (40 rows).
        assert_eq!(hits.iter().sum::<u32>(), 43 * 40);
    }

    fn covered(tris: &[Tri]) -> Vec<u32> {
        coverage(tris)
    }

    proptest::proptest! {
        /// A convex quad split along either diagonal covers the same pixels,
        /// each exactly once: the shared diagonal is never doubled or
        /// dropped, whatever the sub-pixel positions.
        #[test]
        fn quad_split_either_way_covers_the_same_pixels(
            cx in 20.0f32..44.0, cy in 20.0f32..44.0,
            r in proptest::array::uniform4(6.0f32..18.0),
            a0 in 0.0f32..1.4,
            // Snapped to 1/16 px sometimes, so exact hits on edges happen.
            snap in proptest::bool::ANY,
        ) {
            let q = |v: f32| if snap { (v * 16.0).round() / 16.0 } else { v };
            let pts: Vec<(f32, f32)> = (0..4)
                .map(|k| {
                    let a = a0 + k as f32 * std::f32::consts::FRAC_PI_2;
                    (q(cx + r[k] * a.cos()), q(cy + r[k] * a.sin()))
                })
                .collect();
            let one = covered(&[tri([pts[0], pts[1], pts[2]]), tri([pts[0], pts[2], pts[3]])]);
            let other = covered(&[tri([pts[0], pts[1], pts[3]]), tri([pts[1], pts[2], pts[3]])]);
            proptest::prop_assert!(one.iter().all(|&h| h <= 1));
            proptest::prop_assert!(other.iter().all(|&h| h <= 1));
            proptest::prop_assert_eq!(one, other);
        }
    }

    #[test]
    fn barycentrics_reproduce_vertex_positions() {
        let t = tri([(2.5, 2.5), (40.5, 6.5), (10.5, 50.5)]);
        let mut checked = 0;
        for_each_pixel(&t, [0, 0, 64, 64], |x, y, b1, b2| {
            let b0 = 1.0 - b1 - b2;
            let px = b0 * 2.5 + b1 * t.x[1] as f32 / 256.0 + b2 * t.x[2] as f32 / 256.0;
            let py = b0 * 2.5 + b1 * t.y[1] as f32 / 256.0 + b2 * t.y[2] as f32 / 256.0;
            assert!((px - (x as f32 + 0.5)).abs() < 1e-3);
            assert!((py - (y as f32 + 0.5)).abs() < 1e-3);
            checked += 1;
        });
        assert!(checked > 500);
    }

    #[test]
    fn line_has_one_pixel_per_column() {
        let l = Line {
            x: [2.0, 30.0],
            y: [3.0, 10.0],
            z: [0.5, 0.5],
            inv_w: [1.0, 1.0],
            attr: [[0.0; ATTRS]; 2],
            item: 0,
            bbox: [0, 0, 64, 64],
        };
        let mut cols = Vec::new();
        for_each_line_pixel(&l, [0, 0, 64, 64], |x, _, _, _| cols.push(x));
        assert_eq!(cols, (2..30).collect::<Vec<_>>());
        // Split across two tiles: the same pixels.
        let mut split = Vec::new();
        for r in [[0, 0, 16, 64], [16, 0, 64, 64]] {
            for_each_line_pixel(&l, r, |x, y, _, _| split.push((x, y)));
        }
        let mut whole = Vec::new();
        for_each_line_pixel(&l, [0, 0, 64, 64], |x, y, _, _| whole.push((x, y)));
        assert_eq!(split, whole);
    }
}
