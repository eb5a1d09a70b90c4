//! Rule selection: which alternative of a rule group a call runs, by
//! weighted random choice (in the call's own stream, so order does not
//! matter), depth, scale, a selector function, or in sequence.

use super::adjust::{finite, Ctx, Env};
use super::machine::{Machine, SELECT_SLOT};
use crate::core::Span;
use crate::ir::{GroupId, Rule, RuleGroup, Selector};
use crate::model::EvalError;

/// The rule a threshold selector picks for `value`: the one with the
/// smallest weight that is at least `value` (none when no weight is).
pub(super) fn threshold(rules: &[Rule], value: f64) -> Option<&Rule> {
    rules.iter().filter(|r| r.weight >= value).min_by(|a, b| a.weight.total_cmp(&b.weight))
}

impl<'p, 'b> Machine<'p, 'b> {
    /// Picks the alternative of `group` that a call in `ctx` runs, if any.
    pub(super) fn select(&mut self, g: GroupId, group: &'p RuleGroup, ctx: &Ctx) -> Result<Option<&'p Rule>, EvalError> {
        let rules = &group.rules;
        let threshold = |value: f64| threshold(rules, value);
        Ok(match &group.selector {
            Selector::Random if rules.len() == 1 => rules.first(),
            Selector::Random => {
                let cum = &self.ev.setup.cumulative[g as usize];
                let total = cum.last().copied().unwrap_or(0.0);
                let target = ctx.key.uniform(SELECT_SLOT) * total;
                cum.iter().position(|&c| c > target).and_then(|i| rules.get(i))
            }
            Selector::Depth => threshold(f64::from(ctx.depth)),
            Selector::Scale => threshold(ctx.frame.scale),
            Selector::Function(f) => {
                let mut env = Env { params: self.ev.params, key: ctx.key, pos: ctx.frame.translation };
                let span = rules.first().map_or_else(Span::default, |r| r.span);
                threshold(finite(f, &mut env, span, "selector function")?)
            }
            Selector::Sequential => {
                // Each rule runs round(weight) times in order; the cycle repeats.
                let runs = |r: &Rule| r.weight.round().max(0.0) as u64;
                let cycle: u64 = rules.iter().map(runs).sum();
                if cycle == 0 {
                    return Ok(None);
                }
                let n = &mut self.sequence[g as usize];
                let mut at = *n % cycle;
                *n += 1;
                rules.iter().find(|r| {
                    let k = runs(r);
                    if at < k {
                        true
                    } else {
                        at -= k;
                        false
                    }
                })
            }
        })
    }
}
