//! Evaluation of cpfg's expressions and `{ }` blocks, as cpfg's `Eval` and
//! `ProcessStatements` do (`AlgorithmicBotany/vlab`, `cpfg/generate.c`):
//! floats throughout, trigonometry in degrees, `trunc` rounding, `%` on the
//! integer parts, random numbers from the `erand48` stream cpfg keeps in
//! `main_xsubi` (`cpfg/utility.c`), reproduced bit for bit by [`Rand48`].
//!
//! Every statement run and every loop iteration is one step of the budget,
//! so `while (1) { }` ends at the step limit (or the deadline), named.
//! cpfg divides by 1 where a divisor is 0 and warns; here a zero divisor is
//! an error naming its position (the issue asks hostile input to fail,
//! `docs/cpfg.md` records the difference).

use super::syntax::{pure, BinOp, Cpfg, Expr, Func, Stmt, Target, UnOp};
use crate::core::budget::Budget;
use crate::core::Span;
use crate::model::EvalError;

/// The 48-bit linear congruential generator of POSIX `drand48`/`erand48`
/// (X ← 0x5DEECE66D·X + 0xB mod 2⁴⁸), which cpfg uses for both its
/// production choice and `ran`/`nran`; `next` is X / 2⁴⁸ as glibc's
/// `erand48` builds it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Rand48 {
    x: u64,
}

const MASK48: u64 = (1 << 48) - 1;

impl Rand48 {
    /// The state of `seed48({s0, s1, s2})` or of an `erand48` buffer.
    pub(crate) fn from_words(w: [u16; 3]) -> Rand48 {
        Rand48 { x: u64::from(w[0]) | u64::from(w[1]) << 16 | u64::from(w[2]) << 32 }
    }

    /// `drand48`'s state before any seeding (glibc: 0x1234ABCD330E).
    pub fn unseeded() -> Rand48 {
        Rand48 { x: 0x1234_ABCD_330E }
    }

    /// The state of cpfg's production choice after `seed: s` (`cpfg/control.c`:
    /// `seed48({seed, 0, 155})` when the seed is not 0).
    pub(crate) fn cpfg_choice(seed: i64) -> Rand48 {
        if seed as u16 == 0 {
            return Rand48::unseeded();
        }
        Rand48::from_words([seed as u16, 0, 155])
    }

    /// The state `srand(a)` gives `main_xsubi` (`cpfg/utility.c`, `Do_srand`).
    pub(crate) fn cpfg_srand(a: i64) -> Rand48 {
        Rand48::from_words([0x330E, (a & 0xFFFF) as u16, ((a >> 16) & 0xFFFF) as u16])
    }

    /// The next number in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.x = 0x5_DEEC_E66Du64.wrapping_mul(self.x).wrapping_add(0xB) & MASK48;
        self.x as f64 / (1u64 << 48) as f64
    }
}

/// The state blocks and productions work on: globals, arrays and the random streams.
#[derive(Debug, Clone)]
pub(crate) struct Machine {
    /// Global variables.
    pub globals: Vec<f64>,
    /// Global arrays, row-major, with their dimensions.
    pub arrays: Vec<(Vec<usize>, Vec<f64>)>,
    /// The stream of `ran`, `nran`, `bran`, `biran` (`main_xsubi`).
    pub ran: Rand48,
    /// `nran`'s second normal deviate, kept for the next call (`nrand`'s `gset`).
    gauss: Option<f64>,
    /// The stream stochastic productions are chosen with (`drand48`).
    pub choice: Rand48,
    /// The view's functions, `func(1, x)` first.
    pub funcs: Vec<super::func::Function>,
    /// The ids `func` was called with that no function answers, each with
    /// the first call's place: cpfg gives 0 for them with a message on its
    /// console (`SplineFuncValue`), so a render says so in its warnings
    /// (a model sent without its `.fset` otherwise draws every length 0).
    pub missing_funcs: std::collections::BTreeMap<i64, Span>,
}

fn non_finite(span: Span, what: &str, v: f64) -> EvalError {
    EvalError::NonFinite { span, what: what.to_string(), value: format!("{v}") }
}

