//! The CFDG renderer: expands a parsed [`Grammar`] into finished primitives
//! as cfdg 3.4's `RendererImpl` does (`renderimpl.cpp`, `astreplacement.cpp`,
//! John Horigan, Context Free 3.4): the largest unfinished shape first,
//! each shape carrying its own random stream, rule choice by cumulative
//! weight, recursion ending when a shape's area in pixels falls below the
//! minimum size at the scale the picture has so far, and the finished
//! shapes sorted by z, then by the order they were finished.

pub(crate) mod adjust;
pub mod anim;
pub(crate) mod builtins;
pub mod distributions;
pub mod agg;
pub mod expr;
pub mod frame;
pub(crate) mod func;
pub(crate) mod modval;
mod pending;
pub(crate) mod shapeval;
pub mod state;
pub mod symmetry;
pub mod tile;
pub mod wallpaper;

use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{self, Element, Grammar, Term, Value};
use crate::core::budget::{LimitExceeded, OnLimit};
use crate::model::EvalError;
use crate::{ParseError, Span};
use expr::{scalar, Scope};
use state::{Affine, State};
/// Lookups the renderer makes per shape, hashed by foldhash (Orson Peters,
/// 2024) with a fixed seed: nothing iterates these maps, so the seed
/// cannot change output, and SipHash cost a twentieth of a large render.
pub(crate) type FastMap<K, V> = std::collections::HashMap<K, V, foldhash::fast::FixedState>;

/// The primitives' shape numbers (`primShape`): CIRCLE, SQUARE, TRIANGLE.
pub(crate) const PRIMITIVES: [&str; 3] = ["CIRCLE", "SQUARE", "TRIANGLE"];

/// `FILL` as a shape outside a path: the whole canvas blended with the
/// shape's colour (`primShape::fillType`); finished as [`Finished::kind`] 4.
pub const FILL: &str = "FILL";

/// What a render is asked: canvas, minimum size, border and variation
/// (cfdg's command line: `-s`, `-x`, `-b`, `-v`, `-m`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Canvas width in pixels.
    pub width: u32,
    /// Canvas height in pixels.
    pub height: u32,
    /// Minimum shape size in pixels (cfdg's default 0.3).
    pub min_size: f64,
    /// Border mode in [-1, 2] (cfdg's default 2: variable-sized border).
    pub border: f64,
    /// The variation number ([`crate::cfdg::variation`]).
    pub variation: i32,
    /// Most shapes (cfdg `-m`); 0 for none.
    pub max_shapes: u64,
    /// At a budget limit, stop expanding and keep the shapes finished so
    /// far ([`OnLimit::Truncate`]), as cfdg's `-m` stops, or fail.
    pub on_limit: OnLimit,
    /// Expand a provably context-free design by its compiled bodies
    /// (`run/memo.rs`); off forces the general evaluator, which gives the
    /// same picture (the differential tests compare the two).
    pub memo: bool,
    /// Record the memoised expansion's nodes, for an instancing hierarchy.
    pub record: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options { width: 500, height: 500, min_size: 0.3, border: 2.0, variation: 1, max_shapes: 0, on_limit: OnLimit::Error, memo: true, record: false }
    }
}

/// One finished primitive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Finished {
    /// 0 CIRCLE, 1 SQUARE, 2 TRIANGLE, 3 a path, 4 a whole-canvas `FILL`.
    pub kind: usize,
    /// Its map from the unit primitive to design space.
    pub transform: Affine,
    /// Its z (drawing order: lower first).
    pub z: f64,
    /// Its RGBA in [0, 1] (not yet quantised).
    pub rgba: [f64; 4],
    /// The order it was finished in (1-based).
    pub order: u64,
    /// The area of its bounding box in design units (`m_Z.sz` of a finished shape).
    pub box_area: f64,
    /// A path's index in [`Picture::paths`] (0 for a primitive).
    pub path: usize,
    /// Its bounds in design space (cfdg's `FinishedShape::mBounds`): where
    /// a tiled design places its copies.
    pub bounds: frame::Bounds,
}

/// A rendered picture: the shapes cfdg would draw, in drawing order, and the framing.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    /// Shapes in drawing order (too small ones dropped, as cfdg drops them).
    pub shapes: Vec<Finished>,
    /// Width of the drawn area in pixels (cfdg's `curr_width`).
    pub width: u32,
    /// Height of the drawn area in pixels.
    pub height: u32,
    /// The canvas width (`-s`).
    pub canvas_width: u32,
    /// The canvas height.
    pub canvas_height: u32,
    /// Design space to pixels (y up).
    pub to_pixels: Affine,
    /// The background colour, RGBA in [0, 1].
    pub background: [f64; 4],
    /// The variation number used.
    pub variation: i32,
    /// Every primitive finished, including those too small to draw.
    pub finished: u64,
    /// What each path shape draws: one entry per command, in order.
    pub paths: Vec<Vec<PathDraw>>,
    /// The tiling and the final scale (design units to pixels) when the
    /// design is tiled or a frieze: the drawing repeats each shape.
    pub tiling: Option<(tile::Tiling, f64)>,
    /// The limit that ended expansion early under [`OnLimit::Truncate`]:
    /// the picture then holds the shapes finished before it, largest first
    /// as cfdg expands them (what `cfdg -m` draws).
    pub truncated: Option<LimitExceeded>,
    /// The memoised expansion, when the design is context-free and
    /// [`Options::record`] asked for it (`cfdg/instanced.rs` reads it).
    pub memo: Option<std::sync::Arc<Expansion>>,
    /// Whether a path shape was finished (false: `shapes` holds no path,
    /// and a drawing need not look for one).
    pub has_paths: bool,
}

