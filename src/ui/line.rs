//! Anti-aliased lines blended straight into a `0x00RRGGBB` buffer, for
//! the many long lines of the ground grid where a path renderer with a mask
//! costs too much. Xiaolin Wu's algorithm (Wu, "An efficient antialiasing
//! technique", SIGGRAPH 1991): two pixels per step, weighted by distance.

/// Draws a line from `a` to `b` (pixel centres at +0.5) in `color` at
/// opacity `alpha` (0..1), only on pixels where `keep(index)` is true.
pub fn wu_line(
    buf: &mut [u32],
    (width, height): (u32, u32),
    a: (f32, f32),
    b: (f32, f32),
    color: u32,
    alpha: f32,
    keep: impl Fn(usize) -> bool,
) {
    let band = Band {
        width,
        height,
        rows: 0..height,
    };
    wu_line_in(buf, &band, a, b, color, alpha, keep);
}

/// Rows `rows` of a `width`×`height` picture: a band one thread draws.
pub struct Band {
    pub width: u32,
    pub height: u32,
    pub rows: std::ops::Range<u32>,
}

/// [`wu_line`] on one band of the picture: `buf` holds the band's rows
/// only, `keep` still gets whole-picture indices. Every pixel's value
/// depends only on the line and that pixel, so bands drawn apart (on
/// several threads) make the same picture as one drawn whole.
pub fn wu_line_in(
    buf: &mut [u32],
    band: &Band,
    a: (f32, f32),
    b: (f32, f32),
    color: u32,
    alpha: f32,
    keep: impl Fn(usize) -> bool,
) {
    let (w, h) = (band.width as i64, band.height as i64);
    let (r0, r1) = (
        band.rows.start as i64,
        band.rows.end.min(band.height) as i64,
    );
    let Some(line) = WuLine::new(a, b, (w, h)).filter(|_| r0 < r1) else {
        return;
    };
    // Of the on-screen columns, only those that plot into the band's rows.
    let (xs, xe) = if line.steep {
        line.xs.max(r0)..=line.xe.min(r1 - 1)
    } else {
        reaching_rows(line.xs, line.xe, line.grad, |x| line.minor_at(x), r0, r1)
    }
    .into_inner();
    line.walk(xs, xe, |px, py, cov| {
        if px < 0 || py < r0 || px >= w || py >= r1 {
            return;
        }
        let i = (py * w + px) as usize;
        if keep(i) {
            let at = i - (r0 * w) as usize;
            buf[at] = blend(buf[at], color, cov * alpha);
        }
    });
}

/// One line's Wu walk, set up once: the major axis runs along `x` (`y`
/// when `steep`), from left to right, over the on-screen columns
/// `xs..=xe` only.
struct WuLine {
    steep: bool,
    x0: f32,
    y0: f32,
    grad: f32,
    xs: i64,
    xe: i64,
}

impl WuLine {
    /// `None` for a line with a non-finite end or none of it on screen.
    fn new(a: (f32, f32), b: (f32, f32), (w, h): (i64, i64)) -> Option<WuLine> {
        let (mut x0, mut y0, mut x1, mut y1) = (a.0 - 0.5, a.1 - 0.5, b.0 - 0.5, b.1 - 0.5);
        if !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite()) {
            return None;
        }
        let steep = (y1 - y0).abs() > (x1 - x0).abs();
        if steep {
            std::mem::swap(&mut x0, &mut y0);
            std::mem::swap(&mut x1, &mut y1);
        }
        if x0 > x1 {
            std::mem::swap(&mut x0, &mut x1);
            std::mem::swap(&mut y0, &mut y1);
        }
        let dx = x1 - x0;
        let grad = if dx.abs() < 1e-6 { 0.0 } else { (y1 - y0) / dx };
        let major_max = if steep { h } else { w } as f32;
        let xs = x0.round().max(0.0);
        let xe = x1.round().min(major_max - 1.0);
        (xs <= xe).then_some(WuLine {
            steep,
            x0,
            y0,
            grad,
            xs: xs as i64,
            xe: xe as i64,
        })
    }

    /// The line's minor coordinate at major coordinate `x`.
    fn minor_at(&self, x: i64) -> f32 {
        self.y0 + self.grad * (x as f32 - self.x0)
    }

    /// Calls `plot(px, py, coverage)` with picture coordinates for the two
    /// pixels of each major coordinate in `xs..=xe`.
    fn walk(&self, xs: i64, xe: i64, mut plot: impl FnMut(i64, i64, f32)) {
        let mut at = |x: i64, y: i64, cov: f32| {
            if self.steep {
                plot(y, x, cov)
            } else {
                plot(x, y, cov)
            }
        };
        for x in xs..=xe {
            let y = self.minor_at(x);
            let yi = floor(y);
            let frac = y - yi as f32;
            at(x, yi, 1.0 - frac);
            at(x, yi + 1, frac);
        }
    }
}

