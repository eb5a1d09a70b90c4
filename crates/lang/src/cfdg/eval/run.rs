//! The expansion loop (`RendererImpl::run`, `processShape`,
//! `processPrimShapeSiblings`, `outputFinal`; `ASTreplacement::traverse`
//! and its loop, transform, if and switch forms), charging the [`Budget`].

use super::expr::{scalar, Scope};
use super::frame::{bounds_polygon, Bounds};
use super::tile::{Frieze, Tiling};
use super::adjust::{apply_prepared, prepare, Prepared};
use super::state::{Affine, Hsba, State};
use super::{compile, setting, terms_of, Finished, Options, Picture, Rules, Unfinished};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{self, define_seed, loop_seed, term_seed, Adjustment, Element, Grammar, Value};
use crate::core::budget::{Budget, OnLimit};
use crate::model::EvalError;
use super::FastMap as HashMap;

mod bind;
mod names;
mod chosen;
pub(crate) mod memo;
mod path;
pub(crate) use path::PathDraw;

/// Bytes accounted per unfinished or finished shape.
pub(crate) const SHAPE_BYTES: u64 = 160;
/// cfdg's fixed border in pixels (`FIXED_BORDER`).
const FIXED_BORDER: f64 = 8.0;

struct Renderer<'g> {
    rules: Rules<'g>,
    opts: Options,
    cache: HashMap<usize, std::rc::Rc<(Prepared, Rand64)>>,
    scope: Scope<'static>,
    current: Rand64,
    unfinished: super::pending::Pending,
    finished: Vec<Finished>,
    bounds: Bounds,
    scale_area: f64,
    /// Whether `finish_shape` has set `scale_area` from the bounds yet.
    scaled: bool,
    /// Whether a finished shape has a lower z than the one before it.
    unsorted: bool,
    /// The least and greatest box area of the finished shapes but fills,
    /// and whether one was NaN.
    boxes: (f64, f64, bool),
    /// Whether a path shape was finished.
    has_paths: bool,
    min_area: f64,
    fixed_border: f64,
    /// cfdg's `mFixedBorderY` (differs from x only for a frieze).
    fixed_border_y: f64,
    shape_border: f64,
    shape_count: u64,
    max_shapes: u64,
    budget: &'g mut Budget,
    polygons: [Vec<(f64, f64)>; 3],
    /// The parameters of the shape being expanded.
    params: Vec<f64>,
    /// The fixed bounds of a `CF::Size` design.
    sized: Option<Bounds>,
    /// What each finished path shape draws, by [`Finished::path`].
    paths: Vec<Vec<PathDraw>>,
    /// The design's tiling or frieze (`CF::Tile`).
    tiling: Option<Tiling>,
    /// The canvas a tiled design is drawn on (cfdg's `m_width`, `m_height`
    /// after `initBounds`).
    tile_canvas: Option<(i64, i64)>,
    /// cfdg's `mScale` as a tiled design keeps it: guessed at the first
    /// finished shape, 0 before.
    first_scale: f64,
    /// The transforms of `CF::Symmetry`: every primitive and path is
    /// finished once under each (`processPrimShape`).
    symmetry: Vec<super::state::Affine>,
    /// What each subpath draws, worked out at the first one (`path/subpath.rs`).
    subpaths: Option<std::sync::Arc<path::SubpathTypes>>,
    /// What namespaced replacements' seeds hash (`names.rs`).
    entropy_names: &'g std::collections::BTreeMap<(u32, u32, String), String>,
}

/// A replacement's prepared terms and seed, made once per replacement
/// (shared, so a lookup copies no terms).
fn cached(cache: &mut HashMap<usize, std::rc::Rc<(Prepared, Rand64)>>, key: usize, make: impl FnOnce() -> (Prepared, Rand64)) -> std::rc::Rc<(Prepared, Rand64)> {
    cache.entry(key).or_insert_with(|| std::rc::Rc::new(make())).clone()
}

