//! Structure Synth's builder: runs a parsed [`Script`] into a [`Scene`],
//! following `StructureSynth/Model/Builder.cpp`, `CustomRule.cpp`,
//! `AmbiguousRule.cpp`, `Action.cpp` and `Transformation.cpp` of Structure
//! Synth 1.5 (the rpavlik/structure-synth mirror; line numbers below are
//! that source's).
//!
//! Breadth-first by default (`Builder::recurseBreadthFirst`, Builder.cpp:106-177):
//! generation after generation, every pending rule state is applied in order
//! and queues its children; primitives too are queued, and drawn when their
//! generation runs. It stops before a generation when the generations run
//! reach `set maxdepth` (default 1000), or the objects drawn or the states
//! pending reach `set maxobjects` (default 100 000), so which objects a
//! cut-off keeps is the same as in Structure Synth. There is no recursion:
//! a generation limit is not a stack depth, so the request's `max_depth`
//! does not apply; the objects, triangles, memory and steps of the budget
//! are the guards. `set recursion depth` switches to depth-first expansion
//! (`recurseDepthFirst`, Builder.cpp:37-103), with rule depths set as
//! `RuleSet::setRulesMaxDepth` sets them (see [`Builder::rule_maxdepth`]).
//!
//! Randomness is Structure Synth's: two Mersenne Twisters ([`MtRand`]), the
//! geometry stream (rule choices, the per-generation sync seed, `set seed
//! initial`) and the colour stream (`color random`), both seeded with the
//! request's seed as Structure Synth's GUI seeds them with its seed box
//! (`RandomStreams::SetSeed`), and drawn in Structure Synth's order — so a
//! script and a seed choose the same rules and colours, and make the same
//! objects, as in Structure Synth.

use super::draw::{Canvas, Placement};
use super::view::View;
use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::core::mtrand::MtRand;
use crate::eisen::syntax::{colour, Action, ColourPool, Loop, Primitive, RuleDef, Script, Setting, Target, Transform};
use crate::model::scene::Scene;
use crate::model::EvalError;
use glam::{DMat4, DVec3};

/// Structure Synth's default `maxdepth` (generations; Builder.cpp:22).
pub(crate) const DEFAULT_MAX_GENERATIONS: i64 = 1000;
/// Structure Synth's default `maxobjects` (Builder.cpp:23).
pub(crate) const DEFAULT_MAX_OBJECTS: i64 = 100_000;
/// Default half-thickness of `line`, `grid` and `dot` solids, in units of the local frame.
pub const DEFAULT_LINE_RADIUS: f64 = 0.01;


/// What the builder needs besides the script.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BuildOptions {
    /// The initial seed: Structure Synth's seed box (its low 32 bits seed both streams).
    pub seed: u64,
    /// Tessellation detail (for triangle and memory accounting).
    pub detail: u32,
    /// Fail or truncate at a budget limit.
    pub on_limit: OnLimit,
    /// Half-thickness of lines, grid edges and dots, in units of the local frame.
    pub line_radius: f64,
    /// Bytes meshing and export need per primitive of each kind.
    pub downstream_bytes: [u64; 9],
    /// Bytes meshing and export need per free vertex (triangles, meshes).
    pub vertex_bytes: u64,
    /// Bytes per GPU instance when the output instances repeated meshes
    /// ([`Downstream::per_instance`](crate::model::Downstream::per_instance)).
    pub per_instance: Option<u64>,
}

/// What the builder made.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Built {
    /// The scene.
    pub scene: Scene,
    /// Objects drawn (Structure Synth's object count).
    pub objects: u64,
    /// Memory promised for meshing and export, to be released before meshing.
    pub promised: u64,
    /// Generations run (breadth-first) or rule states applied (depth-first).
    pub generations: u64,
    /// What each placement is charged (instanced output charges repeats as instances).
    pub tally: crate::model::instancing::Tally,
}

/// The state a rule runs in: Structure Synth's `State` (State.h:21-37).
#[derive(Debug, Clone, PartialEq)]
struct State {
    matrix: DMat4,
    /// The matrix of the state the last loop action started from (what `mesh`
    /// joins to); `None` until a loop (a `{ … }` block included) lies on the
    /// path, as Structure Synth's null `previous` (State.cpp:10, 41-53).
    previous: Option<DMat4>,
    hsv: [f64; 3],
    alpha: f64,
    /// `maxDepths`: remaining depth per rule *definition* with a `maxdepth`.
    depths: Vec<(u32, i64)>,
    /// `seed`: after `set seed initial`, the seed both streams restart from when this state runs (0: none).
    seed: u32,
}

