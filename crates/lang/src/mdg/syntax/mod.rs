//! Model Design Grammars (Andersson 2015, chapter 4, appendices A–B): lexer,
//! preprocessor and parser producing the shared IR. The language as built is
//! described in `docs/mdg.md`.

pub(crate) mod lexer;
pub mod parser;
pub mod preprocess;

#[cfg(test)]
mod tests;

use crate::{ir::Program, ParseError, Span};

/// Parses MDG source into the IR.
///
/// Never panics; every error carries a 1-based line and column (in characters).
pub fn parse(source: &[u8]) -> Result<Program, ParseError> {
    let text = match std::str::from_utf8(source) {
        Ok(t) => t,
        Err(e) => {
            let valid = source.get(..e.valid_up_to()).unwrap_or_default();
            // The prefix is valid UTF-8 by construction.
            let prefix = std::str::from_utf8(valid).unwrap_or_default();
            let line = prefix.matches('\n').count() + 1;
            let last = prefix.rsplit('\n').next().unwrap_or("");
            let column = last.chars().count() + 1;
            let span = Span::new(u32::try_from(line).unwrap_or(u32::MAX), u32::try_from(column).unwrap_or(u32::MAX));
            return Err(ParseError::single(span, "invalid UTF-8"));
        }
    };
    if text.trim().is_empty() {
        return Err(ParseError::single(Span::new(1, 1), "empty source: expected `startshape` or `rule`"));
    }
    let pp = preprocess::preprocess(text)?;
    let mut warnings = pp.warnings.clone();
    let tokens = lexer::lex(&pp)?;
    let mut program = parser::Parser::new(tokens, text.len()).parse_program()?;
    warnings.append(&mut program.warnings);
    program.warnings = warnings;
    Ok(program)
}
