//! Depth-first evaluation of the IR into a [`Scene`], with an explicit stack.
//!
//! No Rust recursion follows the grammar: every pending piece of work is a
//! [`Task`] on a heap-allocated stack whose peak size is charged to the
//! memory budget. Each call's random stream key is derived from its parent's
//! key, its call site and its iteration index (see [`StreamKey`]), so results
//! do not depend on the order in which work is done.

use crate::core::budget::{Budget, OnLimit};
use crate::model::animation::{looped, Bone, CameraPath, Rig, Timeline, BONE_BYTES};
use crate::core::frame::Frame;
use crate::core::rng::StreamKey;
use crate::model::scene::{
    FreeVertex, Instance, LinePoint, Polyline, Scene, ShapeInstance, FREE_VERTEX_BYTES, INSTANCE_BYTES, LINE_POINT_BYTES, SHAPE_INSTANCE_BYTES,
};
use crate::model::{Downstream, EvalError};
use crate::geom::{primitives, sweep};
use crate::lang::expr::{Expr, ExprEnv};
use crate::lang::ir::{
    Adjust, AdjustOp, Axis, GroupId, Item, Iterate, LineOp, PrimitiveKind, Program, Rule, RuleGroup, RuleTransform, Selector, Target,
};
use std::collections::HashMap;
use std::rc::Rc;
use crate::core::Span;
use glam::{DQuat, DVec3};

/// A frame change plus a colour change: the effect of one adjustment list.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Delta {
    frame: Frame,
    colour: [f64; 4],
}

impl Delta {
    const IDENTITY: Delta = Delta { frame: Frame::IDENTITY, colour: [0.0; 4] };
}

/// The state a piece of work runs in.
#[derive(Debug, Clone, Copy)]
struct Ctx {
    frame: Frame,
    /// Colour as offsets: RGB start at 0 (black), alpha is 1 + offset (seed 000 L1249).
    colour: [f64; 4],
    depth: u32,
    key: StreamKey,
    /// The animation bone the work belongs to (0: none; see [`Rig`]).
    bone: u32,
    /// The namespace of the call that made this context (its pen and
    /// continuation point; 0 is the global namespace).
    ns: u32,
}

impl Ctx {
    fn apply(&self, d: &Delta) -> (Frame, [f64; 4]) {
        let mut c = self.colour;
        for (a, b) in c.iter_mut().zip(d.colour) {
            *a += b;
        }
        (self.frame.then(&d.frame), c)
    }
}

/// Pending work.
enum Task<'p> {
    /// Run `items[next..]` in order, each from `ctx`.
    Items { items: &'p [Item], next: usize, ctx: Ctx },
    /// Produce copies `k..=count` of an iterator body; `current` is copy k's frame and colour.
    Copies { it: &'p Iterate, k: u64, count: u64, step: Delta, current: Ctx, base_key: StreamKey },
    /// Run a convolved rule's body once per path frame, from `frames[i..]`.
    Convolve { body: &'p [Item], frames: Rc<Vec<Frame>>, i: usize, ctx: Ctx },
}

/// Bytes charged per stack slot (the task enum is at most this big).
const TASK_BYTES: u64 = std::mem::size_of::<Task<'static>>() as u64;

/// Expression environment for one invocation: bound parameters plus the invocation's stream.
struct Env<'a> {
    params: &'a [f64],
    key: StreamKey,
    /// Position of the current frame, for functions of x, y, z.
    pos: DVec3,
}

impl ExprEnv for Env<'_> {
    fn param(&self, index: u32) -> f64 {
        self.params.get(index as usize).copied().unwrap_or(f64::NAN)
    }
    fn rand(&mut self, site: u32) -> f64 {
        self.key.uniform(site)
    }
    fn coord(&self, axis: u8) -> f64 {
        self.pos.to_array().get(usize::from(axis)).copied().unwrap_or(f64::NAN)
    }
}

/// Evaluates one number and rejects NaN and infinities with the adjustment's position.
fn finite(e: &Expr, env: &mut Env, span: Span, what: &str) -> Result<f64, EvalError> {
    let v = e.eval(env);
    if v.is_finite() {
        Ok(v)
    } else {
        Err(EvalError::NonFinite { span, what: what.to_string(), value: v.to_string() })
    }
}

/// Computes the combined effect of an adjustment list, each argument divided by `divisor`
/// (an iterator's `/n`; scale becomes k^(1/n) so that n steps multiply by k).
fn eval_adjust(adjust: &[Adjust], env: &mut Env, divisor: f64) -> Result<Delta, EvalError> {
    let mut d = Delta::IDENTITY;
    for a in adjust {
        let op = match &a.op {
            AdjustOp::Translate([x, y, z]) => {
                let v = DVec3::new(
                    finite(x, env, a.span, "translation")?,
                    finite(y, env, a.span, "translation")?,
                    finite(z, env, a.span, "translation")?,
                );
                Frame::from_translation(v / divisor)
            }
            AdjustOp::Rotate { axis, angle } => {
                let t = finite(angle, env, a.span, "angle")? / divisor;
                Frame::from_rotation(match axis {
                    Axis::X => DQuat::from_rotation_x(t),
                    Axis::Y => DQuat::from_rotation_y(t),
                    Axis::Z => DQuat::from_rotation_z(t),
                })
            }
            AdjustOp::Scale(k) => {
                let k = finite(k, env, a.span, "scale")?;
                let k = if divisor == 1.0 { k } else { k.signum() * libm::pow(k.abs(), 1.0 / divisor) };
                Frame::from_scale(k)
            }
            AdjustOp::Reflect([x, y, z]) => Frame::reflection(DVec3::new(
                finite(x, env, a.span, "reflection normal")?,
                finite(y, env, a.span, "reflection normal")?,
                finite(z, env, a.span, "reflection normal")?,
            )),
            AdjustOp::Colour { channel, delta } => {
                let v = finite(delta, env, a.span, "colour")? / divisor;
                if let Some(c) = d.colour.get_mut(usize::from(*channel)) {
                    *c += v;
                }
                continue;
            }
        };
        d.frame = d.frame.then(&op);
        if !d.frame.is_finite() {
            return Err(EvalError::NonFinite { span: a.span, what: "transform".into(), value: "overflow".into() });
        }
    }
    Ok(d)
}

