//! Subpaths: `path NAME [adjustment]` inside a path, as cfdg 3.4 walks
//! them (John Horigan, Context Free 3.4: `builder.cpp`
//! `Builder::MakeElement` decides what a subpath draws while parsing;
//! `astreplacement.cpp` `ASTreplacement::compile` checks it and
//! `ASTreplacement::traverse` walks it; `renderimpl.cpp`
//! `RendererImpl::processSubpath` picks the rule, or a primitive's own
//! path from `ASTrule::ASTrule(int)`).
//!
//! A subpath is a path operation list, a command list or both ("mixed"),
//! as the path it names: a path defined before it has the kind of its
//! body; a primitive, a shape variable, the path itself and a path
//! defined later are taken to be operations only, and cfdg checks when it
//! walks them that they are ("Subpath is not of the expected type").
//! Operations only: the subpath's shape starts from the identity unless
//! its operations are already being transformed, its adjustment applies,
//! and its operations are transformed by the result. Otherwise the
//! adjustment applies to the enclosing shape and the body is walked as a
//! path body is. Its seed is a replacement's (adjustment and name hashed),
//! mixed into the path's stream before its adjustment, after its
//! arguments. Every subpath is a step; they nest at most
//! [`MAX_SUBPATH_DEPTH`] deep (or the budget's depth limit), so a path that
//! draws itself ends in a typed `Depth` error.

use super::super::super::adjust::apply_prepared;
use super::super::super::state::{Affine, State};
use super::super::Renderer;
use super::{error, Ctx, REP_COMMAND, REP_OP, REP_REPLACEMENT};
use crate::cfdg::syntax::{Element, Expr, PathOp, PathOpKind, Replacement, REUSE};
use crate::core::budget::{Limit, LimitExceeded};
use crate::model::EvalError;
use crate::Span;
use std::collections::HashMap;
use std::sync::Arc;

/// Deepest nesting of subpaths, whatever the budget allows: each level is
/// a few frames of the walker.
pub(crate) const MAX_SUBPATH_DEPTH: u32 = 100;

/// The kind (`REP_OP`, `REP_COMMAND` or both) of every subpath of the
/// design, by the address of its [`Replacement`], and of every path body,
/// by shape number; worked out once per render, in the order the shapes
/// were defined, as cfdg's parser does it.
#[derive(Debug, Default)]
pub(crate) struct SubpathTypes {
    by_rep: HashMap<usize, u8>,
    by_shape: Vec<u8>,
}

fn key(r: &Replacement) -> usize {
    r as *const Replacement as usize
}

/// The kinds a body holds, its subpaths counted as `kind_of` says.
fn body_type(body: &[Element], kind_of: &mut dyn FnMut(&Replacement) -> u8) -> u8 {
    body.iter().fold(0, |acc, e| {
        acc | match e {
            Element::PathOp(_) => REP_OP,
            Element::PathCommand(_) => REP_COMMAND,
            Element::Replace(r) => kind_of(r),
            Element::Loop(l) => body_type(&l.body, kind_of) | body_type(&l.finally, kind_of),
            Element::If { then, otherwise, .. } => body_type(then, kind_of) | body_type(otherwise, kind_of),
            Element::Switch { cases, otherwise, .. } => cases.iter().fold(body_type(otherwise, kind_of), |a, (_, b)| a | body_type(b, kind_of)),
            Element::Transform { body, .. } => body_type(body, kind_of),
            Element::Define(_) => 0,
        }
    })
}

/// A primitive's path (`ASTrule::ASTrule(int)`): the square's and the
/// triangle's corners (`primShape.cpp`) as MOVETO and LINETOs, the circle
/// as two half-circle ARCTOs, then CLOSEPOLY.
fn primitive_path(shape: usize, span: Span) -> Vec<Element> {
    let num = |v: f64| Expr::Num(v, String::new());
    let op = |kind, args: &[f64]| Element::PathOp(PathOp { kind, args: args.iter().map(|&v| num(v)).collect(), flags: 0, span });
    let mut out = Vec::new();
    if shape == 0 {
        out.push(op(PathOpKind::MoveTo, &[0.5, 0.0]));
        out.push(op(PathOpKind::ArcTo, &[-0.5, 0.0, 0.5]));
        out.push(op(PathOpKind::ArcTo, &[0.5, 0.0, 0.5]));
    } else {
        let h = 0.5 / (std::f64::consts::PI / 6.0).cos();
        let corners: &[(f64, f64)] = if shape == 1 { &[(0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5), (0.5, -0.5)] } else { &[(0.0, h), (-0.5, -h / 2.0), (0.5, -h / 2.0)] };
        for (i, &(x, y)) in corners.iter().enumerate() {
            out.push(op(if i == 0 { PathOpKind::MoveTo } else { PathOpKind::LineTo }, &[x, y]));
        }
    }
    out.push(op(PathOpKind::ClosePoly, &[]));
    out
}

