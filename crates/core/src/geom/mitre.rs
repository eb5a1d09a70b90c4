//! Where the rings of a swept line go (Andersson 2015 §4.3, issue 16): the plan
//! [`super::sweep`] follows when it places a profile ring at each pen point.
//!
//! A line that moves is swept **along its path**: each ring is turned
//! perpendicular to the path, and a ring at a corner lies in the plane that
//! bisects the incoming and outgoing headings, stretched by 1/cos(½ turn) in
//! the bend plane (a mitre joint), so the tube before and the tube after
//! meet in one shared ring and neither folds into the other. The ring's
//! orientation about the path is carried from point to point by the
//! smallest rotation between consecutive headings (a rotation-minimising,
//! "parallel transport" frame), starting from the first pen frame's own
//! roll; a closed loop spreads the twist it gathers evenly over its segments,
//! so the seam has no jump. The pen frames give each ring its position,
//! scale, mirroring and colour; their rotation matters only for the first
//! ring's roll. Consecutive points at one position (turns on the spot,
//! zero-length segments) are one joint, the first of them giving its scale
//! and colour.
//!
//! A turn sharper than [`MITRE_LIMIT`] allows (more than about 151°, where a
//! mitre would reach four times the tube's radius out of the corner, and a
//! reversal has no bisector at all) ends the tube there with a cap and
//! starts a new capped tube at the same point: two closed solids that
//! overlap, which the print stage's union joins.
//!
//! A line that never moves (every point at one position: a lathe turning a
//! ring about an axis) has no path to follow; its rings are placed by the
//! pen frames as they are, and the sweep takes its normals from the surface.

use super::sweep::LinePoint;
use glam::{DQuat, DVec3};

/// The longest a mitre may stretch a ring, as a multiple of its radius (the
/// SVG `stroke-miterlimit` default): a turn whose mitre would stretch more,
/// that is cos(½ turn) < 1/4, is a break instead.
pub(crate) const MITRE_LIMIT: f64 = 4.0;

/// How one ring is turned.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Turn {
    /// As the pen frame places it (a line that never moves).
    Frame,
    /// Perpendicular to the path, with this rotation (a piece's first or last ring).
    Square(DQuat),
    /// In the bisecting plane of a corner: the incoming heading and its
    /// rotation, the outgoing heading and its rotation.
    Mitre { d_in: DVec3, r_in: DQuat, d_out: DVec3, r_out: DQuat },
}

/// One ring of a piece: the pen point it is at and how it is turned.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Joint {
    /// Index into the line's points.
    pub point: usize,
    /// How the ring is turned.
    pub turn: Turn,
}

/// One closed solid of a line: its rings in order, joined into a loop or capped at both ends.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct Piece {
    /// The rings, in drawing order.
    pub joints: Vec<Joint>,
    /// True when the last ring joins the first (no caps).
    pub closed: bool,
    /// True when the line never moves: rings follow the pen frames and a
    /// loop is found by comparing rings, not positions.
    pub pivot: bool,
}

/// The unit normal of a profile's plane (Newell's method), in the profile's
/// local coordinates; +Z when the profile has no plane (collinear points).
pub(super) fn profile_axis(points: &[DVec3]) -> DVec3 {
    let n = points.len();
    let c = points.iter().copied().sum::<DVec3>() / n.max(1) as f64;
    let newell: DVec3 = (0..n).map(|i| (points[i] - c).cross(points[(i + 1) % n] - c)).sum();
    newell.try_normalize().unwrap_or(DVec3::Z)
}

/// The smallest rotation taking unit `from` onto unit `to`; a half turn about
/// an axis perpendicular to `from` when they are opposite.
fn arc(from: DVec3, to: DVec3) -> DQuat {
    let w = 1.0 + from.dot(to);
    if w < 1e-9 {
        return DQuat::from_axis_angle(from.any_orthonormal_vector(), std::f64::consts::PI);
    }
    let v = from.cross(to);
    DQuat::from_xyzw(v.x, v.y, v.z, w).normalize()
}

/// True when the turn from `a` to `b` (unit headings) is too sharp to mitre.
fn sharp(a: DVec3, b: DVec3) -> bool {
    // cos θ = 2·cos²(θ/2) − 1, and the limit is cos(θ/2) ≥ 1/MITRE_LIMIT.
    a.dot(b) < 2.0 / (MITRE_LIMIT * MITRE_LIMIT) - 1.0
}

