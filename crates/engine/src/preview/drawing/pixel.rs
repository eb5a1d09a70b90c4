//! AGG's 8-bit pixel arithmetic, as Context Free's canvas does it
//! (Maxim Shemanarev, *Anti-Grain Geometry* 2.4, `agg_color_rgba.h`,
//! `agg_pixfmt_rgba.h`): the rounded multiply, premultiplying, source-over
//! blending of premultiplied sRGB without gamma, and back to straight alpha.
//!
//! The blend does the four channels at once, each in a 16-bit lane of a
//! `u64` (no lane can carry into the next: the bounds are in the comments).
//! A big design blends millions of partly covered pixels, and channel by
//! channel this was an eighth of the bush benchmark's time. The test at the
//! bottom checks it against the channel-by-channel blend on every
//! (pixel channel, colour channel, alpha) triple.

/// `a·b/255`, rounded as AGG's `int8u` multiply (`agg::rgba8::multiply`).
pub(super) fn mul(a: u8, b: u8) -> u8 {
    let t = u32::from(a) * u32::from(b) + 128;
    (((t >> 8) + t) >> 8) as u8
}

/// A straight-alpha colour premultiplied.
pub(super) fn premultiply([r, g, b, a]: [u8; 4]) -> [u8; 4] {
    [mul(r, a), mul(g, a), mul(b, a), a]
}

/// A premultiplied colour back to straight alpha (PNG's). An opaque pixel
/// is its own (`(c·255 + 127) / 255` is `c`), most of a picture.
pub(super) fn demultiply([r, g, b, a]: [u8; 4]) -> [u8; 4] {
    match a {
        0 => [0; 4],
        255 => [r, g, b, 255],
        _ => {
            let d = |c: u8| ((u32::from(c) * 255 + u32::from(a) / 2) / u32::from(a)).min(255) as u8;
            [d(r), d(g), d(b), a]
        }
    }
}

/// The low byte of every 16-bit lane.
const LOW: u64 = 0x00FF_00FF_00FF_00FF;

/// Four channels in four 16-bit lanes.
fn lanes([r, g, b, a]: [u8; 4]) -> u64 {
    u64::from(r) | u64::from(g) << 16 | u64::from(b) << 32 | u64::from(a) << 48
}

/// [`mul`] of every lane (each at most 255) by `k`.
fn mul_lanes(x: u64, k: u8) -> u64 {
    // A lane is at most 255·255 + 128 = 65,153, and with its own high byte
    // added at most 65,407: under 2¹⁶, so nothing carries between lanes.
    let t = x * u64::from(k) + 0x0080_0080_0080_0080;
    ((t + ((t >> 8) & LOW)) >> 8) & LOW
}

/// Source over a premultiplied pixel: colour `rgb` at coverage-scaled
/// alpha `alpha` (AGG's `blender_rgba_pre` with `int8u` saturating adds).
pub(super) fn blend(px: &mut [u8; 4], rgb: [u8; 3], alpha: u8) {
    let keep = 255 - alpha;
    // The source's alpha lane is mul(255, alpha), which is alpha.
    let src = mul_lanes(lanes([rgb[0], rgb[1], rgb[2], 255]), alpha);
    // Each lane at most 510: the ninth bit says it saturates.
    let sum = src + mul_lanes(lanes(*px), keep);
    let over = (sum >> 8) & 0x0001_0001_0001_0001;
    let v = (sum | over * 0xFF) & LOW;
    *px = [v as u8, (v >> 16) as u8, (v >> 32) as u8, (v >> 48) as u8];
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The channel-by-channel blend the lanes replace.
    fn blend_by_channel(px: &mut [u8; 4], rgb: [u8; 3], alpha: u8) {
        let keep = 255 - alpha;
        for k in 0..3 {
            px[k] = mul(rgb[k], alpha).saturating_add(mul(px[k], keep));
        }
        px[3] = alpha.saturating_add(mul(px[3], keep));
    }

    /// Every pixel channel, colour channel and alpha, in every lane: the
    /// lanes are independent, so this covers every input.
    #[test]
    fn lanes_blend_as_channels_do() {
        for alpha in 0..=255u8 {
            for c in 0..=255u8 {
                for d in 0..=255u8 {
                    let (mut ours, mut theirs) = ([d, d.wrapping_add(1), d.wrapping_mul(7), d], [d, d.wrapping_add(1), d.wrapping_mul(7), d]);
                    let rgb = [c, c.wrapping_mul(3), 255 - c];
                    blend(&mut ours, rgb, alpha);
                    blend_by_channel(&mut theirs, rgb, alpha);
                    assert_eq!(ours, theirs, "pixel {d}, colour {c}, alpha {alpha}");
                }
            }
        }
    }

    #[test]
    fn demultiply_of_opaque_is_the_same_as_dividing() {
        for c in 0..=255u8 {
            assert_eq!(((u32::from(c) * 255 + 127) / 255) as u8, c);
        }
        assert_eq!(demultiply([10, 20, 30, 255]), [10, 20, 30, 255]);
        assert_eq!(demultiply([10, 20, 30, 0]), [0; 4]);
    }
}
