//! The JSON Schema (draft 2020-12) of the render options, built from the
//! declaration ([`super::RenderOptions::fields`]): each field's schema as
//! declared beside it, and a `dependentSchemas` rule for each field that
//! needs another (`size_mm` needs `print: true`, `size` needs `format: png`).
//! The service serves it inside each grammar's request schema and tightens
//! its OpenAPI document with it; the validator ([`super::RenderOptions::plan`])
//! accepts exactly what it allows.

use super::OptionField;
use serde_json::{json, Map, Value};

/// The schema of a seed: a whole number from 0 to 2^64 − 1, or the same as
/// decimal digits.
pub(crate) fn seed_schema() -> Value {
    json!({
        "description": "Random seed: any 64-bit unsigned value, as a number or (beyond 2^53, where JSON numbers lose precision) a decimal string",
        "anyOf": [
            { "type": "integer", "minimum": 0, "maximum": u64::MAX },
            { "type": "string", "pattern": seed_text_pattern() }
        ]
    })
}

/// The decimal strings a seed may be sent as: 1 to 20 ASCII digits whose
/// value is at most 2^64 − 1 (leading zeros allowed), exactly what
/// [`super::read::seed_number_or_text`] accepts. Written out digit by digit
/// from `u64::MAX`, since a JSON Schema cannot compare a string's value.
pub fn seed_text_pattern() -> String {
    let max = u64::MAX.to_string();
    let digits: Vec<u32> = max.chars().filter_map(|c| c.to_digit(10)).collect();
    // Shorter strings are always in range; a full-length one is when it
    // matches the maximum up to some digit and is smaller there.
    let mut branches = vec![format!("[0-9]{{1,{}}}", digits.len() - 1)];
    for (i, &d) in digits.iter().enumerate() {
        if d > 0 {
            let rest = digits.len() - i - 1;
            let tail = if rest > 0 { format!("[0-9]{{{rest}}}") } else { String::new() };
            branches.push(format!("{}[0-{}]{tail}", &max[..i], d - 1));
        }
    }
    branches.push(max);
    format!("^({})$", branches.join("|"))
}

/// A group's schema (the limits): an object of its fields' schemas, nothing else.
pub(crate) fn group_schema(fields: &[OptionField], description: &str) -> Value {
    let properties: Map<String, Value> = fields.iter().map(|f| (f.name.to_string(), f.schema.clone())).collect();
    json!({ "type": "object", "additionalProperties": false, "description": description, "properties": properties })
}

/// The options' schema: an object of every field's schema (no other
/// property), and the rules tying a field to another it needs.
pub fn options_schema() -> Value {
    let fields = super::RenderOptions::fields();
    let properties: Map<String, Value> = fields.iter().map(|f| (f.name.to_string(), f.schema.clone())).collect();
    let rules: Map<String, Value> = fields
        .iter()
        .filter_map(|f| f.needs.as_ref().map(|(other, value)| (f.name.to_string(), json!({ "properties": { *other: { "const": value } }, "required": [other] }))))
        .collect();
    json!({
        "type": "object",
        "additionalProperties": false,
        "properties": properties,
        "dependentSchemas": rules
    })
}