/// Everything fixed for one evaluation: the program, bound parameters, precomputed deltas.
struct Evaluator<'p> {
    program: &'p Program,
    params: &'p [f64],
    /// Deltas of call sites whose adjustments contain no `rand()`, indexed by site.
    fixed: Vec<Option<Delta>>,
    /// Cumulative weights per group, for weighted selection.
    cumulative: Vec<Vec<f64>>,
    /// Triangles per primitive kind at the requested detail.
    tris: [u64; 9],
    /// Bytes later stages need per primitive of each kind.
    downstream: [u64; 9],
    cost: Downstream,
    detail: u32,
    maxiter: u64,
    /// Sampling of transform rules and the camera.
    timeline: Timeline,
}

/// Evaluation slot reserved for rule selection (never a `rand()` site).
const SELECT_SLOT: u32 = u32::MAX;
/// Stream slot for the copies of a convolved rule.
const CONVOLVE_SLOT: u32 = u32::MAX - 1;
/// Stream slot for path and profile rules.
const CAPTURE_SLOT: u32 = u32::MAX - 2;

impl<'p> Evaluator<'p> {
    fn new(program: &'p Program, params: &'p [f64], options: &EvalOptions) -> Result<Self, EvalError> {
        let detail = options.detail;
        let mut fixed = vec![None; program.site_count as usize];
        for g in &program.groups {
            for r in &g.rules {
                collect_fixed(&r.body, params, &mut fixed)?;
            }
        }
        let cumulative = program
            .groups
            .iter()
            .map(|g| {
                let mut acc = 0.0;
                g.rules.iter().map(|r| {
                    acc += r.weight.max(0.0);
                    acc
                }).collect()
            })
            .collect();
        let mut tris = [0u64; 9];
        for k in PrimitiveKind::ALL {
            tris[k as usize] = primitives::triangle_count(k, detail);
        }
        Ok(Evaluator {
            program,
            params,
            fixed,
            cumulative,
            tris,
            downstream: PrimitiveKind::ALL.map(|k| {
                options.downstream.bytes(primitives::vertex_count(k, detail), primitives::triangle_count(k, detail))
            }),
            cost: options.downstream,
            detail,
            maxiter: program.directives.maxiter.unwrap_or(u64::MAX),
            timeline: Timeline::new(program.directives.fps, program.directives.duration),
        })
    }

    fn delta(&self, adjust: &[Adjust], site: u32, key: StreamKey) -> Result<Delta, EvalError> {
        if let Some(Some(d)) = self.fixed.get(site as usize) {
            return Ok(*d);
        }
        eval_adjust(adjust, &mut Env { params: self.params, key, pos: DVec3::ZERO }, 1.0)
    }
}

/// Precomputes the deltas of every call whose adjustments are deterministic.
fn collect_fixed(items: &[Item], params: &[f64], fixed: &mut [Option<Delta>]) -> Result<(), EvalError> {
    // Iterative walk: bodies can be deeply nested blocks.
    let mut pending: Vec<&[Item]> = vec![items];
    while let Some(items) = pending.pop() {
        for item in items {
            match item {
                Item::Call(c) => {
                    if c.adjust.iter().all(|a| adjust_is_deterministic(&a.op)) {
                        let d = eval_adjust(&c.adjust, &mut Env { params, key: StreamKey(0), pos: DVec3::ZERO }, 1.0)?;
                        if let Some(slot) = fixed.get_mut(c.site as usize) {
                            *slot = Some(d);
                        }
                    }
                }
                Item::Block(b) => pending.push(b),
                Item::Iterate(it) => pending.push(std::slice::from_ref(&*it.body)),
            }
        }
    }
    Ok(())
}

fn adjust_is_deterministic(op: &AdjustOp) -> bool {
    match op {
        AdjustOp::Translate(v) | AdjustOp::Reflect(v) => v.iter().all(Expr::is_deterministic),
        AdjustOp::Rotate { angle, .. } => angle.is_deterministic(),
        AdjustOp::Scale(k) => k.is_deterministic(),
        AdjustOp::Colour { delta, .. } => delta.is_deterministic(),
    }
}

/// Turns `point`'s profile orthogonal to the segment from the line's last point
/// (SLINETO, with the shortest-arc rotation of eq 3.29 as corrected in the
/// seed notes). A line's first point is turned too, so its first segment is straight.
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

/// The frame at `w` ∈ [0, 1] of a `BLENDTO` from `a` to `b` (seed 000 eqs
/// 4.15–4.21, read as the seed notes correct them): positions follow a
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

/// Options for one evaluation that do not come from the source.
#[derive(Debug, Clone, PartialEq)]
pub struct EvalOptions {
    /// The seed; when `None`, the grammar's `randseed`, else 0.
    pub seed: Option<u64>,
    /// Tessellation detail, used to count triangles against the budget.
    pub detail: u32,
    /// Fail or truncate when a limit runs out.
    pub on_limit: OnLimit,
    /// Bytes that later stages (mesh buffers, encoded output) will need per
    /// output vertex and per output triangle. Charged to the memory budget as
    /// geometry is made, so memory binds during evaluation (and truncation
    /// keeps a prefix that will fit) instead of after a scene too big to mesh
    /// has been built. The caller releases the promise with
    /// [`promised_bytes`] before meshing.
    pub downstream: Downstream,
}

