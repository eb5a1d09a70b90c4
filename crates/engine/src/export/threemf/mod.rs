//! 3MF (3D Manufacturing Format) core: a zip package holding the content
//! types, the package relationship and `3D/3dmodel.model`, the XML mesh in
//! millimetres. One `<object>` per mesh, vertices welded by exact position
//! (3MF requires shared vertices for a closed mesh).
//!
//! Colour for colour printers: every distinct triangle colour is a core-spec
//! base material (`<basematerials>`, sRGB `displaycolor`); each object's
//! default is its first triangle's, and a triangle of another colour names
//! its own (`pid`, `p1`). Base materials are in the core specification, so
//! every 3MF consumer must read them (docs/print.md says why not the
//! materials extension's colour groups).
//!
//! Entries carry the zip format's fixed default timestamp, so the same model
//! gives byte-identical files.

use crate::export::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use crate::export::pace::{self, Pace};
use crate::export::{ExportError, ExportMeta, ExportOptions, Provenance, Welded};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use std::fmt::Write as _;
use std::io::Write as _;

/// `3mf`: XML text (about 60 bytes a vertex, 45 a triangle) before
/// compression.
pub(crate) const THREEMF: FormatInfo = FormatInfo {
    name: "3mf",
    extensions: &["3mf"],
    mime: "model/3mf",
    caps: Capabilities::NONE,
    options: OptionGroup::None,
    size: SizeBound { fixed: 4 * 1024, per_vertex: 64, per_triangle: 48, per_instance: 0 },
    writer: Writer::Sink { flat: write_3mf_with, model: None },
};

/// [`write_3mf`] with the model's provenance as metadata.
fn write_3mf_with(meshes: &[NamedMesh], meta: &ExportMeta, _: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_3mf(meshes, meta.provenance.as_ref(), budget)
}

const CONTENT_TYPES: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>
"#;

const RELS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>
"#;

/// The namespace of rulemesh's own `<metadata>` names (3MF requires names
/// that are not the core specification's to be namespace-qualified).
pub(crate) const PROVENANCE_NAMESPACE: &str = "https://rulemesh.dev/3mf/provenance";

/// Escapes text for an XML attribute or element body.
fn xml_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

/// The resource id of the one `<basematerials>` group; objects follow it.
const MATERIALS_ID: usize = 1;

/// Bytes a base material's element takes at most.
const MATERIAL_BYTES: u64 = 64;

/// Bytes a triangle's own colour (` pid="1" p1="…"`) adds at most.
const TRIANGLE_COLOUR_BYTES: u64 = 24;

/// The colour of triangle `k` of `mesh` ([`crate::geom::Mesh::triangle_colour`]),
/// linear RGBA8; opaque white for a mesh without colours.
fn triangle_colour(mesh: &crate::geom::Mesh, k: usize) -> [u8; 4] {
    mesh.triangle_colour(k).unwrap_or([255; 4])
}

/// The distinct triangle colours of `meshes` in order of first use (the
/// base materials), and how many triangles differ from their object's
/// default (the first triangle's colour).
fn palette(meshes: &[NamedMesh]) -> (Vec<[u8; 4]>, u64) {
    let mut colours = Vec::new();
    let mut seen = std::collections::HashSet::new();
    let mut own = 0;
    for m in meshes {
        let first = triangle_colour(&m.mesh, 0);
        for k in 0..m.mesh.triangle_count() {
            let c = triangle_colour(&m.mesh, k);
            own += u64::from(c != first);
            if seen.insert(c) {
                colours.push(c);
            }
        }
    }
    (colours, own)
}

