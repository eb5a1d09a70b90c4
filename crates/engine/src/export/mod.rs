//! The writers: meshes, a picture or a model → bytes. They read meshes,
//! scene metadata and the model only; they never parse.
//!
//! One folder per format family (`gltf`, `strips`, `scene`, `stl`,
//! `threemf`, `png`, `ug`, `usdz`), each declaring its formats' descriptors
//! ([`FormatInfo`]) beside its writers; this file holds what they share
//! (the errors, the scene-level metadata, the request's format options,
//! the welding and the deadline cadence), and `formats` is the registry
//! that lists them. The readers of served bytes are in `crate::decode`.

mod descriptor;
mod formats;
pub mod sink;
pub(crate) mod pace;
pub mod gltf;
pub mod png;
pub mod provenance;
pub mod scene;
pub mod stl;
pub mod strips;
pub mod svg;
pub mod threemf;
pub mod ug;
pub mod usdz;

pub use descriptor::{OptionGroup, Writer};
pub use sink::{Drawn, ExactPlacement, GeometrySink, InstanceData, InstanceLayout, MakeSink, MeshId};
pub(crate) use sink::FlatSink;
pub(crate) use descriptor::{EncodePicture, WriteDrawing, WriteMeshes, WriteModel};
pub use formats::{estimated_size, Format, FORMATS};
pub(crate) use formats::{flat_sink, no_drawing};
pub use gltf::compact::Compression;
pub(crate) use gltf::compact::{parse_compression, GltfOptions};
pub(crate) use provenance::Provenance;
pub(crate) use strips::StripsOptions;

use crate::core::budget::LimitExceeded;
use crate::geom::NamedMesh;

/// How glb/gltf write a model whose meshes repeat (an instancing L-system,
/// or any scene that places a mesh more than once).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Instancing {
    /// Each repeated mesh (an L-system's segment look; a primitive kind,
    /// class and mirroring, or a `mesh` shape, placed more than once) written
    /// once and drawn per instance with `EXT_mesh_gpu_instancing` (a
    /// required extension); the rest plain (docs/service.md, *GPU instancing*).
    #[default]
    Gpu,
    /// The same geometry expanded into plain meshes, for loaders without the extension.
    Flat,
}

rulemesh_core::choice!(Instancing { Gpu => "gpu", Flat => "flat" });

/// A mesh welded by exact position for formats that name shared vertices
/// (3MF, UniGrafix; [`pace::welded`]): the distinct positions in first-use
/// order, and each triangle's index in the mesh with its corners as
/// indices into them; triangles that lose a corner to welding are dropped.
pub(crate) type Welded = (Vec<[f32; 3]>, Vec<(usize, [u32; 3])>);

/// Drops the normals and colours of `meshes`, which STL never writes (facet
/// normals are recomputed from the winding, and STL has no colour), so that
/// the output of a big model is allocated beside positions and indices
/// only: for a grid of boxes the mesh shrinks from 816 to 432 bytes a box,
/// and the process's peak memory from 2.5× to under 2× the STL file (see
/// `docs/benchmarks.md`, big flat outputs). The pipeline calls it between
/// meshing and export for a format whose writer reads positions and
/// indices only ([`Capabilities::positions_only`]).
pub(crate) fn keep_positions_only(meshes: &mut [NamedMesh]) {
    for m in meshes {
        m.mesh.normals = Vec::new();
        m.mesh.colours = Vec::new();
    }
}

/// Scene-level facts an exporter may record besides geometry.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ExportMeta {
    /// Background colour to record (glTF `extras`).
    pub background: Option<[f32; 4]>,
    /// Whether the model was cut short by a limit (recorded in glTF `extras`).
    pub truncated: bool,
    /// Bones, their animation and the camera, for the plain glTF writers;
    /// the meshes are then each in their node's coordinates.
    pub graph: Option<crate::model::graph::NodeGraph>,
    /// Give each mesh its own glTF material named like the mesh, instead of
    /// one shared unnamed material: EisenScript's primitive classes
    /// (`box::glass`) become meshes and materials a viewer can restyle.
    pub material_per_mesh: bool,
    /// A viewpoint to add as a glTF perspective camera (glTF formats only).
    pub camera: Option<crate::model::Camera>,
    /// What made the model (engine, language, seed, parameters, model key),
    /// written where the format has metadata; `None` for meshes that come
    /// from outside a render (a decoded strips file).
    pub provenance: Option<Provenance>,
}

