//! The CFDG syntax tree and its parser, for both the 2.x syntax (`rule X
//! 0.5 { }`, `{ }` canonical and `[ ]` ordered adjustments, `N * { } X { }`
//! loops) and the 3.x syntax (`shape`, `rule`, `[ ]` canonical and `[[ ]]`
//! ordered adjustments, `loop`, `if`, `switch`, `transform`, `clone`,
//! definitions and `CF::` settings), as cfdg 3.4 reads them (John Horigan,
//! `cfdg.ypp` and `cfdg.l`, Context Free 3.4, 2018).
//!
//! The tree keeps each number's text: Context Free hashes the source text of
//! every adjustment into the random seed of the replacement that carries it
//! ("entropy", `astexpression.cpp` `entropy()`), so the same variation code
//! gives the same picture only if the text is hashed as cfdg hashes it.

mod entropy;
pub(crate) mod lexer;
mod parser;
mod shapes;

pub(crate) use entropy::{adjust_entropy, define_seed, is_builtin, is_constant, loop_seed, term_seed};
pub use parser::parse;
pub(crate) use parser::{parse_with, path_op_arity, REUSE};
pub(crate) use shapes::{start_name_entropy, SHAPE_EXPR};

use crate::Span;

/// Which syntax a file is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Version {
    /// Context Free 2.x: `rule NAME { }`, `{ }` canonical adjustments.
    V2,
    /// Context Free 3.x: `shape NAME`, `[ ]` canonical adjustments.
    V3,
}

/// A parsed design.
#[derive(Debug, Clone, PartialEq)]
pub struct Grammar {
    /// The syntax it was read as.
    pub version: Version,
    /// The first shape (`startshape NAME [adjustment]` or `CF::StartShape`).
    pub start: Option<Replacement>,
    /// Every rule, in source order (a 3.x `shape` with one body is one rule of weight 1).
    pub rules: Vec<Rule>,
    /// Global definitions and `CF::` settings in source order.
    pub defines: Vec<Define>,
    /// The 2.x `background { }` adjustment, if any.
    pub background: Option<Adjustment>,
    /// Warnings found while parsing.
    pub warnings: Vec<crate::Diagnostic>,
    /// User functions (`number f(number x) = expr`), by name; a later
    /// definition of the same name replaces an earlier one.
    pub functions: std::collections::BTreeMap<String, Function>,
    /// The typed parameters of each shape or path that declares them (the
    /// names are also in [`Rule::params`]; a shape missing here takes
    /// one number per name).
    pub param_types: std::collections::BTreeMap<String, Vec<Param>>,
    /// Where each `rand_static()` is written, in the order cfdg's builder
    /// makes them: each takes the next number of the parse-time stream
    /// (`eval::rand_static`).
    pub rand_static: Vec<Span>,
    /// The shape names of replacements in files imported into a
    /// namespace, as written (what cfdg hashes into their seeds), by
    /// where they are written and their qualified name
    /// (`parser/namespace.rs`).
    pub entropy_names: std::collections::BTreeMap<(u32, u32, String), String>,
    /// Whether the start shape came from `CF::StartShape = NAME(args),
    /// [adjustment]`, whose seed hashes the arguments' text after the name
    /// ([`start_name_entropy`]).
    pub start_from_setting: bool,
}

/// A parameter's or a function's type, as cfdg's `AST::decodeType`
/// (`ast.cpp`) reads it: `number`, `natural`, `vectorN` (N numbers, 2–99),
/// `shape` or `adjustment`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamType {
    /// One number.
    Number,
    /// One natural number (checked against `CF::MaxNatural` when bound).
    Natural,
    /// A tuple of this many numbers.
    Vector(usize),
    /// A shape with its arguments bound.
    Shape,
    /// An adjustment.
    Adjustment,
}

impl ParamType {
    /// How many numbers a value of this type holds (shapes and adjustments: none).
    pub fn size(self) -> Option<usize> {
        match self {
            ParamType::Number | ParamType::Natural => Some(1),
            ParamType::Vector(n) => Some(n),
            ParamType::Shape | ParamType::Adjustment => None,
        }
    }
}

/// A typed parameter of a shape, a path or a user function.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: ParamType,
}