/// A linear RGBA8 colour as 3MF's sRGB `#RRGGBB` (`#RRGGBBAA` when not
/// opaque; alpha is not gamma-encoded).
fn display_colour(c: [u8; 4]) -> String {
    let srgb = |v: u8| {
        let l = f64::from(v) / 255.0;
        let s = if l <= 0.003_130_8 { 12.92 * l } else { 1.055 * libm::pow(l, 1.0 / 2.4) - 0.055 };
        (s * 255.0).round().clamp(0.0, 255.0) as u8
    };
    let [r, g, b] = [srgb(c[0]), srgb(c[1]), srgb(c[2])];
    match c[3] {
        255 => format!("#{r:02X}{g:02X}{b:02X}"),
        a => format!("#{r:02X}{g:02X}{b:02X}{a:02X}"),
    }
}

/// The model XML for `meshes` (each with its welded points and triangles,
/// `welded`) coloured from `colours` (their [`palette`]), with the core
/// `Application` metadata and, when given, the model's provenance as
/// `rulemesh:` metadata.
fn model_xml(meshes: &[NamedMesh], welded: &[Welded], colours: &[[u8; 4]], provenance: Option<&Provenance>, pace: &mut Pace<'_>) -> Result<String, ExportError> {
    let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"millimeter\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\"");
    if provenance.is_some() {
        let _ = write!(s, " xmlns:rulemesh=\"{PROVENANCE_NAMESPACE}\"");
    }
    s.push_str(">\n");
    let _ = writeln!(s, "<metadata name=\"Application\">{}</metadata>", xml_escape(&Provenance::engine()));
    for (name, value) in provenance.map(Provenance::pairs).unwrap_or_default() {
        let _ = writeln!(s, "<metadata name=\"{name}\">{}</metadata>", xml_escape(&value));
    }
    s.push_str("<resources>\n");
    let index: std::collections::HashMap<[u8; 4], usize> = colours.iter().enumerate().map(|(i, c)| (*c, i)).collect();
    let _ = writeln!(s, "<basematerials id=\"{MATERIALS_ID}\">");
    for c in colours {
        let colour = display_colour(*c);
        let _ = writeln!(s, "<base name=\"{colour}\" displaycolor=\"{colour}\"/>");
    }
    s.push_str("</basematerials>\n");
    let mut ids = Vec::new();
    for (k, (m, (points, tris))) in meshes.iter().zip(welded).enumerate().filter(|(_, (m, _))| m.mesh.triangle_count() > 0) {
        let id = MATERIALS_ID + k + 1;
        ids.push(id);
        let default = index.get(&triangle_colour(&m.mesh, 0)).copied().unwrap_or(0);
        let _ = writeln!(s, "<object id=\"{id}\" type=\"model\" pid=\"{MATERIALS_ID}\" pindex=\"{default}\"><mesh><vertices>");
        for p in points {
            pace.step()?;
            let _ = writeln!(s, "<vertex x=\"{}\" y=\"{}\" z=\"{}\"/>", p[0], p[1], p[2]);
        }
        s.push_str("</vertices><triangles>\n");
        for &(t, [a, b, c]) in tris {
            pace.step()?;
            match index.get(&triangle_colour(&m.mesh, t)).copied().unwrap_or(default) {
                p if p == default => {
                    let _ = writeln!(s, "<triangle v1=\"{a}\" v2=\"{b}\" v3=\"{c}\"/>");
                }
                p => {
                    let _ = writeln!(s, "<triangle v1=\"{a}\" v2=\"{b}\" v3=\"{c}\" pid=\"{MATERIALS_ID}\" p1=\"{p}\"/>");
                }
            }
        }
        s.push_str("</triangles></mesh></object>\n");
    }
    s.push_str("</resources>\n<build>");
    for id in ids {
        let _ = write!(s, "<item objectid=\"{id}\"/>");
    }
    s.push_str("</build>\n</model>\n");
    Ok(s)
}


