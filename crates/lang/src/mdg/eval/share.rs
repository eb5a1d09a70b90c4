//! Whether an MDG derivation may be memoised as an object hierarchy (see
//! [`super::memo`]): a static, conservative check over every rule reachable
//! from the start rule.
//!
//! A subtree is shared under the key (rule, depth, inherited colour), so
//! everything it draws must follow from that key and the frame it is placed
//! in, and the frames of its leaves must compose exactly as the flat
//! derivation composes them (so expanding the hierarchy gives the flat
//! derivation's instances bit for bit). That rules out, anywhere reachable:
//! random selection between several alternatives, sequential and scale or
//! function selectors (a call counter, the absolute scale, the absolute
//! position), `rand()` or `x`/`y`/`z` in an adjustment, continuation (`\`,
//! which reads where the last terminal anywhere left off), iterators (each
//! copy's frame is the previous copy's frame times the step, which a
//! relative entry cannot reproduce to the last bit), lines and pens, free
//! vertices, isosurfaces and meshes, transform rules (convolution,
//! animation), a camera rule, `minsize` (it reads the absolute scale), and
//! mirrored or zero-scale adjustments (entries are unmirrored similarities).
//! Nothing of the rest reads the call path: the program's parameters are
//! bound once, and `maxdepth`, `stacksize` and depth selectors read the depth,
//! which is in the key.

use super::machine::Evaluator;
use crate::ir::{Item, RuleTransform, Selector, Target};

/// True when every rule reachable from `ev`'s start rule may be shared.
pub(super) fn shareable(ev: &Evaluator<'_>) -> bool {
    let program = ev.program;
    let dirs = &program.directives;
    if dirs.minsize.is_some() || dirs.camerarule.is_some() {
        return false;
    }
    let Target::Group(start) = program.start else { return false };
    let mut seen = vec![false; program.groups.len()];
    let mut pending = vec![start];
    while let Some(g) = pending.pop() {
        let Some(slot) = seen.get_mut(g as usize) else { return false };
        if std::mem::replace(slot, true) {
            continue;
        }
        let Some(group) = program.groups.get(g as usize) else { return false };
        let selector_ok = match group.selector {
            Selector::Random => group.rules.len() <= 1,
            Selector::Depth => true,
            Selector::Scale | Selector::Sequential | Selector::Function(_) => false,
        };
        if !selector_ok {
            return false;
        }
        for rule in &group.rules {
            if rule.transform != RuleTransform::None || !items_shareable(ev, &rule.body, &mut pending) {
                return false;
            }
        }
    }
    true
}

/// True when `items` use only shareable constructs; pushes the groups they call.
fn items_shareable(ev: &Evaluator<'_>, items: &[Item], groups: &mut Vec<u32>) -> bool {
    let mut pending: Vec<&[Item]> = vec![items];
    while let Some(items) = pending.pop() {
        for item in items {
            match item {
                Item::Block(b) => pending.push(b),
                Item::Iterate(_) => return false,
                Item::Call(c) => {
                    if c.continues {
                        return false;
                    }
                    match c.target {
                        Target::Group(g) => groups.push(g),
                        Target::Primitive(_) => {}
                        _ => return false,
                    }
                    // Deterministic (precomputed), unmirrored, not collapsing.
                    match ev.setup.fixed.get(c.site as usize) {
                        Some(Some(d)) if !d.frame().parity && d.frame().scale > 0.0 => {}
                        _ => return false,
                    }
                }
            }
        }
    }
    true
}
