//! Adjustment lists: the `{ x 1 ry 90 s 0.5 R 0.1 }` of a call and the step
//! `[ … ]` of an iterator, parsed into transforms, colour changes and
//! reflections. Angles are converted to radians here, under the file's
//! `angle` mode; colour and vertex-weight adjustments go by the names the
//! `color` and `weight` directives give them.

use super::expressions::{num, Ctx, What, E};
use super::{err, PResult, Parser};
use crate::expr::Expr;
use crate::ir::{Adjust, AdjustOp, Axis};
use crate::mdg::syntax::lexer::Tok;
use crate::core::Diagnostic;
use std::f64::consts::FRAC_PI_2;

/// Adjustment keywords (case-sensitive); a bare name equal to one of these is never an argument.
const ADJUST_WORDS: &[&str] = &[
    "x", "y", "z", "r", "rotate", "rx", "pitch", "ry", "yaw", "rz", "roll", "up", "down", "left", "right",
    "rolleft", "rollleft", "rollright", "s", "f", "fx", "fy", "fz", "R", "G", "B", "A", "u", "v", "w", "q",
    "fps",
];

impl<'a> Parser<'a> {
    /// Whether `w` is an adjustment keyword (under the current colour and weight names).
    pub(super) fn is_adjust_word(&self, w: &str) -> bool {
        ADJUST_WORDS.contains(&w) || self.colour_names.contains(&w) || self.weight_names.contains(&w)
    }

    /// Adjustments up to and including the closing `close` (`}` or `]`).
    pub(super) fn adjustments(&mut self, close: char) -> PResult<Vec<Adjust>> {
        let mut out = Vec::new();
        loop {
            let t = self.bump();
            let word = match t.tok {
                Tok::Punct(c) if c == close => return Ok(out),
                Tok::Ident(w) => w,
                Tok::Eof => return Err(err(t.span, format!("expected `{close}` to close the adjustments, found end of input"))),
                other => return Err(err(t.span, format!("expected an adjustment or `{close}`, found {other}"))),
            };
            let span = t.span;
            // Colour and weight adjustments go by their (renamable) names first.
            if let Some(channel) = self.colour_names.iter().position(|n| *n == word) {
                let d = self.arg(Ctx::Plain, What::After(word))?;
                out.push(Adjust { op: AdjustOp::Colour { channel: channel as u8, delta: d.expr }, span });
                continue;
            }
            if self.weight_names.contains(&word) {
                self.arg(Ctx::Plain, What::After(word))?;
                self.warnings.push(Diagnostic::warning(span, format!("vertex weight `{word}` ignored: weights only feed the thesis's shaders")));
                continue;
            }
            let mut push = |op: AdjustOp| out.push(Adjust { op, span });
            let rot = |axis, angle: E| AdjustOp::Rotate { axis, angle: angle.expr };
            match word {
                "x" => {
                    let a = self.arg(Ctx::Plain, What::After("x"))?;
                    let (mut b, mut c) = (num(0.0), num(0.0));
                    if let Some(v) = self.opt_arg(Ctx::Plain, What::After("x"))? {
                        b = v;
                        c = self.opt_arg(Ctx::Plain, What::After("x"))?.unwrap_or_else(|| num(0.0));
                    }
                    push(AdjustOp::Translate([a.expr, b.expr, c.expr]));
                }
                "y" => {
                    let a = self.arg(Ctx::Plain, What::After("y"))?;
                    push(AdjustOp::Translate([Expr::Num(0.0), a.expr, Expr::Num(0.0)]));
                }
                "z" => {
                    let a = self.arg(Ctx::Plain, What::After("z"))?;
                    push(AdjustOp::Translate([Expr::Num(0.0), Expr::Num(0.0), a.expr]));
                }
                "r" | "rotate" => {
                    push(rot(Axis::X, self.angle_arg(word)?));
                    if self.starts_arg() {
                        push(rot(Axis::Y, self.angle_arg(word)?));
                        if self.starts_arg() {
                            push(rot(Axis::Z, self.angle_arg(word)?));
                        }
                    }
                }
                "rx" | "pitch" => push(rot(Axis::X, self.angle_arg(word)?)),
                "ry" | "yaw" => push(rot(Axis::Y, self.angle_arg(word)?)),
                "rz" | "roll" => push(rot(Axis::Z, self.angle_arg(word)?)),
                "up" | "down" | "left" | "right" | "rolleft" | "rollleft" | "rollright" => {
                    let (axis, negative) = match word {
                        "up" => (Axis::X, false),
                        "down" => (Axis::X, true),
                        "left" => (Axis::Y, true),
                        "right" => (Axis::Y, false),
                        "rollright" => (Axis::Z, false),
                        _ => (Axis::Z, true),
                    };
                    let angle = if self.starts_arg() {
                        let a = self.angle_arg(word)?;
                        if negative {
                            Expr::Neg(Box::new(a.expr))
                        } else {
                            a.expr
                        }
                    } else {
                        Expr::Num(if negative { -FRAC_PI_2 } else { FRAC_PI_2 })
                    };
                    push(AdjustOp::Rotate { axis, angle });
                }
                "s" => {
                    let k = self.arg(Ctx::Plain, What::After("s"))?;
                    if self.starts_arg() {
                        return Err(err(self.peek().span, "not supported yet: non-uniform scale `s x y z`"));
                    }
                    push(AdjustOp::Scale(k.expr));
                }
                "f" => {
                    let a = self.arg(Ctx::Plain, What::After("f"))?;
                    let b = self.arg(Ctx::Plain, What::After("f"))?;
                    let c = self.arg(Ctx::Plain, What::After("f"))?;
                    push(AdjustOp::Reflect([a.expr, b.expr, c.expr]));
                }
                "fx" | "fy" | "fz" => {
                    let n = match word {
                        "fx" => [1.0, 0.0, 0.0],
                        "fy" => [0.0, 1.0, 0.0],
                        _ => [0.0, 0.0, 1.0],
                    };
                    push(AdjustOp::Reflect(n.map(Expr::Num)));
                }
                "R" | "G" | "B" | "A" | "u" | "v" | "w" | "q" => {
                    return Err(err(span, format!("unknown adjustment `{word}`: renamed by a `color` or `weight` directive")));
                }
                "fps" => {
                    self.arg(Ctx::Plain, What::After(word))?;
                    self.warnings.push(Diagnostic::warning(span, format!("adjustment `{word}` ignored: not supported yet")));
                }
                other => return Err(err(span, format!("unknown adjustment `{other}`"))),
            }
        }
    }
}
