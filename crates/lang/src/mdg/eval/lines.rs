//! Swept lines: the per-namespace [`Pen`] and its operations (`MOVETO`,
//! `LINETO`, `SLINETO`, `BLENDTO`, `NEWLINE`, `RESET`), the `BLENDTO` curve,
//! line profiles made by profile rules, and what a line point costs. A pen
//! carries state from one call to the next, so its operations live together.

use super::adjust::Ctx;
use super::machine::Machine;
use crate::core::frame::Frame;
use crate::geom::sweep;
use crate::ir::{GroupId, LineOp};
use crate::model::scene::{LinePoint, Polyline, Scene, LINE_POINT_BYTES};
use crate::model::EvalError;
use glam::{DQuat, DVec3};

/// Where the pen of swept lines is (one pen: namespaces come later).
#[derive(Debug, Clone, Copy)]
pub(super) struct Pen {
    /// Where the next segment starts when no line is open. The pen starts
    /// down at the root frame, so a first `LINETO` draws from the origin.
    pub(super) start: Frame,
    /// After `NEWLINE`: the next `LINETO` only puts the pen down.
    pub(super) lifted: bool,
    /// The last `MOVETO`, for `RESET`.
    pub(super) moveto: Frame,
    /// Index in `scene.lines` of the line being drawn.
    pub(super) open: Option<usize>,
}

/// Turns `point`'s frame orthogonal to the segment from the line's last point
/// (SLINETO, with the shortest-arc rotation Andersson 2015 eq 3.29 means; as
/// printed, that equation doubles the angle). A line's first point is turned
/// too. The sweep turns every moving line's rings onto its path anyway
/// (`geom::mitre`), so what this still decides is the frame a continuation
/// starts from and the first ring's roll.
fn orient_along_segment(line: &mut Polyline, point: &mut LinePoint) {
    let Some(prev) = line.points.last_mut() else { return };
    let Some(dir) = (point.frame.translation - prev.frame.translation).try_normalize() else { return };
    let turn = |f: &mut Frame| {
        let axis = (f.rotation * DVec3::Z).normalize();
        f.rotation = (DQuat::from_rotation_arc(axis, dir) * f.rotation).normalize();
    };
    turn(&mut point.frame);
    if line.points.len() == 1 {
        if let Some(first) = line.points.first_mut() {
            turn(&mut first.frame);
        }
    }
}

/// Sub-segments of one `BLENDTO`.
const BLEND_STEPS: u32 = 8;

/// The tangent length factor λ of eq 4.15 (the thesis's Fig 4.2c value).
const BLEND_LAMBDA: f64 = 0.75;

/// The frame at `w` ∈ [0, 1] of a `BLENDTO` from `a` to `b` (Andersson 2015
/// eqs 4.15–4.21, with eq 4.19 read as ending at u₂, not v₂): positions follow a
/// curve leaving `a` along its local +Z and arriving at `b` along its local
/// +Z, with tangent length D = λ·|u₂ − u₁|; the rotation is a shortest-path
/// slerp and the scale blends with smoothstep.
fn blend(a: &Frame, b: &Frame, w: f64) -> Frame {
    let s = w * w * (3.0 - 2.0 * w);
    let d = (b.translation - a.translation).length() * BLEND_LAMBDA;
    let v1 = a.translation + (a.rotation * DVec3::Z) * d;
    let v2 = b.translation - (b.rotation * DVec3::Z) * d;
    let p = a.translation.lerp(v1, s).lerp(v2.lerp(b.translation, s), w);
    let rb = if a.rotation.dot(b.rotation) < 0.0 { -b.rotation } else { b.rotation };
    Frame {
        translation: p,
        rotation: a.rotation.slerp(rb, w).normalize(),
        scale: a.scale + (b.scale - a.scale) * s,
        parity: if w < 1.0 { a.parity } else { b.parity },
    }
}

/// Sides of a line's cross-section: its profile's point count, or the default tube's.
pub(super) fn line_sides(scene: &Scene, profile: Option<u32>, detail: u32) -> u64 {
    profile
        .and_then(|p| scene.profiles.get(p as usize))
        .map_or_else(|| sweep::profile_sides(detail), |p| p.len() as u64)
}

