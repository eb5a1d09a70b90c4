//! Parallel rewriting: one derivation step rewrites every module of the
//! string at once with the first production that matches it (context,
//! arity and condition), choosing among a stochastic group with the seeded
//! stream of the module's position, and copies modules without a match.
//!
//! Each step runs in two passes: the first picks a production for every
//! module and counts the modules and parameters of the next string, so the
//! budget is charged *before* the next string is allocated; the second builds
//! it. For D0L systems (context-free, deterministic, no parameters) the
//! length of every level is predicted up front by counting symbols, and a
//! system that would exceed a limit is refused before any rewriting.

use crate::core::budget::{Budget, Limit, LimitExceeded, OnLimit};
use crate::core::rng::StreamKey;
use crate::model::EvalError;
use crate::expr::{Expr, ExprEnv};
use crate::lsystem::syntax::{LSystem, Module, Pattern, Production, SYM_POP, SYM_PUSH};
use crate::core::Span;

/// No bracket partner (an unbalanced bracket).
const NONE: u32 = u32::MAX;
/// Choice: copy the module unchanged.
const IDENTITY: u32 = u32::MAX;
/// Choice: drop the module (it lies in a branch cut by `%`).
const CUT: u32 = u32::MAX - 1;
/// Random-stream slot used for the stochastic choice of a production.
const CHOICE_SLOT: u32 = u32::MAX;
/// Random-stream site under which the axiom's `rand()` calls draw.
const AXIOM_SITE: u32 = u32::MAX;

/// A string of modules: symbols with their real parameters, stored flat.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ModuleString {
    /// Symbol of each module.
    pub syms: Vec<u32>,
    /// Start of each module's parameters in `params`; one more entry than `syms`.
    pub starts: Vec<u32>,
    /// All parameters, module after module.
    pub params: Vec<f64>,
}

/// Accounted bytes of a string with `modules` modules and `params` parameters.
pub(crate) fn string_bytes(modules: u64, params: u64) -> u64 {
    modules.saturating_mul(8).saturating_add(4).saturating_add(params.saturating_mul(8))
}

impl ModuleString {
    fn with_capacity(modules: usize, params: usize) -> ModuleString {
        let mut starts = Vec::with_capacity(modules + 1);
        starts.push(0);
        ModuleString { syms: Vec::with_capacity(modules), starts, params: Vec::with_capacity(params) }
    }

    /// Number of modules.
    pub fn len(&self) -> usize {
        self.syms.len()
    }

    /// True when there are no modules.
    pub fn is_empty(&self) -> bool {
        self.syms.is_empty()
    }

    /// The parameters of module `i`.
    pub(crate) fn params_of(&self, i: usize) -> &[f64] {
        let (a, b) = (self.starts[i] as usize, self.starts[i + 1] as usize);
        &self.params[a..b]
    }

    /// Bytes accounted for this string.
    pub fn bytes(&self) -> u64 {
        string_bytes(self.syms.len() as u64, self.params.len() as u64)
    }

    fn push(&mut self, sym: u32, params: &[f64]) {
        self.syms.push(sym);
        self.params.extend_from_slice(params);
        // Fits: the caller checked the parameter count against u32 before building.
        self.starts.push(self.params.len() as u32);
    }

    /// The string as text: modules with parameters written `A(1,2.5)`, no spaces.
    pub fn to_text(&self, sys: &LSystem) -> String {
        let mut out = String::new();
        for i in 0..self.len() {
            out.push_str(sys.symbols.get(self.syms[i] as usize).map_or("?", String::as_str));
            let p = self.params_of(i);
            if !p.is_empty() {
                out.push('(');
                for (k, v) in p.iter().enumerate() {
                    if k > 0 {
                        out.push(',');
                    }
                    out.push_str(&format!("{v}"));
                }
                out.push(')');
            }
        }
        out
    }
}

/// The result of a derivation.
#[derive(Debug, Clone, PartialEq)]
pub struct Derivation {
    /// The final string.
    pub string: ModuleString,
    /// Derivation steps completed (the termination table counts as one).
    pub steps: u32,
    /// Set when a limit stopped the derivation early (only with `OnLimit::Truncate`).
    pub truncated: Option<LimitExceeded>,
}

