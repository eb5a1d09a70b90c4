//! Derivation as cpfg performs it (`AlgorithmicBotany/vlab`,
//! `cpfg/generate.c`, `Derive`, `FindProd`, `ApplyProd`,
//! `ApplyRecursiveProductions`): the string is read left to right; at
//! each module the first production (in file order) whose strict
//! predecessor, contexts and condition match is applied — its `{ }`
//! blocks run then, in string order, so globals they change are seen by
//! the modules after — and the modules it covers are skipped. In a
//! stochastic system (one with `seed:`) every matching production is a
//! candidate, weighted by its probability, and one is drawn from
//! `drand48` (`SelectProd`). A `%` no production rewrites cuts its branch
//! (`SkipCutPart`: up to the unmatched `]`, which stays). Decomposition
//! productions are applied to every successor module, recursively up to
//! their maximum depth; homomorphism productions the same way to the string
//! handed to the turtle, with context taken from the derived string.

use super::eval::{Machine, Rand48};
use super::string::CString;
use super::syntax::{Cpfg, Group, Pattern, Production};
use crate::core::budget::{Budget, LimitExceeded, OnLimit};
use crate::core::Span;
use crate::model::EvalError;

/// Context matching settings of a system.
struct Ctx<'a> {
    ignore: &'a [char],
    consider: Option<&'a [char]>,
}

impl Ctx<'_> {
    fn skipped(&self, s: char) -> bool {
        if s == '[' || s == ']' {
            return false;
        }
        self.ignore.contains(&s) || self.consider.is_some_and(|c| !c.contains(&s))
    }
}

/// A derivation in progress: the machine and the system.
pub(crate) struct Deriver<'a> {
    sys: &'a Cpfg,
    /// Globals, arrays and random streams.
    pub machine: Machine,
    ctx: Ctx<'a>,
}

/// The derived string, with the machine after it and the limit that cut it short.
pub(crate) struct Derived {
    /// The string after the last step.
    pub string: CString,
    /// Set when a limit stopped the derivation (`on_limit: truncate`).
    pub truncated: Option<LimitExceeded>,
}

fn finite(v: f64, span: Span) -> Result<f64, EvalError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(EvalError::NonFinite { span, what: "module parameter".into(), value: format!("{v}") })
    }
}

