//! `format=scene`: rulemesh's compact instancing format
//! (`docs/scene-format.md`). Version 2 carries a model as it was made:
//! primitive instances (kind, transform, colour; tessellated by the reader
//! at the detail in the header), the meshes that are not instances (swept
//! lines, free triangles, isosurfaces and modified meshes as prototypes
//! placed by instances) and the L-system object hierarchy, so its size grows
//! with what the grammar placed, not with triangles. Version 1 files (an
//! L-system hierarchy alone) still decode.
//!
//! This module is the format's descriptor ([`SCENE`]) and its writer
//! ([`write_scene`], `write`), with the layout's constants (`format`); the
//! readers are `crate::decode::scene` ([`decode_scene_meshes`] gives the
//! flat formats' meshes, [`decode_scene`] the hierarchy alone).
//!
//! [`decode_scene_meshes`]: crate::decode::scene::decode_scene_meshes
//! [`decode_scene`]: crate::decode::scene::decode_scene

pub mod format;
mod write;

pub use format::{CHECKSUM_BYTES, ENTRY_BYTES, FLAG_CHECKSUM, FLAG_PROVENANCE, FLAG_TRUNCATED, MAGIC, SHAPE_BIT, SHAPE_BYTES};
pub(crate) use write::{write_scene, MAX_RECORD_BYTES};

use super::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};

/// `scene`: written from the model (no meshes are made), its hierarchy
/// sized exactly when written; every placement is charged as an instance
/// record of at most [`MAX_RECORD_BYTES`].
pub(crate) const SCENE: FormatInfo = FormatInfo {
    name: "scene",
    extensions: &["rmscene"],
    mime: "application/vnd.rulemesh.scene",
    caps: Capabilities::NONE,
    options: OptionGroup::Scene,
    size: SizeBound { fixed: 1024, per_vertex: 0, per_triangle: 0, per_instance: MAX_RECORD_BYTES },
    writer: Writer::Model(write_scene),
};