impl<'g> Renderer<'g> {
    /// The kinds of element `body` holds, a subpath counting as what it draws.
    pub(super) fn rep_type(&mut self, body: &[Element]) -> u8 {
        let types = self.subpath_types();
        body_type(body, &mut |r| types.by_rep.get(&key(r)).copied().unwrap_or(REP_OP))
    }

    fn subpath_types(&mut self) -> Arc<SubpathTypes> {
        if let Some(t) = &self.subpaths {
            return t.clone();
        }
        let rules = &self.rules;
        let mut t = SubpathTypes { by_rep: HashMap::new(), by_shape: vec![0; rules.by_shape.len()] };
        for shape in 0..rules.by_shape.len() {
            if !rules.is_path[shape] {
                continue;
            }
            let Some(&(_, body)) = rules.by_shape[shape].first() else { continue };
            let (by_shape, by_rep) = (&t.by_shape, &mut t.by_rep);
            let kind = body_type(body, &mut |r| {
                // MakeElement: a path defined before has its body's kind
                // (a primitive's name is always operations, as compile checks);
                // anything else is taken to be operations.
                let kind = match rules.index.get(r.shape.as_str()) {
                    Some(&j) if j >= 3 && j < shape && rules.is_path[j] && by_shape[j] != 0 => by_shape[j],
                    _ => REP_OP,
                };
                by_rep.insert(key(r), kind);
                kind
            });
            t.by_shape[shape] = kind;
        }
        let t = Arc::new(t);
        self.subpaths = Some(t.clone());
        t
    }

