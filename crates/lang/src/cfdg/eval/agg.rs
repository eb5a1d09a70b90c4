//! The path store Context Free builds its paths in: a port of the parts of
//! AGG's `path_storage` that cfdg uses (Maxim Shemanarev, Anti-Grain
//! Geometry 2.4, `agg_path_storage.h`: `move_to`, `line_to`, `curve3`,
//! `curve4` and their smooth forms, `rel_to_abs`, `end_poly`,
//! `close_polygon`, `start_new_path`, `arc_to` with `join_path`; and
//! `agg_bezier_arc.cpp`: `bezier_arc_svg`, the SVG elliptical arc as at
//! most four cubic curves), and the bounds of a stroked or filled path as
//! `pathIterator::boundingRect` measures them (Context Free 3.4).
//!
//! Written by hand: the vertices and their commands are what cfdg's SVG
//! prints and what its bounds are measured on, so they must be AGG's own.

use super::state::Affine;
use crate::cfdg::syntax::path_flags as pf;
use crate::geom::curves::{flatten_cubic, flatten_quad};

/// AGG's path commands (`path_commands_e`) and the close flag.
pub(crate) const STOP: u8 = 0;
/// Starts a subpath.
pub(crate) const MOVE_TO: u8 = 1;
/// A line.
pub(crate) const LINE_TO: u8 = 2;
/// A quadratic curve's control or end point.
pub(crate) const CURVE3: u8 = 3;
/// A cubic curve's control or end point.
pub(crate) const CURVE4: u8 = 4;
/// Ends a polygon (with [`CLOSE`] when closed).
pub(crate) const END_POLY: u8 = 0x0F;
/// `path_flags_close`.
pub(crate) const CLOSE: u8 = 0x40;

/// One vertex and its command.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vertex {
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
    /// Its command (with flags for [`END_POLY`]).
    pub cmd: u8,
}

/// `is_vertex`: a move, line or curve point.
pub(crate) fn is_vertex(c: u8) -> bool {
    (MOVE_TO..END_POLY).contains(&c)
}

fn is_curve(c: u8) -> bool {
    c == CURVE3 || c == CURVE4
}

/// AGG's `path_storage`.
#[derive(Debug, Clone, Default)]
pub(crate) struct PathStorage {
    /// The vertices.
    pub v: Vec<Vertex>,
}