/// A user function `TYPE NAME(params) = expression` (`function_definition`
/// in `cfdg.ypp`, `ASTdefine` of kind `FunctionDefine`, `builder.cpp`
/// `MakeDefinition`): evaluated on each call with its parameters bound and
/// only the globals visible (`ASTuserFunction::evaluate`, `astexpression.cpp`).
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    /// Its name.
    pub name: String,
    /// Its parameters, in order.
    pub params: Vec<Param>,
    /// What it returns.
    pub ret: ParamType,
    /// Its body.
    pub body: Expr,
    /// Where it is defined.
    pub span: Span,
}

/// One rule of a shape.
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    /// The shape it expands.
    pub name: String,
    /// Its weight (1 when not given).
    pub weight: f64,
    /// Whether the weight was written as a percentage (`rule 20%`).
    pub percent: bool,
    /// Its body.
    pub body: Vec<Element>,
    /// Whether it is a `path` (drawn as a path, not expanded).
    pub is_path: bool,
    /// The names of its shape's parameters, in order (their types in
    /// [`Grammar::param_types`]).
    pub params: Vec<String>,
    /// Where it starts.
    pub span: Span,
}

/// A definition `NAME = expression` (a `CF::` setting when NAME starts with `CF::`).
#[derive(Debug, Clone, PartialEq)]
pub struct Define {
    /// The name defined.
    pub name: String,
    /// Its value: an expression or an adjustment.
    pub value: Value,
    /// Where it is written.
    pub span: Span,
}

/// The right side of a definition.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A numeric expression.
    Expr(Expr),
    /// An adjustment (`CF::Background = [b -1]`).
    Adjust(Adjustment),
    /// A shape name (`CF::StartShape = X`).
    Shape(String),
    /// A list of transforms and symmetry groups (`CF::Symmetry =
    /// CF::Dihedral, 6` or `[r 90], [[s 2 r 45]]`), read by `eval::symmetry`.
    Symmetry(Vec<SymmetryItem>),
}

/// One item of a symmetry list (`getTransforms`, `ast.cpp`, Context Free 3.4):
/// an adjustment, or a flag or number of a symmetry group's specification.
#[derive(Debug, Clone, PartialEq)]
pub enum SymmetryItem {
    /// A geometric adjustment: one transform of the list.
    Adjust(Adjustment),
    /// A `CF::` group flag or one of its numeric arguments.
    Expr(Expr, Span),
}

/// A replacement: a shape and the adjustment placing it.
#[derive(Debug, Clone, PartialEq)]
pub struct Replacement {
    /// The shape's name (a rule's, `SQUARE`, `CIRCLE`, `TRIANGLE`, a shape
    /// variable or parameter, a function returning a shape), or
    /// [`SHAPE_EXPR`] when an expression in `args` chooses the shape.
    pub shape: String,
    /// Its adjustment.
    pub adjust: Adjustment,
    /// Its arguments, when the shape takes parameters (a list of
    /// parenthesised expressions, as cfdg builds and hashes it).
    pub args: Option<Expr>,
    /// Where it is written.
    pub span: Span,
}

/// One element of a rule body.
#[derive(Debug, Clone, PartialEq)]
pub enum Element {
    /// `SHAPE [adjustment]`.
    Replace(Replacement),
    /// A loop (`loop N [adj] body`, `loop i = a, b, s [adj] body`, 2.x `N * {adj} body`).
    Loop(Loop),
    /// `if (cond) body else body`.
    If {
        /// The condition.
        cond: Expr,
        /// Taken when it is not 0.
        then: Vec<Element>,
        /// Taken otherwise.
        otherwise: Vec<Element>,
        /// Where it is written.
        span: Span,
    },
    /// `switch (e) { case a, b..c: body else: body }`.
    Switch {
        /// The selector (floored).
        selector: Expr,
        /// Each case's values (inclusive ranges) and body.
        cases: Vec<(Vec<(i64, i64)>, Vec<Element>)>,
        /// The `else` body.
        otherwise: Vec<Element>,
        /// Where it is written.
        span: Span,
    },
    /// `transform adj… body` or `clone adj… body`.
    Transform {
        /// `clone`: every copy restarts from the same random state.
        clone: bool,
        /// The adjustments, one copy of the body each.
        adjusts: Vec<Adjustment>,
        /// Instead, a comma list of adjustments and symmetry groups
        /// (`clone [], [x 4]`, `clone CF::Dihedral, 6`), read as cfdg reads
        /// it (`getTransforms`); empty for the plain form.
        symmetry: Vec<SymmetryItem>,
        /// The body.
        body: Vec<Element>,
        /// Where it is written.
        span: Span,
    },
    /// A local definition.
    Define(Define),
    /// A path operation (`MOVETO`, `LINETO`, `ARCTO`, `CURVETO`, their
    /// relative forms, `CLOSEPOLY`) inside a `path`.
    PathOp(PathOp),
    /// A path command (`STROKE`, `FILL`) inside a `path`.
    PathCommand(PathCommand),
}

