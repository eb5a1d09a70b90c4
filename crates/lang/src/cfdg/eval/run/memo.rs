//! Memoised expansion of context-free designs: a design whose every rule
//! body evaluates to the same replacements, with the same adjustments,
//! wherever and however often it is expanded is compiled once, body by
//! body, and expanded by composing those compiled bodies, with no
//! interpreter (scopes, random streams, expressions, rule choice) per shape.
//!
//! When is that exact? cfdg expands a shape by choosing one of its rules by
//! the first double of the shape's stream, then walking the rule's body
//! with the shape's stream, scope and parameters (`renderimpl.cpp`
//! `processShape`, `astreplacement.cpp` `ASTreplacement::traverse`). The
//! body's replacements are the same for every instance when
//! ([`Renderer::memo_plan`] checks each, from the start shape over every
//! shape it reaches):
//!
//! - every reached shape has exactly one rule (cfdg's choice by weight is
//!   then always that rule, `CFDGImpl::rulesLoaded` makes its cumulative
//!   weight 1) and no parameters, and is not a path;
//! - every body element is a plain replacement `NAME [adjustment]` of a
//!   shape or primitive resolved without the scope (no shape variable,
//!   `select`, arguments or `FILL`), with no `loop`, `if`, `switch`,
//!   `transform`/`clone` or definition;
//! - every term not folded at compile time has constant arguments (no
//!   variable, no `rand…` function, `ftime`/`frame`; `rand_static` is a
//!   constant: `syntax::is_constant`), so evaluating it once gives the
//!   numbers every instance would draw;
//! - the design has no tile, frieze, `CF::Size` or symmetry (each changes
//!   how a finished shape is kept).
//!
//! The stream then decides nothing, so a shape's expansion depends only on
//! its state; the child states are computed by the very float operations
//! [`super::super::adjust::apply_prepared`] performs (the folded map
//! premultiplied, then each remaining term by [`super::super::adjust::term`]),
//! so every area, bound and transform is bit for bit the general
//! evaluator's. What is *not* context-free is the cut: cfdg keeps a shape
//! only while its area times the current scale squared reaches the
//! minimum size, and the scale shrinks as finished shapes grow the bounds;
//! it truncates at `-m` (and rulemesh at a budget limit) in largest-first
//! order. Both depend on the order of the whole run, so the expansion keeps
//! cfdg's heap ([`super::super::pending`]), its bounds and scale, and the
//! budget charges of the general loop in the same order (a step per shape
//! expanded, memory per shape kept, a primitive per shape finished): the
//! cut, the truncation point and the drawing order are then the general
//! evaluator's by construction, and `tests/it/cfdg_memo.rs` checks the SVG
//! byte for byte. The memo is what each instance *is*: a record of which
//! compiled replacement made which node or finished shape
//! ([`Expansion`]), from which `cfdg/instanced.rs` builds the instancing
//! hierarchy of equal subtrees for `scene` and instanced glTF.

use super::super::adjust::{prepare, term};
use super::super::state::{Affine, State};
use super::super::pending::Pending;
use super::super::FILL;
use super::{Renderer, SHAPE_BYTES};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{self, Element, Replacement, Term};
use crate::model::EvalError;

/// An outcome that made nothing (cut, dropped, or never expanded).
pub(crate) const NONE: u32 = u32::MAX;
/// The tag of an outcome naming a finished shape (its order − 1) rather than a node.
pub(crate) const LEAF: u32 = 1 << 31;

/// One replacement of a compiled body: its target and its adjustment with
/// every argument already evaluated.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Edge {
    /// The shape number replaced.
    pub(crate) shape: usize,
    /// Whether that shape is a primitive finished at once.
    pub(crate) leaf: bool,
    /// The constant geometry cfdg folds at compile time (`Prepared::folded`).
    folded: Option<Affine>,
    /// The remaining terms with their arguments' numbers.
    rest: Vec<(Term, Vec<f64>)>,
    /// The edge applied to the start state: the child's frame in its
    /// parent's (transform, z, colour change), for the hierarchy.
    pub(crate) relative: State,
}

impl Edge {
    /// Applies the edge to a parent's state, as `apply_prepared` would.
    fn apply(&self, s: &mut State) -> Result<(), EvalError> {
        if let Some(m) = &self.folded {
            s.transform.premultiply(m);
        }
        for (t, a) in &self.rest {
            term(t, a, s)?;
        }
        Ok(())
    }
}

/// Every reached shape's compiled body (empty for a primitive).
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Plan {
    /// Per shape number.
    pub(crate) bodies: Vec<Vec<Edge>>,
}

