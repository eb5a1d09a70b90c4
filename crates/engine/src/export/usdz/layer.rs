//! The default layer of a USDZ package, as USD text (`usda`; Pixar
//! Animation Studios, *Universal Scene Description*, openusd.org, the
//! `.usda` grammar of `pxr/usd/sdf/textFileFormat.yy`).
//!
//! The stage: stage metadata (`defaultPrim`, `metersPerUnit = 1`,
//! `upAxis = "Y"`, the provenance in `customLayerData`), one `Xform`
//! named [`ROOT`] holding a `Scope` of materials (one `UsdPreviewSurface`
//! per distinct triangle colour) and one `Mesh` prim per mesh and colour:
//! its points, vertex normals, triangles, extent, constant
//! `primvars:displayColor` and the binding of its colour's material. A
//! mesh of several colours is split by colour, since a material binds a
//! whole prim (a `GeomSubset` per colour would keep one prim per mesh;
//! whole prims are the simpler form every reader binds).

pub(super) use crate::export::pace::Pace;
use crate::export::{ExportError, ExportMeta, Provenance};
use crate::geom::{Mesh, NamedMesh};
use std::collections::HashMap;
use std::fmt::Write as _;

/// The default prim: every mesh and material is below it.
pub(crate) const ROOT: &str = "Model";

/// A mesh's triangles of one colour, re-indexed over the vertices they use.
pub(super) struct Group {
    /// The triangles' colour (linear RGBA8).
    pub colour: [u8; 4],
    /// The mesh's vertex indices this group uses, in first-use order.
    pub vertices: Vec<u32>,
    /// Three indices into `vertices` per triangle.
    pub indices: Vec<u32>,
}

/// Splits `mesh` by triangle colour, groups in order of first use (white
/// for a mesh without colours), keeping `pace`.
pub(super) fn groups(mesh: &Mesh, pace: &mut Pace<'_>) -> Result<Vec<Group>, ExportError> {
    let mut out: Vec<Group> = Vec::new();
    let mut maps: Vec<HashMap<u32, u32>> = Vec::new();
    let mut by_colour: HashMap<[u8; 4], usize> = HashMap::new();
    for (k, tri) in mesh.indices.chunks_exact(3).enumerate() {
        pace.step()?;
        let colour = mesh.triangle_colour(k).unwrap_or([255; 4]);
        let g = *by_colour.entry(colour).or_insert_with(|| {
            out.push(Group { colour, vertices: Vec::new(), indices: Vec::new() });
            maps.push(HashMap::new());
            out.len() - 1
        });
        let (group, map) = (&mut out[g], &mut maps[g]);
        for &i in tri {
            let next = group.vertices.len() as u32;
            let local = *map.entry(i).or_insert(next);
            if local == next {
                group.vertices.push(i);
            }
            group.indices.push(local);
        }
    }
    Ok(out)
}

/// A float as USD text, at most 16 characters: the shortest text that
/// reads back to the same `f32`, in positional notation where that is
/// short (magnitudes from 1e-5 to 1e7) and in exponent notation elsewhere,
/// so the size bound can count characters per number.
pub(super) fn float(out: &mut String, x: f32) {
    let a = x.abs();
    if x == 0.0 {
        out.push('0');
    } else if (1e-5..1e7).contains(&a) {
        let _ = write!(out, "{x}");
    } else {
        let _ = write!(out, "{x:e}");
    }
}

/// Writes `(x, y, z)`.
fn triple(out: &mut String, v: [f32; 3]) {
    out.push('(');
    float(out, v[0]);
    out.push_str(", ");
    float(out, v[1]);
    out.push_str(", ");
    float(out, v[2]);
    out.push(')');
}

/// A colour channel (linear RGBA8) as a float in `[0, 1]`.
fn channel(v: u8) -> f32 {
    f32::from(v) / 255.0
}

/// A colour's RGB as a USD `color3f`.
fn rgb(c: [u8; 4]) -> [f32; 3] {
    [channel(c[0]), channel(c[1]), channel(c[2])]
}

/// The prim name of a colour's material: `Colour_` and its RGBA8 in hex,
/// unique per colour and the same in every file.
pub(super) fn material_name(c: [u8; 4]) -> String {
    format!("Colour_{:02x}{:02x}{:02x}{:02x}", c[0], c[1], c[2], c[3])
}

