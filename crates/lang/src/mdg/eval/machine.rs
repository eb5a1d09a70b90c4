//! The task machine: the explicit stack of pending work and the loop that
//! runs it. [`Evaluator`] holds what is fixed for one evaluation (program,
//! parameters, precomputed deltas and costs); [`Machine`] is its mutable
//! state. `run` pops [`Task`]s, charging the stack's peak size to the memory
//! budget, and `expand` dispatches a call's target: primitives are placed
//! here, lines, shapes, selection and animation go to their own modules
//! (`lines`, `shapes`, `select`, `paths`), which add methods to [`Machine`].
//! No Rust recursion follows the grammar.

use super::adjust::{eval_adjust, finite, Ctx, Delta, Env};
use super::setup::{setup, Setup, SetupMemo};
use super::lines::Pen;
use super::paths::Capture;
use super::evaluator::EvalOptions;
use crate::core::budget::Budget;
use crate::core::frame::Frame;
use crate::core::rng::StreamKey;
use crate::geom::primitives;
use crate::ir::{Adjust, GroupId, Item, Iterate, PrimitiveKind, Program, RuleTransform, Target};
use crate::model::animation::Timeline;
use crate::model::scene::{Instance, Scene, ShapeInstance, INSTANCE_BYTES, SHAPE_INSTANCE_BYTES};
use crate::model::instancing::{Placement, Tally};
use crate::model::{Downstream, EvalError};
use glam::DVec3;
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

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

/// Everything fixed for one evaluation: the program, bound parameters, precomputed deltas.
pub(super) struct Evaluator<'p> {
    pub(super) program: &'p Program,
    pub(super) params: &'p [f64],
    /// The fixed deltas and cumulative weights (module `setup`), shared
    /// with the program's memo.
    pub(super) setup: Arc<Setup>,
    /// Triangles per primitive kind at the requested detail.
    pub(super) tris: [u64; 9],
    /// Bytes later stages need per primitive of each kind.
    pub(super) downstream: [u64; 9],
    pub(super) cost: Downstream,
    pub(super) detail: u32,
    pub(super) maxiter: u64,
    /// Sampling of transform rules and the camera.
    pub(super) timeline: Timeline,
}

/// Evaluation slot reserved for rule selection (never a `rand()` site).
pub(super) const SELECT_SLOT: u32 = u32::MAX;
/// Stream slot for the copies of a convolved rule.
pub(super) const CONVOLVE_SLOT: u32 = u32::MAX - 1;
/// Stream slot for path and profile rules.
pub(super) const CAPTURE_SLOT: u32 = u32::MAX - 2;

