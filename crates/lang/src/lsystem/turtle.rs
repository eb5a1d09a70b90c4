//! The 3D turtle (Calgary instancing thesis §3.2, ABOP p.19): reads a derived string and
//! draws it into a [`Scene`].
//!
//! The turtle starts at the origin heading along +Y with its up vector along
//! +Z (so its left vector is −X). `+`/`-` turn about up, `&`/`^` pitch about
//! left, `\`/`/` roll about the heading, `|` turns around. Every turn takes an
//! optional angle in degrees, else the system's `angle:`.
//!
//! Segments (`F`) are swept tubes by default: each unbranched run of segments
//! is one polyline, so consecutive segments join without gaps and a branch
//! starts where its parent segment ended. With `shape: KIND` each segment is
//! instead one built-in primitive, scaled uniformly by the segment length and
//! centred on the segment.

use super::derive::ModuleString;
use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::core::frame::Frame;
use crate::model::hierarchy::LeafShape;
use crate::core::PrimitiveKind;
use crate::model::scene::{FreeVertex, Instance, LinePoint, Polyline, Scene, FREE_VERTEX_BYTES, INSTANCE_BYTES, LINE_POINT_BYTES};
use crate::model::EvalError;
use crate::geom::{primitives, sweep};
use crate::lsystem::syntax::{LSystem, Shape};
use crate::core::Span;
use glam::{DQuat, DVec3};

/// Default colour of segments (linear RGBA): a bark brown.
pub(crate) const DEFAULT_COLOUR: [f64; 4] = [0.32, 0.2, 0.1, 1.0];
/// Factor `!` without an argument multiplies the width by.
pub(crate) const WIDTH_DECREMENT: f64 = 0.7;

/// What a symbol does to the turtle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Action {
    Draw,
    Move,
    /// Local rotation: axis (0 = x, 1 = y, 2 = z) and sign.
    Turn(u8, f64),
    TurnAround,
    Push,
    Pop,
    Width,
    Colour,
    Tropism,
    RollToTropism,
    PolygonStart,
    PolygonVertex,
    PolygonEnd,
    None,
}

/// The action of the symbol called `name`.
pub(crate) fn action(name: &str) -> Action {
    match name {
        "F" => Action::Draw,
        "f" => Action::Move,
        "+" => Action::Turn(2, 1.0),
        "-" => Action::Turn(2, -1.0),
        "&" => Action::Turn(0, -1.0),
        "^" => Action::Turn(0, 1.0),
        "\\" => Action::Turn(1, 1.0),
        "/" => Action::Turn(1, -1.0),
        "|" => Action::TurnAround,
        "[" => Action::Push,
        "]" => Action::Pop,
        "!" => Action::Width,
        "'" => Action::Colour,
        "@" => Action::Tropism,
        "~" => Action::RollToTropism,
        "{" => Action::PolygonStart,
        "." => Action::PolygonVertex,
        "}" => Action::PolygonEnd,
        _ => Action::None,
    }
}

/// What interpretation needs besides the system and the string.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurtleOptions {
    /// Tessellation detail (for triangle and memory accounting).
    pub detail: u32,
    /// Fail or truncate at a limit.
    pub on_limit: OnLimit,
    /// Bytes that meshing and export will need per tube point.
    pub line_point_bytes: u64,
    /// Bytes that meshing and export will need per primitive of each kind.
    pub downstream_bytes: [u64; 9],
}

/// What the turtle drew.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Drawing {
    /// The scene.
    pub scene: Scene,
    /// Segments drawn (`F` modules).
    pub segments: u64,
    /// Memory promised for meshing and export, to be released before meshing.
    pub promised: u64,
}

/// A segment recorded instead of drawn (leaf mode, for instancing): the
/// turtle's pose at its start, its look and its colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Leaf {
    /// Position at the segment's start.
    pub pos: DVec3,
    /// Orientation (heading is local +Y).
    pub rot: DQuat,
    /// The primitive in the start frame: a cylinder of the width for tubes,
    /// the `shape:` primitive scaled by the length otherwise.
    pub shape: LeafShape,
    /// Linear RGBA in 0..=255.
    pub colour: [u8; 4],
}

#[derive(Debug, Clone, Copy)]
struct State {
    pos: DVec3,
    rot: DQuat,
    width: f64,
    colour: [f64; 4],
    /// The polyline whose last point is at `pos`, if the turtle is drawing one.
    line: Option<usize>,
}