    /// Walks subpath `rep` of a path (`ASTreplacement::traverse` for a
    /// subpath, then `processSubpath`).
    pub(super) fn subpath(&mut self, rep: &Replacement, parent: &State, tr: bool, ctx: &mut Ctx) -> Result<(), EvalError> {
        self.budget.charge_step()?;
        let types = self.subpath_types();
        let expected = types.by_rep.get(&key(rep)).copied().unwrap_or(REP_OP);
        let (shape, bound) = self.target(rep)?;
        // processSubpath: a primitive that is not a path draws its own path.
        let primitive = shape < 3 && !self.rules.is_path[shape];
        let prim_body;
        let (body, actual): (&[Element], u8) = if primitive {
            prim_body = primitive_path(shape, rep.span);
            (&prim_body, REP_OP)
        } else {
            let rules: &[(f64, &'g [Element])] = &self.rules.by_shape[shape];
            match rules.first() {
                Some(&(_, b)) if self.rules.is_path[shape] => (b, types.by_shape.get(shape).copied().unwrap_or(0)),
                Some(&(_, b)) => (b, REP_REPLACEMENT),
                None => return Err(error(rep.span, &format!("shape with no rules encountered: `{}`", rep.shape))),
            }
        };
        if actual != expected {
            return Err(error(rep.span, "Subpath is not of the expected type (path ops/commands)"));
        }
        let max = self.budget.limits().max_depth.min(MAX_SUBPATH_DEPTH);
        if ctx.walking.len() as u64 > u64::from(max) {
            return Err(LimitExceeded::crossed(Limit::Depth, max.into(), ctx.walking.len() as u64).into());
        }
        let ops = expected == REP_OP;
        let mut child = *parent;
        if ops && !tr {
            child.transform = Affine::default();
        }
        // ASTreplacement::replace: the arguments, then the seed, then the adjustment.
        let wanted: usize = self.rules.sizes[shape].iter().sum();
        let params = match (&rep.args, bound) {
            (_, Some(b)) => b,
            (Some(Expr::Var(v, _)), None) if v == REUSE => self.params.clone(),
            (Some(a), None) => {
                let mut p = Vec::new();
                super::super::super::expr::eval(a, &self.scope, &mut self.current, &mut p)?;
                p
            }
            (None, None) => Vec::new(),
        };
        if params.len() != wanted {
            return Err(error(rep.span, &format!("shape `{}` takes {wanted} numbers, given {}", rep.shape, params.len())));
        }
        let prepared = self.seeded_terms(&rep.adjust, self.entropy_name(rep), rep.args.as_ref());
        let (terms, seed) = (&prepared.0, prepared.1);
        self.current.xor(seed);
        self.current.next_u64();
        apply_prepared(&terms, &mut child, &self.scope, &mut self.current)?;
        // processSubpath: the body with the subpath's own parameters.
        let depth = self.scope.vars.len();
        self.bind_params(shape, &params);
        let saved = std::mem::replace(&mut self.params, params);
        ctx.walking.push(shape);
        let walked = self.path_body(body, &child, tr || ops, ctx);
        ctx.walking.pop();
        self.params = saved;
        self.scope.vars.truncate(depth);
        walked
    }
}

#[cfg(test)]
mod tests {
    use crate::cfdg::{eval, parse_checked, syntax};
    use crate::core::budget::{Budget, Limit, Limits};
    use crate::model::EvalError;

    /// Renders `src` read as 3.x (a `shape` makes it so).
    fn render(src: &str) -> Result<eval::Picture, EvalError> {
        let src = format!("{src}shape Z {{ SQUARE [] }}\n");
        let g = parse_checked(src.as_bytes()).map_err(|e| EvalError::BadParam { name: "parse".into(), message: e.to_string() })?;
        eval::render(&g, &eval::Options::default(), &mut Budget::new(Limits::default()))
    }

    #[test]
    fn subpaths_add_their_operations() {
        // Five stars of four lines each, one stroke (subpathtest2).
        let src = "startshape stars\npath star {\n MOVETO(0,1)\n loop 4 [r 144] LINETO(cos(234), sin(234))\n CLOSEPOLY()\n}\npath stars {\n loop 5 [r 72] path star[y 1.6]\n STROKE[]\n}\n";
        let p = render(src).expect("renders");
        assert_eq!(p.shapes.len(), 1);
        let cmds = &p.paths[p.shapes[0].path];
        assert_eq!(cmds.len(), 1);
        // Each star: a move, four lines and a close (AGG's end_poly
        // vertex); then the stop that ends the path.
        assert_eq!(cmds[0].vertices.len(), 5 * 6 + 1);
        assert_eq!(render(src).expect("again"), p);
        // A primitive's path: the square's four corners, closed, and the stop.
        let p = render("startshape P\npath P { path SQUARE[s 2] FILL[] }\n").expect("renders");
        let v = &p.paths[0][0].vertices;
        assert_eq!(v.len(), 6);
        assert_eq!((v[0].x, v[0].y), (1.0, 1.0));
        // A shape variable naming a primitive, and a path with arguments.
        let p = render("startshape P\nhole = TRIANGLE\npath B(number w) { MOVETO(w, 0) LINETO(0, w) CLOSEPOLY() }\npath P { path hole[] path B(2)[x 3] FILL[] }\n").expect("renders");
        // The triangle's move, two lines and close; B's move, line and close; the stop.
        assert_eq!(p.paths[0][0].vertices.len(), 4 + 3 + 1);
        assert_eq!((p.paths[0][0].vertices[4].x, p.paths[0][0].vertices[4].y), (5.0, 0.0));
    }

    #[test]
    fn subpaths_are_checked_as_cfdg_checks_them() {
        // A command path named before it is defined is taken to be operations.
        let e = render("startshape P\npath P { MOVETO(0, 0) LINETO(1, 1) path Q[] }\npath Q { MOVETO(0, 0) LINETO(1, 0) STROKE[] }\n").expect_err("forward");
        assert!(e.to_string().contains("2:41:") && e.to_string().contains("Subpath is not of the expected type"), "{e}");
        // A shape that is not a path.
        let e = render("startshape P\npath P { MOVETO(0, 0) path R[] }\nshape R { SQUARE [] }\n").expect_err("rule");
        assert!(e.to_string().contains("Subpath is not of the expected type"), "{e}");
        // A path that draws itself ends at the depth limit.
        let e = render("startshape P\npath P { MOVETO(0, 0) LINETO(1, 1) path P[s 0.5] }\n").expect_err("endless");
        assert!(matches!(&e, EvalError::Limit(l) if l.limit == Limit::Depth), "{e:?}");
        // A replacement without `path` is a parse error with its position.
        let e = syntax::parse(b"startshape P\npath P {\n  MOVETO(0, 0)\n  SQUARE []\n}\nshape Z { SQUARE [] }\n").expect_err("replacement");
        let d = &e.diagnostics[0];
        assert_eq!((d.span.line, d.span.column), (4, 3), "{d}");
        assert!(d.message.contains("Replacements are not allowed in paths"), "{d}");
        assert!(syntax::parse(b"startshape P\npath P { MOVETO(0, 0) path FILL[] }\nshape Z { SQUARE [] }\n").is_err());
        // An adjustment value chosen inside an expression (subpathtest) is
        // the local adjustment, not the global number of the same name.
        let p = render("B = 3\nstartshape T\nshape T {\n B = [x 1]\n SQUARE [trans select(1, B, B)]\n}\n").expect("renders");
        assert_eq!(p.shapes[0].transform.tx, 1.0);
    }
}
