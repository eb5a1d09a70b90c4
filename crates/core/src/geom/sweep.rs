//! Swept lines (Andersson 2015 §4.3): a profile ring placed at every pen position,
//! consecutive rings joined by quad strips, open ends capped so each line is
//! a closed solid. A line whose last point returns to its first is joined
//! into a loop instead of capped, so a lathe or a knot closes with no gap.
//!
//! The profile is a regular polygon of radius [`PROFILE_RADIUS`] in each
//! frame's local XY plane, or a profile rule's points. Where each ring goes
//! is [`super::mitre`]'s plan: perpendicular to the path, mitred at corners,
//! transported without twist. Orientation is decided from the geometry of
//! each closed piece, so mirrored frames and pens moving backwards still give
//! outward-facing faces, and every vertex normal agrees with the winding.

use super::mesh::mesh_bytes;
use super::mitre::{self, Joint, Piece, Turn};
use super::Mesh;
use crate::core::budget::{Budget, LimitExceeded};
use crate::core::frame::Frame;
use glam::{DQuat, DVec3};
use std::f64::consts::TAU;

/// One pen position of a swept line: the frame the profile is placed in, and its colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinePoint {
    /// The profile's frame (the profile lies in the frame's local XY plane).
    pub frame: Frame,
    /// Linear RGBA, each clamped to [0, 1].
    pub colour: [f32; 4],
}

/// A swept line: consecutive points joined by tubes (Andersson 2015 §4.3).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Polyline {
    /// The pen positions in drawing order; n points make n − 1 segments.
    pub points: Vec<LinePoint>,
    /// Index into `Scene::profiles` of the cross-section; `None` is the default round tube.
    pub profile: Option<u32>,
}

/// Radius of the default line profile, in the local units of each pen frame.
pub const PROFILE_RADIUS: f64 = 0.05;

/// Sides of the profile polygon at `detail`: half the detail, at least 4.
pub fn profile_sides(detail: u32) -> u64 {
    u64::from((detail / 2).max(4))
}

/// Upper bounds on the vertices and triangles one more point can add to a
/// line with an `n`-sided profile (its ring and strip, plus the two caps
/// counted on every point), so the evaluator can charge the budget as points
/// are drawn.
pub fn per_point_bound(n: u64) -> (u64, u64) {
    (n + 2 * (n + 1), 2 * n + 2 * n)
}

/// A line's cross-section in its local frame: `n` points and their outward directions.
fn profile_points(profile: Option<&[DVec3]>, detail: u32) -> Vec<(DVec3, DVec3)> {
    match profile {
        Some(points) if points.len() >= 3 => {
            // Normals point away from the profile's centroid.
            let c = centre(points);
            points.iter().map(|p| (*p, (*p - c).normalize_or_zero())).collect()
        }
        _ => {
            let n = profile_sides(detail);
            (0..n)
                .map(|i| {
                    let a = TAU * i as f64 / n as f64;
                    let dir = DVec3::new(libm::cos(a), libm::sin(a), 0.0);
                    (dir * PROFILE_RADIUS, dir)
                })
                .collect()
        }
    }
}

/// The profile placed at pen point `p` as `joint` turns it: positions and
/// unit normals. Coordinates within rounding error of zero are snapped to
/// zero, so points that are on an axis in exact arithmetic (the poles of a
/// lathe) coincide exactly and the surface closes.
fn ring(p: &LinePoint, joint: &Joint, profile: &[(DVec3, DVec3)]) -> (Vec<DVec3>, Vec<DVec3>) {
    let f = &p.frame;
    let tiny = 1e-12 * f.scale.max(f.translation.abs().max_element());
    let snap = |v: DVec3| DVec3::from_array(v.to_array().map(|c| if c.abs() <= tiny { 0.0 } else { c }));
    // The frame's scale and mirroring with the plan's rotation.
    let offset = |r: DQuat, q: DVec3| f.sign() * f.scale * (r * q);
    let normal = |r: DQuat, d: DVec3| f.sign() * (r * d);
    profile
        .iter()
        .map(|(q, d)| match joint.turn {
            Turn::Frame => (snap(f.transform_point(*q)), f.transform_normal(*d).normalize_or_zero()),
            Turn::Square(r) => (snap(f.translation + offset(r, *q)), normal(r, *d).normalize_or_zero()),
            Turn::Mitre { d_in, r_in, d_out, r_out } => {
                // Along the incoming heading onto the bisecting plane: the
                // outgoing tube's ring lands on the same points.
                let b = (d_in + d_out).normalize_or(d_in);
                let o = offset(r_in, *q);
                let pos = f.translation + o - d_in * (o.dot(b) / d_in.dot(b).max(1.0 / mitre::MITRE_LIMIT));
                let n_in = normal(r_in, *d);
                (snap(pos), (n_in + normal(r_out, *d)).try_normalize().unwrap_or(n_in.normalize_or_zero()))
            }
        })
        .unzip()
}

