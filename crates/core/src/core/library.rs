//! The built-in grammar library: every grammar file of `grammars/` and
//! `grammars/icons/`, of every language, embedded at build time (build.rs),
//! so the server needs no files and MDG's `@import` can read library
//! grammars without touching the file system.

include!(concat!(env!("OUT_DIR"), "/grammars.rs"));

/// The source of built-in grammar `name` (the file stem) whose file has
/// `extension` (e.g. `"mdg"`), if there is one. An import names a grammar
/// of its own language: MDG's `@import "hogeweg"` must not read an L-system.
pub fn source(name: &str, extension: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, x, _)| *n == name && *x == extension).map(|&(_, _, s)| s)
}

/// The printable collection: library grammars designed to be printed, each
/// one watertight shell at its default size (in millimetres) when rendered
/// with `print=true` (docs/print.md shows them; tests/it/collection.rs
/// prints each and checks it with admesh and trimesh). `GET /v1/grammars`
/// marks them `printable`, so an ordering backend can offer them.
pub const PRINTABLE: &[&str] = &["gear", "lamp-shade", "lattice-cube", "ornament", "pendant", "ring", "rook", "vase"];

/// Whether library grammar `name` is in the printable collection.
pub fn is_printable(name: &str) -> bool {
    PRINTABLE.contains(&name)
}
