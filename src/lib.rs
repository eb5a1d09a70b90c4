//! rulemesh: shape grammars to 3D models.
//!
//! This package is the command-line binary (`src/main.rs`) and a facade that
//! re-exports the workspace's crates under one name, for the integration
//! tests, the fuzz targets and the benches. The crates, bottom layer first
//! (`layers.txt`, ARCHITECTURE.md): `rulemesh-core` ([`core`], [`geom`]),
//! `rulemesh-lang` ([`lang`]: each language's parser and front end, and the
//! [`model`] they build; [`eval`], [`lsystem`] and [`eisen`] are its MDG,
//! L-system and EisenScript front ends under their old names),
//! `rulemesh-engine` (the stages, [`export`], [`decode`] and [`pipeline`]) and
//! `rulemesh-service` ([`cache`], [`service`]).

#![warn(missing_docs)]

pub use rulemesh_core::{core, geom, ENGINE_VERSION};
pub use rulemesh_engine::{decode, export, mesh, pipeline, preview, print};
pub use rulemesh_engine::{render, PhaseTimes, RenderError, RenderOptions, RenderOutput, RenderRequest};
pub use rulemesh_lang as lang;
pub use rulemesh_lang::{eisen, lsystem, mdg::eval, model};
pub use rulemesh_service::{cache, service};
