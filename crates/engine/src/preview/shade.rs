//! Lighting that reads at icon size (`docs/preview.md`, "Lighting"): a
//! key light from the upper left, a dimmer fill from the right, a rim that
//! brightens silhouettes, a small white highlight of the key, and ambient
//! light, all fixed to the camera so every view is lit alike.
//!
//! Shading is per vertex (Gouraud) on the mesh's own normals, so flat
//! meshes (a normal per face corner) look faceted and smooth ones smooth.
//! Lighting is two-sided: a normal facing away from the camera (an open
//! surface seen from behind, or a triangle wound inward) is turned towards
//! it, so no visible surface is unlit. Colours are linear, as meshes store
//! them; [`srgb_of_linear`] encodes the result for the picture.

use std::sync::OnceLock;

/// Light directions and strengths, in camera space (x right, y up, z
/// towards the camera). Each direction points *towards* its light.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lights {
    /// Light reaching every surface.
    pub ambient: f32,
    /// The key light's direction and strength.
    pub key: ([f32; 3], f32),
    /// The fill light's direction and strength.
    pub fill: ([f32; 3], f32),
    /// The rim's strength at a silhouette (it falls off as (1 − n·v)³).
    pub rim: f32,
    /// The key's white highlight's strength (Blinn-Phong, exponent 24).
    pub highlight: f32,
    /// The half vector of the key and the view, for the highlight.
    pub half: [f32; 3],
}

impl Default for Lights {
    fn default() -> Self {
        let key = normalised([-0.5, 0.6, 0.62]);
        Lights {
            half: normalised([key[0], key[1], key[2] + 1.0]),
            ambient: 0.22,
            key: (key, 0.8),
            fill: (normalised([0.8, -0.1, 0.6]), 0.2),
            rim: 0.35,
            highlight: 0.18,
        }
    }
}

/// `v` scaled to unit length (zero stays zero).
pub fn normalised(v: [f32; 3]) -> [f32; 3] {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if len > 0.0 {
        v.map(|c| c / len)
    } else {
        v
    }
}

fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl Lights {
    /// The linear colour of a surface of linear colour `albedo` with camera-space normal `n`.
    pub fn shade(&self, albedo: [f32; 3], n: [f32; 3]) -> [f32; 3] {
        let n = normalised(n);
        // A degenerate normal faces the camera; one facing away is turned round.
        let n = if n == [0.0; 3] { [0.0, 0.0, 1.0] } else if n[2] < 0.0 { n.map(|c| -c) } else { n };
        let key = self.key.1 * dot(n, self.key.0).max(0.0);
        let fill = self.fill.1 * dot(n, self.fill.0).max(0.0);
        let edge = 1.0 - n[2];
        let rim = self.rim * edge * edge * edge;
        let light = self.ambient + key + fill + rim;
        // Blinn-Phong: half vector of the key and the view (0, 0, 1); x^24 by squaring.
        let s = dot(n, self.half).max(0.0);
        let s2 = s * s;
        let s8 = {
            let s4 = s2 * s2;
            s4 * s4
        };
        let spec = self.highlight * (s8 * s8 * s8) * if key > 0.0 { 1.0 } else { 0.0 };
        albedo.map(|a| (a * light + spec).clamp(0.0, 1.0))
    }
}

/// Bits of the linear colour values the rasteriser interpolates and stores.
pub(crate) const LINEAR_BITS: u32 = 10;
/// The largest linear value (1.0).
pub(crate) const LINEAR_MAX: i64 = (1 << LINEAR_BITS) - 1;
/// Entries of [`srgb_of_linear`]'s table: two more bits than the stored
/// values, so averaging supersamples keeps some precision.
pub(crate) const RESOLVE_STEPS: usize = 1 << (LINEAR_BITS + 2);

/// The sRGB byte of a linear value in `0..RESOLVE_STEPS` (a table computed
/// once with `libm`, so the same on every machine).
pub(crate) fn srgb_of_linear(v: usize) -> u8 {
    static TABLE: OnceLock<Vec<u8>> = OnceLock::new();
    let t = TABLE.get_or_init(|| {
        (0..RESOLVE_STEPS)
            .map(|i| {
                let l = i as f64 / (RESOLVE_STEPS - 1) as f64;
                let s = if l <= 0.003_130_8 { 12.92 * l } else { 1.055 * libm::pow(l, 1.0 / 2.4) - 0.055 };
                (s * 255.0).round().clamp(0.0, 255.0) as u8
            })
            .collect()
    });
    t.get(v).copied().unwrap_or(255)
}

/// The linear value (`0..=LINEAR_MAX`) of an sRGB byte, for a background colour.
pub(crate) fn linear_of_srgb(s: u8) -> i64 {
    let s = f64::from(s) / 255.0;
    let l = if s <= 0.040_45 { s / 12.92 } else { libm::pow((s + 0.055) / 1.055, 2.4) };
    (l * LINEAR_MAX as f64).round() as i64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lit_from_the_upper_left_and_never_black_facing_away() {
        let l = Lights::default();
        let white = [1.0; 3];
        let upper_left = l.shade(white, [-0.5, 0.5, 0.7])[0];
        let lower_right = l.shade(white, [0.5, -0.5, 0.7])[0];
        assert!(upper_left > lower_right + 0.2, "{upper_left} vs {lower_right}");
        // Two-sided: a normal facing away is lit as the one facing the camera.
        assert_eq!(l.shade(white, [0.2, 0.3, -0.9]), l.shade(white, [-0.2, -0.3, 0.9]));
        // Facing the camera a red surface stays red: no green or blue appears.
        let red = l.shade([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        assert!(red[0] > 0.6 && red[1] < 0.05 && red[2] < 0.05, "{red:?}");
    }

    #[test]
    fn srgb_tables_round_trip_the_ends() {
        assert_eq!(srgb_of_linear(0), 0);
        assert_eq!(srgb_of_linear(RESOLVE_STEPS - 1), 255);
        assert_eq!(linear_of_srgb(255), LINEAR_MAX);
        assert_eq!(linear_of_srgb(0), 0);
        // Mid grey: sRGB 188 is about 50 % linear.
        assert!((linear_of_srgb(188) - 512).abs() < 8, "{}", linear_of_srgb(188));
    }
}
