//! Depth-first evaluation of the IR into a [`Scene`], with an explicit stack.
//!
//! No Rust recursion follows the grammar: every pending piece of work is a
//! task (see [`super::machine`]) on a heap-allocated stack whose peak size is charged to the
//! memory budget. Each call's random stream key is derived from its parent's
//! key, its call site and its iteration index (see [`StreamKey`]), so results
//! do not depend on the order in which work is done.
//!
//! This module is the entry point ([`evaluate`], [`EvalOptions`],
//! [`promised_bytes`]); the work is split by job into sibling modules:
//! `adjust` (adjustment lists, contexts, expression environment), `machine`
//! (the task stack and dispatch), `lines` (pens and swept lines), `shapes`
//! (free vertices, isosurfaces, meshes), `select` (rule selection) and
//! `paths` (path rules, convolution, animation bones, the camera).

use super::adjust::Ctx;
use super::lines::line_sides;
use super::machine::{Evaluator, Machine};
use crate::core::budget::{Budget, OnLimit};
use crate::core::frame::Frame;
use crate::core::rng::StreamKey;
use crate::geom::{primitives, sweep};
use crate::ir::{Program, RuleTransform};
use crate::model::animation::Rig;
use crate::model::scene::Scene;
use crate::model::instancing::{Placement, Tally};
use crate::model::{Downstream, EvalError, Hierarchy};

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
pub(crate) fn promised_bytes(scene: &Scene, options: &EvalOptions) -> u64 {
    let d = &options.downstream;
    // The machine's charges replayed: primitives and shapes are tallied apart.
    let mut tally = Tally::new(d.per_instance);
    let instances = scene.instances.iter().fold(0u64, |acc, i| {
        let bytes = d.bytes(primitives::vertex_count(i.kind, options.detail), primitives::triangle_count(i.kind, options.detail));
        acc.saturating_add(tally.cost(Placement::key_of_instance(i), 0, bytes).1)
    });
    let lines = scene.lines.iter().fold(0u64, |acc, l| {
        let n = line_sides(scene, l.profile, options.detail);
        let (v, t) = sweep::per_point_bound(n);
        acc.saturating_add(d.bytes(v, t).saturating_mul(l.points.len() as u64))
    });
    let vertices = d.bytes(1, 1).saturating_mul(scene.vertices.len() as u64);
    let shapes = scene.shape_instances.iter().fold(0u64, |acc, s| {
        let (v, t) = scene.shapes.get(s.shape as usize).map_or((0, 0), |p| (p.positions.len() as u64, (p.indices.len() / 3) as u64));
        acc.saturating_add(tally.cost(Placement::of_shape(s).map(|p| p.key), 0, d.bytes(v, t)).1)
    });
    instances.saturating_add(lines).saturating_add(vertices).saturating_add(shapes)
}

impl Default for EvalOptions {
    fn default() -> Self {
        EvalOptions { seed: None, detail: crate::geom::DEFAULT_DETAIL, on_limit: OnLimit::Error, downstream: Downstream::default() }
    }
}

/// The linear RGB every primitive of a program that never sets a colour is
/// drawn in: a light neutral grey, so such a grammar looks like a clay model
/// in every format (glTF, 3MF, coloured STL, the PNG preview) instead of a
/// black silhouette. A program that sets any colour starts at black as the
/// thesis says, so explicit colours (black included) are kept exactly.
pub(crate) const NEUTRAL_GREY: f64 = 0.8;

/// The colour offsets evaluation starts from: black, or [`NEUTRAL_GREY`]
/// when the program never adds to red, green or blue ([`Program::sets_colour`]).
fn base_colour(program: &Program) -> [f64; 4] {
    if program.sets_colour() {
        [0.0; 4]
    } else {
        [NEUTRAL_GREY, NEUTRAL_GREY, NEUTRAL_GREY, 0.0]
    }
}

/// The memoised derivation of `program` as an object hierarchy
/// (`eval::memo`), or `None` when some reachable rule uses a construct that
/// cannot be shared (`eval::share`) or when nothing would be shared (no
/// object is placed twice), in which case nothing was charged to `budget`.
/// Its leaves, walked, are the instances [`evaluate`] places, in order.
pub fn evaluate_hierarchy(program: &Program, params: &[f64], options: &EvalOptions, budget: &mut Budget) -> Result<Option<Hierarchy>, EvalError> {
    hierarchy_of(&Evaluator::new(program, params, options, None)?, budget)
}

/// [`evaluate_hierarchy`] with the evaluator made already: `build_model`
/// makes one for both attempts (a hierarchy, then the flat scene when
/// there is none to share), since making it evaluates every constant
/// adjustment of the program (issue 33: twice was 4 % of a fresh icon).
pub(super) fn hierarchy_of(ev: &Evaluator<'_>, budget: &mut Budget) -> Result<Option<Hierarchy>, EvalError> {
    let program = ev.program;
    if !super::share::shareable(ev) {
        return Ok(None);
    }
    let mark = budget.mark();
    let h = super::memo::build(ev, base_colour(program), budget)?;
    if h.multiplicities().iter().all(|&m| m <= 1) {
        budget.rewind(mark);
        return Ok(None);
    }
    Ok(Some(h))
}

/// The program's `background` colour as the scene carries it.
pub(super) fn background(program: &Program) -> Option<[f32; 4]> {
    program.directives.background.map(|c| c.map(|v| v.clamp(0.0, 1.0) as f32))
}

/// Evaluates `program` with bound `params` into a scene, under `budget`.
pub fn evaluate(program: &Program, params: &[f64], options: &EvalOptions, budget: &mut Budget) -> Result<Scene, EvalError> {
    scene_of(&Evaluator::new(program, params, options, None)?, options, budget)
}

/// [`evaluate`] with the evaluator made already (see [`hierarchy_of`]).
pub(super) fn scene_of(ev: &Evaluator<'_>, options: &EvalOptions, budget: &mut Budget) -> Result<Scene, EvalError> {
    let program = ev.program;
    let seed = options.seed.or(program.directives.randseed).unwrap_or(0);
    let animated = program.groups.iter().flat_map(|g| &g.rules).any(|r| matches!(r.transform, RuleTransform::Animate(_)));
    let scene = Scene {
        background: background(program),
        rig: animated.then(|| Rig::new(ev.timeline)),
        ..Scene::default()
    };
    let root = Ctx { frame: Frame::IDENTITY, colour: base_colour(program), depth: 0, key: StreamKey::root(seed), bone: 0, ns: 0 };
    let mut m = Machine::new(ev, budget, scene, None, root.key);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::{Limit, Limits};
    use crate::core::Span;
    use crate::expr::Expr;
    use crate::ir::{Adjust, AdjustOp, Axis, Item, Iterate, Selector, Target};
    use crate::ir::{Call, Directives, PrimitiveKind, Rule, RuleGroup};

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
            continues: false,
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
        let bad = Expr::Binary(crate::expr::BinOp::Div, Box::new(num(1.0)), Box::new(num(0.0)));
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
