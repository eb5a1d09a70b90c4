//! Bézier curves flattened into line segments by recursive subdivision, as
//! the Anti-Grain Geometry library does it (Maxim Shemanarev, AGG 2.4,
//! `agg_curves.cpp`: `curve3_div` and `curve4_div`, 2002–2006), with its
//! angle tolerance off (AGG's default). Context Free (John Horigan, cfdg
//! 3.4) measures and draws its paths through exactly these polylines: the
//! bounds that frame a picture (`pathIterator::boundingRect`, at a tenth
//! of the drawing's accuracy) and the outlines its rasteriser fills. A
//! Rust crate that flattens (lyon, kurbo) picks other points, and a path's
//! bounds decide the framing of the whole picture, so the points are AGG's.
//!
//! The tolerance is AGG's: a point is accepted when the curve is within
//! `0.5 / scale` of the chord, `scale` being the approximation scale (the
//! size of one unit in pixels for a drawing).

/// Deepest subdivision: 16, where AGG's `curve_recursion_limit` is 32.
/// Each level can double a curve's points, so AGG's limit lets one curve
/// drawn at an absurd scale (a path under `s 7.5` nine times over) become
/// billions of points: the `render_cfdg` fuzz target ran out of memory on
/// it (`fuzz/seeds/render_cfdg/oom-huge-scale-arcs`). 2^16 points bound a
/// curve to 1 MiB, and a curve needs more only when its chord error must
/// stay under half a pixel at a radius of about 2^31 pixels, far beyond
/// any picture, so every drawing cfdg makes is flattened as AGG does.
const RECURSION_LIMIT: u32 = 16;
/// `curve_collinearity_epsilon`.
const COLLINEARITY_EPSILON: f64 = 1e-30;

type P = (f64, f64);

fn sq_dist(a: P, b: P) -> f64 {
    (a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)
}

/// The points of the quadratic curve from `p1` (not emitted) through
/// control `p2` to `p3` (emitted last), pushed to `out` (`curve3_div`).
pub fn flatten_quad(p1: P, p2: P, p3: P, scale: f64, out: &mut Vec<P>) {
    let tol = (0.5 / scale).powi(2);
    quad(p1, p2, p3, tol, 0, out);
    out.push(p3);
}

fn quad(p1: P, p2: P, p3: P, tol: f64, level: u32, out: &mut Vec<P>) {
    if level > RECURSION_LIMIT {
        return;
    }
    let p12 = ((p1.0 + p2.0) / 2.0, (p1.1 + p2.1) / 2.0);
    let p23 = ((p2.0 + p3.0) / 2.0, (p2.1 + p3.1) / 2.0);
    let p123 = ((p12.0 + p23.0) / 2.0, (p12.1 + p23.1) / 2.0);
    let (dx, dy) = (p3.0 - p1.0, p3.1 - p1.1);
    let mut d = ((p2.0 - p3.0) * dy - (p2.1 - p3.1) * dx).abs();
    if d > COLLINEARITY_EPSILON {
        if d * d <= tol * (dx * dx + dy * dy) {
            out.push(p123);
            return;
        }
    } else {
        let da = dx * dx + dy * dy;
        if da == 0.0 {
            d = sq_dist(p1, p2);
        } else {
            d = ((p2.0 - p1.0) * dx + (p2.1 - p1.1) * dy) / da;
            if d > 0.0 && d < 1.0 {
                return;
            }
            d = if d <= 0.0 { sq_dist(p2, p1) } else { sq_dist(p2, p3) };
        }
        if d < tol {
            out.push(p2);
            return;
        }
    }
    quad(p1, p12, p123, tol, level + 1, out);
    quad(p123, p23, p3, tol, level + 1, out);
}

