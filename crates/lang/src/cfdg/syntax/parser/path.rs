//! Paths: `path NAME { … }` and the path operations and commands inside it,
//! read as cfdg 3.4 reads them (John Horigan, Context Free 3.4: `cfdg.ypp`
//! for the productions, `astreplacement.cpp` `ASTpathOp::makePositional`
//! and `checkArguments` for the 2.x keyword arguments and the argument
//! counts, `ASTpathCommand::compile` and `GetFlagsAndStroke` for a
//! command's width and flags, `astexpression.cpp` `ASTmodTerm` for the
//! `p`/`param` flag words and `builder.cpp` `FlagNames` for the `CF::`
//! flags). An operation is left with positional arguments (end point, then
//! the arc's radius or radii and angle, or the curve's control points), so
//! the evaluator sees one form whichever syntax wrote it.

use super::super::path_flags as pf;
use super::super::{Element, Expr, PathCommand, PathOp, PathOpKind, Rule};
use super::Parser;
use super::Tok;
use crate::{ParseError, Span};

/// Whether `w` names a path operation or command.
pub(crate) fn is_path_op(w: &str) -> bool {
    op_kind(w).is_some() || w == "STROKE" || w == "FILL"
}

fn op_kind(w: &str) -> Option<PathOpKind> {
    Some(match w {
        "MOVETO" => PathOpKind::MoveTo,
        "MOVEREL" => PathOpKind::MoveRel,
        "LINETO" => PathOpKind::LineTo,
        "LINEREL" => PathOpKind::LineRel,
        "ARCTO" => PathOpKind::ArcTo,
        "ARCREL" => PathOpKind::ArcRel,
        "CURVETO" => PathOpKind::CurveTo,
        "CURVEREL" => PathOpKind::CurveRel,
        "CLOSEPOLY" => PathOpKind::ClosePoly,
        _ => return None,
    })
}

/// Words a path command's adjustment reads besides the adjustment terms.
pub(super) fn is_path_term(w: &str) -> bool {
    matches!(w, "p" | "param" | "width")
}

/// The flags a `p`/`param` word sets (`ASTmodTerm`'s `paramStrings`).
fn param_flag(w: &str) -> Option<u32> {
    Some(match w {
        "evenodd" => pf::EVEN_ODD,
        "iso" => pf::ISO_WIDTH,
        "miterjoin" => pf::JOIN_PRESENT,
        "roundjoin" => 2 | pf::JOIN_PRESENT,
        "beveljoin" => 3 | pf::JOIN_PRESENT,
        "buttcap" => pf::CAP_PRESENT,
        "squarecap" => (1 << pf::CAP_SHIFT) | pf::CAP_PRESENT,
        "roundcap" => (2 << pf::CAP_SHIFT) | pf::CAP_PRESENT,
        "large" => pf::ARC_LARGE,
        "cw" => pf::ARC_CW,
        "align" => pf::ALIGN,
        _ => return None,
    })
}

/// The value of a `CF::` flag name (`Builder::FlagNames`).
fn cf_flag(w: &str) -> Option<u32> {
    Some(match w {
        "CF::None" => 0,
        "CF::MiterJoin" => pf::JOIN_PRESENT,
        "CF::RoundJoin" => 2 | pf::JOIN_PRESENT,
        "CF::BevelJoin" => 3 | pf::JOIN_PRESENT,
        "CF::ButtCap" => pf::CAP_PRESENT,
        "CF::RoundCap" => (2 << pf::CAP_SHIFT) | pf::CAP_PRESENT,
        "CF::SquareCap" => (1 << pf::CAP_SHIFT) | pf::CAP_PRESENT,
        "CF::ArcCW" => pf::ARC_CW,
        "CF::ArcLarge" => pf::ARC_LARGE,
        "CF::Continuous" => pf::CONTINUOUS,
        "CF::Align" => pf::ALIGN,
        "CF::EvenOdd" => pf::EVEN_ODD,
        "CF::IsoWidth" => pf::ISO_WIDTH,
        _ => return None,
    })
}

/// A constant flag expression: `CF::` names joined by `+`; `None` when
/// the expression is not a flag expression at all (it is numeric).
fn flag_value(e: &Expr) -> Option<u32> {
    match e {
        Expr::Var(v, _) => cf_flag(v),
        Expr::Paren(a) => flag_value(a),
        Expr::Binary('+', a, b) => Some(flag_value(a)? | flag_value(b)?),
        _ => None,
    }
}

