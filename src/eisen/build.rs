//! Structure Synth's builder: runs a parsed [`Script`] into a [`Scene`].
//!
//! Breadth-first by default, as Structure Synth 1.5 does it: generation
//! after generation, every pending rule state is applied in order and
//! queues its children (primitives too are queued, and drawn when their
//! generation runs). `set maxdepth` bounds the generations, and `set
//! maxobjects` stops at the first generation boundary where the objects
//! drawn, or the states pending, reach it — so which objects a cut-off keeps
//! is the same as in Structure Synth. `set recursion depth` switches to
//! depth-first expansion, where every rule without its own `maxdepth`
//! retires at the global `maxdepth`.
//!
//! Randomness is per branch: every queued state carries a stream key derived
//! from its parent's key, its action and its loop copy ([`StreamKey`]), so a
//! choice depends only on where in the derivation it is made. (Structure
//! Synth draws from one global Mersenne Twister in evaluation order; the
//! numbers differ, the distributions and `set seed` reproducibility are the
//! same.)

use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::core::rng::StreamKey;
use crate::model::scene::{AffineInstance, FreeVertex, Scene, AFFINE_INSTANCE_BYTES, FREE_VERTEX_BYTES};
use crate::model::EvalError;
use crate::model::Camera;
use crate::lang::eisen::{colour, Action, CameraSetting, ColourPool, Loop, Primitive, RuleDef, Script, Setting, Target, Transform};
use crate::core::PrimitiveKind;
use glam::{DMat3, DMat4, DVec3, Mat3};

/// Structure Synth's default `maxdepth` (generations).
pub const DEFAULT_MAX_GENERATIONS: i64 = 1000;
/// Structure Synth's default `maxobjects`.
pub const DEFAULT_MAX_OBJECTS: i64 = 100_000;
/// Default half-thickness of `line`, `grid` and `dot` solids, in units of the local frame.
pub const DEFAULT_LINE_RADIUS: f64 = 0.01;

/// Structure Synth's default view: the model 20 units in front of the eye.
pub const DEFAULT_VIEW_TRANSLATION: [f64; 3] = [0.0, 0.0, -20.0];
/// Structure Synth's default vertical field of view, degrees.
pub const DEFAULT_PERSPECTIVE_ANGLE: f64 = 22.0;

/// The viewer settings seen so far: Structure Synth's view maps a world
/// point p to `translation + rotation · (scale · (p − pivot))`, the eye at
/// the view-space origin looking down −Z.
#[derive(Debug, Clone, Copy, PartialEq)]
struct View {
    translation: DVec3,
    rotation: DMat3,
    pivot: DVec3,
    scale: f64,
    angle: f64,
}

impl Default for View {
    fn default() -> Self {
        View { translation: DVec3::from_array(DEFAULT_VIEW_TRANSLATION), rotation: DMat3::IDENTITY, pivot: DVec3::ZERO, scale: 1.0, angle: DEFAULT_PERSPECTIVE_ANGLE }
    }
}

impl View {
    /// The eye in world space: the inverse of the view map at the view origin.
    fn camera(&self) -> Option<Camera> {
        // Structure Synth's saved rotations are rotations up to rounding; re-orthonormalise.
        let q = glam::DQuat::from_mat3(&self.rotation).normalize();
        if !q.is_finite() || !(self.scale.is_finite() && self.scale > 0.0) {
            return None;
        }
        let inverse = q.conjugate();
        let position = self.pivot - (inverse * self.translation) / self.scale;
        let fov = self.angle.clamp(1.0, 179.0).to_radians();
        position.is_finite().then(|| Camera::still(position.as_vec3().to_array(), inverse.as_quat().normalize().to_array(), fov as f32))
    }
}

/// What the builder needs besides the script.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BuildOptions {
    /// The initial seed (`set seed N` in the script replaces it from that point on).
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
}

