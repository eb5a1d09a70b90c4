//! gRPC `RenderBatch` (issue 20): the batch of [`super::batch`] as a server
//! stream of `RenderBatchItem`s, the same members, order and per-member
//! errors as the HTTP route, and the same bytes for the same seeds.

use super::batch::{Batch, MemberOutcome, Variation};
use super::grpc::pb;
use super::request::RenderBody;
use super::{library, AppState, ServiceError};
use crate::core::ParamValue;
use futures_util::stream::{Stream, StreamExt};
use std::sync::Arc;
use tonic::Status;

/// The stream `RenderBatch` answers with.
pub(crate) type ItemStream = std::pin::Pin<Box<dyn Stream<Item = Result<pb::RenderBatchItem, Status>> + Send>>;

/// The batch a `RenderBatchRequest` asks for, validated against `ceiling`
/// (a malformed batch fails whole, before anything renders), and whether
/// its members bypass the cache.
pub(crate) fn batch_of(request: pb::RenderBatchRequest, ceiling: &crate::core::Limits) -> Result<(Batch, bool), ServiceError> {
    let render = request.render.unwrap_or_default();
    let no_cache = render.no_cache;
    let mut base = RenderBody::from(render);
    if !request.grammar.is_empty() {
        if !base.source.is_empty() {
            return Err(ServiceError::BadRequest("a batch takes render.source or grammar, not both".into()));
        }
        let builtin = library::find_route_name(&request.grammar)?;
        base.source = builtin.source.to_string();
        base.options.language = base.options.language.or_else(|| Some(builtin.language.name().to_string()));
    }
    let variation = match (request.seeds.is_empty(), request.sweep.is_empty()) {
        (false, false) => return Err(ServiceError::BadRequest("a batch takes seeds or sweep, not both".into())),
        (false, true) => Variation::Seeds(request.seeds),
        // An empty sweep is refused by `Batch::new` as a batch without members.
        (true, _) => Variation::Sweep(request.sweep.into_iter().map(|(k, v)| (k, v.values.into_iter().map(ParamValue::Text).collect())).collect()),
    };
    Ok((Batch::new(base, variation, ceiling)?, no_cache))
}

/// A parameter value as gRPC text: what the CLI or a query string would send.
fn param_text(v: &ParamValue) -> String {
    match v.canonical() {
        ParamValue::Number(n) => n.to_string(),
        ParamValue::Bool(b) => b.to_string(),
        ParamValue::Text(t) => t,
    }
}

/// The item of one member.
fn item(outcome: MemberOutcome, state: &AppState) -> pb::RenderBatchItem {
    let MemberOutcome { member, result } = outcome;
    let params = member.params.iter().map(|(k, v)| (k.clone(), param_text(v))).collect();
    let index = u32::try_from(member.index).unwrap_or(u32::MAX);
    match result {
        Ok((served, format)) => {
            state.metrics.bytes_out("grpc", format, served.model.bytes.len());
            let m = &served.model;
            let meta = super::grpc::meta(&served);
            let model = pb::RenderReply { meta: Some(meta), model: m.bytes.to_vec() };
            pb::RenderBatchItem { index, seed: Some(m.seed), params, result: Some(pb::render_batch_item::Result::Model(model)) }
        }
        Err(e) => {
            let error = pb::MemberError { code: e.code().to_string(), message: e.to_string(), details: e.body().to_string().into_bytes() };
            pb::RenderBatchItem { index, seed: member.seed, params, result: Some(pb::render_batch_item::Result::Error(error)) }
        }
    }
}

/// Runs `batch`, one item per member in request order, holding `hold` (the
/// caller's API-key admission) until the stream ends or is dropped.
pub fn items<H: Send + 'static>(batch: Batch, state: Arc<AppState>, ceiling: crate::core::Limits, no_cache: bool, span: tracing::Span, hold: H) -> ItemStream {
    let st = state.clone();
    Box::pin(batch.run(state, ceiling, no_cache, span).map(move |o| {
        let _share = &hold;
        Ok(item(o, &st))
    }))
}