/// Renders `g` as cfdg renders it with `opts`, charging `budget`: a step
/// per rule expanded and per loop iteration, memory per shape kept, a
/// primitive per shape finished (on the caller's thread: [`super::render`]
/// gives it a stack).
pub(super) fn render(g: &Grammar, opts: &Options, budget: &mut Budget) -> Result<Picture, EvalError> {
    let rules = compile(g).map_err(|e| EvalError::BadParam { name: "grammar".into(), message: e.to_string() })?;
    // Globals, in order, each xoring its name's seed in (ASTdefine::traverse at init).
    let mut scope = Scope { funcs: std::sync::Arc::new(super::func::Functions::new(g.functions.clone())), rand_static: std::sync::Arc::new(super::rand_static(g, opts.variation)), ..Scope::default() };
    scope.funcs.allow(budget.steps(), budget.limits().max_steps, budget.limits().max_depth);
    bind::push_predefined(&mut scope);
    // A still's ftime() and frame() (eval/anim.rs), before the globals use them.
    super::anim::setup(g, &mut scope)?;
    let mut current = Rand64::seeded(opts.variation.max(1) as u64);
    current.next_u64();
    // The globals are traversed with the renderer's own stream, which the
    // start shape then goes on with (RendererImpl::init, then run's
    // getInitialShape): a random global changes every draw after it
    // (arraytest1).
    let global_rand = &mut current;
    for d in &g.defines {
        if let (false, Value::Expr(e)) = (d.name.starts_with("CF::"), &d.value) {
            if bind::names_rule(e, &rules, &scope) {
                if !bind::shape_is_constant(e, &scope) {
                    global_rand.xor(define_seed(&d.name));
                }
                if let Some(v) = bind::shape_value(e, &rules, &scope, global_rand, &[])? {
                    bind::push_shape_var(&mut scope, &d.name, v);
                }
                continue;
            }
            if !super::adjust::is_constant(e) {
                global_rand.xor(define_seed(&d.name));
            }
            let mut v = Vec::new();
            super::expr::eval(e, &scope, global_rand, &mut v)?;
            scope.vars.push((d.name.clone(), v));
        } else if let (false, Value::Adjust(a)) = (d.name.starts_with("CF::"), &d.value) {
            let constant = super::modval::is_constant(a);
            if !constant {
                global_rand.xor(define_seed(&d.name));
            }
            let v = super::modval::value_of(a, &scope, global_rand, constant)?;
            super::shapeval::push_adjust(&mut scope, &d.name, v);
        }
    }
    scope.globals = Some(scope.vars.len());
    budget.charge_steps(scope.funcs.take_calls())?;
    // RendererImpl::init: CF::MaxNatural must be ≥ 1 and < 2⁵³; CF::Impure lifts it.
    if let Some(m) = setting(g, "CF::MaxNatural", &scope)? {
        if !(1.0..9_007_199_254_740_992.0).contains(&m) {
            return Err(EvalError::BadParam { name: "CF::MaxNatural".into(), message: "must be >= 1 and < 9007199254740992".into() });
        }
        scope.max_natural = m;
    }
    if setting(g, "CF::Impure", &scope)?.is_some_and(|v| v != 0.0) {
        scope.max_natural = f64::INFINITY;
    }
    let min_size = setting(g, "CF::MinimumSize", &scope)?.unwrap_or(opts.min_size);
    let min_size = if min_size > 0.0 { min_size } else { 0.3 };
    let mut max_shapes = setting(g, "CF::MaxShapes", &scope)?.map(|v| v.max(1.0) as u64).unwrap_or(opts.max_shapes);
    if max_shapes == 0 {
        max_shapes = 500_000_000;
    }
    let border = opts.border;
    // RendererImpl::init: CF::BorderFixed and CF::BorderDynamic override the border mode's.
    let fixed_border = setting(g, "CF::BorderFixed", &scope)?.unwrap_or(FIXED_BORDER * if border <= 1.0 { border } else { 1.0 });
    let fixed_border = if 2.0 * fixed_border.abs().floor() >= f64::from(opts.width.min(opts.height)) { 0.0 } else { fixed_border };
    let shape_border = setting(g, "CF::BorderDynamic", &scope)?.unwrap_or(if border <= 1.0 { 1.0 } else { border });
    let shape_border = if shape_border <= 0.0 { 1.0 } else { shape_border };
    let background = background(g, &scope)?;
    let sized = sized(g, &scope)?;
    let tiling = super::tile::tiling(g, &scope)?;
    let mut r = Renderer {
        rules,
        opts: *opts,
        cache: HashMap::default(),
        scope,
        current,
        unfinished: Default::default(),
        finished: Vec::new(),
        bounds: Bounds::default(),
        scale_area: 0.0,
        scaled: false,
        unsorted: false,
        boxes: (f64::INFINITY, f64::NEG_INFINITY, false),
        has_paths: false,
        min_area: min_size * min_size,
        fixed_border,
        fixed_border_y: fixed_border,
        shape_border,
        shape_count: 0,
        max_shapes,
        budget,
        polygons: [bounds_polygon(0), bounds_polygon(1), bounds_polygon(2)],
        params: Vec::new(),
        sized: None,
        paths: Vec::new(),
        tiling,
        tile_canvas: None,
        first_scale: 0.0,
        symmetry: Vec::new(),
        subpaths: None,
        entropy_names: &g.entropy_names,
    };
    r.symmetry = super::symmetry::symmetry(g, &r.scope, r.tiling.as_ref(), r.budget)?;
    // CF::Size fixes the bounds (centred on the origin) and the scale, and
    // offsets the start shape (RendererImpl::initBounds, getInitialShape).
    let mut offset = (0.0, 0.0);
    if let Some((w, h, x, y)) = sized {
        r.fixed_border = 0.0;
        r.fixed_border_y = 0.0;
        r.shape_border = 0.0;
        r.bounds = Bounds { min_x: -w / 2.0, max_x: w / 2.0, min_y: -h / 2.0, max_y: h / 2.0 };
        let (scale, ..) = r.bounds.compute_scale_exact(i64::from(opts.width), i64::from(opts.height), 0.0, 0.0, true);
        r.scale_area = scale * scale;
        r.sized = Some(r.bounds);
        offset = (x, y);
    }
    // A tiled design's bounds are its tile, without borders; a frieze's
    // repeating axis is the tile's and has no fixed border (initBounds).
    if let Some(t) = &tiling {
        let (tx, ty) = t.size;
        match t.frieze {
            Frieze::None => {
                r.fixed_border = 0.0;
                r.fixed_border_y = 0.0;
                r.shape_border = 0.0;
                r.bounds = Bounds { min_x: -tx / 2.0, max_x: tx / 2.0, min_y: -ty / 2.0, max_y: ty / 2.0 };
                let (scale, w, h, _) = r.bounds.compute_scale_exact(i64::from(opts.width), i64::from(opts.height), 0.0, 0.0, true);
                r.scale_area = scale * scale;
                r.tile_canvas = Some((w, h));
            }
            Frieze::X => r.fixed_border = 0.0,
            Frieze::Y => r.fixed_border_y = 0.0,
        }
        offset = (offset.0 + t.offset.0, offset.1 + t.offset.1);
    }
    let start = g.start.as_ref().ok_or_else(|| EvalError::BadParam { name: "startshape".into(), message: "the design has no startshape".into() })?;
    // The start shape may be a global shape variable (stackargtest).
    let (start_shape, bound) = r.target_of(start)?;
    let mut init = State::initial();
    // The start shape's arguments are evaluated before its seed is mixed in (ASTreplacement::replace).
    let chosen = bound.is_some();
    let mut start_params = bound.unwrap_or_default();
    if let (Some(a), false) = (&start.args, chosen) {
        super::expr::eval(a, &r.scope, &mut r.current, &mut start_params)?;
    }
    let seed = if start.adjust.terms.is_empty() && !g.start_from_setting {
        // A start shape without adjustment has an empty modification, seeded with the default seed.
        let mut s = Rand64::default();
        let mut i = 0;
        s.xor_bytes(start.shape.as_bytes(), &mut i);
        s
    } else {
        // The start shape's adjustment is hashed in its own modification
        // (from the default seed), grabbed into the start replacement's
        // (xored with the default seed), then the name is hashed on
        // (CFDGImpl's mInitShape, ASTmodification::grab).
        let mut s = Rand64::default();
        let mut i = 0;
        crate::cfdg::syntax::adjust_entropy(&start.adjust, &mut s, &mut i);
        s.xor(Rand64::default());
        s.xor_bytes(&crate::cfdg::syntax::start_name_entropy(start, g.start_from_setting), &mut i);
        s
    };
    r.current.xor(seed);
    r.current.next_u64();
    apply_prepared(&prepare(&start.adjust), &mut init, &r.scope, &mut r.current)?;
    init.transform.tx += offset.0;
    init.transform.ty += offset.1;
    init.seed = r.current;
    // A context-free design expands by its compiled bodies (run/memo.rs).
    let plan = if opts.memo && !chosen && start.args.is_none() { r.memo_plan(start_shape) } else { None };
    let mut memo = plan.map(|plan| memo::Expansion { plan, recorded: opts.record, ..Default::default() });
    let expanded = match memo.as_mut() {
        Some(x) => r.memo_expand(x, start_shape, init),
        None => r.expand(start_shape, init, start_params),
    };
    let truncated = match expanded {
        Ok(()) => None,
        Err(EvalError::Limit(e)) if opts.on_limit == OnLimit::Truncate => Some(e),
        Err(e) => return Err(e),
    };
    Ok(Picture { truncated, memo: memo.filter(|x| x.recorded).map(std::sync::Arc::new), ..r.finish(background) })
}