struct Env<'a> {
    params: &'a [f64],
    key: StreamKey,
}

impl ExprEnv for Env<'_> {
    fn param(&self, index: u32) -> f64 {
        self.params.get(index as usize).copied().unwrap_or(f64::NAN)
    }
    fn rand(&mut self, site: u32) -> f64 {
        self.key.uniform(site)
    }
}

fn finite(v: f64, span: Span, what: &str) -> Result<f64, EvalError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(EvalError::NonFinite { span, what: what.to_string(), value: format!("{v}") })
    }
}

fn eval(e: &Expr, params: &[f64], key: StreamKey, span: Span, what: &str) -> Result<f64, EvalError> {
    finite(e.eval(&mut Env { params, key }), span, what)
}

/// Evaluates the axiom into the starting string.
pub fn axiom(sys: &LSystem, seed: u64, budget: &mut Budget) -> Result<ModuleString, EvalError> {
    let nparams: usize = sys.axiom.iter().map(|m| m.args.len()).sum();
    budget.reserve_memory(string_bytes(sys.axiom.len() as u64, nparams as u64))?;
    let mut s = ModuleString::with_capacity(sys.axiom.len(), nparams);
    let root = StreamKey::root(seed);
    let mut vals = Vec::new();
    for (i, m) in sys.axiom.iter().enumerate() {
        let key = root.child(AXIOM_SITE, i as u64);
        vals.clear();
        for a in &m.args {
            vals.push(eval(a, &[], key, m.span, "axiom argument")?);
        }
        s.push(m.symbol, &vals);
    }
    Ok(s)
}

/// Derives `sys` from its axiom for its `iterations`, then applies the termination table.
pub fn derive(sys: &LSystem, seed: u64, on_limit: OnLimit, budget: &mut Budget) -> Result<Derivation, EvalError> {
    derive_n(sys, seed, sys.iterations, on_limit, budget)
}

/// Like [`derive`] with an explicit number of iterations.
pub fn derive_n(sys: &LSystem, seed: u64, iterations: u32, on_limit: OnLimit, budget: &mut Budget) -> Result<Derivation, EvalError> {
    if on_limit == OnLimit::Error {
        predict(sys, iterations, budget)?;
    }
    let mut cur = axiom(sys, seed, budget)?;
    let rewriter = Rewriter::new(sys, &sys.productions);
    let terminator = Rewriter::new(sys, &sys.terminate);
    let root = StreamKey::root(seed);
    let total = iterations + u32::from(!sys.terminate.is_empty());
    let queries = super::turtle::has_queries(sys);
    for n in 0..=total {
        // Environment queries see the turtle after every step (Calgary instancing thesis §3.6).
        let step = if queries { super::turtle::fill_queries(sys, &mut cur, budget) } else { Ok(()) };
        let step = match step {
            Ok(()) if n == total => break,
            Ok(()) => {
                let rw = if n < iterations { &rewriter } else { &terminator };
                rw.step(&cur, root.child(n, 0), budget)
            }
            Err(e) => Err(e),
        };
        match step {
            Ok(next) => {
                budget.release_memory(cur.bytes());
                cur = next;
            }
            Err(EvalError::Limit(l)) if on_limit == OnLimit::Truncate => {
                return Ok(Derivation { string: cur, steps: n, truncated: Some(l) });
            }
            Err(e) => return Err(e),
        }
    }
    Ok(Derivation { string: cur, steps: total, truncated: None })
}

