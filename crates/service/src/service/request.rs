//! Requests in two stages, shared by HTTP and gRPC: a raw request exactly as
//! the client sent it ([`RenderBody`]), and a validated [`RenderPlan`] with
//! every default filled in, every limit clamped and the cache key computed.
//! The options themselves are declared once, in the pipeline
//! ([`RenderOptions`]); this module adds the source, the JSON shape and the key.

use super::ServiceError;
use crate::cache::CacheKey;
use crate::pipeline::key::{cache_key, normalize_source};
use crate::pipeline::options::InvalidOptions;
use crate::pipeline::{LimitsOptions, RenderOptions};
use crate::core::Limits;
use crate::export::{Format, OptionGroup};
use crate::lang::Language;
use crate::preview::PreviewOptions;
use crate::RenderRequest;
use std::collections::BTreeMap;
use serde::Deserialize;
use serde_json::{Map, Value};
use std::sync::Arc;
use utoipa::openapi::schema::{ObjectBuilder, Schema};
use utoipa::openapi::RefOr;
use utoipa::{PartialSchema, ToSchema};

pub use crate::pipeline::options::SeedValue;

impl From<InvalidOptions> for ServiceError {
    fn from(e: InvalidOptions) -> Self {
        ServiceError::BadRequest(e.0)
    }
}

/// The JSON shape of a grammar parameter's value (for the OpenAPI document;
/// requests are read as [`ParamValue`](crate::core::ParamValue)).
#[derive(Debug, Clone, PartialEq, serde::Serialize, ToSchema)]
#[serde(untagged)]
#[schema(as = ParamValue)]
// Only its shape is read (utoipa derives the OpenAPI schema from it); nothing
// constructs it, so rustc would call its variants dead.
#[allow(dead_code, reason = "a schema-only type: utoipa reads its shape, nothing constructs it")]
pub(crate) enum ParamValueSchema {
    /// A number.
    Number(f64),
    /// A boolean.
    Bool(bool),
    /// Text read as a number or `true`/`false`.
    Text(String),
}

/// The JSON shape of a seed (for the OpenAPI document; requests are read
/// as [`RenderOptions::seed`] says).
#[derive(Debug, Clone, PartialEq, serde::Serialize, ToSchema)]
#[serde(untagged)]
#[schema(as = Seed)]
// Only its shape is read (utoipa derives the OpenAPI schema from it); nothing
// constructs it, so rustc would call its variants dead.
#[allow(dead_code, reason = "a schema-only type: utoipa reads its shape, nothing constructs it")]
pub(crate) enum SeedSchema {
    /// A whole number from 0 to 2^64 − 1.
    Number(u64),
    /// The same as decimal digits (up to 20).
    Text(String),
}

/// `POST /v1/render` as sent (and the gRPC `RenderRequest`, converted): the
/// source and the options of the one declaration, [`RenderOptions`], whose
/// fields sit beside `source` in the JSON object.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RenderBody {
    /// Grammar source.
    pub source: String,
    /// Everything else the request says.
    pub options: RenderOptions,
    /// Named files beside the source (a cpfg model's `.v`, `.a`, `.map` and
    /// `#include`s, docs/cpfg.md): name → text, or `base64:` and the bytes.
    /// Content like the source, not an option of the render: they count
    /// against `max_source_bytes` and are part of the cache key.
    pub files: BTreeMap<String, String>,
}

impl<'de> Deserialize<'de> for RenderBody {
    /// `source` (required, a string) and the options, each by its name,
    /// nothing else. (serde's `flatten` cannot be combined with
    /// `deny_unknown_fields`, so the object is split here.)
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let mut fields = Map::<String, Value>::deserialize(d)?;
        let source = match fields.remove("source") {
            Some(Value::String(s)) => s,
            Some(other) => return Err(serde::de::Error::custom(format!("`source` must be a string, not {other}"))),
            None => return Err(serde::de::Error::missing_field("source")),
        };
        let files = match fields.remove("files") {
            None => BTreeMap::new(),
            Some(v) => serde_json::from_value(v).map_err(|e| serde::de::Error::custom(format!("`files`: {e}")))?,
        };
        let options = RenderOptions::deserialize(Value::Object(fields)).map_err(serde::de::Error::custom)?;
        Ok(RenderBody { source, files, options })
    }
}

