//! The declaration's own consistency: names and flags unique, every rule
//! naming a declared option, every example read by the one validator, and
//! the text doors reading what the body reads.

use super::*;
use crate::core::Limits;
use serde_json::{Map, Value};

fn all() -> Vec<&'static OptionField> {
    let mut out = Vec::new();
    for f in RenderOptions::fields() {
        out.push(f);
        out.extend(f.group().unwrap_or(&[]).iter());
    }
    out
}

#[test]
fn names_and_flags_are_unique_and_rules_name_declared_options() {
    let fields = all();
    let mut names: Vec<&str> = fields.iter().map(|f| f.name).collect();
    let mut flags: Vec<String> = fields.iter().filter(|f| f.group().is_none()).map(|f| f.flag()).collect();
    let (n, k) = (names.len(), flags.len());
    names.sort_unstable();
    names.dedup();
    flags.sort_unstable();
    flags.dedup();
    assert_eq!((names.len(), flags.len()), (n, k), "a name or a flag is declared twice");
    for f in &fields {
        if let Some((other, value)) = &f.needs {
            let target = RenderOptions::fields().iter().find(|g| g.name == *other).unwrap_or_else(|| panic!("{} needs an undeclared `{other}`", f.name));
            if let Some(values) = target.schema.get("enum").and_then(Value::as_array) {
                assert!(values.contains(value), "{} needs {other}={value}, which its schema refuses", f.name);
            }
        }
        if let (Some(values), Some(default)) = (f.schema.get("enum").and_then(Value::as_array), f.schema.get("default")) {
            assert!(values.contains(default), "{}: default {default} is not one of its values", f.name);
        }
    }
}

#[test]
fn every_example_is_planned_in_its_context_and_read_alike_from_text() {
    for f in all().into_iter().filter(|f| f.group().is_none()) {
        let in_group = RenderOptions::fields().iter().find(|g| g.group().is_some_and(|inner| inner.iter().any(|i| std::ptr::eq(i, f))));
        let mut body: Map<String, Value> = f.context.as_object().cloned().unwrap_or_default();
        let place = |body: &mut Map<String, Value>, v: Value| match in_group {
            Some(g) => body.insert(g.name.into(), serde_json::json!({ f.name: v })),
            None => body.insert(f.name.into(), v),
        };
        place(&mut body, f.example.clone());
        let from_body: RenderOptions = serde_json::from_value(Value::Object(body.clone())).unwrap_or_else(|e| panic!("{}: {e}", f.name));
        from_body.clone().plan(&Limits::ceiling()).unwrap_or_else(|e| panic!("{}: example refused: {e}", f.name));
        // A text door writes the example as text; it must read back the same.
        let text = match &f.example {
            Value::String(s) => s.clone(),
            Value::Array(items) => items.iter().map(Value::to_string).collect::<Vec<_>>().join("x"),
            Value::Object(_) => continue,
            other => other.to_string(),
        };
        let read = f.kind.read_text(&text).unwrap_or_else(|e| panic!("{}: `{text}` {e}", f.name));
        place(&mut body, read);
        let from_text: RenderOptions = serde_json::from_value(Value::Object(body)).unwrap_or_else(|e| panic!("{}: {e}", f.name));
        assert_eq!(from_text, from_body, "{}: text `{text}` reads differently", f.name);
    }
}

#[test]
fn the_validator_refuses_what_the_schema_refuses() {
    let plan = |json: Value| serde_json::from_value::<RenderOptions>(json).map_err(|e| e.to_string()).and_then(|o| o.plan(&Limits::ceiling()).map_err(|e| e.to_string()));
    for bad in [
        serde_json::json!({ "size_mm": 10 }),
        serde_json::json!({ "size": 64 }),
        serde_json::json!({ "format": "png", "size": 8 }),
        serde_json::json!({ "position_bits": 9, "format": "strips" }),
        serde_json::json!({ "detail": 0 }),
        serde_json::json!({ "seed": "0x10" }),
        serde_json::json!({ "limits": [1, 2] }),
        serde_json::json!({ "colour": "red" }),
    ] {
        assert!(plan(bad.clone()).is_err(), "{bad}");
    }
    assert!(plan(serde_json::json!({ "detail": 8.0, "seed": "18446744073709551615", "limits": { "max_depth": 3.0 } })).is_ok());
}