/// The first point of every run of consecutive points at one position.
fn distinct(points: &[LinePoint], eps: f64) -> Vec<usize> {
    let mut firsts: Vec<usize> = Vec::new();
    for (i, p) in points.iter().enumerate() {
        let moved = firsts.last().is_none_or(|&j| points[j].frame.translation.distance(p.frame.translation) > eps);
        if moved {
            firsts.push(i);
        }
    }
    firsts
}

/// The pieces a line's rings form, given its profile's plane normal `axis`
/// (local). Empty when the line has no points.
pub(super) fn plan(points: &[LinePoint], axis: DVec3) -> Vec<Piece> {
    let size = points.iter().fold(1.0f64, |m, p| m.max(p.frame.translation.abs().max_element()));
    let eps = 1e-9 * size;
    let mut firsts = distinct(points, eps);
    if firsts.len() < 2 {
        let joints = (0..points.len()).map(|point| Joint { point, turn: Turn::Frame }).collect();
        return if points.is_empty() { Vec::new() } else { vec![Piece { joints, closed: false, pivot: true }] };
    }
    let at = |i: usize| points[i].frame.translation;
    let closed = firsts.len() > 2 && firsts.first().zip(firsts.last()).is_some_and(|(&a, &b)| at(a).distance(at(b)) <= eps);
    if closed {
        firsts.pop();
    }
    let g = firsts.len();
    let segments = if closed { g } else { g - 1 };
    let dirs: Vec<DVec3> = (0..segments).map(|j| (at(firsts[(j + 1) % g]) - at(firsts[j])).normalize_or(DVec3::Z)).collect();
    let rots = transport(points[firsts[0]].frame.rotation, axis, &dirs, closed);
    // Joint j joins segment j − 1 (in) and segment j (out).
    let incoming = |j: usize| if j > 0 { Some(j - 1) } else if closed { Some(segments - 1) } else { None };
    let mitre = |j: usize, i: usize| Turn::Mitre { d_in: dirs[i], r_in: rots[i], d_out: dirs[j], r_out: rots[j] };
    let is_break = |j: usize| incoming(j).is_some_and(|i| j < segments && sharp(dirs[i], dirs[j]));
    let joint = |j: usize, turn: Turn| Joint { point: firsts[j % g], turn };
    let mut pieces = Vec::new();
    match (closed, (0..g).find(|&j| is_break(j))) {
        (true, None) => {
            let joints = (0..g).filter_map(|j| incoming(j).map(|i| joint(j, mitre(j, i)))).collect();
            pieces.push(Piece { joints, closed: true, pivot: false });
        }
        (closed, first_break) => {
            // An open walk: from the start (or, for a loop, from its first break) round to the end.
            let start = first_break.filter(|_| closed).unwrap_or(0);
            let last = if closed { start + g } else { g - 1 };
            let mut piece = vec![joint(start, Turn::Square(rots[start]))];
            for k in start + 1..=last {
                let j = k % g;
                // Every joint after the first has an incoming segment.
                let Some(i) = incoming(j) else { continue };
                if k == last {
                    piece.push(joint(j, Turn::Square(rots[i])));
                } else if is_break(j) {
                    piece.push(joint(j, Turn::Square(rots[i])));
                    pieces.push(Piece { joints: std::mem::take(&mut piece), closed: false, pivot: false });
                    piece.push(joint(j, Turn::Square(rots[j])));
                } else {
                    piece.push(joint(j, mitre(j, i)));
                }
            }
            pieces.push(Piece { joints: piece, closed: false, pivot: false });
        }
    }
    pieces
}