/// Checks that a path operation has `n` numbers and these flags
/// (`ASTpathOp::checkArguments`); the message says what it takes.
pub(crate) fn path_op_arity(kind: PathOpKind, flags: u32, n: usize) -> Result<(), String> {
    let ok = match kind {
        PathOpKind::MoveTo | PathOpKind::MoveRel | PathOpKind::LineTo | PathOpKind::LineRel => flags == 0 && n == 2,
        PathOpKind::ArcTo | PathOpKind::ArcRel => flags & !(pf::ARC_CW | pf::ARC_LARGE) == 0 && (n == 3 || n == 5),
        PathOpKind::CurveTo | PathOpKind::CurveRel if flags & pf::CONTINUOUS != 0 => flags == pf::CONTINUOUS && (n == 2 || n == 4),
        PathOpKind::CurveTo | PathOpKind::CurveRel => flags == 0 && (n == 4 || n == 6),
        PathOpKind::ClosePoly => flags & !pf::ALIGN == 0 && n == 0,
    };
    if ok {
        return Ok(());
    }
    let want = match kind {
        PathOpKind::MoveTo | PathOpKind::MoveRel | PathOpKind::LineTo | PathOpKind::LineRel => "two arguments and no flags",
        PathOpKind::ArcTo | PathOpKind::ArcRel => "three or five arguments (flags CF::ArcCW, CF::ArcLarge)",
        PathOpKind::CurveTo | PathOpKind::CurveRel => "four or six arguments (two or four with CF::Continuous)",
        PathOpKind::ClosePoly => "no arguments (flag CF::Align)",
    };
    Err(format!("this path operation takes {want}, given {n} arguments"))
}

/// Whether `e` may evaluate to more than one number (a variable, an
/// index, a call or a list, or arithmetic on one).
fn may_be_vector(e: &Expr) -> bool {
    match e {
        Expr::Num(..) => false,
        Expr::Unary(_, a) | Expr::Paren(a) => may_be_vector(a),
        Expr::Binary(_, a, b) => may_be_vector(a) || may_be_vector(b),
        _ => true,
    }
}

/// What the parser keeps while it reads a path.
#[derive(Debug, Default)]
pub(in crate::cfdg::syntax) struct PathState {
    /// Inside a `path` body: operations and commands are allowed.
    pub(super) in_path: bool,
    /// Inside a command's adjustment: `p`, `param` and `width` are read.
    pub(super) terms: bool,
    flags: u32,
    width: Option<Expr>,
}