#[derive(Debug, Clone)]
struct Unfinished {
    shape: usize,
    state: State,
    params: Vec<f64>,
}

/// A compiled rule set: rules of each shape with cumulative weights.
struct Rules<'g> {
    index: FastMap<&'g str, usize>,
    /// Per shape number (primitives first): (cumulative weight, body).
    by_shape: Vec<Vec<(f64, &'g [Element])>>,
    /// Per shape number: its parameters' names.
    params: Vec<&'g [String]>,
    /// Per shape number: how many numbers each parameter takes.
    sizes: Vec<Vec<usize>>,
    /// Per shape number: whether it is a `path`.
    is_path: Vec<bool>,
}

fn compile(g: &Grammar) -> Result<Rules<'_>, ParseError> {
    let mut index: FastMap<&str, usize> = FastMap::default();
    for (i, p) in PRIMITIVES.iter().enumerate() {
        index.insert(p, i);
    }
    let mut by_shape: Vec<Vec<(f64, f64, bool, &[Element])>> = vec![Vec::new(); 3];
    let mut params: Vec<&[String]> = vec![&[]; 3];
    let mut sizes: Vec<Vec<usize>> = vec![Vec::new(); 3];
    let mut is_path = vec![false; 3];
    let sizes_of = |r: &syntax::Rule| -> Vec<usize> {
        match g.param_types.get(&r.name) {
            Some(ps) if ps.len() == r.params.len() => ps.iter().map(|p| shapeval::slot_size(p.ty)).collect(),
            _ => vec![1; r.params.len()],
        }
    };
    for r in &g.rules {
        // A rule for a primitive's name replaces the primitive (cfdg's shape
        // type becomes a rule type, `CFDGImpl::addRule`); so does a 2.x
        // `rule FILL` (quadcity_v2), FILL outside a path being a shape name.
        let n = index.len();
        let i = *index.entry(r.name.as_str()).or_insert(n);
        if i == by_shape.len() {
            by_shape.push(Vec::new());
            params.push(&r.params);
            sizes.push(sizes_of(r));
            is_path.push(r.is_path);
        }
        // A path named as a primitive replaces the primitive (trisvgtest).
        if r.is_path {
            is_path[i] = true;
            params[i] = &r.params;
            sizes[i] = sizes_of(r);
        }
        by_shape[i].push((r.weight, 0.0, r.percent, &r.body));
    }
    // CFDGImpl::rulesLoaded: normalise, percentages apart, cumulative, the last 1.
    let by_shape = by_shape
        .into_iter()
        .map(|rules| {
            let total: f64 = rules.iter().filter(|r| !r.2).map(|r| r.0).sum();
            let pct: f64 = rules.iter().filter(|r| r.2).map(|r| r.0).sum();
            let any_pct = rules.iter().any(|r| r.2);
            let mut acc = 0.0;
            let n = rules.len();
            rules
                .into_iter()
                .enumerate()
                .map(|(k, (w, _, is_pct, body))| {
                    let mut weight = w / total;
                    if any_pct {
                        weight = if is_pct { w } else { weight * (1.0 - pct) };
                    }
                    if !weight.is_finite() {
                        weight = 0.0;
                    }
                    acc += weight;
                    (if k + 1 == n { 1.0 } else { acc }, body)
                })
                .collect()
        })
        .collect();
    Ok(Rules { index, by_shape, params, sizes, is_path })
}

