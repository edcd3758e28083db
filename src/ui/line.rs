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
    let (w, h) = (width as i64, height as i64);
    let (mut x0, mut y0, mut x1, mut y1) = (a.0 - 0.5, a.1 - 0.5, b.0 - 0.5, b.1 - 0.5);
    if !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite()) {
        return;
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
    // Only walk the part of the major axis that is on screen.
    let major_max = if steep { h } else { w } as f32;
    let xs = x0.round().max(0.0);
    let xe = x1.round().min(major_max - 1.0);
    if xs > xe {
        return;
    }
    let mut plot = |x: i64, y: i64, cov: f32| {
        let (px, py) = if steep { (y, x) } else { (x, y) };
        if px < 0 || py < 0 || px >= w || py >= h {
            return;
        }
        let i = (py * w + px) as usize;
        if !keep(i) {
            return;
        }
        let k = (cov * alpha).clamp(0.0, 1.0);
        let d = buf[i];
        let mix = |sh: u32| {
            let s = ((color >> sh) & 255) as f32;
            let t = ((d >> sh) & 255) as f32;
            ((t + (s - t) * k + 0.5) as u32).min(255) << sh
        };
        buf[i] = mix(16) | mix(8) | mix(0);
    };
    let mut x = xs as i64;
    while x as f32 <= xe {
        let y = y0 + grad * (x as f32 - x0);
        let yi = floor(y);
        let frac = y - yi as f32;
        plot(x, yi, 1.0 - frac);
        plot(x, yi + 1, frac);
        x += 1;
    }
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
}