/// Export failures.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The output would exceed the memory budget.
    #[error(transparent)]
    Limit(#[from] LimitExceeded),
    /// The model is too large for the format (e.g. glTF's 4 GiB buffer limit).
    #[error("model too large for {format}: {detail}")]
    TooLarge {
        /// The format's name.
        format: &'static str,
        /// What overflowed.
        detail: String,
    },
    /// A mesh handed to an exporter is malformed (index out of range,
    /// attribute arrays of different lengths, non-finite positions). Meshes
    /// from [`build_meshes`](crate::mesh::build_meshes) never are; this guards
    /// library callers who build meshes themselves.
    #[error("invalid mesh {name:?}: {detail}")]
    InvalidMesh {
        /// The mesh's name.
        name: String,
        /// What is wrong with it.
        detail: String,
    },
    /// The format options of the request are out of range (e.g. 7-bit positions).
    #[error("invalid {format} options: {detail}")]
    InvalidOptions {
        /// The format's name.
        format: &'static str,
        /// What is wrong.
        detail: String,
    },
    /// JSON serialisation failed.
    #[error("serialising glTF JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// The PNG encoder failed (it cannot on a well-formed picture).
    #[error("encoding PNG: {0}")]
    Png(String),
}

impl From<crate::preview::PreviewError> for ExportError {
    fn from(e: crate::preview::PreviewError) -> Self {
        match e {
            crate::preview::PreviewError::Limit(l) => ExportError::Limit(l),
            crate::preview::PreviewError::BadOptions(detail) => ExportError::InvalidOptions { format: png::PNG.name, detail },
        }
    }
}

/// Per-format encoding options of a request. They travel with the request
/// to the exporter only: the parser and evaluator never see them, so they
/// cannot change the model, only its encoding.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct ExportOptions {
    /// Precision and compression of the `strips` format.
    pub strips: StripsOptions,
    /// Welding, quantisation and compression of the `glb` and `gltf` formats.
    pub gltf: GltfOptions,
    /// Scale and move the model into a unit box centred at the origin (every
    /// format): its longest side becomes 1, its bounding box centre the origin.
    pub fit_unit_box: bool,
    /// `glb`/`gltf`: GPU instancing of repeated meshes or the flat fallback.
    pub instancing: Instancing,
    /// Printable output: one watertight solid in millimetres (`docs/print.md`).
    /// A pipeline stage before export ([`crate::pipeline`]); exporters ignore it.
    pub print: crate::print::PrintOptions,
    /// Size, view and background of the `png` preview (`docs/preview.md`).
    pub preview: crate::preview::PreviewOptions,
    /// `scene`: end the file with a CRC-32 of its bytes
    /// (`docs/scene-format.md`, "Checksum"); off by default, so files stay
    /// readable by decoders from before the flag.
    #[serde(default)]
    pub checksum: bool,
}

/// Triangles a writer writes between two looks at the deadline: often enough
/// that a writer overruns it by well under a millisecond's work, rarely
/// enough that the clock costs nothing measurable.
pub(crate) const DEADLINE_EVERY: usize = 1 << 16;