/// The OpenAPI schema of `options`' fields: each field's name and
/// description from the declaration, to be tightened to its declared schema
/// ([`super::schema::tighten_openapi`]); `params` as a map of [`ParamValueSchema`].
fn declared_object(fields: &[crate::pipeline::options::OptionField]) -> ObjectBuilder {
    let mut object = ObjectBuilder::new();
    for f in fields {
        let schema: RefOr<Schema> = match f.name {
            "params" => ObjectBuilder::new()
                .additional_properties(Some(utoipa::openapi::Ref::from_schema_name("ParamValue")))
                .description(Some(f.doc.clone()))
                .into(),
            _ => ObjectBuilder::new().description(Some(f.doc.clone())).into(),
        };
        object = object.property(f.name, schema);
    }
    object
}

impl PartialSchema for RenderBody {
    fn schema() -> RefOr<Schema> {
        let source = ObjectBuilder::new().schema_type(utoipa::openapi::schema::Type::String).description(Some("Grammar source."));
        let files = ObjectBuilder::new()
            .additional_properties(Some(ObjectBuilder::new().schema_type(utoipa::openapi::schema::Type::String)))
            .description(Some("Files beside the source (a cpfg model's .v, .a, .map, #includes): name → text, or `base64:` and the bytes."));
        declared_object(RenderOptions::fields())
            .property("source", source)
            .required("source")
            .property("files", files)
            .description(Some("`POST /v1/render` as sent: the source and the render options (the one declaration, `pipeline::options`)."))
            .into()
    }
}

impl ToSchema for RenderBody {
    fn schemas(schemas: &mut Vec<(String, RefOr<Schema>)>) {
        schemas.push(("ParamValue".into(), ParamValueSchema::schema()));
        schemas.push(("Seed".into(), SeedSchema::schema()));
        schemas.push(("LimitsBody".into(), LimitsBody::schema()));
    }
}

/// The limits' OpenAPI component, from [`LimitsOptions`]' declaration.
pub struct LimitsBody;

impl PartialSchema for LimitsBody {
    fn schema() -> RefOr<Schema> {
        declared_object(LimitsOptions::fields()).description(Some("Client-supplied limits: every field optional, missing ones take the defaults.")).into()
    }
}

impl ToSchema for LimitsBody {}

/// `POST /v1/check` as sent.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CheckBody {
    /// Grammar source.
    pub source: String,
    /// A language's name (`"mdg"`, `"lsystem"`, `"eisenscript"`, …, `Language::ALL`); detected from the source when absent.
    pub language: Option<String>,
    /// Named files beside the source, as a render body's `files` (text, or
    /// `base64:` and the bytes): a cpfg model's view and `#include`s, so the
    /// check reads what the render reads. They count against the source limit.
    #[serde(default)]
    pub files: BTreeMap<String, String>,
}

/// A validated render: what to render, how, and under which cache key.
#[derive(Debug, Clone)]
pub struct RenderPlan {
    /// The source with line endings normalised.
    pub source: Arc<[u8]>,
    /// The pipeline request.
    pub request: RenderRequest,
    /// The cache key.
    pub key: CacheKey,
    /// Render afresh, ignoring the cache.
    pub no_cache: bool,
}

/// Reads a language name (the pipeline's [`parse_language`](crate::pipeline::options::parse_language)).
pub fn parse_language(name: Option<&str>) -> Result<Option<Language>, ServiceError> {
    Ok(crate::pipeline::options::parse_language(name)?)
}

/// Reads a format: a name or an extension of the registry's
/// (`crate::export::Format::parse`), case-insensitively; absent, the default.
pub fn parse_format(name: Option<&str>) -> Result<Format, ServiceError> {
    Ok(crate::pipeline::options::parse_format(name)?)
}

/// Reads the `png` fields; they need `format=png`.
pub fn preview_options(format: Format, size: Option<u32>, view: Option<&str>, background: Option<&str>) -> Result<PreviewOptions, ServiceError> {
    Ok(crate::pipeline::options::preview_options(format, size, view, background)?)
}

