//! What an evaluation sets up from the program and its bound parameters
//! alone, kept between evaluations of one parsed program.
//!
//! Making an [`Evaluator`](super::machine::Evaluator) evaluates every
//! constant adjustment of the program (its "fixed deltas") and sums each
//! rule group's weights. Both depend on nothing but the program and the
//! parameter values bound to it, yet a fresh render of the library's `gem`
//! made them again each time: about 2 % of its instructions (issue 33). MDG
//! keeps one [`SetupMemo`] beside each parsed program (`mdg::PARSED`), and
//! an evaluation whose parameters are bit for bit the last one's reuses
//! that set-up. The same arithmetic ran once, so the numbers, and every
//! byte made from them, are the same.

use super::adjust::{collect_fixed, Delta};
use crate::ir::Program;
use crate::model::EvalError;
use std::sync::{Arc, Mutex};

/// A program's set-up for one set of bound parameters.
#[derive(Debug)]
pub(super) struct Setup {
    /// The bound parameter values it was made for, as bits (so that a NaN
    /// matches itself and -0 does not match 0).
    params: Vec<u64>,
    /// Deltas of call sites whose adjustments contain no `rand()`, by site.
    pub(super) fixed: Vec<Option<Delta>>,
    /// Cumulative weights per group, for weighted selection.
    pub(super) cumulative: Vec<Vec<f64>>,
}

/// The last [`Setup`] made for one program (empty until the first).
#[derive(Debug, Default)]
pub struct SetupMemo(Mutex<Option<Arc<Setup>>>);

/// The set-up of `program` under `params`: `memo`'s when it was made for
/// the same values, else made now (and kept in `memo`, if any).
pub(super) fn setup(program: &Program, params: &[f64], memo: Option<&SetupMemo>) -> Result<Arc<Setup>, EvalError> {
    let same = |s: &Setup| s.params.len() == params.len() && s.params.iter().zip(params).all(|(a, b)| *a == b.to_bits());
    // A poisoned lock (a panic while holding it) only costs the memo.
    if let Some(kept) = memo.and_then(|m| m.0.lock().ok().and_then(|s| s.clone())).filter(|s| same(s)) {
        return Ok(kept);
    }
    let mut fixed = vec![None; program.site_count as usize];
    for g in &program.groups {
        for r in &g.rules {
            collect_fixed(&r.body, params, &mut fixed)?;
        }
    }
    let cumulative = program
        .groups
        .iter()
        .map(|g| {
            let mut acc = 0.0;
            g.rules.iter().map(|r| {
                acc += r.weight.max(0.0);
                acc
            }).collect()
        })
        .collect();
    let made = Arc::new(Setup { params: params.iter().map(|p| p.to_bits()).collect(), fixed, cumulative });
    if let Some(slot) = memo.and_then(|m| m.0.lock().ok()).as_deref_mut() {
        *slot = Some(made.clone());
    }
    Ok(made)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The memo hands back its set-up for the same parameter values (bit
    /// for bit), and makes a new one, equal to one made without a memo,
    /// for other values.
    #[test]
    fn the_set_up_is_kept_for_the_same_values_only() {
        let program = crate::mdg::parse(b"@param float w 1 0 10\nstartshape A\nrule A { box { x w s 2 } A { x 1 rz 10 } }\nrule A 0.5 { sphere { y w } }\n").expect("parses");
        let memo = SetupMemo::default();
        let first = setup(&program, &[1.0], Some(&memo)).expect("set up");
        assert!(Arc::ptr_eq(&first, &setup(&program, &[1.0], Some(&memo)).expect("again")), "the same values reuse it");
        let other = setup(&program, &[2.0], Some(&memo)).expect("other values");
        assert!(!Arc::ptr_eq(&first, &other));
        let plain = setup(&program, &[2.0], None).expect("no memo");
        assert_eq!(other.fixed, plain.fixed, "a kept set-up is the one made afresh");
        assert_eq!(other.cumulative, plain.cumulative);
        assert_ne!(first.fixed, other.fixed, "the parameter moves a fixed delta");
        assert!(!Arc::ptr_eq(&setup(&program, &[-0.0], Some(&memo)).expect("-0"), &setup(&program, &[0.0], Some(&memo)).expect("0")), "-0 and 0 are told apart");
        assert_eq!(first.cumulative.iter().map(Vec::len).sum::<usize>(), 2);
    }
}