impl<'p, 'b> Machine<'p, 'b> {
    /// Moves the pen of the call's namespace (Andersson 2015 §4.3, §4.1.4): every
    /// operation is a terminal for continuation.
    pub(super) fn draw_line(&mut self, op: LineOp, profile: Option<GroupId>, ctx: &Ctx) -> Result<(), EvalError> {
        let frame = ctx.frame;
        let ns = (ctx.ns as usize).min(self.pens.len().saturating_sub(1));
        let Some(mut pen) = self.pens.get(ns).copied() else { return Ok(()) };
        let result = self.move_pen(&mut pen, op, profile, ctx);
        if let Some(p) = self.pens.get_mut(ns) {
            *p = pen;
        }
        result?;
        if op != LineOp::Reset {
            self.set_terminal(ctx.ns, frame);
        }
        Ok(())
    }

    /// One pen operation on `pen` (the pen of the call's namespace).
    fn move_pen(&mut self, pen: &mut Pen, op: LineOp, profile: Option<GroupId>, ctx: &Ctx) -> Result<(), EvalError> {
        let frame = ctx.frame;
        match op {
            LineOp::MoveTo => {
                *pen = Pen { start: frame, lifted: false, moveto: frame, open: None };
            }
            LineOp::NewLine => {
                pen.open = None;
                pen.lifted = true;
            }
            LineOp::Reset => {
                pen.open = None;
                pen.lifted = false;
                pen.start = pen.moveto;
                self.set_terminal(ctx.ns, pen.moveto);
                return Ok(());
            }
            LineOp::LineTo | LineOp::SLineTo | LineOp::BlendTo if pen.lifted => {
                pen.lifted = false;
                pen.start = frame;
            }
            LineOp::LineTo | LineOp::SLineTo | LineOp::BlendTo => {
                let mut colour = ctx.colour;
                colour[3] += 1.0;
                let colour = colour.map(|c| c.clamp(0.0, 1.0) as f32);
                let open = match pen.open {
                    Some(i) => i,
                    None => {
                        let profile = match profile.or(self.ev.program.directives.linerule) {
                            Some(g) => self.profile(g)?,
                            None => None,
                        };
                        let start = LinePoint { frame: pen.start, colour };
                        self.charge_line_point(profile)?;
                        self.scene.lines.push(Polyline { points: vec![start], profile });
                        self.tag(|r| &mut r.line_bone, ctx.bone)?;
                        let i = self.scene.lines.len() - 1;
                        pen.open = Some(i);
                        i
                    }
                };
                let line_profile = self.scene.lines.get(open).and_then(|l| l.profile);
                let mut point = LinePoint { frame, colour };
                if op == LineOp::BlendTo {
                    let from = self.scene.lines.get(open).and_then(|l| l.points.last()).map_or(frame, |p| p.frame);
                    for k in 1..BLEND_STEPS {
                        self.charge_line_point(line_profile)?;
                        let w = k as f64 / BLEND_STEPS as f64;
                        let blended = LinePoint { frame: blend(&from, &frame, w), colour };
                        if let Some(line) = self.scene.lines.get_mut(open) {
                            line.points.push(blended);
                        }
                    }
                }
                self.charge_line_point(line_profile)?;
                let Some(line) = self.scene.lines.get_mut(open) else { return Ok(()) };
                if op == LineOp::SLineTo {
                    orient_along_segment(line, &mut point);
                }
                line.points.push(point);
            }
        }
        Ok(())
    }

    /// Charges one more line point: its storage, and the mesh and output it will become.
    fn charge_line_point(&mut self, profile: Option<u32>) -> Result<(), EvalError> {
        let (v, t) = sweep::per_point_bound(line_sides(&self.scene, profile, self.ev.detail));
        self.budget.charge_triangles(t)?;
        self.budget.reserve_memory(LINE_POINT_BYTES.saturating_add(self.ev.cost.bytes(v, t)))?;
        Ok(())
    }

    /// The scene profile made by profile rule `g` (its `VERTEX` points), if it made one.
    pub(super) fn profile(&mut self, g: GroupId) -> Result<Option<u32>, EvalError> {
        if let Some(p) = self.profile_index.get(&g) {
            return Ok(*p);
        }
        let points = self.capture_group(g, None)?.vertices.clone();
        let index = if points.len() >= 3 {
            self.scene.profiles.push(points);
            Some((self.scene.profiles.len() - 1) as u32)
        } else {
            None
        };
        self.profile_index.insert(g, index);
        Ok(index)
    }
}