impl State {
    fn depth_of(&self, def: u32) -> Option<i64> {
        self.depths.iter().find(|(d, _)| *d == def).map(|&(_, v)| v)
    }

    fn set_depth(&mut self, def: u32, v: i64) {
        match self.depths.iter_mut().find(|(d, _)| *d == def) {
            Some(e) => e.1 = v,
            None => self.depths.push((def, v)),
        }
    }
}

#[derive(Debug, Clone)]
enum Pending<'a> {
    Top,
    Target(&'a Target),
}

#[derive(Debug, Clone)]
struct RuleState<'a> {
    what: Pending<'a>,
    state: State,
}

const RULE_STATE_BYTES: u64 = std::mem::size_of::<RuleState>() as u64;
const STATE_BYTES: u64 = std::mem::size_of::<State>() as u64;

fn state_bytes(s: &RuleState) -> u64 {
    RULE_STATE_BYTES + 16 * s.state.depths.capacity() as u64
}

struct Builder<'a> {
    script: &'a Script,
    opts: BuildOptions,
    budget: &'a mut Budget,
    max_generations: i64,
    max_objects: i64,
    min_size: f64,
    max_size: f64,
    pool: ColourPool,
    sync_random: bool,
    /// `RandomStreams::Geometry()` and `RandomStreams::Color()`.
    geometry: MtRand,
    colour: MtRand,
    /// `initialSeed` (Builder.cpp:338-342): drawn once, at the first `set seed initial`.
    initial_seed: u32,
    /// The last two streams seeded by [`Builder::reseed`], with their seeds, latest first.
    seeded: Vec<(u32, MtRand)>,
    /// Depth-first only: the maxdepth `RuleSet::setRulesMaxDepth` last gave
    /// the definitions of rules with several definitions.
    ambiguous_maxdepth: i64,
    next: Vec<RuleState<'a>>,
    next_bytes: u64,
    built: Built,
    /// The viewer settings, once a script sets one.
    view: Option<View>,
}

/// Runs `script` under `budget`.
pub fn build(script: &Script, opts: &BuildOptions, budget: &mut Budget) -> Result<Built, EvalError> {
    // Structure Synth's seeds are C ints: the request's seed is cut to 32 bits.
    let seed = opts.seed as u32;
    let mut b = Builder {
        script,
        opts: *opts,
        budget,
        max_generations: DEFAULT_MAX_GENERATIONS,
        max_objects: DEFAULT_MAX_OBJECTS,
        min_size: 0.0,
        max_size: 0.0,
        pool: ColourPool::RandomHue,
        sync_random: false,
        geometry: MtRand::new(seed),
        colour: MtRand::new(seed),
        initial_seed: 0,
        seeded: Vec::with_capacity(2),
        ambiguous_maxdepth: DEFAULT_MAX_GENERATIONS,
        next: Vec::new(),
        next_bytes: 0,
        built: Built::default(),
        view: None,
    };
    b.built.scene.classes = script.classes.clone();
    b.built.tally = crate::model::instancing::Tally::new(opts.per_instance);
    let start = RuleState {
        what: Pending::Top,
        state: State { matrix: DMat4::IDENTITY, previous: None, hsv: [0.0, 1.0, 1.0], alpha: 1.0, depths: Vec::new(), seed: 0 },
    };
    let result = if script.depth_first { b.depth_first(start) } else { b.breadth_first(start) };
    b.budget.release_memory(b.next_bytes);
    b.built.scene.camera = b.view.and_then(|v| v.camera());
    match result {
        Ok(()) => Ok(b.built),
        Err(e) if b.opts.on_limit == OnLimit::Truncate => {
            b.built.scene.truncated = Some(e);
            Ok(b.built)
        }
        Err(e) => Err(EvalError::Limit(e)),
    }
}

