//! Derivation without the string: a memoised DAG of subtrees (Calgary
//! instancing thesis §4.1, §4.3, §5.1).
//!
//! In a context-free system a module's future depends only on the module
//! itself (symbol and parameters) and the number of derivation steps left,
//! so `(symbol, parameter bits, remaining steps, variant)` names a subtree
//! of the derivation. [`build`] expands each distinct key once into a
//! [`DagNode`] whose items are terminal modules or other nodes, which is the
//! thesis's b-grammar: cost O(distinct keys), never O(string length).
//!
//! * A module no production matches is terminal from then on (it is copied
//!   unchanged), so its key carries no depth; with a termination table it
//!   skips to the last step instead.
//! * A successor of one module passes through: the key maps to that
//!   module's own expansion (L2059), so counters like `F(l) → F(l*2)` add no node.
//! * Stochastic systems instance only with `variety: k`: each occurrence of
//!   a module in a successor picks one of k variants from a hash of the seed,
//!   its parent's key and its position, and the variant's productions and
//!   `rand()` draw from the variant's own stream (the pseudo-stochastic
//!   scheme of Fig 5.2). The output is a function of the seed, but not the
//!   distribution of an exact derivation.
//!
//! Budget: every successor module evaluated is one step, and every item,
//! parameter and memo entry is accounted before it is stored.

use super::derive::{axiom, ModuleString, Rewriter};
use super::turtle::ModuleSink;
use crate::core::budget::Budget;
use crate::core::rng::StreamKey;
use crate::model::EvalError;
use crate::lsystem::syntax::{LSystem, SYM_POP, SYM_PUSH};
use std::collections::HashMap;

/// Deepest derivation instanced: the DAG and its walks recurse once per step,
/// so deeper systems are derived in full instead.
pub(crate) const MAX_INSTANCED_STEPS: u32 = 256;

/// Stream site of the per-key random stream of a variant.
const KEY_SITE: u32 = 0x4441_4700; // "DAG"
/// Stream site of a child's variant choice.
const VARIANT_SITE: u32 = 0x5641_5200; // "VAR"

/// Bytes accounted per item, parameter and memo entry.
const ITEM_BYTES: u64 = std::mem::size_of::<Item>() as u64;
const PARAM_BYTES: u64 = 8;
const MEMO_BYTES: u64 = 96;

/// Why a system cannot be instanced (it is derived in full instead).
pub fn not_instanceable(sys: &LSystem) -> Option<&'static str> {
    let all = || sys.productions.iter().chain(&sys.terminate);
    if all().any(|p| !p.left.is_empty() || !p.right.is_empty()) {
        return Some("context-sensitive productions");
    }
    if sys.symbol("%").is_some() {
        return Some("the cut symbol `%`");
    }
    if sys.symbols.iter().any(|s| s.starts_with('?')) {
        return Some("environment queries");
    }
    if sys.symbol("{").is_some() {
        return Some("polygons");
    }
    if sys.tropism.is_some() && (sys.symbol("@").is_some() || sys.symbol("~").is_some()) {
        return Some("tropism");
    }
    if sys.variety.is_none() && (sys.site_count > 0 || all().any(|p| p.probability.is_some())) {
        return Some("stochastic productions or `rand()` without `variety:`");
    }
    if total_steps(sys) > MAX_INSTANCED_STEPS {
        return Some("more derivation steps than instancing supports");
    }
    None
}

/// Derivation steps including the termination table.
pub(crate) fn total_steps(sys: &LSystem) -> u32 {
    sys.iterations.saturating_add(u32::from(!sys.terminate.is_empty()))
}

/// One item of a node: a terminal module or a sub-node.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Item {
    /// A module that is not rewritten any more: symbol and its parameters'
    /// range in [`StringDag::params`].
    Module {
        /// The symbol.
        sym: u32,
        /// First parameter.
        start: u32,
        /// Number of parameters.
        len: u32,
    },
    /// A sub-node (always of a lower index).
    Node(u32),
}

/// One distinct subtree: its items in string order and its expanded sizes.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DagNode {
    /// The items.
    pub items: Vec<Item>,
    /// Modules in the expansion (saturating): the length of the string it stands for.
    pub modules: u64,
    /// `F` modules in the expansion (saturating): the segments it draws.
    pub segments: u64,
    /// Least bracket depth reached in the expansion, relative to its start.
    pub low: i64,
    /// Bracket depth at the end of the expansion, relative to its start.
    pub net: i64,
}

