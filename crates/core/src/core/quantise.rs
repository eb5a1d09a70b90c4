//! Colour channels in [0, 1] as bytes: the one quantisation every stage
//! shares (vertex colours, instance colours, scene files, swept lines), so
//! an instance, its flat copy and its decoded scene carry the same byte.

/// `c` clamped to [0, 1], times 255, rounded half away from zero, as a byte
/// (NaN gives 0): exactly `(c.clamp(0.0, 1.0) * 255.0).round() as u8`.
///
/// Written by hand because `f32::round` is a libm call on the baseline
/// x86-64 target (no SSE4.1 `roundss`), and this runs per placement on the
/// hot path of million-instance scenes. For `x` in [0, 255], `x - trunc(x)`
/// is exact in f32, so comparing it with 0.5 rounds exactly as `round` does;
/// the unit test checks every tie's neighbourhood and a sample of [0, 1].
#[inline]
pub(crate) fn unit_to_u8(c: f32) -> u8 {
    let x = c.clamp(0.0, 1.0) * 255.0;
    // `as` saturates and maps NaN to 0, as `round() as u8` does.
    let t = x as u8;
    if x - f32::from(t) >= 0.5 {
        t + 1
    } else {
        t
    }
}

/// [`unit_to_u8`] of each channel.
#[inline]
pub fn rgba8(colour: [f32; 4]) -> [u8; 4] {
    colour.map(unit_to_u8)
}

#[cfg(test)]
mod tests {
    use super::unit_to_u8;

    #[test]
    fn matches_round_across_the_unit_interval_and_at_every_half_step() {
        let same = |c: f32| assert_eq!(unit_to_u8(c), (c.clamp(0.0, 1.0) * 255.0).round() as u8, "{c}");
        // Every 61st f32 from 0.0 up to 1.0 (bit patterns are ordered for positives).
        let one = 1.0f32.to_bits();
        (0..=one).step_by(61).for_each(|b| same(f32::from_bits(b)));
        // The 200 f32s either side of every tie (k + 0.5) / 255, where rounding decides.
        for k in 0..255u32 {
            let tie = ((k as f32 + 0.5) / 255.0).to_bits();
            (tie - 200..=tie + 200).for_each(|b| same(f32::from_bits(b)));
        }
        for c in [-1.0, -0.0, 1.0, 1.5, f32::INFINITY, f32::NEG_INFINITY, f32::NAN] {
            same(c);
        }
    }
}