/// The memory promised for later stages by `scene`'s instances under `options`.
pub fn promised_bytes(scene: &Scene, options: &EvalOptions) -> u64 {
    let d = &options.downstream;
    let instances = scene.instances.iter().fold(0u64, |acc, i| {
        acc.saturating_add(d.bytes(primitives::vertex_count(i.kind, options.detail), primitives::triangle_count(i.kind, options.detail)))
    });
    let lines = scene.lines.iter().fold(0u64, |acc, l| {
        let n = line_sides(scene, l.profile, options.detail);
        let (v, t) = sweep::per_point_bound(n);
        acc.saturating_add(d.bytes(v, t).saturating_mul(l.points.len() as u64))
    });
    let vertices = d.bytes(1, 1).saturating_mul(scene.vertices.len() as u64);
    let shapes = scene.shape_instances.iter().fold(0u64, |acc, s| {
        let (v, t) = scene.shapes.get(s.shape as usize).map_or((0, 0), |p| (p.positions.len() as u64, (p.indices.len() / 3) as u64));
        acc.saturating_add(d.bytes(v, t))
    });
    instances.saturating_add(lines).saturating_add(vertices).saturating_add(shapes)
}

/// Sides of a line's cross-section: its profile's point count, or the default tube's.
fn line_sides(scene: &Scene, profile: Option<u32>, detail: u32) -> u64 {
    profile
        .and_then(|p| scene.profiles.get(p as usize))
        .map_or_else(|| sweep::profile_sides(detail), |p| p.len() as u64)
}

impl Default for EvalOptions {
    fn default() -> Self {
        EvalOptions { seed: None, detail: crate::geom::DEFAULT_DETAIL, on_limit: OnLimit::Error, downstream: Downstream::default() }
    }
}

/// Evaluates `program` with bound `params` into a scene, under `budget`.
pub fn evaluate(program: &Program, params: &[f64], options: &EvalOptions, budget: &mut Budget) -> Result<Scene, EvalError> {
    let ev = Evaluator::new(program, params, options)?;
    let seed = options.seed.or(program.directives.randseed).unwrap_or(0);
    let animated = program.groups.iter().flat_map(|g| &g.rules).any(|r| matches!(r.transform, RuleTransform::Animate(_)));
    let scene = Scene {
        background: program.directives.background.map(|c| c.map(|v| v.clamp(0.0, 1.0) as f32)),
        rig: animated.then(|| Rig::new(ev.timeline)),
        ..Scene::default()
    };
    let root = Ctx { frame: Frame::IDENTITY, colour: [0.0; 4], depth: 0, key: StreamKey::root(seed), bone: 0, ns: 0 };
    let mut m = Machine::new(&ev, budget, scene, None, root.key);
    let mut result = m.run(ev.program.start, root);
    if result.is_ok() {
        match m.camera() {
            Ok(c) => m.scene.camera = c.as_ref().map(crate::model::Camera::from_path),
            Err(e) => result = Err(e),
        }
    }
    m.release();
    let mut scene = m.scene;
    match result {
        Ok(()) => Ok(scene),
        Err(EvalError::Limit(e)) if options.on_limit == OnLimit::Truncate => {
            scene.truncated = Some(e);
            Ok(scene)
        }
        Err(e) => Err(e),
    }
}

/// The mutable state of one evaluation.
struct Machine<'p, 'b> {
    ev: &'b Evaluator<'p>,
    /// Pending work, depth-first (last pushed runs first).
    stack: Vec<Task<'p>>,
    /// Stack slots already charged to the memory budget (the peak so far).
    charged_slots: u64,
    scene: Scene,
    budget: &'b mut Budget,
    /// Calls so far per group, for sequential selection.
    sequence: Vec<u64>,
    /// Per namespace, the frame of the last terminal drawn, where a continued call (`\`) starts.
    last_terminal: Vec<Option<Frame>>,
    /// Per namespace, the swept-line pen.
    pens: Vec<Pen>,
    /// Set while evaluating a path or profile rule: `FRAME` and `VERTEX` are collected here.
    capture: Option<Capture>,
    /// Paths and profiles already evaluated, by group.
    captured: HashMap<GroupId, Rc<Capture>>,
    /// Scene profile index of each profile group (`None`: it made no usable profile).
    profile_index: HashMap<GroupId, Option<u32>>,
    /// The evaluation's root stream key (paths derive their own from it).
    root_key: StreamKey,
    /// Scene shape index of each isosurface meshed so far.
    isosurface_shape: HashMap<u32, u32>,
    /// Track index in the scene's rig of each list of transform rules.
    track_index: HashMap<Vec<GroupId>, u32>,
    /// Scene shape index of each `mesh` declaration built so far.
    mesh_shape: HashMap<u32, u32>,
}

/// What a path or profile rule emitted.
#[derive(Debug, Default)]
struct Capture {
    /// Stop once this many frames are captured (animation paths may recurse
    /// forever; only their first frames are needed).
    frame_limit: Option<usize>,
    /// `FRAME {}` frames, in order.
    frames: Vec<Frame>,
    /// `VERTEX {}` positions, in order.
    vertices: Vec<DVec3>,
}

/// Where the pen of swept lines is (one pen: namespaces come later).
#[derive(Debug, Clone, Copy)]
struct Pen {
    /// Where the next segment starts when no line is open. The pen starts
    /// down at the root frame, so a first `LINETO` draws from the origin.
    start: Frame,
    /// After `NEWLINE`: the next `LINETO` only puts the pen down.
    lifted: bool,
    /// The last `MOVETO`, for `RESET`.
    moveto: Frame,
    /// Index in `scene.lines` of the line being drawn.
    open: Option<usize>,
}

