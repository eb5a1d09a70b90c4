//! From a derivation DAG to an object-instancing [`Hierarchy`] (Calgary instancing thesis §4.2).
//!
//! Each DAG node is read by a turtle in leaf mode that starts at the origin:
//! its segments become leaf entries and its sub-nodes become entries placing
//! the sub-node's object at the turtle's pose, after which the turtle moves by
//! the sub-object's end state (its status function, memoised with it). An
//! object's geometry is thus expressed in its start frame and reused wherever
//! the subtree occurs.
//!
//! A subtree reads the turtle's width and colour at its start (segments
//! without an explicit width, and every segment's colour), so the object key
//! is (node, width, colour): the same subtree under another colour is another
//! object. Orientation is not part of the key because every turtle operation
//! that instancing allows is local (tropism is global and is refused by
//! [`super::dag::not_instanceable`]).

use super::dag::{Item, StringDag};
use super::turtle::{LeafTurtle, TurtleOptions};
use crate::core::budget::Budget;
use crate::model::hierarchy::{Entry, Hierarchy, LeafShape, Object, Target, ENTRY_BYTES};
use crate::model::EvalError;
use crate::lsystem::syntax::LSystem;
use glam::{DQuat, DVec3};
use std::collections::HashMap;

/// Bytes accounted per memoised object.
const MEMO_BYTES: u64 = 128;

/// The start-relative end state of a sub-object, and its object (`None` when it draws nothing).
#[derive(Debug, Clone, Copy)]
struct Built {
    object: Option<u32>,
    pos: DVec3,
    rot: DQuat,
    width: f64,
    colour: [f64; 4],
}

type ShapeKey = (u8, bool, [u32; 3], [u32; 3]);

struct Builder<'a, 'b> {
    sys: &'a LSystem,
    opts: &'a TurtleOptions,
    dag: &'a StringDag,
    out: Hierarchy,
    shapes: HashMap<ShapeKey, u32>,
    memo: HashMap<(u32, u64, [u64; 4]), Built>,
    budget: &'b mut Budget,
}

/// Builds the hierarchy of `dag`, whose non-root nodes must be
/// [balanced](StringDag::balanced). The root draws like the whole string
/// would (unbalanced brackets there are handled as the turtle does).
pub fn build(sys: &LSystem, dag: &StringDag, budget: &mut Budget) -> Result<Hierarchy, EvalError> {
    let opts = TurtleOptions { detail: 0, on_limit: crate::core::OnLimit::Error, line_point_bytes: 0, downstream_bytes: [0; 9] };
    let mut b = Builder { sys, opts: &opts, dag, out: Hierarchy::default(), shapes: HashMap::new(), memo: HashMap::new(), budget };
    let built = b.object(dag.root_index(), sys.width, super::turtle::DEFAULT_COLOUR, true)?;
    if built.object.is_none() || built.object != Some((b.out.objects.len() as u32).wrapping_sub(1)) {
        // The root must be last and exist: wrap whatever it aliased (or nothing).
        let entries = built
            .object
            .map(|o| vec![Entry { target: Target::Object(o), translation: DVec3::ZERO, rotation: DQuat::IDENTITY, scale: 1.0, colour: [0; 4] }])
            .unwrap_or_default();
        let leaves = built.object.map_or(0, |o| b.out.objects[o as usize].leaves);
        b.out.objects.push(Object { entries, leaves });
    }
    Ok(b.out)
}

impl Builder<'_, '_> {
    fn shape(&mut self, s: LeafShape) -> u32 {
        let key = (s.kind as u8, s.tube, s.scale.map(f32::to_bits), s.offset.map(f32::to_bits));
        let next = self.out.shapes.len() as u32;
        *self.shapes.entry(key).or_insert_with(|| {
            self.out.shapes.push(s);
            next
        })
    }

    fn object(&mut self, node: u32, width: f64, colour: [f64; 4], root: bool) -> Result<Built, EvalError> {
        let key = (node, width.to_bits(), colour.map(f64::to_bits));
        if !root {
            if let Some(b) = self.memo.get(&key) {
                return Ok(*b);
            }
        }
        let dag = self.dag;
        let Some(n) = dag.nodes.get(node as usize) else {
            return Ok(Built { object: None, pos: DVec3::ZERO, rot: DQuat::IDENTITY, width, colour });
        };
        let mut t = LeafTurtle::new(self.sys, self.opts, width, colour);
        let mut entries: Vec<Entry> = Vec::new();
        let mut leaves = 0u64;
        for item in &n.items {
            match *item {
                Item::Module { sym, start, len } => {
                    t.module(sym, dag.params_of(start, len), self.budget)?;
                    for leaf in t.take_leaves() {
                        self.budget.reserve_memory(ENTRY_BYTES)?;
                        let s = self.shape(leaf.shape);
                        entries.push(Entry { target: Target::Shape(s), translation: leaf.pos, rotation: leaf.rot, scale: 1.0, colour: leaf.colour });
                        leaves = leaves.saturating_add(1);
                    }
                }
                Item::Node(c) if c < node => {
                    let (w, col) = t.inherited();
                    let sub = self.object(c, w, col, false)?;
                    if let Some(o) = sub.object {
                        self.budget.reserve_memory(ENTRY_BYTES)?;
                        let (pos, rot) = t.pose();
                        entries.push(Entry { target: Target::Object(o), translation: pos, rotation: rot, scale: 1.0, colour: [0; 4] });
                        leaves = leaves.saturating_add(self.out.objects[o as usize].leaves);
                    }
                    t.follow(sub.pos, sub.rot, sub.width, sub.colour);
                }
                Item::Node(_) => {}
            }
        }
        // A balanced subtree ends where its brackets put it; the caller checked balance.
        debug_assert!(root || t.depth() == 0);
        let (pos, rot) = t.pose();
        let (w, col) = t.inherited();
        t.release(self.budget);
        let object = match entries.as_slice() {
            [] => None,
            // A single sub-object at the origin passes through.
            [Entry { target: Target::Object(o), translation, rotation, .. }] if *translation == DVec3::ZERO && *rotation == DQuat::IDENTITY => {
                Some(*o)
            }
            _ => {
                self.out.objects.push(Object { entries, leaves });
                Some((self.out.objects.len() - 1) as u32)
            }
        };
        let built = Built { object, pos, rot, width: w, colour: col };
        if !root {
            self.budget.reserve_memory(MEMO_BYTES)?;
            self.memo.insert(key, built);
        }
        Ok(built)
    }
}
