//! Structural similarity (SSIM), the perceptual option of [`super::compare`].
//!
//! Wang, Bovik, Sheikh and Simoncelli, "Image quality assessment: from error
//! visibility to structural similarity", IEEE Trans. Image Processing 13(4),
//! 2004, eq. 13 with the paper's constants: an 11×11 circular-symmetric
//! Gaussian window with σ = 1.5 (normalised to sum 1), K1 = 0.01, K2 = 0.03,
//! L = 255, averaged over the picture (the paper's MSSIM, eq. 17). The
//! paper works on grey pictures; we take each of R, G and B as one and
//! report the lowest of the three means, because on luma alone a change of
//! hue at equal brightness (a grey floor turned red) scores 0.99. Near the
//! border the window is clamped to the picture (edge pixels repeated), so
//! the map has one value per pixel and pictures smaller than the window
//! still get a score. No crate was used: the maintained SSIM crate (dssim)
//! is AGPL and others pull in `image`'s default features.
//!
//! Everything is f64 evaluated in a fixed order, so the score is the same
//! on every run and thread count.

const RADIUS: i64 = 5;
const SIGMA: f64 = 1.5;
const C1: f64 = (0.01 * 255.0) * (0.01 * 255.0);
const C2: f64 = (0.03 * 255.0) * (0.03 * 255.0);

fn weights() -> [f64; (2 * RADIUS + 1) as usize] {
    let mut w = [0.0; (2 * RADIUS + 1) as usize];
    let mut sum = 0.0;
    for (i, v) in w.iter_mut().enumerate() {
        let d = i as f64 - RADIUS as f64;
        *v = (-(d * d) / (2.0 * SIGMA * SIGMA)).exp();
        sum += *v;
    }
    for v in &mut w {
        *v /= sum;
    }
    w
}

/// Separable Gaussian blur with clamped borders.
fn blur(src: &[f64], w: usize, h: usize, k: &[f64]) -> Vec<f64> {
    let mut tmp = vec![0.0; src.len()];
    let clamp = |v: i64, n: usize| v.clamp(0, n as i64 - 1) as usize;
    for y in 0..h {
        for x in 0..w {
            let mut s = 0.0;
            for (i, kv) in k.iter().enumerate() {
                s += kv * src[y * w + clamp(x as i64 + i as i64 - RADIUS, w)];
            }
            tmp[y * w + x] = s;
        }
    }
    let mut out = vec![0.0; src.len()];
    for y in 0..h {
        for x in 0..w {
            let mut s = 0.0;
            for (i, kv) in k.iter().enumerate() {
                s += kv * tmp[clamp(y as i64 + i as i64 - RADIUS, h) * w + x];
            }
            out[y * w + x] = s;
        }
    }
    out
}

fn channel(rgb: &[u8], c: usize) -> Vec<f64> {
    rgb.chunks_exact(3).map(|p| p[c] as f64).collect()
}

/// The SSIM map (one value per pixel, 1 = identical neighbourhood) of
/// channel `c` (0 = R, 1 = G, 2 = B) of two RGB buffers of the same `w`×`h`.
pub fn ssim_map(a: &[u8], b: &[u8], w: usize, h: usize, c: usize) -> Vec<f64> {
    if w == 0 || h == 0 {
        return Vec::new();
    }
    let k = weights();
    let (x, y) = (channel(a, c), channel(b, c));
    let xx: Vec<f64> = x.iter().map(|v| v * v).collect();
    let yy: Vec<f64> = y.iter().map(|v| v * v).collect();
    let xy: Vec<f64> = x.iter().zip(&y).map(|(a, b)| a * b).collect();
    let (mx, my) = (blur(&x, w, h, &k), blur(&y, w, h, &k));
    let (sxx, syy, sxy) = (
        blur(&xx, w, h, &k),
        blur(&yy, w, h, &k),
        blur(&xy, w, h, &k),
    );
    (0..w * h)
        .map(|i| {
            let (ux, uy) = (mx[i], my[i]);
            let vx = sxx[i] - ux * ux;
            let vy = syy[i] - uy * uy;
            let cxy = sxy[i] - ux * uy;
            ((2.0 * ux * uy + C1) * (2.0 * cxy + C2)) / ((ux * ux + uy * uy + C1) * (vx + vy + C2))
        })
        .collect()
}

/// The picture's score: the lowest over R, G and B of the mean SSIM.
pub fn score(a: &[u8], b: &[u8], w: usize, h: usize) -> f64 {
    (0..3)
        .map(|c| mean(&ssim_map(a, b, w, h, c)))
        .fold(1.0, f64::min)
}

/// Mean SSIM of a map (1 for an empty picture).
pub fn mean(map: &[f64]) -> f64 {
    if map.is_empty() {
        1.0
    } else {
        map.iter().sum::<f64>() / map.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn noise(w: usize, h: usize, seed: u32) -> Vec<u8> {
        let mut s = seed;
        (0..w * h * 3)
            .map(|_| {
                s = s.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                (s >> 24) as u8
            })
            .collect()
    }

    #[test]
    fn identical_pictures_score_one() {
        let a = noise(32, 24, 1);
        let m = ssim_map(&a, &a, 32, 24, 1);
        assert!(m.iter().all(|v| (v - 1.0).abs() < 1e-9));
        assert!((mean(&m) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn weights_sum_to_one_and_peak_in_the_middle() {
        let k = weights();
        assert!((k.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(k[RADIUS as usize] > k[0]);
        assert_eq!(k[0], k[(2 * RADIUS) as usize]);
    }

    #[test]
    fn unrelated_noise_scores_near_zero_and_small_shifts_score_high() {
        let (a, b) = (noise(40, 40, 1), noise(40, 40, 2));
        assert!(score(&a, &b, 40, 40).abs() < 0.1);
        // A uniform brightness change of 2 levels keeps the structure.
        let c: Vec<u8> = a.iter().map(|v| v.saturating_add(2)).collect();
        let s = score(&a, &c, 40, 40);
        assert!(s > 0.99 && s < 1.0, "{s}");
    }

    #[test]
    fn a_hue_change_at_equal_brightness_scores_low() {
        // Grey (115, 122, 107) turned reddish (179, 77, 77) with a texture
        // on top: luma changes little (SSIM on luma ≈ 0.99), the red
        // channel a lot (luminance term 2·120·184/(120²+184²) ≈ 0.915).
        let tex = noise(32, 32, 3);
        let paint = |base: [u8; 3]| -> Vec<u8> {
            tex.chunks_exact(3)
                .flat_map(|p| {
                    let d = p[0] / 16;
                    [base[0] + d, base[1] + d, base[2] + d]
                })
                .collect()
        };
        let (grey, red) = (paint([115, 122, 107]), paint([179, 77, 77]));
        let s = score(&grey, &red, 32, 32);
        assert!(s < 0.93, "{s}");
    }

    #[test]
    fn constant_pictures_follow_the_luminance_term() {
        // Flat 100 vs 110: variances are 0, so SSIM is the luminance
        // term (2·100·110 + C1) / (100² + 110² + C1) (paper eq. 6).
        let a = vec![100u8; 8 * 8 * 3];
        let b = vec![110u8; 8 * 8 * 3];
        let want = (2.0 * 100.0 * 110.0 + C1) / (100.0f64.powi(2) + 110.0f64.powi(2) + C1);
        let got = score(&a, &b, 8, 8);
        assert!((got - want).abs() < 1e-9, "{got} vs {want}");
    }
}