/// The points of the cubic curve from `p1` (not emitted) with controls
/// `p2`, `p3` to `p4` (emitted last), pushed to `out` (`curve4_div`).
pub fn flatten_cubic(p1: P, p2: P, p3: P, p4: P, scale: f64, out: &mut Vec<P>) {
    let tol = (0.5 / scale).powi(2);
    cubic(p1, p2, p3, p4, tol, 0, out);
    out.push(p4);
}

fn cubic(p1: P, p2: P, p3: P, p4: P, tol: f64, level: u32, out: &mut Vec<P>) {
    if level > RECURSION_LIMIT {
        return;
    }
    let mid = |a: P, b: P| ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
    let (p12, p23, p34) = (mid(p1, p2), mid(p2, p3), mid(p3, p4));
    let (p123, p234) = (mid(p12, p23), mid(p23, p34));
    let p1234 = mid(p123, p234);
    let (dx, dy) = (p4.0 - p1.0, p4.1 - p1.1);
    let mut d2 = ((p2.0 - p4.0) * dy - (p2.1 - p4.1) * dx).abs();
    let mut d3 = ((p3.0 - p4.0) * dy - (p3.1 - p4.1) * dx).abs();
    match (u8::from(d2 > COLLINEARITY_EPSILON) << 1) + u8::from(d3 > COLLINEARITY_EPSILON) {
        0 => {
            let k = dx * dx + dy * dy;
            if k == 0.0 {
                d2 = sq_dist(p1, p2);
                d3 = sq_dist(p4, p3);
            } else {
                let k = 1.0 / k;
                d2 = k * ((p2.0 - p1.0) * dx + (p2.1 - p1.1) * dy);
                d3 = k * ((p3.0 - p1.0) * dx + (p3.1 - p1.1) * dy);
                if d2 > 0.0 && d2 < 1.0 && d3 > 0.0 && d3 < 1.0 {
                    return;
                }
                d2 = if d2 <= 0.0 {
                    sq_dist(p2, p1)
                } else if d2 >= 1.0 {
                    sq_dist(p2, p4)
                } else {
                    sq_dist(p2, (p1.0 + d2 * dx, p1.1 + d2 * dy))
                };
                d3 = if d3 <= 0.0 {
                    sq_dist(p3, p1)
                } else if d3 >= 1.0 {
                    sq_dist(p3, p4)
                } else {
                    sq_dist(p3, (p1.0 + d3 * dx, p1.1 + d3 * dy))
                };
            }
            if d2 > d3 {
                if d2 < tol {
                    out.push(p2);
                    return;
                }
            } else if d3 < tol {
                out.push(p3);
                return;
            }
        }
        1 => {
            if d3 * d3 <= tol * (dx * dx + dy * dy) {
                out.push(p23);
                return;
            }
        }
        2 => {
            if d2 * d2 <= tol * (dx * dx + dy * dy) {
                out.push(p23);
                return;
            }
        }
        _ => {
            if (d2 + d3) * (d2 + d3) <= tol * (dx * dx + dy * dy) {
                out.push(p23);
                return;
            }
        }
    }
    cubic(p1, p12, p123, p1234, tol, level + 1, out);
    cubic(p1234, p234, p34, p4, tol, level + 1, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quarter_circle_stays_within_the_tolerance() {
        let k = 0.552_284_749_8;
        let mut pts = Vec::new();
        flatten_cubic((1.0, 0.0), (1.0, k), (k, 1.0), (0.0, 1.0), 100.0, &mut pts);
        assert_eq!(pts.last(), Some(&(0.0, 1.0)));
        assert!(pts.len() > 4 && pts.len() < 64, "{}", pts.len());
        for p in &pts {
            assert!((p.0.hypot(p.1) - 1.0).abs() < 0.005 + 3e-4, "{p:?}");
        }
        let mut line = Vec::new();
        flatten_quad((0.0, 0.0), (0.5, 0.0), (1.0, 0.0), 1.0, &mut line);
        assert_eq!(line, vec![(1.0, 0.0)]);
    }
}
