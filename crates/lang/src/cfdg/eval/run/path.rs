//! Paths as cfdg 3.4 evaluates them (John Horigan, Context Free 3.4,
//! `astreplacement.cpp`: `ASTrule::traversePath`, `ASTpathOp::traverse`,
//! `ASTcompiledPath::addPathOp` and `finish`, `ASTpathCommand::traverse`;
//! `ASTloop::traverse` and `ASTtransform::traverse` for loops and
//! transforms of path operations; `renderimpl.cpp` `processPrimShapeSiblings`
//! and `processPathCommand` for the bounds). A path shape is finished at
//! once: its body is walked with the shape's own random stream, the
//! operations build an AGG path ([`super::super::agg`]), every command
//! takes the operations since the last command (or the same ones again
//! when two commands follow each other), and operations that no command
//! covers are filled by the default command. Each operation and each
//! command is a step; a loop's iterations are steps.

use super::super::agg::{is_vertex, PathStorage, Vertex, CURVE3, CURVE4, LINE_TO, MOVE_TO};
use super::super::expr::scalar;
use super::super::frame::Bounds;
use super::super::state::{Affine, State};
use super::super::adjust::{apply_prepared, prepare};
use super::Renderer;
use crate::cfdg::syntax::{path_flags as pf, Element, PathCommand, PathOp, PathOpKind};
use crate::model::EvalError;

mod subpath;
pub(in crate::cfdg::eval) use subpath::SubpathTypes;

/// cfdg's default stroke width and miter limit (`ast.h`).
pub(crate) const DEFAULT_WIDTH: f64 = 0.1;
/// The miter limit (`DefaultMiterLimit`).
pub(crate) const MITER_LIMIT: f64 = 4.0;

/// Bytes accounted per path vertex a command keeps.
const VERTEX_BYTES: u64 = std::mem::size_of::<Vertex>() as u64;

/// What one command draws: the path sequence it covers, its paint and the
/// state (transform, colour) of the shape its adjustment made.
#[derive(Debug, Clone, PartialEq)]
pub struct PathDraw {
    /// The vertices, in the path's units, with AGG's commands.
    pub vertices: Vec<Vertex>,
    /// The command's flags (`FILL`, joins, caps, even-odd, iso).
    pub flags: u32,
    /// Stroke width.
    pub width: f64,
    /// Miter limit.
    pub miter: f64,
    /// Path units to design space.
    pub transform: Affine,
    /// RGBA in [0, 1].
    pub rgba: [f64; 4],
}

/// The path being built (`ASTcompiledPath` and the renderer's path fields).
struct Ctx {
    store: PathStorage,
    cmds: Vec<PathDraw>,
    index: usize,
    next_index: usize,
    last: (f64, f64),
    want_move_to: bool,
    want_command: bool,
    closed: bool,
    stop: bool,
    /// The path shapes being walked, outermost first (subpaths nest).
    walking: Vec<usize>,
}

/// The kinds of element a body holds (`ASTreplacement::repElemListEnum`;
/// a subpath counts as the kind of the path it draws, `subpath.rs`).
const REP_REPLACEMENT: u8 = 1;
const REP_OP: u8 = 4;
const REP_COMMAND: u8 = 8;

fn invert(t: &Affine) -> Affine {
    let d = 1.0 / t.determinant();
    let (sx, sy, shy, shx) = (t.sy * d, t.sx * d, -t.shy * d, -t.shx * d);
    Affine { sx, shy, shx, sy, tx: -t.tx * sx - t.ty * shx, ty: -t.tx * shy - t.ty * sy }
}

fn error(op_line: crate::Span, message: &str) -> EvalError {
    EvalError::BadParam { name: "path".into(), message: format!("{}:{}: {message}", op_line.line, op_line.column) }
}

impl Ctx {
    fn new() -> Ctx {
        Ctx { store: PathStorage::default(), cmds: Vec::new(), index: 0, next_index: 0, last: (0.0, 0.0), want_move_to: true, want_command: true, closed: false, stop: false, walking: Vec::new() }
    }

    /// `ASTcompiledPath::finish`; returns whether the default command is needed.
    fn finish(&mut self, set_attr: bool) -> bool {
        if !self.closed {
            self.store.end_poly(0);
            self.closed = true;
        }
        if !self.stop {
            self.store.start_new_path();
            self.stop = true;
        }
        self.want_move_to = true;
        self.next_index = self.store.v.len();
        let terminal = set_attr && self.want_command;
        if terminal {
            self.want_command = false;
        }
        terminal
    }