/// The state a rule runs in: Structure Synth's `State`.
#[derive(Debug, Clone, PartialEq)]
struct State {
    matrix: DMat4,
    /// The matrix before the last loop step (what `mesh` joins to).
    previous: DMat4,
    hsv: [f64; 3],
    alpha: f64,
    /// Remaining depth per rule definition with a `maxdepth`.
    depths: Vec<(u32, i64)>,
    key: StreamKey,
    /// Nesting depth (rule applications from the start), for the depth budget.
    depth: u32,
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
    initial: StreamKey,
    /// The stream of the rule state being applied, and how many numbers it has drawn.
    stream: StreamKey,
    draws: u32,
    next: Vec<RuleState<'a>>,
    next_bytes: u64,
    built: Built,
    /// The viewer settings, once a script sets one.
    view: Option<View>,
}

/// Runs `script` under `budget`.
pub fn build(script: &Script, opts: &BuildOptions, budget: &mut Budget) -> Result<Built, EvalError> {
    let initial = StreamKey::root(opts.seed);
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
        initial,
        stream: initial,
        draws: 0,
        next: Vec::new(),
        next_bytes: 0,
        built: Built::default(),
        view: None,
    };
    b.built.scene.classes = script.classes.clone();
    let start = RuleState {
        what: Pending::Top,
        state: State {
            matrix: DMat4::IDENTITY,
            previous: DMat4::IDENTITY,
            hsv: [0.0, 1.0, 1.0],
            alpha: 1.0,
            depths: Vec::new(),
            key: initial,
            depth: 0,
        },
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
    fn breadth_first(&mut self, start: RuleState<'a>) -> Result<(), LimitExceeded> {
        let mut stack = vec![start];
        let mut stack_bytes = 0;
        let mut generation: i64 = 0;
        let result = (|| {
            while !stack.is_empty()
                && generation < self.max_generations
                && (self.built.objects as i64) < self.max_objects
                && (stack.len() as i64) < self.max_objects
            {
                generation += 1;
                let sync = self.initial.child(u32::MAX, generation as u64);
                for rs in &stack {
                    let key = if self.sync_random { sync } else { rs.state.key };
                    self.apply_pending(rs, key)?;
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

    fn depth_first(&mut self, start: RuleState<'a>) -> Result<(), LimitExceeded> {
        // A stack whose top is the front of Structure Synth's list: children
        // are pushed in reverse so the first child runs next.
        let mut stack = vec![start];
        let mut stack_bytes = 0u64;
        let result = (|| {
            while let Some(rs) = stack.pop() {
                if (self.built.objects as i64) >= self.max_objects {
                    break;
                }
                stack_bytes = stack_bytes.saturating_sub(state_bytes(&rs));
                self.built.generations += 1;
                self.apply_pending(&rs, rs.state.key)?;
                let children = std::mem::take(&mut self.next);
                stack_bytes += std::mem::take(&mut self.next_bytes);
                stack.extend(children.into_iter().rev());
            }
            Ok(())
        })();
        self.budget.release_memory(stack_bytes);
        result
    }

    /// Applies one pending rule state (after the size checks), drawing random numbers from `key`.
    fn apply_pending(&mut self, rs: &RuleState<'a>, key: StreamKey) -> Result<(), LimitExceeded> {
        self.budget.charge_step()?;
        self.budget.check_depth(rs.state.depth)?;
        if self.max_size != 0.0 || self.min_size != 0.0 {
            let l = (rs.state.matrix.transform_point3(DVec3::ONE) - rs.state.matrix.transform_point3(DVec3::ZERO)).length();
            if (self.max_size != 0.0 && l > self.max_size) || (self.min_size != 0.0 && l < self.min_size) {
                return Ok(());
            }
        }
        self.stream = key;
        self.draws = 0;
        let mut state = rs.state.clone();
        state.key = key;
        match rs.what {
            Pending::Top => self.run_actions(&self.script.top, &state, None),
            Pending::Target(t) => self.apply_target(t, &mut state),
        }
    }

    fn uniform(&mut self) -> f64 {
        self.draws += 1;
        self.stream.uniform(self.draws)
    }

    /// Applies `target` in `state`. A retired rule's substitute runs in
    /// place; the chain is followed in a loop (one step each), so a rule that
    /// retires into itself forever ends at the step limit instead of
    /// overflowing the stack.
    fn apply_target(&mut self, target: &'a Target, state: &mut State) -> Result<(), LimitExceeded> {
        let mut target = target;
        loop {
            let name = match target {
                Target::Rule(name) => *name,
                Target::Primitive(p, class) => return self.draw(*p, *class, state, None),
                Target::Triangle(pts, class) => return self.draw(Primitive::Template, *class, state, Some(pts)),
            };
            let defs = &self.script.groups[name as usize];
            let pick = if defs.len() == 1 {
                defs[0]
            } else {
                let total: f64 = defs.iter().map(|&d| self.script.rules[d as usize].weight).sum();
                let r = total * self.uniform();
                let mut acc = 0.0;
                let mut chosen = defs[defs.len() - 1];
                for &d in defs {
                    acc += self.script.rules[d as usize].weight;
                    if r <= acc {
                        chosen = d;
                        break;
                    }
                }
                chosen
            };
            match self.apply_rule(pick, state)? {
                Some(substitute) => {
                    self.budget.charge_step()?;
                    target = substitute;
                }
                None => return Ok(()),
            }
        }
    }

    /// Structure Synth's `CustomRule::apply`, with rule retirement: returns
    /// the substitute to run in place when the rule has retired.
    fn apply_rule(&mut self, index: u32, state: &mut State) -> Result<Option<&'a Target>, LimitExceeded> {
        let def: &'a RuleDef = &self.script.rules[index as usize];
        let maxdepth = def.maxdepth.or((self.script.depth_first && self.max_generations > 0).then_some(self.max_generations));
        let mut calling = None;
        if let Some(md) = maxdepth {
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

    fn run_actions(&mut self, actions: &'a [Action], state: &State, calling: Option<(u32, i64)>) -> Result<(), LimitExceeded> {
        for a in actions {
            match a {
                Action::Set(s, _) => self.set(s, state),
                Action::Call { loops, target, site, .. } => self.call(loops, target, *site, state, calling)?,
            }
        }
        Ok(())
    }

    fn set(&mut self, s: &Setting, _state: &State) {
        match s {
            Setting::MaxDepth(n) => self.max_generations = *n,
            Setting::MaxObjects(n) => self.max_objects = *n,
            Setting::MinSize(v) => self.min_size = *v,
            Setting::MaxSize(v) => self.max_size = *v,
            // Reseeding changes the stream of the state being applied, so its
            // children (and their random choices) follow the new seed.
            Setting::Seed(Some(n)) => {
                self.stream = StreamKey::root(*n as u64);
                self.draws = 0;
            }
            Setting::Seed(None) => {
                self.stream = self.initial;
                self.draws = 0;
            }
            Setting::Background(rgb) => {
                let c = rgb.map(|v| colour::srgb_to_linear(f64::from(v) / 255.0) as f32);
                self.built.scene.background = Some([c[0], c[1], c[2], 1.0]);
            }
            Setting::ColourPool(p) => self.pool = p.clone(),
            Setting::SyncRandom(b) => self.sync_random = *b,
            Setting::Camera(c) => {
                let v = self.view.get_or_insert_with(View::default);
                match *c {
                    CameraSetting::Translation(t) => v.translation = t,
                    CameraSetting::Rotation(r) => v.rotation = r,
                    CameraSetting::Pivot(p) => v.pivot = p,
                    CameraSetting::Scale(s) => v.scale = s,
                    CameraSetting::PerspectiveAngle(a) => v.angle = a,
                }
            }
            Setting::Ignored => {}
        }
    }

    /// Structure Synth's `Action::apply`: queues `target` once per loop copy,
    /// in Structure Synth's order (the first loop's copy index runs fastest).
    /// Each loop's copies are made incrementally — copy k is copy k − 1 with
    /// the step applied once more, the same operations in the same order as
    /// applying it k times afresh — so N copies cost N steps, not N²/2.
    fn call(&mut self, loops: &'a [Loop], target: &'a Target, site: u32, state: &State, calling: Option<(u32, i64)>) -> Result<(), LimitExceeded> {
        let parent = self.stream.child(self.draws, 0);
        if loops.iter().any(|l| l.count == 0) {
            return Ok(());
        }
        let mut base = state.clone();
        if !loops.is_empty() {
            base.previous = state.matrix;
        }
        if let Some((def, d)) = calling {
            base.set_depth(def, d);
        }
        base.depth = state.depth.saturating_add(1);
        let per_state = STATE_BYTES.saturating_add(16 * base.depths.len() as u64);
        let mut held = 0u64;
        let result = (|| {
            let mut level = vec![base];
            for l in loops {
                let n = (level.len() as u64).saturating_mul(u64::from(l.count));
                // Reserved before allocating, so a huge loop fails on memory, not on allocation.
                self.budget.reserve_memory(n.saturating_mul(per_state))?;
                held = held.saturating_add(n.saturating_mul(per_state));
                let mut next = Vec::with_capacity(n as usize);
                for s in &level {
                    let mut cur = s.clone();
                    for _ in 0..l.count {
                        self.budget.charge_step()?;
                        self.transform(&mut cur, &l.transform);
                        next.push(cur.clone());
                    }
                }
                level = next;
            }
            // `level` has the first loop's index slowest; Structure Synth runs it fastest.
            let counts: Vec<usize> = loops.iter().map(|l| l.count as usize).collect();
            let mut states: Vec<Option<State>> = level.into_iter().map(Some).collect();
            for copy in 0..states.len() {
                let (mut rem, mut index) = (copy, 0);
                let mut digits = vec![0usize; counts.len()];
                for (d, &c) in digits.iter_mut().zip(&counts) {
                    *d = rem % c;
                    rem /= c;
                }
                for (d, &c) in digits.iter().zip(&counts) {
                    index = index * c + d;
                }
                let Some(mut s) = states.get_mut(index).and_then(Option::take) else { continue };
                s.key = parent.child(site, copy as u64);
                let rs = RuleState { what: Pending::Target(target), state: s };
                let bytes = state_bytes(&rs);
                self.budget.reserve_memory(bytes)?;
                self.next_bytes += bytes;
                self.next.push(rs);
            }
            Ok(())
        })();
        self.budget.release_memory(held);
        result
    }

    /// Structure Synth's `Transformation::apply`.
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

    /// A colour from the current pool (`color random`), as HSV.
    fn draw_colour(&mut self) -> [f64; 3] {
        let int = |u: f64, max: u32| ((u * f64::from(max + 1)).floor() as u32).min(max);
        match self.pool.clone() {
            ColourPool::RandomHue => [f64::from(int(self.uniform(), 359)), 1.0, 1.0],
            ColourPool::Greyscale => {
                let g = int(self.uniform(), 255) as u8;
                colour::rgb_to_hsv([g, g, g])
            }
            ColourPool::RandomRgb => {
                let r = int(self.uniform(), 255) as u8;
                let g = int(self.uniform(), 255) as u8;
                let b = int(self.uniform(), 255) as u8;
                colour::rgb_to_hsv([r, g, b])
            }
            ColourPool::List(list) => {
                let n = list.len() as u32;
                let i = int(self.uniform(), n.saturating_sub(1)) as usize;
                let rgb = list.get(i).copied().unwrap_or([255, 255, 255]);
                colour::rgb_to_hsv(rgb)
            }
        }
    }

    /// The state's colour as linear RGBA.
    fn colour(s: &State) -> [f32; 4] {
        let rgb = colour::hsv_to_rgb(s.hsv).map(colour::srgb_to_linear);
        [rgb[0] as f32, rgb[1] as f32, rgb[2] as f32, s.alpha.clamp(0.0, 1.0) as f32]
    }

    /// Draws primitive `p` (or the triangle `tri`) in state `s`.
    fn draw(&mut self, p: Primitive, class: u32, s: &State, tri: Option<&[DVec3; 3]>) -> Result<(), LimitExceeded> {
        let colour = Self::colour(s);
        let m = s.matrix;
        let r = self.opts.line_radius;
        let mut placed: Vec<(PrimitiveKind, DMat3, DVec3)> = Vec::new();
        let mut faces: Vec<[DVec3; 3]> = Vec::new();
        let lin = DMat3::from_mat4(m);
        let size = lin.determinant().abs().cbrt();
        let size = if size.is_finite() && size > 0.0 { size } else { (lin.x_axis.length() + lin.y_axis.length() + lin.z_axis.length()) / 3.0 };
        let half = DVec3::splat(0.5);
        match (p, tri) {
            (_, Some(pts)) => {
                let [a, b, c] = pts.map(|q| m.transform_point3(q));
                // Both sides, so the triangle shows from either side.
                faces.push([a, b, c]);
                faces.push([a, c, b]);
            }
            (Primitive::Box, _) => placed.push((PrimitiveKind::Box, lin, m.transform_point3(half))),
            (Primitive::Sphere, _) => placed.push((PrimitiveKind::Sphere, lin, m.transform_point3(half))),
            (Primitive::Cylinder, _) => {
                // The prototype's axis is +Y; Structure Synth's is local x.
                let swap = DMat3::from_cols(DVec3::Y, DVec3::X, DVec3::Z);
                let flip = DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0));
                placed.push((PrimitiveKind::Cylinder, lin * swap * flip, m.transform_point3(half)));
            }
            (Primitive::Line, _) => {
                let a = m.transform_point3(DVec3::new(0.0, 0.5, 0.5));
                let b = m.transform_point3(DVec3::new(1.0, 0.5, 0.5));
                placed.extend(bar(a, b, r * size));
            }
            (Primitive::Grid, _) => {
                for (a, b) in cube_edges() {
                    placed.extend(bar(m.transform_point3(a), m.transform_point3(b), r * size));
                }
            }
            (Primitive::Point, _) => {
                placed.push((PrimitiveKind::Icosahedron, DMat3::from_diagonal(DVec3::splat(4.0 * r * size)), m.transform_point3(half)));
            }
            (Primitive::Mesh, _) => faces.extend(mesh_solid(&s.previous, &m)),
            (Primitive::Template, None) => {}
        }
        let triangles: u64 = placed.iter().map(|(k, ..)| crate::geom::primitives::triangle_count(*k, self.opts.detail)).sum::<u64>() + faces.len() as u64;
        self.built.objects += 1;
        if triangles == 0 {
            return Ok(());
        }
        self.budget.charge_primitive(triangles)?;
        let downstream: u64 = placed.iter().map(|(k, ..)| self.opts.downstream_bytes[*k as usize]).sum::<u64>()
            + 3 * faces.len() as u64 * self.opts.vertex_bytes;
        let stored = AFFINE_INSTANCE_BYTES * placed.len() as u64 + 3 * FREE_VERTEX_BYTES * faces.len() as u64;
        self.budget.reserve_memory(stored.saturating_add(downstream))?;
        self.built.promised = self.built.promised.saturating_add(downstream);
        for (kind, l, t) in placed {
            self.built.scene.affine.push(AffineInstance {
                kind,
                linear: Mat3::from_cols(l.x_axis.as_vec3(), l.y_axis.as_vec3(), l.z_axis.as_vec3()),
                translation: t.as_vec3(),
                colour,
                class,
            });
        }
        for [a, b, c] in faces {
            let n = (b - a).cross(c - a);
            let Some(n) = n.try_normalize() else { continue };
            for v in [a, b, c] {
                self.built.scene.vertices.push(FreeVertex { position: v, normal: n, colour });
            }
        }
        Ok(())
    }
}

/// A thin square bar from `a` to `b` with half-thickness `r`, as a box.
fn bar(a: DVec3, b: DVec3, r: f64) -> Option<(PrimitiveKind, DMat3, DVec3)> {
    let d = b - a;
    if !(d.length() > 0.0) || !(r > 0.0) {
        return None;
    }
    let u = d.any_orthonormal_vector() * (2.0 * r);
    let v = d.normalize().cross(u.normalize()) * (2.0 * r);
    Some((PrimitiveKind::Box, DMat3::from_cols(d, u, v), (a + b) * 0.5))
}

/// The twelve edges of the unit cube: along each axis, from each corner of the opposite face.
fn cube_edges() -> impl Iterator<Item = (DVec3, DVec3)> {
    (0..3).flat_map(|axis: usize| {
        (0..4).map(move |k: u32| {
            let mut a = DVec3::ZERO;
            a[(axis + 1) % 3] = f64::from(k & 1);
            a[(axis + 2) % 3] = f64::from(k >> 1);
            let mut b = a;
            b[axis] = 1.0;
            (a, b)
        })
    })
}

/// The closed solid between the x = 0 unit squares of two frames, as
/// outward-facing triangles (12; degenerate ones are dropped by the caller).
fn mesh_solid(from: &DMat4, to: &DMat4) -> Vec<[DVec3; 3]> {
    let square = |m: &DMat4| [(0., 0.), (1., 0.), (1., 1.), (0., 1.)].map(|(y, z)| m.transform_point3(DVec3::new(0.0, y, z)));
    let (a, b) = (square(from), square(to));
    let centre = (a.iter().chain(b.iter()).copied().sum::<DVec3>()) / 8.0;
    let quads = [[a[0], a[1], a[2], a[3]], [b[0], b[3], b[2], b[1]], [a[0], b[0], b[1], a[1]], [a[1], b[1], b[2], a[2]], [a[2], b[2], b[3], a[3]], [a[3], b[3], b[0], a[0]]];
    let mut out = Vec::with_capacity(12);
    for q in quads {
        for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
            let n = (t[1] - t[0]).cross(t[2] - t[0]);
            let mid = (t[0] + t[1] + t[2]) / 3.0;
            out.push(if n.dot(mid - centre) < 0.0 { [t[0], t[2], t[1]] } else { t });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_edges_are_the_twelve_unit_edges() {
        let edges: Vec<(DVec3, DVec3)> = cube_edges().collect();
        assert_eq!(edges.len(), 12);
        for (i, (a, b)) in edges.iter().enumerate() {
            assert_eq!((*b - *a).length(), 1.0);
            assert!(edges[..i].iter().all(|e| e != &(*a, *b)));
        }
    }

    #[test]
    fn mesh_solid_is_closed_and_outward() {
        let from = DMat4::IDENTITY;
        for to in [DMat4::from_translation(DVec3::X), DMat4::from_translation(-2.0 * DVec3::X), DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::new(1.0, -1.0, 1.0))] {
            let tris = mesh_solid(&from, &to);
            assert_eq!(tris.len(), 12);
            // Signed volume by the divergence theorem: positive when every face points outward.
            let v: f64 = tris.iter().map(|[a, b, c]| a.dot(b.cross(*c)) / 6.0).sum();
            assert!(v > 0.0, "{v}");
        }
    }

    #[test]
    fn bars_span_their_segment() {
        let Some((kind, m, t)) = bar(DVec3::ZERO, DVec3::new(0.0, 0.0, 2.0), 0.1) else { panic!("no bar") };
        assert_eq!(kind, PrimitiveKind::Box);
        assert_eq!(t, DVec3::new(0.0, 0.0, 1.0));
        assert!((m.determinant().abs() - 2.0 * 0.2 * 0.2).abs() < 1e-12);
        assert!(bar(DVec3::ONE, DVec3::ONE, 0.1).is_none());
    }
}