const STATE_BYTES: u64 = std::mem::size_of::<State>() as u64;
/// Bytes accounted per open polygon and per recorded polygon vertex.
const POLYGON_BYTES: u64 = std::mem::size_of::<Vec<DVec3>>() as u64;
const VERTEX_BYTES: u64 = std::mem::size_of::<DVec3>() as u64;

/// The local rotation of a turn action: about axis `axis` (0 = x, 1 = y, 2 = z)
/// by `sign` times `degrees`.
pub(crate) fn turn_quat(axis: u8, sign: f64, degrees: f64) -> DQuat {
    let a = sign * degrees.to_radians();
    match axis {
        0 => DQuat::from_rotation_x(a),
        1 => DQuat::from_rotation_y(a),
        _ => DQuat::from_rotation_z(a),
    }
}

/// What an environment query module (Calgary instancing thesis §3.6) receives: `?P`, `?Q`,
/// `?R` and `?S` the turtle's position (the thesis's topiary uses the last
/// three like `?P`, L3572), `?H`, `?U` and `?L` its heading, up and left vectors.
fn query_kind(name: &str) -> Option<u8> {
    match name {
        "?P" | "?Q" | "?R" | "?S" => Some(0),
        "?H" => Some(1),
        "?U" => Some(2),
        "?L" => Some(3),
        _ => None,
    }
}

/// True when `sys` uses an environment query, so every derivation step must
/// be followed by an interpretation that fills the queries in.
pub(crate) fn has_queries(sys: &LSystem) -> bool {
    sys.symbols.iter().any(|n| query_kind(n).is_some())
}

/// Interprets `s` without drawing and writes, into the parameters of every
/// query module, what the turtle sees there: its position (x, y, z) or one of
/// its axes. A query with fewer parameters gets the first ones; extra
/// parameters are kept. Each module read costs one step, so the queries
/// after every derivation step are budgeted like the step itself.
pub(crate) fn fill_queries(sys: &LSystem, s: &mut ModuleString, budget: &mut Budget) -> Result<(), EvalError> {
    let kinds: Vec<Option<u8>> = sys.symbols.iter().map(|n| query_kind(n)).collect();
    let opts = TurtleOptions { detail: 0, on_limit: OnLimit::Error, line_point_bytes: 0, downstream_bytes: [0; 9] };
    let mut t = LeafTurtle::new(sys, &opts, sys.width, DEFAULT_COLOUR);
    let mut result = Ok(());
    for i in 0..s.len() {
        if let Err(e) = budget.charge_step() {
            result = Err(e.into());
            break;
        }
        let sym = s.syms[i];
        match kinds.get(sym as usize).copied().flatten() {
            Some(kind) => {
                let (pos, rot) = t.pose();
                let v = match kind {
                    0 => pos,
                    1 => rot * DVec3::Y,
                    2 => rot * DVec3::Z,
                    _ => rot * DVec3::NEG_X,
                };
                let (a, b) = (s.starts[i] as usize, s.starts[i + 1] as usize);
                for (slot, value) in s.params[a..b].iter_mut().zip(v.to_array()) {
                    *slot = value;
                }
            }
            None => {
                let (a, b) = (s.starts[i] as usize, s.starts[i + 1] as usize);
                let p: Vec<f64> = s.params[a..b].to_vec();
                if let Err(e) = t.module(sym, &p, budget) {
                    result = Err(e);
                    break;
                }
                t.take_leaves();
            }
        }
    }
    t.release(budget);
    result
}

/// A sink the modules of a string are fed into, one at a time, in string order.
pub(crate) type ModuleSink<'s> = dyn FnMut(u32, &[f64]) -> Result<(), EvalError> + 's;

fn non_finite(what: &str, v: f64) -> EvalError {
    EvalError::NonFinite { span: Span::default(), what: what.to_string(), value: format!("{v}") }
}

/// Interprets `s` into a scene under `budget`.
pub fn interpret(sys: &LSystem, s: &ModuleString, opts: &TurtleOptions, budget: &mut Budget) -> Result<Drawing, EvalError> {
    interpret_stream(sys, opts, budget, &mut |sink| {
        for i in 0..s.len() {
            sink(s.syms[i], s.params_of(i))?;
        }
        Ok(())
    })
}

