//! rulemesh-lang: the parsers, one submodule of [`lang`] per language, the
//! shared rule IR and the expression grammar. Source bytes in, IR (or a
//! language's own syntax tree) or a positioned `ParseError` out; nothing here
//! evaluates. It sees only `rulemesh-core`, so a parser cannot reach the
//! model, the stages or a format.

#![warn(missing_docs)]

// The layers below, under the names the code has always used (`crate::core`,
// `crate::geom`), so a module's paths do not depend on which crate holds it.
use rulemesh_core::{core, geom};

pub mod lang;
