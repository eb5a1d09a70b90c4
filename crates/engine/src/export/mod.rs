//! Exporters: meshes → bytes. They read meshes and scene metadata only; they never parse.

pub mod compact;
pub mod gltf;
mod gltf_buffer;
mod gltf_document;
mod gltf_graph;
mod gltf_instanced;
pub mod instanced;
pub mod png;
pub mod provenance;
pub mod scene;
mod scene_decode;
mod scene_format;
mod scene_v2;
pub mod stl;
pub mod strips;
mod strips_chunk;
mod strips_decode;
mod strips_format;
pub mod threemf;
pub mod ug;

pub use compact::{Compression, GltfOptions};
pub use provenance::Provenance;
pub use strips::{decode_strips, StripsError, StripsOptions};

use crate::core::budget::{Budget, LimitExceeded};
use crate::geom::NamedMesh;

/// Output formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Format {
    /// Binary glTF 2.0 (.glb).
    Glb,
    /// glTF 2.0 JSON with the buffer embedded as a data URI (.gltf).
    Gltf,
    /// Binary STL.
    Stl,
    /// ASCII STL.
    StlAscii,
    /// rulemesh's compact triangle-strip format for phone clients
    /// (`docs/strips-format.md`): quantised, stripified and compressed.
    Strips,
    /// rulemesh's object-instancing hierarchy (`docs/scene-format.md`), for
    /// L-systems: its size grows with the distinct subtrees, not the segments.
    Scene,
    /// 3MF core package (a zip with the model XML in millimetres), for printing.
    #[serde(rename = "3mf")]
    ThreeMf,
    /// Berkeley UniGrafix text (Séquin (ed.) 1992): `def`/`v`/`f`/`c`/`i` statements.
    Ug,
    /// A PNG picture of the model (the preview stage, `docs/preview.md`):
    /// drawn on the CPU, for icons and order pages.
    Png,
}

impl crate::core::Choice for Format {
    const ALL: &'static [Self] = &Format::ALL;
    fn name(self) -> &'static str {
        Format::name(self)
    }
}

impl Format {
    /// Picks a format from an output file name's extension.
    pub fn from_extension(path: &std::path::Path) -> Option<Format> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "glb" => Some(Format::Glb),
            "gltf" => Some(Format::Gltf),
            "stl" => Some(Format::Stl),
            "strips" => Some(Format::Strips),
            "rmscene" => Some(Format::Scene),
            "3mf" => Some(Format::ThreeMf),
            "ug" => Some(Format::Ug),
            "png" => Some(Format::Png),
            _ => None,
        }
    }

    /// Every format, in the order they are listed in messages.
    pub const ALL: [Format; 9] =
        [Format::Glb, Format::Gltf, Format::Stl, Format::StlAscii, Format::Strips, Format::Scene, Format::ThreeMf, Format::Ug, Format::Png];

    /// The output file extensions [`Format::from_extension`] knows, with a dot
    /// each, for messages that list them.
    pub fn known_extensions() -> String {
        let mut exts: Vec<&str> = Vec::new();
        for f in Format::ALL {
            if !exts.contains(&f.extension()) {
                exts.push(f.extension());
            }
        }
        exts.iter().map(|e| format!(".{e}")).collect::<Vec<_>>().join(", ")
    }

    /// The MIME type of the format.
    pub fn content_type(self) -> &'static str {
        match self {
            Format::Glb => "model/gltf-binary",
            Format::Gltf => "model/gltf+json",
            Format::Stl | Format::StlAscii => "model/stl",
            Format::Strips => "application/vnd.rulemesh.strips",
            Format::Scene => "application/vnd.rulemesh.scene",
            Format::ThreeMf => "model/3mf",
            Format::Ug => "text/plain; charset=utf-8",
            Format::Png => "image/png",
        }
    }

    /// The format's request name (`"glb"`, `"stl-ascii"`, `"3mf"` …), as
    /// requests spell it: the one spelling the cache key, metrics labels and
    /// logs share, so a name cannot drift between them.
    pub fn name(self) -> &'static str {
        match self {
            Format::Glb => "glb",
            Format::Gltf => "gltf",
            Format::Stl => "stl",
            Format::StlAscii => "stl-ascii",
            Format::Strips => "strips",
            Format::Scene => "scene",
            Format::ThreeMf => "3mf",
            Format::Ug => "ug",
            Format::Png => "png",
        }
    }

    /// The usual file extension (without the dot), so front ends can name outputs.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Glb => "glb",
            Format::Gltf => "gltf",
            Format::Stl => "stl",
            Format::StlAscii => "stl",
            Format::Strips => "strips",
            Format::Scene => "rmscene",
            Format::ThreeMf => "3mf",
            Format::Ug => "ug",
            Format::Png => "png",
        }
    }
}

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

/// Welds a mesh's vertices by exact position for formats that name shared
/// vertices (3MF, UniGrafix): the distinct positions in first-use order, and
/// each triangle's index in the mesh with its corners as indices into them;
/// triangles that lose a corner to welding are dropped.
pub(crate) fn welded(mesh: &crate::geom::Mesh) -> (Vec<[f32; 3]>, Vec<(usize, [u32; 3])>) {
    use crate::geom::weld;
    let (points, remap) = weld::weld_by(mesh.positions.iter().copied(), weld::f32_key);
    let tris = weld::welded_triangles(&mesh.indices, &remap).collect();
    (points, tris)
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
    /// `print=true` could not make a printable solid.
    #[error("print: {0}")]
    Print(crate::print::PrintError),
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
            crate::preview::PreviewError::BadOptions(detail) => ExportError::InvalidOptions { format: "png", detail },
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
}