impl Renderer<'_> {
    /// Expands the start shape, then the largest unfinished shape first,
    /// until none is left or cfdg's maximum shapes is reached.
    fn expand(&mut self, start_shape: usize, init: State, start_params: Vec<f64>) -> Result<(), EvalError> {
        let r = self;
        r.process(start_shape, init, start_params)?;
        while !r.unfinished.is_empty() {
            if r.shape_count.max(r.unfinished.len() as u64) >= r.max_shapes {
                break;
            }
            let Some(mut s) = r.unfinished.pop() else { break };
            r.budget.release_memory(SHAPE_BYTES + 8 * s.params.len() as u64);
            r.budget.charge_step()?;
            let choice = s.state.seed.next_double();
            let rules = &r.rules.by_shape[s.shape];
            let Some(&(_, body)) = rules.iter().find(|(w, _)| *w >= choice).or(rules.last()) else { continue };
            r.current = s.state.seed;
            let depth = r.scope.vars.len();
            r.bind_params(s.shape, &s.params);
            r.params = std::mem::take(&mut s.params);
            r.body(body, &s.state)?;
            r.scope.vars.truncate(depth);
            r.charge_calls()?;
        }
        r.charge_calls()
    }
}

/// The `CF::Size` (or 2.x `size { }`) adjustment's size and offset.
fn sized(g: &Grammar, scope: &Scope) -> Result<Option<(f64, f64, f64, f64)>, EvalError> {
    let Some(d) = g.defines.iter().rev().find(|d| d.name == "CF::Size") else { return Ok(None) };
    let Value::Adjust(a) = &d.value else { return Ok(None) };
    let mut s = State::initial();
    let mut rand = Rand64::default();
    super::adjust::apply(&terms_of(a), &mut s, scope, &mut rand)?;
    let t = s.transform;
    if t.shx != 0.0 || t.shy != 0.0 || !(t.sx > 0.0 && t.sy > 0.0) {
        return Err(EvalError::BadParam { name: "CF::Size".into(), message: format!("{}:{}: a size must be positive and not rotated or skewed", d.span.line, d.span.column) });
    }
    Ok(Some((t.sx, t.sy, t.tx, t.ty)))
}

