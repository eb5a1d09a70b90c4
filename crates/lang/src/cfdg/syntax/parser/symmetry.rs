//! `CF::Symmetry`'s list of adjustments and symmetry groups, read as cfdg
//! 3.4 reads it (John Horigan, Context Free 3.4: `cfdg.ypp`, a
//! `CFDGdefinition` whose expression is a comma list of modifications,
//! flags and numbers; `ast.cpp` `getTransforms` reads the list in order).

use super::super::SymmetryItem;
use super::Parser;
use crate::ParseError;

impl Parser<'_> {
    /// Items separated by commas: an adjustment (`[ ]` or `[[ ]]`) or an
    /// expression (a `CF::` group flag or a number).
    pub(super) fn symmetry_list(&mut self) -> Result<Vec<SymmetryItem>, ParseError> {
        let mut items = Vec::new();
        loop {
            if self.is_punct("[") {
                items.push(SymmetryItem::Adjust(self.adjustment()?));
            } else {
                let span = self.span();
                items.push(SymmetryItem::Expr(self.expr(1)?, span));
            }
            if !self.is_punct(",") {
                return Ok(items);
            }
            self.bump();
        }
    }
}
