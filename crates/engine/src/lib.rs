//! rulemesh-engine: source to bytes under one budget, with no async runtime,
//! network or command-line code.
//!
//! Data flows one way: source → a language's front end (rulemesh-lang,
//! found through [`lang::Language::front_end`]) → one [`model::Model`] →
//! the stages ([`print`], [`mesh`], [`preview`]) → [`export`] → bytes,
//! each format written as the registry in [`export`] (`formats.rs`) says;
//! [`decode`] reads rulemesh's own formats back, for clients and tests.
//! [`render`] ([`pipeline`]) is the only orchestrator and runs it all under
//! one `core::Budget`. `ARCHITECTURE.md` has the code map.

#![warn(missing_docs)]

// The layers below, under the names the code has always used (`crate::core`,
// `crate::geom`, `crate::lang`, `crate::model`), so a module's paths do not
// depend on which crate holds it.
use rulemesh_core::{core, geom};
use rulemesh_lang as lang;
use rulemesh_lang::model;
pub use rulemesh_core::ENGINE_VERSION;

pub mod decode;
pub mod export;
pub mod mesh;
pub mod pipeline;
pub mod preview;
pub mod print;

pub use pipeline::{render, PhaseTimes, RenderError, RenderOptions, RenderOutput, RenderRequest};
