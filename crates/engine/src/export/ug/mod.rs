//! Berkeley UniGrafix (`format=ug`, Séquin (ed.) 1992): the exchange format of the
//! CS285 tools, so rulemesh models open in that lineage of viewers.
//!
//! Each mesh becomes a `def … end;` definition of `v` (vertex) and `f`
//! (face) statements, with a `c` colour statement per distinct vertex colour,
//! and one `i` (instance) statement places it. Vertices are welded by exact
//! position so faces share them, as UG faces name vertices by id.

use crate::export::descriptor::{Capabilities, FormatInfo, OptionGroup, SizeBound, Writer};
use crate::export::pace::{self, Pace};
use crate::export::{ExportError, ExportMeta, ExportOptions};
use crate::core::budget::Budget;
use crate::geom::NamedMesh;
use std::collections::HashMap;
use std::fmt::Write as _;

/// `ug`: `v vN x y z;` and `f (va vb vc) cN;` lines with shortest-round-trip floats.
pub const UG: FormatInfo = FormatInfo {
    name: "ug",
    extensions: &["ug"],
    mime: "text/plain; charset=utf-8",
    caps: Capabilities { text: true, ..Capabilities::NONE },
    options: OptionGroup::None,
    size: SizeBound { fixed: 4 * 1024, per_vertex: 64, per_triangle: 48, per_instance: 0 },
    writer: Writer::Sink { flat: write_ug_with, model: None },
};

/// [`write_ug`] (UniGrafix has no metadata).
fn write_ug_with(meshes: &[NamedMesh], _: &ExportMeta, _: &ExportOptions, budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    write_ug(meshes, budget)
}

/// A UG identifier from a mesh name: letters, digits and `_` only.
fn ident(name: &str, k: usize) -> String {
    let clean: String = name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
    format!("m{k}_{clean}")
}

/// Writes the model as UniGrafix text, reserving its worst-case size first.
pub(crate) fn write_ug(meshes: &[NamedMesh], budget: &mut Budget) -> Result<Vec<u8>, ExportError> {
    let v: u64 = meshes.iter().map(|m| m.mesh.positions.len() as u64).sum();
    let t: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    let bytes = UG.size.of(v, t);
    budget.reserve_memory(bytes)?;
    let text = ug_text(meshes, budget);
    budget.release_memory(bytes);
    text.map(String::into_bytes)
}

/// The UniGrafix text of `meshes`, looking at the deadline as it welds and
/// writes ([`Pace`]).
fn ug_text(meshes: &[NamedMesh], budget: &Budget) -> Result<String, ExportError> {
    let mut s = String::from("{ UniGrafix written by rulemesh }\n");
    let mut colours: HashMap<[u8; 4], String> = HashMap::new();
    let mut defs = Vec::new();
    let mut pace = Pace::new(budget);
    for (k, m) in meshes.iter().enumerate() {
        let name = ident(&m.name, k);
        let _ = writeln!(s, "def {name};");
        let (points, tris) = pace::welded(&m.mesh, &mut pace)?;
        for (n, p) in points.iter().enumerate() {
            pace.step()?;
            let _ = writeln!(s, "  v v{n} {} {} {};", p[0], p[1], p[2]);
        }
        for (k, [a, b, c]) in tris {
            pace.step()?;
            // The colour of the triangle's first corner (flat per face in rulemesh meshes).
            let rgba = m.mesh.indices.get(3 * k).and_then(|&i| m.mesh.colours.get(i as usize)).copied().unwrap_or([255; 4]);
            let next = colours.len();
            let cname = colours.entry(rgba).or_insert_with(|| format!("c{next}")).clone();
            let _ = writeln!(s, "  f (v{a} v{b} v{c}) {cname};");
        }
        s.push_str("end;\n");
        defs.push(name);
    }
    // Colour statements, in first-use order, before the instances that use them.
    let mut cs: Vec<(&[u8; 4], &String)> = colours.iter().collect();
    cs.sort_by_key(|(_, n)| n[1..].parse::<usize>().unwrap_or(0));
    for (rgba, name) in cs {
        let _ = writeln!(s, "c {name} {:.4} {:.4} {:.4};", f64::from(rgba[0]) / 255.0, f64::from(rgba[1]) / 255.0, f64::from(rgba[2]) / 255.0);
    }
    for d in defs {
        let _ = writeln!(s, "i ({d});");
    }
    Ok(s)
}