/// Checks that every shape a design names exists, so a missing rule is a
/// parse error at its use rather than a stop in the middle of rendering.
pub fn check(g: &Grammar) -> Result<(), ParseError> {
    let rules = compile(g)?;
    fn walk(body: &[Element], rules: &Rules<'_>) -> Result<(), ParseError> {
        for e in body {
            match e {
                Element::Replace(r) => arity(r, rules)?,
                Element::Loop(l) => {
                    walk(&l.body, rules)?;
                    walk(&l.finally, rules)?;
                }
                Element::If { then, otherwise, .. } => {
                    walk(then, rules)?;
                    walk(otherwise, rules)?;
                }
                Element::Switch { cases, otherwise, .. } => {
                    for (_, b) in cases {
                        walk(b, rules)?;
                    }
                    walk(otherwise, rules)?;
                }
                Element::Transform { body, .. } => walk(body, rules)?,
                Element::Define(_) | Element::PathOp(_) | Element::PathCommand(_) => {}
            }
        }
        Ok(())
    }
    fn arity(r: &syntax::Replacement, rules: &Rules<'_>) -> Result<(), ParseError> {
        // A name with no rules may be a shape variable, or never reached:
        // cfdg stops only when it meets it (run/bind.rs); FILL without rules
        // of its own is cfdg's whole-canvas fill (primShape::fillType).
        let Some(&i) = rules.index.get(r.shape.as_str()) else {
            return Ok(());
        };
        // Vector parameters take lists that may come from one variable:
        // their counts are checked when the arguments are evaluated.
        if rules.sizes[i].iter().any(|&k| k != 1) {
            return Ok(());
        }
        let wanted = rules.params[i].len();
        if matches!(&r.args, Some(syntax::Expr::Var(v, _)) if v == syntax::REUSE) {
            return Ok(());
        }
        let given = r.args.as_ref().map_or(0, |a| a.items().len());
        if given != wanted {
            return Err(ParseError::single(r.span, format!("shape `{}` takes {wanted} arguments, given {given}", r.shape)));
        }
        Ok(())
    }
    for r in &g.rules {
        walk(&r.body, &rules)?;
    }
    if let Some(s) = &g.start {
        if rules.index.contains_key(s.shape.as_str()) {
            arity(s, &rules)?;
        }
    }
    match &g.start {
        None => Err(ParseError::single(Span::new(1, 1), "no `startshape`")),
        // The start shape may be a global shape variable (stackargtest).
        Some(s) if !rules.index.contains_key(s.shape.as_str()) && !g.defines.iter().any(|d| d.name == s.shape) && s.shape != syntax::SHAPE_EXPR && !g.functions.contains_key(&s.shape) => Err(ParseError::single(s.span, format!("start shape `{}` has no rules", s.shape))),
        Some(_) => Ok(()),
    }
}

mod run;
pub(crate) use run::{PathDraw, SHAPE_BYTES};
pub use run::memo::Expansion;

/// The stack the render runs on: user functions recurse through the
/// evaluator (a few Rust frames per call, about 9 KiB in a debug build), so
/// [`func::MAX_CALL_DEPTH`] calls need more than the 2 MiB a server or test
/// thread has. Reserved address space; only the pages used are touched.
pub(crate) const RENDER_STACK: usize = 64 << 20;

/// Renders `g` as cfdg renders it with `opts`, charging `budget` (a step
/// per rule expanded, per loop iteration and per user function call,
/// memory per shape kept, a primitive per shape finished), on a thread of
/// its own with a [`RENDER_STACK`]-byte stack.
pub fn render(g: &Grammar, opts: &Options, budget: &mut crate::core::budget::Budget) -> Result<Picture, EvalError> {
    std::thread::scope(|s| {
        let spawned = std::thread::Builder::new().name("cfdg-render".into()).stack_size(RENDER_STACK).spawn_scoped(s, || run::render(g, opts, budget));
        match spawned {
            Ok(h) => h.join().unwrap_or_else(|_| Err(EvalError::BadParam { name: "cfdg".into(), message: "the renderer failed (a bug: please report the design)".into() })),
            Err(e) => Err(EvalError::BadParam { name: "cfdg".into(), message: format!("cannot start the renderer's thread: {e}") }),
        }
    })
}

/// The terms of an adjustment in evaluation order, cached per adjustment.
pub(crate) fn terms_of(adj: &syntax::Adjustment) -> Vec<Term> {
    adjust::ordered(adj)
}

/// The number each `rand_static()` of `g` draws: cfdg's builder seeds a
/// stream with the variation (not stepped, unlike the renderer's) and every
/// `rand_static` it makes takes the next double (`builder.cpp`
/// `Builder::Builder`, `MakeFunction`; `astexpression.cpp`
/// `ASTfunction::ASTfunction`), so they differ from call to call and from
/// variation to variation but not from run to run.
pub(crate) fn rand_static(g: &Grammar, variation: i32) -> Vec<(Span, f64)> {
    let mut r = Rand64::seeded(variation.max(1) as u64);
    g.rand_static.iter().map(|&at| (at, r.next_double())).collect()
}

/// Evaluates the numeric `CF::` setting `name`, if set.
pub(crate) fn setting(g: &Grammar, name: &str, scope: &Scope) -> Result<Option<f64>, EvalError> {
    let mut r = Rand64::default();
    for d in g.defines.iter().rev() {
        if d.name == name {
            if let Value::Expr(e) = &d.value {
                return scalar(e, scope, &mut r).map(Some);
            }
        }
    }
    Ok(None)
}
