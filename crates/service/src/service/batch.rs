//! Variations in one call (issue 20): a batch is one render request plus a
//! list of seeds or a parameter sweep, expanded into members that each go
//! through [`super::Engine::serve`] exactly as a single render does (same
//! cache key, same cache, same concurrency limit and budgets). Shared by the
//! HTTP route ([`super::http_batch`]) and gRPC `RenderBatch`; this module
//! knows nothing of either wire format.

use super::library;
use super::request::{from_json, RenderBody, SeedValue};
use super::{AppState, Served, ServiceError};
use crate::core::{Limits, ParamValue};
use crate::export::Format;
use futures_util::stream::{self, Stream, StreamExt};
use serde_json::{Map, Value};
use std::collections::BTreeMap;
use std::sync::Arc;
use tracing::Instrument;

/// The most members one batch may have. A batch holds one connection and
/// one API-key share for all its members, so an unbounded one could keep a
/// worker busy for as long as its client liked; 256 variations is more than
/// a picker shows at once and, at the default deadline, bounded in time.
pub(crate) const MAX_MEMBERS: usize = 256;

/// What varies across a batch's members.
#[derive(Debug, Clone, PartialEq)]
pub enum Variation {
    /// One member per seed, in this order.
    Seeds(Vec<u64>),
    /// One member per combination of these parameter values (the cartesian
    /// product, parameter names in sorted order, the last name varying fastest).
    Sweep(BTreeMap<String, Vec<ParamValue>>),
}

/// One member of a batch: its place and what it renders with.
#[derive(Debug, Clone, PartialEq)]
pub struct Member {
    /// Its 0-based position in the request's order.
    pub index: usize,
    /// The seed it asks for: its own in a seed list, the request's `seed` in
    /// a sweep (`None`: the grammar's own seed directive, else 0).
    pub seed: Option<u64>,
    /// Its parameters: the base request's, overridden by the sweep's values.
    pub params: BTreeMap<String, ParamValue>,
}

/// A member and how its render went.
#[derive(Debug, Clone)]
pub struct MemberOutcome {
    /// The member.
    pub member: Member,
    /// The model (and its format), or why this member alone failed.
    pub result: Result<(Served, Format), ServiceError>,
}

/// A validated batch: the shared request and its members.
#[derive(Debug, Clone)]
pub struct Batch {
    base: RenderBody,
    members: Vec<Member>,
}

impl Batch {
    /// A batch of `base` varied by `variation`, checked against the server's
    /// `ceiling`: every option all members share is validated here, so a
    /// malformed request fails whole (400) before anything is rendered;
    /// what remains can only fail one member at a time.
    pub fn new(base: RenderBody, variation: Variation, ceiling: &Limits) -> Result<Batch, ServiceError> {
        base.clone().plan(ceiling, false)?;
        let members = match variation {
            Variation::Seeds(seeds) => {
                if base.options.seed.is_some() {
                    return Err(ServiceError::BadRequest("a batch takes `seed` or `seeds`, not both".into()));
                }
                check_size(seeds.len())?;
                seeds.into_iter().enumerate().map(|(index, seed)| Member { index, seed: Some(seed), params: base.options.params.clone() }).collect()
            }
            Variation::Sweep(sweep) => sweep_members(&base, &sweep)?,
        };
        Ok(Batch { base, members })
    }

    /// The members, in request order.
    pub fn members(&self) -> &[Member] {
        &self.members
    }

    /// The render body of `member`: the base request (source, `files`,
    /// options) with the member's seed and parameters, as [`Batch::run`]
    /// renders it.
    pub fn member_body(&self, member: &Member) -> RenderBody {
        member_body(&self.base, member)
    }

    /// Renders every member through the engine, at most as many at once as
    /// the server has render slots (so a batch alone never sheds its own
    /// members), yielding each outcome as soon as it and every member before
    /// it are done: in request order, streamed. Each member runs inside
    /// `span` (the request's), as a single render would.
    pub fn run(self, state: Arc<AppState>, ceiling: Limits, no_cache: bool, span: tracing::Span) -> impl Stream<Item = MemberOutcome> + Send + 'static {
        let width = state.config.concurrency().max(1);
        let base = Arc::new(self.base);
        stream::iter(self.members)
            .map(move |member| {
                let (state, base) = (state.clone(), base.clone());
                async move {
                    let body = member_body(&base, &member);
                    let result = match body.plan(&ceiling, no_cache) {
                        Ok(plan) => {
                            let format = plan.request.format;
                            state.engine.serve(plan).await.map(|served| (served, format))
                        }
                        Err(e) => Err(e),
                    };
                    MemberOutcome { member, result }
                }
                .instrument(span.clone())
            })
            .buffered(width)
    }
}

