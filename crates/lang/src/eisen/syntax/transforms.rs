//! Transformation lists `{ x 1 ry 90 s 0.5 hue 10 … }`: each operator becomes
//! a 4×4 matrix (rotations, scales and reflections about the centre of the
//! unit cube, as in Structure Synth) or a colour change, and a list composes
//! them in order into one [`Transform`].

use super::Parser;
use crate::eisen::syntax::tokens::{number, Token};
use crate::eisen::syntax::{colour, Transform};
use crate::core::ParseError;
use glam::{DMat4, DVec3};

/// Transformation operator names and their long forms.
pub(super) fn operator(word: &str) -> Option<&'static str> {
    Some(match word {
        "x" => "x",
        "y" => "y",
        "z" => "z",
        "rx" => "rx",
        "ry" => "ry",
        "rz" => "rz",
        "s" => "s",
        "matrix" => "matrix",
        "fx" => "fx",
        "fy" => "fy",
        "fz" => "fz",
        "reflect" => "reflect",
        "h" | "hue" => "hue",
        "sat" => "sat",
        "b" | "brightness" | "v" => "brightness",
        "a" | "alpha" => "alpha",
        "c" | "color" => "color",
        "blend" => "blend",
        "md" | "maxdepth" => "maxdepth",
        "w" | "weight" => "weight",
        _ => return None,
    })
}

/// Translation by `v`, then `m` about the centre of the unit cube or an axis through it.
fn about(centre: DVec3, m: DMat4) -> DMat4 {
    DMat4::from_translation(centre) * m * DMat4::from_translation(-centre)
}

impl Parser {
    pub(super) fn transform_list(&mut self) -> Result<Transform, ParseError> {
        let open = self.next("`{`")?;
        let mut t = Transform::default();
        loop {
            let tok = self.next("a transformation or `}`")?;
            if tok.text == "}" {
                return Ok(t);
            }
            let lower = tok.text.to_ascii_lowercase();
            // `m` (matrix) and `saturation` (sat) are the JavaScript ports'
            // words, `colour` rulemesh's own, read only inside a list: Structure
            // Synth's tokenizer knows none of them (Tokenizer.cpp:21), so its
            // scripts may name rules `m` or `colour`.
            let extension = match lower.as_str() {
                "m" => Some("matrix"),
                "saturation" => Some("sat"),
                "colour" => Some("color"),
                _ => None,
            };
            let Some(op) = operator(&lower).or(extension) else {
                return Err(ParseError::single(
                    tok.span,
                    format!("unknown transformation `{}` (the list opened at {}:{} is not closed?)", tok.text, open.span.line, open.span.column),
                ));
            };
            let step = self.transformation(op, &tok)?;
            t.append(&step);
        }
    }

    /// A number inside a transformation list. Besides Structure Synth's
    /// number tokens, eisenscript.js's arithmetic is read (`x 2 * 3`,
    /// `s 1 / 3`, `y - 2`): a `*`, `/` or lone sign inside a list is an error
    /// in Structure Synth, so reading it changes none of its scripts.
    fn list_num(&mut self, what: &str) -> Result<f64, ParseError> {
        let sign = match self.peek().map(|t| t.text.as_str()) {
            Some("-") => -1.0,
            Some("+") => 1.0,
            _ => 0.0,
        };
        if sign != 0.0 {
            self.pos += 1;
        }
        let mut v = self.num(what)? * if sign == 0.0 { 1.0 } else { sign };
        loop {
            let op = match self.peek().map(|t| t.text.as_str()) {
                Some(o @ ("*" | "/")) => o == "*",
                _ => break,
            };
            if !self.tokens.get(self.pos + 1).is_some_and(|t| number(&t.text).is_some()) {
                break;
            }
            let at = self.next("an operator")?.span;
            let rhs = self.num(what)?;
            v = if op { v * rhs } else { v / rhs };
            if !v.is_finite() {
                return Err(ParseError::single(at, format!("{what}: the arithmetic gives no finite number")));
            }
        }
        Ok(v)
    }