fn centre(points: &[DVec3]) -> DVec3 {
    points.iter().copied().sum::<DVec3>() / points.len().max(1) as f64
}

fn colour8(c: [f32; 4]) -> [u8; 4] {
    crate::core::quantise::rgba8(c)
}

fn push(mesh: &mut Mesh, p: DVec3, n: DVec3, c: [u8; 4]) -> u32 {
    // Fits: the caller bounds the vertex count below u32::MAX.
    let i = mesh.positions.len() as u32;
    mesh.positions.push(p.as_vec3().to_array());
    // glTF requires unit normals; a point with no defined normal gets +Z.
    mesh.normals.push(n.try_normalize().unwrap_or(DVec3::Z).as_vec3().to_array());
    mesh.colours.push(c);
    i
}

/// True when two rings are the same place (a segment between them has no area).
fn same_ring(a: &[DVec3], b: &[DVec3]) -> bool {
    let scale = a.iter().chain(b).fold(0.0f64, |m, p| m.max(p.abs().max_element())).max(1.0);
    a.iter().zip(b).all(|(p, q)| (*p - *q).length() <= 1e-9 * scale)
}

/// Appends a strip between two rings (vertex index bases `ia`, `ib`). Ring
/// edges run a_i → a_{i+1} in the strip's triangles; caps use the opposite
/// direction, so a whole line is consistently wound (its outward side is
/// chosen afterwards from its signed volume).
fn strip(mesh: &mut Mesh, ia: u32, ib: u32, n: u32) {
    for i in 0..n {
        let j = (i + 1) % n;
        for t in [[ia + i, ia + j, ib + j], [ia + i, ib + j, ib + i]] {
            // Rings that share a point (a lathe around its own axis) would give
            // zero-area triangles; leaving them out keeps the surface closed.
            if !degenerate(mesh, t) {
                mesh.indices.extend_from_slice(&t);
            }
        }
    }
}

/// True when a triangle has (numerically) no area.
fn degenerate(mesh: &Mesh, t: [u32; 3]) -> bool {
    let at = |i: u32| DVec3::from_array(mesh.positions[i as usize].map(f64::from));
    let (a, b, c) = (at(t[0]), at(t[1]), at(t[2]));
    let scale = (b - a).length().max((c - a).length()).max(1e-30);
    (b - a).cross(c - a).length() <= 1e-9 * scale * scale
}

/// Appends a flat cap over `ring` with its normal facing away from `inward`
/// (a point on the line's other side). `at_start` picks the edge direction
/// that matches the strip next to it.
fn cap(mesh: &mut Mesh, ring: &[DVec3], inward: DVec3, colour: [u8; 4], at_start: bool) {
    let c = centre(ring);
    let Some(face) = (ring[1] - ring[0]).cross(ring[2 % ring.len()] - ring[0]).try_normalize() else {
        // A ring collapsed to a point (scale 0) closes the line by itself.
        return;
    };
    let normal = if face.dot(c - inward) < 0.0 { -face } else { face };
    let base = push(mesh, c, normal, colour);
    for p in ring {
        push(mesh, *p, normal, colour);
    }
    let n = ring.len() as u32;
    for i in 0..n {
        let (a, b) = (base + 1 + i, base + 1 + (i + 1) % n);
        let t = if at_start { [base, b, a] } else { [base, a, b] };
        // A ring collapsed to a point (scale 0) needs no cap.
        if !degenerate(mesh, t) {
            mesh.indices.extend_from_slice(&t);
        }
    }
}

