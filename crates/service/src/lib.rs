//! rulemesh-service: the doors around the engine's one `render`: HTTP
//! (axum) and gRPC (tonic) in [`service`], and the cache tiers (memory, disk,
//! Redis) in [`cache`], keyed by the canonical request's BLAKE3.

#![warn(missing_docs)]

// The layers below, under the names the code has always used.
use rulemesh_core::core;
use rulemesh_engine::{export, pipeline, preview, print};
use rulemesh_engine::{render, RenderError, RenderOutput, RenderRequest};
use rulemesh_lang as lang;
use rulemesh_lang::model;
pub use rulemesh_core::ENGINE_VERSION;

pub mod cache;
pub mod service;
