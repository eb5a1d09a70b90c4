//! Arithmetic expressions shared by every front end.
//!
//! Front ends parse them with the one grammar in [`grammar`] (each through
//! its own lexer and names) into [`Expr`] trees; the evaluator computes them with an
//! [`ExprEnv`] that supplies parameter values and per-site random numbers.
//! Expressions are pure apart from `rand()`, whose value comes from the
//! caller's deterministic stream, so the same inputs always give the same value.
//! Trigonometric functions work in radians. Transcendental functions come from
//! the pure-Rust `libm` crate, not the platform's C library, so values are
//! bit-identical on every machine (outputs are cached by content hash).

pub mod grammar;

/// A binary operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/` (division by zero yields a non-finite value, which the evaluator rejects)
    Div,
    /// `^` (power, right-associative)
    Pow,
    /// `<` (1 when true, else 0; likewise for the comparisons and logical operators below)
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `==`
    Eq,
    /// `!=`
    Ne,
    /// `&&`: 1 when both operands are non-zero
    And,
    /// `||`: 1 when either operand is non-zero
    Or,
}

/// A built-in function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    /// sin(x), radians
    Sin,
    /// cos(x), radians
    Cos,
    /// tan(x), radians
    Tan,
    /// asin(x), radians
    Asin,
    /// acos(x), radians
    Acos,
    /// atan(x), radians
    Atan,
    /// atan2(y, x), radians
    Atan2,
    /// sqrt(x)
    Sqrt,
    /// abs(x)
    Abs,
    /// min(a, b, …)
    Min,
    /// max(a, b, …)
    Max,
    /// floor(x)
    Floor,
    /// ceil(x)
    Ceil,
    /// pow(x, y)
    Pow,
    /// exp(x)
    Exp,
    /// log(x), natural
    Log,
}

impl Func {
    /// Looks a function name up (lower-case names as written in the source).
    pub fn from_name(name: &str) -> Option<Func> {
        Some(match name {
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "tan" => Func::Tan,
            "asin" => Func::Asin,
            "acos" => Func::Acos,
            "atan" => Func::Atan,
            "atan2" => Func::Atan2,
            "sqrt" => Func::Sqrt,
            "abs" => Func::Abs,
            "min" => Func::Min,
            "max" => Func::Max,
            "floor" => Func::Floor,
            "ceil" => Func::Ceil,
            "pow" => Func::Pow,
            "exp" => Func::Exp,
            "log" => Func::Log,
            _ => return None,
        })
    }

    /// How many arguments the function takes: (min, max); `None` max means "any number ≥ min".
    pub(crate) fn arity(self) -> (usize, Option<usize>) {
        match self {
            Func::Atan2 | Func::Pow => (2, Some(2)),
            Func::Min | Func::Max => (1, None),
            _ => (1, Some(1)),
        }
    }
}

/// An expression tree. Depth is bounded by the parser's nesting limit, so
/// recursive evaluation cannot overflow the stack.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// A literal.
    Num(f64),
    /// The value of `Program::params[i]`.
    Param(u32),
    /// Unary minus.
    Neg(Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// A function call (arity already checked by the parser).
    Func(Func, Vec<Expr>),
    /// `rand()`: uniform in [0, 1) from the stream of this site within the current call.
    Rand(u32),
    /// A coordinate of the current frame's origin: 0 = x, 1 = y, 2 = z
    /// (only where the language allows it, e.g. function selectors).
    Coord(u8),
}

/// What an expression needs from its surroundings.
pub trait ExprEnv {
    /// The bound value of parameter `index`.
    fn param(&self, index: u32) -> f64;
    /// A uniform number in [0, 1) for `rand()` site `site`, deterministic per invocation.
    fn rand(&mut self, site: u32) -> f64;
    /// Coordinate `axis` (0 = x, 1 = y, 2 = z) of the current position; NaN where there is none.
    fn coord(&self, _axis: u8) -> f64 {
        f64::NAN
    }
}