impl PathStorage {
    fn add(&mut self, x: f64, y: f64, cmd: u8) {
        self.v.push(Vertex { x, y, cmd });
    }
    /// The last command, [`STOP`] when empty.
    pub(crate) fn last_command(&self) -> u8 {
        self.v.last().map_or(STOP, |v| v.cmd)
    }
    /// The last vertex and its command.
    pub(crate) fn last_vertex(&self) -> (f64, f64, u8) {
        self.v.last().map_or((0.0, 0.0, STOP), |v| (v.x, v.y, v.cmd))
    }
    fn prev_vertex(&self) -> (f64, f64, u8) {
        let n = self.v.len();
        if n > 1 {
            let v = self.v[n - 2];
            (v.x, v.y, v.cmd)
        } else {
            (0.0, 0.0, STOP)
        }
    }
    /// Makes a relative point absolute.
    pub(crate) fn rel_to_abs(&self, x: &mut f64, y: &mut f64) {
        let (x2, y2, c) = self.last_vertex();
        if is_vertex(c) {
            *x += x2;
            *y += y2;
        }
    }
    /// `move_to`.
    pub(crate) fn move_to(&mut self, x: f64, y: f64) {
        self.add(x, y, MOVE_TO);
    }
    /// `line_to`.
    pub(crate) fn line_to(&mut self, x: f64, y: f64) {
        self.add(x, y, LINE_TO);
    }
    /// `curve3(ctrl, to)`.
    pub(crate) fn curve3(&mut self, cx: f64, cy: f64, x: f64, y: f64) {
        self.add(cx, cy, CURVE3);
        self.add(x, y, CURVE3);
    }
    /// `curve3(to)`: the control point reflected from the last curve's.
    pub(crate) fn curve3_smooth(&mut self, x: f64, y: f64) {
        let (x0, y0, c) = self.last_vertex();
        if is_vertex(c) {
            let (px, py, pc) = self.prev_vertex();
            let (cx, cy) = if is_curve(pc) { (2.0 * x0 - px, 2.0 * y0 - py) } else { (x0, y0) };
            self.curve3(cx, cy, x, y);
        }
    }
    /// `curve4(ctrl1, ctrl2, to)`.
    pub(crate) fn curve4(&mut self, c1: (f64, f64), c2: (f64, f64), x: f64, y: f64) {
        self.add(c1.0, c1.1, CURVE4);
        self.add(c2.0, c2.1, CURVE4);
        self.add(x, y, CURVE4);
    }
    /// `curve4(ctrl2, to)`: the first control point reflected.
    pub(crate) fn curve4_smooth(&mut self, c2: (f64, f64), x: f64, y: f64) {
        let (x0, y0, c) = self.last_vertex();
        if is_vertex(c) {
            let (px, py, pc) = self.prev_vertex();
            let c1 = if is_curve(pc) { (2.0 * x0 - px, 2.0 * y0 - py) } else { (x0, y0) };
            self.curve4(c1, c2, x, y);
        }
    }
    /// `end_poly(flags)`.
    pub(crate) fn end_poly(&mut self, flags: u8) {
        if is_vertex(self.last_command()) {
            self.add(0.0, 0.0, END_POLY | flags);
        }
    }
    /// `close_polygon`.
    pub(crate) fn close_polygon(&mut self) {
        self.end_poly(CLOSE);
    }
    /// `start_new_path`.
    pub(crate) fn start_new_path(&mut self) {
        if self.last_command() != STOP {
            self.add(0.0, 0.0, STOP);
        }
    }
    /// Applies `t` to every vertex from `start` on.
    pub(crate) fn transform_from(&mut self, start: usize, t: &Affine) {
        for v in self.v.iter_mut().skip(start) {
            if is_vertex(v.cmd) {
                (v.x, v.y) = t.apply(v.x, v.y);
            }
        }
    }
    /// `arc_to`: an SVG elliptical arc from the last point to `(x, y)`.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn arc_to(&mut self, rx: f64, ry: f64, angle: f64, large: bool, sweep: bool, x: f64, y: f64) {
        let (x0, y0, c) = self.last_vertex();
        if !is_vertex(c) {
            self.move_to(x, y);
            return;
        }
        let (rx, ry) = (rx.abs(), ry.abs());
        if rx < 1e-30 || ry < 1e-30 {
            self.line_to(x, y);
            return;
        }
        if (x - x0).hypot(y - y0) < 1e-30 {
            return;
        }
        match bezier_arc_svg(x0, y0, rx, ry, angle, large, sweep, x, y) {
            Some((pts, cmd)) => {
                // join_path: the first point is the last one already there.
                for &(px, py) in pts.iter().skip(1) {
                    self.add(px, py, cmd);
                }
            }
            None => self.line_to(x, y),
        }
    }
}

/// `bezier_arc_svg::init`: the arc's points (the start first) and their
/// command, or `None` when the radii are far too small (`radii_ok`).
#[allow(clippy::too_many_arguments)]
fn bezier_arc_svg(x0: f64, y0: f64, mut rx: f64, mut ry: f64, angle: f64, large: bool, sweep: bool, x2: f64, y2: f64) -> Option<(Vec<(f64, f64)>, u8)> {
    let pi = std::f64::consts::PI;
    let (dx2, dy2) = ((x0 - x2) / 2.0, (y0 - y2) / 2.0);
    let (cos_a, sin_a) = (angle.cos(), angle.sin());
    let x1 = cos_a * dx2 + sin_a * dy2;
    let y1 = -sin_a * dx2 + cos_a * dy2;
    let (mut prx, mut pry) = (rx * rx, ry * ry);
    let (px1, py1) = (x1 * x1, y1 * y1);
    let check = px1 / prx + py1 / pry;
    let mut ok = true;
    if check > 1.0 {
        rx *= check.sqrt();
        ry *= check.sqrt();
        prx = rx * rx;
        pry = ry * ry;
        ok = check <= 10.0;
    }
    let sign = if large == sweep { -1.0 } else { 1.0 };
    let sq = (prx * pry - prx * py1 - pry * px1) / (prx * py1 + pry * px1);
    let coef = sign * (if sq < 0.0 { 0.0 } else { sq }).sqrt();
    let cx1 = coef * ((rx * y1) / ry);
    let cy1 = coef * -((ry * x1) / rx);
    let (sx2, sy2) = ((x0 + x2) / 2.0, (y0 + y2) / 2.0);
    let cx = sx2 + (cos_a * cx1 - sin_a * cy1);
    let cy = sy2 + (sin_a * cx1 + cos_a * cy1);
    let (ux, uy) = ((x1 - cx1) / rx, (y1 - cy1) / ry);
    let (vx, vy) = ((-x1 - cx1) / rx, (-y1 - cy1) / ry);
    let n = (ux * ux + uy * uy).sqrt();
    let s = if uy < 0.0 { -1.0 } else { 1.0 };
    let start = s * (ux / n).clamp(-1.0, 1.0).acos();
    let n = ((ux * ux + uy * uy) * (vx * vx + vy * vy)).sqrt();
    let p = ux * vx + uy * vy;
    let s = if ux * vy - uy * vx < 0.0 { -1.0 } else { 1.0 };
    let mut sweep_angle = s * (p / n).clamp(-1.0, 1.0).acos();
    if !sweep && sweep_angle > 0.0 {
        sweep_angle -= 2.0 * pi;
    } else if sweep && sweep_angle < 0.0 {
        sweep_angle += 2.0 * pi;
    }
    if !ok {
        return None;
    }
    let (mut pts, cmd) = bezier_arc(rx, ry, start, sweep_angle);
    let (sa, ca) = angle.sin_cos();
    let last = pts.len() - 1;
    for p in pts.iter_mut().take(last).skip(1) {
        let (x, y) = *p;
        *p = (x * ca - y * sa + cx, x * sa + y * ca + cy);
    }
    pts[0] = (x0, y0);
    pts[last] = (x2, y2);
    Some((pts, cmd))
}