/// For D0L systems: refuses, before any rewriting, a derivation whose string
/// lengths (counted per symbol, level by level) would exceed the step or memory limit.
fn predict(sys: &LSystem, iterations: u32, budget: &Budget) -> Result<(), LimitExceeded> {
    if !sys.is_d0l() || !sys.terminate.is_empty() {
        return Ok(());
    }
    let n = sys.symbols.len();
    let mut succ: Vec<Option<Vec<u32>>> = vec![None; n];
    for p in &sys.productions {
        succ[p.pred.symbol as usize] = Some(p.successor.iter().map(|m| m.symbol).collect());
    }
    let mut counts = vec![0u64; n];
    for m in &sys.axiom {
        counts[m.symbol as usize] = counts[m.symbol as usize].saturating_add(1);
    }
    let mut steps = budget.steps();
    for _ in 0..iterations {
        let len: u64 = counts.iter().fold(0u64, |a, &c| a.saturating_add(c));
        steps = steps.saturating_add(len);
        budget.check_total(Limit::Steps, steps)?;
        let mut next = vec![0u64; n];
        for (s, &c) in counts.iter().enumerate() {
            if c == 0 {
                continue;
            }
            match &succ[s] {
                None => next[s] = next[s].saturating_add(c),
                Some(v) => {
                    for &t in v {
                        next[t as usize] = next[t as usize].saturating_add(c);
                    }
                }
            }
        }
        counts = next;
        let len: u64 = counts.iter().fold(0u64, |a, &c| a.saturating_add(c));
        budget.check_memory(string_bytes(len, 0))?;
    }
    Ok(())
}

/// One table of productions, indexed for rewriting.
pub(crate) struct Rewriter<'a> {
    sys: &'a LSystem,
    prods: &'a [Production],
    /// Production indices per predecessor symbol, in source order.
    by_symbol: Vec<Vec<usize>>,
    /// Members of each stochastic group, in source order.
    groups: Vec<Vec<usize>>,
    ignore: Vec<bool>,
    needs_brackets: bool,
    cut: Option<u32>,
}