/// A memoised run: the plan, and what each node's replacements made
/// (recorded only when a hierarchy is wanted).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Expansion {
    pub(crate) plan: Plan,
    /// The start shape and state.
    pub(crate) start_shape: usize,
    pub(crate) start: Option<State>,
    /// What the start shape became (a node, `LEAF | order − 1`, or [`NONE`]).
    pub(crate) root: u32,
    /// Whether the nodes were recorded (and fitted in 31 bits).
    pub(crate) recorded: bool,
    /// Per node: its shape.
    pub(crate) shape: Vec<u32>,
    /// Per node: where its outcomes start in `outcomes`, [`NONE`] if never expanded.
    pub(crate) first: Vec<u32>,
    /// One outcome per edge of each expanded node.
    pub(crate) outcomes: Vec<u32>,
}

impl Expansion {
    fn node(&mut self, shape: usize) -> u32 {
        if !self.recorded {
            return 0;
        }
        let n = self.first.len() as u32;
        if n >= LEAF {
            self.recorded = false;
            return 0;
        }
        self.first.push(NONE);
        self.shape.push(shape as u32);
        n
    }
}

impl Renderer<'_> {
    /// The compiled bodies of the design from `start`, or `None` when its
    /// expansion is not provably context-free (module documentation).
    pub(super) fn memo_plan(&mut self, start: usize) -> Option<Plan> {
        if self.tiling.is_some() || !self.symmetry.is_empty() || self.sized.is_some() || self.tile_canvas.is_some() {
            return None;
        }
        let n = self.rules.by_shape.len();
        let mut bodies = vec![Vec::new(); n];
        let mut seen = vec![false; n];
        *seen.get_mut(start)? = true;
        let mut stack = vec![start];
        while let Some(s) = stack.pop() {
            if self.rules.is_path[s] {
                return None;
            }
            if self.is_leaf(s) {
                continue;
            }
            if self.rules.by_shape[s].len() != 1 || !self.rules.params[s].is_empty() {
                return None;
            }
            let body = self.rules.by_shape[s][0].1;
            let mut edges = Vec::with_capacity(body.len());
            for e in body {
                let Element::Replace(rep) = e else { return None };
                let edge = self.compile_edge(rep)?;
                if !seen[edge.shape] {
                    seen[edge.shape] = true;
                    stack.push(edge.shape);
                }
                edges.push(edge);
            }
            bodies[s] = edges;
        }
        Some(Plan { bodies })
    }

    /// Whether shape `s` is a primitive finished when made.
    fn is_leaf(&self, s: usize) -> bool {
        s < 3 && self.rules.by_shape[s].is_empty() && !self.rules.is_path[s]
    }

    fn compile_edge(&mut self, rep: &Replacement) -> Option<Edge> {
        if rep.args.is_some() || rep.shape == syntax::SHAPE_EXPR || (rep.shape == FILL && !self.rules.index.contains_key(FILL)) {
            return None;
        }
        let Ok((shape, None)) = self.target_of(rep) else { return None };
        let p = prepare(&rep.adjust);
        let mut rest = Vec::with_capacity(p.rest.len());
        let mut rand = Rand64::default();
        for t in p.rest {
            if !syntax::is_constant(&t.args) {
                return None;
            }
            let mut a = Vec::new();
            super::super::expr::eval(&t.args, &self.scope, &mut rand, &mut a).ok()?;
            let value = t.kind == syntax::TermKind::Transform && (super::super::modval::lookup(&t.args, &self.scope).is_some() || super::super::shapeval::as_adjust(&a).is_some());
            if value {
                return None;
            }
            rest.push((t, a));
        }
        let mut edge = Edge { shape, leaf: self.is_leaf(shape), folded: p.folded, rest, relative: State::initial() };
        let mut rel = State::initial();
        edge.apply(&mut rel).ok()?;
        edge.relative = rel;
        Some(edge)
    }

    /// Expands `start` from `init` by the compiled bodies of `x.plan`, in
    /// cfdg's order and with the general loop's charges (`expand`). When no
    /// edge changes anything but the transform, a waiting shape keeps only
    /// its transform (the rest is the start state's): a quarter of the
    /// bytes per slot, the slots being fetched in area order, all over a
    /// large array.
    pub(super) fn memo_expand(&mut self, x: &mut Expansion, start: usize, init: State) -> Result<(), EvalError> {
        x.start_shape = start;
        x.start = Some(init);
        x.root = NONE;
        // The finished shapes' room, up front: at most what the primitive,
        // shape and memory limits let finish (capped at 2²⁰; pages are touched only
        // as shapes finish), so 262 143 shapes of 152 bytes are not copied
        // by doubling.
        let memory = self.budget.limits().max_memory.saturating_sub(self.budget.memory()) / SHAPE_BYTES;
        let room = self.budget.limits().max_primitives.saturating_sub(self.budget.primitives()).saturating_add(1).min(self.max_shapes).min(memory).min(1 << 20);
        let room = usize::try_from(room).unwrap_or(0);
        self.finished.reserve(room);
        crate::core::hugepages::advise(&mut self.finished);
        let affine = x.plan.bodies.iter().flatten().all(|e| e.rest.is_empty());
        let mut waiting: Pending<Waiting<State>> = Pending::default();
        let mut moved: Pending<Waiting<Affine>> = Pending::default();
        // As many may wait as may finish, at most (each waiting shape is
        // charged as a finished one is): room that is never touched costs
        // no memory, and a grown array is a copy into fresh pages.
        let result = if affine {
            moved.reserve(room);
            // The finished shapes' pages are faulted in on another thread,
            // ahead of this one (`core::hugepages::Prefault`): this loop is
            // sequential, and first touching 40 MB had been a tenth of the
            // bush's expansion, more when the machine's host backs the pages late.
            // The waiting shapes' slots too, as they fill.
            let ahead = [crate::core::hugepages::Prefault::of(&self.finished), moved.slots_prefault()];
            let room_bytes = room.saturating_mul(std::mem::size_of::<super::super::Finished>());
            if room_bytes > crate::core::hugepages::AHEAD {
                std::thread::scope(|scope| {
                    // Without a thread (the system refuses one) the loop runs alone.
                    // Stops the helper however the loop ends, a panic included.
                    let _done = ahead[0].finish_on_drop();
                    let helper = std::thread::Builder::new().name("cfdg-prefault".into()).spawn_scoped(scope, || crate::core::hugepages::Prefault::run_all(&[&ahead[0], &ahead[1]], std::time::Duration::from_micros(200)));
                    self.memo_loop_affine(x, &mut moved, start, init, helper.is_ok().then_some(&ahead))
                })
            } else {
                self.memo_loop_affine(x, &mut moved, start, init, None)
            }
        } else {
            waiting.reserve(room);
            self.memo_loop(x, &mut waiting, start, init)
        };
        // What still waits is given back, as `finish` gives back the general loop's.
        self.budget.release_memory(SHAPE_BYTES * (waiting.len() + moved.len()) as u64);
        result
    }

    /// [`Renderer::memo_loop`] for a design whose every edge only moves the
    /// transform (no term left after folding): every other part of every
    /// state is the start state's, so a waiting shape keeps only its
    /// transform (a quarter of the bytes per slot, the slots fetched in
    /// area order all over a large array), and a child is its parent's
    /// transform premultiplied by the edge's folded map, with no whole
    /// state copied. The colour, z and drop test are the start state's,
    /// worked out once. Each step is `memo_loop`'s, in the same order.
    fn memo_loop_affine(&mut self, x: &mut Expansion, waiting: &mut Pending<Waiting<Affine>>, start: usize, init: State, ahead: Option<&[crate::core::hugepages::Prefault; 2]>) -> Result<(), EvalError> {
        let leaf = self.is_leaf(start);
        x.root = self.memo_process(x, waiting, start, leaf, init)?;
        let base_finite = State { transform: Affine::scaling(1.0, 1.0), ..init }.is_finite();
        let (dropped, z, rgba) = (super::super::anim::dropped(&init), init.tz, init.color.rgba());
        let mut reported = 0usize;
        while let Some((w, edges)) = self.memo_next(x, waiting)? {
            if let Some(a) = ahead {
                if self.finished.len() >= reported + 4096 {
                    reported = self.finished.len();
                    a[0].written(reported, std::mem::size_of::<super::super::Finished>());
                    waiting.report_slots(&a[1]);
                }
            }
            let shape = w.shape as usize;
            for k in 0..edges {
                let e = &x.plan.bodies[shape][k];
                let (target, leaf) = (e.shape, e.leaf);
                let mut t = w.carried;
                if let Some(m) = &e.folded {
                    t.premultiply(m);
                }
                if !(base_finite && super::super::state::all_finite(&[t.sx, t.shy, t.shx, t.sy, t.tx, t.ty])) {
                    return Err(non_finite());
                }
                let out = if dropped {
                    NONE
                } else if leaf {
                    self.memo_leaf(target, &t, z, rgba)?
                } else {
                    self.memo_keep(x, waiting, target, t.determinant().abs(), t)?
                };
                if x.recorded {
                    x.outcomes.push(out);
                }
            }
        }
        Ok(())
    }

    fn memo_loop(&mut self, x: &mut Expansion, waiting: &mut Pending<Waiting<State>>, start: usize, init: State) -> Result<(), EvalError> {
        let leaf = self.is_leaf(start);
        x.root = self.memo_process(x, waiting, start, leaf, init)?;
        while let Some((w, edges)) = self.memo_next(x, waiting)? {
            let (state, shape) = (w.carried, w.shape as usize);
            for k in 0..edges {
                let e = &x.plan.bodies[shape][k];
                let (target, leaf) = (e.shape, e.leaf);
                let mut child = state;
                e.apply(&mut child)?;
                let out = self.memo_process(x, waiting, target, leaf, child)?;
                if x.recorded {
                    x.outcomes.push(out);
                }
            }
        }
        Ok(())
    }

    /// The next shape to expand and its number of edges, taken as the
    /// general loop takes it (largest first, cfdg's maximum shapes, a step
    /// charged and its memory given back), its node's outcomes begun when
    /// recorded; `None` when none is left to expand.
    fn memo_next<C>(&mut self, x: &mut Expansion, waiting: &mut Pending<Waiting<C>>) -> Result<Option<(Waiting<C>, usize)>, EvalError> {
        if waiting.is_empty() || self.shape_count.max(waiting.len() as u64) >= self.max_shapes {
            return Ok(None);
        }
        let Some(w) = waiting.pop() else { return Ok(None) };
        self.budget.release_memory(SHAPE_BYTES);
        self.budget.charge_step()?;
        let edges = x.plan.bodies[w.shape as usize].len();
        if x.recorded {
            self.budget.reserve_memory(4 * edges as u64)?;
            x.first[w.node as usize] = x.outcomes.len() as u32;
        }
        Ok(Some((w, edges)))
    }

    /// `process` for a compiled design: finishes a primitive or keeps a
    /// shape big enough to expand, and says which.
    fn memo_process<C: Carried>(&mut self, x: &mut Expansion, waiting: &mut Pending<Waiting<C>>, shape: usize, leaf: bool, state: State) -> Result<u32, EvalError> {
        if !state.is_finite() {
            return Err(non_finite());
        }
        if super::super::anim::dropped(&state) {
            return Ok(NONE);
        }
        if leaf {
            return self.memo_leaf(shape, &state.transform, state.tz, state.color.rgba());
        }
        self.memo_keep(x, waiting, shape, state.area(), C::of(&state))
    }

    /// Finishes primitive `shape` placed by `t` (`drawn` for a primitive,
    /// which is all a compiled design finishes), and says which it became.
    fn memo_leaf(&mut self, shape: usize, t: &Affine, z: f64, rgba: [f64; 4]) -> Result<u32, EvalError> {
        let before = self.shape_count;
        let b = super::super::frame::Bounds::of_polygon(t, &self.polygons[shape]);
        if b.valid() {
            let box_area = ((b.max_x - b.min_x) * (b.max_y - b.min_y)).abs();
            self.finish_shape(shape, t, z, rgba, b, box_area, 0)?;
        }
        Ok(match u32::try_from(before) {
            Ok(o) if self.shape_count > before && o < LEAF => LEAF | o,
            _ => NONE,
        })
    }

    /// Keeps a shape of `area` to expand when it is big enough (`process`).
    fn memo_keep<C>(&mut self, x: &mut Expansion, waiting: &mut Pending<Waiting<C>>, shape: usize, area: f64, carried: C) -> Result<u32, EvalError> {
        if !self.bounds.valid() || area * self.scale_area >= self.min_area {
            self.budget.reserve_memory(SHAPE_BYTES)?;
            self.budget.reserve_memory(0)?;
            let node = x.node(shape);
            waiting.push(area, Waiting { shape: shape as u32, node, carried });
            return Ok(if x.recorded { node } else { NONE });
        }
        Ok(NONE)
    }
}

/// The error of a shape whose state is not finite (`memo_process`).
fn non_finite() -> EvalError {
    EvalError::NonFinite { span: crate::Span::new(1, 1), what: "a shape's state".into(), value: "undefined or infinite".into() }
}

/// What a waiting shape keeps of its state.
trait Carried: Copy {
    fn of(s: &State) -> Self;
}

impl Carried for State {
    fn of(s: &State) -> Self {
        *s
    }
}

/// Only the transform: every other part of every state is the start's
/// when no edge has a term left after folding (all of them geometric).
impl Carried for Affine {
    fn of(s: &State) -> Self {
        s.transform
    }
}

/// A shape waiting to be expanded: its shape, its recorded node and its state.
#[derive(Clone, Copy)]
struct Waiting<C> {
    shape: u32,
    node: u32,
    carried: C,
}