/// Interprets the modules `feed` hands to its sink, in order, as if they were
/// one string: how an instancing DAG is drawn without ever building its string.
pub fn interpret_stream(
    sys: &LSystem,
    opts: &TurtleOptions,
    budget: &mut Budget,
    feed: &mut dyn FnMut(&mut ModuleSink<'_>) -> Result<(), EvalError>,
) -> Result<Drawing, EvalError> {
    let mut t = Turtle {
        sys,
        opts,
        actions: sys.symbols.iter().map(|n| action(n)).collect(),
        drawing: Drawing::default(),
        stack: Vec::new(),
        state: State { pos: DVec3::ZERO, rot: DQuat::IDENTITY, width: sys.width, colour: DEFAULT_COLOUR, line: None },
        point_tris: sweep::per_point_bound(sweep::profile_sides(opts.detail)).1,
        leaves: None,
        polygons: Vec::new(),
        read: 0,
    };
    let result = feed(&mut |sym, p| t.module(sym, p, budget));
    t.release_scratch(budget);
    match result {
        Ok(()) => {}
        Err(EvalError::Limit(l)) if opts.on_limit == OnLimit::Truncate => {
            t.drawing.scene.truncated = Some(l);
        }
        Err(e) => return Err(e),
    }
    Ok(t.drawing)
}

struct Turtle<'a> {
    sys: &'a LSystem,
    opts: &'a TurtleOptions,
    actions: Vec<Action>,
    drawing: Drawing,
    stack: Vec<State>,
    state: State,
    point_tris: u64,
    /// In leaf mode, the segments recorded instead of drawn.
    leaves: Option<Vec<Leaf>>,
    /// Open polygons (`{`), innermost last: the vertices recorded by `.` so far.
    polygons: Vec<Vec<DVec3>>,
    /// Modules read so far, to look at the deadline every 1024 of them
    /// (reading is not charged as steps; only the clock bounds it).
    read: u32,
}

/// A turtle in leaf mode: it records each segment as a [`Leaf`] in its own
/// start frame instead of drawing, and can be moved by a sub-object's end
/// state, so one subtree of a derivation becomes one reusable object.
pub(crate) struct LeafTurtle<'a> {
    t: Turtle<'a>,
}

impl<'a> LeafTurtle<'a> {
    /// A turtle at the origin with the given inherited width and colour.
    pub(crate) fn new(sys: &'a LSystem, opts: &'a TurtleOptions, width: f64, colour: [f64; 4]) -> LeafTurtle<'a> {
        LeafTurtle {
            t: Turtle {
                sys,
                opts,
                actions: sys.symbols.iter().map(|n| action(n)).collect(),
                drawing: Drawing::default(),
                stack: Vec::new(),
                state: State { pos: DVec3::ZERO, rot: DQuat::IDENTITY, width, colour, line: None },
                point_tris: 0,
                leaves: Some(Vec::new()),
                polygons: Vec::new(),
                read: 0,
            },
        }
    }

    /// Interprets one module.
    pub(crate) fn module(&mut self, sym: u32, p: &[f64], budget: &mut Budget) -> Result<(), EvalError> {
        self.t.module(sym, p, budget)
    }

    /// The segments recorded since the last call.
    pub(crate) fn take_leaves(&mut self) -> Vec<Leaf> {
        self.t.leaves.as_mut().map(std::mem::take).unwrap_or_default()
    }

    /// Position and orientation.
    pub(crate) fn pose(&self) -> (DVec3, DQuat) {
        (self.t.state.pos, self.t.state.rot)
    }

    /// Width and colour, which a sub-object inherits.
    pub(crate) fn inherited(&self) -> (f64, [f64; 4]) {
        (self.t.state.width, self.t.state.colour)
    }

    /// Moves by a sub-object's end state: `pos` and `rot` relative to the
    /// current pose, and the width and colour it ended with.
    pub(crate) fn follow(&mut self, pos: DVec3, rot: DQuat, width: f64, colour: [f64; 4]) {
        let st = &mut self.t.state;
        st.pos += st.rot * pos;
        st.rot = (st.rot * rot).normalize();
        st.width = width;
        st.colour = colour;
    }

    /// Open brackets not closed yet.
    pub(crate) fn depth(&self) -> usize {
        self.t.stack.len()
    }

    /// Returns the memory its state stack accounted.
    pub(crate) fn release(self, budget: &mut Budget) {
        self.t.release_scratch(budget);
    }
}