impl<'a> Builder<'a> {
    /// `RandomStreams::SetSeed`: both streams restart from `seed`. Under
    /// `syncrandom` or `set seed initial` every state reseeds, mostly with
    /// its siblings' seed (and, with both, alternately with the generation's
    /// sync seed), so the last two seeded streams are kept and copied.
    fn reseed(&mut self, seed: u32) {
        match self.seeded.iter().position(|(s, _)| *s == seed) {
            Some(0) => {}
            Some(i) => self.seeded.swap(0, i),
            None => {
                self.seeded.truncate(1);
                self.seeded.insert(0, (seed, MtRand::new(seed)));
            }
        }
        if let Some((_, fresh)) = self.seeded.first() {
            self.geometry.clone_from(fresh);
            self.colour.clone_from(fresh);
        }
    }

    /// Builder.cpp:106-177.
    fn breadth_first(&mut self, start: RuleState<'a>) -> Result<(), LimitExceeded> {
        let mut stack = vec![start];
        let mut stack_bytes = 0;
        let mut generation: i64 = 0;
        let result = (|| {
            // Builder.cpp:107-110 draws a sync seed first when `syncRandom` is
            // on, which it never is yet (only a running script sets it).
            if self.sync_random {
                self.geometry.next_u32();
            }
            while !stack.is_empty()
                && generation < self.max_generations
                && (self.built.objects as i64) < self.max_objects
                && (stack.len() as i64) < self.max_objects
            {
                // Builder.cpp:118: one geometry draw per generation, synchronised or not.
                let sync_seed = self.geometry.next_u32();
                generation += 1;
                for rs in &mut stack {
                    self.restart_streams(&mut rs.state);
                    if self.sync_random {
                        self.reseed(sync_seed);
                    }
                    self.apply_pending(rs)?;
                }
                self.budget.release_memory(stack_bytes);
                stack = std::mem::take(&mut self.next);
                stack_bytes = std::mem::take(&mut self.next_bytes);
            }
            Ok(())
        })();
        self.budget.release_memory(stack_bytes);
        self.built.generations = generation as u64;
        result
    }

    /// Builder.cpp:37-103: a list whose front runs next, children inserted in
    /// front in order (a stack popped from its end, children pushed reversed).
    fn depth_first(&mut self, start: RuleState<'a>) -> Result<(), LimitExceeded> {
        let mut stack = vec![start];
        let mut stack_bytes = 0u64;
        let result = (|| {
            while let Some(mut rs) = stack.pop() {
                if (self.built.objects as i64) >= self.max_objects {
                    break;
                }
                stack_bytes = stack_bytes.saturating_sub(state_bytes(&rs));
                self.built.generations += 1;
                self.restart_streams(&mut rs.state);
                // Structure Synth `continue`s here without removing a pruned
                // state (Builder.cpp:90-91), so it never ends; it is dropped instead.
                self.apply_pending(&rs)?;
                let children = std::mem::take(&mut self.next);
                stack_bytes += std::mem::take(&mut self.next_bytes);
                stack.extend(children.into_iter().rev());
            }
            Ok(())
        })();
        self.budget.release_memory(stack_bytes);
        result
    }

    /// Builder.cpp:155-158: a state after `set seed initial` restarts both
    /// streams from its seed and hands a fresh seed to its children.
    fn restart_streams(&mut self, state: &mut State) {
        if state.seed != 0 {
            self.reseed(state.seed);
            state.seed = self.geometry.next_u32();
        }
    }

    /// Applies one pending rule state after the size checks (Builder.cpp:165-173).
    fn apply_pending(&mut self, rs: &RuleState<'a>) -> Result<(), LimitExceeded> {
        self.budget.charge_step()?;
        if self.max_size != 0.0 || self.min_size != 0.0 {
            let l = (rs.state.matrix.transform_point3(DVec3::ONE) - rs.state.matrix.transform_point3(DVec3::ZERO)).length();
            if (self.max_size != 0.0 && l > self.max_size) || (self.min_size != 0.0 && l < self.min_size) {
                return Ok(());
            }
        }
        let mut state = rs.state.clone();
        match rs.what {
            Pending::Top => self.run_actions(&self.script.top, &mut state, None),
            Pending::Target(t) => self.apply_target(t, &mut state),
        }
    }

