//! The built-in grammar library: every `grammars/*.mdg`, embedded at build
//! time (build.rs), so the server needs no files and `@import` can read
//! library grammars without touching the file system.

include!(concat!(env!("OUT_DIR"), "/grammars.rs"));

/// The source of built-in grammar `name` (the file stem), if there is one.
pub fn source(name: &str) -> Option<&'static str> {
    BUILTIN.iter().find(|(n, _, _)| *n == name).map(|&(_, _, s)| s)
}