impl RenderBody {
    /// Validates the request against the server's `ceiling` (the one
    /// validator, [`RenderOptions::plan`]) and computes its cache key.
    pub fn plan(self, ceiling: &Limits, no_cache: bool) -> Result<RenderPlan, ServiceError> {
        let mut request = self.options.plan(ceiling)?;
        request.files = decode_files(self.files)?;
        let source: Arc<[u8]> = normalize_source(self.source.as_bytes()).into();
        let key = cache_key(&source, &request);
        Ok(RenderPlan { source, request, key, no_cache })
    }
}

/// The body a models-route URL asks for: `source` in `language` (a library
/// grammar's), written as `ext`, with the options its query names
/// (`query_pairs`, in order; a later one wins). Which options a query may
/// name, and how each is read from text, comes from the declaration: the
/// fields with [`Doors::QUERY`](crate::pipeline::options::Doors::QUERY),
/// and `p.NAME` for a grammar parameter. The picture's options apply to
/// the picture formats (the registry's `OptionGroup::Preview`: `png`) and are ignored for the other extensions (checked all the same),
/// as `checksum` applies to `scene` (`OptionGroup::Scene`) and is ignored for the others,
/// so one query string serves every format of a model (docs/service.md).
pub fn query_body(source: &str, language: Language, ext: &str, query_pairs: &[(String, String)]) -> Result<RenderBody, ServiceError> {
    use crate::pipeline::options::Doors;
    let mut fields = Map::new();
    let mut params = Map::new();
    let fields_of_query = || RenderOptions::fields().iter().filter(|f| f.doors.has(Doors::QUERY) && f.name != "params");
    for (k, v) in query_pairs {
        let bad = |what: &str| ServiceError::BadRequest(format!("query `{k}={v}`: {what}"));
        if let Some(p) = k.strip_prefix("p.").filter(|p| !p.is_empty()) {
            params.insert(p.to_string(), Value::from(v.as_str()));
            continue;
        }
        let Some(field) = fields_of_query().find(|f| f.name == k) else {
            let known: Vec<&str> = fields_of_query().map(|f| f.name).collect();
            return Err(bad(&format!("unknown query parameter ({}, p.<name>)", known.join(", "))));
        };
        let value = field.kind.read_text(v).map_err(|e| bad(&format!("{k} {e}")))?;
        fields.insert(k.clone(), value);
    }
    fields.insert("language".into(), Value::from(language.name()));
    fields.insert("format".into(), Value::from(ext));
    fields.insert("params".into(), Value::Object(params));
    let mut options = RenderOptions::deserialize(Value::Object(fields)).map_err(|e| ServiceError::BadRequest(format!("query: {e}")))?;
    let format = parse_format(Some(ext))?;
    if format.info().options != OptionGroup::Preview {
        let (size, view, background) = (options.size.take(), options.view.take(), options.background.take());
        let picture = Format::picture().unwrap_or(format);
        preview_options(picture, size, view.as_deref(), background.as_deref())?;
    }
    // `checksum` likewise applies to `scene` alone and is ignored for the
    // other extensions (checked as a boolean all the same, by the read above).
    if format.info().options != OptionGroup::Scene {
        options.checksum = None;
    }
    Ok(RenderBody { source: source.to_string(), files: BTreeMap::new(), options })
}

