//! Namespaces: `import @ns file` reads every name of `file` as `ns::name`
//! (shapes, paths, functions, definitions, parameters), so another file
//! names them `ns::name` (`ns::SHAPE [ ]`, `ns::f(1)`), as cfdg 3.4 does
//! (John Horigan, Context Free 3.4: `cfdg.ypp`'s `IMPORT fileNameSpace
//! fileString`; `builder.cpp` `PushNameSpace`, `PopNameSpace`,
//! `StringToShape`, `CheckName`). The names cfdg does not look up as
//! names stay as they are: keywords, adjustment terms, built-in functions,
//! `CF::` settings and flags, path operations; and a primitive's name
//! (`CIRCLE`, `SQUARE`, `TRIANGLE`, `FILL`) stays the primitive unless the
//! file defines a shape or path of that name (`StringToShape`'s
//! `maybePrimitive`).
//!
//! cfdg hashes a replacement's shape name as written (`ASTruleSpecifier`'s
//! `entropyVal`), not as qualified, so each qualified name keeps what was
//! written ([`Token::written`]) and a replacement records it in
//! [`Grammar::entropy_names`](super::super::Grammar::entropy_names). A
//! namespaced file's own imports are read in no namespace of their own
//! unless they name one (cfdg would nest them as `outer::inner::`).

use super::super::lexer::{Tok, Token};
use super::Parser;
use crate::{ParseError, Span};

/// The words a namespaced file keeps as they are.
const KEPT: &[&str] = &[
    "startshape", "shape", "rule", "path", "loop", "finally", "if", "else", "switch", "case", "transform", "trans", "clone", "import", "include", "tile", "background", "size", "let", "select", "number", "natural", "adjustment", "infinity", "MOVETO", "MOVEREL", "LINETO", "LINEREL", "ARCTO", "ARCREL", "CURVETO", "CURVEREL", "CLOSEPOLY", "STROKE", "FILL", "x", "y", "z", "s", "r", "f", "h", "b", "a", "rotate", "flip", "skew", "hue", "sat", "saturation", "brightness", "alpha", "time", "timescale", "blend", "p", "param", "width", "x1", "y1", "x2", "y2", "rx", "ry", "\u{3c0}",
];

/// The primitives' names.
const PRIMITIVES: [&str; 3] = ["CIRCLE", "SQUARE", "TRIANGLE"];

fn kept(w: &str) -> bool {
    KEPT.contains(&w)
        || w.starts_with("CF::")
        || w.starts_with('|')
        || w.starts_with("rand::")
        || w.starts_with("randint::")
        || (w.starts_with("vector") && w[6..].bytes().all(|c| c.is_ascii_digit()) && w.len() > 6)
        || super::super::is_builtin(w)
        || !w.chars().next().is_some_and(|c| c.is_alphabetic() || c == '_')
}

/// Reads every name of `toks` (one imported file) as `ns::name`.
pub(super) fn qualify(toks: &mut [Token], ns: &str) {
    // Primitives redefined by the file are its own.
    let own: Vec<String> = toks
        .windows(2)
        .filter_map(|w| match (&w[0].tok, &w[1].tok) {
            (Tok::Word(k), Tok::Word(n)) if matches!(k.as_str(), "shape" | "path" | "rule") && PRIMITIVES.contains(&n.as_str()) => Some(n.clone()),
            _ => None,
        })
        .collect();
    for t in toks.iter_mut() {
        let Tok::Word(w) = &t.tok else { continue };
        if kept(w) || (PRIMITIVES.contains(&w.as_str()) && !own.contains(w)) {
            continue;
        }
        let written = t.written.take().unwrap_or_else(|| w.clone().into_boxed_str());
        t.tok = Tok::Word(format!("{ns}::{w}"));
        t.written = Some(written);
    }
}

impl Parser<'_> {
    /// `@ns` after `import`, if written (`PushNameSpace`'s checks).
    pub(super) fn namespace(&mut self) -> Result<Option<String>, ParseError> {
        if !self.is_punct("@") {
            return Ok(None);
        }
        self.bump();
        let span = self.span();
        let ns = match self.bump().tok {
            Tok::Word(w) => w,
            _ => return Err(ParseError::single(span, "expected a namespace name after `@`")),
        };
        if ns == "CF" {
            return Err(ParseError::single(span, "CF namespace is reserved"));
        }
        if ns.contains(':') {
            return Err(ParseError::single(span, "namespace specification not allowed in this context"));
        }
        Ok(Some(ns))
    }

    /// Records the name a replacement's shape was written as, when the
    /// token just read was qualified by a namespace.
    pub(super) fn note_written(&mut self, shape: &str, span: Span) {
        if let Some(w) = self.toks.get(self.pos.wrapping_sub(1)).and_then(|t| t.written.as_deref()) {
            self.entropy_names.insert((span.line, span.column, shape.to_string()), w.to_string());
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::cfdg::syntax::parse_with;

    #[test]
    fn imported_names_are_qualified() {
        let lib = b"startshape A\nshape A { B [x 1] CIRCLE [] }\nshape B { SQUARE [s twice(2)] }\ntwice(n) = n * sin(90)\n".to_vec();
        let load = move |name: &str| (name == "lib.cfdg").then(|| lib.clone());
        let g = parse_with(b"startshape T\nimport @lib lib.cfdg\nshape T { lib::A [] SQUARE [s lib::twice(1)] }\n", &load).expect("parses");
        let names: Vec<&str> = g.rules.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(names, ["lib::A", "lib::B", "T"]);
        assert!(g.functions.contains_key("lib::twice"));
        assert_eq!(g.start.as_ref().map(|s| s.shape.as_str()), Some("T"));
        // The replacement `B` inside lib keeps its written name for its seed.
        assert_eq!(g.entropy_names.values().collect::<Vec<_>>(), ["B"]);
        let e = parse_with(b"startshape T\nimport @CF lib.cfdg\n", &load).expect_err("reserved");
        assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (2, 9));
    }
}