impl Turtle<'_> {
    /// Returns the memory of the state stack and of polygons left open.
    fn release_scratch(&self, budget: &mut Budget) {
        let open: u64 = self.polygons.iter().map(|p| POLYGON_BYTES.saturating_add(VERTEX_BYTES.saturating_mul(p.len() as u64))).sum();
        budget.release_memory((self.stack.capacity() as u64).saturating_mul(STATE_BYTES).saturating_add(open));
    }

    fn module(&mut self, sym: u32, p: &[f64], budget: &mut Budget) -> Result<(), EvalError> {
        self.read = self.read.wrapping_add(1);
        if self.read % 1024 == 0 {
            budget.check_deadline()?;
        }
        let arg = |k: usize| p.get(k).copied();
        match self.actions.get(sym as usize).copied().unwrap_or(Action::None) {
            Action::Draw => {
                let len = arg(0).unwrap_or(self.sys.length);
                if let Some(w) = arg(1) {
                    self.state.width = w;
                }
                self.draw(len, budget)?;
            }
            Action::Move => {
                let len = arg(0).unwrap_or(self.sys.length);
                self.advance(len)?;
                self.state.line = None;
            }
            Action::Turn(axis, sign) => self.turn(turn_quat(axis, sign, arg(0).unwrap_or(self.sys.angle))),
            Action::TurnAround => self.turn(DQuat::from_rotation_z(std::f64::consts::PI)),
            Action::Push => {
                if self.stack.len() == self.stack.capacity() {
                    let extra = self.stack.capacity().max(16);
                    budget.reserve_memory((extra as u64).saturating_mul(STATE_BYTES))?;
                    self.stack.reserve_exact(extra);
                }
                self.stack.push(self.state);
                self.state.line = None;
            }
            Action::Pop => {
                // An unbalanced `]` is ignored.
                if let Some(st) = self.stack.pop() {
                    self.state = st;
                }
            }
            Action::Width => {
                self.state.width = match arg(0) {
                    Some(w) => w,
                    None => self.state.width * WIDTH_DECREMENT,
                };
                if !self.state.width.is_finite() {
                    return Err(non_finite("width", self.state.width));
                }
            }
            Action::Colour => {
                if p.len() >= 3 {
                    self.state.colour = [p[0], p[1], p[2], p.get(3).copied().unwrap_or(1.0)];
                }
            }
            Action::Tropism => {
                if let Some(t) = self.sys.tropism {
                    let e = arg(0).unwrap_or(self.sys.elasticity);
                    self.tropism(DVec3::from_array(t), e);
                }
            }
            Action::RollToTropism => {
                if let Some(t) = self.sys.tropism {
                    self.roll_to(DVec3::from_array(t));
                }
            }
            Action::PolygonStart => {
                budget.reserve_memory(POLYGON_BYTES)?;
                self.polygons.push(Vec::new());
            }
            Action::PolygonVertex => {
                if let Some(poly) = self.polygons.last_mut() {
                    budget.reserve_memory(VERTEX_BYTES)?;
                    poly.push(self.state.pos);
                }
            }
            Action::PolygonEnd => {
                if let Some(poly) = self.polygons.pop() {
                    let held = POLYGON_BYTES.saturating_add(VERTEX_BYTES.saturating_mul(poly.len() as u64));
                    let r = self.polygon(&poly, budget);
                    budget.release_memory(held);
                    r?;
                }
            }
            Action::None => {}
        }
        Ok(())
    }

    /// Fills a closed polygon (ABOP p.120 `{ . }`) as a triangle fan from its
    /// first vertex, facing along its Newell normal, in the current colour.
    /// Polygons are two-sided (leaves are seen from both sides), so every
    /// triangle is written in both windings. Fewer than 3 vertices draw nothing.
    fn polygon(&mut self, poly: &[DVec3], budget: &mut Budget) -> Result<(), EvalError> {
        if poly.len() < 3 || self.leaves.is_some() {
            return Ok(());
        }
        let mut normal = DVec3::ZERO;
        for (k, a) in poly.iter().enumerate() {
            let b = poly[(k + 1) % poly.len()];
            normal += DVec3::new((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
        let normal = normal.normalize_or_zero();
        let triangles = 2 * (poly.len() as u64 - 2);
        budget.charge_primitive(triangles)?;
        budget.reserve_memory(FREE_VERTEX_BYTES.saturating_mul(3 * triangles))?;
        let colour = self.state.colour.map(|c| c.clamp(0.0, 1.0) as f32);
        let v = |position: DVec3, normal: DVec3| FreeVertex { position, normal, colour };
        for k in 1..poly.len() - 1 {
            let (a, b, c) = (poly[0], poly[k], poly[k + 1]);
            self.drawing.scene.vertices.extend([v(a, normal), v(b, normal), v(c, normal)]);
            self.drawing.scene.vertices.extend([v(a, -normal), v(c, -normal), v(b, -normal)]);
        }
        Ok(())
    }

    fn heading(&self) -> DVec3 {
        self.state.rot * DVec3::Y
    }

    fn turn(&mut self, local: DQuat) {
        self.state.rot = (self.state.rot * local).normalize();
    }

    /// Bends the heading towards `t` by e·|H×T| about H×T (Calgary instancing thesis §3.7).
    fn tropism(&mut self, t: DVec3, e: f64) {
        let h = self.heading();
        let axis = h.cross(t);
        let len = axis.length();
        if len < 1e-12 || !len.is_finite() || !e.is_finite() {
            return;
        }
        let q = DQuat::from_axis_angle(axis / len, e * len);
        self.state.rot = (q * self.state.rot).normalize();
    }

    /// Rolls about the heading so that the up vector points as nearly along `t` as possible.
    fn roll_to(&mut self, t: DVec3) {
        let h = self.heading();
        let tp = t - h * t.dot(h);
        if tp.length() < 1e-12 || !tp.is_finite() {
            return;
        }
        let up = self.state.rot * DVec3::Z;
        let sigma = libm::atan2(up.cross(tp).dot(h), up.dot(tp));
        self.state.rot = (DQuat::from_axis_angle(h, sigma) * self.state.rot).normalize();
    }

    fn advance(&mut self, len: f64) -> Result<DVec3, EvalError> {
        let to = self.state.pos + self.heading() * len;
        if !to.is_finite() {
            return Err(non_finite("turtle position", len));
        }
        self.state.pos = to;
        Ok(to)
    }

    fn point(&self, budget: &mut Budget) -> Result<LinePoint, LimitExceeded> {
        budget.reserve_memory(LINE_POINT_BYTES.saturating_add(self.opts.line_point_bytes))?;
        // The sweep profile lies in local XY and the pen moves along local +Z: turn +Z onto the heading.
        let rot = self.state.rot * DQuat::from_rotation_x(-std::f64::consts::FRAC_PI_2);
        let scale = (self.state.width / (2.0 * sweep::PROFILE_RADIUS)).abs().max(1e-9);
        let frame = Frame { translation: self.state.pos, rotation: rot, scale, parity: false };
        Ok(LinePoint { frame, colour: self.state.colour.map(|c| c.clamp(0.0, 1.0) as f32) })
    }

    fn draw(&mut self, len: f64, budget: &mut Budget) -> Result<(), EvalError> {
        if self.leaves.is_some() {
            let length = len.abs().max(1e-9) as f32;
            let shape = match self.sys.shape {
                Shape::Tube => {
                    let w = self.state.width.abs().max(1e-9) as f32;
                    LeafShape { kind: PrimitiveKind::Cylinder, scale: [w, length, w], offset: [0.0, (len / 2.0) as f32, 0.0], tube: true }
                }
                Shape::Primitive(kind) => LeafShape { kind, scale: [length; 3], offset: [0.0, (len / 2.0) as f32, 0.0], tube: false },
            };
            let colour = self.state.colour.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
            let leaf = Leaf { pos: self.state.pos, rot: self.state.rot, shape, colour };
            self.advance(len)?;
            if let Some(leaves) = self.leaves.as_mut() {
                leaves.push(leaf);
            }
            self.drawing.segments += 1;
            return Ok(());
        }
        match self.sys.shape {
            Shape::Tube => {
                budget.charge_primitive(self.point_tris)?;
                if self.state.line.is_none() {
                    let first = self.point(budget)?;
                    self.drawing.promised = self.drawing.promised.saturating_add(self.opts.line_point_bytes);
                    self.drawing.scene.lines.push(Polyline { points: vec![first], profile: None });
                    self.state.line = Some(self.drawing.scene.lines.len() - 1);
                }
                self.advance(len)?;
                let p = self.point(budget)?;
                self.drawing.promised = self.drawing.promised.saturating_add(self.opts.line_point_bytes);
                if let Some(line) = self.state.line.and_then(|l| self.drawing.scene.lines.get_mut(l)) {
                    line.points.push(p);
                }
            }
            Shape::Primitive(kind) => {
                budget.charge_primitive(primitives::triangle_count(kind, self.opts.detail))?;
                let down = self.opts.downstream_bytes[kind as usize];
                budget.reserve_memory(INSTANCE_BYTES.saturating_add(down))?;
                self.drawing.promised = self.drawing.promised.saturating_add(down);
                let from = self.state.pos;
                let to = self.advance(len)?;
                let frame = Frame { translation: (from + to) * 0.5, rotation: self.state.rot, scale: len.abs().max(1e-9), parity: false };
                self.drawing.scene.instances.push(Instance::new(kind, &frame, self.state.colour));
            }
        }
        self.drawing.segments += 1;
        Ok(())
    }
}
