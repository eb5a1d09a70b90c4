//! rulemesh: shape grammars to 3D models.
//!
//! Data flows one way: source → a front end ([`eval`] for MDG, stacking
//! strings and UniGrafix, [`lsystem`] for L-systems and ETOL, [`eisen`] for
//! EisenScript) → one [`model::Model`] → the stages ([`print`], [`mesh`], [`preview`]) →
//! [`export`] → bytes. [`render`] ([`pipeline`]) is the only orchestrator and
//! runs it all under one [`core::Budget`]. `ARCHITECTURE.md` has the code map.

#![warn(missing_docs)]

pub mod cache;
pub mod core;
pub mod eisen;
pub mod eval;
pub mod export;
pub mod geom;
pub mod lang;
pub mod lsystem;
pub mod mesh;
pub mod model;
pub mod pipeline;
pub mod preview;
pub mod print;
pub mod service;

pub use pipeline::{render, PhaseTimes, RenderError, RenderOutput, RenderRequest};

/// The engine version; part of every cache key, since outputs may change with it.
pub const ENGINE_VERSION: &str = env!("CARGO_PKG_VERSION");