impl Machine {
    /// The machine of `sys` before its `start:` block, with the streams seeded.
    pub fn new(sys: &Cpfg, choice: Rand48, ran: Rand48) -> Machine {
        let arrays = sys
            .arrays
            .iter()
            .map(|a| {
                let size = a.dims.iter().product::<usize>();
                let mut v = a.init.clone();
                v.resize(size, 0.0);
                (a.dims.clone(), v)
            })
            .collect();
        Machine { globals: vec![0.0; sys.globals.len()], arrays, ran, gauss: None, choice, funcs: Vec::new(), missing_funcs: Default::default() }
    }

    fn index(&mut self, a: u32, idx: &[Expr], span: Span, locals: &mut [f64], budget: &mut Budget) -> Result<usize, EvalError> {
        let mut flat = 0usize;
        let dims = self.arrays.get(a as usize).map(|x| x.0.clone()).unwrap_or_default();
        if idx.len() != dims.len() {
            return Err(EvalError::BadIteration { span, value: format!("{} indices for an array of {} dimensions", idx.len(), dims.len()) });
        }
        for (e, d) in idx.iter().zip(&dims) {
            let v = self.eval(e, locals, budget)?;
            if !(v >= 0.0 && v < *d as f64) {
                return Err(EvalError::BadIteration { span, value: format!("array index {v} outside 0..{d}") });
            }
            flat = flat * d + v as usize;
        }
        Ok(flat)
    }

    /// Evaluates `e` with the production's `locals`.
    pub fn eval(&mut self, e: &Expr, locals: &mut [f64], budget: &mut Budget) -> Result<f64, EvalError> {
        Ok(match e {
            Expr::Num(v) => *v,
            Expr::Str => 0.0,
            Expr::Global(g) => self.globals.get(*g as usize).copied().unwrap_or(0.0),
            Expr::Local(l) => locals.get(*l as usize).copied().unwrap_or(0.0),
            Expr::Elem(a, idx, span) => {
                let k = self.index(*a, idx, *span, locals, budget)?;
                self.arrays[*a as usize].1[k]
            }
            Expr::Unary(UnOp::Neg, x) => -self.eval(x, locals, budget)?,
            Expr::Unary(UnOp::Not, x) => f64::from(self.eval(x, locals, budget)? == 0.0),
            Expr::Cond(c, a, b) => {
                if self.eval(c, locals, budget)? != 0.0 {
                    self.eval(a, locals, budget)?
                } else {
                    self.eval(b, locals, budget)?
                }
            }
            Expr::Binary(op, a, b, span) => {
                let x = self.eval(a, locals, budget)?;
                // cpfg's stack machine evaluates both sides of && and || too.
                let y = self.eval(b, locals, budget)?;
                binary(*op, x, y, *span)?
            }
            Expr::Call(f, args, span) => {
                let mut v = [0.0; 2];
                for (k, a) in args.iter().enumerate() {
                    let x = self.eval(a, locals, budget)?;
                    if let Some(s) = v.get_mut(k) {
                        *s = x;
                    }
                }
                self.call(*f, v, args.len(), *span, budget)?
            }
        })
    }

    fn call(&mut self, f: Func, v: [f64; 2], n: usize, span: Span, budget: &mut Budget) -> Result<f64, EvalError> {
        if let Some(r) = pure::function(f, v, n) {
            return Ok(r);
        }
        let x = v[0];
        Ok(match f {
            Func::Ran => self.ran.uniform() * x,
            Func::Nran => self.nran(x, v[1], budget)?,
            Func::Bran => self.bran(x, v[1], span, budget)?,
            Func::Biran => {
                let trials = x.clamp(0.0, 1e9) as u64;
                budget.charge_steps(trials)?;
                (0..trials).filter(|_| self.ran.uniform() <= v[1]).count() as f64
            }
            Func::Srand => {
                self.ran = Rand48::cpfg_srand(x as i64);
                self.gauss = None;
                0.0
            }
            // cpfg warns and gives 0 for an id without a function (`SplineFuncValue`).
            Func::Func => match (x as i64).checked_sub(1).and_then(|k| usize::try_from(k).ok()).and_then(|k| self.funcs.get(k)) {
                Some(f) => f.value(v[1]),
                None => {
                    self.missing_funcs.entry(x as i64).or_insert(span);
                    0.0
                }
            },
            // The deterministic functions were answered by `pure::function`.
            _ => 0.0,
        })
    }