// geom::normalize's tests, which export glTF (a layer above geom).
#[cfg(test)]
mod normalize_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::{Budget, Limits};
    use crate::export::gltf::tests::{all_nine, meshes_of};
    use crate::mesh::tests::{inst, scene};
    use crate::mesh::MeshLayout;
    use crate::core::PrimitiveKind;
    use std::path::{Path, PathBuf};

    /// The sample models: each primitive alone, all nine merged and per kind,
    /// mirrored ones, and an empty model.
    fn samples() -> Vec<(String, Vec<NamedMesh>, ExportMeta)> {
        let mut out = Vec::new();
        let plain = ExportMeta::default();
        for kind in PrimitiveKind::ALL {
            let s = scene(vec![inst(kind, [0.0; 3], 1.0, false)]);
            out.push((kind.name().to_ascii_lowercase(), meshes_of(&s, 16, MeshLayout::Merged), plain.clone()));
        }
        let meta = ExportMeta { background: Some([0.1, 0.2, 0.3, 1.0]), truncated: true, graph: None, material_per_mesh: false, camera: None, provenance: None };
        out.push(("all-merged".into(), meshes_of(&all_nine(), 16, MeshLayout::Merged), meta.clone()));
        out.push(("all-per-kind".into(), meshes_of(&all_nine(), 5, MeshLayout::PerKind), meta));
        let mirrored = scene(vec![inst(PrimitiveKind::Cone, [1.0, 2.0, 3.0], 2.0, true)]);
        out.push(("mirrored-cone".into(), meshes_of(&mirrored, 16, MeshLayout::Merged), plain.clone()));
        let mirrored = scene(vec![inst(PrimitiveKind::Box, [0.0; 3], 1.0, true)]);
        out.push(("mirrored-box".into(), meshes_of(&mirrored, 16, MeshLayout::Merged), plain.clone()));
        let big = scene((0..3).map(|k| inst(PrimitiveKind::Sphere, [k as f32, 0.0, 0.0], 1.0, k == 1)).collect());
        out.push(("u32-indices".into(), meshes_of(&big, 256, MeshLayout::Merged), plain.clone()));
        out.push(("empty".into(), Vec::new(), plain));
        out
    }

    fn counts(meshes: &[NamedMesh]) -> (u64, u64) {
        meshes.iter().fold((0, 0), |(v, t), m| (v + m.mesh.positions.len() as u64, t + m.mesh.triangle_count() as u64))
    }

    /// Writes every sample in every format (to `RULEMESH_SAMPLE_DIR` if set,
    /// else a temporary folder), checks each size against [`estimated_size`],
    /// and runs `scripts/validate-gltf.mjs` on the glTF files when Node and
    /// the validator are available (see the script for where it looks).
    #[test]
    fn samples_fit_estimates_and_validate() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = std::env::var_os("RULEMESH_SAMPLE_DIR").map(PathBuf::from).unwrap_or_else(|| tmp.path().to_path_buf());
        std::fs::create_dir_all(&dir).unwrap();
        let mut gltf_files = Vec::new();
        for (name, meshes, meta) in samples() {
            let (v, t) = counts(&meshes);
            // Every format written from meshes, as the registry lists them.
            for &format in Format::ALL.iter().filter(|f| matches!(f.info().writer, Writer::Sink { .. } | Writer::Instancing { .. })) {
                let ext = format!("{}.{}", format.name(), format.extension());
                let mut budget = Budget::new(Limits::default());
                let mut sink = flat_sink(format, &ExportOptions::default()).unwrap();
                sink.begin(&meta, &mut budget).unwrap();
                for mesh in meshes.iter().cloned() {
                    sink.mesh(mesh, Drawn::Plain, &mut budget).unwrap();
                }
                let bytes = sink.end(&mut budget).unwrap();
                assert!(bytes.len() as u64 <= estimated_size(format, v, t), "{name}.{ext}: {} > estimate", bytes.len());
                let path = dir.join(format!("{name}.{ext}"));
                std::fs::write(&path, &bytes).unwrap();
                if format.info().caps.node_graph {
                    gltf_files.push(path);
                }
            }
        }
        let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scripts/validate-gltf.mjs");
        let run = std::process::Command::new("node").arg(&script).args(&gltf_files).output();
        // scripts/test installs the validator and sets GLTF_VALIDATOR_DIR; there a missing
        // validator is a failure, not a skip. A bare `cargo test` may lack it.
        let required = std::env::var_os("GLTF_VALIDATOR_DIR").is_some();
        match run {
            Err(e) if !required => eprintln!("skipping glTF validation: cannot run node: {e}"),
            Ok(o) if o.status.code() == Some(2) && !required => {
                eprintln!("skipping glTF validation: {}", String::from_utf8_lossy(&o.stderr))
            }
            Err(e) => panic!("GLTF_VALIDATOR_DIR is set but node cannot run: {e}"),
            Ok(o) => {
                let report = String::from_utf8_lossy(&o.stdout);
                assert!(o.status.success(), "validator found errors:\n{report}");
                for line in report.lines() {
                    let r: serde_json::Value = serde_json::from_str(line).unwrap();
                    assert_eq!(r["numErrors"], 0, "{line}");
                    assert_eq!(r["numWarnings"], 0, "{line}");
                }
                assert_eq!(report.lines().count(), gltf_files.len());
            }
        }
    }
}