impl<'a> Deriver<'a> {
    /// A deriver for `sys`; `seed` (the request's) replaces the system's
    /// `seed:` for the choice of productions and seeds `ran` as `srand` would.
    pub fn new(sys: &'a Cpfg, seed: Option<u64>) -> Deriver<'a> {
        let choice = Rand48::cpfg_choice(seed.map(|s| s as i64).or(sys.seed).unwrap_or(0));
        let ran = match seed {
            Some(s) => Rand48::cpfg_srand(s as i64),
            None => Rand48::from_words([0x330E, 0, 0]),
        };
        let ctx = Ctx { ignore: &sys.ignore, consider: sys.consider.as_deref() };
        Deriver { sys, machine: Machine::new(sys, choice, ran), ctx }
    }

    /// Runs `start:` and builds the axiom.
    pub fn axiom(&mut self, budget: &mut Budget) -> Result<CString, EvalError> {
        let mut locals = vec![0.0; self.sys.block_locals as usize];
        self.machine.run(&self.sys.start, &mut locals, budget)?;
        let mut s = CString::new();
        for m in &self.sys.axiom {
            budget.charge_step()?;
            let mut p = Vec::with_capacity(m.args.len());
            for a in &m.args {
                p.push(finite(self.machine.eval(a, &mut locals, budget)?, m.span)?);
            }
            s.push(m.sym, &p, budget)?;
        }
        Ok(s)
    }

    /// Derives `steps` steps from the axiom (then runs `end:`); with a
    /// view, a system that queries the turtle has its queries filled in
    /// after the axiom and every step (on the derived string: a
    /// homomorphism is not applied first).
    pub fn derive(&mut self, steps: u32, view: Option<&super::view::View>, on_limit: OnLimit, budget: &mut Budget) -> Result<Derived, EvalError> {
        let queries = view.filter(|_| super::lower::has_queries(self.sys));
        let mut cur = self.axiom(budget)?;
        if let Some(v) = queries {
            super::lower::fill_queries(&mut cur, v, budget)?;
        }
        let mut truncated = None;
        let mut locals = vec![0.0; self.sys.block_locals as usize];
        for _ in 0..steps {
            let mark = cur.bytes();
            let r = self.machine.run(&self.sys.start_each, &mut locals, budget).and_then(|()| self.step(&cur, budget));
            match r {
                Ok(mut next) => {
                    budget.release_memory(mark);
                    if let Some(v) = queries {
                        super::lower::fill_queries(&mut next, v, budget)?;
                    }
                    cur = next;
                }
                Err(EvalError::Limit(l)) if on_limit == OnLimit::Truncate => {
                    truncated = Some(l);
                    break;
                }
                Err(e) => return Err(e),
            }
            self.machine.run(&self.sys.end_each, &mut locals, budget)?;
        }
        if truncated.is_none() {
            self.machine.run(&self.sys.end, &mut locals, budget)?;
        }
        Ok(Derived { string: cur, truncated })
    }

    /// One derivation step.
    pub fn step(&mut self, cur: &CString, budget: &mut Budget) -> Result<CString, EvalError> {
        let partners = cur.partners();
        let mut next = CString::new();
        let mut i = 0;
        let stochastic = self.sys.seed.is_some();
        while i < cur.len() {
            budget.charge_step()?;
            let chosen = if stochastic { self.choose(cur, &partners, i, budget)? } else { self.first(&self.sys.productions, cur, &partners, i, budget)? };
            match chosen {
                Some((p, mut locals)) => {
                    self.machine.run(&p.post, &mut locals, budget)?;
                    let succ = self.successor(p, &mut locals, budget)?;
                    let left = i;
                    i += p.pred.len();
                    self.decompose(&succ, cur, &partners, left, i, &mut next, budget)?;
                }
                None if cur.syms[i] == '%' && cur.params_of(i).len() <= 1 => {
                    // Cut: skip to the `]` closing this branch (kept), or the end.
                    let mut level = 0usize;
                    i += 1;
                    while i < cur.len() {
                        match cur.syms[i] {
                            '[' => level += 1,
                            ']' if level == 0 => break,
                            ']' => level -= 1,
                            _ => {}
                        }
                        i += 1;
                    }
                }
                None => {
                    let mut one = CString::new();
                    one.push(cur.syms[i], cur.params_of(i), budget)?;
                    let left = i;
                    i += 1;
                    self.decompose(&one, cur, &partners, left, i, &mut next, budget)?;
                    budget.release_memory(one.bytes());
                }
            }
        }
        Ok(next)
    }

    /// Appends `succ` to `next`, each module decomposed (context from `cur`
    /// around `left..right`).
    #[allow(clippy::too_many_arguments)]
    fn decompose(&mut self, succ: &CString, cur: &CString, partners: &[usize], left: usize, right: usize, next: &mut CString, budget: &mut Budget) -> Result<(), EvalError> {
        let g = &self.sys.decomposition;
        if g.productions.is_empty() {
            for k in 0..succ.len() {
                next.push(succ.syms[k], succ.params_of(k), budget)?;
            }
            budget.release_memory(succ.bytes());
            return Ok(());
        }
        let sys = self.sys;
        self.recursive(&sys.decomposition, succ, cur, partners, left, right, 0, next, budget)?;
        budget.release_memory(succ.bytes());
        Ok(())
    }

    /// `ApplyRecursiveProductions` over every module of `s`: a production of
    /// `g` rewrites it and its successor is treated the same one level
    /// deeper, up to `g.depth`; the context is that of `cur` around the
    /// original predecessor.
    #[allow(clippy::too_many_arguments)]
    fn recursive(&mut self, g: &'a Group, s: &CString, cur: &CString, partners: &[usize], left: usize, right: usize, depth: u32, out: &mut CString, budget: &mut Budget) -> Result<(), EvalError> {
        budget.check_depth(depth)?;
        let sp = s.partners();
        let mut k = 0;
        while k < s.len() {
            budget.charge_step()?;
            let found = if depth < g.depth { self.first_in(&g.productions, s, &sp, k, cur, partners, left, right, budget)? } else { None };
            match found {
                Some((p, mut locals)) => {
                    self.machine.run(&p.post, &mut locals, budget)?;
                    let succ = self.successor(p, &mut locals, budget)?;
                    k += p.pred.len();
                    self.recursive(g, &succ, cur, partners, left, right, depth + 1, out, budget)?;
                    budget.release_memory(succ.bytes());
                }
                None => {
                    out.push(s.syms[k], s.params_of(k), budget)?;
                    k += 1;
                }
            }
        }
        Ok(())
    }

    /// Applies the homomorphism to `s` (for the turtle only).
    pub fn homomorphism(&mut self, s: &CString, budget: &mut Budget) -> Result<CString, EvalError> {
        let sys = self.sys;
        if sys.homomorphism.productions.is_empty() {
            let mut c = CString::new();
            for k in 0..s.len() {
                c.push(s.syms[k], s.params_of(k), budget)?;
            }
            return Ok(c);
        }
        let saved = self.machine.ran;
        if let Some(seed) = sys.homomorphism.seed {
            self.machine.ran = Rand48::cpfg_srand(seed);
        }
        let partners = s.partners();
        let mut out = CString::new();
        for i in 0..s.len() {
            let mut one = CString::new();
            one.push(s.syms[i], s.params_of(i), budget)?;
            self.recursive(&sys.homomorphism, &one, s, &partners, i, i + 1, 0, &mut out, budget)?;
            budget.release_memory(one.bytes());
        }
        if sys.homomorphism.seed.is_some() {
            self.machine.ran = saved;
        }
        Ok(out)
    }

    fn successor(&mut self, p: &Production, locals: &mut [f64], budget: &mut Budget) -> Result<CString, EvalError> {
        let mut s = CString::new();
        for m in &p.succ {
            let mut v = Vec::with_capacity(m.args.len());
            for a in &m.args {
                v.push(finite(self.machine.eval(a, locals, budget)?, m.span)?);
            }
            s.push(m.sym, &v, budget)?;
        }
        Ok(s)
    }

    /// The first production of `prods` that applies at module `i` of `cur`.
    fn first(&mut self, prods: &'a [Production], cur: &CString, partners: &[usize], i: usize, budget: &mut Budget) -> Result<Option<(&'a Production, Vec<f64>)>, EvalError> {
        for p in prods {
            if let Some(locals) = self.try_match(p, cur, partners, i, cur, partners, i, budget)? {
                return Ok(Some((p, locals)));
            }
        }
        Ok(None)
    }

    /// As [`Deriver::first`] over a successor `s`, context from `cur`.
    #[allow(clippy::too_many_arguments)]
    fn first_in(&mut self, prods: &'a [Production], s: &CString, sp: &[usize], k: usize, cur: &CString, partners: &[usize], left: usize, right: usize, budget: &mut Budget) -> Result<Option<(&'a Production, Vec<f64>)>, EvalError> {
        for p in prods {
            let mut locals = vec![0.0; p.locals as usize];
            if !self.bind(&p.pred, s, k, &mut locals) {
                continue;
            }
            let _ = sp;
            if !p.right.is_empty() && !self.right(&p.right, cur, partners, right, &mut locals) {
                continue;
            }
            if !p.left.is_empty() && !self.left(&p.left, cur, partners, left, &mut locals) {
                continue;
            }
            if self.condition(p, &mut locals, budget)? {
                return Ok(Some((p, locals)));
            }
        }
        Ok(None)
    }

    /// Every production that applies at `i`, one drawn by weight (`SelectProd`).
    fn choose(&mut self, cur: &CString, partners: &[usize], i: usize, budget: &mut Budget) -> Result<Option<(&'a Production, Vec<f64>)>, EvalError> {
        let sys = self.sys;
        let mut cands = Vec::new();
        let mut total = 0.0f32;
        for p in &sys.productions {
            if let Some(mut locals) = self.try_match(p, cur, partners, i, cur, partners, i, budget)? {
                let w = match &p.prob {
                    Some(e) => self.machine.eval(e, &mut locals, budget)?,
                    None => 1.0,
                };
                // cpfg sums the weights in a float.
                total += w as f32;
                cands.push((p, locals, w as f32));
            }
        }
        if cands.is_empty() {
            return Ok(None);
        }
        let mut r = total * self.machine.choice.uniform() as f32;
        for (p, locals, w) in cands {
            r -= w;
            if r <= 0.0 {
                return Ok(Some((p, locals)));
            }
        }
        Ok(None)
    }

    #[allow(clippy::too_many_arguments)]
    fn try_match(&mut self, p: &Production, s: &CString, _sp: &[usize], i: usize, cur: &CString, partners: &[usize], ci: usize, budget: &mut Budget) -> Result<Option<Vec<f64>>, EvalError> {
        if p.pred[0].sym != s.syms[i] {
            return Ok(None);
        }
        let mut locals = vec![0.0; p.locals as usize];
        if !self.bind(&p.pred, s, i, &mut locals) {
            return Ok(None);
        }
        if !p.right.is_empty() && !self.right(&p.right, cur, partners, ci + p.pred.len(), &mut locals) {
            return Ok(None);
        }
        if !p.left.is_empty() && !self.left(&p.left, cur, partners, ci, &mut locals) {
            return Ok(None);
        }
        Ok(if self.condition(p, &mut locals, budget)? { Some(locals) } else { None })
    }

    fn condition(&mut self, p: &Production, locals: &mut [f64], budget: &mut Budget) -> Result<bool, EvalError> {
        self.machine.run(&p.pre, locals, budget)?;
        match &p.cond {
            Some(c) => Ok(self.machine.eval(c, locals, budget)? != 0.0),
            None => Ok(true),
        }
    }

    /// Binds module `at` of `s` to `pat` when symbol and parameter count agree.
    fn bind_one(pat: &Pattern, s: &CString, at: usize, locals: &mut [f64]) -> bool {
        let p = s.params_of(at);
        if pat.sym != s.syms[at] || pat.params.len() != p.len() {
            return false;
        }
        for (slot, v) in pat.params.iter().zip(p) {
            if let Some(x) = locals.get_mut(*slot as usize) {
                *x = *v;
            }
        }
        true
    }

    /// The strict predecessor: consecutive modules from `i`.
    fn bind(&self, pred: &[Pattern], s: &CString, i: usize, locals: &mut [f64]) -> bool {
        if i + pred.len() > s.len() {
            return false;
        }
        pred.iter().enumerate().all(|(k, pat)| Self::bind_one(pat, s, i + k, locals))
    }

    /// The right context from `j`: ignored symbols and whole branches are
    /// skipped; the context cannot leave the branch it starts in.
    fn right(&self, pats: &[Pattern], s: &CString, partners: &[usize], mut j: usize, locals: &mut [f64]) -> bool {
        let mut k = 0;
        while k < pats.len() {
            let Some(&c) = s.syms.get(j) else { return false };
            let want = pats[k].sym;
            if want == ']' {
                // Skip to the end of the current branch.
                let mut level = 0usize;
                while j < s.len() {
                    match s.syms[j] {
                        '[' => level += 1,
                        ']' if level == 0 => break,
                        ']' => level -= 1,
                        _ => {}
                    }
                    j += 1;
                }
                if j >= s.len() {
                    return false;
                }
                j += 1;
                k += 1;
                continue;
            }
            if c == want && (c == '[' || Self::bind_one(&pats[k], s, j, locals)) {
                j += 1;
                k += 1;
                continue;
            }
            if c == '[' {
                match partners[j] {
                    usize::MAX => return false,
                    p => j = p + 1,
                }
                continue;
            }
            if self.ctx.skipped(c) {
                j += 1;
                continue;
            }
            return false;
        }
        true
    }

    /// The left context ending just before `i`: ignored symbols are
    /// skipped, a branch before is passed over, and a `[` leads to the
    /// module its branch hangs from.
    fn left(&self, pats: &[Pattern], s: &CString, partners: &[usize], i: usize, locals: &mut [f64]) -> bool {
        let mut k = pats.len();
        let mut j = i;
        while k > 0 {
            if j == 0 {
                return false;
            }
            let c = s.syms[j - 1];
            if c == ']' {
                match partners[j - 1] {
                    usize::MAX => return false,
                    p => j = p,
                }
                continue;
            }
            if c == '[' || self.ctx.skipped(c) {
                j -= 1;
                continue;
            }
            if !Self::bind_one(&pats[k - 1], s, j - 1, locals) {
                return false;
            }
            k -= 1;
            j -= 1;
        }
        true
    }
}