impl<'p, 'b> Machine<'p, 'b> {
    fn new(ev: &'b Evaluator<'p>, budget: &'b mut Budget, scene: Scene, capture: Option<Capture>, root_key: StreamKey) -> Self {
        Machine {
            sequence: vec![0; ev.program.groups.len()],
            ev,
            stack: Vec::new(),
            charged_slots: 0,
            scene,
            budget,
            last_terminal: vec![None; ev.program.namespaces.count()],
            pens: vec![Pen { start: Frame::IDENTITY, lifted: false, moveto: Frame::IDENTITY, open: None }; ev.program.namespaces.count()],
            capture,
            captured: HashMap::new(),
            profile_index: HashMap::new(),
            root_key,
            isosurface_shape: HashMap::new(),
            track_index: HashMap::new(),
            mesh_shape: HashMap::new(),
        }
    }

    /// Returns the stack's memory to the budget.
    fn release(&mut self) {
        self.budget.release_memory(self.charged_slots * TASK_BYTES);
        self.charged_slots = 0;
    }

    fn run(&mut self, start: Target, root: Ctx) -> Result<(), EvalError> {
        self.expand(start, root)?;
        loop {
            // Charge the stack's peak size before it can grow further.
            let needed = self.stack.len() as u64 + 2;
            if needed > self.charged_slots {
                self.budget.reserve_memory((needed - self.charged_slots) * TASK_BYTES)?;
                self.charged_slots = needed;
            }
            if self.capture.as_ref().is_some_and(|c| c.frame_limit.is_some_and(|l| c.frames.len() >= l)) {
                return Ok(());
            }
            let Some(task) = self.stack.pop() else { return Ok(()) };
            match task {
                Task::Items { items, next, ctx } => {
                    let Some(item) = items.get(next) else { continue };
                    if next + 1 < items.len() {
                        self.stack.push(Task::Items { items, next: next + 1, ctx });
                    }
                    self.run_item(item, ctx)?;
                }
                Task::Copies { it, k, count, step, current, base_key } => {
                    self.budget.charge_step()?;
                    if k < count {
                        let (frame, colour) = current.apply(&step);
                        self.stack.push(Task::Copies {
                            it,
                            k: k + 1,
                            count,
                            step,
                            current: Ctx { frame, colour, ..current },
                            base_key,
                        });
                    }
                    let ctx = Ctx { key: base_key.child(it.site, k), ..current };
                    self.run_item(&it.body, ctx)?;
                }
                Task::Convolve { body, frames, i, ctx } => {
                    self.budget.charge_step()?;
                    let Some(f) = frames.get(i) else { continue };
                    let here = Ctx { frame: ctx.frame.then(f), key: ctx.key.child(CONVOLVE_SLOT, i as u64), ..ctx };
                    if i + 1 < frames.len() {
                        self.stack.push(Task::Convolve { body, frames, i: i + 1, ctx });
                    }
                    self.stack.push(Task::Items { items: body, next: 0, ctx: here });
                }
            }
        }
    }

    /// Starts one item in `ctx`: calls resolve now, blocks and iterators push work.
    fn run_item(&mut self, item: &'p Item, ctx: Ctx) -> Result<(), EvalError> {
        match item {
            Item::Call(call) => {
                let key = ctx.key.child(call.site, 0);
                let d = self.ev.delta(&call.adjust, call.site, key)?;
                let ns = self.ev.program.namespaces.of(call.site);
                let base = match (call.continues, self.last_terminal.get(ns as usize).copied().flatten()) {
                    (true, Some(frame)) => Ctx { frame, ..ctx },
                    _ => ctx,
                };
                let (frame, colour) = base.apply(&d);
                let child = Ctx { frame, colour, depth: ctx.depth + 1, key, bone: ctx.bone, ns };
                self.expand(call.target, child)
            }
            Item::Block(items) => {
                if !items.is_empty() {
                    self.stack.push(Task::Items { items, next: 0, ctx });
                }
                Ok(())
            }
            Item::Iterate(it) => {
                let mut env = Env { params: self.ev.params, key: ctx.key.child(it.site, 0), pos: ctx.frame.translation };
                let count = finite(&it.count, &mut env, it.span, "iteration count")?;
                if count < 0.0 || count.fract() != 0.0 {
                    return Err(EvalError::BadIteration { span: it.span, value: count.to_string() });
                }
                let divisor = match &it.divisor {
                    Some(e) => {
                        let n = finite(e, &mut env, it.span, "iteration divisor")?;
                        if n <= 0.0 {
                            return Err(EvalError::BadIteration { span: it.span, value: format!("divisor {n}") });
                        }
                        n
                    }
                    None => 1.0,
                };
                // `count` is a finite non-negative whole number; saturate absurd values, the
                // step budget stops them long before they matter.
                let count = (count.min(u64::MAX as f64) as u64).min(self.ev.maxiter);
                if count == 0 {
                    return Ok(());
                }
                let step = eval_adjust(&it.step, &mut env, divisor)?;
                let (frame, colour) = ctx.apply(&step);
                self.stack.push(Task::Copies {
                    it,
                    k: 1,
                    count,
                    step,
                    current: Ctx { frame, colour, ..ctx },
                    base_key: ctx.key,
                });
                Ok(())
            }
        }
    }