    /// `ASTcompiledPath::addPathOp`.
    fn add_op(&mut self, op: &PathOp, n: usize, mut d: [f64; 6], t: &Affine, tr: bool) -> Result<(), EvalError> {
        let arc = matches!(op.kind, PathOpKind::ArcTo | PathOpKind::ArcRel);
        let (mut rx, mut ry, mut angle) = (0.0, 0.0, 0.0);
        let mut sweep = op.flags & pf::ARC_CW == 0;
        let large = op.flags & pf::ARC_LARGE != 0;
        if arc {
            if n == 5 {
                (rx, ry, angle) = (d[2], d[3], d[4] * 0.017_453_292_519_9);
            } else {
                (rx, ry) = (d[2], d[2]);
            }
            if rx < 0.0 || ry < 0.0 {
                (rx, ry, sweep) = (rx.abs(), ry.abs(), !sweep);
            }
        } else if tr {
            for k in 0..3 {
                (d[2 * k], d[2 * k + 1]) = t.apply(d[2 * k], d[2 * k + 1]);
            }
        }
        self.index = self.next_index;
        self.closed = false;
        self.stop = false;
        self.want_command = true;
        let s = &mut self.store;
        if op.kind == PathOpKind::ClosePoly {
            let n = s.v.len();
            if n > 1 && (LINE_TO..0x0F).contains(&s.last_command()) {
                let start = s.v[..n - 1].iter().rev().take_while(|v| is_vertex(v.cmd)).find(|v| v.cmd == MOVE_TO).map(|v| (v.x, v.y));
                let Some(p) = start else {
                    return Err(error(op.span, "CLOSEPOLY: unable to find a MOVETO/MOVEREL for start of path"));
                };
                self.last = p;
                if op.flags & pf::ALIGN != 0 {
                    (s.v[n - 1].x, s.v[n - 1].y) = p;
                }
            } else if op.flags & pf::ALIGN != 0 {
                return Err(error(op.span, "CLOSEPOLY: nothing to align to"));
            }
            s.close_polygon();
            self.closed = true;
            self.want_move_to = true;
            return Ok(());
        }
        if self.want_move_to && op.kind > PathOpKind::MoveRel {
            self.want_move_to = false;
            s.move_to(self.last.0, self.last.1);
        }
        let rel = matches!(op.kind, PathOpKind::MoveRel | PathOpKind::LineRel | PathOpKind::ArcRel | PathOpKind::CurveRel);
        if rel {
            let [a, b, ..] = &mut d;
            s.rel_to_abs(a, b);
        }
        match op.kind {
            PathOpKind::MoveTo | PathOpKind::MoveRel => {
                s.move_to(d[0], d[1]);
                self.want_move_to = false;
            }
            PathOpKind::LineTo | PathOpKind::LineRel => s.line_to(d[0], d[1]),
            PathOpKind::ArcTo | PathOpKind::ArcRel => {
                let (lx, ly, lc) = s.last_vertex();
                if is_vertex(lc) && !(tr && t.determinant() < 1e-10) {
                    if tr {
                        let start = s.v.len() - 1;
                        s.transform_from(start, &invert(t));
                        s.arc_to(rx, ry, angle, large, sweep, d[0], d[1]);
                        (s.v[start].x, s.v[start].y) = (lx, ly);
                        s.transform_from(start + 1, t);
                    } else {
                        s.arc_to(rx, ry, angle, large, sweep, d[0], d[1]);
                    }
                }
            }
            PathOpKind::CurveTo | PathOpKind::CurveRel => {
                if rel {
                    let [_, _, c, e, f, g] = &mut d;
                    s.rel_to_abs(c, e);
                    s.rel_to_abs(f, g);
                }
                let continuous = op.flags & pf::CONTINUOUS != 0;
                if continuous && !matches!(s.last_command(), CURVE3 | CURVE4) {
                    return Err(error(op.span, "smooth curve operations must be preceded by another curve operation"));
                }
                match n {
                    2 => s.curve3_smooth(d[0], d[1]),
                    4 if continuous => s.curve4_smooth((d[2], d[3]), d[0], d[1]),
                    4 => s.curve3(d[2], d[3], d[0], d[1]),
                    6 => s.curve4((d[2], d[3]), (d[4], d[5]), d[0], d[1]),
                    _ => {}
                }
            }
            PathOpKind::ClosePoly => {}
        }
        let (x, y, _) = s.last_vertex();
        self.last = (x, y);
        Ok(())
    }
}

