//! The shared rule IR that every front end lowers into and the evaluator runs.
//!
//! The IR is deliberately small: rules grouped by name, bodies of calls,
//! blocks and iterators, and adjustments whose arguments are expressions.
//! Names are already resolved (a call points at a rule group or a built-in
//! primitive), angles are already in radians, and `@define` constants are
//! already substituted, so the evaluator never looks at source text.

use crate::expr::Expr;
use crate::Span;

/// Index of a rule group in [`Program::groups`].
pub(crate) type GroupId = u32;

/// A whole parsed program, ready to be bound to parameters and evaluated.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    /// The group evaluated first (from `startshape`, else the first rule defined).
    pub start: Target,
    /// Every rule name with its alternatives; indexed by [`GroupId`].
    pub groups: Vec<RuleGroup>,
    /// Top-level directives that change how evaluation runs.
    pub directives: Directives,
    /// `@param` declarations, in source order; [`Expr::Param`] indexes this.
    pub params: Vec<ParamDecl>,
    /// Number of distinct call sites and `rand()` sites; every site id is below it.
    /// Random streams are derived from site ids, so they must be stable for a given source.
    pub site_count: u32,
    /// Non-fatal diagnostics found while parsing (ignored blocks, unknown directives).
    pub warnings: Vec<crate::Diagnostic>,
    /// `isosurface` declarations; [`Target::Isosurface`] indexes this.
    pub isosurfaces: Vec<Isosurface>,
    /// `mesh` declarations and named solids; [`Target::Mesh`] indexes this.
    pub meshes: Vec<MeshDecl>,
    /// Namespaces (Andersson 2015 §4.1.4): each has its own line pen and its own
    /// "last terminal" for continuation.
    pub namespaces: Namespaces,
}

/// The namespaces of a program and which one each call site is written in.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Namespaces {
    /// Namespace names; index 0 is the global namespace "". Empty when the
    /// program uses no namespace (everything is global).
    pub names: Vec<String>,
    /// The namespace of each call site (indexed by site); empty when `names` is.
    pub of_site: Vec<u32>,
}

impl Namespaces {
    /// The namespace call site `site` draws and continues in (0: global).
    pub fn of(&self, site: u32) -> u32 {
        self.of_site.get(site as usize).copied().unwrap_or(0)
    }

    /// How many pens evaluation needs (at least the global one).
    pub fn count(&self) -> usize {
        self.names.len().max(1)
    }
}

/// All rules that share one name; a call picks one of them with the group's selector.
#[derive(Debug, Clone, PartialEq)]
pub struct RuleGroup {
    /// The rule name as written in the source.
    pub name: String,
    /// The alternatives, in source order.
    pub rules: Vec<Rule>,
    /// How a call picks one alternative (Andersson 2015 §4.2.2; `selector` directive).
    pub selector: Selector,
}

/// Rule selection modes (Andersson 2015 §4.2.2). Threshold modes read each rule's
/// weight as a threshold and pick the rule with the smallest weight that is
/// ≥ the measured value; when no rule qualifies the call draws nothing.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Selector {
    /// Weighted random choice (weights normalised per name). `frequency` is an alias.
    #[default]
    Random,
    /// Threshold on the call's recursion depth (the start rule is depth 0).
    Depth,
    /// Threshold on the frame's uniform length scale.
    Scale,
    /// Each rule runs `weight` times (rounded) in source order, counted per name
    /// in depth-first order; the cycle then repeats.
    Sequential,
    /// Threshold on a function of the frame's position (`x`, `y`, `z` in the expression).
    Function(Expr),
}

/// One `rule NAME [weight] { body }` definition.
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    /// Relative weight; weights are normalised per group at selection time. Default 1.
    pub weight: f64,
    /// A transform-rule header (`* path : t1 …` or `: x1 : x2 …`), if any.
    pub transform: RuleTransform,
    /// The body items, run in order, each from the rule's own frame.
    pub body: Vec<Item>,
    /// Where the rule header is.
    pub span: Span,
}