/// Six times the signed volume enclosed by the triangles in `indices`.
fn signed_volume6(mesh: &Mesh, indices: &[u32]) -> f64 {
    let at = |i: u32| DVec3::from_array(mesh.positions[i as usize].map(f64::from));
    indices.chunks_exact(3).map(|t| at(t[0]).dot(at(t[1]).cross(at(t[2])))).sum()
}

/// Sweeps every line into one mesh, reserving its bytes in `budget` first.
/// `profiles` are the scene's cross-sections that lines refer to by index.
/// Lines with fewer than two distinct rings draw nothing. `stop` is asked
/// before each line whether to stop there (a caller's deadline); the lines
/// swept by then are the mesh.
pub fn sweep_lines(
    lines: &[Polyline],
    profiles: &[Vec<DVec3>],
    detail: u32,
    budget: &mut Budget,
    stop: &mut dyn FnMut(&Budget) -> Result<bool, LimitExceeded>,
) -> Result<Option<Mesh>, LimitExceeded> {
    let profile_of = |l: &Polyline| profile_points(l.profile.and_then(|i| profiles.get(i as usize)).map(Vec::as_slice), detail);
    let (mut vmax, mut tmax) = (0u64, 0u64);
    for l in lines {
        let profile = profile_of(l);
        for piece in mitre::plan(&l.points, axis_of(&profile)) {
            let (pv, pt) = piece_bound(&piece, profile.len() as u64);
            vmax = vmax.saturating_add(pv);
            tmax = tmax.saturating_add(pt);
        }
    }
    if vmax == 0 {
        return Ok(None);
    }
    if vmax > u64::from(u32::MAX) {
        return Err(budget.memory_refused(mesh_bytes(vmax, tmax)));
    }
    budget.reserve_memory(mesh_bytes(vmax, tmax))?;
    let mut mesh = Mesh {
        positions: Vec::with_capacity(vmax as usize),
        normals: Vec::with_capacity(vmax as usize),
        colours: Vec::with_capacity(vmax as usize),
        indices: Vec::with_capacity((tmax as usize).saturating_mul(3)),
    };
    for line in lines {
        if stop(budget)? {
            break;
        }
        let profile = profile_of(line);
        for piece in mitre::plan(&line.points, axis_of(&profile)) {
            sweep_piece(&mut mesh, line, &piece, &profile);
        }
    }
    // Give back what the upper bound over-reserved.
    let used = mesh_bytes(mesh.positions.len() as u64, mesh.triangle_count() as u64);
    budget.release_memory(mesh_bytes(vmax, tmax).saturating_sub(used));
    mesh.positions.shrink_to_fit();
    mesh.normals.shrink_to_fit();
    mesh.colours.shrink_to_fit();
    mesh.indices.shrink_to_fit();
    Ok(if mesh.indices.is_empty() { None } else { Some(mesh) })
}

/// The plane normal of a placed profile (local), for the plan.
fn axis_of(profile: &[(DVec3, DVec3)]) -> DVec3 {
    mitre::profile_axis(&profile.iter().map(|(p, _)| *p).collect::<Vec<_>>())
}

/// Upper bounds on the vertices and triangles of one piece with an
/// `n`-sided profile: its rings, a strip per ring (the loop's closing one
/// included) and two caps.
fn piece_bound(piece: &Piece, n: u64) -> (u64, u64) {
    let r = piece.joints.len() as u64;
    (r.saturating_mul(n).saturating_add(2 * (n + 1)), r.saturating_add(1).saturating_mul(2 * n))
}