impl Parser<'_> {
    /// `path NAME [(params)] body`: a rule drawn as a path.
    pub(super) fn path_rule(&mut self, span: Span) -> Result<Rule, ParseError> {
        self.bump();
        let (name, _) = self.name("a path name after `path`")?;
        let params = if self.is_punct("(") { self.param_list()? } else { Vec::new() };
        let outer = std::mem::replace(&mut self.path.in_path, true);
        let body = if self.v3() { self.body() } else { self.body_v2() };
        self.path.in_path = outer;
        Ok(Rule { name, weight: 1.0, percent: false, body: body?, is_path: true, params, span })
    }

    /// A path operation or command (the current token names it).
    pub(super) fn path_element(&mut self) -> Result<Element, ParseError> {
        let span = self.span();
        let word = match self.peek() {
            Tok::Word(w) => w.clone(),
            _ => return self.err("expected a path operation"),
        };
        if !self.path.in_path {
            return self.err("path operations and commands are only allowed in a `path` (FILL and STROKE as shapes are not supported yet)");
        }
        self.bump();
        match op_kind(&word) {
            Some(kind) => self.path_op(kind, span).map(Element::PathOp),
            None => self.path_command(word == "FILL", span).map(Element::PathCommand),
        }
    }

    /// `STROKE (width, flags) [adj]`, `FILL [adj]` (3.x) or `STROKE { adj width w p flags }` (2.x).
    fn path_command(&mut self, fill: bool, span: Span) -> Result<PathCommand, ParseError> {
        let mut flags = if fill { pf::FILL } else { 0 };
        let mut width = None;
        if self.is_punct("(") {
            self.bump();
            let mut items = Vec::new();
            while !self.is_punct(")") {
                items.push((self.span(), self.expr(1)?));
                if !self.is_punct(",") {
                    break;
                }
                self.bump();
            }
            self.expect(")")?;
            if items.len() > 2 {
                return Err(ParseError::single(span, "path commands can have zero, one, or two parameters"));
            }
            for (at, e) in items {
                match flag_value(&e) {
                    Some(f) => flags = merge_flags(flags, f),
                    None if width.is_none() => width = Some(e),
                    None => return Err(ParseError::single(at, "unexpected argument in path command")),
                }
            }
        }
        self.path.terms = true;
        self.path.flags = 0;
        self.path.width = None;
        let adjust = self.adjustment();
        self.path.terms = false;
        let adjust = adjust?;
        flags = merge_flags(flags, std::mem::take(&mut self.path.flags));
        if let Some(w) = self.path.width.take() {
            if width.is_some() {
                return Err(ParseError::single(span, "cannot have a stroke adjustment in a v3 path command"));
            }
            width = Some(w);
        }
        Ok(PathCommand { fill, adjust, width, flags, span })
    }

    /// Reads a `p WORD`, `param WORD` or `width EXPR` term of a command's adjustment.
    pub(super) fn path_term(&mut self) -> Result<bool, ParseError> {
        match self.peek().clone() {
            Tok::Word(w) if w == "p" || w == "param" => {
                self.bump();
                let words = match self.bump().tok {
                    Tok::Word(n) | Tok::Str(n) => n,
                    _ => return Err(ParseError::single(self.span(), "expected a path parameter (evenodd, iso, roundjoin, …)")),
                };
                for f in words.split(' ').filter_map(param_flag) {
                    self.path.flags = merge_flags(self.path.flags, f);
                }
                Ok(true)
            }
            Tok::Word(w) if w == "width" => {
                self.bump();
                self.path.width = Some(self.exp()?);
                Ok(true)
            }
            _ => Ok(false),
        }
    }

    /// A path operation's arguments: `(x, y, …, flags)` or the 2.x
    /// keywords `{x y x1 y1 x2 y2 rx ry r p}` made positional.
    fn path_op(&mut self, kind: PathOpKind, span: Span) -> Result<PathOp, ParseError> {
        let (args, flags) = if self.is_punct("(") {
            self.bump();
            let (mut args, mut flags) = (Vec::new(), 0);
            while !self.is_punct(")") {
                let at = self.span();
                let e = self.expr(1)?;
                match flag_value(&e) {
                    Some(f) => flags |= f,
                    None if flags != 0 => return Err(ParseError::single(at, "flags must be the last argument")),
                    None => args.push(e),
                }
                if !self.is_punct(",") {
                    break;
                }
                self.bump();
            }
            self.expect(")")?;
            (args, flags)
        } else if self.is_punct("{") || self.is_punct("[") {
            self.keyword_args(kind, span)?
        } else {
            return self.err("expected `(`, `{` or `[` after a path operation");
        };
        // A vector argument counts as its numbers (cfdg counts the
        // evaluated size, `ASTpathOp::checkArguments`): when one may be a
        // vector, the count is checked when the arguments are evaluated.
        if let Err(e) = path_op_arity(kind, flags, args.len()) {
            if flags & !(pf::ARC_CW | pf::ARC_LARGE | pf::CONTINUOUS | pf::ALIGN) != 0 || !args.iter().any(may_be_vector) {
                return Err(ParseError::single(span, e));
            }
        }
        Ok(PathOp { kind, args, flags, span })
    }

    /// `ASTpathOp::makePositional`: the 2.x keyword form.
    fn keyword_args(&mut self, kind: PathOpKind, span: Span) -> Result<(Vec<Expr>, u32), ParseError> {
        let close = if self.is_punct("{") { "}" } else { "]" };
        self.bump();
        let mut slots: [Option<Expr>; 9] = Default::default();
        const NAMES: [&str; 9] = ["x", "y", "x1", "y1", "x2", "y2", "rx", "ry", "r"];
        let mut flags = 0;
        while !self.is_punct(close) {
            let at = self.span();
            let w = match self.peek() {
                Tok::Word(w) => w.clone(),
                _ => return self.err(format!("expected a path argument (x, y, x1, y1, x2, y2, rx, ry, r, p) or `{close}`")),
            };
            self.bump();
            let key = match w.as_str() {
                "rotate" => "r",
                "p" | "param" => {
                    let words = match self.bump().tok {
                        Tok::Word(n) | Tok::Str(n) => n,
                        _ => return Err(ParseError::single(at, "expected a path parameter after `p`")),
                    };
                    words.split(' ').filter_map(param_flag).for_each(|f| flags |= f);
                    continue;
                }
                "z" => return Err(ParseError::single(at, "z changes are not permitted in paths")),
                k => k,
            };
            let Some(slot) = NAMES.iter().position(|n| *n == key) else {
                return Err(ParseError::single(at, format!("`{w}` is not a path operation argument")));
            };
            if slots[slot].is_some() {
                return Err(ParseError::single(at, format!("duplicate argument `{w}`")));
            }
            slots[slot] = Some(self.exp()?);
        }
        self.bump();
        let [x, y, x1, y1, x2, y2, rx, ry, r] = slots;
        let num = |v: f64| Expr::Num(v, String::new());
        let xy = |a: Option<Expr>, b: Option<Expr>, def: f64| vec![a.unwrap_or_else(|| num(def)), b.unwrap_or_else(|| num(def))];
        let mut args = Vec::new();
        if kind != PathOpKind::ClosePoly {
            args = xy(x, y, 0.0);
        } else if x.is_some() || y.is_some() {
            return Err(ParseError::single(span, "CLOSEPOLY takes no arguments, only flags"));
        }
        match kind {
            PathOpKind::ArcTo | PathOpKind::ArcRel if rx.is_some() || ry.is_some() => {
                args.extend(xy(rx, ry, 1.0));
                args.push(r.unwrap_or_else(|| num(0.0)));
            }
            PathOpKind::ArcTo | PathOpKind::ArcRel => args.push(r.unwrap_or_else(|| num(1.0))),
            PathOpKind::CurveTo | PathOpKind::CurveRel => {
                if x1.is_some() || y1.is_some() {
                    args.extend(xy(x1, y1, 0.0));
                } else {
                    flags |= pf::CONTINUOUS;
                }
                if x2.is_some() || y2.is_some() {
                    args.extend(xy(x2, y2, 0.0));
                }
            }
            _ if [&x1, &y1, &x2, &y2, &rx, &ry, &r].iter().any(|a| a.is_some()) => {
                return Err(ParseError::single(span, "illegal argument for this path operation"));
            }
            _ => {}
        }
        Ok((args, flags))
    }
}

