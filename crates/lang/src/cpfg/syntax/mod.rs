//! The L-system file of cpfg (`language: "cpfg"`, `.l` files), as cpfg's
//! own grammar reads it: Prusinkiewicz's group, *cpfg* (L-studio / vlab),
//! `AlgorithmicBotany/vlab`, `cpfg/lsys_input.l` (tokens) and
//! `cpfg/lsys_input.y` (grammar), with the manual `docs/CPFGManual.pdf`
//! (2022) for what the source leaves implicit. See `docs/cpfg.md`.
//!
//! Every symbol is one character (`lsys_input.l`, `<SYMBOL>{symbol}`
//! returns `yytext[0]`): `@O(2)` is the modules `@` and `O(2)`, which the
//! turtle reads as one command. The text is preprocessed first
//! ([`preprocess`]).

pub mod cond;
pub mod expr;
mod parser;
pub mod preprocess;
pub mod pure;

pub use parser::parse;
pub(crate) use parser::parse_with;

use crate::core::{Diagnostic, Span};

/// A built-in function of cpfg's expressions (`lsys_input.l`, `CheckReserved`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    /// Trigonometry in degrees, as cpfg (`generate.c`, `Eval`).
    Sin,
    /// Cosine of degrees.
    Cos,
    /// Tangent of degrees.
    Tan,
    /// Arcsine in degrees.
    Asin,
    /// Arccosine in degrees.
    Acos,
    /// Arctangent in degrees; with two arguments `atan2(x, y)` = atan(y/x).
    Atan,
    /// `atan2(x, y)`: the angle of (x, y) in degrees.
    Atan2,
    /// e^x.
    Exp,
    /// Natural logarithm.
    Log,
    /// Square root.
    Sqrt,
    /// Largest integer ≤ x.
    Floor,
    /// Smallest integer ≥ x.
    Ceil,
    /// cpfg's `trunc` rounds: `floor(x + 0.5)` (`generate.c`, `case tTRUNC`).
    Trunc,
    /// Absolute value.
    Fabs,
    /// −1, 0 or 1.
    Sign,
    /// Uniform on [0, x].
    Ran,
    /// Normal with mean and standard deviation.
    Nran,
    /// Beta-distributed.
    Bran,
    /// Binomial: successes in n trials of probability p.
    Biran,
    /// Reseeds the stream of `ran`.
    Srand,
    /// `func(id, x)`: the view's function `id` at x (`cpfg/splinefun.cpp`).
    Func,
    /// `printf`, `fprintf`, `fopen`, `fclose`, `fflush`, `fscanf`, `stop`,
    /// `play`, `Display`: no file or console here; they return 0.
    Ignored,
}

impl Func {
    /// The function called `name`, if cpfg has one.
    pub fn from_name(name: &str) -> Option<Func> {
        Some(match name {
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "tan" => Func::Tan,
            "asin" => Func::Asin,
            "acos" => Func::Acos,
            "atan" => Func::Atan,
            "atan2" => Func::Atan2,
            "exp" => Func::Exp,
            "log" => Func::Log,
            "sqrt" => Func::Sqrt,
            "floor" => Func::Floor,
            "ceil" => Func::Ceil,
            "trunc" => Func::Trunc,
            "fabs" => Func::Fabs,
            "sign" => Func::Sign,
            "ran" => Func::Ran,
            "nran" => Func::Nran,
            "bran" => Func::Bran,
            "biran" => Func::Biran,
            "srand" => Func::Srand,
            "func" => Func::Func,
            "printf" | "fprintf" | "fopen" | "fclose" | "fflush" | "fscanf" | "stop" | "play" | "Display" => Func::Ignored,
            _ => return None,
        })
    }
}

/// Unary operators.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnOp {
    /// `-x`
    Neg,
    /// `!x`
    Not,
}

/// Binary operators, in cpfg's precedence (`lsys_input.y`, `%left`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinOp {
    /// `||`
    Or,
    /// `&&`
    And,
    /// `==`
    Eq,
    /// `!=` or `<>`
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `%` on the integer parts
    Rem,
    /// `^`: power
    Pow,
}

/// An expression over floats.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// A number.
    Num(f64),
    /// A string (only as a `printf` argument).
    Str,
    /// A global variable (index into [`Cpfg::globals`]).
    Global(u32),
    /// A production's formal parameter or local variable (its slot).
    Local(u32),
    /// An element of a global array (index into [`Cpfg::arrays`]).
    Elem(u32, Vec<Expr>, Span),
    /// `op x`
    Unary(UnOp, Box<Expr>),
    /// `x op y`, with where the operator is written.
    Binary(BinOp, Box<Expr>, Box<Expr>, Span),
    /// `c ? a : b`
    Cond(Box<Expr>, Box<Expr>, Box<Expr>),
    /// A call, with where it is written.
    Call(Func, Vec<Expr>, Span),
}