    /// Applies `target` in `state`. A retired rule's substitute runs in
    /// place; the chain is followed in a loop (one step each), so a rule that
    /// retires into itself forever ends at the step limit instead of
    /// overflowing the stack (as Structure Synth's recursion would).
    fn apply_target(&mut self, target: &'a Target, state: &mut State) -> Result<(), LimitExceeded> {
        let mut target = target;
        loop {
            let name = match target {
                Target::Rule(name) => *name,
                Target::Primitive(p, class) => return self.draw(*p, *class, state, None),
                Target::Triangle(pts, class) => return self.draw(Primitive::Template, *class, state, Some(pts)),
            };
            let pick = self.choose(&self.script.groups[name as usize]);
            match self.apply_rule(pick, state)? {
                Some(substitute) => {
                    self.budget.charge_step()?;
                    target = substitute;
                }
                None => return Ok(()),
            }
        }
    }

    /// `AmbiguousRule::apply` (AmbiguousRule.cpp:24-48): one geometry draw
    /// picks a definition by weight; a rule with one definition draws nothing.
    fn choose(&mut self, defs: &[u32]) -> u32 {
        if let [only] = defs {
            return *only;
        }
        let weight = |d: u32| self.script.rules.get(d as usize).map_or(0.0, |r| r.weight);
        let total: f64 = defs.iter().map(|&d| weight(d)).sum();
        let r = total * self.geometry.double();
        let mut acc = 0.0;
        for &d in defs {
            acc += weight(d);
            if r <= acc {
                return d;
            }
        }
        defs.last().copied().unwrap_or(0)
    }

    /// The maxdepth definition `index` runs with, or `None` for no limit
    /// (Structure Synth's −1). Breadth-first, a definition's own `md`.
    /// Depth-first, `RuleSet::setRulesMaxDepth` (RuleSet.cpp:42-48) first
    /// gives every rule without a positive `md` the default 1000
    /// (Builder.cpp:40-42, before the script's own `set maxdepth` runs), and
    /// every `set maxdepth N` (N > 0) then gives N to all definitions of rules
    /// with several definitions — their own `md` included, since the group's
    /// `AmbiguousRule::setMaxDepth` passes it on (AmbiguousRule.h:28).
    fn rule_maxdepth(&self, def: &RuleDef) -> Option<i64> {
        let own = def.maxdepth.filter(|&m| m != -1);
        if !self.script.depth_first {
            return own;
        }
        if self.script.groups.get(def.name as usize).is_some_and(|g| g.len() > 1) {
            return Some(self.ambiguous_maxdepth);
        }
        Some(own.filter(|&m| m > 0).unwrap_or(DEFAULT_MAX_GENERATIONS))
    }