/// Transform-rule headers (Andersson 2015 §4.4–4.5). The named rules are *paths*:
/// evaluated once from the identity frame, their `FRAME {}` calls give a list
/// of frames.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum RuleTransform {
    /// A plain rule.
    #[default]
    None,
    /// `rule R * path : t1 : t2 { body }`: the body runs once per frame of `path`,
    /// in that frame composed (parent first) with the same-index frames of t1, t2, ….
    Convolve(Vec<GroupId>),
    /// `rule R : x1 : x2 { body }`: an animated rule. Static output shows it at
    /// time 0, i.e. in the composition of each path's first frame.
    Animate(Vec<GroupId>),
}

/// What a call refers to, resolved at parse time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Target {
    /// A user rule group.
    Group(GroupId),
    /// A built-in drawable.
    Primitive(PrimitiveKind),
    /// A line drawable (Andersson 2015 §4.3, Table B.6), with an optional profile
    /// rule whose `VERTEX` calls give the cross-section (else `linerule`, else a round tube).
    Line(LineOp, Option<GroupId>),
    /// `VERTEX {}`: a free vertex (every three make a triangle), or a profile
    /// point inside a profile rule.
    Vertex,
    /// `FACENORMALS {}`: the last three vertices get their triangle's face normal.
    FaceNormals,
    /// `FRAME {}`: emits a frame into the path of a transform rule.
    Frame,
    /// An `isosurface` drawable, by index in [`Program::isosurfaces`].
    Isosurface(u32),
    /// A modified or generated mesh, by index in [`Program::meshes`].
    Mesh(u32),
}

impl Program {
    /// A program that draws one mesh and nothing else: what the stacking
    /// string and UniGrafix front ends lower to.
    pub(crate) fn single_mesh(mesh: MeshDecl, warnings: Vec<crate::Diagnostic>) -> Program {
        Program {
            start: Target::Mesh(0),
            groups: Vec::new(),
            directives: Directives::default(),
            params: Vec::new(),
            site_count: 0,
            warnings,
            isosurfaces: Vec::new(),
            meshes: vec![mesh],
            namespaces: Namespaces::default(),
        }
    }

    /// True when some call or iterator step anywhere in the program adds to
    /// red, green or blue (`R`, `G`, `B`, even by 0), whether or not it ever
    /// runs. The evaluator gives a program that never does a neutral grey
    /// base colour instead of black (docs/mdg.md, "Colour"); alpha alone
    /// does not count, since translucent black is no more meant than black.
    pub(crate) fn sets_colour(&self) -> bool {
        let mut pending: Vec<&Item> = self.groups.iter().flat_map(|g| &g.rules).flat_map(|r| &r.body).collect();
        let rgb = |adjust: &[Adjust]| adjust.iter().any(|a| matches!(a.op, AdjustOp::Colour { channel: 0..=2, .. }));
        while let Some(item) = pending.pop() {
            match item {
                Item::Call(c) if rgb(&c.adjust) => return true,
                Item::Call(_) => {}
                Item::Block(items) => pending.extend(items),
                Item::Iterate(it) if rgb(&it.step) => return true,
                Item::Iterate(it) => pending.push(it.body.as_ref()),
            }
        }
        false
    }
}

/// `mesh NAME { BASE | modifier … | modifier … }` (docs/modifiers.md): a
/// base shape with a chain of modifiers, built once on first use and placed
/// like a primitive. Named solids (`SNUB_CUBE`) lower to a declaration with
/// no modifiers.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshDecl {
    /// The drawable's name.
    pub name: String,
    /// What the chain starts from.
    pub base: crate::geom::modifiers::MeshBase,
    /// The modifiers, applied in order.
    pub modifiers: Vec<crate::geom::modifiers::Modifier>,
    /// Where it is declared.
    pub span: Span,
}