/// Where an assignment stores.
#[derive(Debug, Clone, PartialEq)]
pub enum Target {
    /// A global variable.
    Global(u32),
    /// A local slot.
    Local(u32),
    /// An array element.
    Elem(u32, Vec<Expr>, Span),
}

/// A statement of a `{ }` block (manual §3.2).
#[derive(Debug, Clone, PartialEq)]
pub enum Stmt {
    /// `x = e;`
    Assign(Target, Expr),
    /// A call for its effect (`printf(…);`, `srand(…);`).
    Expr(Expr),
    /// `if (c) { … } else { … }`
    If(Expr, Vec<Stmt>, Vec<Stmt>),
    /// `while (c) { … }`
    While(Expr, Vec<Stmt>),
    /// `do { … } while (c)`
    Do(Vec<Stmt>, Expr),
}

/// A module of an axiom or successor: a symbol and its argument expressions.
#[derive(Debug, Clone, PartialEq)]
pub struct Module {
    /// The symbol.
    pub sym: char,
    /// Arguments.
    pub args: Vec<Expr>,
    /// Where it is written.
    pub span: Span,
}

/// A module of a predecessor or context: a symbol and the local slots its
/// formal parameters bind.
#[derive(Debug, Clone, PartialEq)]
pub struct Pattern {
    /// The symbol.
    pub sym: char,
    /// Slots of the formal parameters; a module matches with exactly this many parameters.
    pub params: Vec<u32>,
}

/// `lc < pred > rc : { pre } cond { post } --> succ : prob` (manual §3).
#[derive(Debug, Clone, PartialEq)]
pub struct Production {
    /// Left context, in source order.
    pub left: Vec<Pattern>,
    /// The strict predecessor (one or more modules).
    pub pred: Vec<Pattern>,
    /// Right context.
    pub right: Vec<Pattern>,
    /// Statements run when the predecessor and contexts match.
    pub pre: Vec<Stmt>,
    /// The condition (`None`: `*`, true).
    pub cond: Option<Expr>,
    /// Statements run once the condition holds.
    pub post: Vec<Stmt>,
    /// The successor (empty: `*`).
    pub succ: Vec<Module>,
    /// The probability weight (stochastic systems only; default 1).
    pub prob: Option<Expr>,
    /// Local slots the production uses (parameters first).
    pub locals: u32,
    /// Where it is written.
    pub span: Span,
}

/// A global array (`define: { array a[2,3] = {…}; }`, manual §2.2.2).
#[derive(Debug, Clone, PartialEq)]
pub struct Array {
    /// Its name.
    pub name: String,
    /// Sizes of its dimensions.
    pub dims: Vec<usize>,
    /// Initial values, row-major (the rest are 0).
    pub init: Vec<f64>,
}

/// Decomposition or homomorphism productions and their maximum depth.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Group {
    /// The productions, in order.
    pub productions: Vec<Production>,
    /// `maximum depth:` (default 1).
    pub depth: u32,
    /// The homomorphism's own `seed:`, if given.
    pub seed: Option<i64>,
}

/// A parsed cpfg L-system (the first of the file; sub-L-systems are refused).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Cpfg {
    /// `derivation length:` (`None`: not given; the `.a` file or 0 decides).
    pub derivation_length: Option<u32>,
    /// The axiom.
    pub axiom: Vec<Module>,
    /// `seed:`: the system is stochastic (`lsys_input.y`, `Seed`).
    pub seed: Option<i64>,
    /// `ring lsystem`.
    pub ring: bool,
    /// `ignore:` symbols.
    pub ignore: Vec<char>,
    /// `consider:` symbols (`None`: all are considered).
    pub consider: Option<Vec<char>>,
    /// `start:` statements.
    pub start: Vec<Stmt>,
    /// `end:` statements.
    pub end: Vec<Stmt>,
    /// `startEach:` statements.
    pub start_each: Vec<Stmt>,
    /// `endEach:` statements.
    pub end_each: Vec<Stmt>,
    /// Local slots the axiom and the global blocks need.
    pub block_locals: u32,
    /// The L-system's productions.
    pub productions: Vec<Production>,
    /// Decomposition productions.
    pub decomposition: Group,
    /// Homomorphism productions.
    pub homomorphism: Group,
    /// Names of the global variables.
    pub globals: Vec<String>,
    /// Global arrays.
    pub arrays: Vec<Array>,
    /// Non-fatal diagnostics.
    pub warnings: Vec<Diagnostic>,
}
