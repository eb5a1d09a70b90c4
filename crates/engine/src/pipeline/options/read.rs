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
///
/// A visitor rather than an untagged enum: serde's untagged enums buffer
/// the value and build an error for every variant tried first, and the
/// URL query's seed (text) came third, so every `GET /v1/models` built two
/// errors it threw away (issue 33's cached path).
pub(crate) fn seed_number_or_text<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<u64>, D::Error> {
    d.deserialize_option(OptionalSeed)
}

const SEED_SHAPE: &str = "seed must be a whole number from 0 to 2^64 - 1, as a number or a decimal string";

/// `null` or absent reads as no seed; anything else as [`Seed`].
struct OptionalSeed;

impl<'de> serde::de::Visitor<'de> for OptionalSeed {
    type Value = Option<u64>;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(SEED_SHAPE)
    }
    fn visit_none<E: serde::de::Error>(self) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_unit<E: serde::de::Error>(self) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_some<D: serde::Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(Seed).map(Some)
    }
}

/// One seed: a whole number, an integral float (`5.0`: JSON Schema's
/// `integer` admits it) or up to 20 decimal digits.
struct Seed;

impl<'de> serde::de::Visitor<'de> for Seed {
    type Value = u64;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(SEED_SHAPE)
    }
    fn visit_u64<E: serde::de::Error>(self, n: u64) -> Result<u64, E> {
        Ok(n)
    }
    fn visit_i64<E: serde::de::Error>(self, n: i64) -> Result<u64, E> {
        u64::try_from(n).or_else(|_| self.visit_f64(n as f64))
    }
    fn visit_f64<E: serde::de::Error>(self, f: f64) -> Result<u64, E> {
        integral_u64(f).ok_or_else(|| E::custom(format!("seed {f} is not a whole number from 0 to 2^64 - 1")))
    }
    fn visit_str<E: serde::de::Error>(self, t: &str) -> Result<u64, E> {
        if !t.is_empty() && t.len() <= 20 && t.bytes().all(|b| b.is_ascii_digit()) {
            t.parse().map_err(|_| E::custom(format!("seed `{t}` is beyond 2^64 - 1")))
        } else {
            Err(E::custom(format!("seed `{t}` is not a whole number from 0 to 2^64 - 1")))
        }
    }
    fn visit_bool<E: serde::de::Error>(self, _: bool) -> Result<u64, E> {
        Err(E::custom(SEED_SHAPE))
    }
    fn visit_unit<E: serde::de::Error>(self) -> Result<u64, E> {
        Err(E::custom(SEED_SHAPE))
    }
    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, _: A) -> Result<u64, A::Error> {
        Err(serde::de::Error::custom(SEED_SHAPE))
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, _: A) -> Result<u64, A::Error> {
        Err(serde::de::Error::custom(SEED_SHAPE))
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

#[cfg(test)]
mod tests {
    #[derive(serde::Deserialize)]
    struct S {
        #[serde(default, deserialize_with = "super::seed_number_or_text")]
        seed: Option<u64>,
    }

    fn read(json: &str) -> Result<Option<u64>, String> {
        serde_json::from_str::<S>(json).map(|s| s.seed).map_err(|e| e.to_string())
    }

    /// Every shape JSON Schema's `integer` or a decimal string allows reads,
    /// and every other shape is refused with a message naming the seed.
    #[test]
    fn seeds_read_as_numbers_integral_floats_or_decimal_text() {
        assert_eq!(read("{}"), Ok(None));
        assert_eq!(read(r#"{"seed": null}"#), Ok(None));
        assert_eq!(read(r#"{"seed": 5}"#), Ok(Some(5)));
        assert_eq!(read(r#"{"seed": 5.0}"#), Ok(Some(5)));
        assert_eq!(read(r#"{"seed": "5"}"#), Ok(Some(5)));
        assert_eq!(read(r#"{"seed": "18446744073709551615"}"#), Ok(Some(u64::MAX)));
        assert_eq!(read(r#"{"seed": 18446744073709551615}"#), Ok(Some(u64::MAX)));
        let refused = |json: &str, says: &str| {
            let e = read(json).expect_err(json);
            assert!(e.contains(says), "{json}: {e}");
        };
        refused(r#"{"seed": "18446744073709551616"}"#, "beyond 2^64 - 1");
        refused(r#"{"seed": -1}"#, "seed -1 is not a whole number");
        refused(r#"{"seed": 1.5}"#, "seed 1.5 is not a whole number");
        refused(r#"{"seed": 18446744073709551616}"#, "is not a whole number from 0 to 2^64 - 1");
        refused(r#"{"seed": ""}"#, "seed `` is not a whole number");
        refused(r#"{"seed": "-1"}"#, "seed `-1` is not a whole number");
        for other in ["true", "[]", "[1]", "{}"] {
            refused(&format!(r#"{{"seed": {other}}}"#), "seed must be a whole number");
        }
    }
}
