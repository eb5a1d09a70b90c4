//! Front ends: one module per language, each turning source bytes into the
//! shared [`ir::Program`]. Parsers never touch geometry or output formats.

pub mod eisen;
pub mod etol;
pub mod expr;
pub mod ir;
pub mod lsystem;
pub mod mdg;
pub mod stack;
pub mod ug;

use serde::Serialize;

pub use crate::core::diagnostic::{Diagnostic, ParseError, Severity, Span};

/// The languages rulemesh reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Language {
    /// Model Design Grammars (Mattias Andersson, *Procedural Modeling and
    /// Animation with Quaternions*, MSc thesis, Chalmers, 2015); see `docs/mdg.md`.
    Mdg,
    /// L-systems in the notation of *The Algorithmic Beauty of Plants* (as used in the
    /// Calgary instancing thesis, c. 1995); see `docs/lsystem.md`.
    Lsystem,
    /// EisenScript, the language of Structure Synth 1.5; see `docs/eisenscript.md`.
    Eisenscript,
    /// The stacking string of Anton Haglund, *Procedural Modelling* (MSc
    /// thesis, Umeå University, 2009): a primitive and a modifier chain (`b1.5s1.4w0.1`); see `docs/modifiers.md`.
    Stack,
    /// Berkeley UniGrafix (as in Carlo H. Séquin (ed.), *Generation of
    /// Time-Varying Geometrical Models*, UC Berkeley, 1992), the safe subset: `v f c def end i`; see `docs/modifiers.md`.
    Ug,
    /// The ETOL token stream of Haglund 2009, Appendix A, read as an L-system; see `docs/lsystem.md`.
    Etol,
}

impl crate::core::Choice for Language {
    const ALL: &'static [Self] =
        &[Language::Mdg, Language::Lsystem, Language::Eisenscript, Language::Stack, Language::Ug, Language::Etol];
    fn name(self) -> &'static str {
        Language::name(self)
    }
}

impl Language {
    /// The language's name as used on the CLI and in requests.
    pub fn name(self) -> &'static str {
        match self {
            Language::Mdg => "mdg",
            Language::Lsystem => "lsystem",
            Language::Eisenscript => "eisenscript",
            Language::Stack => "stack",
            Language::Ug => "ug",
            Language::Etol => "etol",
        }
    }

    /// Picks a language from a file extension (`grammar.mdg` → MDG).
    pub fn from_extension(path: &std::path::Path) -> Option<Language> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "mdg" => Some(Language::Mdg),
            "ls" => Some(Language::Lsystem),
            "es" => Some(Language::Eisenscript),
            "stack" => Some(Language::Stack),
            "ug" => Some(Language::Ug),
            "etol" => Some(Language::Etol),
            _ => None,
        }
    }

    /// Guesses the language from the source text; `None` if nothing matches.
    pub fn detect(source: &[u8]) -> Option<Language> {
        let text = String::from_utf8_lossy(&source[..source.len().min(64 * 1024)]);
        let mdg_words = ["startshape", "rule ", "rule\t", "@param", "@define"];
        let lsystem_line = |l: &str| {
            let l = l.trim_start();
            l.starts_with("axiom:") || l.starts_with("iterations:")
        };
        // EisenScript shares `rule ` with MDG and `#define` with L-systems, so
        // it wins only without their unambiguous markers.
        let eisen = eisen::looks_like_eisenscript(&text)
            && !text.lines().any(lsystem_line)
            && !["startshape", "@param", "@define"].iter().any(|w| text.contains(w));
        if eisen {
            Some(Language::Eisenscript)
        } else if mdg_words.iter().any(|w| text.contains(w)) {
            Some(Language::Mdg)
        } else if text.lines().any(lsystem_line) {
            Some(Language::Lsystem)
        } else {
            None
        }
    }
}

/// Parses `source` in `language` into the IR. `source` is raw bytes so that
/// invalid UTF-8 is reported with a position instead of crashing a caller.
/// L-systems do not lower into the rule IR (they are derived, not expanded):
/// parse them with [`lsystem::parse`]; here they are checked and refused.
pub fn parse(language: Language, source: &[u8]) -> Result<ir::Program, ParseError> {
    match language {
        Language::Mdg => mdg::parse(source),
        Language::Lsystem => {
            lsystem::parse(source)?;
            Err(ParseError::single(Span::new(1, 1), "L-systems do not lower into the rule IR; use lang::lsystem::parse"))
        }
        Language::Eisenscript => {
            eisen::parse(source, &Default::default())?;
            Err(ParseError::single(Span::new(1, 1), "EisenScript does not lower into the rule IR (see docs/eisenscript.md); use lang::eisen::parse"))
        }
        Language::Stack => stack::parse(source),
        Language::Ug => ug::parse(source),
        Language::Etol => {
            let t = etol::translate(source)?;
            lsystem::parse(t.source.as_bytes()).map_err(|e| t.map_error(e))?;
            Err(ParseError::single(Span::new(1, 1), "ETOL streams are L-systems and do not lower into the rule IR; use lang::etol::translate"))
        }
    }
}

/// Parses `source` in `language` only to report its diagnostics (warnings on success).
pub fn check(language: Language, source: &[u8]) -> Result<Vec<Diagnostic>, ParseError> {
    match language {
        Language::Mdg => mdg::parse(source).map(|p| p.warnings),
        Language::Lsystem => lsystem::parse(source).map(|s| s.warnings),
        // A JavaScript script is a program: it is only known what it builds by running it.
        Language::Eisenscript if eisen::is_javascript(source) => {
            Ok(vec![Diagnostic::warning(Span::new(1, 1), "a Structure Synth JavaScript script is run, not checked; render it to run it")])
        }
        Language::Eisenscript => eisen::parse(source, &Default::default()).map(|s| s.warnings),
        Language::Stack => stack::parse(source).map(|p| p.warnings),
        Language::Ug => ug::parse(source).map(|p| p.warnings),
        Language::Etol => {
            let t = etol::translate(source)?;
            let mut warnings = lsystem::parse(t.source.as_bytes()).map_err(|e| t.map_error(e))?.warnings;
            t.map_warnings(&mut warnings);
            Ok(warnings)
        }
    }
}