/// Appends one piece of `line`: its rings, the strips between them, and caps
/// unless it is a loop; then turns it outward. A line that never moves gets
/// its normals from its own surface (its rings may sweep over themselves).
fn sweep_piece(mesh: &mut Mesh, line: &Polyline, piece: &Piece, profile: &[(DVec3, DVec3)]) {
    // Fits: profiles come from a bounded number of VERTEX calls.
    let n32 = profile.len() as u32;
    let mut rings: Vec<(Vec<DVec3>, Vec<DVec3>, [u8; 4])> = Vec::with_capacity(piece.joints.len());
    for joint in &piece.joints {
        let Some(p) = line.points.get(joint.point) else { continue };
        let (pos, nrm) = ring(p, joint, profile);
        // A still line's rings may repeat (pure turns about the ring's own axis).
        if piece.pivot && rings.last().is_some_and(|(prev, _, _)| same_ring(prev, &pos)) {
            continue;
        }
        rings.push((pos, nrm, colour8(p.colour)));
    }
    if rings.len() < 2 {
        return;
    }
    let mut closed = piece.closed;
    if piece.pivot && rings.len() > 2 && rings.first().zip(rings.last()).is_some_and(|(a, b)| same_ring(&a.0, &b.0)) {
        rings.pop();
        closed = true;
    }
    let (vertex_start, index_start) = (mesh.positions.len(), mesh.indices.len());
    let bases: Vec<u32> = rings
        .iter()
        .map(|(pos, nrm, c)| {
            let base = mesh.positions.len() as u32;
            for (p, q) in pos.iter().zip(nrm) {
                push(mesh, *p, *q, *c);
            }
            base
        })
        .collect();
    for w in bases.windows(2) {
        strip(mesh, w[0], w[1], n32);
    }
    if closed {
        if let (Some(&last), Some(&first)) = (bases.last(), bases.first()) {
            strip(mesh, last, first, n32);
        }
    } else if let (Some(first), Some(second), Some(last), Some(before)) =
        (rings.first(), rings.get(1), rings.last(), rings.get(rings.len() - 2))
    {
        cap(mesh, &first.0, centre(&second.0), first.2, true);
        cap(mesh, &last.0, centre(&before.0), last.2, false);
    }
    // Consistent winding throughout; turn the piece outward if it is inside out.
    if signed_volume6(mesh, &mesh.indices[index_start..]) < 0.0 {
        for t in mesh.indices[index_start..].chunks_exact_mut(3) {
            t.swap(1, 2);
        }
    }
    if piece.pivot {
        surface_normals(mesh, vertex_start, index_start);
    }
}

/// Replaces the normals of the vertices from `vertex_start` on with the
/// area-weighted mean of the faces (from `index_start` on) around them, so
/// they agree with the winding wherever the surface does not fold; a vertex
/// with no face keeps its normal.
fn surface_normals(mesh: &mut Mesh, vertex_start: usize, index_start: usize) {
    let at = |m: &Mesh, i: u32| DVec3::from_array(m.positions[i as usize].map(f64::from));
    let mut sum = vec![DVec3::ZERO; mesh.positions.len() - vertex_start];
    for t in mesh.indices[index_start..].chunks_exact(3) {
        let face = (at(mesh, t[1]) - at(mesh, t[0])).cross(at(mesh, t[2]) - at(mesh, t[0]));
        for &i in t {
            if let Some(s) = sum.get_mut((i as usize).wrapping_sub(vertex_start)) {
                *s += face;
            }
        }
    }
    for (n, s) in mesh.normals[vertex_start..].iter_mut().zip(sum) {
        if let Some(u) = s.try_normalize() {
            *n = u.as_vec3().to_array();
        }
    }
}