/// `isosurface NAME { … }`: the surface f(x, y, z) = 0 of a field sampled on a
/// grid, with the inside where f > 0, closed against its bounding box.
#[derive(Debug, Clone, PartialEq)]
pub struct Isosurface {
    /// The drawable's name (it overrides a built-in primitive of that name).
    pub name: String,
    /// Per axis x, y, z: (min, max, cells). Samples per axis are cells + 1.
    pub axes: [(f64, f64, u32); 3],
    /// The field, a function of the coordinates (`Expr::Coord`).
    pub field: Expr,
    /// Where it is declared.
    pub span: Span,
}

/// The pen operations of swept lines. Each is a terminal: it updates the
/// frame that a continued call (`\`) starts from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LineOp {
    /// `MOVETO`: ends the current line and puts the pen down here.
    MoveTo,
    /// `LINETO` (and `ALINETO`): draws a segment from the pen to here; if the
    /// pen is lifted (after `NEWLINE`), only puts it down.
    LineTo,
    /// `SLINETO`: like `LINETO`, with the profile turned orthogonal to the segment.
    SLineTo,
    /// `BLENDTO`: like `LINETO`, through interpolated sub-segments that blend
    /// position, orientation and scale smoothly (Andersson 2015 eqs 4.15–4.21).
    BlendTo,
    /// `NEWLINE`: ends the current line and lifts the pen.
    NewLine,
    /// `RESET`: ends the current line and puts the pen back at the last `MOVETO`.
    Reset,
}

pub use crate::core::primitive::PrimitiveKind;

/// One item of a rule body.
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// `NAME { adjustments }`: run the target from the current frame plus the adjustments.
    Call(Call),
    /// `{ items }`: a group of items sharing the frame they are run from (used under iterators).
    Block(Vec<Item>),
    /// `m[/n] * { step } item`: copies k = 1..m of `body`, copy k with the step applied k times.
    Iterate(Iterate),
}

/// A call of a rule group or primitive.
#[derive(Debug, Clone, PartialEq)]
pub struct Call {
    /// What is called.
    pub target: Target,
    /// Applied left to right in the caller's local frame.
    pub adjust: Vec<Adjust>,
    /// Unique per call site; seeds the random stream of this call.
    pub site: u32,
    /// Preceded by `\`: the call starts from the frame where the last terminal
    /// (primitive or line drawable) left off, not from the caller's frame.
    pub continues: bool,
    /// Where the call is written.
    pub span: Span,
}

/// An iterator `count [/ divisor] * { step } body`.
#[derive(Debug, Clone, PartialEq)]
pub struct Iterate {
    /// Number of copies m (must evaluate to a finite non-negative integer).
    pub count: Expr,
    /// Optional n: the step is divided into n equal parts (each argument / n, scale k^(1/n)).
    pub divisor: Option<Expr>,
    /// The step transform applied once more for each successive copy.
    pub step: Vec<Adjust>,
    /// What each copy runs.
    pub body: Box<Item>,
    /// Written after `\` (`\ 10/10 * {rx 120} LINETO{}`): the copies are
    /// placed relative to the frame where the namespace's last terminal
    /// left off, as a continued call is, instead of the enclosing frame. A
    /// `\` inside the body (`2 * {} \ ABCB{}`) continues each copy's call
    /// instead, which discards the iterator's step (docs/mdg.md).
    pub continues: bool,
    /// Unique per iterator site; combined with the copy index for random streams.
    pub site: u32,
    /// Where the iterator is written.
    pub span: Span,
}

/// One adjustment with its source position (for errors such as a NaN argument).
#[derive(Debug, Clone, PartialEq)]
pub struct Adjust {
    /// What the adjustment does.
    pub op: AdjustOp,
    /// Where it is written.
    pub span: Span,
}

/// A coordinate axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The X axis.
    X,
    /// The Y axis.
    Y,
    /// The Z axis.
    Z,
}

