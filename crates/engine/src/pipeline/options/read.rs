//! Reading option values as JSON Schema describes them: whole numbers that
//! may arrive as `8.0`, seeds as numbers or decimal text, the limits only
//! as an object. Every door reads through these (the text doors turn their
//! text into JSON first, [`super::Kind::read_text`]), so the published
//! schema and what the server reads cannot differ by door.

use serde::Deserialize;

/// `f` as a `u64` when it is a whole number from 0 to 2^64 − 1 (`8.0`):
/// JSON Schema's `integer` admits such numbers, so the server reads them.
pub(crate) fn integral_u64(f: f64) -> Option<u64> {
    (f.fract() == 0.0 && (0.0..18_446_744_073_709_551_616.0).contains(&f)).then_some(f as u64)
}

/// Reads an optional whole number sent as a JSON integer or as a number
/// with no fraction (`8.0`): JSON Schema's `integer`, which the published
/// schemas use, admits both, so the server must too. Null reads as absent.
pub fn whole<'de, D, T>(d: D) -> Result<Option<T>, D::Error>
where
    D: serde::Deserializer<'de>,
    T: TryFrom<u64>,
{
    let Some(n) = Option::<serde_json::Number>::deserialize(d)? else { return Ok(None) };
    let value = n.as_u64().or_else(|| n.as_f64().and_then(integral_u64));
    match value.map(T::try_from) {
        Some(Ok(v)) => Ok(Some(v)),
        Some(Err(_)) => Err(serde::de::Error::custom(format!("{n} is out of range"))),
        None => Err(serde::de::Error::custom(format!("{n} is not a whole number ≥ 0"))),
    }
}

/// Reads `limits` as a JSON object only: serde would also read a struct
/// from an array of its fields in order, which the published schema (an
/// object) does not allow. Null reads as absent.
pub(crate) fn limits_object<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<super::LimitsOptions>, D::Error> {
    match Option::<serde_json::Map<String, serde_json::Value>>::deserialize(d)? {
        None => Ok(None),
        Some(map) => serde_json::from_value(serde_json::Value::Object(map)).map(Some).map_err(serde::de::Error::custom),
    }
}

/// Reads a seed given as a JSON number or a decimal string, refusing
/// negatives, fractions and values beyond 2^64 − 1 with a message.
pub(crate) fn seed_number_or_text<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<u64>, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Raw {
        Number(u64),
        // An integral float (`5.0`): JSON Schema's `integer` admits it.
        Float(f64),
        Text(String),
    }
    match Option::<Raw>::deserialize(d) {
        Ok(None) => Ok(None),
        Ok(Some(Raw::Number(n))) => Ok(Some(n)),
        Ok(Some(Raw::Float(f))) => integral_u64(f).map(Some).ok_or_else(|| serde::de::Error::custom(format!("seed {f} is not a whole number from 0 to 2^64 - 1"))),
        Ok(Some(Raw::Text(t))) if !t.is_empty() && t.len() <= 20 && t.bytes().all(|b| b.is_ascii_digit()) => {
            t.parse().map(Some).map_err(|_| serde::de::Error::custom(format!("seed `{t}` is beyond 2^64 - 1")))
        }
        Ok(Some(Raw::Text(t))) => Err(serde::de::Error::custom(format!("seed `{t}` is not a whole number from 0 to 2^64 - 1"))),
        Err(_) => Err(serde::de::Error::custom("seed must be a whole number from 0 to 2^64 - 1, as a number or a decimal string")),
    }
}

/// One seed of a list (the batch route's `seeds`), read like `seed`: a
/// JSON number or a decimal string, 0 to 2^64 − 1, never null.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SeedValue(pub u64);

impl<'de> Deserialize<'de> for SeedValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        seed_number_or_text(d)?.map(SeedValue).ok_or_else(|| serde::de::Error::custom("a seed in a list must not be null"))
    }
}