    /// Runs a call's target in `ctx` (already adjusted, depth already increased).
    fn expand(&mut self, target: Target, ctx: Ctx) -> Result<(), EvalError> {
        match target {
            Target::Primitive(_) | Target::Line(..) if self.capture.is_some() => {
                // Path and profile rules emit frames and vertices only.
                self.budget.charge_step()?;
                Ok(())
            }
            Target::Vertex | Target::Frame | Target::FaceNormals => {
                self.budget.charge_step()?;
                self.special(target, &ctx)
            }
            Target::Isosurface(_) | Target::Mesh(_) if self.capture.is_some() => Ok(()),
            Target::Isosurface(_) | Target::Mesh(_) => {
                self.budget.charge_step()?;
                let shape = match target {
                    Target::Mesh(i) => self.mesh(i)?,
                    Target::Isosurface(i) => self.isosurface(i)?,
                    _ => return Ok(()),
                };
                let (v, t) = self.scene.shapes.get(shape as usize).map_or((0, 0), |p| (p.positions.len() as u64, (p.indices.len() / 3) as u64));
                self.budget.charge_triangles(t)?;
                self.budget.reserve_memory(SHAPE_INSTANCE_BYTES.saturating_add(self.ev.cost.bytes(v, t)))?;
                let mut colour = ctx.colour;
                colour[3] += 1.0;
                self.scene.shape_instances.push(ShapeInstance { shape, frame: ctx.frame, colour: colour.map(|c| c.clamp(0.0, 1.0) as f32) });
                self.tag(|r| &mut r.shape_instance_bone, ctx.bone)?;
                self.set_terminal(ctx.ns, ctx.frame);
                Ok(())
            }
            Target::Primitive(kind) => {
                self.budget.charge_step()?;
                self.budget.charge_primitive(self.ev.tris[kind as usize])?;
                self.budget.reserve_memory(self.ev.downstream[kind as usize])?;
                let instances = &mut self.scene.instances;
                if instances.len() == instances.capacity() {
                    let grow = instances.capacity().max(64);
                    self.budget.reserve_memory(grow as u64 * INSTANCE_BYTES)?;
                    instances.reserve_exact(grow);
                }
                let mut colour = ctx.colour;
                colour[3] += 1.0;
                instances.push(Instance::new(kind, &ctx.frame, colour));
                self.tag(|r| &mut r.instance_bone, ctx.bone)?;
                self.set_terminal(ctx.ns, ctx.frame);
                Ok(())
            }
            Target::Line(op, profile) => {
                self.budget.charge_step()?;
                self.draw_line(op, profile, &ctx)
            }
            Target::Group(g) => {
                let dirs = &self.ev.program.directives;
                if dirs.maxdepth.is_some_and(|m| ctx.depth > m) || dirs.stacksize.is_some_and(|m| ctx.depth > m) || dirs.minsize.is_some_and(|m| ctx.frame.scale < m) {
                    return Ok(());
                }
                // A transform rule sampled for animation may recurse once per
                // frame (Listing 4.2's X2, C.3's CAMERARULE): its frame limit,
                // the step budget and the charged stack bound it, not the depth.
                if !self.capture.as_ref().is_some_and(|c| c.frame_limit.is_some()) {
                    self.budget.check_depth(ctx.depth)?;
                }
                self.budget.charge_step()?;
                let Some(group) = self.ev.program.groups.get(g as usize) else { return Ok(()) };
                let Some(rule) = self.select(g, group, &ctx)? else { return Ok(()) };
                if rule.body.is_empty() {
                    return Ok(());
                }
                match &rule.transform {
                    RuleTransform::None => self.stack.push(Task::Items { items: &rule.body, next: 0, ctx }),
                    RuleTransform::Convolve(paths) => {
                        let frames = self.convolved(paths)?;
                        if !frames.is_empty() {
                            self.stack.push(Task::Convolve { body: &rule.body, frames, i: 0, ctx });
                        }
                    }
                    RuleTransform::Animate(paths) => {
                        // The body runs at the animation's time 0; a rig records the bone.
                        let (frame, bone) = self.bone(&group.name, paths, &ctx)?;
                        self.stack.push(Task::Items { items: &rule.body, next: 0, ctx: Ctx { frame, bone, ..ctx } });
                    }
                }
                Ok(())
            }
        }
    }

    /// Records where the last terminal of namespace `ns` left off.
    fn set_terminal(&mut self, ns: u32, frame: Frame) {
        if let Some(t) = self.last_terminal.get_mut(ns as usize) {
            *t = Some(frame);
        }
    }