/// `bezier_arc::init` about the origin.
fn bezier_arc(rx: f64, ry: f64, start: f64, sweep: f64) -> (Vec<(f64, f64)>, u8) {
    let pi = std::f64::consts::PI;
    let mut start = start % (2.0 * pi);
    let sweep = sweep.clamp(-2.0 * pi, 2.0 * pi);
    if sweep.abs() < 1e-10 {
        return (vec![(rx * start.cos(), ry * start.sin()), (rx * (start + sweep).cos(), ry * (start + sweep).sin())], LINE_TO);
    }
    let mut pts = vec![(0.0, 0.0)];
    let (mut total, mut done) = (0.0, false);
    while !done && pts.len() < 13 {
        let prev = total;
        let mut local;
        if sweep < 0.0 {
            local = -pi * 0.5;
            total -= pi * 0.5;
            if total <= sweep + 0.01 {
                local = sweep - prev;
                done = true;
            }
        } else {
            local = pi * 0.5;
            total += pi * 0.5;
            if total >= sweep - 0.01 {
                local = sweep - prev;
                done = true;
            }
        }
        // arc_to_bezier
        let (x0, y0) = ((local / 2.0).cos(), (local / 2.0).sin());
        let tx = (1.0 - x0) * 4.0 / 3.0;
        let ty = y0 - tx * x0 / y0;
        let px = [x0, x0 + tx, x0 + tx, x0];
        let py = [-y0, -ty, ty, y0];
        let (sn, cs) = (start + local / 2.0).sin_cos();
        let at = |i: usize| (rx * (px[i] * cs - py[i] * sn), ry * (px[i] * sn + py[i] * cs));
        if let Some(first) = pts.last_mut() {
            *first = at(0);
        }
        pts.extend([at(1), at(2), at(3)]);
        start += local;
    }
    (pts, CURVE4)
}

