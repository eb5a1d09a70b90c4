//! `mesh NAME { BASE | modifier … }` declarations and implicitly declared
//! named solids (`TRUNCATED_ICOSAHEDRON {}`), kept out of the main parser
//! file so the hook there stays a few lines.
//!
//! BASE is a primitive (`ICOSAHEDRON`), an Archimedean solid
//! (`SNUB_CUBE`) or `GEODESIC n`. Each stage after `|` is a modifier name
//! and its words: constant numbers and option keywords, parsed by
//! [`crate::geom::modifiers::syntax::stage`].

use super::{err, PResult, Parser};
use crate::geom::modifiers::syntax::{stage, Word};
use crate::geom::modifiers::MeshBase;
use crate::geom::polyhedra::Solid;
use crate::ir::{MeshDecl, PrimitiveKind};
use crate::mdg::syntax::lexer::Tok;
use crate::core::Span;

/// Largest geodesic frequency a grammar may name (20·256² = 1.3M triangles;
/// the budget usually stops far earlier).
const MAX_FREQUENCY: f64 = 256.0;

impl<'a> Parser<'a> {
    /// Parses a `mesh` declaration (the keyword is already consumed).
    pub(super) fn mesh_decl(&mut self, span: Span) -> PResult<()> {
        let (name, _) = self.name_after("mesh")?;
        self.expect_punct('{', || format!("after `mesh {name}`"))?;
        let b = self.bump();
        let base = match b.tok {
            Tok::Ident(w) if w.eq_ignore_ascii_case("geodesic") => {
                let n = self.whole_value("the geodesic frequency", MAX_FREQUENCY)?;
                if n < 1.0 {
                    return Err(err(b.span, "geodesic frequency must be at least 1"));
                }
                MeshBase::Geodesic(n as u32)
            }
            Tok::Ident(w) => base_named(w).ok_or_else(|| err(b.span, format!("unknown mesh base `{w}` (a primitive, an Archimedean solid or GEODESIC n)")))?,
            other => return Err(err(b.span, format!("expected a base shape in mesh `{name}`, found {other}"))),
        };
        let mut modifiers = Vec::new();
        loop {
            let t = self.bump();
            match t.tok {
                Tok::Punct('}') => break,
                Tok::Punct('|') => {}
                other => return Err(err(t.span, format!("expected `|` or `}}` in mesh `{name}`, found {other}"))),
            }
            let (op, ospan) = self.name_after("`|`")?;
            let mut words = Vec::new();
            while !self.is_punct('|') && !self.is_punct('}') {
                match self.peek().tok {
                    Tok::Ident(k) => {
                        self.bump();
                        words.push(Word::Key(k.to_ascii_lowercase()));
                    }
                    Tok::Eof => return Err(err(self.peek().span, format!("mesh `{name}` is not closed with `}}`"))),
                    _ => words.push(Word::Num(self.const_value("a modifier argument")?.0)),
                }
            }
            modifiers.push(stage(op, &words).map_err(|m| err(ospan, m))?);
        }
        if self.mesh_index.contains_key(name) || self.isosurface_index.contains_key(name) {
            return Err(err(span, format!("`{name}` is declared twice")));
        }
        self.push_mesh(MeshDecl { name: name.to_string(), base, modifiers, span })?;
        Ok(())
    }

    fn push_mesh(&mut self, decl: MeshDecl) -> PResult<u32> {
        let i = u32::try_from(self.meshes.len()).map_err(|_| err(decl.span, "too many meshes"))?;
        self.mesh_index.insert(decl.name.clone(), i);
        self.meshes.push(decl);
        Ok(i)
    }

    /// Declares every Archimedean solid that a call or `startshape` names and
    /// no rule, isosurface or mesh claims, so `SNUB_CUBE {}` works like a primitive.
    pub(super) fn declare_named_solids(&mut self) -> PResult<()> {
        let names: Vec<(&'a str, Span)> =
            self.call_names.iter().map(|&(_, n, s, _)| (n, s)).chain(self.startshape).collect();
        for (name, span) in names {
            if self.group_index.contains_key(name) || self.isosurface_index.contains_key(name) || self.mesh_index.contains_key(name) {
                continue;
            }
            if let Some(s) = Solid::by_name(name) {
                self.push_mesh(MeshDecl { name: name.to_string(), base: MeshBase::Solid(s), modifiers: Vec::new(), span })?;
            }
        }
        Ok(())
    }
}

/// A named base: a built-in primitive or an Archimedean solid.
fn base_named(word: &str) -> Option<MeshBase> {
    PrimitiveKind::from_keyword(word).map(MeshBase::Primitive).or_else(|| Solid::by_name(word).map(MeshBase::Solid))
}
