//! [`compare`]: is a rendered picture the golden one, within a
//! [`Tolerance`]? The answer ([`Comparison`]) carries the figures and a diff
//! picture (see `diff.rs`) for a person to look at.
//!
//! Two ways to allow differences: per pixel (a channel may differ by up to
//! `channel` levels; up to `pixels` pixels may differ by more), or
//! perceptual (mean SSIM at least `ssim`, see `ssim.rs`). animed's renderer
//! is deterministic, so the default tolerance is exact.

mod diff;
mod ssim;

use crate::picture::Image;
use std::fmt;

/// How many pixels may differ by more than the per-pixel tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Allowance {
    /// At most this many pixels.
    Count(u64),
    /// At most this fraction (0..1) of all pixels, rounded down.
    Fraction(f64),
}

/// What differences [`compare`] accepts.
///
/// ```
/// use animed::{Allowance, Tolerance};
/// let exact = Tolerance::default();
/// assert_eq!(exact, Tolerance::exact());
/// let loose = Tolerance::new(2, Allowance::Fraction(0.001));
/// assert_eq!(loose.channel, 2);
/// let perceptual = Tolerance::exact().with_ssim(0.99);
/// assert_eq!(perceptual.ssim, Some(0.99));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Largest difference (0..255) of one colour channel of one pixel that
    /// still counts as equal.
    pub channel: u8,
    /// How many pixels may exceed `channel`.
    pub pixels: Allowance,
    /// Perceptual mode: when set, the pictures match when their SSIM
    /// (0..1, 1 = identical; the lowest of the mean SSIMs of R, G and B) is
    /// at least this, and `channel`/`pixels` are only reported, not
    /// enforced.
    pub ssim: Option<f64>,
}

impl Default for Tolerance {
    fn default() -> Self {
        Tolerance::exact()
    }
}

impl Tolerance {
    /// Every byte equal.
    pub const fn exact() -> Tolerance {
        Tolerance {
            channel: 0,
            pixels: Allowance::Count(0),
            ssim: None,
        }
    }

    /// Per-pixel tolerance `channel` with `pixels` allowed beyond it.
    pub const fn new(channel: u8, pixels: Allowance) -> Tolerance {
        Tolerance {
            channel,
            pixels,
            ssim: None,
        }
    }

    /// The same tolerance in perceptual mode (mean SSIM ≥ `min`).
    pub const fn with_ssim(self, min: f64) -> Tolerance {
        Tolerance {
            ssim: Some(min),
            ..self
        }
    }

    /// How many pixels of a `pixel_count`-pixel picture may differ.
    pub fn allowed(&self, pixel_count: u64) -> u64 {
        match self.pixels {
            Allowance::Count(n) => n,
            Allowance::Fraction(f) => (pixel_count as f64 * f.clamp(0.0, 1.0)).floor() as u64,
        }
    }
}

/// The result of [`compare`]: the verdict, the figures behind it and the
/// diff picture.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Comparison {
    /// Whether the pictures match within the tolerance.
    pub passed: bool,
    /// The actual picture's size.
    pub actual_size: (u32, u32),
    /// The golden's size (a different size never passes).
    pub golden_size: (u32, u32),
    /// Pixels whose largest channel difference exceeds `tolerance.channel`.
    pub differing: u64,
    /// Pixels that differ at all.
    pub changed: u64,
    /// Pixels allowed beyond the per-pixel tolerance.
    pub allowed: u64,
    /// The largest channel difference anywhere (0..255).
    pub worst: u8,
    /// SSIM (0..1, the lowest of the R, G and B means); `None` when the
    /// sizes differ.
    pub ssim: Option<f64>,
    /// The tolerance used.
    pub tolerance: Tolerance,
    /// Differences over a dimmed golden: red beyond tolerance, amber
    /// within it, a cyan frame around the red, magenta where only one
    /// picture has pixels.
    pub diff: Image,
}

impl Comparison {
    /// One line for a terminal or a test failure.
    pub fn summary(&self) -> String {
        self.to_string()
    }
}

impl fmt::Display for Comparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.actual_size != self.golden_size {
            return write!(
                f,
                "size {}x{} but the golden is {}x{}",
                self.actual_size.0, self.actual_size.1, self.golden_size.0, self.golden_size.1
            );
        }
        write!(
            f,
            "{} pixels differ by more than {} (allowed {}), worst {}",
            self.differing, self.tolerance.channel, self.allowed, self.worst
        )?;
        if let Some(s) = self.ssim {
            write!(f, ", SSIM {s:.5}")?;
            if let Some(min) = self.tolerance.ssim {
                write!(f, " (need {min})")?;
            }
        }
        Ok(())
    }
}

