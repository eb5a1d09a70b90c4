//! The built-in grammar library: every grammar in `grammars/` and
//! `grammars/icons/`, of every language, embedded at build time so the
//! server needs no files.

use crate::core::Limits;
use crate::lang::ir::ParamKind;
use crate::lang::Language;
use serde::Serialize;
use utoipa::ToSchema;

use crate::core::library::BUILTIN;

/// One built-in grammar.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Builtin {
    /// Its name (the file stem).
    pub name: &'static str,
    /// Its language.
    pub language: Language,
    /// Its source.
    pub source: &'static str,
}

/// Every built-in grammar, sorted by name.
pub fn all() -> impl Iterator<Item = Builtin> {
    // Files no language claims (by extension) are not grammars.
    BUILTIN.iter().filter_map(|&(name, extension, source)| Some(Builtin { name, language: Language::from_extension_name(extension)?, source }))
}

/// The built-in grammar called `name`, if any.
pub fn find(name: &str) -> Option<Builtin> {
    all().find(|b| b.name == name)
}

/// The built-in grammar a route names (`gem`, or with its file's extension,
/// `gem.mdg`, `hogeweg.ls`), or the 404 that every grammar route answers for
/// a name the library does not have.
pub(crate) fn find_route_name(name: &str) -> Result<Builtin, super::ServiceError> {
    let name = Language::ALL
        .iter()
        .flat_map(|l| l.front_end().extensions())
        .find_map(|x| name.strip_suffix(x).and_then(|n| n.strip_suffix('.')))
        .unwrap_or(name);
    find(name).ok_or_else(|| super::ServiceError::NotFound(format!("no built-in grammar `{name}`")))
}

/// A declared parameter as listed by the API.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct ParamInfo {
    /// Its name.
    pub name: String,
    /// `int`, `float` or `bool`.
    pub kind: &'static str,
    /// Its default value.
    pub default: f64,
    /// Lowest accepted value, if declared.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min: Option<f64>,
    /// Highest accepted value, if declared.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max: Option<f64>,
}

/// A grammar as listed by `GET /v1/grammars`.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct GrammarInfo {
    /// Its name.
    pub name: &'static str,
    /// Its language name.
    pub language: &'static str,
    /// The leading `//` comment lines, joined.
    pub description: String,
    /// Its parameters with defaults and ranges.
    pub params: Vec<ParamInfo>,
    /// Whether it is in the printable collection: designed to print as one
    /// watertight shell at its default size, in millimetres (`print=true`).
    pub printable: bool,
    /// A parse error, if the grammar does not parse with this engine.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// The leading `//` comment lines of `source`, without the slashes, joined by spaces.
pub fn description(source: &str) -> String {
    source
        .lines()
        .map(str::trim)
        .take_while(|l| l.starts_with("//"))
        .map(|l| l.trim_start_matches('/').trim())
        .collect::<Vec<_>>()
        .join(" ")
}

impl Builtin {
    /// Name, language, description and parameters (from the parsed program).
    pub fn info(&self) -> GrammarInfo {
        let parsed = crate::pipeline::declared_params(self.source.as_bytes(), Some(self.language), &Limits::default());
        let (params, error) = match parsed {
            Ok((_, params)) => (
                params
                    .iter()
                    .map(|p| ParamInfo {
                        name: p.name.clone(),
                        kind: match p.kind {
                            ParamKind::Int => "int",
                            ParamKind::Float => "float",
                            ParamKind::Bool => "bool",
                        },
                        default: p.default,
                        min: p.range.map(|r| r.0),
                        max: p.range.map(|r| r.1),
                    })
                    .collect(),
                None,
            ),
            Err(e) => (Vec::new(), Some(e.to_string())),
        };
        let printable = crate::core::library::is_printable(self.name);
        GrammarInfo { name: self.name, language: self.language.name(), description: description(self.source), params, printable, error }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn library_is_embedded() {
        assert!(all().count() >= 8);
        let gem = find("gem").expect("gem is built in");
        assert!(gem.source.contains("startshape"));
        assert!(description(gem.source).starts_with("An icon-sized gem"));
        assert!(find("nope").is_none());
    }
}
