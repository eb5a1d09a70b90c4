//! Haglund 2009's stacking string as a language (`language: "stack"`): one
//! primitive and a modifier chain, e.g. `b1.5s1.4w0.1` (a box of size 1.5,
//! subdivided once with weight 1.4, spikes of height 0.1).
//!
//! It lowers into the rule IR as a program whose start is a single
//! [`MeshDecl`], so evaluation, budgets, meshing and every output format
//! work unchanged. The letters are documented in `docs/modifiers.md` and
//! [`crate::geom::modifiers::syntax::stack`].

use crate::ir::{MeshDecl, Program};
use crate::{ParseError, Span};

/// Parses a stacking string (surrounding whitespace and one trailing newline are fine).
pub fn parse(source: &[u8]) -> Result<Program, ParseError> {
    let text = std::str::from_utf8(source).map_err(|e| ParseError::single(Span::new(1, e.valid_up_to() as u32 + 1), "the stacking string is not UTF-8"))?;
    let stack = crate::geom::modifiers::syntax::stack(text.trim()).map_err(|m| ParseError::single(Span::new(1, 1), m))?;
    let mesh = MeshDecl { name: "stack".into(), base: stack.base, modifiers: stack.modifiers, span: Span::new(1, 1) };
    Ok(Program::single_mesh(mesh, Vec::new()))
}