impl Renderer<'_> {
    /// Finishes path shape `shape` in `state` (`traversePath` in bounds mode).
    pub(super) fn path_shape(&mut self, shape: usize, state: State, params: Vec<f64>) -> Result<(), EvalError> {
        let Some(&(_, body)) = self.rules.by_shape[shape].first() else { return Ok(()) };
        // traversePath takes the shape's stream and leaves it as the
        // renderer's current one: the rule that made the path goes on with it.
        self.current = state.seed;
        let depth = self.scope.vars.len();
        self.bind_params(shape, &params);
        let saved_params = std::mem::replace(&mut self.params, params);
        let mut ctx = Ctx::new();
        ctx.walking.push(shape);
        let walked = self.path_body(body, &state, false, &mut ctx);
        self.scope.vars.truncate(depth);
        self.params = saved_params;
        self.budget.release_memory(VERTEX_BYTES.saturating_mul(ctx.store.v.len() as u64));
        walked?;
        if ctx.finish(true) {
            let vertices = ctx.store.v[ctx.index.min(ctx.store.v.len())..].to_vec();
            self.budget.reserve_memory(VERTEX_BYTES.saturating_mul(vertices.len() as u64))?;
            ctx.cmds.push(PathDraw { vertices, flags: pf::FILL, width: DEFAULT_WIDTH, miter: MITER_LIMIT, transform: state.transform, rgba: state.color.rgba() });
        }
        // processPrimShapeSiblings: the scale guessed before any bounds.
        // A tiled design's scale never follows its bounds, so cfdg keeps the
        // guess made at its first finished shape (`mScale`).
        let scale = match self.tile_canvas {
            Some(_) => self.guess_scale(&state),
            None if self.scale_area > 0.0 => self.scale_area.sqrt(),
            None => f64::from(self.opts.width + self.opts.height) / state.area().sqrt(),
        };
        let mut b = Bounds::default();
        for c in &ctx.cmds {
            if let Some([x0, y0, x1, y1]) = super::super::agg::bounds(&c.vertices, &c.transform, c.flags, c.width, c.miter, scale * 0.1) {
                b.merge(&Bounds { min_x: x0, min_y: y0, max_x: x1, max_y: y1 });
            }
        }
        if !b.valid() {
            return Ok(());
        }
        let area = ((b.max_x - b.min_x) * (b.max_y - b.min_y)).abs();
        let index = self.paths.len();
        self.paths.push(ctx.cmds);
        self.finish_shape(3, &state.transform, state.tz, state.color.rgba(), b, area, index)
    }

    fn path_body(&mut self, body: &[Element], parent: &State, tr: bool, ctx: &mut Ctx) -> Result<(), EvalError> {
        let depth = self.scope.vars.len();
        for e in body {
            self.path_element(e, parent, tr, ctx)?;
        }
        self.scope.vars.truncate(depth);
        Ok(())
    }

    fn path_element(&mut self, e: &Element, parent: &State, tr: bool, ctx: &mut Ctx) -> Result<(), EvalError> {
        match e {
            Element::PathOp(op) => {
                self.budget.charge_step()?;
                let mut v = Vec::with_capacity(6);
                for a in &op.args {
                    super::super::expr::eval(a, &self.scope, &mut self.current, &mut v)?;
                }
                // Vector arguments count as their numbers (checkArguments).
                if v.len() != op.args.len() {
                    crate::cfdg::syntax::path_op_arity(op.kind, op.flags, v.len()).map_err(|m| error(op.span, &m))?;
                }
                let before = ctx.store.v.len();
                let mut d = [0.0; 6];
                for (slot, x) in d.iter_mut().zip(&v) {
                    if !x.is_finite() {
                        return Err(EvalError::NonFinite { span: op.span, what: "a path operation's argument".into(), value: format!("{x}") });
                    }
                    *slot = *x;
                }
                ctx.add_op(op, v.len(), d, &parent.transform, tr)?;
                self.budget.reserve_memory(VERTEX_BYTES.saturating_mul(ctx.store.v.len().saturating_sub(before) as u64))?;
                if ctx.store.v.iter().rev().take(13).any(|v| !(v.x.is_finite() && v.y.is_finite())) {
                    return Err(EvalError::NonFinite { span: op.span, what: "a path point".into(), value: "undefined or infinite".into() });
                }
                Ok(())
            }
            Element::PathCommand(c) => self.path_command(c, parent, ctx),
            Element::Loop(l) => {
                let ops_only = (self.rep_type(&l.body) | self.rep_type(&l.finally)) == REP_OP;
                let mut child = *parent;
                if ops_only && !tr {
                    child.transform = Affine::default();
                }
                let (terms, var, start, end, step) = self.loop_setup(l)?;
                let mut index = start;
                self.scope.vars.push((var, vec![index]));
                let slot = self.scope.vars.len() - 1;
                while !((step > 0.0 && index >= end) || (step < 0.0 && index <= end)) {
                    self.budget.charge_step()?;
                    self.scope.vars[slot].1[0] = index;
                    self.path_body(&l.body, &child, tr || ops_only, ctx)?;
                    apply_prepared(&terms, &mut child, &self.scope, &mut self.current)?;
                    index += step;
                }
                self.scope.vars[slot].1[0] = index;
                self.path_body(&l.finally, &child, tr || ops_only, ctx)?;
                self.scope.vars.truncate(slot);
                Ok(())
            }
            Element::Transform { symmetry, span, .. } if !symmetry.is_empty() => {
                Err(EvalError::BadParam { name: "transform".into(), message: format!("{}:{}: a list of transforms or a symmetry group in a path is not supported yet (docs/cfdg.md)", span.line, span.column) })
            }
            Element::Transform { clone, adjusts, body, .. } => {
                let ops_only = self.rep_type(body) == REP_OP;
                let mut base = *parent;
                if ops_only && !tr {
                    base.transform = Affine::default();
                }
                let clone_seed = self.current;
                for adj in adjusts {
                    let mut child = base;
                    apply_prepared(&prepare(adj), &mut child, &self.scope, &mut self.current)?;
                    self.current.next_u64();
                    let depth = self.scope.vars.len();
                    for e in body {
                        if *clone {
                            self.current = clone_seed;
                        }
                        self.path_element(e, &child, ops_only || tr, ctx)?;
                    }
                    self.scope.vars.truncate(depth);
                }
                Ok(())
            }
            Element::If { cond, then, otherwise, .. } => {
                let c = scalar(cond, &self.scope, &mut self.current)?;
                self.path_body(if c != 0.0 { then } else { otherwise }, parent, tr, ctx)
            }
            Element::Switch { selector, cases, otherwise, .. } => {
                let v = scalar(selector, &self.scope, &mut self.current)?.floor();
                let body = cases.iter().find(|(ranges, _)| ranges.iter().any(|&(lo, hi)| v >= lo as f64 && v <= hi as f64)).map(|(_, b)| b).unwrap_or(otherwise);
                self.path_body(body, parent, tr, ctx)
            }
            Element::Define(_) => self.element(e, parent),
            Element::Replace(r) => self.subpath(r, parent, tr, ctx),
        }
    }

    /// `ASTpathCommand::traverse`: the command's shape, then what it draws.
    fn path_command(&mut self, c: &PathCommand, parent: &State, ctx: &mut Ctx) -> Result<(), EvalError> {
        self.budget.charge_step()?;
        let prepared = self.seeded_terms(&c.adjust, if c.fill { "FILL" } else { "STROKE" }, None);
        let (terms, seed) = (&prepared.0, prepared.1);
        let mut child = *parent;
        self.current.xor(seed);
        self.current.next_u64();
        apply_prepared(&terms, &mut child, &self.scope, &mut self.current)?;
        let width = match &c.width {
            Some(w) => scalar(w, &self.scope, &mut self.current)?,
            None => DEFAULT_WIDTH,
        };
        if !width.is_finite() {
            return Err(EvalError::NonFinite { span: c.span, what: "a stroke width".into(), value: format!("{width}") });
        }
        if ctx.store.v.is_empty() {
            return Err(error(c.span, "path commands must be preceded by at least one path operation"));
        }
        ctx.want_command = false;
        ctx.finish(false);
        let vertices = ctx.store.v[ctx.index.min(ctx.store.v.len())..].to_vec();
        self.budget.reserve_memory(VERTEX_BYTES.saturating_mul(vertices.len() as u64))?;
        ctx.cmds.push(PathDraw { vertices, flags: c.flags, width, miter: MITER_LIMIT, transform: child.transform, rgba: child.color.rgba() });
        Ok(())
    }
}
