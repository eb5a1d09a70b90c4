//! A cpfg string: one-character symbols with float parameters, stored
//! flat, and its bracket structure for context matching.

use crate::core::budget::Budget;
use crate::core::LimitExceeded;

/// Symbols with their parameters. Parameters are kept at `f32` precision,
/// as cpfg stores them in the string (`cpfg/generate.c`, `AppendParameter`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CString {
    /// The symbol of each module.
    pub syms: Vec<char>,
    /// Start of each module's parameters in `params`; one more entry than `syms`.
    pub starts: Vec<u32>,
    /// All parameters, module after module.
    pub params: Vec<f64>,
}

/// Bytes accounted per module and per parameter.
pub(crate) const MODULE_BYTES: u64 = 8;
/// Bytes accounted per parameter.
pub(crate) const PARAM_BYTES: u64 = 8;

impl CString {
    /// An empty string.
    pub fn new() -> CString {
        CString { syms: Vec::new(), starts: vec![0], params: Vec::new() }
    }

    /// Number of modules.
    pub fn len(&self) -> usize {
        self.syms.len()
    }

    /// True when empty.
    pub fn is_empty(&self) -> bool {
        self.syms.is_empty()
    }

    /// Parameters of module `i`.
    pub(crate) fn params_of(&self, i: usize) -> &[f64] {
        &self.params[self.starts[i] as usize..self.starts[i + 1] as usize]
    }

    /// Appends a module, charging its bytes to `budget`'s memory.
    pub fn push(&mut self, sym: char, params: &[f64], budget: &mut Budget) -> Result<(), LimitExceeded> {
        budget.reserve_memory(MODULE_BYTES + PARAM_BYTES * params.len() as u64)?;
        self.syms.push(sym);
        self.params.extend(params.iter().map(|&v| f64::from(v as f32)));
        self.starts.push(self.params.len() as u32);
        Ok(())
    }

    /// The bytes this string holds in the budget.
    pub fn bytes(&self) -> u64 {
        MODULE_BYTES * self.syms.len() as u64 + PARAM_BYTES * self.params.len() as u64
    }

    /// The string as cpfg writes it: `F(1,2.5)+F`, no blanks.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        for i in 0..self.len() {
            out.push(self.syms[i]);
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

    /// For every `[` the index of its `]` and back; `usize::MAX` when unmatched.
    pub(crate) fn partners(&self) -> Vec<usize> {
        let mut p = vec![usize::MAX; self.len()];
        let mut stack = Vec::new();
        for (i, &s) in self.syms.iter().enumerate() {
            match s {
                '[' => stack.push(i),
                ']' => {
                    if let Some(o) = stack.pop() {
                        p[o] = i;
                        p[i] = o;
                    }
                }
                _ => {}
            }
        }
        p
    }
}