/// `color` over `under` (both `0x00RRGGBB`) at opacity `k` (clamped to
/// 0..1), each channel rounded.
fn blend(under: u32, color: u32, k: f32) -> u32 {
    let k = k.clamp(0.0, 1.0);
    let mix = |sh: u32| {
        let s = ((color >> sh) & 255) as f32;
        let t = ((under >> sh) & 255) as f32;
        ((t + (s - t) * k + 0.5) as u32).min(255) << sh
    };
    mix(16) | mix(8) | mix(0)
}

/// The columns `xs..=xe` of a shallow line (minor coordinate `minor_at`)
/// that plot into rows `r0..r1`: those whose `floor(y)` or `floor(y) + 1`
/// is one of them, i.e. `r0 - 1 <= y < r1`. `y` moves one way along the
/// line (each float step is monotonic), so they are one run, found by
/// bisection with the very `y` the walk computes.
fn reaching_rows(
    xs: i64,
    xe: i64,
    grad: f32,
    minor_at: impl Fn(i64) -> f32,
    r0: i64,
    r1: i64,
) -> std::ops::RangeInclusive<i64> {
    let (lo, hi) = ((r0 - 1) as f32, r1 as f32);
    let above = |x: i64| minor_at(x) >= lo;
    let below = |x: i64| minor_at(x) < hi;
    if grad >= 0.0 {
        first_true(xs, xe, above)..=first_true(xs, xe, |x| !below(x)) - 1
    } else {
        first_true(xs, xe, below)..=first_true(xs, xe, |x| !above(x)) - 1
    }
}