impl<'p> Evaluator<'p> {
    /// Precomputes the fixed deltas, cumulative weights and per-kind costs
    /// of `program`; the first two from `memo` when it holds them for the
    /// same parameter values (module `setup`).
    pub(super) fn new(program: &'p Program, params: &'p [f64], options: &EvalOptions, memo: Option<&SetupMemo>) -> Result<Self, EvalError> {
        let detail = options.detail;
        let setup = setup(program, params, memo)?;
        let mut tris = [0u64; 9];
        for k in PrimitiveKind::ALL {
            tris[k as usize] = primitives::triangle_count(k, detail);
        }
        Ok(Evaluator {
            program,
            params,
            setup,
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

    /// The delta of call site `site`: precomputed when deterministic, else evaluated in stream `key`.
    pub(super) fn delta(&self, adjust: &[Adjust], site: u32, key: StreamKey) -> Result<Delta, EvalError> {
        if let Some(Some(d)) = self.setup.fixed.get(site as usize) {
            return Ok(*d);
        }
        eval_adjust(adjust, &mut Env { params: self.params, key, pos: DVec3::ZERO }, 1.0)
    }
}

/// The mutable state of one evaluation.
pub(super) struct Machine<'p, 'b> {
    pub(super) ev: &'b Evaluator<'p>,
    /// Pending work, depth-first (last pushed runs first).
    stack: Vec<Task<'p>>,
    /// Stack slots already charged to the memory budget (the peak so far).
    pub(super) charged_slots: u64,
    pub(super) scene: Scene,
    pub(super) budget: &'b mut Budget,
    /// Calls so far per group, for sequential selection.
    pub(super) sequence: Vec<u64>,
    /// Per namespace, the frame of the last terminal drawn, where a continued call (`\`) starts.
    pub(super) last_terminal: Vec<Option<Frame>>,
    /// Per namespace, the swept-line pen.
    pub(super) pens: Vec<Pen>,
    /// Set while evaluating a path or profile rule: `FRAME` and `VERTEX` are collected here.
    pub(super) capture: Option<Capture>,
    /// Paths and profiles already evaluated, by group.
    pub(super) captured: HashMap<GroupId, Rc<Capture>>,
    /// Scene profile index of each profile group (`None`: it made no usable profile).
    pub(super) profile_index: HashMap<GroupId, Option<u32>>,
    /// The evaluation's root stream key (paths derive their own from it).
    pub(super) root_key: StreamKey,
    /// Scene shape index of each isosurface meshed so far.
    pub(super) isosurface_shape: HashMap<u32, u32>,
    /// Track index in the scene's rig of each list of transform rules.
    pub(super) track_index: HashMap<Vec<GroupId>, u32>,
    /// Scene shape index of each `mesh` declaration built so far.
    pub(super) mesh_shape: HashMap<u32, u32>,
    /// The path, profile and camera rules being evaluated by the machines
    /// above this one (each capture runs in a machine of its own, on the
    /// call stack): a rule already here is a cycle, and the chain's length
    /// is bounded so the call stack is (see `paths::MAX_CAPTURE_NESTING`).
    pub(super) capturing: Vec<GroupId>,
    /// What each placement costs when the output instances repeated meshes.
    pub(super) tally: Tally,
}

impl<'p, 'b> Machine<'p, 'b> {
    /// A machine with an empty stack that adds to `scene` (or, with `capture`, collects a path).
    pub(super) fn new(ev: &'b Evaluator<'p>, budget: &'b mut Budget, scene: Scene, capture: Option<Capture>, root_key: StreamKey) -> Self {
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
            capturing: Vec::new(),
            tally: Tally::new(ev.cost.per_instance),
        }
    }

    /// Returns the stack's memory to the budget.
    pub(super) fn release(&mut self) {
        self.budget.release_memory(self.charged_slots * TASK_BYTES);
        self.charged_slots = 0;
    }

    /// Runs `start` from `root` until the stack is empty (or a capture has its frames).
    pub(super) fn run(&mut self, start: Target, root: Ctx) -> Result<(), EvalError> {
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
            // Items and copies advance in place on top of the stack, where
            // popping and pushing them back would copy a few hundred bytes
            // per item (a tenth of a million-box grid's evaluation). The
            // stack then holds exactly what it held before, in order.
            match self.stack.last_mut() {
                None => return Ok(()),
                Some(Task::Items { items, next, ctx }) => {
                    let (items, at, ctx) = (*items, *next, *ctx);
                    if at + 1 < items.len() {
                        *next = at + 1;
                    } else {
                        self.stack.pop();
                    }
                    let Some(item) = items.get(at) else { continue };
                    self.run_item(item, ctx)?;
                    continue;
                }
                Some(Task::Copies { it, k, count, step, current, base_key }) => {
                    self.budget.charge_step()?;
                    let (it, at, this, base_key) = (*it, *k, *current, *base_key);
                    if at < *count {
                        let (frame, colour) = this.apply(step);
                        *current = Ctx { frame, colour, ..this };
                        *k = at + 1;
                    } else {
                        self.stack.pop();
                    }
                    let ctx = Ctx { key: base_key.child(it.site, at), ..this };
                    self.run_item(&it.body, ctx)?;
                    continue;
                }
                Some(Task::Convolve { .. }) => {}
            }
            // A convolution is on top: it is popped, and pushed back under its body.
            let Some(Task::Convolve { body, frames, i, ctx }) = self.stack.pop() else { continue };
            self.budget.charge_step()?;
            let Some(f) = frames.get(i) else { continue };
            let here = Ctx { frame: ctx.frame.then(f), key: ctx.key.child(CONVOLVE_SLOT, i as u64), ..ctx };
            if i + 1 < frames.len() {
                self.stack.push(Task::Convolve { body, frames, i: i + 1, ctx });
            }
            self.stack.push(Task::Items { items: body, next: 0, ctx: here });
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
                let ns = first_call_site(&it.body).map_or(0, |site| self.ev.program.namespaces.of(site));
                let ctx = match (it.continues, self.last_terminal.get(ns as usize).copied().flatten()) {
                    (true, Some(frame)) => Ctx { frame, ..ctx },
                    _ => ctx,
                };
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
                let mut colour = ctx.colour;
                colour[3] += 1.0;
                let placed = ShapeInstance { shape, frame: ctx.frame, colour: colour.map(|c| c.clamp(0.0, 1.0) as f32) };
                let (t, bytes) = self.tally.cost(Placement::of_shape(&placed).map(|p| p.key), t, self.ev.cost.bytes(v, t));
                self.budget.charge_triangles(t)?;
                self.budget.reserve_memory(SHAPE_INSTANCE_BYTES.saturating_add(bytes))?;
                self.scene.shape_instances.push(placed);
                self.tag(|r| &mut r.shape_instance_bone, ctx.bone)?;
                self.set_terminal(ctx.ns, ctx.frame);
                Ok(())
            }
            Target::Primitive(kind) => {
                self.budget.charge_step()?;
                let mut colour = ctx.colour;
                colour[3] += 1.0;
                let placed = Instance::new(kind, &ctx.frame, colour);
                let (t, bytes) = self.tally.cost(Placement::key_of_instance(&placed), self.ev.tris[kind as usize], self.ev.downstream[kind as usize]);
                self.budget.charge_primitive(t)?;
                self.budget.reserve_memory(bytes)?;
                let instances = &mut self.scene.instances;
                if instances.len() == instances.capacity() {
                    let grow = instances.capacity().max(64);
                    self.budget.reserve_memory(grow as u64 * INSTANCE_BYTES)?;
                    instances.reserve_exact(grow);
                }
                instances.push(placed);
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
    pub(super) fn set_terminal(&mut self, ns: u32, frame: Frame) {
        if let Some(t) = self.last_terminal.get_mut(ns as usize) {
            *t = Some(frame);
        }
    }
}

/// The call site of the first call `item` reaches (through iterators and
/// blocks): the namespace a continued iterator reads its pen from is its
/// body's (`\\ 3 * {rx 10} X.LINETO{}` continues in `X`).
fn first_call_site(item: &Item) -> Option<u32> {
    let mut cur = item;
    loop {
        match cur {
            Item::Call(c) => return Some(c.site),
            Item::Iterate(it) => cur = &it.body,
            Item::Block(b) => match b.first() {
                Some(first) => cur = first,
                None => return None,
            },
        }
    }
}