/// The adjustment operations of MDG Table B.3, after sugar is removed
/// (`up a` is `Rotate{X, a}`, `r a b c` is three rotations, `fx` is `Reflect(1,0,0)`).
#[derive(Debug, Clone, PartialEq)]
pub enum AdjustOp {
    /// Move by (x, y, z) in the local frame.
    Translate([Expr; 3]),
    /// Rotate about a local axis by an angle in radians (right-handed).
    Rotate {
        /// The axis.
        axis: Axis,
        /// The angle, already converted to radians.
        angle: Expr,
    },
    /// Multiply lengths by k (a negative k also reflects through the origin).
    Scale(Expr),
    /// Reflect across the plane through the origin with this normal (normalised at evaluation).
    Reflect([Expr; 3]),
    /// Add to a colour channel: 0 = R, 1 = G, 2 = B, 3 = A.
    Colour {
        /// Channel index 0..=3.
        channel: u8,
        /// Amount added.
        delta: Expr,
    },
}

/// The angle unit chosen by the `angle` directive.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AngleMode {
    /// Degrees (the default).
    #[default]
    Degrees,
    /// Radians.
    Radians,
    /// Full turns: 1 = 360°.
    Orbits,
}

/// Top-level directives that affect evaluation.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Directives {
    /// `maxdepth N`: calls deeper than N are silently not expanded (a grammar's own termination).
    pub maxdepth: Option<u32>,
    /// `minsize v`: rule calls whose frame scale is below v are silently not expanded.
    pub minsize: Option<f64>,
    /// `maxiter N`: every iterator runs at most N copies.
    pub maxiter: Option<u64>,
    /// `randseed N`: the seed used when the request gives none.
    pub randseed: Option<u64>,
    /// `background r g b [a]`: clear colour, carried to the output as metadata.
    pub background: Option<[f64; 4]>,
    /// `angle …`: informational; angles in the IR are already radians.
    pub angle: AngleMode,
    /// `linerule NAME`: the default profile rule of swept lines.
    pub linerule: Option<GroupId>,
    /// `normal x y z`: the local normal given to `VERTEX` (default 0 0 1).
    pub normal: Option<[f64; 3]>,
    /// `stacksize N`: calls whose depth (nested rule calls) exceeds N are
    /// silently not expanded, like `maxdepth` (Andersson 2015's Table B.1 lists both).
    pub stacksize: Option<u32>,
    /// `fps N`: animation frames per second (transform rules emit one frame per tick).
    pub fps: Option<f64>,
    /// `duration T`: animation length in seconds, sampled at `fps`.
    pub duration: Option<f64>,
    /// `camerarule NAME`: the transform rule whose frames give the camera (view) path.
    pub camerarule: Option<GroupId>,
    /// `camerafov`, `cameranearplane`, `camerafarplane`: the camera's lens.
    pub camera: CameraLens,
}

/// The camera's lens from `camerafov`, `cameranearplane` and `camerafarplane`
/// (Andersson 2015's Table B.1 gives the defaults 40°, 0.1 and 1000).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraLens {
    /// Vertical field of view in degrees.
    pub fov_degrees: f64,
    /// Near clipping distance (> 0).
    pub near: f64,
    /// Far clipping distance (> near).
    pub far: f64,
}

impl Default for CameraLens {
    fn default() -> Self {
        CameraLens { fov_degrees: 40.0, near: 0.1, far: 1000.0 }
    }
}

/// The type of an `@param`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKind {
    /// Whole numbers only.
    Int,
    /// Any finite number.
    Float,
    /// 0 or 1 (`true`/`false` accepted from requests).
    Bool,
}

/// An `@param kind name default [min max]` declaration.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamDecl {
    /// The parameter name, as used in expressions and in requests.
    pub name: String,
    /// Its type.
    pub kind: ParamKind,
    /// The default value.
    pub default: f64,
    /// Inclusive range, if declared.
    pub range: Option<(f64, f64)>,
    /// Names of the values 0, 1, … (`@presets`): a request may give a name
    /// instead of its index. Empty for ordinary parameters.
    pub choices: Vec<String>,
    /// Where it is declared.
    pub span: Span,
}
