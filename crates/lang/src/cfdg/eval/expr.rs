//! Expressions as cfdg evaluates them (`ASTfunction::evaluate`,
//! `ASToperator::evaluate`, `astexpression.cpp`, Context Free 3.4): trig in
//! degrees, `rand` family drawing from the current random stream, lists
//! flattening into tuples.

use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::Expr;
use crate::model::EvalError;
use crate::Span;

/// Variables in scope: globals first, then the locals pushed by loops and
/// definitions (searched from the top), then those of the enclosing scope
/// (a `let` sees its caller's variables; a user function only the globals).
#[derive(Debug, Clone)]
pub struct Scope<'a> {
    /// Name and value (a tuple) of each variable.
    pub vars: Vec<(String, Vec<f64>)>,
    /// The enclosing scope and how many of its variables are visible.
    pub(crate) up: Option<(&'a Scope<'a>, usize)>,
    /// How many of `vars` are globals (all of them while the globals are
    /// being evaluated); what a user function sees of this scope.
    pub globals: Option<usize>,
    /// The largest natural number `isNatural` accepts (`CF::MaxNatural`,
    /// cfdg's default 1000); infinite under `CF::Impure`.
    pub max_natural: f64,
    /// The user functions and the count of calls made ([`super::func`]).
    pub funcs: std::sync::Arc<super::func::Functions>,
    /// The number each `rand_static()` drew at parse time, by where it is
    /// written ([`crate::cfdg::eval::rand_static`]).
    pub rand_static: std::sync::Arc<Vec<(crate::Span, f64)>>,
}

impl Default for Scope<'_> {
    fn default() -> Self {
        Scope { vars: Vec::new(), up: None, globals: None, max_natural: 1000.0, funcs: Default::default(), rand_static: Default::default() }
    }
}

impl Scope<'_> {
    pub(crate) fn get(&self, name: &str) -> Option<&[f64]> {
        self.find_in(&|n: &str| n == name, self.vars.len())
    }

    /// The value of `marker` + `name` (a shape or adjustment variable's
    /// key), found without building the key: the renderer asks this for
    /// every shape it places. The length is compared first, so most keys
    /// are passed over without comparing a byte (a third of the bush's
    /// time went to `memcmp` on the marker when it was compared first).
    pub(crate) fn get_marked(&self, marker: char, name: &str) -> Option<&[f64]> {
        let len = marker.len_utf8() + name.len();
        self.find_in(&|n: &str| n.len() == len && n.ends_with(name) && n.starts_with(marker), self.vars.len())
    }

    /// The innermost visible variable whose key `is` accepts, this scope's
    /// first `visible` variables and then the enclosing scopes'.
    fn find_in<F: Fn(&str) -> bool>(&self, is: &F, visible: usize) -> Option<&[f64]> {
        match self.vars[..visible.min(self.vars.len())].iter().rev().find(|(n, _)| is(n)) {
            Some((_, v)) => Some(v.as_slice()),
            None => self.up.and_then(|(s, n)| s.find_in(is, n)),
        }
    }
}

/// Largest tuple an expression may build (cfdg's adjustments take at most 6).
const MAX_TUPLE: usize = 100;

fn bad(span: Span, what: &str, value: impl std::fmt::Display) -> EvalError {
    EvalError::NonFinite { span, what: what.to_string(), value: value.to_string() }
}

