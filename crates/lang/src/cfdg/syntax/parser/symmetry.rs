//! `CF::Symmetry`'s list of adjustments and symmetry groups, read as cfdg
//! 3.4 reads it (John Horigan, Context Free 3.4: `cfdg.ypp`, a
//! `CFDGdefinition` whose expression is a comma list of modifications,
//! flags and numbers; `ast.cpp` `getTransforms` reads the list in order).

use super::super::{Adjustment, SymmetryItem};
use super::Tok;
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

    /// What follows `transform` or `clone`: adjustments side by side (the
    /// plain form, kept as adjustments), or a comma list that may name
    /// symmetry groups (`clone [], [x 4]`, `clone CF::Dihedral, 6`).
    pub(super) fn transform_list(&mut self) -> Result<(Vec<Adjustment>, Vec<SymmetryItem>), ParseError> {
        if matches!(self.peek(), Tok::Word(w) if w.starts_with("CF::")) {
            return Ok((Vec::new(), self.symmetry_list()?));
        }
        let mut adjusts = Vec::new();
        while self.is_punct("[") {
            adjusts.push(self.adjustment()?);
        }
        if adjusts.is_empty() {
            return self.err("expected an adjustment `[ ]`");
        }
        if !self.is_punct(",") {
            return Ok((adjusts, Vec::new()));
        }
        self.bump();
        let mut items: Vec<SymmetryItem> = adjusts.into_iter().map(SymmetryItem::Adjust).collect();
        items.extend(self.symmetry_list()?);
        Ok((Vec::new(), items))
    }
}