/// Reads a JSON body into `T`, with serde's message (and position) on failure.
pub(crate) fn from_json<T: serde::de::DeserializeOwned>(body: &[u8]) -> Result<T, ServiceError> {
    serde_json::from_slice(body).map_err(|e| ServiceError::BadRequest(format!("malformed JSON request: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rulemesh_core::geom::DEFAULT_DETAIL;
    use crate::preview::View;

    #[test]
    fn defaults_and_clamping() {
        let body: RenderBody = from_json(br#"{"source":"startshape A","limits":{"max_primitives":999999999999}}"#).expect("parses");
        let plan = body.plan(&Limits { max_primitives: 1000, ..Limits::ceiling() }, false).expect("valid");
        assert_eq!(plan.request.limits.max_primitives, 1000);
        assert_eq!(plan.request.format, Format::Glb);
        assert_eq!(plan.request.detail, DEFAULT_DETAIL);
    }

    #[test]
    fn bad_fields_are_bad_requests() {
        for bad in [
            r#"{"source":"x","format":"nope"}"#,
            r#"{"source":"x","language":"nope"}"#,
            r#"{"source":"x","on_limit":"maybe"}"#,
            r#"{"source":"x","layout":"spread"}"#,
            r#"{"source":"x","format":"png","size":8}"#,
            r#"{"source":"x","format":"png","size":4096}"#,
            r#"{"source":"x","format":"png","view":"side"}"#,
            r#"{"source":"x","format":"png","background":"red"}"#,
            r#"{"source":"x","format":"glb","size":64}"#,
        ] {
            let body: RenderBody = from_json(bad.as_bytes()).expect("json ok");
            assert!(matches!(body.plan(&Limits::ceiling(), false), Err(ServiceError::BadRequest(_))), "{bad}");
        }
        for bad in [
            r#"{"source":1}"#,
            r#"{"src":"x"}"#,
            r#"{"source":"x","seed":-1}"#,
            r#"{"source":"x","seed":1.5}"#,
            r#"{"source":"x","seed":"-1"}"#,
            r#"{"source":"x","seed":"18446744073709551616"}"#,
            r#"{"source":"x","seed":"0x10"}"#,
            "{",
            r#"{"source":"x","limits":{"max_foo":1}}"#,
        ] {
            assert!(matches!(from_json::<RenderBody>(bad.as_bytes()), Err(ServiceError::BadRequest(_))), "{bad}");
        }
    }

    #[test]
    fn seeds_are_64_bit_as_numbers_or_decimal_text() {
        let seed = |json: &str| from_json::<RenderBody>(json.as_bytes()).expect("parses").options.seed;
        assert_eq!(seed(r#"{"source":"x","seed":9223372036854775809}"#), Some((1 << 63) + 1));
        assert_eq!(seed(r#"{"source":"x","seed":"9223372036854775809"}"#), Some((1 << 63) + 1));
        assert_eq!(seed(r#"{"source":"x","seed":"18446744073709551615"}"#), Some(u64::MAX));
        assert_eq!(seed(r#"{"source":"x","seed":null}"#), None);
        assert_eq!(seed(r#"{"source":"x"}"#), None);
    }

    #[test]
    fn png_options_are_read() {
        let body: RenderBody = from_json(br##"{"source":"x","format":"png","size":64,"view":"iso","background":"#ff8000"}"##).expect("json");
        let plan = body.plan(&Limits::ceiling(), false).expect("valid");
        assert_eq!(plan.request.format, Format::Png);
        assert_eq!(plan.request.export_options.preview, PreviewOptions { size: 64, view: View::Iso, background: Some([255, 128, 0]) });
        let plain: RenderBody = from_json(br#"{"source":"x","format":"png"}"#).expect("json");
        assert_eq!(plain.plan(&Limits::ceiling(), false).expect("valid").request.export_options.preview, PreviewOptions::default());
    }

    #[test]
    fn crlf_and_lf_share_a_key() {
        let a: RenderBody = from_json(br#"{"source":"startshape A\r\nrule A { BOX {} }\r\n"}"#).expect("json");
        let b: RenderBody = from_json(br#"{"source":"startshape A\nrule A { BOX {} }\n"}"#).expect("json");
        assert_eq!(a.plan(&Limits::ceiling(), false).expect("a").key, b.plan(&Limits::ceiling(), false).expect("b").key);
    }
}

/// The body's `files` as bytes: text as UTF-8, `base64:…` decoded (a
/// value that is not valid base64 after the prefix is text). Names are only
/// keys the front end looks up (nothing is read from disk), so any is kept.
pub(crate) fn decode_files(files: BTreeMap<String, String>) -> Result<BTreeMap<String, Vec<u8>>, ServiceError> {
    use base64::Engine as _;
    Ok(files
        .into_iter()
        .map(|(name, text)| {
            let decoded = text.strip_prefix("base64:").and_then(|b| base64::engine::general_purpose::STANDARD.decode(b.trim()).ok());
            (name, decoded.unwrap_or_else(|| text.into_bytes()))
        })
        .collect())
}