/// `base` with `member`'s seed and parameters.
fn member_body(base: &RenderBody, member: &Member) -> RenderBody {
    let mut body = base.clone();
    body.options.seed = member.seed;
    body.options.params = member.params.clone();
    body
}

/// Refuses an empty batch or one over [`MAX_MEMBERS`].
fn check_size(members: usize) -> Result<(), ServiceError> {
    match members {
        0 => Err(ServiceError::BadRequest("a batch needs at least one member (a non-empty `seeds` or `sweep`)".into())),
        // Over the cap is a request too large to take, as a body over the
        // byte limit is (413): the schema cannot bound a sweep's product.
        n if n > MAX_MEMBERS => Err(ServiceError::TooManyMembers { members: n, cap: MAX_MEMBERS }),
        _ => Ok(()),
    }
}

/// The cartesian product of `sweep` over `base`'s parameters.
fn sweep_members(base: &RenderBody, sweep: &BTreeMap<String, Vec<ParamValue>>) -> Result<Vec<Member>, ServiceError> {
    if let Some((name, _)) = sweep.iter().find(|(_, values)| values.is_empty()) {
        return Err(ServiceError::BadRequest(format!("sweep parameter `{name}` has no values")));
    }
    // Checked, so that a product too large to count is refused, not wrapped.
    let total = sweep.values().try_fold(1usize, |n, v| n.checked_mul(v.len())).unwrap_or(usize::MAX);
    check_size(if sweep.is_empty() { 0 } else { total })?;
    let mut members = Vec::with_capacity(total);
    for index in 0..total {
        let mut params = base.options.params.clone();
        // Mixed radix, the last name the lowest digit.
        let mut rest = index;
        for (name, values) in sweep.iter().rev() {
            if let Some(v) = values.get(rest % values.len()) {
                params.insert(name.clone(), v.clone());
            }
            rest /= values.len();
        }
        members.push(Member { index, seed: base.options.seed, params });
    }
    Ok(members)
}

/// Reads the JSON batch body: a `/v1/render` body (or `grammar`, a library
/// grammar's name, instead of `source`) plus `seeds` or `sweep`.
pub fn from_json_body(body: &[u8], ceiling: &Limits, phone: bool) -> Result<Batch, ServiceError> {
    let mut fields: Map<String, Value> = from_json(body)?;
    let grammar: Option<String> = take(&mut fields, "grammar")?;
    let seeds: Option<Vec<SeedValue>> = take(&mut fields, "seeds")?;
    let sweep: Option<BTreeMap<String, Vec<ParamValue>>> = take(&mut fields, "sweep")?;
    if let Some(name) = grammar {
        if fields.contains_key("source") {
            return Err(ServiceError::BadRequest("a batch takes `source` or `grammar`, not both".into()));
        }
        let builtin = library::find_route_name(&name)?;
        fields.insert("source".into(), Value::from(builtin.source));
        fields.entry("language").or_insert_with(|| Value::from(builtin.language.name()));
    }
    let base: RenderBody = serde_json::from_value(Value::Object(fields)).map_err(|e| ServiceError::BadRequest(format!("malformed JSON request: {e}")))?;
    // A phone's default (docs/loaders.md) is the base's, so every member inherits it.
    let base = base.with_phone_default(phone);
    let variation = match (seeds, sweep) {
        (Some(seeds), None) => Variation::Seeds(seeds.into_iter().map(|s| s.0).collect()),
        (None, Some(sweep)) => Variation::Sweep(sweep),
        (Some(_), Some(_)) => return Err(ServiceError::BadRequest("a batch takes `seeds` or `sweep`, not both".into())),
        (None, None) => return Err(ServiceError::BadRequest("a batch needs `seeds` (a list of seeds) or `sweep` (parameter → list of values)".into())),
    };
    Batch::new(base, variation, ceiling)
}

