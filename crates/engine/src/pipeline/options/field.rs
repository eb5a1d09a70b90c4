//! What the one declaration of the render options says about each field,
//! and the macro that turns the declaration into the struct and its field
//! table.
//!
//! The doors read this table instead of keeping lists: the CLI makes one
//! flag per field, the models route reads its URL query through it, the
//! JSON Schema and the OpenAPI document are built from it, and
//! `tests/it/options_fields.rs` walks it to check that every field reaches
//! every door it names and the cache key. The pattern is the "X macro" of C
//! (a list declared once and expanded wherever it is needed), done with
//! `macro_rules!` because a derive crate would be a proc-macro dependency
//! for what one table and a struct need.

use serde_json::{Map, Value};

/// The doors a field is offered through, as a small bit set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Doors(u8);

impl Doors {
    /// `rulemesh render` has a flag for it (a group's fields are flags of their own).
    pub const CLI: Doors = Doors(1);
    /// The JSON body of `POST /v1/render` (and of a batch) has it.
    pub const BODY: Doors = Doors(2);
    /// `GET /v1/models/{file}` reads it from the URL query.
    pub const QUERY: Doors = Doors(4);
    /// gRPC's `RenderRequest` (or, in a group, its `Limits` message) has a field of this name.
    pub const GRPC: Doors = Doors(8);
    /// Every door but the URL query.
    pub(crate) const NOT_QUERY: Doors = Doors(1 | 2 | 8);
    /// Every door.
    pub const ALL: Doors = Doors(1 | 2 | 4 | 8);

    /// Whether every door of `other` is in `self`.
    pub const fn has(self, other: Doors) -> bool {
        self.0 & other.0 == other.0
    }
}

/// How a field's value is written, which is what the text doors (a command
/// line, a URL query) need to turn text into the JSON value the body would
/// carry: the one deserializer then reads every door alike.
#[derive(Debug, Clone, Copy)]
pub enum Kind {
    /// `true` or `false` (on the command line, a bare flag).
    Bool,
    /// A whole number ≥ 0.
    Whole,
    /// A finite number.
    Number,
    /// A word or text (the schema says which).
    Text,
    /// A seed: a whole number from 0 to 2^64 − 1, kept as decimal text so
    /// no door loses precision beyond 2^53.
    Seed,
    /// Three numbers, `XxYxZ` (or `X,Y,Z`) as text.
    Volume,
    /// Grammar parameters, `name → value` (`--param NAME=VALUE`, `p.NAME=VALUE`).
    Params,
    /// A nested group of options (the limits), declared the same way.
    Group(fn() -> &'static [OptionField]),
}

impl Kind {
    /// The JSON value a text door's `text` stands for (a flag's or a URL
    /// query parameter's value), or why it cannot be one.
    pub fn read_text(self, text: &str) -> Result<Value, String> {
        let t = text.trim();
        match self {
            Kind::Bool => t.parse::<bool>().map(Value::Bool).map_err(|_| "must be true or false".into()),
            Kind::Whole => t.parse::<u64>().map(Value::from).map_err(|_| "must be a whole number ≥ 0".into()),
            Kind::Number => match t.parse::<f64>() {
                Ok(n) if n.is_finite() => Ok(Value::from(n)),
                _ => Err("must be a number".into()),
            },
            Kind::Text => Ok(Value::from(text)),
            Kind::Seed => match t.parse::<u64>() {
                Ok(_) => Ok(Value::from(t)),
                Err(_) => Err("must be a whole number from 0 to 2^64 - 1".into()),
            },
            Kind::Volume => crate::print::profile::parse_build_volume(t).map(Value::from).map_err(|e| e.to_string()),
            Kind::Params | Kind::Group(_) => Err("is not given as one value".into()),
        }
    }
}

/// Whether a field is part of the cache key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    /// Changing the field alone changes the key (where its `context` holds).
    Changes,
    /// The field never changes the key, for the reason given.
    Unchanged(&'static str),
}

/// One field of the declaration, as the doors and the tests read it.
#[derive(Debug, Clone)]
pub struct OptionField {
    /// The field's name: its JSON key, its gRPC field name and (with `-`
    /// for `_`) its command-line flag unless `cli` says otherwise.
    pub name: &'static str,
    /// What it does, one paragraph: the CLI's help and the schema's description.
    pub doc: String,
    /// The doors it is offered through.
    pub doors: Doors,
    /// The long flag's name, when it is not `name` with `-` for `_`.
    pub cli: Option<&'static str>,
    /// On the command line, a bare flag that sets this value (`--weld` sets
    /// `true`, `--fit-unit-box` sets `"unit"`) instead of a flag with a value.
    pub cli_flag: Option<Value>,
    /// How its value is written.
    pub kind: Kind,
    /// The JSON Schema of its values: exactly what the validator accepts.
    pub schema: Value,
    /// Another option this one needs, and the value it must have (the
    /// schema's `dependentSchemas`, the validator's refusal).
    pub needs: Option<(&'static str, Value)>,
    /// A valid value other than the default, for examples and tests.
    pub example: Value,
    /// The other options under which `example` matters (`format: strips`
    /// for a strips option): a request is only different where it applies.
    pub context: Value,
    /// Whether it is part of the cache key.
    pub key: Key,
}

impl OptionField {
    /// A field called `name` with every attribute at its plainest: the
    /// declaration's entries say what differs.
    pub fn blank(name: &'static str, doc: String) -> OptionField {
        OptionField {
            name,
            doc,
            doors: Doors::ALL,
            cli: None,
            cli_flag: None,
            kind: Kind::Text,
            schema: Value::Object(Map::new()),
            needs: None,
            example: Value::Null,
            context: Value::Object(Map::new()),
            key: Key::Changes,
        }
    }