/// The polylines of `v` (one path sequence: from its start to its stop),
/// curves flattened at approximation scale `scale`, each with whether it
/// is closed, after `t`.
pub fn polylines(v: &[Vertex], t: &Affine, scale: f64) -> Vec<(Vec<(f64, f64)>, bool)> {
    let mut out: Vec<(Vec<(f64, f64)>, bool)> = Vec::new();
    let mut i = 0;
    let tp = |v: &Vertex| t.apply(v.x, v.y);
    while i < v.len() {
        let c = v[i].cmd;
        let last = out.last_mut().and_then(|(p, _)| p.last().copied());
        match c {
            MOVE_TO => out.push((vec![tp(&v[i])], false)),
            LINE_TO => match out.last_mut() {
                Some((p, _)) => p.push(tp(&v[i])),
                None => out.push((vec![tp(&v[i])], false)),
            },
            CURVE3 if i + 1 < v.len() => {
                if let (Some(l), Some((p, _))) = (last, out.last_mut()) {
                    flatten_quad(l, tp(&v[i]), tp(&v[i + 1]), scale, p);
                }
                i += 1;
            }
            CURVE4 if i + 2 < v.len() => {
                if let (Some(l), Some((p, _))) = (last, out.last_mut()) {
                    flatten_cubic(l, tp(&v[i]), tp(&v[i + 1]), tp(&v[i + 2]), scale, p);
                }
                i += 2;
            }
            STOP => break,
            c if c & END_POLY == END_POLY && c & CLOSE != 0 => {
                if let Some((_, closed)) = out.last_mut() {
                    *closed = true;
                }
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// The bounds (min x, min y, max x, max y) of what a command draws of the
/// path sequence `v` under `t`: the flattened outline for a fill, its
/// stroked outline for a stroke (`pathIterator::boundingRect` at accuracy
/// `accuracy`). The stroke's joins and caps are measured by their extreme
/// points (miter points within the limit, the pen's circle for round ones).
pub fn bounds(v: &[Vertex], t: &Affine, flags: u32, width: f64, miter: f64, accuracy: f64) -> Option<[f64; 4]> {
    let scale = t.determinant().abs().sqrt();
    let approx = accuracy * scale;
    let fill = flags & pf::FILL != 0;
    let iso = flags & pf::ISO_WIDTH != 0;
    let (lines, post, half) = if fill {
        (polylines(v, t, approx), Affine::default(), 0.0)
    } else if iso {
        (polylines(v, t, approx), Affine::default(), width * scale / 2.0)
    } else {
        (polylines(v, &Affine::default(), approx), *t, width / 2.0)
    };
    let mut b = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    let mut add = |(x, y): (f64, f64)| {
        let (x, y) = post.apply(x, y);
        b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
    };
    let join = flags & pf::JOIN_MASK;
    let cap = (flags & pf::CAP_MASK) >> pf::CAP_SHIFT;
    for (p, closed) in &lines {
        if fill || half == 0.0 {
            p.iter().for_each(|&q| add(q));
            continue;
        }
        let n = p.len();
        let dir = |a: (f64, f64), b: (f64, f64)| {
            let l = (b.0 - a.0).hypot(b.1 - a.1);
            if l > 0.0 {
                ((b.0 - a.0) / l, (b.1 - a.1) / l)
            } else {
                (0.0, 0.0)
            }
        };
        let round = |q: (f64, f64), add: &mut dyn FnMut((f64, f64))| {
            for k in 0..16 {
                let a = f64::from(k) * std::f64::consts::PI / 8.0;
                add((q.0 + half * a.cos(), q.1 + half * a.sin()));
            }
        };
        let segments = if *closed { n } else { n.saturating_sub(1) };
        for k in 0..segments {
            let (a, c) = (p[k], p[(k + 1) % n]);
            let (dx, dy) = dir(a, c);
            for q in [a, c] {
                add((q.0 - dy * half, q.1 + dx * half));
                add((q.0 + dy * half, q.1 - dx * half));
            }
        }
        // Joins at inner vertices (and at the start of a closed outline).
        let joins = if *closed { 0..n } else { 1..n.saturating_sub(1) };
        for k in joins {
            let (prev, here, next) = (p[(k + n - 1) % n], p[k], p[(k + 1) % n]);
            if join == 2 {
                round(here, &mut add);
                continue;
            }
            let (d1, d2) = (dir(prev, here), dir(here, next));
            if join == 3 {
                continue;
            }
            // AGG's `math_stroke::calc_miter` on each side: the miter
            // tip within the limit, else the miter clipped at the limit.
            let lim = miter * half;
            for side in [1.0, -1.0] {
                let (n1, n2) = ((-d1.1 * half * side, d1.0 * half * side), (-d2.1 * half * side, d2.0 * half * side));
                let (a1, a2) = ((here.0 + n1.0, here.1 + n1.1), (here.0 + n2.0, here.1 + n2.1));
                let den = d1.0 * d2.1 - d1.1 * d2.0;
                if den.abs() < 1e-12 {
                    continue;
                }
                let t = ((a2.0 - a1.0) * d2.1 - (a2.1 - a1.1) * d2.0) / den;
                let xi = (a1.0 + d1.0 * t, a1.1 + d1.1 * t);
                let di = (xi.0 - here.0).hypot(xi.1 - here.1);
                if di <= lim {
                    add(xi);
                } else {
                    let mid = ((a1.0 + a2.0) / 2.0, (a1.1 + a2.1) / 2.0);
                    let dbevel = (mid.0 - here.0).hypot(mid.1 - here.1);
                    let f = (lim - dbevel) / (di - dbevel);
                    add((a1.0 + (xi.0 - a1.0) * f, a1.1 + (xi.1 - a1.1) * f));
                    add((a2.0 + (xi.0 - a2.0) * f, a2.1 + (xi.1 - a2.1) * f));
                }
            }
        }
        if !*closed && n > 0 {
            for (end, toward) in [(p[0], if n > 1 { p[1] } else { p[0] }), (p[n - 1], if n > 1 { p[n - 2] } else { p[n - 1] })] {
                match cap {
                    2 => round(end, &mut add),
                    1 => {
                        let (dx, dy) = dir(toward, end);
                        let e = (end.0 + dx * half, end.1 + dy * half);
                        add((e.0 - dy * half, e.1 + dx * half));
                        add((e.0 + dy * half, e.1 - dx * half));
                    }
                    _ => {}
                }
            }
        }
    }
    (b[0] <= b[2] && b[1] <= b[3]).then_some(b)
}
