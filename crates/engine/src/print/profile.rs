//! The printer profile of a print request: what the customer's printer can
//! make (its thinnest wall, its build volume, the most triangles its
//! pipeline accepts). The report's findings are measured against it, and
//! open surfaces are thickened to its minimum wall.
//!
//! Values travel in whole micrometres (and a triangle count), so the profile
//! is `Eq` and `Hash` like the rest of the request, and a value given in
//! millimetres that equals the default is the default (same cache key).

use super::PrintError;
use serde::{Deserialize, Serialize};

/// The thinnest wall or feature most FDM printers reproduce (a 0.4 mm
/// nozzle's two perimeters), in micrometres: the default minimum.
pub(crate) const DEFAULT_MIN_WALL_UM: u32 = 800;

/// A common desktop printer's build volume (x, y, z) in micrometres
/// (Prusa MK4 class: 250 × 210 × 210 mm).
pub(crate) const DEFAULT_BUILD_UM: [u32; 3] = [250_000, 210_000, 210_000];

/// The polygon ceiling print services apply (Shapeways: one million).
pub(crate) const DEFAULT_TRIANGLE_CEILING: u32 = 1_000_000;

/// The largest minimum wall accepted (mm): anything thicker is not a printer.
pub(crate) const MAX_MIN_WALL_MM: f64 = 100.0;

/// The largest build-volume side accepted (mm), as for `size_mm`.
pub(crate) const MAX_BUILD_MM: f64 = 10_000.0;

/// The largest triangle ceiling accepted.
pub(crate) const MAX_TRIANGLE_CEILING: u64 = 100_000_000;

/// What the printer can make. Part of [`PrintOptions`](super::PrintOptions)
/// and so of the cache key (only when it differs from the default, so
/// requests that do not name a profile keep their keys).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct PrinterProfile {
    /// Thinnest wall or feature the printer makes (µm); walls measured
    /// thinner are reported as `thin_wall`, open surfaces are thickened to it.
    pub min_wall_um: u32,
    /// Build volume along x, y, z (µm), z being the build direction.
    pub build_um: [u32; 3],
    /// Most triangles the printer's pipeline accepts (`too_many_triangles`).
    pub triangle_ceiling: u32,
}

impl Default for PrinterProfile {
    fn default() -> Self {
        PrinterProfile { min_wall_um: DEFAULT_MIN_WALL_UM, build_um: DEFAULT_BUILD_UM, triangle_ceiling: DEFAULT_TRIANGLE_CEILING }
    }
}

impl PrinterProfile {
    /// The profile a request names, each value checked: `None` keeps the
    /// default. The minimum wall is in (0, 100] mm, each build side in
    /// (0, 10 000] mm, the ceiling in 1..=10⁸ triangles.
    pub(crate) fn from_request(min_wall_mm: Option<f64>, build_volume_mm: Option<&[f64]>, triangle_ceiling: Option<u64>) -> Result<Self, PrintError> {
        let mut p = PrinterProfile::default();
        if let Some(mm) = min_wall_mm {
            if !(mm > 0.0 && mm <= MAX_MIN_WALL_MM) {
                return Err(PrintError::BadMinWall(mm));
            }
            p.min_wall_um = to_um(mm);
        }
        if let Some(sides) = build_volume_mm {
            let [x, y, z] = <[f64; 3]>::try_from(sides).map_err(|_| PrintError::BadBuildVolume(format!("{} numbers, expected 3 (x, y, z)", sides.len())))?;
            for side in [x, y, z] {
                if !(side > 0.0 && side <= MAX_BUILD_MM) {
                    return Err(PrintError::BadBuildVolume(format!("side {side} mm is not in (0, {MAX_BUILD_MM}]")));
                }
            }
            p.build_um = [x, y, z].map(to_um);
        }
        if let Some(n) = triangle_ceiling {
            if !(1..=MAX_TRIANGLE_CEILING).contains(&n) {
                return Err(PrintError::BadTriangleCeiling(n));
            }
            // Fits: at most 10⁸.
            p.triangle_ceiling = n as u32;
        }
        Ok(p)
    }

    /// Checks a profile built by a library caller (the doors check theirs in
    /// [`from_request`](Self::from_request)).
    pub fn validate(&self) -> Result<(), PrintError> {
        Self::from_request(Some(self.min_wall_mm()), Some(&self.build_mm()), Some(u64::from(self.triangle_ceiling))).map(|_| ())
    }

    /// The minimum wall in millimetres.
    pub fn min_wall_mm(&self) -> f64 {
        f64::from(self.min_wall_um) / 1000.0
    }

    /// The build volume in millimetres.
    pub(crate) fn build_mm(&self) -> [f64; 3] {
        self.build_um.map(|v| f64::from(v) / 1000.0)
    }
}

/// Reads a build volume written `XxYxZ` or `X,Y,Z` (millimetres), as the
/// CLI's `--build-volume-mm` and the models route's query take it. Range
/// checks are [`PrinterProfile::from_request`]'s.
pub(crate) fn parse_build_volume(text: &str) -> Result<Vec<f64>, PrintError> {
    text.split(['x', 'X', ','])
        .map(|s| s.trim().parse::<f64>().map_err(|_| PrintError::BadBuildVolume(format!("`{text}`: expected three millimetre sizes, as 250x210x210"))))
        .collect()
}

/// Millimetres to whole micrometres (at least 1: a positive size stays positive).
fn to_um(mm: f64) -> u32 {
    (mm * 1000.0).round().max(1.0) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_and_ranges() {
        assert_eq!(PrinterProfile::from_request(None, None, None), Ok(PrinterProfile::default()));
        // The default named explicitly is the default (same cache key).
        assert_eq!(PrinterProfile::from_request(Some(0.8), Some(&[250.0, 210.0, 210.0]), Some(1_000_000)), Ok(PrinterProfile::default()));
        let p = PrinterProfile::from_request(Some(0.4), Some(&[100.0, 100.0, 50.5]), Some(10)).expect("valid");
        assert_eq!((p.min_wall_um, p.build_um, p.triangle_ceiling), (400, [100_000, 100_000, 50_500], 10));
        assert_eq!(p.validate(), Ok(()));
        assert!(matches!(PrinterProfile::from_request(Some(0.0), None, None), Err(PrintError::BadMinWall(_))));
        assert!(matches!(PrinterProfile::from_request(Some(f64::NAN), None, None), Err(PrintError::BadMinWall(_))));
        assert!(matches!(PrinterProfile::from_request(None, Some(&[1.0, 2.0]), None), Err(PrintError::BadBuildVolume(_))));
        assert!(matches!(PrinterProfile::from_request(None, Some(&[1.0, -2.0, 3.0]), None), Err(PrintError::BadBuildVolume(_))));
        assert!(matches!(PrinterProfile::from_request(None, None, Some(0)), Err(PrintError::BadTriangleCeiling(0))));
        assert!(PrinterProfile { min_wall_um: 0, ..PrinterProfile::default() }.validate().is_err());
    }

    #[test]
    fn build_volume_text() {
        assert_eq!(parse_build_volume("250x210x210"), Ok(vec![250.0, 210.0, 210.0]));
        assert_eq!(parse_build_volume("180, 180,180.5"), Ok(vec![180.0, 180.0, 180.5]));
        assert!(parse_build_volume("big").is_err());
        assert_eq!(parse_build_volume("1x2").map(|v| v.len()), Ok(2));
    }
}