/// One line swept for printing: one mesh per run that stays clear of itself
/// ([`mitre::apart`]), so the print stage's union can join a line that
/// crosses or touches itself. Charges `budget` for the meshes.
pub fn sweep_line_parts(line: &Polyline, profiles: &[Vec<DVec3>], detail: u32, budget: &mut Budget) -> Result<Vec<Mesh>, LimitExceeded> {
    let profile = profile_points(line.profile.and_then(|i| profiles.get(i as usize)).map(Vec::as_slice), detail);
    let reach = profile.iter().fold(0.0f64, |m, (p, _)| m.max(p.length()));
    let mut meshes = Vec::new();
    for piece in mitre::apart(&line.points, mitre::plan(&line.points, axis_of(&profile)), reach) {
        let (v, t) = piece_bound(&piece, profile.len() as u64);
        if v > u64::from(u32::MAX) {
            return Err(budget.memory_refused(mesh_bytes(v, t)));
        }
        budget.reserve_memory(mesh_bytes(v, t))?;
        let mut mesh = Mesh::default();
        sweep_piece(&mut mesh, line, &piece, &profile);
        budget.release_memory(mesh_bytes(v, t).saturating_sub(mesh_bytes(mesh.positions.len() as u64, mesh.triangle_count() as u64)));
        if !mesh.indices.is_empty() {
            meshes.push(mesh);
        }
    }
    Ok(meshes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;
    use crate::core::frame::Frame;
    use std::collections::BTreeMap;

    fn sweep(ps: &[[f64; 3]]) -> Mesh {
        let points = ps.iter().map(|p| LinePoint { frame: Frame::from_translation(DVec3::from_array(*p)), colour: [1.0; 4] }).collect();
        let mut budget = Budget::new(Limits::default());
        sweep_lines(&[Polyline { points, profile: None }], &[], 16, &mut budget, &mut |_| Ok(false)).expect("fits").expect("a mesh")
    }

    fn at(m: &Mesh, i: u32) -> DVec3 {
        DVec3::from_array(m.positions[i as usize].map(f64::from))
    }

    /// Triangles whose winding disagrees with the mean of their vertex normals.
    fn disagreeing(m: &Mesh) -> usize {
        let n = |i: u32| DVec3::from_array(m.normals[i as usize].map(f64::from));
        m.indices.chunks_exact(3).filter(|t| (at(m, t[1]) - at(m, t[0])).cross(at(m, t[2]) - at(m, t[0])).dot(n(t[0]) + n(t[1]) + n(t[2])) <= 0.0).count()
    }

    /// Directed edges by position that have no opposite partner (0 for a closed, consistently wound surface).
    fn unmatched_edges(m: &Mesh) -> usize {
        let key = |i: u32| m.positions[i as usize].map(f32::to_bits);
        let mut count: BTreeMap<([u32; 3], [u32; 3]), i64> = BTreeMap::new();
        for t in m.indices.chunks_exact(3) {
            for k in 0..3 {
                let (a, b) = (key(t[k]), key(t[(k + 1) % 3]));
                *count.entry((a.min(b), a.max(b))).or_default() += if a < b { 1 } else { -1 };
            }
        }
        count.values().filter(|&&v| v != 0).count()
    }

    #[test]
    fn a_right_angle_is_mitred_closed_and_agrees_with_its_normals() {
        let m = sweep(&[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0]]);
        // Three rings of 8, two caps of 9; 2 strips of 16 and 2 caps of 8 triangles.
        assert_eq!((m.positions.len(), m.triangle_count()), (42, 48));
        assert_eq!(unmatched_edges(&m), 0);
        assert_eq!(disagreeing(&m), 0);
        // The corner ring lies in the bisecting plane, stretched by √2 in the bend plane.
        let c = DVec3::new(0.0, 0.0, 1.0);
        let b = DVec3::new(1.0, 0.0, 1.0).normalize();
        let corner: Vec<DVec3> = (8..16).map(|i| at(&m, i) - c).collect();
        assert!(corner.iter().all(|o| o.dot(b).abs() < 1e-7));
        let reach = corner.iter().fold(0.0f64, |r, o| r.max(o.length()));
        assert!((reach - PROFILE_RADIUS * std::f64::consts::SQRT_2).abs() < 1e-7, "{reach}");
    }

    #[test]
    fn a_reversal_is_two_capped_tubes_and_a_square_loop_has_no_caps() {
        let m = sweep(&[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.5]]);
        assert_eq!((m.positions.len(), m.triangle_count()), (2 * (16 + 18), 2 * 32));
        assert!(m.positions.iter().flatten().all(|c| c.is_finite()));
        assert_eq!((unmatched_edges(&m), disagreeing(&m)), (0, 0));
        let square = sweep(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]]);
        assert_eq!((square.positions.len(), square.triangle_count()), (32, 64));
        assert_eq!((unmatched_edges(&square), disagreeing(&square)), (0, 0));
    }
}