/// Evaluates `e` and appends its values to `out`.
pub fn eval(e: &Expr, scope: &Scope, rand: &mut Rand64, out: &mut Vec<f64>) -> Result<(), EvalError> {
    match e {
        Expr::Num(v, _) => out.push(*v),
        Expr::Var(name, span) => match scope.get(name) {
            Some(v) => out.extend_from_slice(v),
            None if name == "infinity" => out.push(f64::INFINITY),
            None if super::shapeval::var_fallback(name, scope, out) => {}
            None => return Err(bad(*span, &format!("`{name}` (not defined)"), "undefined")),
        },
        Expr::Paren(a) => eval(a, scope, rand, out)?,
        Expr::Cons(v) => {
            for a in v {
                eval(a, scope, rand, out)?;
                if out.len() > MAX_TUPLE {
                    return Err(bad(Span::new(1, 1), "a list", "too long"));
                }
            }
        }
        Expr::Unary(op, a) => {
            if *op == '!' {
                let x = scalar(a, scope, rand)?;
                out.push(f64::from(x == 0.0));
            } else {
                // `-` and `+` apply to every element of a tuple (ASToperator::evaluate).
                let from = out.len();
                eval(a, scope, rand, out)?;
                if *op == 'N' {
                    out[from..].iter_mut().for_each(|v| *v = -*v);
                }
            }
        }
        Expr::Binary(op, a, b) if matches!(op, '+' | '-' | '_' | '*' | '/' | '=' | 'n') => {
            // Tuples: element-wise, or a scalar against each element for
            // `*` and `/` (ASToperator::compile's size rules and evaluate).
            let (mut l, mut r) = (Vec::new(), Vec::new());
            eval(a, scope, rand, &mut l)?;
            eval(b, scope, rand, &mut r)?;
            let (ln, rn) = (l.len(), r.len());
            let same = ln == rn && ln >= 1;
            let scaled = matches!(op, '*' | '/') && (ln == 1 || rn == 1) && ln >= 1 && rn >= 1;
            if !same && !scaled {
                return Err(EvalError::BadParam { name: "expression".into(), message: format!("operands of `{}` have {ln} and {rn} numbers", op_text(*op)) });
            }
            let n = ln.max(rn);
            let at = |v: &[f64], i: usize| if v.len() == 1 { v[0] } else { v[i] };
            match op {
                '=' => out.push(f64::from(l == r)),
                'n' => out.push(f64::from(l != r)),
                _ => {
                    for i in 0..n {
                        let (x, y) = (at(&l, i), at(&r, i));
                        out.push(match op {
                            '+' => x + y,
                            '-' => x - y,
                            '*' => x * y,
                            '/' => x / y,
                            _ => {
                                if x - y > 0.0 {
                                    x - y
                                } else {
                                    0.0
                                }
                            }
                        });
                    }
                }
            }
        }
        Expr::Binary(op, a, b) => {
            let x = scalar(a, scope, rand)?;
            // && and || short-circuit as cfdg's do, giving the deciding
            // operand's value (ASToperator::evaluate).
            if *op == '&' && x == 0.0 {
                out.push(0.0);
                return Ok(());
            }
            if *op == '|' && x != 0.0 {
                out.push(x);
                return Ok(());
            }
            let y = scalar(b, scope, rand)?;
            out.push(match op {
                '^' => x.powf(y),
                '<' => f64::from(x < y),
                '>' => f64::from(x > y),
                'L' => f64::from(x <= y),
                'G' => f64::from(x >= y),
                '&' | '|' => y,
                'X' => f64::from((x != 0.0) != (y != 0.0)),
                _ => f64::NAN,
            });
        }
        Expr::Call(name, args, span) if name == "if" || name == "select" => {
            // Only the chosen argument is evaluated (ASTselect::evaluate), so
            // only its random numbers are drawn.
            let items = args.as_ref().as_ref().map(|a| a.items()).unwrap_or_default();
            if items.len() < 3 || (name == "if" && items.len() != 3) {
                return Err(EvalError::BadParam { name: name.clone(), message: format!("{}:{}: expected a selector and at least two choices", span.line, span.column) });
            }
            let sel = scalar(items[0], scope, rand)?;
            let i = if name == "if" {
                usize::from(sel == 0.0)
            } else if sel < 0.0 || sel.is_nan() {
                0
            } else {
                (sel as usize).min(items.len() - 2)
            };
            eval(items[1 + i], scope, rand, out)?;
        }
        Expr::Call(name, args, span) if matches!(name.as_str(), "dot" | "cross" | "hsb2rgb" | "rgb2hsb" | "vec") => {
            super::func::vector_builtin(name, args.as_ref().as_ref(), *span, scope, rand, out)?;
        }
        Expr::Call(name, args, span) if !crate::cfdg::syntax::is_builtin(name) => {
            super::func::call(name, args.as_ref().as_ref(), *span, scope, rand, out)?;
        }
        Expr::Let(defs, body, span) => super::func::let_in(defs, body, *span, scope, rand, out)?,
        Expr::Index(name, args, span) => super::func::index(name, args, *span, scope, rand, out)?,
        Expr::Shape(name, shape, args, span) => super::shapeval::shape_value(name, *shape, args.as_ref().as_ref(), *span, scope, rand, out)?,
        Expr::Adjust(a, _) => super::shapeval::adjust_value(a, scope, rand, out)?,
        Expr::Call(name, args, span) => {
            let mut a = Vec::new();
            if let Some(x) = args.as_ref() {
                eval(x, scope, rand, &mut a)?;
            }
            out.push(call(name, &a, rand, *span, scope)?);
        }
    }
    Ok(())
}

fn op_text(op: char) -> &'static str {
    match op {
        '+' => "+",
        '-' => "-",
        '_' => "--",
        '*' => "*",
        '/' => "/",
        '=' => "==",
        _ => "!=",
    }
}

/// Evaluates `e` to one number.
pub fn scalar(e: &Expr, scope: &Scope, rand: &mut Rand64) -> Result<f64, EvalError> {
    let mut v = Vec::with_capacity(1);
    eval(e, scope, rand, &mut v)?;
    match v.as_slice() {
        [x] => Ok(*x),
        _ => Err(EvalError::BadParam { name: "expression".into(), message: format!("expected one number, got {}", v.len()) }),
    }
}

const DEG: f64 = 0.0174532925199;
const RAD: f64 = 57.29577951308;

