//! The arithmetic of cpfg's expressions that needs no state (`cpfg/generate.c`,
//! `Eval`): operators, the deterministic built-in functions, and constant
//! folding for the header values the grammar evaluates at once
//! (`derivation length:`, `seed:`, array sizes). `crate::cpfg::eval` runs
//! the rest (variables, random numbers, user functions) on top of it.

use super::{BinOp, Expr, Func, UnOp};

fn rad(d: f64) -> f64 {
    d * std::f64::consts::PI / 180.0
}

fn deg(r: f64) -> f64 {
    r * 180.0 / std::f64::consts::PI
}

/// `x op y`; `None` for a zero divisor of `/` or `%` (the caller names the error).
pub fn binary(op: BinOp, x: f64, y: f64) -> Option<f64> {
    let b = |v: bool| f64::from(v);
    Some(match op {
        BinOp::Or => b(x != 0.0 || y != 0.0),
        BinOp::And => b(x != 0.0 && y != 0.0),
        BinOp::Eq => b(x == y),
        BinOp::Ne => b(x != y),
        BinOp::Lt => b(x < y),
        BinOp::Le => b(x <= y),
        BinOp::Gt => b(x > y),
        BinOp::Ge => b(x >= y),
        BinOp::Add => x + y,
        BinOp::Sub => x - y,
        BinOp::Mul => x * y,
        BinOp::Div if y == 0.0 => return None,
        BinOp::Div => x / y,
        // C's int conversion then %, as cpfg's `case tREM`.
        BinOp::Rem if y as i64 == 0 => return None,
        BinOp::Rem => (x as i64).wrapping_rem(y as i64) as f64,
        BinOp::Pow => x.powf(y),
    })
}

/// A deterministic built-in at `v` (`n` arguments given): trigonometry in
/// degrees, `trunc` rounding as cpfg's `floor(x + 0.5)`; `None` for the
/// functions that need the machine (random numbers, `func`, I/O).
pub fn function(f: Func, v: [f64; 2], n: usize) -> Option<f64> {
    let x = v[0];
    Some(match f {
        Func::Sin => rad(x).sin(),
        Func::Cos => rad(x).cos(),
        Func::Tan => rad(x).tan(),
        Func::Asin => deg(x.asin()),
        Func::Acos => deg(x.acos()),
        Func::Atan if n == 2 => deg(v[1].atan2(x)),
        Func::Atan => deg(x.atan()),
        Func::Atan2 => deg(v[1].atan2(x)),
        Func::Exp => x.exp(),
        Func::Log => x.ln(),
        Func::Sqrt => x.sqrt(),
        Func::Floor => x.floor(),
        Func::Ceil => x.ceil(),
        Func::Trunc => (x + 0.5).floor(),
        Func::Fabs => x.abs(),
        Func::Sign if x == 0.0 => 0.0,
        Func::Sign => x.signum(),
        _ => return None,
    })
}

/// The value of a constant expression (numbers, operators and deterministic
/// functions only).
pub fn constant(e: &Expr) -> Option<f64> {
    match e {
        Expr::Num(v) => Some(*v),
        Expr::Unary(UnOp::Neg, x) => constant(x).map(|v| -v),
        Expr::Unary(UnOp::Not, x) => constant(x).map(|v| f64::from(v == 0.0)),
        Expr::Binary(op, a, b, _) => binary(*op, constant(a)?, constant(b)?),
        Expr::Cond(c, a, b) => {
            if constant(c)? != 0.0 {
                constant(a)
            } else {
                constant(b)
            }
        }
        Expr::Call(f, args, _) => {
            let mut v = [0.0; 2];
            for (k, a) in args.iter().enumerate() {
                let x = constant(a)?;
                if let Some(s) = v.get_mut(k) {
                    *s = x;
                }
            }
            function(*f, v, args.len())
        }
        _ => None,
    }
}
