//! HSV colour maths for VRML97 ColorInterpolator playback (ISO/IEC 14772-1
//! §6.10 says colours blend in HSV), shared by the reader (which adds keys so
//! RGB playback follows the HSV path) and the writer's sampling (which checks
//! both RGB and HSV playback against the authored curve).

use glam::Vec3;

/// RGB → HSV: hue in [0, 6), saturation and value in [0, 1].
pub fn rgb_to_hsv(c: Vec3) -> Vec3 {
    let max = c.max_element();
    let min = c.min_element();
    let d = max - min;
    let h = if d <= 0.0 {
        0.0
    } else if max == c.x {
        ((c.y - c.z) / d).rem_euclid(6.0)
    } else if max == c.y {
        (c.z - c.x) / d + 2.0
    } else {
        (c.x - c.y) / d + 4.0
    };
    let s = if max > 0.0 { d / max } else { 0.0 };
    Vec3::new(h, s, max)
}

/// HSV (hue in sixths of a turn, any real) → RGB.
pub fn hsv_to_rgb(hsv: Vec3) -> Vec3 {
    let (h, s, v) = (hsv.x.rem_euclid(6.0), hsv.y, hsv.z);
    let i = h.floor();
    let f = h - i;
    let p = v * (1.0 - s);
    let q = v * (1.0 - s * f);
    let t = v * (1.0 - s * (1.0 - f));
    match i as i32 {
        0 => Vec3::new(v, t, p),
        1 => Vec3::new(q, v, p),
        2 => Vec3::new(p, v, t),
        3 => Vec3::new(p, q, v),
        4 => Vec3::new(t, p, v),
        _ => Vec3::new(v, p, q),
    }
}

/// Blends two HSV colours the short way round the hue circle; a grey end
/// takes the other end's hue.
pub fn lerp_hsv(a: Vec3, b: Vec3, t: f32) -> Vec3 {
    let (mut ha, mut hb) = (a.x, b.x);
    if a.y == 0.0 {
        ha = hb;
    }
    if b.y == 0.0 {
        hb = ha;
    }
    let mut dh = hb - ha;
    if dh > 3.0 {
        dh -= 6.0;
    } else if dh < -3.0 {
        dh += 6.0;
    }
    Vec3::new(
        (ha + dh * t).rem_euclid(6.0),
        a.y + (b.y - a.y) * t,
        a.z + (b.z - a.z) * t,
    )
}

/// The RGB colour a VRML97 ColorInterpolator plays at fraction `t` between
/// RGB colours `a` and `b`.
pub fn hsv_lerp_rgb(a: Vec3, b: Vec3, t: f32) -> Vec3 {
    hsv_to_rgb(lerp_hsv(rgb_to_hsv(a), rgb_to_hsv(b), t))
}