fn call(name: &str, a: &[f64], rand: &mut Rand64, span: Span, scope: &Scope) -> Result<f64, EvalError> {
    let max_natural = scope.max_natural;
    let arg = |i: usize| a.get(i).copied().unwrap_or(0.0);
    let want = |n: usize| -> Result<(), EvalError> {
        if a.len() == n {
            Ok(())
        } else {
            Err(EvalError::BadParam { name: name.to_string(), message: format!("{}:{}: expected {n} arguments, got {}", span.line, span.column, a.len()) })
        }
    };
    // `rand()` is [0,1), `rand(x)` [0,x), `rand(a,b)` [a,b) (ASTfunction's constructor fills the pair).
    let pair = |a: &[f64]| match a.len() {
        0 => (0.0, 1.0),
        1 => (0.0, a[0]),
        _ => (a[0], a[1]),
    };
    Ok(match name {
        "rand_static" => {
            // Drawn at parse time (ASTfunction's constructor): without its
            // number (a fold with no design scope) it is not constant here.
            let Some(&(_, r)) = scope.rand_static.iter().find(|(at, _)| *at == span) else {
                return Err(EvalError::BadParam { name: name.to_string(), message: format!("{}:{}: not drawn yet", span.line, span.column) });
            };
            let (lo, hi) = pair(a);
            r * (hi - lo).abs() + lo.min(hi)
        }
        "rand" | "rand." => {
            let (lo, hi) = pair(a);
            rand.next_double() * (hi - lo).abs() + lo.min(hi)
        }
        "rand+/-" => {
            want(2)?;
            (rand.next_double() * 2.0 - 1.0) * a[1] + a[0]
        }
        "randint" => {
            // `randint()` is [0, 2) (ASTfunction's constructor).
            let (lo, hi) = if a.is_empty() { (0.0, 2.0) } else { pair(a) };
            (rand.next_double() * (hi - lo).abs() + lo.min(hi)).floor()
        }
        "ftime" | "frame" => {
            want(0)?;
            super::anim::value(name, scope)
        }
        "cos" => (arg(0) * DEG).cos(),
        "sin" => (arg(0) * DEG).sin(),
        "tan" => (arg(0) * DEG).tan(),
        "cot" => 1.0 / (arg(0) * DEG).tan(),
        "acos" => arg(0).acos() * RAD,
        "asin" => arg(0).asin() * RAD,
        "atan" => arg(0).atan() * RAD,
        "acot" => (1.0 / arg(0)).atan() * RAD,
        "atan2" => {
            want(2)?;
            a[0].atan2(a[1]) * RAD
        }
        "cosh" => arg(0).cosh(),
        "sinh" => arg(0).sinh(),
        "tanh" => arg(0).tanh(),
        "acosh" => arg(0).acosh(),
        "asinh" => arg(0).asinh(),
        "atanh" => arg(0).atanh(),
        "log" => arg(0).ln(),
        "log10" => arg(0).log10(),
        "sqrt" => arg(0).sqrt(),
        "exp" => arg(0).exp(),
        "abs" => arg(0).abs(),
        "floor" => arg(0).floor(),
        "ceiling" => arg(0).ceil(),
        "infinity" => {
            if a.is_empty() {
                f64::INFINITY
            } else {
                f64::INFINITY.copysign(arg(0))
            }
        }
        "sg" => {
            if arg(0) == 0.0 {
                0.0
            } else {
                1.0
            }
        }
        "factorial" => {
            let n = arg(0);
            if !(0.0..=170.0).contains(&n) || n.fract() != 0.0 {
                return Err(bad(span, "factorial's argument", n));
            }
            (1..=n as u32).map(f64::from).product()
        }
        "isNatural" => f64::from(arg(0) >= 0.0 && arg(0) <= max_natural && arg(0) == arg(0).floor()),
        "div" => {
            want(2)?;
            (a[0] / a[1]).floor()
        }
        "divides" => {
            want(2)?;
            f64::from(a[0] % a[1] == 0.0)
        }
        "mod" => {
            want(2)?;
            let m = a[0] % a[1];
            if m != 0.0 && (m < 0.0) != (a[1] < 0.0) {
                m + a[1]
            } else {
                m
            }
        }
        "min" => a.iter().copied().fold(f64::INFINITY, f64::min),
        "max" => a.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        "bitnot" | "bitor" | "bitand" | "bitxor" | "bitleft" | "bitright" => {
            // On 64-bit integers, kept to 52 bits (ASTfunction::evaluate).
            let n = if name == "bitnot" { 1 } else { 2 };
            want(n)?;
            let (x, y) = (a[0] as u64, if n == 2 { a[1] as u64 } else { 0 });
            let v = match name {
                "bitnot" => !x,
                "bitor" => x | y,
                "bitand" => x & y,
                "bitxor" => x ^ y,
                "bitleft" => x.checked_shl(y.min(64) as u32).unwrap_or(0),
                _ => x.checked_shr(y.min(64) as u32).unwrap_or(0),
            };
            (v & 0x000F_FFFF_FFFF_FFFF) as f64
        }
        n if super::distributions::is_distribution(n) => super::distributions::draw(n, a, rand, span)?,
        _ => return Err(EvalError::BadParam { name: name.to_string(), message: format!("{}:{}: unknown or unsupported function", span.line, span.column) }),
    })
}
