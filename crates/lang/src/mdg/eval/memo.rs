//! Memoised MDG derivation: the object [`Hierarchy`] of a program that
//! [`super::share::shareable`] accepts, built as the L-system DAG is (Calgary
//! instancing thesis §2.2): each distinct (rule, depth, inherited colour) is expanded once into
//! an object whose entries are its rule body's calls, each a primitive leaf
//! or another object, placed by the call's own adjustment. The binary bush
//! `rule B { BOX {} B { y 1 rz 25 s 0.8 } B { y 1 rz -25 s 0.8 } }` with
//! maxdepth 17 becomes 18 objects of 3 entries (one per depth) instead of
//! 262,143 boxes.
//!
//! An entry's frame is the call's adjustment, which the flat derivation
//! composes onto the caller's frame with [`Frame::then`]; the hierarchy's
//! walk composes the very same way, so its leaves are the flat derivation's
//! instances bit for bit and in the same (depth-first, textual) order. Leaf
//! colours are the bytes the mesher would write.
//!
//! No Rust recursion follows the grammar: pending objects sit on an explicit
//! stack, children finish before their parents (so objects are stored
//! children first, as [`Hierarchy`] requires), and depth only grows along a
//! chain, so there are no cycles; `maxdepth`/`stacksize` end a chain, else the
//! depth limit does. Budgets: a step per rule expansion and per entry, memory
//! for every entry, pending call and memo slot as it is made.

use super::machine::Evaluator;
use super::select::threshold;
use crate::core::budget::Budget;
use crate::core::frame::Frame;
use crate::core::PrimitiveKind;
use crate::ir::{GroupId, Item, Selector, Target};
use crate::model::hierarchy::{Entry, Hierarchy, LeafShape, Object, Target as HTarget, ENTRY_BYTES};
use crate::model::instancing::rgba8;
use crate::model::scene::Instance;
use crate::model::EvalError;
use std::collections::HashMap;

/// What a subtree's expansion depends on: its rule, its depth and the exact
/// bits of the colour it inherits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct Key {
    group: GroupId,
    depth: u32,
    colour: [u64; 4],
}

/// A call of an object being expanded, before its callee is known.
#[derive(Debug, Clone, Copy)]
struct Call {
    /// A leaf shape, or the callee's key.
    target: Pending,
    /// The call's adjustment.
    frame: Frame,
    /// The leaf's colour (0 for a rule call).
    colour: [u8; 4],
}

#[derive(Debug, Clone, Copy)]
enum Pending {
    Shape(u32),
    Rule(Key),
}

/// An object whose callees are still being expanded.
struct Open {
    key: Key,
    calls: Vec<Call>,
    /// Calls before this one have their callee finished.
    next: usize,
}

/// Bytes accounted per pending call and per memo slot.
const CALL_BYTES: u64 = std::mem::size_of::<Call>() as u64;
const MEMO_BYTES: u64 = (std::mem::size_of::<Key>() + std::mem::size_of::<Option<u32>>()) as u64 * 2;

/// The builder's state.
struct Builder<'e, 'p, 'b> {
    ev: &'e Evaluator<'p>,
    budget: &'b mut Budget,
    h: Hierarchy,
    /// Leaf shape of each primitive kind used so far.
    shape_of: [Option<u32>; PrimitiveKind::ALL.len()],
    /// Object of each finished key (`None`: it draws nothing).
    memo: HashMap<Key, Option<u32>>,
    /// Memory charged for pending calls, returned when they are finished.
    pending_bytes: u64,
}

/// Builds the hierarchy of `ev`'s program (which must be
/// [`shareable`](super::share::shareable)) from its start rule, at depth 0
/// in `colour`.
pub(super) fn build(ev: &Evaluator<'_>, colour: [f64; 4], budget: &mut Budget) -> Result<Hierarchy, EvalError> {
    let Target::Group(start) = ev.program.start else { return Ok(Hierarchy::default()) };
    let mut b = Builder { ev, budget, h: Hierarchy::default(), shape_of: [None; PrimitiveKind::ALL.len()], memo: HashMap::new(), pending_bytes: 0 };
    let result = b.run(Key { group: start, depth: 0, colour: colour.map(f64::to_bits) });
    b.budget.release_memory(b.pending_bytes);
    result.map(|()| b.h)
}

