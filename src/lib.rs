//! rulemesh: shape grammars to 3D models.
//!
//! Data flows one way: source → [`lang`] (IR) → [`eval`] ([`eval::Scene`]) →
//! [`geom`] (meshes) → [`export`] (bytes). [`render`] runs the whole pipeline
//! under one [`eval::Budget`].

#![warn(missing_docs)]

pub mod cache;
pub mod export;
pub mod eval;
pub mod geom;
pub mod grammars;
pub mod eisen;
pub mod lang;
pub mod lsystem;
pub mod pipeline;
pub mod print;
pub mod service;

pub use pipeline::{render, PhaseTimes, RenderError, RenderOutput, RenderRequest};

/// The engine version; part of every cache key, since outputs may change with it.
pub const ENGINE_VERSION: &str = env!("CARGO_PKG_VERSION");
