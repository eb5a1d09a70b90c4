//! The L-system front end (`language: "lsystem"`, `.ls` files): the notation
//! of *The Algorithmic Beauty of Plants* as used in the Calgary instancing
//! thesis (ARCHITECTURE.md, "References"), with header
//! settings, `#define` constants, parametric, stochastic and
//! context-sensitive productions and a termination table. See `docs/lsystem.md`.
//!
//! Unlike MDG, an L-system does not lower into the rule IR: it is derived
//! (rewritten in parallel) by [`crate::lsystem`] and then read by a turtle.

mod parser;

pub use parser::parse;

use crate::expr::Expr;
use crate::{Diagnostic, Span};
use crate::core::PrimitiveKind;

/// Symbol id of `[` (push the turtle state); interned first in every system.
pub(crate) const SYM_PUSH: u32 = 0;
/// Symbol id of `]` (pop the turtle state); interned second in every system.
pub(crate) const SYM_POP: u32 = 1;

/// A module in an axiom or successor: a symbol and its argument expressions.
#[derive(Debug, Clone, PartialEq)]
pub struct Module {
    /// Index into [`LSystem::symbols`].
    pub symbol: u32,
    /// Argument expressions; [`Expr::Param`] indexes the matched production's formal parameters.
    pub args: Vec<Expr>,
    /// Where the module is written.
    pub span: Span,
}

/// A module in a predecessor or context: a symbol and the number of formal parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Pattern {
    /// Index into [`LSystem::symbols`].
    pub symbol: u32,
    /// Number of formal parameters; a module matches only with exactly this many.
    pub arity: u32,
    /// Where the pattern is written.
    pub span: Span,
}

/// One production `label: left < pred > right : condition -> successor : probability`.
#[derive(Debug, Clone, PartialEq)]
pub struct Production {
    /// The optional label (`p1`).
    pub label: Option<String>,
    /// Left context, in source order (empty: none).
    pub left: Vec<Pattern>,
    /// The strict predecessor.
    pub pred: Pattern,
    /// Right context, in source order (empty: none).
    pub right: Vec<Pattern>,
    /// The condition; the production applies only where it is non-zero.
    pub condition: Option<Expr>,
    /// The successor modules (empty: the module is erased).
    pub successor: Vec<Module>,
    /// The probability weight of a stochastic production; normalised over its group.
    pub probability: Option<Expr>,
    /// Productions with the same predecessor, contexts and condition share a group:
    /// a stochastic choice is made among the members of one group.
    pub group: u32,
    /// Where the production starts.
    pub span: Span,
}

/// How `F` segments are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// Generalised cylinders: each unbranched run of segments is one swept tube with joints.
    Tube,
    /// One built-in primitive per segment, scaled uniformly by the segment length
    /// and centred on the segment.
    Primitive(PrimitiveKind),
}

/// A parsed L-system.
#[derive(Debug, Clone, PartialEq)]
pub struct LSystem {
    /// Symbol names; a module's symbol indexes this. `[` and `]` come first.
    pub symbols: Vec<String>,
    /// The starting string.
    pub axiom: Vec<Module>,
    /// The productions, in source order (the first matching one wins, apart from stochastic groups).
    pub productions: Vec<Production>,
    /// The termination table, applied once after the last iteration.
    pub terminate: Vec<Production>,
    /// Derivation steps (`iterations:`; default 0).
    pub iterations: u32,
    /// Default turning angle in degrees (`angle:`; default 90).
    pub angle: f64,
    /// Default segment length (`length:`; default 1).
    pub length: f64,
    /// Initial segment width (`width:`; default 0.1).
    pub width: f64,
    /// The grammar's seed (`seed:`), used when the request gives none.
    pub seed: Option<u64>,
    /// Symbols skipped in context matching (`ignore:`).
    pub ignore: Vec<u32>,
    /// How segments are drawn (`shape:`).
    pub shape: Shape,
    /// Tropism vector T (`tropism: x y z`), if set.
    pub tropism: Option<[f64; 3]>,
    /// Susceptibility to tropism e (`elasticity:`; default 0.2 when a tropism is set).
    pub elasticity: f64,
    /// `variety: k`: instance a stochastic system with at most k pseudo-stochastic
    /// variants per (module, parameters, remaining depth) (Calgary instancing thesis §5.1), trading
    /// exactness of the distribution for a model whose size does not grow with the
    /// string. `None`: stochastic systems are derived in full.
    pub variety: Option<u32>,
    /// Number of `rand()`/`ran()` sites; every site id is below it.
    pub site_count: u32,
    /// Non-fatal diagnostics.
    pub warnings: Vec<Diagnostic>,
}

impl LSystem {
    /// The id of a symbol by name, if the system uses it.
    pub(crate) fn symbol(&self, name: &str) -> Option<u32> {
        self.symbols.iter().position(|s| s == name).map(|i| i as u32)
    }

    /// True when every production is context-free, condition-free, deterministic and
    /// parameter-free, so string lengths can be predicted per level by counting symbols.
    pub(crate) fn is_d0l(&self) -> bool {
        let plain = |p: &Production| {
            p.left.is_empty()
                && p.right.is_empty()
                && p.condition.is_none()
                && p.probability.is_none()
                && p.pred.arity == 0
                && p.successor.iter().all(|m| m.args.is_empty())
        };
        let mut seen = vec![false; self.symbols.len()];
        for p in &self.productions {
            if !plain(p) {
                return false;
            }
            match seen.get_mut(p.pred.symbol as usize) {
                Some(s) if *s => return false,
                Some(s) => *s = true,
                None => return false,
            }
        }
        self.axiom.iter().all(|m| m.args.is_empty())
    }
}