/// The ring rotation of every segment: the first turns the pen frame's
/// profile plane (normal `rotation · axis`) onto the first heading by the
/// smallest rotation, each next one follows by the smallest rotation between
/// headings, and a loop's gathered twist about the path is spread evenly.
fn transport(rotation: DQuat, axis: DVec3, dirs: &[DVec3], closed: bool) -> Vec<DQuat> {
    let Some(&d0) = dirs.first() else { return Vec::new() };
    let mut a0 = (rotation * axis).normalize_or(DVec3::Z);
    if a0.dot(d0) < 0.0 {
        a0 = -a0;
    }
    let mut rots = Vec::with_capacity(dirs.len());
    rots.push((arc(a0, d0) * rotation).normalize());
    for w in dirs.windows(2) {
        let prev = rots[rots.len() - 1];
        rots.push((arc(w[0], w[1]) * prev).normalize());
    }
    let n = dirs.len();
    let has_break = closed && (0..n).any(|j| sharp(dirs[(j + n - 1) % n], dirs[j]));
    if closed && !has_break {
        // Carried once round, the first ring comes back turned by φ about d0.
        let back = arc(dirs[n - 1], d0) * rots[n - 1];
        let q = rots[0] * back.inverse();
        let phi = 2.0 * libm::atan2(DVec3::new(q.x, q.y, q.z).dot(d0), q.w);
        let phi = libm::atan2(libm::sin(phi), libm::cos(phi));
        for (j, (r, d)) in rots.iter_mut().zip(dirs).enumerate() {
            *r = (DQuat::from_axis_angle(*d, phi * j as f64 / n as f64) * *r).normalize();
        }
    }
    rots
}

/// How far a joint's ring reaches out of its centre, per unit of profile reach at scale 1.
fn stretch(j: &Joint) -> f64 {
    match j.turn {
        Turn::Mitre { d_in, d_out, .. } => 1.0 / d_in.dot((d_in + d_out).normalize_or(d_in)).max(1.0 / MITRE_LIMIT),
        Turn::Frame | Turn::Square(_) => 1.0,
    }
}

