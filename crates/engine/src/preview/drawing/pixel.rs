//! AGG's 8-bit pixel arithmetic, as Context Free's canvas does it
//! (Maxim Shemanarev, *Anti-Grain Geometry* 2.4, `agg_color_rgba.h`,
//! `agg_pixfmt_rgba.h`): the rounded multiply, premultiplying, source-over
//! blending of premultiplied sRGB without gamma, and back to straight alpha.

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

/// Source over a premultiplied pixel: colour `rgb` at coverage-scaled
/// alpha `alpha` (AGG's `blender_rgba_pre` with `int8u` saturating adds).
/// Channel by channel: the same in four 16-bit lanes of a `u64` was tried
/// and was slower on the bush benchmark (packing costs more than it saves).
pub(super) fn blend(px: &mut [u8; 4], rgb: [u8; 3], alpha: u8) {
    let keep = 255 - alpha;
    for k in 0..3 {
        px[k] = mul(rgb[k], alpha).saturating_add(mul(px[k], keep));
    }
    px[3] = alpha.saturating_add(mul(px[3], keep));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn demultiply_of_opaque_is_the_same_as_dividing() {
        for c in 0..=255u8 {
            assert_eq!(((u32::from(c) * 255 + 127) / 255) as u8, c);
        }
        assert_eq!(demultiply([10, 20, 30, 255]), [10, 20, 30, 255]);
        assert_eq!(demultiply([10, 20, 30, 0]), [0; 4]);
    }
}