/// Adds flags `f` to `flags`, a given join or cap replacing the one before
/// (`ASTpathCommand::compile`).
fn merge_flags(mut flags: u32, f: u32) -> u32 {
    if f & pf::JOIN_PRESENT != 0 {
        flags &= !pf::JOIN_MASK;
    }
    if f & pf::CAP_PRESENT != 0 {
        flags &= !pf::CAP_MASK;
    }
    flags | f
}

#[cfg(test)]
mod tests {
    use crate::cfdg::{eval, parse_checked, syntax};
    use crate::core::budget::{Budget, Limits};

    /// A vector argument counts as its numbers (retaintest): checked
    /// when it is evaluated, with the operation's position.
    #[test]
    fn vector_arguments_count_as_their_numbers() {
        let src = "startshape R((2, 3))\npath R(vector2 sz) {\n MOVETO(sz)\n LINEREL(-sz[0], 0)\n LINETO(0, 0)\n CLOSEPOLY()\n FILL[]\n}\n";
        let g = parse_checked(src.as_bytes()).expect("parses");
        let p = eval::render(&g, &eval::Options::default(), &mut Budget::new(Limits::default())).expect("renders");
        let v = &p.paths[0][0].vertices;
        assert_eq!((v[0].x, v[0].y, v[1].x, v[1].y), (2.0, 3.0, 0.0, 3.0));
        let bad = "startshape R((2, 3, 4))\npath R(vector3 sz) {\n MOVETO(sz)\n FILL[]\n}\n";
        let g = parse_checked(bad.as_bytes()).expect("parses");
        let e = eval::render(&g, &eval::Options::default(), &mut Budget::new(Limits::default())).expect_err("three numbers");
        assert!(e.to_string().contains("3:2:") && e.to_string().contains("given 3 arguments"), "{e}");
        // Plain numbers are still counted when parsed.
        let e = syntax::parse(b"startshape R\npath R {\n MOVETO(1)\n}\n").expect_err("one number");
        assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (3, 2));
    }
}