    /// `CustomRule::apply` (CustomRule.cpp:20-54): a definition with a
    /// maxdepth counts its applications in the state, per definition; once
    /// retired it does nothing, or resets its count and runs its substitute in
    /// place, which is returned.
    fn apply_rule(&mut self, index: u32, state: &mut State) -> Result<Option<&'a Target>, LimitExceeded> {
        let def: &'a RuleDef = &self.script.rules[index as usize];
        let mut calling = None;
        if let Some(md) = self.rule_maxdepth(def) {
            let new_depth = match state.depth_of(index) {
                None => md - 1,
                Some(d) if d <= 0 => {
                    if let Some(r) = &def.retirement {
                        state.set_depth(index, md);
                        return Ok(Some(r));
                    }
                    return Ok(None);
                }
                Some(d) => d - 1,
            };
            calling = Some((index, new_depth));
        }
        self.run_actions(&def.actions, state, calling)?;
        Ok(None)
    }

    fn run_actions(&mut self, actions: &'a [Action], state: &mut State, calling: Option<(u32, i64)>) -> Result<(), LimitExceeded> {
        for a in actions {
            match a {
                Action::Set(s, _) => self.set(s, state),
                Action::Call { loops, target, .. } => self.call(loops, target, state, calling)?,
            }
        }
        Ok(())
    }

    /// `Builder::setCommand` (Builder.cpp:244-387), for the settings that reach the builder.
    fn set(&mut self, s: &Setting, state: &mut State) {
        match s {
            Setting::MaxDepth(n) => {
                self.max_generations = *n;
                if self.script.depth_first && *n > 0 {
                    self.ambiguous_maxdepth = *n;
                }
            }
            Setting::MaxObjects(n) => self.max_objects = *n,
            Setting::MinSize(v) => self.min_size = *v,
            Setting::MaxSize(v) => self.max_size = *v,
            Setting::Seed(Some(n)) => self.reseed(*n as u32),
            Setting::Seed(None) => {
                if self.initial_seed == 0 {
                    self.initial_seed = self.geometry.next_u32();
                }
                state.seed = self.initial_seed;
            }
            Setting::Background(rgb) => {
                let c = rgb.map(|v| colour::srgb_to_linear(f64::from(v) / 255.0) as f32);
                self.built.scene.background = Some([c[0], c[1], c[2], 1.0]);
            }
            Setting::ColourPool(p) => self.pool = p.clone(),
            Setting::SyncRandom(b) => self.sync_random = *b,
            Setting::Camera(c) => self.view.get_or_insert_with(View::default).set(*c),
            Setting::Ignored => {}
        }
    }

    /// `Action::apply` (Action.cpp:11-66): queues `target` once per loop
    /// copy, in Structure Synth's counter order ([`loop_counters`]). A copy
    /// applies each loop's step as many times as its counter says, afresh
    /// (Action.cpp:42-46); when no step draws a random colour the copies are
    /// made incrementally instead — copy k is copy k − 1 with the step applied
    /// once more, the same operations in the same order — so N copies cost N
    /// steps, not N²/2. With `color random` every application draws, as in
    /// Structure Synth, so the copies are made afresh.
    fn call(&mut self, loops: &'a [Loop], target: &'a Target, state: &State, calling: Option<(u32, i64)>) -> Result<(), LimitExceeded> {
        let mut base = state.clone();
        if let Some((def, d)) = calling {
            base.set_depth(def, d);
        }
        if loops.is_empty() {
            return self.queue(target, base);
        }
        base.previous = Some(state.matrix);
        let per_state = STATE_BYTES.saturating_add(16 * base.depths.len() as u64);
        let reps: Vec<u32> = loops.iter().map(|l| l.count).collect();
        let mut held = 0u64;
        let result = (|| {
            if loops.iter().any(|l| l.transform.draws_colour()) {
                for counters in loop_counters(&reps) {
                    let mut s = base.clone();
                    for (l, &c) in loops.iter().zip(&counters) {
                        for _ in 0..c {
                            self.budget.charge_step()?;
                            self.transform(&mut s, &l.transform);
                        }
                    }
                    self.queue(target, s)?;
                }
                return Ok(());
            }
            // Every copy's counters lie in 1..=max(count, 1): build those states level by level.
            let widths: Vec<usize> = reps.iter().map(|&r| r.max(1) as usize).collect();
            let mut level = vec![base];
            for (l, &w) in loops.iter().zip(&widths) {
                let n = (level.len() as u64).saturating_mul(w as u64);
                // Reserved before allocating, so a huge loop fails on memory, not on allocation.
                self.budget.reserve_memory(n.saturating_mul(per_state))?;
                held = held.saturating_add(n.saturating_mul(per_state));
                let mut next = Vec::with_capacity(n as usize);
                for s in &level {
                    let mut cur = s.clone();
                    for _ in 0..w {
                        self.budget.charge_step()?;
                        self.transform(&mut cur, &l.transform);
                        next.push(cur.clone());
                    }
                }
                level = next;
            }
            for counters in loop_counters(&reps) {
                // `level` is indexed with the first loop slowest.
                let index = counters.iter().zip(&widths).fold(0usize, |acc, (&c, &w)| acc * w + (c as usize - 1));
                let Some(s) = level.get(index).cloned() else { continue };
                self.queue(target, s)?;
            }
            Ok(())
        })();
        self.budget.release_memory(held);
        result
    }

    /// Appends a rule state to the next generation (`getNextStack().append`).
    fn queue(&mut self, target: &'a Target, state: State) -> Result<(), LimitExceeded> {
        let rs = RuleState { what: Pending::Target(target), state };
        let bytes = state_bytes(&rs);
        self.budget.reserve_memory(bytes)?;
        self.next_bytes += bytes;
        self.next.push(rs);
        Ok(())
    }

    /// Structure Synth's `Transformation::apply` (Transformation.cpp:32-107).
    fn transform(&mut self, s: &mut State, t: &Transform) {
        s.matrix *= t.matrix;
        if t.absolute {
            if t.delta_h > 360.0 {
                s.hsv = self.draw_colour();
                s.alpha = 1.0;
            } else {
                s.hsv = [t.delta_h, t.scale_s, t.scale_v];
                s.alpha = t.scale_a;
            }
        } else {
            let mut h = s.hsv[0] + t.delta_h;
            if h.is_finite() {
                h = h.rem_euclid(360.0);
            } else {
                h = 0.0;
            }
            s.hsv = [h, (s.hsv[1] * t.scale_s).clamp(0.0, 1.0), (s.hsv[2] * t.scale_v).clamp(0.0, 1.0)];
            s.alpha = (s.alpha * t.scale_a).clamp(0.0, 1.0);
        }
        if let Some((bl, strength)) = t.blend {
            let mut b = [0.0; 3];
            for k in 0..3 {
                b[k] = (s.hsv[k] + strength * bl[k]) / (1.0 + strength);
            }
            b[0] = if b[0].is_finite() { b[0].rem_euclid(360.0) } else { 0.0 };
            s.hsv = [b[0], b[1].clamp(0.0, 1.0), b[2].clamp(0.0, 1.0)];
        }
    }

    /// `ColorPool::drawColor` (ColorPool.cpp:62-84): a colour from the
    /// current pool, from the colour stream, as HSV.
    fn draw_colour(&mut self) -> [f64; 3] {
        match &self.pool {
            ColourPool::RandomHue => [f64::from(self.colour.int_to(359)), 1.0, 1.0],
            ColourPool::Greyscale => {
                let g = self.colour.int_to(255) as u8;
                colour::rgb_to_hsv([g, g, g])
            }
            ColourPool::RandomRgb => {
                let r = self.colour.int_to(255) as u8;
                let g = self.colour.int_to(255) as u8;
                let b = self.colour.int_to(255) as u8;
                colour::rgb_to_hsv([r, g, b])
            }
            ColourPool::List(list) => {
                let n = list.len().saturating_sub(1) as u32;
                let i = self.colour.int_to(n) as usize;
                let rgb = list.get(i).copied().unwrap_or([255, 255, 255]);
                colour::rgb_to_hsv(rgb)
            }
        }
    }

    /// Draws primitive `p` (or the triangle `tri`) in state `s`.
    fn draw(&mut self, p: Primitive, class: u32, s: &State, tri: Option<&[DVec3; 3]>) -> Result<(), LimitExceeded> {
        let rgb = colour::hsv_to_rgb(s.hsv).map(colour::srgb_to_linear);
        let at = Placement { matrix: s.matrix, previous: s.previous, colour: [rgb[0] as f32, rgb[1] as f32, rgb[2] as f32, s.alpha.clamp(0.0, 1.0) as f32] };
        Canvas { opts: &self.opts, budget: self.budget, built: &mut self.built }.draw(p, class, &at, tri)
    }
}