/// The derivation as a DAG; the root (the axiom) is the last node.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StringDag {
    /// The nodes, sub-nodes first.
    pub nodes: Vec<DagNode>,
    /// Parameters of terminal modules.
    pub params: Vec<f64>,
}

impl StringDag {
    /// The root node (the axiom's expansion; an empty node for an empty DAG).
    pub fn root(&self) -> &DagNode {
        static EMPTY: DagNode = DagNode { items: Vec::new(), modules: 0, segments: 0, low: 0, net: 0 };
        self.nodes.last().unwrap_or(&EMPTY)
    }

    /// Index of the root node, which [`build`] always pushes last.
    pub fn root_index(&self) -> u32 {
        self.nodes.len().saturating_sub(1) as u32
    }

    /// The parameters of a terminal module item.
    pub(crate) fn params_of(&self, start: u32, len: u32) -> &[f64] {
        self.params.get(start as usize..(start as usize).saturating_add(len as usize)).unwrap_or(&[])
    }

    /// True when every node but the root closes every bracket it opens and
    /// never pops one it did not open, so each subtree's turtle state at its
    /// end depends only on its start (the status function has n = 0).
    pub fn balanced(&self) -> bool {
        let Some((_, inner)) = self.nodes.split_last() else { return true };
        inner.iter().all(|n| n.low >= 0 && n.net == 0)
    }

    /// Feeds the expansion of node `id` to `sink` module by module: the
    /// derived string, without storing it.
    pub fn feed(&self, id: u32, sink: &mut ModuleSink<'_>) -> Result<(), EvalError> {
        let Some(node) = self.nodes.get(id as usize) else { return Ok(()) };
        for item in &node.items {
            match *item {
                Item::Module { sym, start, len } => sink(sym, self.params_of(start, len))?,
                Item::Node(c) if c < id => self.feed(c, sink)?,
                Item::Node(_) => {}
            }
        }
        Ok(())
    }
}

/// What a key expands to.
#[derive(Debug, Clone, Copy)]
enum Expansion {
    /// The module itself, unchanged.
    Terminal,
    /// A single terminal module (a pass-through successor).
    Module(Item),
    /// A node.
    Node(u32),
}

type Key = (u32, u32, u32, Box<[u64]>);

struct Builder<'a, 'b> {
    main: &'b Rewriter<'a>,
    term: &'b Rewriter<'a>,
    root: StreamKey,
    variety: u32,
    draw: Option<u32>,
    dag: StringDag,
    memo: HashMap<Key, Expansion>,
    budget: &'b mut Budget,
}

fn bits(v: f64) -> u64 {
    // −0.0 and 0.0 behave alike in every expression the turtle reads.
    if v == 0.0 {
        0
    } else {
        v.to_bits()
    }
}

/// Builds the DAG of `sys` with `seed` (which only matters with `variety:`).
/// The caller checks [`not_instanceable`] first.
pub fn build(sys: &LSystem, seed: u64, budget: &mut Budget) -> Result<StringDag, EvalError> {
    let start = axiom(sys, seed, budget)?;
    let (main, term) = (Rewriter::new(sys, &sys.productions), Rewriter::new(sys, &sys.terminate));
    let mut b = Builder {
        main: &main,
        term: &term,
        root: StreamKey::root(seed),
        variety: sys.variety.unwrap_or(1).max(1),
        draw: sys.symbol("F"),
        dag: StringDag::default(),
        memo: HashMap::new(),
        budget,
    };
    let total = total_steps(sys);
    let mut items = Vec::with_capacity(start.len());
    for i in 0..start.len() {
        let variant = b.variant(b.root.child(VARIANT_SITE, u64::MAX), i);
        let (sym, params) = (start.syms[i], start.params_of(i));
        let item = b.item(sym, params, total, variant)?;
        items.push(item);
    }
    b.push_node(items)?;
    b.budget.release_memory(start.bytes());
    Ok(b.dag)
}

impl Builder<'_, '_> {
    fn variant(&self, parent: StreamKey, index: usize) -> u32 {
        if self.variety <= 1 {
            return 0;
        }
        (parent.child(VARIANT_SITE, index as u64).0 % u64::from(self.variety)) as u32
    }

    /// The item standing for `sym(params)` with `r` steps left.
    fn item(&mut self, sym: u32, params: &[f64], r: u32, variant: u32) -> Result<Item, EvalError> {
        match self.expand(sym, params, r, variant)? {
            Expansion::Terminal => self.terminal(sym, params),
            Expansion::Module(item) => Ok(item),
            Expansion::Node(id) => Ok(Item::Node(id)),
        }
    }