/// Writes a 3MF package (with `provenance` as metadata when given),
/// reserving its worst-case size first.
pub(crate) fn write_3mf(meshes: &[NamedMesh], provenance: Option<&Provenance>, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    // 3MF shares vertices: the estimate counts the welded ones (a printed
    // solid's flat mesh has three positions per triangle, about six times
    // as many as it shares; counted unwelded, the Sierpinski bush's million
    // triangles asked for 480 MB). The welded copy is reserved first.
    let positions: u64 = meshes.iter().map(|m| m.mesh.positions.len() as u64).sum();
    let t: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    let weld_bytes = positions.saturating_mul(12 + 4).saturating_add(t.saturating_mul(20));
    budget.reserve_memory(weld_bytes)?;
    let mut pace = Pace::new(budget);
    let welded = match meshes.iter().map(|m| pace::welded(&m.mesh, &mut pace)).collect::<Result<Vec<Welded>, _>>() {
        Ok(w) => w,
        Err(e) => {
            budget.release_memory(weld_bytes);
            return Err(e);
        }
    };
    let v: u64 = welded.iter().map(|w| w.0.len() as u64).sum();
    // The XML text and the zip each hold about the estimate (plus the
    // colours: the materials and the triangles of their own colour); both
    // live at once.
    let (colours, own) = palette(meshes);
    let colour_bytes = (colours.len() as u64).saturating_mul(MATERIAL_BYTES).saturating_add(own.saturating_mul(TRIANGLE_COLOUR_BYTES));
    let bytes = THREEMF.size.of(v, t).saturating_add(colour_bytes).saturating_mul(2);
    if let Err(e) = budget.reserve_memory(bytes) {
        budget.release_memory(weld_bytes);
        return Err(e.into());
    }
    let out = package(meshes, &welded, &colours, provenance, budget);
    budget.release_memory(bytes.saturating_add(weld_bytes));
    out
}

/// The zip's output, looking at the deadline at each piece the compressor
/// writes out (deflate runs at tens of megabytes a second, so a 200 MB
/// model is seconds of it). The deadline is looked at below the compressor,
/// not by feeding it the XML in pieces: the pieces would change where
/// deflate's blocks end, and so the file's bytes.
struct Paced<'a> {
    out: std::io::Cursor<Vec<u8>>,
    budget: &'a Budget,
    late: &'a std::cell::Cell<Option<crate::core::budget::LimitExceeded>>,
}

impl std::io::Write for Paced<'_> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if let Err(e) = self.budget.check_deadline() {
            self.late.set(Some(e));
            return Err(std::io::Error::other("deadline"));
        }
        self.out.write(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.out.flush()
    }
}

impl std::io::Seek for Paced<'_> {
    fn seek(&mut self, pos: std::io::SeekFrom) -> std::io::Result<u64> {
        self.out.seek(pos)
    }
}

/// The XML of `meshes` and its zip package, looking at the deadline as it
/// writes the text and as the compressor writes its output.
fn package(meshes: &[NamedMesh], welded: &[Welded], colours: &[[u8; 4]], provenance: Option<&Provenance>, budget: &Budget) -> Result<Vec<u8>, ExportError> {
    let xml = model_xml(meshes, welded, colours, provenance, &mut Pace::new(budget))?;
    let late = std::cell::Cell::new(None);
    let mut zip = zip::ZipWriter::new(Paced { out: std::io::Cursor::new(Vec::new()), budget, late: &late });
    let options = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
    let fail = |e: &dyn std::fmt::Display| match late.take() {
        Some(late) => ExportError::from(late),
        None => ExportError::TooLarge { format: THREEMF.name, detail: e.to_string() },
    };
    for (name, body) in [("[Content_Types].xml", CONTENT_TYPES), ("_rels/.rels", RELS), ("3D/3dmodel.model", xml.as_str())] {
        if let Err(e) = zip.start_file(name, options) {
            return Err(fail(&e));
        }
        if let Err(e) = zip.write_all(body.as_bytes()) {
            return Err(fail(&e));
        }
    }
    match zip.finish() {
        Ok(paced) => Ok(paced.out.into_inner()),
        Err(e) => Err(fail(&e)),
    }
}