/// The shortest distance between segments `p0`–`p1` and `q0`–`q1`
/// (closest points by clamped parameters, after Ericson's *Real-Time
/// Collision Detection* §5.1.9).
fn segment_distance(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> f64 {
    let (d1, d2, r) = (p1 - p0, q1 - q0, p0 - q0);
    let (a, e, f) = (d1.dot(d1), d2.dot(d2), d2.dot(r));
    let (s, t) = if a <= 1e-300 && e <= 1e-300 {
        (0.0, 0.0)
    } else if a <= 1e-300 {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(r);
        if e <= 1e-300 {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(d2);
            let denom = a * e - b * b;
            let mut s = if denom > 1e-300 { ((b * f - c * e) / denom).clamp(0.0, 1.0) } else { 0.0 };
            let mut t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
            (s, t)
        }
    };
    (p0 + d1 * s).distance(q0 + d2 * t)
}

/// Splits `pieces` into runs whose tubes stay clear of themselves, for the
/// print stage, which unites separate solids but cannot mend one solid that
/// passes through itself (the Koch curve's tube meets itself wherever the
/// curve does). A run ends at a joint when its next segment would come
/// within the two tubes' reach of an earlier segment of the run further back
/// along the path than twice that reach; the next run starts from the same
/// ring, so the two meet face to face and the union fuses them. `reach` is
/// how far the profile reaches from its centre at scale 1. A loop that never
/// comes near itself stays one loop.
pub(super) fn apart(points: &[LinePoint], pieces: Vec<Piece>, reach: f64) -> Vec<Piece> {
    let mut out = Vec::new();
    for piece in pieces {
        if piece.pivot || piece.joints.len() < 2 {
            out.push(piece);
            continue;
        }
        let mut walk = piece.joints.clone();
        if piece.closed {
            walk.push(piece.joints[0]);
        }
        let centre = |j: &Joint| points.get(j.point).map_or(DVec3::ZERO, |p| p.frame.translation);
        let radius = |j: &Joint| points.get(j.point).map_or(0.0, |p| p.frame.scale) * reach * stretch(j);
        let mut runs: Vec<Vec<Joint>> = Vec::new();
        let mut run = vec![walk[0]];
        // The run's segments: ends, radius, and arc length at their end.
        let mut segs: Vec<(DVec3, DVec3, f64, f64)> = Vec::new();
        let mut along = 0.0;
        for w in walk.windows(2) {
            let (a, b) = (centre(&w[0]), centre(&w[1]));
            let rad = radius(&w[0]).max(radius(&w[1]));
            let clash = segs.iter().any(|(p, q, r, end)| along - end > 2.0 * (rad + r) && segment_distance(a, b, *p, *q) < rad + r);
            if clash {
                runs.push(std::mem::take(&mut run));
                run.push(w[0]);
                segs.clear();
            }
            along += a.distance(b);
            run.push(w[1]);
            segs.push((a, b, rad, along));
        }
        runs.push(run);
        if piece.closed && runs.len() == 1 {
            out.push(piece);
        } else {
            out.extend(runs.into_iter().map(|joints| Piece { joints, closed: false, pivot: false }));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::frame::Frame;

    fn line(ps: &[[f64; 3]]) -> Vec<LinePoint> {
        ps.iter().map(|p| LinePoint { frame: Frame::from_translation(DVec3::from_array(*p)), colour: [1.0; 4] }).collect()
    }

    #[test]
    fn a_right_angle_is_one_mitre_between_two_square_ends() {
        let pieces = plan(&line(&[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0]]), DVec3::Z);
        assert_eq!(pieces.len(), 1);
        let turns: Vec<&str> = pieces[0].joints.iter().map(|j| match j.turn {
            Turn::Frame => "frame",
            Turn::Square(_) => "square",
            Turn::Mitre { .. } => "mitre",
        }).collect();
        assert_eq!(turns, ["square", "mitre", "square"]);
        assert!(!pieces[0].closed);
    }

    #[test]
    fn a_reversal_breaks_the_line_into_two_pieces_without_nan() {
        let pieces = plan(&line(&[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.5]]), DVec3::Z);
        assert_eq!(pieces.iter().map(|p| p.joints.len()).collect::<Vec<_>>(), [2, 2]);
        for j in pieces.iter().flat_map(|p| &p.joints) {
            if let Turn::Square(r) = j.turn {
                assert!(r.is_finite());
            }
        }
    }

    #[test]
    fn zero_length_segments_are_one_joint_and_a_still_line_is_a_pivot() {
        let pieces = plan(&line(&[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 1.0, 1.0]]), DVec3::Z);
        assert_eq!(pieces[0].joints.iter().map(|j| j.point).collect::<Vec<_>>(), [0, 1, 3]);
        let still = plan(&line(&[[1.0, 2.0, 3.0]; 3]), DVec3::Z);
        assert!(still[0].pivot);
        assert_eq!(still[0].joints.len(), 3);
    }

    #[test]
    fn a_closed_square_is_one_loop_whose_transport_closes_without_twist() {
        let pieces = plan(&line(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]]), DVec3::Z);
        assert_eq!(pieces.len(), 1);
        assert!(pieces[0].closed);
        assert_eq!(pieces[0].joints.len(), 4);
        // Every joint's in and out rotations differ exactly by the turn between headings.
        for j in &pieces[0].joints {
            let Turn::Mitre { d_in, r_in, d_out, r_out } = j.turn else { panic!("not a mitre") };
            let carried = arc(d_in, d_out) * r_in;
            assert!(carried.dot(r_out).abs() > 1.0 - 1e-12, "twist at joint {}", j.point);
        }
    }

    #[test]
    fn a_run_ends_where_the_tube_would_meet_itself() {
        // A square spiral whose fourth side runs back over the first's start.
        let pts = line(&[[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 2.0, 0.0], [0.0, -1.0, 0.0]]);
        let pieces = plan(&pts, DVec3::Z);
        assert_eq!(pieces.len(), 1);
        let runs = apart(&pts, pieces, 0.1);
        assert_eq!(runs.iter().map(|p| p.joints.iter().map(|j| j.point).collect::<Vec<_>>()).collect::<Vec<_>>(), [vec![0, 1, 2, 3], vec![3, 4]]);
        assert!((segment_distance(DVec3::ZERO, DVec3::X, DVec3::new(0.5, 1.0, 0.0), DVec3::new(0.5, 1.0, 5.0)) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_loop_with_a_reversal_opens_at_it() {
        // Out along x, back to the start: both turns are reversals.
        let pieces = plan(&line(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 0.0]]), DVec3::Z);
        assert!(pieces.iter().all(|p| !p.closed));
        assert_eq!(pieces.iter().map(|p| p.joints.len()).sum::<usize>(), 5);
    }
}
