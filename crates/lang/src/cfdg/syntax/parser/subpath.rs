//! Subpaths: `path NAME [adjustment]` (or `path NAME(args) [adjustment]`)
//! inside a path body, as cfdg 3.4 reads them (John Horigan, Context Free
//! 3.4: `cfdg.ypp`'s `path_element: PATH shapeName parameter_spec
//! modification`, `builder.cpp` `Builder::MakeElement` with `subPath`
//! set). Inside a path the only replacement is a subpath, so a subpath is
//! kept as an [`Element::Replace`] of the path's body; a replacement
//! written without `path` there is cfdg's error "Replacements are not
//! allowed in paths". `eval/run/path/subpath.rs` walks them.

use super::super::{Element, Replacement};
use super::Parser;
use crate::ParseError;

impl Parser<'_> {
    /// `path NAME [(args)] [adjustment]` in a path body (the current token is `path`).
    pub(super) fn subpath(&mut self) -> Result<Element, ParseError> {
        self.bump();
        let (shape, span) = self.name("a path or shape name after `path`")?;
        self.note_written(&shape, span);
        if shape == "FILL" || shape == "STROKE" {
            return Err(ParseError::single(span, "FILL cannot be a subpath"));
        }
        let args = if self.is_punct("(") { self.call_args(&shape)? } else { None };
        let adjust = self.adjustment()?;
        Ok(Element::Replace(Replacement { shape, adjust, args, span }))
    }
}