    /// The command-line flag's long name.
    pub fn flag(&self) -> String {
        self.cli.map_or_else(|| self.name.replace('_', "-"), str::to_string)
    }

    /// The fields of a group (the limits), if this is one.
    pub fn group(&self) -> Option<&'static [OptionField]> {
        match self.kind {
            Kind::Group(fields) => Some(fields()),
            _ => None,
        }
    }
}

/// A doc comment's lines as one paragraph.
pub(crate) fn paragraph(lines: &[&str]) -> String {
    lines.iter().map(|l| l.trim()).filter(|l| !l.is_empty()).collect::<Vec<_>>().join(" ")
}

/// Declares an options struct and its field table in one list: each field
/// is written once, with its doc comment, serde attributes, type and an
/// [`OptionField`] entry (`doors`, `kind`, `schema`, `example`, … as
/// `name: expression` pairs; what is left out takes [`OptionField::blank`]'s
/// value). Expands to the struct (every field `pub`) and
/// `fn fields() -> &'static [OptionField]` in the struct's order.
macro_rules! declare_options {
    (
        $(#[$smeta:meta])*
        pub struct $name:ident {
            $(
                $(#[doc = $doc:literal])*
                $(#[serde($($serde:tt)*)])*
                $field:ident : $ty:ty => { $($attr:ident : $value:expr),* $(,)? }
            ),* $(,)?
        }
    ) => {
        $(#[$smeta])*
        pub struct $name {
            $(
                $(#[doc = $doc])*
                $(#[serde($($serde)*)])*
                pub $field: $ty,
            )*
        }

        impl $name {
            /// This struct's fields as the doors read them, in declaration order.
            pub fn fields() -> &'static [$crate::pipeline::options::OptionField] {
                static FIELDS: std::sync::OnceLock<Vec<$crate::pipeline::options::OptionField>> = std::sync::OnceLock::new();
                FIELDS.get_or_init(|| {
                    vec![$(
                        $crate::pipeline::options::OptionField {
                            $($attr: $value,)*
                            ..$crate::pipeline::options::OptionField::blank(
                                stringify!($field),
                                $crate::pipeline::options::field::paragraph(&[$($doc),*]),
                            )
                        }
                    ),*]
                })
            }
        }
    };
}

pub(crate) use declare_options;
