//! rulemesh-core: the bottom of rulemesh's layers (`layers.txt`).
//!
//! [`core`] holds what every layer shares and nothing about languages,
//! scenes or formats: budgets and limits, seeded random streams, colour
//! quantisation, request parameter values, diagnostics, stage timing and the
//! embedded grammar library. [`geom`] is the geometry kernel: meshes,
//! primitive tessellation, half-edge meshes, sweeps, welding, strips and the
//! modifier stack. Everything here is a pure function of its inputs plus the
//! budget it charges.

#![warn(missing_docs)]

pub mod core;
pub mod geom;

/// The engine version; part of every cache key and every file's generator
/// string, since outputs may change with it. One version for the workspace.
pub const ENGINE_VERSION: &str = env!("CARGO_PKG_VERSION");