/// The loop counters of `Action::apply`, copy by copy, in Structure Synth's
/// order (Action.cpp:22-23, 52-63): every counter starts at 1 and the first
/// runs fastest. A loop of count 0 still makes its one copy — the counters
/// are checked only after a copy is made — so `0 * { x 1 } box` draws one
/// box, as in Structure Synth.
fn loop_counters(reps: &[u32]) -> impl Iterator<Item = Vec<u32>> + '_ {
    let mut counters = (!reps.is_empty()).then(|| vec![1u32; reps.len()]);
    std::iter::from_fn(move || {
        let current = counters.take()?;
        let mut next = current.clone();
        next[0] += 1;
        let mut done = false;
        for i in 0..next.len() {
            if next[i] > reps[i] {
                if i == next.len() - 1 {
                    done = true;
                } else {
                    next[i] = 1;
                    next[i + 1] += 1;
                }
            }
        }
        if !done {
            counters = Some(next);
        }
        Some(current)
    })
}

#[cfg(test)]
mod tests {
    use super::loop_counters;

    #[test]
    fn loop_counters_follow_action_apply() {
        let all = |r: &[u32]| loop_counters(r).collect::<Vec<_>>();
        assert_eq!(all(&[2, 2]), [vec![1, 1], vec![2, 1], vec![1, 2], vec![2, 2]]);
        assert_eq!(all(&[3]).len(), 3);
        // A zero count makes one copy, and a zero last loop ends after the first.
        assert_eq!(all(&[0]), [vec![1]]);
        assert_eq!(all(&[4, 0]), [vec![1, 1]]);
        // A zero first loop carries into the next one at every copy.
        assert_eq!(all(&[0, 3]), [vec![1, 1], vec![1, 2], vec![1, 3]]);
    }
}