    fn transformation(&mut self, op: &str, tok: &Token) -> Result<Transform, ParseError> {
        let half = 0.5;
        let mut t = Transform::default();
        match op {
            "x" | "y" | "z" => {
                let v = self.list_num(&format!("`{op}`"))?;
                let mut d = DVec3::ZERO;
                d[(op.as_bytes()[0] - b'x') as usize] = v;
                t.matrix = DMat4::from_translation(d);
            }
            "rx" | "ry" | "rz" => {
                let a = self.list_num(&format!("`{op}`"))?.to_radians();
                t.matrix = match op {
                    "rx" => about(DVec3::new(0.0, half, half), DMat4::from_rotation_x(a)),
                    "ry" => about(DVec3::new(half, 0.0, half), DMat4::from_rotation_y(a)),
                    _ => about(DVec3::new(half, half, 0.0), DMat4::from_rotation_z(a)),
                };
            }
            "s" => {
                let a = self.list_num("`s`")?;
                let s = if self.peek().is_some_and(|t| number(&t.text).is_some()) {
                    let b = self.list_num("`s` (second factor)")?;
                    let c = self.list_num("`s` (third factor)")?;
                    DVec3::new(a, b, c)
                } else {
                    DVec3::splat(a)
                };
                t.matrix = about(DVec3::splat(half), DMat4::from_scale(s));
            }
            "matrix" => {
                let mut v = [0.0; 9];
                for (k, slot) in v.iter_mut().enumerate() {
                    *slot = self.list_num(&format!("`m` (entry {} of 9)", k + 1))?;
                }
                // Arguments are row-major; glam stores columns.
                let m = glam::DMat3::from_cols_array(&v).transpose();
                t.matrix = about(DVec3::splat(half), DMat4::from_mat3(m));
            }
            "fx" | "fy" | "fz" => {
                let mut s = DVec3::ONE;
                s[(op.as_bytes()[1] - b'x') as usize] = -1.0;
                t.matrix = about(DVec3::splat(half), DMat4::from_scale(s));
            }
            "reflect" => {
                let n = DVec3::new(self.list_num("`reflect`")?, self.list_num("`reflect`")?, self.list_num("`reflect`")?);
                let n = n.normalize_or_zero();
                if n == DVec3::ZERO {
                    return Err(ParseError::single(tok.span, "`reflect` needs a non-zero normal"));
                }
                let m = glam::DMat3::IDENTITY - 2.0 * glam::DMat3::from_cols(n * n.x, n * n.y, n * n.z);
                t.matrix = DMat4::from_mat3(m);
            }
            "hue" => t.delta_h = self.list_num("`hue`")?,
            "sat" => t.scale_s = self.list_num("`sat`")?,
            "brightness" => t.scale_v = self.list_num("`brightness`")?,
            "alpha" => t.scale_a = self.list_num("`alpha`")?,
            "color" => {
                let c = self.next("a colour")?;
                t.absolute = true;
                if c.text.eq_ignore_ascii_case("random") {
                    t.delta_h = 1000.0;
                } else {
                    let rgb = colour::parse(&c.text).ok_or_else(|| ParseError::single(c.span, format!("`color`: `{}` is not a colour", c.text)))?;
                    let [h, s, v] = colour::rgb_to_hsv(rgb);
                    (t.delta_h, t.scale_s, t.scale_v, t.scale_a) = (h, s, v, 1.0);
                }
            }
            "blend" => {
                let c = self.next("a colour")?;
                let rgb = colour::parse(&c.text).ok_or_else(|| ParseError::single(c.span, format!("`blend`: `{}` is not a colour", c.text)))?;
                let strength = self.list_num("`blend` strength")?;
                t.blend = (strength != 0.0).then_some((colour::rgb_to_hsv(rgb), strength));
            }
            _ => {
                return Err(ParseError::single(tok.span, format!("`{}` is a rule modifier, not a transformation", tok.text)));
            }
        }
        Ok(t)
    }
}