/// Triangles a writer writes between two looks at the deadline: often enough
/// that a writer overruns it by well under a millisecond's work, rarely
/// enough that the clock costs nothing measurable.
pub(crate) const DEADLINE_EVERY: usize = 1 << 16;

/// Writes `meshes` in `format` with default options, reserving the output size in `budget` first.
pub fn export(format: Format, meshes: &[NamedMesh], meta: &ExportMeta, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    export_with(format, meshes, meta, &ExportOptions::default(), budget)
}

/// Writes `meshes` in `format` with the request's format options, reserving
/// the output size in `budget` first.
pub fn export_with(
    format: Format,
    meshes: &[NamedMesh],
    meta: &ExportMeta,
    options: &ExportOptions,
    budget: &mut Budget,
) -> Result<Vec<u8>, ExportError> {
    // Writing a large model takes a share of the deadline; a model that
    // arrives here late is not started.
    budget.check_deadline()?;
    let (fitted, moved);
    let (meshes, meta) = if options.fit_unit_box {
        // The camera moves with the model, so the fitted model is seen as the original was.
        let map;
        (fitted, map) = crate::geom::normalize::fit_unit_box(meshes, budget)?;
        moved = ExportMeta { camera: meta.camera.as_ref().map(|c| map.map_or_else(|| c.clone(), |(centre, scale)| c.fitted(centre, scale))), ..meta.clone() };
        (&fitted[..], &moved)
    } else {
        (meshes, meta)
    };
    let g = &options.gltf;
    match format {
        Format::Strips => strips::write_strips(meshes, &options.strips, budget),
        Format::Glb if !g.is_plain() => compact::write_glb(meshes, meta, g, budget),
        Format::Gltf if !g.is_plain() => compact::write_gltf(meshes, meta, g, budget),
        Format::Glb => gltf::write_glb(meshes, meta, budget),
        Format::Gltf => gltf::write_gltf(meshes, meta, budget),
        Format::Stl => stl::write_binary_titled(meshes, &stl::title(meta.provenance.as_ref()), budget),
        Format::StlAscii => stl::write_ascii(meshes, budget),
        Format::Scene => Err(ExportError::InvalidOptions {
            format: "scene",
            detail: "the scene format is written from the model (instances, hierarchy), not from meshes".into(),
        }),
        Format::ThreeMf => threemf::write_3mf(meshes, meta.provenance.as_ref(), budget),
        Format::Ug => ug::write_ug(meshes, budget),
        // The pipeline runs the preview stage itself (to time it) and then
        // `png::write_png` with the same text chunks; this arm serves meshes
        // from outside a render (a decoded strips file) and library callers.
        Format::Png => self::png::write_png(&crate::preview::render(meshes, &options.preview, budget)?, &self::png::text_chunks(meta.provenance.as_ref()), budget),
    }
}

/// An upper bound on the encoded size of a model with this many vertices and
/// triangles in `format`, so the budget can be checked before encoding.
/// `estimated_size(format, 0, 0)` is the fixed per-file overhead.
pub fn estimated_size(format: Format, vertices: u64, triangles: u64) -> u64 {
    let (fixed, per_vertex, per_triangle) = match format {
        Format::Glb => (64 * 1024, 28, 12),
        // base64 inflates the buffer by 4/3.
        Format::Gltf => (64 * 1024, 38, 16),
        Format::Stl => (84, 0, 50),
        Format::StlAscii => (1024, 0, 300),
        // Header, CRC and palette, plus meshoptimizer's worst cases: a vertex
        // block costs at most 4164 bytes per 256 16-byte vertices (and one
        // partial block), a strip at most 5 indices per triangle at 5 bytes
        // each; zstd's worst-case growth fits in the per-vertex slack.
        Format::Strips => (16 * 1024, 20, 25),
        // The hierarchy is sized exactly when written; no meshes are made.
        Format::Scene => (1024, 0, 0),
        // XML text (about 60 bytes a vertex, 45 a triangle) before compression.
        Format::ThreeMf => (4 * 1024, 64, 48),
        // `v vN x y z;` and `f (va vb vc) cN;` lines with shortest-round-trip floats.
        Format::Ug => (4 * 1024, 64, 48),
        // The picture's size depends on the preview options, not the model;
        // the preview stage reserves its framebuffer and output itself.
        Format::Png => (1024, 0, 0),
    };
    vertices
        .saturating_mul(per_vertex)
        .saturating_add(triangles.saturating_mul(per_triangle))
        .saturating_add(fixed)
}

// geom::normalize's tests, which export glTF (a layer above geom).
#[cfg(test)]
mod normalize_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::budget::Limits;
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
            for (format, ext) in
                [(Format::Glb, "glb"), (Format::Gltf, "gltf"), (Format::Stl, "stl"), (Format::StlAscii, "ascii.stl"), (Format::Strips, "strips")]
            {
                let bytes = export(format, &meshes, &meta, &mut Budget::new(Limits::default())).unwrap();
                assert!(bytes.len() as u64 <= estimated_size(format, v, t), "{name}.{ext}: {} > estimate", bytes.len());
                let path = dir.join(format!("{name}.{ext}"));
                std::fs::write(&path, &bytes).unwrap();
                if matches!(format, Format::Glb | Format::Gltf) {
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