impl Builder<'_, '_, '_> {
    fn run(&mut self, root: Key) -> Result<(), EvalError> {
        let mut stack: Vec<Open> = Vec::new();
        match self.open(root)? {
            Some(o) => stack.push(o),
            None => return Ok(()),
        }
        while let Some(top) = stack.last_mut() {
            // Skip the calls whose callee is finished.
            let mut unfinished = None;
            while let Some(call) = top.calls.get(top.next) {
                if let Pending::Rule(k) = call.target {
                    if !self.memo.contains_key(&k) {
                        unfinished = Some(k);
                        break;
                    }
                }
                top.next += 1;
            }
            if let Some(k) = unfinished {
                match self.open(k)? {
                    Some(o) => stack.push(o),
                    None => self.finish(k, None)?,
                }
                continue;
            }
            if let Some(done) = stack.pop() {
                self.close(done)?;
            }
        }
        Ok(())
    }

    /// Starts expanding the rule of `key` (as the machine's `expand` would):
    /// its calls, or `None` when it draws nothing.
    fn open(&mut self, key: Key) -> Result<Option<Open>, EvalError> {
        let dirs = &self.ev.program.directives;
        if dirs.maxdepth.is_some_and(|m| key.depth > m) || dirs.stacksize.is_some_and(|m| key.depth > m) {
            return Ok(None);
        }
        self.budget.check_depth(key.depth)?;
        self.budget.charge_step()?;
        let Some(group) = self.ev.program.groups.get(key.group as usize) else { return Ok(None) };
        let rule = match group.selector {
            Selector::Depth => threshold(&group.rules, f64::from(key.depth)),
            _ => group.rules.first(),
        };
        let Some(rule) = rule else { return Ok(None) };
        let colour = key.colour.map(f64::from_bits);
        let mut calls = Vec::new();
        let mut pending: Vec<&[Item]> = vec![&rule.body];
        while let Some(items) = pending.pop() {
            // Depth first in textual order: a block runs before the items after it.
            for (i, item) in items.iter().enumerate() {
                match item {
                    Item::Block(b) => {
                        if let Some(rest) = items.get(i + 1..).filter(|r| !r.is_empty()) {
                            pending.push(rest);
                        }
                        pending.push(b);
                        break;
                    }
                    Item::Call(c) => {
                        let Some(Some(d)) = self.ev.setup.fixed.get(c.site as usize) else { continue };
                        self.budget.charge_step()?;
                        self.budget.reserve_memory(CALL_BYTES)?;
                        self.pending_bytes += CALL_BYTES;
                        let mut here = colour;
                        for (a, b) in here.iter_mut().zip(d.colour()) {
                            *a += b;
                        }
                        let call = match c.target {
                            Target::Primitive(kind) => {
                                here[3] += 1.0;
                                let placed = Instance::new(kind, &Frame::IDENTITY, here);
                                Call { target: Pending::Shape(self.shape(kind)), frame: *d.frame(), colour: rgba8(placed.colour) }
                            }
                            Target::Group(g) => {
                                let k = Key { group: g, depth: key.depth + 1, colour: here.map(f64::to_bits) };
                                Call { target: Pending::Rule(k), frame: *d.frame(), colour: [0; 4] }
                            }
                            // `shareable` admits no other target.
                            _ => continue,
                        };
                        calls.push(call);
                    }
                    // `shareable` admits no iterator.
                    Item::Iterate(_) => {}
                }
            }
        }
        Ok(Some(Open { key, calls, next: 0 }))
    }

    /// The leaf shape of primitive `kind`, added on first use.
    fn shape(&mut self, kind: PrimitiveKind) -> u32 {
        let slot = &mut self.shape_of[kind as usize];
        *slot.get_or_insert_with(|| {
            // Fits: at most nine kinds.
            let i = self.h.shapes.len() as u32;
            self.h.shapes.push(LeafShape::primitive(kind));
            i
        })
    }

    /// Records the object (or nothing) a key expands to.
    fn finish(&mut self, key: Key, object: Option<u32>) -> Result<(), EvalError> {
        self.budget.reserve_memory(MEMO_BYTES)?;
        self.memo.insert(key, object);
        Ok(())
    }

    /// Turns a finished expansion into an object (its callees are all in the memo).
    fn close(&mut self, open: Open) -> Result<(), EvalError> {
        let mut entries = Vec::with_capacity(open.calls.len());
        let mut leaves = 0u64;
        for call in &open.calls {
            let target = match call.target {
                Pending::Shape(s) => {
                    leaves = leaves.saturating_add(1);
                    HTarget::Shape(s)
                }
                Pending::Rule(k) => match self.memo.get(&k).copied().flatten() {
                    Some(o) => {
                        leaves = leaves.saturating_add(self.h.objects.get(o as usize).map_or(0, |x| x.leaves));
                        HTarget::Object(o)
                    }
                    None => continue,
                },
            };
            let f = call.frame;
            entries.push(Entry { target, translation: f.translation, rotation: f.rotation, scale: f.scale, colour: call.colour });
        }
        let bytes = CALL_BYTES * open.calls.len() as u64;
        self.budget.release_memory(bytes);
        self.pending_bytes -= bytes;
        if entries.is_empty() {
            return self.finish(open.key, None);
        }
        self.budget.reserve_memory(ENTRY_BYTES.saturating_mul(entries.len() as u64))?;
        // Fits: an object per memo slot, each charged to the memory budget first.
        let index = self.h.objects.len() as u32;
        self.h.objects.push(Object { entries, leaves });
        self.finish(open.key, Some(index))
    }
}
