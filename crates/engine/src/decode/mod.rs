//! The readers of served bytes: the reference decoders of rulemesh's own
//! formats, for the CLI's `decode`, tests, fuzz targets and clients written
//! in Rust. They sit above the writers (`crate::export`), whose layout
//! constants they check bytes against, and apart from them: nothing on the
//! way from source to bytes reads bytes back.
//!
//! Every count a file states is checked against the bytes that carry it
//! before anything is allocated, so damaged or hostile input is a typed
//! error, never a large allocation or a panic (the fuzz targets
//! `decode_strips` and `decode_scene` hold them to it).

pub mod scene;
pub mod strips;

pub use scene::{decode_scene, decode_scene_meshes, scene_provenance, DecodedScene, SceneError};
pub use strips::{decode_strips, decode_strips_full, DecodedStrips, StripsError};