fn background(g: &Grammar, scope: &Scope) -> Result<[f64; 4], EvalError> {
    let adj = g.background.as_ref().or_else(|| {
        g.defines.iter().rev().find(|d| d.name == "CF::Background").and_then(|d| match &d.value {
            Value::Adjust(a) => Some(a),
            _ => None,
        })
    });
    let mut s = State::initial();
    s.color = Hsba { h: 0.0, s: 0.0, b: 1.0, a: 1.0 };
    if let Some(a) = adj {
        let mut rand = Rand64::default();
        super::adjust::apply(&terms_of(a), &mut s, scope, &mut rand)?;
    }
    Ok(s.color.rgba())
}

impl Renderer<'_> {
    fn process(&mut self, shape: usize, state: State, params: Vec<f64>) -> Result<(), EvalError> {
        if !state.is_finite() {
            return Err(EvalError::NonFinite { span: crate::Span::new(1, 1), what: "a shape's state".into(), value: "undefined or infinite".into() });
        }
        if super::anim::dropped(&state) {
            return Ok(());
        }
        let drawn = self.rules.is_path[shape] || (shape < 3 && self.rules.by_shape[shape].is_empty());
        if drawn && !self.symmetry.is_empty() {
            // One copy per symmetry transform, each finished in turn (processPrimShape).
            for k in 0..self.symmetry.len() {
                self.budget.charge_step()?;
                let mut copy = state;
                copy.transform.multiply(&self.symmetry[k]);
                self.drawn(shape, copy, params.clone())?;
            }
            return Ok(());
        }
        if drawn {
            return self.drawn(shape, state, params);
        }
        if shape >= 3 || !self.rules.by_shape[shape].is_empty() {
            let area = state.area();
            if !self.bounds.valid() || area * self.scale_area >= self.min_area {
                self.budget.reserve_memory(SHAPE_BYTES)?;
                self.budget.reserve_memory(8 * params.len() as u64)?;
                self.unfinished.push(area, Unfinished { shape, state, params });
            }
            return Ok(());
        }
        Ok(())
    }

    /// Finishes a primitive or path shape.
    fn drawn(&mut self, shape: usize, state: State, params: Vec<f64>) -> Result<(), EvalError> {
        if self.rules.is_path[shape] {
            return self.path_shape(shape, state, params);
        }
        if self.tile_canvas.is_some() {
            self.guess_scale(&state);
        }
        let b = Bounds::of_polygon(&state.transform, &self.polygons[shape]);
        if !b.valid() {
            return Ok(());
        }
        let box_area = ((b.max_x - b.min_x) * (b.max_y - b.min_y)).abs();
        self.finish_shape(shape, &state.transform, state.tz, state.color.rgba(), b, box_area, 0)
    }

    /// cfdg's `mScale` of a tiled design: guessed from the first finished
    /// shape, `(m_width + m_height) / sqrt|det|` on the tile's canvas
    /// (`processPrimShapeSiblings`), then kept.
    fn guess_scale(&mut self, state: &State) -> f64 {
        if self.first_scale == 0.0 {
            let (w, h) = self.tile_canvas.unwrap_or((i64::from(self.opts.width), i64::from(self.opts.height)));
            self.first_scale = (w + h) as f64 / state.transform.determinant().abs().sqrt();
        }
        self.first_scale
    }

    /// Keeps a finished shape of bounds `b` (unless a sized design drops it
    /// off the canvas), growing the picture's bounds and scale
    /// (`processPrimShapeSiblings`).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn finish_shape(&mut self, kind: usize, transform: &Affine, z: f64, rgba: [f64; 4], b: Bounds, box_area: f64, path: usize) -> Result<(), EvalError> {
        match &self.sized {
            // Off-canvas shapes are dropped from a sized design.
            Some(fixed) => {
                if b.min_x > fixed.max_x || b.max_x < fixed.min_x || b.min_y > fixed.max_y || b.max_y < fixed.min_y {
                    return Ok(());
                }
            }
            None if self.tile_canvas.is_some() => {}
            None => {
                let before = self.bounds;
                self.bounds.merge(&b.dilate(self.shape_border));
                if let Some(t) = &self.tiling {
                    // A frieze's repeating axis keeps the tile's extent.
                    match t.frieze {
                        Frieze::X => (self.bounds.min_x, self.bounds.max_x) = (-t.size.0 / 2.0, t.size.0 / 2.0),
                        Frieze::Y => (self.bounds.min_y, self.bounds.max_y) = (-t.size.1 / 2.0, t.size.1 / 2.0),
                        Frieze::None => {}
                    }
                }
                // The scale is a function of the bounds alone (the canvas and
                // borders are fixed for the run), and most shapes land inside
                // the bounds so far: the same bounds keep the same scale.
                if self.bounds != before || !self.scaled {
                    let (scale, ..) = self.bounds.compute_scale(i64::from(self.opts.width), i64::from(self.opts.height), self.fixed_border, self.fixed_border_y);
                    self.scale_area = scale * scale;
                    self.scaled = true;
                }
            }
        }
        self.shape_count += 1;
        self.budget.charge_primitive(2)?;
        self.budget.reserve_memory(SHAPE_BYTES)?;
        self.keep(Finished { kind, transform: *transform, z, rgba, order: self.shape_count, box_area, path, bounds: b });
        Ok(())
    }

    /// Appends a finished shape; a grown array asks for huge pages
    /// (`core::hugepages`: fresh memory filled front to back).
    fn keep(&mut self, f: Finished) {
        // What `finish` would otherwise learn by reading every shape again:
        // whether they need sorting, and their least and greatest box.
        if self.finished.last().is_some_and(|last| last.z.total_cmp(&f.z).is_gt()) {
            self.unsorted = true;
        }
        self.has_paths |= f.kind == 3;
        if f.kind != 4 {
            let b = f.box_area;
            (self.boxes.0, self.boxes.1, self.boxes.2) = (self.boxes.0.min(b), self.boxes.1.max(b), self.boxes.2 | b.is_nan());
        }
        let room = self.finished.capacity();
        self.finished.push(f);
        if self.finished.capacity() != room {
            crate::core::hugepages::advise(&mut self.finished);
        }
    }

    fn seeded_terms(&mut self, adj: &Adjustment, shape: &str, args: Option<&syntax::Expr>) -> std::rc::Rc<(Prepared, Rand64)> {
        let key = adj as *const Adjustment as usize;
        let scope = &self.scope;
        cached(&mut self.cache, key, || {
            let mut seed = term_seed(adj, shape, args);
            super::modval::fold_seeds(adj, scope, &mut seed);
            (prepare(adj), seed)
        })
    }

    fn body(&mut self, body: &[Element], parent: &State) -> Result<(), EvalError> {
        let depth = self.scope.vars.len();
        for e in body {
            self.element(e, parent)?;
        }
        self.scope.vars.truncate(depth);
        Ok(())
    }

    fn element(&mut self, e: &Element, parent: &State) -> Result<(), EvalError> {
        match e {
            Element::Replace(rep) if rep.shape == super::FILL && !self.rules.index.contains_key(super::FILL) => {
                // processPrimShapeSiblings for fillType: no bounds, never
                // copied by symmetry or tiles, always drawn; a shape all the same.
                let prepared = self.seeded_terms(&rep.adjust, self.entropy_name(rep), rep.args.as_ref());
                let (terms, seed) = (&prepared.0, prepared.1);
                let mut child = *parent;
                self.current.xor(seed);
                self.current.next_u64();
                apply_prepared(&terms, &mut child, &self.scope, &mut self.current)?;
                if !child.is_finite() {
                    return Err(EvalError::NonFinite { span: rep.span, what: "a shape's state".into(), value: "undefined or infinite".into() });
                }
                self.shape_count += 1;
                self.budget.charge_primitive(2)?;
                self.budget.reserve_memory(SHAPE_BYTES)?;
                self.keep(Finished { kind: 4, transform: child.transform, z: child.tz, rgba: child.color.rgba(), order: self.shape_count, box_area: 1.0, path: 0, bounds: Bounds::default() });
                Ok(())
            }
            Element::Replace(rep) => {
                let (shape, bound) = self.target_of(rep)?;
                let prepared = self.seeded_terms(&rep.adjust, self.entropy_name(rep), rep.args.as_ref());
                let (terms, seed) = (&prepared.0, prepared.1);
                let mut params = Vec::new();
                let wanted: usize = self.rules.sizes[shape].len();
                match (&rep.args, bound) {
                    (_, Some(b)) => params = b,
                    (Some(syntax::Expr::Var(v, _)), None) if v == syntax::REUSE => {
                        params = self.params.clone();
                        if super::shapeval::split(&self.rules.sizes[shape], &params).is_none() {
                            return Err(EvalError::BadParam { name: rep.shape.clone(), message: format!("{}:{}: `(=)` needs a parent with the same parameters", rep.span.line, rep.span.column) });
                        }
                    }
                    (Some(a), None) => super::expr::eval(a, &self.scope, &mut self.current, &mut params)?,
                    (None, None) => {}
                }
                if super::shapeval::split(&self.rules.sizes[shape], &params).is_none() {
                    return Err(EvalError::BadParam { name: rep.shape.clone(), message: format!("{}:{}: shape `{}` takes {wanted} parameters, given {} numbers that do not fit them", rep.span.line, rep.span.column, rep.shape, params.len()) });
                }
                let mut child = *parent;
                self.current.xor(seed);
                self.current.next_u64();
                apply_prepared(&terms, &mut child, &self.scope, &mut self.current)?;
                child.seed = self.current;
                child.seed.next_u64();
                self.process(shape, child, params)
            }
            Element::Loop(l) => {
                let (terms, var, start, end, step) = self.loop_setup(l)?;
                let mut child = *parent;
                let mut index = start;
                self.scope.vars.push((var, vec![index]));
                let slot = self.scope.vars.len() - 1;
                loop {
                    if (step > 0.0 && index >= end) || (step < 0.0 && index <= end) {
                        break;
                    }
                    self.budget.charge_step()?;
                    self.scope.vars[slot].1[0] = index;
                    self.body(&l.body, &child)?;
                    apply_prepared(&terms, &mut child, &self.scope, &mut self.current)?;
                    index += step;
                }
                self.scope.vars[slot].1[0] = index;
                self.body(&l.finally, &child)?;
                self.scope.vars.truncate(slot);
                Ok(())
            }
            Element::If { cond, then, otherwise, .. } => {
                let c = scalar(cond, &self.scope, &mut self.current)?;
                self.body(if c != 0.0 { then } else { otherwise }, parent)
            }
            Element::Switch { selector, cases, otherwise, .. } => {
                let v = scalar(selector, &self.scope, &mut self.current)?.floor();
                let body = cases.iter().find(|(ranges, _)| ranges.iter().any(|&(lo, hi)| v >= lo as f64 && v <= hi as f64)).map(|(_, b)| b).unwrap_or(otherwise);
                self.body(body, parent)
            }
            Element::Transform { clone, symmetry, body, .. } if !symmetry.is_empty() => {
                // ASTtransform::traverse: the list is built first (drawing
                // on the stream), then one copy per non-geometric adjustment
                // and one per transform, premultiplied.
                let (mods, syms) = super::symmetry::list(symmetry, &self.scope, &super::state::Affine::default(), false, &mut self.current, self.budget)?;
                let clone_seed = self.current;
                for k in 0..mods.len() + syms.len() {
                    self.budget.charge_step()?;
                    let mut child = *parent;
                    match mods.get(k) {
                        Some(adj) => apply_prepared(&prepare(adj), &mut child, &self.scope, &mut self.current)?,
                        None => child.transform.premultiply(&syms[k - mods.len()]),
                    }
                    self.current.next_u64();
                    let depth = self.scope.vars.len();
                    for e in body {
                        if *clone {
                            self.current = clone_seed;
                        }
                        self.element(e, &child)?;
                    }
                    self.scope.vars.truncate(depth);
                }
                Ok(())
            }
            Element::Transform { clone, adjusts, body, .. } => {
                let clone_seed = self.current;
                for adj in adjusts {
                    let mut child = *parent;
                    apply_prepared(&prepare(adj), &mut child, &self.scope, &mut self.current)?;
                    self.current.next_u64();
                    let depth = self.scope.vars.len();
                    for e in body {
                        if *clone {
                            self.current = clone_seed;
                        }
                        self.element(e, &child)?;
                    }
                    self.scope.vars.truncate(depth);
                }
                Ok(())
            }
            // The parser allows these only in a path, which `path_shape` walks.
            Element::PathOp(_) | Element::PathCommand(_) => Ok(()),
            Element::Define(d) if matches!(&d.value, Value::Expr(e) if bind::names_rule(e, &self.rules, &self.scope)) => {
                let Value::Expr(e) = &d.value else { return Ok(()) };
                if !bind::shape_is_constant(e, &self.scope) {
                    self.current.xor(define_seed(&d.name));
                }
                if let Some(v) = bind::shape_value(e, &self.rules, &self.scope, &mut self.current, &self.params)? {
                    bind::push_shape_var(&mut self.scope, &d.name, v);
                }
                Ok(())
            }
            Element::Define(d) => {
                // A constant definition is folded at compile time and never
                // traversed (ASTdefine::traverse returns for non-stack defines).
                let constant = match &d.value {
                    Value::Expr(e) => super::adjust::is_constant(e),
                    Value::Adjust(a) => super::modval::is_constant(a),
                    Value::Shape(_) => true,
                    // Symmetry lists are settings (`CF::Symmetry`), read before the run.
                    Value::Symmetry(_) => false,
                };
                if !constant {
                    self.current.xor(define_seed(&d.name));
                }
                match &d.value {
                    Value::Expr(e) => {
                        let mut v = Vec::new();
                        super::expr::eval(e, &self.scope, &mut self.current, &mut v)?;
                        self.scope.vars.push((d.name.clone(), v));
                    }
                    Value::Adjust(a) => {
                        let v = super::modval::value_of(a, &self.scope, &mut self.current, constant)?;
                        super::shapeval::push_adjust(&mut self.scope, &d.name, v);
                    }
                    Value::Shape(_) | Value::Symmetry(_) => {}
                }
                Ok(())
            }
        }
    }

    /// A loop's adjustment, index name and range, its seed mixed in (`ASTloop::setupLoop`).
    fn loop_setup(&mut self, l: &syntax::Loop) -> Result<(Prepared, String, f64, f64, f64), EvalError> {
        let key = l as *const syntax::Loop as usize;
        let var = l.var.clone().unwrap_or_else(|| "~~inaccessiblevar~~".into());
        let (terms, seed) = cached(&mut self.cache, key, || (prepare(&l.adjust), loop_seed(&l.adjust, &var, &l.args, l.v2))).as_ref().clone();
        self.current.xor(seed);
        let mut a = Vec::new();
        super::expr::eval(&l.args, &self.scope, &mut self.current, &mut a)?;
        let (start, end, step) = match a.as_slice() {
            [n] => (0.0, *n, 1.0),
            [s, e] => (*s, *e, 1.0),
            [s, e, st] => (*s, *e, *st),
            _ => return Err(EvalError::BadIteration { span: l.span, value: format!("{} loop arguments", a.len()) }),
        };
        if !(start.is_finite() && end.is_finite() && step.is_finite()) || step == 0.0 {
            return Err(EvalError::BadIteration { span: l.span, value: format!("{start}, {end}, {step}") });
        }
        Ok((terms, var, start, end, step))
    }

    /// Sorts, frames and drops what cfdg would not draw (`outputFinal`, `drawShape`).
    fn finish(mut self, background: [f64; 4]) -> Picture {
        // A tiled design's canvas was fixed by its tile; a frieze's is the
        // final bounds fitted exactly (the end of RendererImpl::run), and
        // the output is framed again on that canvas (outputFinal).
        let (mut cw, mut ch) = (i64::from(self.opts.width), i64::from(self.opts.height));
        let exact = self.sized.is_some() || self.tiling.is_some();
        if let Some(c) = self.tile_canvas {
            (cw, ch) = c;
        } else if self.tiling.is_some() || self.sized.is_some() {
            let (_, w, h, _) = self.bounds.compute_scale_exact(cw, ch, self.fixed_border, self.fixed_border_y, true);
            (cw, ch) = (w, h);
        }
        let (scale, w, h, to_pixels) = self.bounds.compute_scale_exact(cw, ch, self.fixed_border, self.fixed_border_y, exact);
        let area = scale * scale;
        let finished = self.finished.len() as u64;
        // Finished in order, so sorted already when no z goes down (every
        // shape of most designs is at z 0; `keep` notes a z going down): a
        // stable sort would still copy the whole array through a buffer
        // half its size.
        if self.unsorted {
            self.finished.sort_by(|a, b| a.z.total_cmp(&b.z).then(a.order.cmp(&b.order)));
        }
        let min_area = self.min_area;
        // Every shape passes when the least and the greatest box do (a box
        // times the scale is monotone in the box): no pass over them all.
        let (least, most, nan) = self.boxes;
        let all_pass = !nan && (least * area).is_finite() && least * area >= min_area && (most * area).is_finite();
        self.finished.retain(|s| {
            if all_pass || s.kind == 4 {
                return true;
            }
            if s.kind == 4 {
                return true;
            }
            let a = s.box_area * area;
            a.is_finite() && a >= min_area
        });
        self.budget.release_memory(SHAPE_BYTES * (self.unfinished.len() as u64));
        Picture {
            shapes: self.finished,
            width: w.clamp(0, u32::MAX as i64) as u32,
            height: h.clamp(0, u32::MAX as i64) as u32,
            // A sized design's canvas is its size fitted exactly, as a tile's
            // (RendererImpl::initBounds rescales the output for both).
            canvas_width: if self.tiling.is_some() || self.sized.is_some() { cw.clamp(0, u32::MAX as i64) as u32 } else { self.opts.width },
            canvas_height: if self.tiling.is_some() || self.sized.is_some() { ch.clamp(0, u32::MAX as i64) as u32 } else { self.opts.height },
            to_pixels,
            background,
            variation: self.opts.variation,
            finished,
            paths: self.paths,
            tiling: self.tiling.map(|t| (t, scale)),
            truncated: None,
            memo: None,
            has_paths: self.has_paths,
        }
    }
}