/// Removes `name` from `fields` and reads it as `T` (null reads as absent).
fn take<T: serde::de::DeserializeOwned>(fields: &mut Map<String, Value>, name: &str) -> Result<Option<T>, ServiceError> {
    match fields.remove(name) {
        None | Some(Value::Null) => Ok(None),
        Some(v) => serde_json::from_value(v).map(Some).map_err(|e| ServiceError::BadRequest(format!("malformed JSON request: `{name}`: {e}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn batch(json: &str) -> Result<Batch, ServiceError> {
        from_json_body(json.as_bytes(), &Limits::ceiling(), false)
    }

    #[test]
    fn seeds_keep_their_order_and_full_width() {
        let b = batch(r#"{"grammar":"gem","seeds":[3,"9223372036854775809",1]}"#).expect("valid");
        let seeds: Vec<Option<u64>> = b.members().iter().map(|m| m.seed).collect();
        assert_eq!(seeds, [Some(3), Some((1 << 63) + 1), Some(1)]);
        assert_eq!(b.members().iter().map(|m| m.index).collect::<Vec<_>>(), [0, 1, 2]);
    }

    #[test]
    fn a_sweep_is_the_cartesian_product_last_name_fastest() {
        let b = batch(r#"{"source":"startshape A\nrule A { BOX {} }","params":{"k":1},"sweep":{"b":[1,2],"a":["x","y","z"]}}"#).expect("valid");
        let combos: Vec<(String, String)> = b
            .members()
            .iter()
            .map(|m| {
                let show = |n: &str| match &m.params[n] {
                    ParamValue::Number(v) => v.to_string(),
                    ParamValue::Text(t) => t.clone(),
                    ParamValue::Bool(b) => b.to_string(),
                };
                assert_eq!(m.params["k"], ParamValue::Number(1.0));
                (show("a"), show("b"))
            })
            .collect();
        let want: Vec<(String, String)> = [("x", "1"), ("x", "2"), ("y", "1"), ("y", "2"), ("z", "1"), ("z", "2")].iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
        assert_eq!(combos, want);
    }

    #[test]
    fn malformed_batches_fail_whole() {
        let many: Vec<u64> = (0..=MAX_MEMBERS as u64).collect();
        let over = format!(r#"{{"grammar":"gem","seeds":{}}}"#, serde_json::to_string(&many).expect("json"));
        match batch(&over) {
            Err(e @ ServiceError::TooManyMembers { members: 257, cap: 256 }) => assert!(e.to_string().contains("cap of 256"), "{e}"),
            other => panic!("{other:?}"),
        }
        let wide: Vec<u32> = (0..17).collect();
        let sweep = format!(r#"{{"grammar":"gem","sweep":{{"a":{w},"b":{w}}}}}"#, w = serde_json::to_string(&wide).expect("json"));
        assert!(matches!(batch(&sweep), Err(ServiceError::TooManyMembers { members: 289, .. })));
        for bad in [
            r#"{"grammar":"gem"}"#,
            r#"{"grammar":"gem","seeds":[]}"#,
            r#"{"grammar":"gem","sweep":{}}"#,
            r#"{"grammar":"gem","sweep":{"a":[]}}"#,
            r#"{"grammar":"gem","seeds":[1],"sweep":{"a":[1]}}"#,
            r#"{"grammar":"gem","seeds":[1],"seed":2}"#,
            r#"{"grammar":"gem","seeds":[-1]}"#,
            r#"{"grammar":"gem","seeds":[null]}"#,
            r#"{"grammar":"gem","seeds":"1"}"#,
            r#"{"grammar":"gem","source":"x","seeds":[1]}"#,
            r#"{"grammar":"gem","seeds":[1],"format":"obj"}"#,
            r#"{"grammar":"gem","seeds":[1],"colour":"red"}"#,
            r#"[1]"#,
        ] {
            assert!(matches!(batch(bad), Err(ServiceError::BadRequest(_))), "{bad}");
        }
        assert!(matches!(batch(r#"{"grammar":"nope","seeds":[1]}"#), Err(ServiceError::NotFound(_))));
    }
}