/// The path operations (`ASTpathOp`'s `pathOpEnum`), in cfdg's order: an
/// implicit MOVETO is inserted before any operation after `MoveRel`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum PathOpKind {
    /// `MOVETO x y`.
    MoveTo,
    /// `MOVEREL dx dy`.
    MoveRel,
    /// `LINETO x y`.
    LineTo,
    /// `LINEREL dx dy`.
    LineRel,
    /// `ARCTO x y r` or `ARCTO x y rx ry angle`.
    ArcTo,
    /// `ARCREL`.
    ArcRel,
    /// `CURVETO x y x1 y1 [x2 y2]`.
    CurveTo,
    /// `CURVEREL`.
    CurveRel,
    /// `CLOSEPOLY`.
    ClosePoly,
}

/// A path operation with its positional arguments, as cfdg's
/// `ASTpathOp::makePositional` and `checkArguments` leave it: the end
/// point, then the radius (or radii and angle in degrees) of an arc, or
/// the control points of a curve.
#[derive(Debug, Clone, PartialEq)]
pub struct PathOp {
    /// Which operation.
    pub kind: PathOpKind,
    /// Its numeric arguments (flags removed).
    pub args: Vec<Expr>,
    /// Its flags (`CF::ArcCW`, `CF::ArcLarge`, `CF::Continuous`, `CF::Align`: [`path_flags`]).
    pub flags: u32,
    /// Where it is written.
    pub span: Span,
}

/// A path command: fill or stroke the operations since the last command.
#[derive(Debug, Clone, PartialEq)]
pub struct PathCommand {
    /// `FILL` (else `STROKE`).
    pub fill: bool,
    /// Its adjustment (colour and transform of what it draws).
    pub adjust: Adjustment,
    /// Its stroke width, when given (cfdg's default is 0.1).
    pub width: Option<Expr>,
    /// Its flags (joins, caps, `evenodd`, `iso`: [`path_flags`]).
    pub flags: u32,
    /// Where it is written.
    pub span: Span,
}

/// Context Free's path flags (`ast.h` `FlagTypes`, with AGG's join and cap numbers).
pub(crate) mod path_flags {
    /// Mask of the line join (AGG: 0 miter, 2 round, 3 bevel).
    pub(crate) const JOIN_MASK: u32 = 0x7;
    /// A join was given.
    pub(crate) const JOIN_PRESENT: u32 = 8;
    /// Shift of the line cap (AGG: 0 butt, 1 square, 2 round).
    pub(crate) const CAP_SHIFT: u32 = 4;
    /// Mask of the line cap.
    pub(crate) const CAP_MASK: u32 = 0x7 << CAP_SHIFT;
    /// A cap was given.
    pub(crate) const CAP_PRESENT: u32 = 8 << CAP_SHIFT;
    /// Arc clockwise.
    pub(crate) const ARC_CW: u32 = 1 << 8;
    /// The large arc.
    pub(crate) const ARC_LARGE: u32 = 1 << 9;
    /// A smooth curve (control point reflected).
    pub(crate) const CONTINUOUS: u32 = 1 << 10;
    /// CLOSEPOLY moves the last point onto the first.
    pub(crate) const ALIGN: u32 = 1 << 11;
    /// Even-odd fill.
    pub(crate) const EVEN_ODD: u32 = 1 << 12;
    /// Stroke width in pixels of the untransformed path (`iso`).
    pub(crate) const ISO_WIDTH: u32 = 1 << 13;
    /// Fill (else stroke).
    pub const FILL: u32 = 1 << 14;
}