/// Compares `actual` with `golden` within `tolerance`.
///
/// ```
/// use animed::{compare, Allowance, Image, Tolerance};
/// let golden = Image::new(8, 8, [0, 0, 0]);
/// let mut actual = golden.clone();
/// actual.set_pixel(3, 3, [200, 0, 0]);
///
/// let exact = compare(&actual, &golden, &Tolerance::exact());
/// assert!(!exact.passed);
/// assert_eq!(exact.differing, 1);
/// assert_eq!(exact.diff.pixel(3, 3)[0] > 150, true); // red in the diff
///
/// let one_allowed = compare(&actual, &golden, &Tolerance::new(0, Allowance::Count(1)));
/// assert!(one_allowed.passed);
/// ```
pub fn compare(actual: &Image, golden: &Image, tolerance: &Tolerance) -> Comparison {
    let actual_size = (actual.width(), actual.height());
    let golden_size = (golden.width(), golden.height());
    let diff = diff::diff_image(actual, golden, tolerance.channel);
    let pixel_count = actual_size.0 as u64 * actual_size.1 as u64;
    let allowed = tolerance.allowed(pixel_count);
    if actual_size != golden_size {
        return Comparison {
            passed: false,
            actual_size,
            golden_size,
            differing: pixel_count.max(golden_size.0 as u64 * golden_size.1 as u64),
            changed: pixel_count.max(golden_size.0 as u64 * golden_size.1 as u64),
            allowed,
            worst: 255,
            ssim: None,
            tolerance: *tolerance,
            diff,
        };
    }
    let (mut differing, mut changed, mut worst) = (0u64, 0u64, 0u8);
    for (a, g) in actual
        .as_rgb()
        .chunks_exact(3)
        .zip(golden.as_rgb().chunks_exact(3))
    {
        let d = diff::channel_diff([a[0], a[1], a[2]], [g[0], g[1], g[2]]);
        worst = worst.max(d);
        changed += (d > 0) as u64;
        differing += (d > tolerance.channel) as u64;
    }
    let (w, h) = (actual_size.0 as usize, actual_size.1 as usize);
    let ssim = if changed == 0 {
        Some(1.0)
    } else {
        Some(ssim::score(actual.as_rgb(), golden.as_rgb(), w, h))
    };
    let passed = match tolerance.ssim {
        Some(min) => ssim.is_some_and(|s| s >= min),
        None => differing <= allowed,
    };
    Comparison {
        passed,
        actual_size,
        golden_size,
        differing,
        changed,
        allowed,
        worst,
        ssim,
        tolerance: *tolerance,
        diff,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gradient(w: u32, h: u32) -> Image {
        let mut img = Image::new(w, h, [0, 0, 0]);
        for y in 0..h {
            for x in 0..w {
                img.set_pixel(x, y, [(x * 255 / w) as u8, (y * 255 / h) as u8, 90]);
            }
        }
        img
    }

    #[test]
    fn identical_pictures_pass_exactly_with_a_dim_diff() {
        let g = gradient(40, 30);
        let c = compare(&g, &g, &Tolerance::exact());
        assert!(c.passed);
        assert_eq!((c.differing, c.changed, c.worst), (0, 0, 0));
        assert_eq!(c.ssim, Some(1.0));
        // The diff is a grey copy, darker than the brightest input.
        let p = c.diff.pixel(39, 29);
        assert!(p[0] == p[1] && p[1] == p[2] && p[0] < 120, "{p:?}");
    }

    #[test]
    fn per_pixel_tolerance_and_allowance_decide() {
        let g = gradient(10, 10);
        let mut a = g.clone();
        a.set_pixel(1, 1, add(g.pixel(1, 1), 2));
        a.set_pixel(5, 5, add(g.pixel(5, 5), 9));
        a.set_pixel(6, 5, add(g.pixel(6, 5), 9));
        let c = compare(&a, &g, &Tolerance::new(2, Allowance::Count(1)));
        assert!(!c.passed);
        assert_eq!((c.differing, c.changed, c.worst), (2, 3, 9));
        assert!(compare(&a, &g, &Tolerance::new(2, Allowance::Count(2))).passed);
        assert!(compare(&a, &g, &Tolerance::new(9, Allowance::Count(0))).passed);
        // 2 of 100 pixels = 0.02.
        assert!(compare(&a, &g, &Tolerance::new(2, Allowance::Fraction(0.02))).passed);
        assert!(!compare(&a, &g, &Tolerance::new(2, Allowance::Fraction(0.019))).passed);
        // Diff colours: red beyond, amber within, cyan frame around red.
        assert_eq!(c.diff.pixel(1, 1), diff_amber());
        assert!(c.diff.pixel(5, 5)[0] >= 150 && c.diff.pixel(5, 5)[1] == 0);
        assert_eq!(c.diff.pixel(3, 3), [0, 220, 255]);
        assert_eq!(c.diff.pixel(8, 7), [0, 220, 255]);
        assert_ne!(c.diff.pixel(9, 9), [0, 220, 255]);
    }

    fn add(p: [u8; 3], d: u8) -> [u8; 3] {
        [p[0].saturating_add(d), p[1], p[2]]
    }

    fn diff_amber() -> [u8; 3] {
        [150, 105, 0]
    }

    #[test]
    fn different_sizes_never_pass_and_mark_the_extra_part() {
        let (a, g) = (gradient(12, 10), gradient(10, 10));
        let c = compare(&a, &g, &Tolerance::new(255, Allowance::Fraction(1.0)));
        assert!(!c.passed);
        assert_eq!(c.diff.width(), 12);
        assert_eq!(c.diff.pixel(11, 0), [200, 0, 200]);
        assert!(c.to_string().contains("12x10 but the golden is 10x10"));
    }

    #[test]
    fn ssim_mode_accepts_small_noise_and_rejects_a_changed_shape() {
        let g = gradient(64, 48);
        let mut noisy = g.clone();
        for i in 0..64 {
            let (x, y) = ((i * 7) % 64, (i * 5) % 48);
            noisy.set_pixel(x, y, add(g.pixel(x, y), 6));
        }
        let tol = Tolerance::exact().with_ssim(0.99);
        let c = compare(&noisy, &g, &tol);
        assert!(c.passed, "{c}");
        assert!(c.differing > 0);
        let mut shape = g.clone();
        for y in 10..30 {
            for x in 10..40 {
                shape.set_pixel(x, y, [255, 255, 255]);
            }
        }
        let c = compare(&shape, &g, &tol);
        assert!(!c.passed, "{c}");
        assert!(c.ssim.unwrap() < 0.9);
    }
}
