//! Binding request parameters to a program's `@param` declarations.

use crate::model::EvalError;
use crate::ir::{ParamKind, Program};
use std::collections::BTreeMap;

pub use crate::core::param::ParamValue;

/// Returns the value of every declared parameter, in declaration order: the
/// request's value where given, else the default. Unknown names, values of
/// the wrong type and values outside the declared range are errors.
pub fn bind_params(program: &Program, given: &BTreeMap<String, ParamValue>) -> Result<Vec<f64>, EvalError> {
    for name in given.keys() {
        if !program.params.iter().any(|p| &p.name == name) {
            let declared: Vec<&str> = program.params.iter().map(|p| p.name.as_str()).collect();
            return Err(EvalError::UnknownParam { name: name.clone(), declared: declared.join(", ") });
        }
    }
    program
        .params
        .iter()
        .map(|p| {
            let Some(raw) = given.get(&p.name) else { return Ok(p.default) };
            let bad = |message: String| EvalError::BadParam { name: p.name.clone(), message };
            // A named choice (`@presets`) stands for its index.
            let named = match raw {
                ParamValue::Text(t) => p.choices.iter().position(|c| c == t.trim()).map(|i| i as f64),
                _ => None,
            };
            let v = named
                .or_else(|| raw.as_number())
                .filter(|v| v.is_finite())
                .ok_or_else(|| match p.choices.is_empty() {
                    true => bad(format!("{raw:?} is not a finite number")),
                    false => bad(format!("{raw:?} is not one of {} (or their index)", p.choices.join(", "))),
                })?;
            match p.kind {
                ParamKind::Int if v.fract() != 0.0 => return Err(bad(format!("{v} is not a whole number"))),
                ParamKind::Bool if v != 0.0 && v != 1.0 => return Err(bad(format!("{v} is not a boolean"))),
                _ => {}
            }
            if let Some((lo, hi)) = p.range {
                if v < lo || v > hi {
                    return Err(bad(format!("{v} is outside [{lo}, {hi}]")));
                }
            }
            Ok(v)
        })
        .collect()
}
