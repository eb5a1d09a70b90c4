//! Parameter values as requests carry them (CLI `name=value`, query
//! strings, JSON bodies), before any grammar binds them.

/// A parameter value as a request gives it.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(untagged)]
pub enum ParamValue {
    /// A number (ints and floats).
    Number(f64),
    /// A boolean.
    Bool(bool),
    /// Text, parsed as a number or `true`/`false` (from CLI `name=value` and URL query strings).
    Text(String),
}

impl ParamValue {
    /// The value in one spelling whichever door it came through: text that
    /// reads as a finite number or as `true`/`false` becomes that number or
    /// boolean (the CLI, query strings and gRPC send text; JSON bodies send
    /// numbers), other text stays text. Outputs record parameters in this
    /// form, so the same request gives the same bytes from every door. (A
    /// `@presets` choice literally named like a number is recorded as that
    /// number: a documented corner, docs/service.md.)
    pub fn canonical(&self) -> ParamValue {
        match self {
            ParamValue::Text(s) => match s.trim() {
                "true" => ParamValue::Bool(true),
                "false" => ParamValue::Bool(false),
                t => t.parse::<f64>().ok().filter(|v| v.is_finite()).map_or_else(|| self.clone(), ParamValue::Number),
            },
            v => v.clone(),
        }
    }

    /// The value as a number: booleans are 0 and 1, text is parsed.
    pub fn as_number(&self) -> Option<f64> {
        match self {
            ParamValue::Number(v) => Some(*v),
            ParamValue::Bool(b) => Some(if *b { 1.0 } else { 0.0 }),
            ParamValue::Text(s) => match s.trim() {
                "true" => Some(1.0),
                "false" => Some(0.0),
                t => t.parse::<f64>().ok(),
            },
        }
    }
}
