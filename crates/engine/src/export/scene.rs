//! `format=scene`: rulemesh's compact instancing format
//! (`docs/scene-format.md`). Version 2 carries a model as it was made:
//! primitive instances (kind, transform, colour; tessellated by the reader
//! at the detail in the header), the meshes that are not instances (swept
//! lines, free triangles, isosurfaces and modified meshes as prototypes
//! placed by instances) and the L-system object hierarchy, so its size grows
//! with what the grammar placed, not with triangles. Version 1 files (an
//! L-system hierarchy alone) still decode.
//!
//! This module is the format's public face: the writer ([`write_scene`],
//! `scene_v2`), the readers ([`decode_scene_meshes`], the flat formats'
//! meshes; [`decode_scene`], the hierarchy alone; `scene_decode`) and what
//! they share (`scene_format`).

pub use super::scene_decode::{decode_scene, decode_scene_meshes, DecodedScene};
pub use super::scene_format::{
    scene_provenance, SceneError, ENTRY_BYTES, ENTRY_BYTES_V1, FLAG_PROVENANCE, FLAG_TRUNCATED, HEADER_BYTES, HEADER_BYTES_V1, MAGIC, SHAPE_BIT, SHAPE_BYTES, VERSION,
    VERSION_1,
};
pub use super::scene_v2::{write_scene, MAX_RECORD_BYTES};
