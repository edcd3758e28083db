//! The colour of a surface: the one shading sequence every opaque pixel
//! goes through — texture before lighting, lighting, emissive map, texture
//! models acting after lighting — for one eight-lane block or a pair of
//! them ([`Blocks`]), and its one-pixel twin for the transparent pass.
//!
//! Why one sequence: the shading pass lights a block alone or two blocks
//! together (a [`super::lanes::Pair`]); written out twice the steps drift
//! apart. The `TEX` parameter compiles the texture steps out of the
//! shading loop of tiles without textured triangles: untextured pixels
//! then run in a loop as small as if textures did not exist (the texture
//! code inlined beside the lighting cost untextured frames a third of
//! their rate through register pressure and code size).

use super::clip::{A_COLOR, A_NORMAL, A_POS, A_UV};
use super::lanes::Blocks;
use super::prepare::{Item, Tri, INV_W};
use super::shade::{shade, shade8};
use super::simd::V8;
use super::texture_lanes::UvIn;
use glam::{Vec2, Vec3};

/// The colour of lanes of `item` at world positions `pos` with normals
/// `normal` and interpolated colours `color`, seen from `eye`. `uv` holds
/// each block's texture coordinates when `TEX` and the item is textured
/// (else it is empty and unused). Every lane does exactly the arithmetic
/// of [`shade_textured`]'s one pixel.
#[inline(always)]
pub fn shade_lanes<V: V8, L: Blocks<V>, const TEX: bool>(
    item: &Item,
    eye: Vec3,
    pos: [L; 3],
    normal: [L; 3],
    color: [L; 3],
    uv: &[UvIn<V>],
) -> [L; 3] {
    let textured = TEX && item.textured;
    let mut diffuse = color;
    let mut texels = [[V::splat(1.0); 4]; 2];
    if let (true, Some(s)) = (textured, &item.texture) {
        // Kept for after the lighting only where a model acts there: the
        // copy of four lanes into the array costs a stalled reload
        // (narrow stores read back by wide loads) on every block.
        let keep = s.acts_after_lighting();
        for (k, uv) in uv.iter().take(L::N).enumerate() {
            let texel = s.texel8_lod(uv);
            let d = s.before_lighting8(&texel, block(&diffuse, k));
            set_block(&mut diffuse, k, d);
            if keep {
                texels[k] = texel;
            }
        }
    }
    // Unlit (no normals): the unlit colour is the lit colour, so the
    // texture models that act after lighting still apply; it has no
    // emissive map (its colour already is the emission).
    let mut lit = if item.unlit {
        diffuse
    } else {
        shade8(&item.material, &item.lights, eye, pos, normal, diffuse)
    };
    if !textured {
        return lit;
    }
    if let (Some(e), false) = (&item.emissive, item.unlit) {
        let f = [
            V::splat(e.factor.x),
            V::splat(e.factor.y),
            V::splat(e.factor.z),
        ];
        for (k, uv) in uv.iter().take(L::N).enumerate() {
            // factor × texel added before anything clamps the sum.
            let t = e.map.texel8(uv);
            let b = block(&lit, k);
            set_block(
                &mut lit,
                k,
                [b[0] + f[0] * t[0], b[1] + f[1] * t[1], b[2] + f[2] * t[2]],
            );
        }
    }
    if let Some(s) = &item.texture {
        for (k, texel) in texels.iter().take(L::N).enumerate() {
            let c = s.after_lighting8(texel, block(&lit, k));
            set_block(&mut lit, k, c);
        }
    }
    lit
}

/// Block `k` of three channels.
#[inline(always)]
fn block<V: V8, L: Blocks<V>>(c: &[L; 3], k: usize) -> [V; 3] {
    [c[0].block(k), c[1].block(k), c[2].block(k)]
}

/// Replaces block `k` of three channels.
#[inline(always)]
fn set_block<V: V8, L: Blocks<V>>(c: &mut [L; 3], k: usize, v: [V; 3]) {
    for (c, v) in c.iter_mut().zip(v) {
        c.set_block(k, v);
    }
}

/// One pixel of a textured triangle drawn outside the 8-lane pass (the
/// transparent pass): colour and alpha at screen weights `b1`, `b2`, with
/// the same texture arithmetic as the lanes (texture, then lighting, then
/// the emissive map, then the models acting after lighting).
pub fn shade_textured(item: &Item, t: &Tri, b1: f32, b2: f32, eye: Vec3) -> (Vec3, f32) {
    let a = t.attrs_at(b1, b2);
    let plane = |j: usize| t.base[j] + b1 * t.d1[j] + b2 * t.d2[j];
    let inv_q = 1.0 / plane(INV_W);
    let (u, v) = (a[A_UV], a[A_UV + 1]);
    let g = t.grad;
    let ddx = Vec2::new(
        (g.uv[0][0] - u * g.q[0]) * inv_q,
        (g.uv[1][0] - v * g.q[0]) * inv_q,
    );
    let ddy = Vec2::new(
        (g.uv[0][1] - u * g.q[1]) * inv_q,
        (g.uv[1][1] - v * g.q[1]) * inv_q,
    );
    let uv = Vec2::new(u, v);
    let color = Vec3::new(a[A_COLOR], a[A_COLOR + 1], a[A_COLOR + 2]);
    let mut diffuse = color;
    let mut alpha = item.material.alpha;
    let texel = item.texture.as_ref().map(|s| s.texel(uv, ddx, ddy));
    if let (Some(s), Some(texel)) = (&item.texture, texel) {
        (diffuse, alpha) = s.before_lighting(texel, color, alpha);
    }
    let p = Vec3::new(a[A_POS], a[A_POS + 1], a[A_POS + 2]);
    let n = Vec3::new(a[A_NORMAL], a[A_NORMAL + 1], a[A_NORMAL + 2]);
    // Unlit (no normals): the unlit colour is the lit colour, as in
    // `shade_lanes` (its emission is already that colour).
    let mut lit = if item.unlit {
        diffuse
    } else {
        shade(&item.material, diffuse, &item.lights, p, n, eye)
    };
    if let (Some(e), false) = (&item.emissive, item.unlit) {
        lit += e.factor * e.map.texel(uv, ddx, ddy).truncate();
    }
    match (&item.texture, texel) {
        (Some(s), Some(texel)) => {
            let (c, alpha) = s.after_lighting(texel, lit, alpha);
            (c, s.masked(alpha))
        }
        _ => (lit, alpha),
    }
}