    /// Moves the pen of the call's namespace (seed 000 §4.3, §4.1.4): every
    /// operation is a terminal for continuation.
    fn draw_line(&mut self, op: LineOp, profile: Option<GroupId>, ctx: &Ctx) -> Result<(), EvalError> {
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

    /// `VERTEX`, `FACENORMALS` and `FRAME`.
    fn special(&mut self, target: Target, ctx: &Ctx) -> Result<(), EvalError> {
        let frame_bytes = std::mem::size_of::<Frame>() as u64;
        if let Some(capture) = &mut self.capture {
            match target {
                Target::Vertex => {
                    self.budget.reserve_memory(24)?;
                    capture.vertices.push(ctx.frame.translation);
                }
                Target::Frame => {
                    self.budget.reserve_memory(frame_bytes)?;
                    capture.frames.push(ctx.frame);
                }
                _ => {}
            }
            return Ok(());
        }
        match target {
            Target::Vertex => {
                let vertices = self.scene.vertices.len() as u64 + 1;
                if vertices % 3 == 0 {
                    self.budget.charge_triangles(1)?;
                }
                self.budget.reserve_memory(FREE_VERTEX_BYTES.saturating_add(self.ev.cost.bytes(1, 1)))?;
                let local = self.ev.program.directives.normal.map_or(DVec3::Z, DVec3::from_array);
                let mut colour = ctx.colour;
                colour[3] += 1.0;
                self.tag(|r| &mut r.vertex_bone, ctx.bone)?;
                self.scene.vertices.push(FreeVertex {
                    position: ctx.frame.translation,
                    normal: ctx.frame.transform_normal(local).normalize_or_zero(),
                    colour: colour.map(|c| c.clamp(0.0, 1.0) as f32),
                });
                self.set_terminal(ctx.ns, ctx.frame);
            }
            Target::FaceNormals => {
                let n = self.scene.vertices.len();
                if n >= 3 {
                    let v = &mut self.scene.vertices[n - 3..];
                    // A degenerate triangle has no face normal: keep the vertex normals.
                    if let Some(face) = (v[1].position - v[0].position).cross(v[2].position - v[0].position).try_normalize() {
                        for x in v {
                            x.normal = face;
                        }
                    }
                }
            }
            // A FRAME outside a path (animation, cameras) does not draw.
            _ => {}
        }
        Ok(())
    }

    /// Records which bone a new piece of geometry belongs to (when the scene has a rig).
    fn tag(&mut self, tags: fn(&mut Rig) -> &mut Vec<u32>, bone: u32) -> Result<(), EvalError> {
        if let Some(rig) = &mut self.scene.rig {
            self.budget.reserve_memory(4)?;
            tags(rig).push(bone);
        }
        Ok(())
    }

    /// A call of animated rule `name` with transform rules `paths`: the frame
    /// its body runs in (the call frame composed with the track at time 0)
    /// and its bone (a new one when the scene has a rig).
    fn bone(&mut self, name: &str, paths: &[GroupId], ctx: &Ctx) -> Result<(Frame, u32), EvalError> {
        let Some(samples) = self.scene.rig.as_ref().map(|r| r.timeline.samples) else {
            // No rig (inside a path rule): only time 0 matters.
            let mut frame = ctx.frame;
            for &p in paths {
                if let Some(f) = self.capture_group(p, Some(1))?.frames.first() {
                    frame = frame.then(f);
                }
            }
            return Ok((frame, ctx.bone));
        };
        let track = match self.track_index.get(paths) {
            Some(&t) => t,
            None => {
                let streams = paths.iter().map(|&p| self.capture_group(p, Some(samples as usize))).collect::<Result<Vec<_>, _>>()?;
                self.budget.reserve_memory(u64::from(samples).saturating_mul(std::mem::size_of::<Frame>() as u64))?;
                let frames: Vec<Frame> = (0..samples as usize)
                    .map(|k| streams.iter().fold(Frame::IDENTITY, |f, s| f.then(&looped(&s.frames, k))))
                    .collect();
                let Some(rig) = self.scene.rig.as_mut() else { return Ok((ctx.frame, ctx.bone)) };
                rig.tracks.push(frames);
                let t = (rig.tracks.len() - 1) as u32;
                self.track_index.insert(paths.to_vec(), t);
                t
            }
        };
        self.budget.reserve_memory(BONE_BYTES)?;
        let Some(rig) = self.scene.rig.as_mut() else { return Ok((ctx.frame, ctx.bone)) };
        let start = rig.tracks.get(track as usize).and_then(|t| t.first()).copied().unwrap_or(Frame::IDENTITY);
        let body = ctx.frame.then(&start);
        let parent_body = rig.bones.get(ctx.bone as usize).map_or(Frame::IDENTITY, |b| b.body);
        // A parent collapsed to zero scale hides its children anyway.
        let local = parent_body.inverse().map_or(Frame::IDENTITY, |inv| inv.then(&ctx.frame));
        let id = u32::try_from(rig.bones.len()).unwrap_or(u32::MAX);
        rig.bones.push(Bone { name: name.to_string(), parent: ctx.bone, local, body, track });
        Ok((body, id))
    }

    /// The camera path of `camerarule`, sampled on the timeline.
    fn camera(&mut self) -> Result<Option<CameraPath>, EvalError> {
        let dirs = &self.ev.program.directives;
        let Some(g) = dirs.camerarule else { return Ok(None) };
        let lens = dirs.camera;
        let timeline = self.ev.timeline;
        let stream = self.capture_group(g, Some(timeline.samples as usize))?;
        let frames = match stream.frames.len() {
            0 => vec![Frame::IDENTITY],
            1 => vec![stream.frames[0]],
            _ => {
                self.budget.reserve_memory(u64::from(timeline.samples).saturating_mul(std::mem::size_of::<Frame>() as u64))?;
                (0..timeline.samples as usize).map(|k| looped(&stream.frames, k)).collect()
            }
        };
        Ok(Some(CameraPath { timeline, frames, lens }))
    }

    /// Evaluates a path or profile rule from the identity frame, once per evaluation.
    fn capture_group(&mut self, g: GroupId, frame_limit: Option<usize>) -> Result<Rc<Capture>, EvalError> {
        if let Some(c) = self.captured.get(&g).filter(|c| c.frame_limit.is_none() || c.frame_limit == frame_limit) {
            return Ok(Rc::clone(c));
        }
        let key = self.root_key.child(CAPTURE_SLOT, u64::from(g));
        let root = Ctx { frame: Frame::IDENTITY, colour: [0.0; 4], depth: 0, key, bone: 0, ns: 0 };
        let capture = Capture { frame_limit, ..Capture::default() };
        let mut sub = Machine::new(self.ev, &mut *self.budget, Scene::default(), Some(capture), self.root_key);
        let result = sub.run(Target::Group(g), root);
        sub.release();
        result?;
        let c = Rc::new(sub.capture.take().unwrap_or_default());
        self.captured.insert(g, Rc::clone(&c));
        Ok(c)
    }

    /// The frames of a convolved rule: frame i of the first path composed with
    /// frame i of each further path, as many as the shortest path has.
    fn convolved(&mut self, paths: &[GroupId]) -> Result<Rc<Vec<Frame>>, EvalError> {
        let captures = paths.iter().map(|&p| self.capture_group(p, None)).collect::<Result<Vec<_>, _>>()?;
        let n = captures.iter().map(|c| c.frames.len()).min().unwrap_or(0);
        self.budget.reserve_memory((n as u64).saturating_mul(std::mem::size_of::<Frame>() as u64))?;
        let frames = (0..n)
            .map(|i| captures.iter().skip(1).fold(captures[0].frames[i], |f, c| f.then(&c.frames[i])))
            .collect();
        Ok(Rc::new(frames))
    }

    /// The scene shape of isosurface `i`, meshed on first use. The grid's
    /// samples are charged as steps and memory before any is computed.
    fn isosurface(&mut self, i: u32) -> Result<u32, EvalError> {
        if let Some(&s) = self.isosurface_shape.get(&i) {
            return Ok(s);
        }
        let Some(iso) = self.ev.program.isosurfaces.get(i as usize) else { return Ok(0) };
        let samples = crate::geom::isosurface::sample_count(&iso.axes);
        self.budget.charge_steps(samples)?;
        // The grid (an f32 field and a u32 vertex map per sample) is transient but large.
        let grid_bytes = samples.saturating_mul(12);
        self.budget.reserve_memory(grid_bytes)?;
        let params = self.ev.params;
        let key = self.root_key;
        let proto = crate::geom::isosurface::mesh_isosurface(&iso.axes, |p| {
            iso.field.eval(&mut Env { params, key, pos: DVec3::from_array(p) })
        });
        self.budget.release_memory(grid_bytes);
        self.budget.reserve_memory(crate::geom::mesh::mesh_bytes(proto.positions.len() as u64, (proto.indices.len() / 3) as u64))?;
        self.scene.shapes.push(proto);
        let s = (self.scene.shapes.len() - 1) as u32;
        self.isosurface_shape.insert(i, s);
        Ok(s)
    }

    /// The scene shape of `mesh` declaration `i`, built on first use; the
    /// modifiers check every intermediate size against the budget first.
    fn mesh(&mut self, i: u32) -> Result<u32, EvalError> {
        if let Some(&s) = self.mesh_shape.get(&i) {
            return Ok(s);
        }
        let Some(decl) = self.ev.program.meshes.get(i as usize) else { return Ok(0) };
        let proto = crate::geom::modifiers::build(&decl.base, &decl.modifiers, self.ev.detail, self.budget).map_err(|e| match e {
            crate::geom::modifiers::ModifyError::Limit(l) => EvalError::Limit(l),
            other => EvalError::Mesh { span: decl.span, name: decl.name.clone(), message: other.to_string() },
        })?;
        self.budget.reserve_memory(crate::geom::mesh::mesh_bytes(proto.positions.len() as u64, (proto.indices.len() / 3) as u64))?;
        self.scene.shapes.push(proto);
        let s = (self.scene.shapes.len() - 1) as u32;
        self.mesh_shape.insert(i, s);
        Ok(s)
    }

    /// The scene profile made by profile rule `g` (its `VERTEX` points), if it made one.
    fn profile(&mut self, g: GroupId) -> Result<Option<u32>, EvalError> {
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

    /// Picks the alternative of `group` that a call in `ctx` runs, if any.
    fn select(&mut self, g: GroupId, group: &'p RuleGroup, ctx: &Ctx) -> Result<Option<&'p Rule>, EvalError> {
        let rules = &group.rules;
        let threshold = |value: f64| {
            rules
                .iter()
                .filter(|r| r.weight >= value)
                .min_by(|a, b| a.weight.total_cmp(&b.weight))
        };
        Ok(match &group.selector {
            Selector::Random if rules.len() == 1 => rules.first(),
            Selector::Random => {
                let cum = &self.ev.cumulative[g as usize];
                let total = cum.last().copied().unwrap_or(0.0);
                let target = ctx.key.uniform(SELECT_SLOT) * total;
                cum.iter().position(|&c| c > target).and_then(|i| rules.get(i))
            }
            Selector::Depth => threshold(f64::from(ctx.depth)),
            Selector::Scale => threshold(ctx.frame.scale),
            Selector::Function(f) => {
                let mut env = Env { params: self.ev.params, key: ctx.key, pos: ctx.frame.translation };
                let span = rules.first().map_or_else(Span::default, |r| r.span);
                threshold(finite(f, &mut env, span, "selector function")?)
            }
            Selector::Sequential => {
                // Each rule runs round(weight) times in order; the cycle repeats.
                let runs = |r: &Rule| r.weight.round().max(0.0) as u64;
                let cycle: u64 = rules.iter().map(runs).sum();
                if cycle == 0 {
                    return Ok(None);
                }
                let n = &mut self.sequence[g as usize];
                let mut at = *n % cycle;
                *n += 1;
                rules.iter().find(|r| {
                    let k = runs(r);
                    if at < k {
                        true
                    } else {
                        at -= k;
                        false
                    }
                })
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::{Limit, Limits};
    use crate::lang::ir::{Call, Directives, PrimitiveKind, Rule, RuleGroup};

    fn num(v: f64) -> Expr {
        Expr::Num(v)
    }

    fn adj(op: AdjustOp) -> Adjust {
        Adjust { op, span: Span::new(1, 1) }
    }

    fn call(target: Target, adjust: Vec<Adjust>, site: u32) -> Item {
        Item::Call(Call { target, adjust, site, continues: false, span: Span::new(1, 1) })
    }

    fn iterate(count: f64, divisor: Option<f64>, step: Vec<Adjust>, body: Item, site: u32) -> Item {
        Item::Iterate(Iterate {
            count: num(count),
            divisor: divisor.map(num),
            step,
            body: Box::new(body),
            site,
            span: Span::new(1, 1),
        })
    }

    fn program(groups: Vec<RuleGroup>, site_count: u32) -> Program {
        Program {
            start: Target::Group(0),
            groups,
            directives: Directives::default(),
            params: vec![],
            site_count,
            warnings: vec![],
            isosurfaces: vec![],
            namespaces: Default::default(),
            meshes: vec![],
        }
    }

    fn single(body: Vec<Item>) -> RuleGroup {
        RuleGroup { name: "A".into(), rules: vec![Rule { weight: 1.0, transform: RuleTransform::None, body, span: Span::new(1, 1) }], selector: Selector::Random }
    }

    fn run(p: &Program, limits: Limits, on_limit: OnLimit) -> Result<Scene, EvalError> {
        let opts = EvalOptions { on_limit, ..EvalOptions::default() };
        evaluate(p, &[], &opts, &mut Budget::new(limits))
    }

    const BOX: Target = Target::Primitive(PrimitiveKind::Box);

    #[test]
    fn iterator_copies_get_the_step_k_times() {
        // 10 * {x 1} BOX {}
        let step = vec![adj(AdjustOp::Translate([num(1.0), num(0.0), num(0.0)]))];
        let p = program(vec![single(vec![iterate(10.0, None, step, call(BOX, vec![], 1), 0)])], 2);
        let scene = run(&p, Limits::default(), OnLimit::Error).unwrap();
        let xs: Vec<f32> = scene.instances.iter().map(|i| i.translation.x).collect();
        assert_eq!(xs, (1..=10).map(|k| k as f32).collect::<Vec<_>>());
    }

    #[test]
    fn divided_iterator_closes_a_turn() {
        // 2/2 * {rz 180} BOX {x 1}: copies at rz 90 and rz 180, the last back at x = -1.
        let step = vec![adj(AdjustOp::Rotate { axis: Axis::Z, angle: num(std::f64::consts::PI) })];
        let body = call(BOX, vec![adj(AdjustOp::Translate([num(1.0), num(0.0), num(0.0)]))], 1);
        let p = program(vec![single(vec![iterate(2.0, Some(2.0), step, body, 0)])], 2);
        let scene = run(&p, Limits::default(), OnLimit::Error).unwrap();
        let t: Vec<_> = scene.instances.iter().map(|i| i.translation).collect();
        assert!((t[0] - glam::Vec3::new(0.0, 1.0, 0.0)).length() < 1e-6, "{t:?}");
        assert!((t[1] - glam::Vec3::new(-1.0, 0.0, 0.0)).length() < 1e-6, "{t:?}");
    }

    #[test]
    fn runaway_recursion_hits_the_depth_limit_without_recursing_in_rust() {
        // rule A { A {} }
        let p = program(vec![single(vec![call(Target::Group(0), vec![], 0)])], 1);
        let limits = Limits { max_depth: 50_000, ..Limits::default() };
        match run(&p, limits, OnLimit::Error) {
            Err(EvalError::Limit(e)) => assert_eq!((e.limit, e.reached), (Limit::Depth, 50_001)),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn huge_iterator_is_lazy_and_truncates_at_the_primitive_limit() {
        let step = vec![adj(AdjustOp::Translate([num(1.0), num(0.0), num(0.0)]))];
        let p = program(vec![single(vec![iterate(1e9, None, step, call(BOX, vec![], 1), 0)])], 2);
        let limits = Limits { max_primitives: 1000, ..Limits::default() };
        let scene = run(&p, limits, OnLimit::Truncate).unwrap();
        assert_eq!(scene.instances.len(), 1000);
        assert_eq!(scene.truncated.map(|t| t.limit), Some(Limit::Primitives));
        assert!(matches!(run(&p, limits, OnLimit::Error), Err(EvalError::Limit(_))));
    }

    #[test]
    fn weighted_choice_depends_on_seed_and_position_not_order() {
        // A → 200 * {x 1} B ; B has two alternatives (BOX or SPHERE), weights 1 and 3.
        let a = single(vec![iterate(200.0, None, vec![adj(AdjustOp::Translate([num(1.0), num(0.0), num(0.0)]))], call(Target::Group(1), vec![], 1), 0)]);
        let b = RuleGroup {
            name: "B".into(),
            rules: vec![
                Rule { weight: 1.0, transform: RuleTransform::None, body: vec![call(BOX, vec![], 2)], span: Span::new(1, 1) },
                Rule { weight: 3.0, transform: RuleTransform::None, body: vec![call(Target::Primitive(PrimitiveKind::Sphere), vec![], 3)], span: Span::new(1, 1) },
            ],
            selector: Selector::Random,
        };
        let p = program(vec![a, b], 4);
        let kinds = |seed| {
            let opts = EvalOptions { seed: Some(seed), ..EvalOptions::default() };
            evaluate(&p, &[], &opts, &mut Budget::new(Limits::default()))
                .unwrap()
                .instances
                .iter()
                .map(|i| i.kind)
                .collect::<Vec<_>>()
        };
        assert_eq!(kinds(1), kinds(1));
        assert_ne!(kinds(1), kinds(2));
        let spheres = kinds(1).iter().filter(|k| **k == PrimitiveKind::Sphere).count();
        assert!((120..=180).contains(&spheres), "{spheres} of 200 should be about 150");
    }

    #[test]
    fn non_finite_arguments_are_errors_with_position() {
        let bad = Expr::Binary(crate::lang::expr::BinOp::Div, Box::new(num(1.0)), Box::new(num(0.0)));
        let p = program(vec![single(vec![call(BOX, vec![Adjust { op: AdjustOp::Scale(bad), span: Span::new(3, 7) }], 0)])], 1);
        match run(&p, Limits::default(), OnLimit::Error) {
            Err(EvalError::NonFinite { span, .. }) => assert_eq!(span, Span::new(3, 7)),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn stack_memory_is_charged() {
        // rule A { A{} A{} } with a tiny memory budget fails on memory, not by OOM.
        let p = program(vec![single(vec![call(Target::Group(0), vec![], 0), call(Target::Group(0), vec![], 1)])], 2);
        let limits = Limits { max_memory: 10_000, max_depth: 100_000, ..Limits::default() };
        match run(&p, limits, OnLimit::Error) {
            Err(EvalError::Limit(e)) => assert_eq!(e.limit, Limit::Memory),
            other => panic!("{other:?}"),
        }
    }
}
