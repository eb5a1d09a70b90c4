//! The name a replacement's seed hashes: as written, which for a shape
//! named inside a file imported into a namespace is not its qualified name
//! (`ASTruleSpecifier`'s `entropyVal`, `astexpression.cpp`, Context Free
//! 3.4; `syntax/parser/namespace.rs` records them).

use super::Renderer;
use crate::cfdg::syntax::Replacement;

impl<'g> Renderer<'g> {
    /// The name `rep`'s seed hashes.
    pub(super) fn entropy_name<'a>(&self, rep: &'a Replacement) -> &'a str
    where
        'g: 'a,
    {
        let names: &'g std::collections::BTreeMap<(u32, u32, String), String> = self.entropy_names;
        if names.is_empty() {
            return &rep.shape;
        }
        match names.get(&(rep.span.line, rep.span.column, rep.shape.clone())) {
            Some(w) => w,
            None => &rep.shape,
        }
    }
}
