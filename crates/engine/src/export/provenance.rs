//! What made a model, written into the model itself: engine version,
//! language, seed, parameters and the model key. A glb, 3MF, PNG or scene
//! file found on its own (in an app bundle, a print order, a bug report) can
//! then be made again byte for byte, or looked up in the cache, without the
//! request that made it. `docs/service.md` ("Reproducible outputs") lists
//! where each format carries it.

use crate::core::ParamValue;
use crate::lang::Language;
use std::collections::BTreeMap;

/// The provenance of one rendered model. Everything in it is part of the
/// request or derived from it deterministically, so recording it keeps
/// outputs byte-identical across runs and doors.
#[derive(Debug, Clone, PartialEq)]
pub struct Provenance {
    /// The language the source was read as.
    pub language: Language,
    /// The seed the model was made with (the request's, else the grammar's
    /// own, else 0): sent as the request's seed, it makes the same model.
    pub seed: u64,
    /// The parameters the request set (defaults it left alone are not
    /// listed: the source holds them).
    pub params: BTreeMap<String, ParamValue>,
    /// The model key, lowercase hex (BLAKE3, 64 digits): the cache key of
    /// the request without its limits (`pipeline::key::model_key`), which
    /// names the model's content the same way whichever door made it.
    pub model_key: String,
}

impl Provenance {
    /// The engine that wrote the model, as `rulemesh <version>`.
    pub fn engine() -> String {
        format!("rulemesh {}", crate::ENGINE_VERSION)
    }

    /// The parameters as one compact JSON object (keys sorted), in ASCII:
    /// every character beyond it is a `\uXXXX` escape, so the text fits
    /// PNG's Latin-1 `tEXt` and STL-era readers alike.
    pub(crate) fn params_json(&self) -> String {
        let text = self.params_value().to_string();
        let mut out = String::with_capacity(text.len());
        for c in text.chars() {
            if c.is_ascii() {
                out.push(c);
            } else {
                let mut units = [0u16; 2];
                for u in c.encode_utf16(&mut units) {
                    out.push_str(&format!("\\u{u:04x}"));
                }
            }
        }
        out
    }

    /// The provenance as a JSON object. The seed is a decimal string:
    /// JSON numbers lose precision above 2⁵³ in most readers, and seeds are
    /// full 64-bit values.
    pub fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "engine": Self::engine(),
            "language": self.language.name(),
            "seed": self.seed.to_string(),
            "params": self.params_value(),
            "model_key": self.model_key,
        })
    }

    /// The parameters as a JSON object, keys sorted (the map is ordered).
    fn params_value(&self) -> serde_json::Value {
        serde_json::Value::Object(self.params.iter().map(|(k, v)| (k.clone(), param_json(v))).collect())
    }

    /// The provenance as (name, text) pairs, in a fixed order, for formats
    /// with flat key–value metadata (PNG `tEXt`, 3MF `<metadata>`). Names
    /// are prefixed `rulemesh:`.
    pub fn pairs(&self) -> Vec<(&'static str, String)> {
        vec![
            ("rulemesh:engine", Self::engine()),
            ("rulemesh:language", self.language.name().to_string()),
            ("rulemesh:seed", self.seed.to_string()),
            ("rulemesh:params", self.params_json()),
            ("rulemesh:model-key", self.model_key.clone()),
        ]
    }
}

/// [`Provenance::json`]'s fields in its key order (sorted, as its map
/// writes them), borrowed: the same text without building a `Value`.
#[derive(serde::Serialize)]
struct Fields<'a> {
    engine: &'a str,
    language: &'a str,
    model_key: &'a str,
    params: Params<'a>,
    seed: String,
}

/// The parameters as [`Provenance::params_value`] writes them.
struct Params<'a>(&'a BTreeMap<String, ParamValue>);

impl serde::Serialize for Params<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in self.0 {
            match v {
                ParamValue::Number(n) if n.is_finite() => map.serialize_entry(k, n)?,
                ParamValue::Number(_) => map.serialize_entry(k, &())?,
                ParamValue::Bool(b) => map.serialize_entry(k, b)?,
                ParamValue::Text(t) => map.serialize_entry(k, t)?,
            }
        }
        map.end()
    }
}

impl Provenance {
    /// [`Provenance::json`] as raw JSON, the same text, written directly:
    /// building the `Value` and parsing its text back into a `RawValue`
    /// were a few per cent of a fresh icon's glTF (issue 33).
    pub(crate) fn raw_json(&self) -> Result<Box<serde_json::value::RawValue>, serde_json::Error> {
        let engine = Self::engine();
        let fields = Fields { engine: &engine, language: self.language.name(), model_key: &self.model_key, params: Params(&self.params), seed: self.seed.to_string() };
        serde_json::value::to_raw_value(&fields)
    }
}

/// One parameter value as JSON (a non-finite number, which requests cannot
/// carry, would be `null`).
fn param_json(v: &ParamValue) -> serde_json::Value {
    match v {
        ParamValue::Number(n) => serde_json::Number::from_f64(*n).map_or(serde_json::Value::Null, serde_json::Value::Number),
        ParamValue::Bool(b) => serde_json::Value::Bool(*b),
        ParamValue::Text(t) => serde_json::Value::String(t.clone()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Provenance {
        Provenance {
            language: Language::Mdg,
            seed: (1 << 63) + 1,
            params: [("b".to_string(), ParamValue::Bool(true)), ("a".to_string(), ParamValue::Number(0.5)), ("c".to_string(), ParamValue::Text("x\"y".into()))].into(),
            model_key: "ab".repeat(32),
        }
    }

    #[test]
    fn the_seed_is_exact_and_params_are_sorted() {
        let p = sample();
        assert_eq!(p.json()["seed"], "9223372036854775809");
        assert_eq!(p.params_json(), r#"{"a":0.5,"b":true,"c":"x\"y"}"#);
        let names: Vec<&str> = p.pairs().iter().map(|(n, _)| *n).collect();
        assert_eq!(names, ["rulemesh:engine", "rulemesh:language", "rulemesh:seed", "rulemesh:params", "rulemesh:model-key"]);
        assert_eq!(p.pairs()[2].1, "9223372036854775809");
        // Beyond ASCII, escapes that read back to the same text.
        let q = Provenance { params: [("t".to_string(), ParamValue::Text("é😀".into()))].into(), ..sample() };
        assert_eq!(q.params_json(), r#"{"t":"\u00e9\ud83d\ude00"}"#);
        let back: serde_json::Value = serde_json::from_str(&q.params_json()).expect("json");
        assert_eq!(back["t"], "é😀");
    }

    #[test]
    fn the_raw_json_is_the_values_text() {
        let many = [("n".to_string(), ParamValue::Number(3.0)), ("inf".to_string(), ParamValue::Number(f64::INFINITY)), ("t".to_string(), ParamValue::Text("é\n\"😀".into())), ("z".to_string(), ParamValue::Number(-1e-300))];
        for p in [sample(), Provenance { params: many.into(), ..sample() }, Provenance { params: BTreeMap::new(), seed: 0, ..sample() }] {
            assert_eq!(p.raw_json().expect("raw").get(), serde_json::to_string(&p.json()).expect("text"));
        }
    }
}
