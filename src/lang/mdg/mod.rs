//! Model Design Grammars (seed 000, chapter 4, appendices A–B): lexer,
//! preprocessor and parser producing the shared IR.

use super::{ir::Program, ParseError, Span};

/// Parses MDG source into the IR.
pub fn parse(_source: &[u8]) -> Result<Program, ParseError> {
    Err(ParseError::single(Span::new(1, 1), "MDG parser not implemented yet"))
}