impl Expr {
    /// Computes the value. May be NaN or infinite (e.g. `1/0`); callers check.
    pub fn eval(&self, env: &mut dyn ExprEnv) -> f64 {
        match self {
            Expr::Num(v) => *v,
            Expr::Param(i) => env.param(*i),
            Expr::Neg(e) => -e.eval(env),
            Expr::Binary(op, a, b) => {
                let (a, b) = (a.eval(env), b.eval(env));
                match op {
                    BinOp::Add => a + b,
                    BinOp::Sub => a - b,
                    BinOp::Mul => a * b,
                    BinOp::Div => a / b,
                    BinOp::Pow => libm::pow(a, b),
                    BinOp::Lt => truth(a < b),
                    BinOp::Le => truth(a <= b),
                    BinOp::Gt => truth(a > b),
                    BinOp::Ge => truth(a >= b),
                    BinOp::Eq => truth(a == b),
                    BinOp::Ne => truth(a != b),
                    BinOp::And => truth(a != 0.0 && b != 0.0),
                    BinOp::Or => truth(a != 0.0 || b != 0.0),
                }
            }
            Expr::Func(f, args) => {
                let mut vals = args.iter().map(|a| a.eval(env));
                let mut next = || vals.next().unwrap_or(f64::NAN);
                match f {
                    Func::Sin => libm::sin(next()),
                    Func::Cos => libm::cos(next()),
                    Func::Tan => libm::tan(next()),
                    Func::Asin => libm::asin(next()),
                    Func::Acos => libm::acos(next()),
                    Func::Atan => libm::atan(next()),
                    Func::Atan2 => {
                        let y = next();
                        libm::atan2(y, next())
                    }
                    Func::Sqrt => libm::sqrt(next()),
                    Func::Abs => next().abs(),
                    Func::Floor => next().floor(),
                    Func::Ceil => next().ceil(),
                    Func::Pow => {
                        let b = next();
                        libm::pow(b, next())
                    }
                    Func::Exp => libm::exp(next()),
                    Func::Log => libm::log(next()),
                    Func::Min => {
                        let first = next();
                        vals.fold(first, f64::min)
                    }
                    Func::Max => {
                        let first = next();
                        vals.fold(first, f64::max)
                    }
                }
            }
            Expr::Rand(site) => env.rand(*site),
            Expr::Coord(axis) => env.coord(*axis),
        }
    }

    /// True when the expression contains no `rand()`, so its value depends only on parameters.
    pub(crate) fn is_deterministic(&self) -> bool {
        match self {
            Expr::Num(_) | Expr::Param(_) => true,
            Expr::Rand(_) | Expr::Coord(_) => false,
            Expr::Neg(e) => e.is_deterministic(),
            Expr::Binary(_, a, b) => a.is_deterministic() && b.is_deterministic(),
            Expr::Func(_, args) => args.iter().all(Expr::is_deterministic),
        }
    }
}

/// 1 for true, 0 for false: how comparisons and logical operators report.
fn truth(b: bool) -> f64 {
    if b {
        1.0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Env;
    impl ExprEnv for Env {
        fn param(&self, i: u32) -> f64 {
            f64::from(i) * 10.0
        }
        fn rand(&mut self, _site: u32) -> f64 {
            0.25
        }
    }

    fn n(v: f64) -> Box<Expr> {
        Box::new(Expr::Num(v))
    }

    #[test]
    fn evaluates_operators_functions_params_and_rand() {
        let e = Expr::Binary(
            BinOp::Add,
            Box::new(Expr::Func(Func::Max, vec![Expr::Num(1.0), Expr::Param(2), Expr::Num(3.0)])),
            Box::new(Expr::Binary(BinOp::Pow, n(2.0), n(3.0))),
        );
        assert_eq!(e.eval(&mut Env), 28.0);
        assert_eq!(Expr::Rand(7).eval(&mut Env), 0.25);
        assert!(!Expr::Rand(7).is_deterministic());
        assert!(e.is_deterministic());
        let e = Expr::Func(Func::Atan2, vec![Expr::Num(1.0), Expr::Num(0.0)]);
        assert!((e.eval(&mut Env) - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }

    #[test]
    fn comparisons_and_logic_give_one_or_zero() {
        let b = |op, x, y| Expr::Binary(op, n(x), n(y)).eval(&mut Env);
        assert_eq!(b(BinOp::Lt, 1.0, 2.0), 1.0);
        assert_eq!(b(BinOp::Ge, 1.0, 2.0), 0.0);
        assert_eq!(b(BinOp::Eq, 2.0, 2.0), 1.0);
        assert_eq!(b(BinOp::Ne, 2.0, 2.0), 0.0);
        assert_eq!(b(BinOp::And, 1.0, 0.0), 0.0);
        assert_eq!(b(BinOp::Or, 1.0, 0.0), 1.0);
    }

    #[test]
    fn division_by_zero_is_not_finite() {
        let e = Expr::Binary(BinOp::Div, n(1.0), n(0.0));
        assert!(!e.eval(&mut Env).is_finite());
    }
}
