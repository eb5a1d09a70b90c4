//! Findings: the report's verdicts against the printer profile, each a code
//! an ordering backend can act on (and translate for its customers), a
//! message in English, and where known the place and the measured value.

use super::profile::PrinterProfile;
use super::report::PrintReport;
use serde::Serialize;

/// What is wrong, as a stable machine-readable code.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingCode {
    /// A wall measured thinner than the profile's minimum (`value`: its thickness, mm).
    ThinWall,
    /// The model as placed (z up, on the plate) does not fit the build
    /// volume along some axis (`value`: the largest overshoot, mm).
    TooBig,
    /// More triangles than the profile's ceiling (`value`: the count).
    TooManyTriangles,
    /// The solid is several pieces (`value`: how many).
    SeparateShells,
    /// Parts of the model are open surfaces: thickened into walls or left out (`value`: how many).
    OpenSurface,
    /// The result has edges that are not shared by exactly two oppositely
    /// wound faces (`value`: how many).
    NotWatertight,
}

/// One finding of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Finding {
    /// What is wrong.
    pub code: FindingCode,
    /// The same in words, with the figures.
    pub message: String,
    /// Where (mm, in the printed solid's coordinates), when one place says it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub position_mm: Option<[f64; 3]>,
    /// The measured value the code describes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
}

impl Finding {
    fn new(code: FindingCode, message: String, value: f64) -> Finding {
        Finding { code, message, position_mm: None, value: Some(value) }
    }
}

/// The findings the report's measurements imply against `profile`, in a
/// fixed order (the codes' order).
pub(super) fn findings(r: &PrintReport, profile: &PrinterProfile) -> Vec<Finding> {
    let mut out = Vec::new();
    let min_wall = profile.min_wall_mm();
    if let (Some(t), Some(at)) = (r.thinnest_wall_mm, r.thinnest_wall_at_mm) {
        // The profile's resolution is a micrometre.
        if t < min_wall - 1e-3 {
            out.push(Finding {
                code: FindingCode::ThinWall,
                message: format!(
                    "thinnest feature is a wall {t:.3} mm thick at ({:.2}, {:.2}, {:.2}) mm, below the printer's {min_wall} mm minimum ({} of {} places measured are thinner, {:.1} mm² of surface): it may not print (raise size_mm)",
                    at[0], at[1], at[2], r.thin_wall_places, r.wall_rays, r.thin_wall_area_mm2
                ),
                position_mm: Some(at),
                value: Some(t),
            });
        }
    }
    let build = profile.build_mm();
    let over = (0..3).map(|k| r.bbox_mm[k] - build[k]).fold(0.0, f64::max);
    // A micrometre of slack: sizes are scaled in f32.
    if over > 1e-3 {
        out.push(Finding::new(
            FindingCode::TooBig,
            format!(
                "the model is {:.1} × {:.1} × {:.1} mm as placed (z up), larger than the build volume {} × {} × {} mm (by {over:.1} mm): lower size_mm",
                r.bbox_mm[0], r.bbox_mm[1], r.bbox_mm[2], build[0], build[1], build[2]
            ),
            over,
        ));
    }
    if r.triangles > u64::from(profile.triangle_ceiling) {
        out.push(Finding::new(
            FindingCode::TooManyTriangles,
            format!("{} triangles, more than the ceiling of {}: lower the detail", r.triangles, profile.triangle_ceiling),
            r.triangles as f64,
        ));
    }
    if r.shells > 1 {
        out.push(Finding::new(
            FindingCode::SeparateShells,
            format!("{} separate shells: the parts do not all touch (or the solid has inner cavities)", r.shells),
            r.shells as f64,
        ));
    }
    if r.thickened_parts > 0 {
        out.push(Finding::new(
            FindingCode::OpenSurface,
            format!(
                "the model has no solid: its {} open or non-manifold parts (surfaces without volume) were thickened into walls {:.3} mm thick",
                r.thickened_parts, r.wall_mm
            ),
            r.thickened_parts as f64,
        ));
    }
    if r.skipped_parts > 0 {
        out.push(Finding::new(
            FindingCode::OpenSurface,
            format!("{} open or non-manifold parts (e.g. free-vertex surfaces) were left out", r.skipped_parts),
            r.skipped_parts as f64,
        ));
    }
    if !r.is_watertight {
        out.push(Finding::new(
            FindingCode::NotWatertight,
            format!(
                "the result is not watertight: {} edges are not shared by exactly two oppositely wound faces (parts that touch only along an edge or at a point); separate them slightly or thicken the contact",
                r.nonmanifold_edges
            ),
            r.nonmanifold_edges as f64,
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn codes(r: &PrintReport, p: &PrinterProfile) -> Vec<FindingCode> {
        findings(r, p).iter().map(|f| f.code).collect()
    }

    #[test]
    fn each_code_from_its_measurement() {
        let fine = PrintReport { bbox_mm: [20.0, 20.0, 2.0], shells: 1, is_watertight: true, triangles: 12, thinnest_wall_mm: Some(2.0), thinnest_wall_at_mm: Some([0.0; 3]), ..PrintReport::default() };
        let p = PrinterProfile::default();
        assert_eq!(codes(&fine, &p), vec![]);
        let thin = PrintReport { thinnest_wall_mm: Some(0.5), thinnest_wall_at_mm: Some([1.0, 2.0, 0.5]), ..fine.clone() };
        let f = findings(&thin, &p);
        assert_eq!((f[0].code, f[0].value, f[0].position_mm), (FindingCode::ThinWall, Some(0.5), Some([1.0, 2.0, 0.5])));
        assert!(f[0].message.contains("0.500 mm"), "{}", f[0].message);
        assert_eq!(codes(&thin, &PrinterProfile { min_wall_um: 400, ..p }), vec![]);
        // Exactly the minimum is not thin.
        assert_eq!(codes(&PrintReport { thinnest_wall_mm: Some(0.8), ..thin.clone() }, &p), vec![]);
        let big = PrintReport { bbox_mm: [20.0, 20.0, 300.0], ..fine.clone() };
        let f = findings(&big, &p);
        assert_eq!((f[0].code, f[0].value), (FindingCode::TooBig, Some(90.0)));
        assert_eq!(codes(&fine, &PrinterProfile { triangle_ceiling: 11, ..p }), vec![FindingCode::TooManyTriangles]);
        let bad = PrintReport { shells: 3, is_watertight: false, nonmanifold_edges: 4, thickened_parts: 2, skipped_parts: 1, ..fine.clone() };
        assert_eq!(codes(&bad, &p), vec![FindingCode::SeparateShells, FindingCode::OpenSurface, FindingCode::OpenSurface, FindingCode::NotWatertight]);
        let json = serde_json::to_value(findings(&big, &p)).expect("json");
        assert_eq!(json[0]["code"], "too_big");
        assert!(json[0].get("position_mm").is_none(), "{json}");
    }
}