/// A loop.
#[derive(Debug, Clone, PartialEq)]
pub struct Loop {
    /// The index variable's name, if named.
    pub var: Option<String>,
    /// The loop arguments (count; or start, end[, step]).
    pub args: Expr,
    /// The adjustment applied after each step.
    pub adjust: Adjustment,
    /// The body.
    pub body: Vec<Element>,
    /// The `finally` body.
    pub finally: Vec<Element>,
    /// Written in the 2.x form `N * {adj}`.
    pub v2: bool,
    /// Where it is written.
    pub span: Span,
}

/// An adjustment: terms in order, applied canonically or as written.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Adjustment {
    /// Canonical order (translate, rotate, size, skew, flip) or as written.
    pub canonical: bool,
    /// The terms as written (after Context Free's merging of `x a y b`).
    pub terms: Vec<Term>,
}

/// The kinds of adjustment term (`ASTmodTerm::modTypeEnum`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TermKind {
    /// `x` (one or two arguments).
    X,
    /// `y`.
    Y,
    /// `z`.
    Z,
    /// `size`/`s` (one or two arguments; three also scales z).
    Size,
    /// The z part of a three-number `size` (`zsize`).
    ZSize,
    /// `rotate`/`r`.
    Rotate,
    /// `flip`/`f`.
    Flip,
    /// `skew`.
    Skew,
    /// `transform`/`trans` with 1, 2, 4 or 6 numbers.
    Transform,
    /// `hue`/`h`.
    Hue,
    /// `saturation`/`sat`.
    Sat,
    /// `brightness`/`b`.
    Bright,
    /// `alpha`/`a`.
    Alpha,
    /// `hue v |`: towards the target hue.
    HueTarg,
    /// `sat v |`.
    SatTarg,
    /// `b v |`.
    BrightTarg,
    /// `a v |`.
    AlphaTarg,
    /// `|hue v`: changes the target hue.
    TargHue,
    /// `|sat v`.
    TargSat,
    /// `|b v`.
    TargBright,
    /// `|a v`.
    TargAlpha,
    /// `time begin end`: moves the shape's time span (`ASTmodTerm::time`,
    /// `agg::trans_affine_time_translation`); a still draws every shape
    /// but drops one whose span runs backwards (eval/time.rs).
    Time,
    /// `timescale s`: scales later time moves (`ASTmodTerm::timescale`).
    TimeScale,
    /// `blend`: read and ignored (no blend modes).
    Ignored,
}

/// One adjustment term.
#[derive(Debug, Clone, PartialEq)]
pub struct Term {
    /// Which term.
    pub kind: TermKind,
    /// Its arguments (a `Cons` when more than one).
    pub args: Expr,
    /// Where it is written.
    pub span: Span,
}

/// An expression, keeping what Context Free hashes.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// A number and its text.
    Num(f64, String),
    /// A variable (a definition, a loop index or a parameter).
    Var(String, Span),
    /// Unary `-` (`N`) or `+` (`P`) or `!`.
    Unary(char, Box<Expr>),
    /// A binary operator (Context Free's one-letter names: `+ - * / ^ < > L G = n & | X`).
    Binary(char, Box<Expr>, Box<Expr>),
    /// A parenthesised expression.
    Paren(Box<Expr>),
    /// A list `a, b` or the several arguments of a term.
    Cons(Vec<Expr>),
    /// A function call by its name (`rand`, `sin`, …; `rand.` for `a..b`,
    /// `rand+/-` for `a ± b`; a user function's name).
    Call(String, Box<Option<Expr>>, Span),
    /// `let(a = e; b = e; body)` (`ASTlet`): the definitions in order, then the body.
    Let(Vec<(String, Expr)>, Box<Expr>, Span),
    /// `name[index]` or `name[index, length, stride]` (`ASTarray`): elements of a vector.
    Index(String, Box<Expr>, Span),
    /// A shape named in an expression, with its arguments (`ASTruleSpecifier`:
    /// `foo(0.5)`, `CIRCLE`) and its number among the design's shapes
    /// (primitives first, then rules in order: [`shape_numbers`]).
    Shape(String, usize, Box<Option<Expr>>, Span),
    /// An adjustment written inside an expression (`[r 5]` as an argument,
    /// a `select` choice or a function's value: `ASTmodification`).
    Adjust(Box<Adjustment>, Span),
}

impl Expr {
    /// The expressions a list holds (itself when it is not a list).
    pub fn items(&self) -> Vec<&Expr> {
        match self {
            Expr::Cons(v) => v.iter().collect(),
            e => vec![e],
        }
    }
}