/// The first `x` in `lo..=hi` for which `p` holds (`hi + 1` if none),
/// for a `p` that is false and then true.
fn first_true(mut lo: i64, hi: i64, p: impl Fn(i64) -> bool) -> i64 {
    let mut end = hi + 1;
    while lo < end {
        let mid = lo + (end - lo) / 2;
        if p(mid) {
            end = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// `y.floor() as i64` without a libm call (the SSE2 baseline has no
/// rounding instruction, and this runs twice per grid pixel): truncation,
/// one less for negative non-integers. Exact for every finite `f32`: past
/// 2^23 every float is an integer, and both saturate at `i64::MIN`.
fn floor(y: f32) -> i64 {
    let t = y as i64;
    t.saturating_sub(((t as f32) > y) as i64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horizontal_line_on_pixel_centres_is_solid() {
        let mut buf = vec![0u32; 10 * 5];
        wu_line(
            &mut buf,
            (10, 5),
            (0.5, 2.5),
            (9.5, 2.5),
            0xffffff,
            1.0,
            |_| true,
        );
        assert!(buf[20..30].iter().all(|&c| c == 0xffffff));
        assert!(buf[10..20].iter().all(|&c| c == 0));
    }

    #[test]
    fn keep_masks_pixels_and_offscreen_is_safe() {
        let mut buf = vec![0u32; 10 * 10];
        wu_line(
            &mut buf,
            (10, 10),
            (-50.0, -50.0),
            (60.0, 60.0),
            0xff0000,
            1.0,
            |i| i % 2 == 0,
        );
        assert!(buf.iter().enumerate().all(|(i, &c)| i % 2 == 0 || c == 0));
        assert!(buf.iter().any(|&c| c != 0));
    }

    #[test]
    fn floor_matches_the_library_floor() {
        for y in [
            0.0f32,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            2.9999998,
            -2.0000002,
            1e-30,
            -1e-30,
            8_388_607.5,
            -8_388_607.5,
            3e9,
            -3e9,
            1e20,
            -1e20,
        ] {
            assert_eq!(floor(y), y.floor() as i64, "{y}");
        }
        let mut bits = 0x1234_5678u32;
        for _ in 0..100_000 {
            bits = bits.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            let y = f32::from_bits(bits);
            if y.is_finite() {
                assert_eq!(floor(y), y.floor() as i64, "{y}");
            }
        }
    }

    /// The line as drawn before bands: the whole picture, every column.
    fn whole_picture_walk(
        buf: &mut [u32],
        (width, height): (u32, u32),
        a: (f32, f32),
        b: (f32, f32),
        color: u32,
        alpha: f32,
        keep: impl Fn(usize) -> bool,
    ) {
        let (w, h) = (width as i64, height as i64);
        let Some(line) = WuLine::new(a, b, (w, h)) else {
            return;
        };
        line.walk(line.xs, line.xe, |px, py, cov| {
            if px < 0 || py < 0 || px >= w || py >= h {
                return;
            }
            let i = (py * w + px) as usize;
            if keep(i) {
                buf[i] = blend(buf[i], color, cov * alpha);
            }
        });
    }

    #[test]
    fn bands_drawn_apart_make_the_whole_picture() {
        // Seeded random lines of every slope and direction, some far off
        // screen, over a random picture with a random keep mask; drawn
        // whole as before, then in bands of several heights.
        let (w, h) = (97u32, 61u32);
        let mut s = 0x9e37_79b9u32;
        let mut next = || {
            s = s.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            s >> 8
        };
        let start: Vec<u32> = (0..w * h).map(|_| next() & 0xff_ffff).collect();
        let kept: Vec<bool> = (0..w * h).map(|_| next() % 4 != 0).collect();
        let keep = |i: usize| kept[i];
        let mut coord =
            |span: u32| (next() % (span * 3)) as f32 - span as f32 + (next() % 97) as f32 / 97.0;
        let lines: Vec<_> = (0..300)
            .map(|_| ((coord(w), coord(h)), (coord(w), coord(h))))
            .chain([((3.5, 60.5), (90.5, -500.0)), ((0.0, 5.25), (96.9, 5.25))])
            .collect();
        let mut want = start.clone();
        for &(a, b) in &lines {
            whole_picture_walk(&mut want, (w, h), a, b, 0xc0_80_40, 0.8, keep);
        }
        assert_ne!(want, start);
        let mut whole = start.clone();
        for &(a, b) in &lines {
            wu_line(&mut whole, (w, h), a, b, 0xc0_80_40, 0.8, keep);
        }
        assert!(whole == want, "wu_line changed the picture");
        for rows in [1u32, 2, 7, 16, 61] {
            let mut got = start.clone();
            for (k, band) in got.chunks_mut((rows * w) as usize).enumerate() {
                let r0 = k as u32 * rows;
                let band_rows = Band {
                    width: w,
                    height: h,
                    rows: r0..(r0 + rows).min(h),
                };
                for &(a, b) in &lines {
                    wu_line_in(band, &band_rows, a, b, 0xc0_80_40, 0.8, keep);
                }
            }
            assert!(got == want, "bands of {rows} rows");
        }
    }
}