    /// `nrand` of `cpfg/utility.c`: Marsaglia's polar method, the second
    /// deviate kept for the next call.
    fn nran(&mut self, mean: f64, sd: f64, budget: &mut Budget) -> Result<f64, EvalError> {
        if let Some(g) = self.gauss.take() {
            return Ok(g * sd + mean);
        }
        loop {
            budget.charge_step()?;
            let v1 = 2.0 * self.ran.uniform() - 1.0;
            let v2 = 2.0 * self.ran.uniform() - 1.0;
            let rsq = v1 * v1 + v2 * v2;
            if rsq < 1.0 && rsq != 0.0 {
                let fac = (-2.0 * rsq.ln() / rsq).sqrt();
                self.gauss = Some(v1 * fac);
                return Ok(v2 * fac * sd + mean);
            }
        }
    }

    /// A Beta(a, b) deviate by Cheng's algorithm BA, as cpfg's `brand`
    /// (`cpfg/utility.c`, by Paul Kruszewski), from the same stream.
    fn bran(&mut self, a: f64, b: f64, span: Span, budget: &mut Budget) -> Result<f64, EvalError> {
        if !(a > 0.0 && b > 0.0 && (a + b).is_finite()) {
            return Err(non_finite(span, "bran() shape", a.min(b)));
        }
        let s = a + b;
        let lambda = if a.min(b) <= 1.0 { a.min(b) } else { ((2.0 * a * b - s) / (s - 2.0)).sqrt() };
        let u = a + lambda;
        loop {
            budget.charge_step()?;
            let mut u1 = self.ran.uniform();
            while u1 == 0.0 {
                u1 = self.ran.uniform();
            }
            let mut u2 = self.ran.uniform();
            while u2 == 0.0 {
                u2 = self.ran.uniform();
            }
            let v = (1.0 / lambda) * (u1 / (1.0 - u1)).ln();
            let ym = a * v.exp();
            if s * (s / (b + ym)).ln() + u * v - 4f64.ln() >= (u1 * u1 * u2).ln() {
                return Ok(ym / (b + ym));
            }
        }
    }

    /// Runs `stmts`, one step per statement and per loop iteration.
    pub fn run(&mut self, stmts: &[Stmt], locals: &mut [f64], budget: &mut Budget) -> Result<(), EvalError> {
        for s in stmts {
            budget.charge_step()?;
            match s {
                Stmt::Assign(t, e) => {
                    let v = self.eval(e, locals, budget)?;
                    match t {
                        Target::Global(g) => {
                            if let Some(x) = self.globals.get_mut(*g as usize) {
                                *x = v;
                            }
                        }
                        Target::Local(l) => {
                            if let Some(x) = locals.get_mut(*l as usize) {
                                *x = v;
                            }
                        }
                        Target::Elem(a, idx, span) => {
                            let k = self.index(*a, idx, *span, locals, budget)?;
                            self.arrays[*a as usize].1[k] = v;
                        }
                    }
                }
                Stmt::Expr(e) => {
                    self.eval(e, locals, budget)?;
                }
                Stmt::If(c, a, b) => {
                    if self.eval(c, locals, budget)? != 0.0 {
                        self.run(a, locals, budget)?;
                    } else {
                        self.run(b, locals, budget)?;
                    }
                }
                Stmt::While(c, body) => {
                    while self.eval(c, locals, budget)? != 0.0 {
                        budget.charge_step()?;
                        self.run(body, locals, budget)?;
                    }
                }
                Stmt::Do(body, c) => loop {
                    budget.charge_step()?;
                    self.run(body, locals, budget)?;
                    if self.eval(c, locals, budget)? == 0.0 {
                        break;
                    }
                },
            }
        }
        Ok(())
    }
}

fn binary(op: BinOp, x: f64, y: f64, span: Span) -> Result<f64, EvalError> {
    pure::binary(op, x, y).ok_or_else(|| non_finite(span, if op == BinOp::Rem { "divisor of %" } else { "divisor" }, y))
}