/// Escapes text for a double-quoted USD string (backslash escapes, as
/// `textFileFormat.ll` reads them).
fn quoted(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\x{:02x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The layer's header: stage metadata, with the engine and, when given, the
/// provenance (language, seed, parameters, model key) and truncation in
/// `customLayerData.rulemesh`.
pub(super) fn header(out: &mut String, meta: &ExportMeta) {
    out.push_str("#usda 1.0\n(\n    customLayerData = {\n        dictionary rulemesh = {\n");
    let _ = writeln!(out, "            string engine = {}", quoted(&Provenance::engine()));
    if let Some(p) = &meta.provenance {
        let _ = writeln!(out, "            string language = {}", quoted(p.language.name()));
        let _ = writeln!(out, "            string model_key = {}", quoted(&p.model_key));
        let _ = writeln!(out, "            string params = {}", quoted(&p.params_json()));
        let _ = writeln!(out, "            string seed = {}", quoted(&p.seed.to_string()));
    }
    if meta.truncated {
        out.push_str("            bool truncated = 1\n");
    }
    out.push_str("        }\n    }\n");
    let _ = writeln!(out, "    defaultPrim = \"{ROOT}\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n)\n");
    let _ = writeln!(out, "def Xform \"{ROOT}\" (\n    kind = \"component\"\n)\n{{");
}

/// The materials scope: one `UsdPreviewSurface` per colour (diffuse colour
/// and opacity from the colour, metallic 0 and roughness 0.8 as the glTF
/// writers' material).
pub(super) fn materials(out: &mut String, colours: &[[u8; 4]]) {
    out.push_str("    def Scope \"Materials\"\n    {\n");
    for &c in colours {
        let name = material_name(c);
        let _ = writeln!(out, "        def Material \"{name}\"\n        {{");
        let _ = writeln!(out, "            token outputs:surface.connect = </{ROOT}/Materials/{name}/Surface.outputs:surface>\n");
        out.push_str("            def Shader \"Surface\"\n            {\n                uniform token info:id = \"UsdPreviewSurface\"\n");
        out.push_str("                color3f inputs:diffuseColor = ");
        triple(out, rgb(c));
        out.push_str("\n                float inputs:metallic = 0\n");
        if c[3] < 255 {
            out.push_str("                float inputs:opacity = ");
            float(out, channel(c[3]));
            out.push('\n');
        }
        out.push_str("                float inputs:roughness = 0.8\n                token outputs:surface\n            }\n        }\n");
    }
    out.push_str("    }\n");
}

/// One `Mesh` prim named `name`: `group`'s triangles of `mesh`, their
/// vertex normals (when the mesh has them), constant display colour and
/// opacity, and, when `bind`, its colour's material bound (a prototype's
/// mesh is bound by its instances instead: a binding may not reach out of
/// a referenced layer). Keeps `pace` per index and vertex written.
pub(super) fn mesh_prim(out: &mut String, name: &str, mesh: &NamedMesh, group: &Group, bind: bool, pace: &mut Pace<'_>) -> Result<(), ExportError> {
    let m = &mesh.mesh;
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for &v in &group.vertices {
        let p = m.positions.get(v as usize).ok_or_else(|| invalid(mesh, "index out of range"))?;
        for a in 0..3 {
            lo[a] = lo[a].min(p[a]);
            hi[a] = hi[a].max(p[a]);
        }
    }
    match bind {
        true => {
            let _ = writeln!(out, "\n    def Mesh \"{name}\" (\n        prepend apiSchemas = [\"MaterialBindingAPI\"]\n    )\n    {{");
        }
        false => {
            let _ = writeln!(out, "\n    def Mesh \"{name}\"\n    {{");
        }
    }
    out.push_str("        float3[] extent = [");
    triple(out, lo);
    out.push_str(", ");
    triple(out, hi);
    out.push_str("]\n        int[] faceVertexCounts = [");
    for k in 0..group.indices.len() / 3 {
        out.push_str(if k == 0 { "3" } else { ", 3" });
    }
    out.push_str("]\n        int[] faceVertexIndices = [");
    for (k, i) in group.indices.iter().enumerate() {
        pace.step()?;
        if k > 0 {
            out.push_str(", ");
        }
        let _ = write!(out, "{i}");
    }
    out.push_str("]\n");
    if bind {
        let _ = writeln!(out, "        rel material:binding = </{ROOT}/Materials/{}>", material_name(group.colour));
    }
    if !m.normals.is_empty() {
        out.push_str("        normal3f[] normals = [");
        list(out, &m.normals, &group.vertices, mesh, pace)?;
        out.push_str("] (\n            interpolation = \"vertex\"\n        )\n");
    }
    out.push_str("        point3f[] points = [");
    list(out, &m.positions, &group.vertices, mesh, pace)?;
    out.push_str("]\n        color3f[] primvars:displayColor = [");
    triple(out, rgb(group.colour));
    out.push_str("] (\n            interpolation = \"constant\"\n        )\n");
    if group.colour[3] < 255 {
        out.push_str("        float[] primvars:displayOpacity = [");
        float(out, channel(group.colour[3]));
        out.push_str("] (\n            interpolation = \"constant\"\n        )\n");
    }
    out.push_str("        uniform token subdivisionScheme = \"none\"\n    }\n");
    Ok(())
}

/// Writes `values[v]` for each `v` of `vertices`, comma-separated.
fn list(out: &mut String, values: &[[f32; 3]], vertices: &[u32], mesh: &NamedMesh, pace: &mut Pace<'_>) -> Result<(), ExportError> {
    for (k, &v) in vertices.iter().enumerate() {
        pace.step()?;
        if k > 0 {
            out.push_str(", ");
        }
        triple(out, *values.get(v as usize).ok_or_else(|| invalid(mesh, "index out of range"))?);
    }
    Ok(())
}

/// An [`ExportError::InvalidMesh`] for `mesh`.
pub(super) fn invalid(mesh: &NamedMesh, detail: &str) -> ExportError {
    ExportError::InvalidMesh { name: mesh.name.clone(), detail: detail.to_string() }
}

/// Closes the root prim.
pub(super) fn footer(out: &mut String) {
    out.push_str("}\n");
}