impl<'a> Rewriter<'a> {
    /// Indexes `prods` of `sys`.
    pub fn new(sys: &'a LSystem, prods: &'a [Production]) -> Rewriter<'a> {
        let n = sys.symbols.len();
        let mut by_symbol = vec![Vec::new(); n];
        let mut groups: Vec<Vec<usize>> = Vec::new();
        for (i, p) in prods.iter().enumerate() {
            if let Some(v) = by_symbol.get_mut(p.pred.symbol as usize) {
                v.push(i);
            }
            let g = p.group as usize;
            if groups.len() <= g {
                groups.resize(g + 1, Vec::new());
            }
            groups[g].push(i);
        }
        let mut ignore = vec![false; n];
        for &s in &sys.ignore {
            if let Some(slot) = ignore.get_mut(s as usize) {
                *slot = true;
            }
        }
        let cut = sys.symbol("%");
        let needs_brackets = cut.is_some() || prods.iter().any(|p| !p.left.is_empty() || !p.right.is_empty());
        Rewriter { sys, prods, by_symbol, groups, ignore, needs_brackets, cut }
    }

    fn arity_ok(s: &ModuleString, i: usize, p: &Pattern) -> bool {
        s.syms[i] == p.symbol && (s.starts[i + 1] - s.starts[i]) == p.arity
    }

    /// Matches the left context ending before `i`; pushes its parameters to `env` (in source order).
    fn left(&self, s: &ModuleString, br: &[u32], i: usize, pats: &[Pattern], env: &mut Vec<f64>) -> bool {
        let mut found: Vec<usize> = Vec::with_capacity(pats.len());
        let mut j = i;
        for pat in pats.iter().rev() {
            loop {
                if j == 0 {
                    return false;
                }
                j -= 1;
                let sym = s.syms[j];
                if sym == SYM_POP {
                    // Skip the whole branch that ends here.
                    match br.get(j) {
                        Some(&m) if m != NONE => j = m as usize,
                        _ => return false,
                    }
                    continue;
                }
                let ignored = self.ignore.get(sym as usize).copied().unwrap_or(false);
                if sym == SYM_PUSH || (ignored && sym != pat.symbol) {
                    continue;
                }
                if Self::arity_ok(s, j, pat) {
                    found.push(j);
                    break;
                }
                return false;
            }
        }
        for &pos in found.iter().rev() {
            env.extend_from_slice(s.params_of(pos));
        }
        true
    }

    /// Matches the right context starting after `i`; pushes its parameters to `env`.
    fn right(&self, s: &ModuleString, br: &[u32], i: usize, pats: &[Pattern], env: &mut Vec<f64>) -> bool {
        let mut j = i + 1;
        for pat in pats {
            loop {
                if j >= s.len() {
                    return false;
                }
                let sym = s.syms[j];
                if Self::arity_ok(s, j, pat) {
                    env.extend_from_slice(s.params_of(j));
                    j += 1;
                    break;
                }
                if pat.symbol == SYM_POP {
                    // `]` in a context: skip to the end of the current branch.
                    if sym == SYM_PUSH {
                        match br.get(j) {
                            Some(&m) if m != NONE => j = m as usize + 1,
                            _ => return false,
                        }
                    } else {
                        j += 1;
                    }
                    continue;
                }
                if sym == SYM_PUSH {
                    match br.get(j) {
                        Some(&m) if m != NONE => j = m as usize + 1,
                        _ => return false,
                    }
                    continue;
                }
                if sym == SYM_POP {
                    return false;
                }
                if self.ignore.get(sym as usize).copied().unwrap_or(false) {
                    j += 1;
                    continue;
                }
                return false;
            }
        }
        true
    }

    /// Binds production `p` at module `i`: contexts and arity; parameters go to `env`.
    fn bind(&self, s: &ModuleString, br: &[u32], i: usize, p: &Production, env: &mut Vec<f64>) -> bool {
        env.clear();
        if !Self::arity_ok(s, i, &p.pred) {
            return false;
        }
        if !p.left.is_empty() && !self.left(s, br, i, &p.left, env) {
            return false;
        }
        env.extend_from_slice(s.params_of(i));
        p.right.is_empty() || self.right(s, br, i, &p.right, env)
    }

    /// Picks the production for module `i`, or [`IDENTITY`].
    fn select(&self, s: &ModuleString, br: &[u32], i: usize, key: StreamKey, env: &mut Vec<f64>) -> Result<u32, EvalError> {
        let Some(cands) = self.by_symbol.get(s.syms[i] as usize) else { return Ok(IDENTITY) };
        for &pi in cands {
            let p = &self.prods[pi];
            if !self.bind(s, br, i, p, env) {
                continue;
            }
            if let Some(c) = &p.condition {
                if eval(c, env, key, p.span, "condition")? == 0.0 {
                    continue;
                }
            }
            let Some(_) = &p.probability else { return Ok(pi as u32) };
            // A stochastic group: members share predecessor, contexts and condition.
            let members = &self.groups[p.group as usize];
            let mut total = 0.0;
            let mut weights = Vec::with_capacity(members.len());
            for &q in members {
                let qp = &self.prods[q];
                let w = match (&qp.probability, qp.pred.arity == p.pred.arity) {
                    (Some(e), true) => eval(e, env, key, qp.span, "probability")?.max(0.0),
                    _ => 0.0,
                };
                total += w;
                weights.push(w);
            }
            if total <= 0.0 {
                continue;
            }
            let mut r = key.uniform(CHOICE_SLOT) * total;
            let mut chosen = pi;
            for (&q, &w) in members.iter().zip(&weights) {
                if w > 0.0 {
                    chosen = q;
                    if r < w {
                        break;
                    }
                    r -= w;
                }
            }
            return Ok(chosen as u32);
        }
        Ok(IDENTITY)
    }

    /// Bracket partners: for `[` its `]` and for `]` its `[`, else [`NONE`].
    fn brackets(s: &ModuleString) -> Vec<u32> {
        let mut br = vec![NONE; s.len()];
        let mut stack: Vec<u32> = Vec::new();
        for (i, &sym) in s.syms.iter().enumerate() {
            if sym == SYM_PUSH {
                stack.push(i as u32);
            } else if sym == SYM_POP {
                if let Some(open) = stack.pop() {
                    br[i] = open;
                    br[open as usize] = i as u32;
                }
            }
        }
        br
    }

    /// Rewrites `cur` once, charging one step per module and reserving the next string's memory first.
    pub fn step(&self, cur: &ModuleString, key: StreamKey, budget: &mut Budget) -> Result<ModuleString, EvalError> {
        let n = cur.len();
        let scratch = (n as u64).saturating_mul(if self.needs_brackets { 8 } else { 4 });
        budget.reserve_memory(scratch)?;
        let result = self.step_inner(cur, key, budget);
        budget.release_memory(scratch);
        result
    }

    fn step_inner(&self, cur: &ModuleString, key: StreamKey, budget: &mut Budget) -> Result<ModuleString, EvalError> {
        let n = cur.len();
        let br = if self.needs_brackets { Self::brackets(cur) } else { Vec::new() };
        let mut choices = vec![IDENTITY; n];
        let mut env: Vec<f64> = Vec::new();
        let (mut out_len, mut out_params) = (0u64, 0u64);
        let mut i = 0;
        while i < n {
            budget.charge_step()?;
            if Some(cur.syms[i]) == self.cut {
                // Remove `%` and the rest of its branch; keep the closing `]`.
                let mut j = i;
                while j < n && cur.syms[j] != SYM_POP {
                    if cur.syms[j] == SYM_PUSH && br[j] != NONE {
                        for c in &mut choices[j..=br[j] as usize] {
                            *c = CUT;
                        }
                        j = br[j] as usize + 1;
                    } else {
                        choices[j] = CUT;
                        j += 1;
                    }
                }
                i = j;
                continue;
            }
            let c = self.select(cur, &br, i, key.child(0, i as u64), &mut env)?;
            choices[i] = c;
            if c == IDENTITY {
                out_len += 1;
                out_params += u64::from(cur.starts[i + 1] - cur.starts[i]);
            } else {
                let succ = &self.prods[c as usize].successor;
                out_len += succ.len() as u64;
                out_params += succ.iter().map(|m| m.args.len() as u64).sum::<u64>();
            }
            i += 1;
        }
        if out_params > u64::from(u32::MAX - 1) || out_len > u64::from(u32::MAX - 1) {
            // Indices are u32: a string this long is refused as the memory it would take.
            return Err(budget.memory_refused(string_bytes(out_len, out_params)).into());
        }
        let out_bytes = string_bytes(out_len, out_params);
        budget.reserve_memory(out_bytes)?;
        let mut next = ModuleString::with_capacity(out_len as usize, out_params as usize);
        let mut vals: Vec<f64> = Vec::new();
        for i in 0..n {
            // Writing a string of millions of modules takes as long as
            // choosing them did: look at the deadline here too (it overran
            // a 1.5 s deadline by 0.3 s when only the first pass looked).
            if i % 4096 == 4095 {
                if let Err(l) = budget.check_deadline() {
                    budget.release_memory(out_bytes);
                    return Err(l.into());
                }
            }
            match choices[i] {
                CUT => {}
                IDENTITY => next.push(cur.syms[i], cur.params_of(i)),
                c => {
                    let p = &self.prods[c as usize];
                    self.bind(cur, &br, i, p, &mut env);
                    let k = key.child(0, i as u64);
                    for m in &p.successor {
                        self.emit(m, &env, k, &mut vals)?;
                        next.push(m.symbol, &vals);
                    }
                }
            }
        }
        Ok(next)
    }

    /// Context-free choice for one module `sym(params)` on its own: the
    /// production applied (its formal parameters bound in `env`), or `None`
    /// when the module is copied. Only meaningful for context-free tables.
    pub(crate) fn choose(&self, sym: u32, params: &[f64], key: StreamKey, env: &mut Vec<f64>) -> Result<Option<&'a Production>, EvalError> {
        let mut one = ModuleString::with_capacity(1, params.len());
        one.push(sym, params);
        let c = self.select(&one, &[], 0, key, env)?;
        let Some(p) = self.prods.get(c as usize) else { return Ok(None) };
        self.bind(&one, &[], 0, p, env);
        Ok(Some(p))
    }

    /// True when the table has no productions.
    pub(crate) fn is_empty(&self) -> bool {
        self.prods.is_empty()
    }

    /// Evaluates the arguments of successor module `m` under `env` into `vals`.
    pub(crate) fn emit(&self, m: &Module, env: &[f64], key: StreamKey, vals: &mut Vec<f64>) -> Result<(), EvalError> {
        vals.clear();
        for a in &m.args {
            let what = self.sys.symbols.get(m.symbol as usize).map_or("module", String::as_str);
            vals.push(eval(a, env, key, m.span, &format!("argument of {what}"))?);
        }
        Ok(())
    }
}