    fn terminal(&mut self, sym: u32, params: &[f64]) -> Result<Item, EvalError> {
        self.budget.reserve_memory(PARAM_BYTES.saturating_mul(params.len() as u64))?;
        let start = self.dag.params.len();
        self.dag.params.extend_from_slice(params);
        // Fits: 2³² parameters would be 32 GiB, beyond the memory ceiling reserved above.
        Ok(Item::Module { sym, start: start as u32, len: params.len() as u32 })
    }

    fn expand(&mut self, sym: u32, params: &[f64], r: u32, variant: u32) -> Result<Expansion, EvalError> {
        if r == 0 {
            return Ok(Expansion::Terminal);
        }
        let key: Key = (sym, r, variant, params.iter().map(|&v| bits(v)).collect());
        if let Some(&e) = self.memo.get(&key) {
            return Ok(e);
        }
        let mut stream = self.root.child(KEY_SITE, u64::from(sym)).child(r, u64::from(variant));
        for &b in key.3.iter() {
            stream = stream.child(KEY_SITE, b);
        }
        let last = !self.term.is_empty() && r == 1;
        let rw: &Rewriter<'_> = if last { self.term } else { self.main };
        let mut env = Vec::new();
        let result = match rw.choose(sym, params, stream, &mut env)? {
            // Never rewritten again, except by the termination table at the last step.
            None if !self.term.is_empty() && r > 1 => self.expand(sym, params, 1, variant)?,
            None => Expansion::Terminal,
            Some(p) => {
                let mut items = Vec::with_capacity(p.successor.len());
                let mut vals = Vec::new();
                for (j, m) in p.successor.iter().enumerate() {
                    self.budget.charge_step()?;
                    rw.emit(m, &env, stream, &mut vals)?;
                    let v = self.variant(stream, j);
                    items.push(self.item(m.symbol, &vals, r - 1, v)?);
                }
                match items.as_slice() {
                    [Item::Node(id)] => Expansion::Node(*id),
                    [one @ Item::Module { .. }] => Expansion::Module(*one),
                    _ => Expansion::Node(self.push_node(items)?),
                }
            }
        };
        self.budget.reserve_memory(MEMO_BYTES.saturating_add(PARAM_BYTES.saturating_mul(params.len() as u64)))?;
        self.memo.insert(key, result);
        Ok(result)
    }

    fn push_node(&mut self, items: Vec<Item>) -> Result<u32, EvalError> {
        self.budget.reserve_memory(ITEM_BYTES.saturating_mul(items.len() as u64).saturating_add(64))?;
        let node = summarise(&self.dag.nodes, items, self.draw);
        self.dag.nodes.push(node);
        Ok((self.dag.nodes.len() - 1) as u32)
    }
}

/// A node of `items` with its expanded sizes and bracket depths; sub-nodes must be in `nodes`.
fn summarise(nodes: &[DagNode], items: Vec<Item>, draw: Option<u32>) -> DagNode {
    let mut node = DagNode::default();
    let mut depth = 0i64;
    for item in &items {
        match *item {
            Item::Module { sym, .. } => {
                node.modules = node.modules.saturating_add(1);
                if Some(sym) == draw {
                    node.segments = node.segments.saturating_add(1);
                }
                if sym == SYM_PUSH {
                    depth += 1;
                } else if sym == SYM_POP {
                    depth -= 1;
                    node.low = node.low.min(depth);
                }
            }
            Item::Node(c) => {
                if let Some(child) = nodes.get(c as usize) {
                    node.modules = node.modules.saturating_add(child.modules);
                    node.segments = node.segments.saturating_add(child.segments);
                    node.low = node.low.min(depth + child.low);
                    depth += child.net;
                }
            }
        }
    }
    node.net = depth;
    node.items = items;
    node
}

/// A one-node DAG holding a fully derived string: how systems that cannot
/// be instanced still become a (flat) hierarchy for `format=scene`.
pub fn from_string(sys: &LSystem, s: &ModuleString, budget: &mut Budget) -> Result<StringDag, EvalError> {
    budget.reserve_memory(ITEM_BYTES.saturating_mul(s.len() as u64).saturating_add(PARAM_BYTES.saturating_mul(s.params.len() as u64)))?;
    let mut dag = StringDag { nodes: Vec::new(), params: s.params.clone() };
    let items = (0..s.len())
        .map(|i| Item::Module { sym: s.syms[i], start: s.starts[i], len: s.starts[i + 1] - s.starts[i] })
        .collect();
    dag.nodes.push(summarise(&[], items, sys.symbol("F")));
    Ok(dag)
}
