//! rulemesh-lang: the languages rulemesh reads, each in one folder holding
//! its parser (`syntax`) and its front end (a [`FrontEnd`] that builds the
//! one [`model::Model`] the stages take), with what they share: the rule IR
//! ([`ir`]), the expression grammar ([`expr`]) and the model itself.
//!
//! It sees only `rulemesh-core`: a front end cannot reach the stages, a
//! writer or the pipeline (the compiler holds that; `layers.txt` orders the
//! modules inside). The crate root is the registry: [`Language`] and its
//! front ends are declared once, in the `languages!` table below, and every
//! list of languages elsewhere (the CLI's choices, the request schema, the
//! library's extensions, the golden table) reads [`Language::ALL`].
//! `docs/extending.md` says how a language is added.

#![warn(missing_docs)]

// The layers below, under the names the code has always used (`crate::core`,
// `crate::geom`), so a module's paths do not depend on which crate holds it.
use rulemesh_core::{core, geom};

pub use crate::core::diagnostic::{Diagnostic, ParseError, Severity, Span};
pub use frontend::FrontEnd;

pub mod expr;
pub(crate) mod frontend;
pub mod ir;
pub mod model;
pub(crate) mod parse_cache;

pub mod cfdg;
pub mod cpfg;
pub mod eisen;
pub mod etol;
pub mod lsystem;
pub mod mdg;
pub mod stack;
pub mod ug;

/// Declares [`Language`] and its registry from one table: each variant and
/// the front end that reads it. The name, file extensions and everything
/// else a door shows come from the front end, never from a second list.
macro_rules! languages {
    ($($(#[$doc:meta])* $variant:ident => $front_end:expr,)*) => {
        /// The languages rulemesh reads (serialised by name: `"mdg"`, `"lsystem"`, …).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Language {
            $($(#[$doc])* $variant,)*
        }

        impl Language {
            /// Every language, in the registry's order.
            pub const ALL: &'static [Language] = &[$(Language::$variant),*];

            /// The language's front end: its parser, checks and model builder.
            pub fn front_end(self) -> &'static dyn FrontEnd {
                match self {
                    $(Language::$variant => &$front_end,)*
                }
            }
        }
    };
}

languages! {
    /// Model Design Grammars (Mattias Andersson, *Procedural Modeling and
    /// Animation with Quaternions*, MSc thesis, Chalmers, 2015); see `docs/mdg.md`.
    Mdg => mdg::Mdg,
    /// L-systems in the notation of *The Algorithmic Beauty of Plants* (as used in the
    /// Calgary instancing thesis, c. 1995); see `docs/lsystem.md`.
    Lsystem => lsystem::Lsystem,
    /// EisenScript, the language of Structure Synth 1.5; see `docs/eisenscript.md`.
    Eisenscript => eisen::Eisenscript,
    /// The stacking string of Anton Haglund, *Procedural Modelling* (MSc
    /// thesis, Umeå University, 2009): a primitive and a modifier chain (`b1.5s1.4w0.1`); see `docs/modifiers.md`.
    Stack => stack::Stack,
    /// Berkeley UniGrafix (as in Carlo H. Séquin (ed.), *Generation of
    /// Time-Varying Geometrical Models*, UC Berkeley, 1992), the safe subset: `v f c def end i`; see `docs/modifiers.md`.
    Ug => ug::Ug,
    /// The ETOL token stream of Haglund 2009, Appendix A, read as an L-system; see `docs/lsystem.md`.
    Etol => etol::Etol,
    /// Context Free Design Grammar (CFDG 2.x and 3.x, as cfdg 3.4 reads and draws it); see `docs/cfdg.md`.
    Cfdg => cfdg::Cfdg,
    /// L-systems written for cpfg, the L-system program of L-studio and vlab (`AlgorithmicBotany/vlab`); see `docs/cpfg.md`.
    Cpfg => cpfg::Cpfg,
}

impl crate::core::Choice for Language {
    const ALL: &'static [Self] = Language::ALL;
    fn name(self) -> &'static str {
        Language::name(self)
    }
}

impl serde::Serialize for Language {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl Language {
    /// The language's name as used on the CLI and in requests (its front end's).
    pub fn name(self) -> &'static str {
        self.front_end().name()
    }

    /// Picks a language from a file's extension (`grammar.mdg` → MDG), case-insensitively.
    pub fn from_extension(path: &std::path::Path) -> Option<Language> {
        Language::from_extension_name(path.extension()?.to_str()?)
    }

    /// The language whose front end claims extension `ext` (without the
    /// dot, case-insensitively): the library's entries are stored by it.
    pub fn from_extension_name(ext: &str) -> Option<Language> {
        // Compared without case in place: lowercasing into a new String cost
        // every model request an allocation (issue 33).
        Language::ALL.iter().copied().find(|l| l.front_end().extensions().iter().any(|e| e.eq_ignore_ascii_case(ext)))
    }

    /// Guesses the language from the source text; `None` if nothing matches.
    ///
    /// Detection is a precedence across languages, so it is written here
    /// rather than per front end: EisenScript shares `rule ` with MDG and
    /// `#define` with L-systems, so it wins only without their unambiguous
    /// markers; then CFDG, whose `startshape` MDG shares, only with a 3.x
    /// `shape` line, a `CF::` setting or a 2D primitive and no MDG-only word
    /// ([`cfdg::looks_like_cfdg`]); then MDG's words; then an L-system's settings lines. A
    /// cpfg L-system comes first of all: its `Lsystem:` line (as cpfg's
    /// lexer reads it, `[Ll]system:`) is in no other language. The other
    /// languages are named or known by extension.
    pub fn detect(source: &[u8]) -> Option<Language> {
        let text = String::from_utf8_lossy(&source[..source.len().min(64 * 1024)]);
        let cpfg_line = |l: &str| {
            let l = l.trim_start();
            l.starts_with("Lsystem:") || l.starts_with("lsystem:")
        };
        if text.lines().any(cpfg_line) {
            return Some(Language::Cpfg);
        }
        let mdg_words = ["startshape", "rule ", "rule\t", "@param", "@define"];
        let lsystem_line = |l: &str| {
            let l = l.trim_start();
            l.starts_with("axiom:") || l.starts_with("iterations:")
        };
        let eisen = eisen::syntax::looks_like_eisenscript(&text)
            && !text.lines().any(lsystem_line)
            && !["startshape", "@param", "@define"].iter().any(|w| text.contains(w));
        if eisen {
            Some(Language::Eisenscript)
        } else if cfdg::looks_like_cfdg(&text) {
            Some(Language::Cfdg)
        } else if mdg_words.iter().any(|w| text.contains(w)) {
            Some(Language::Mdg)
        } else if text.lines().any(lsystem_line) {
            Some(Language::Lsystem)
        } else {
            None
        }
    }
}
