//! The format registry: [`Format`] and its descriptors are declared once, in
//! the `formats!` table below, one line per format naming the
//! [`FormatInfo`] its folder declares beside its writer. Every list of
//! formats elsewhere reads it: the CLI's `--format` choices and its output
//! extensions, the service's format names, `Content-Type`s and
//! `/v1/models/NAME.EXT` extensions, the request schema's and the OpenAPI
//! document's enums, the cache key's option groups, the pipeline's route
//! and writer, and the golden table's variants. `docs/extending.md` says
//! how a format is added.
//!
//! This module sits above the format folders (`crates/engine/layers.txt`):
//! the folders never name it, so a writer cannot depend on which other
//! formats exist.

use super::descriptor::{FormatInfo, OptionGroup, Writer};
use super::{gltf, png, scene, stl, strips, svg, threemf, ug, usdz, ExportError, ExportOptions, FlatSink, GeometrySink};

/// Declares [`Format`] and the registry from one table: each variant and
/// the descriptor of the format it stands for. Names, extensions, MIME
/// types and everything else a door shows come from the descriptor, never
/// from a second list.
macro_rules! formats {
    ($($(#[$doc:meta])* $variant:ident => $info:expr,)*) => {
        /// Output formats (serialised by name: `"glb"`, `"stl-ascii"`, `"3mf"`, …).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Format {
            $($(#[$doc])* $variant,)*
        }

        /// Every format's descriptor, in the registry's order (that of [`Format::ALL`]).
        pub static FORMATS: &[FormatInfo] = &[$($info),*];

        impl Format {
            /// Every format, in the registry's order: the order of help
            /// text, messages and the schema's enum. The first is the default.
            pub const ALL: &'static [Format] = &[$(Format::$variant),*];

            /// The format's descriptor: name, extensions, MIME type,
            /// capabilities, size bound and writer.
            pub fn info(self) -> &'static FormatInfo {
                match self {
                    $(Format::$variant => &$info,)*
                }
            }
        }
    };
}

formats! {
    /// Binary glTF 2.0 (.glb).
    Glb => gltf::GLB,
    /// glTF 2.0 JSON with the buffer embedded as a data URI (.gltf).
    Gltf => gltf::GLTF,
    /// Binary STL.
    Stl => stl::STL,
    /// ASCII STL.
    StlAscii => stl::STL_ASCII,
    /// rulemesh's compact triangle-strip format for phone clients
    /// (`docs/strips-format.md`): quantised, stripified and compressed.
    Strips => strips::STRIPS,
    /// rulemesh's object-instancing hierarchy (`docs/scene-format.md`), for
    /// L-systems: its size grows with the distinct subtrees, not the segments.
    Scene => scene::SCENE,
    /// 3MF core package (a zip with the model XML in millimetres), for printing.
    ThreeMf => threemf::THREEMF,
    /// USDZ (Pixar's usdz package: USD text in a stored, 64-byte-aligned
    /// zip), for iOS's AR Quick Look and RealityKit: see docs/usdz.md.
    Usdz => usdz::USDZ,
    /// Berkeley UniGrafix text (Séquin (ed.) 1992): `def`/`v`/`f`/`c`/`i` statements.
    Ug => ug::UG,
    /// A PNG picture of the model (the preview stage, `docs/preview.md`):
    /// drawn on the CPU, for icons and order pages.
    Png => png::PNG,
    /// SVG of a 2D design (Context Free's), as `cfdg -V` writes it; the 3D
    /// languages have no drawing and are refused (docs/cfdg.md).
    Svg => svg::SVG,
}

impl Default for Format {
    /// The registry's first format (glb).
    fn default() -> Self {
        Format::ALL[0]
    }
}

impl crate::core::Choice for Format {
    const ALL: &'static [Self] = Format::ALL;
    fn name(self) -> &'static str {
        Format::name(self)
    }
}

impl serde::Serialize for Format {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> serde::Deserialize<'de> for Format {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        <Format as crate::core::Choice>::from_name(&name)
            .ok_or_else(|| serde::de::Error::custom(format!("unknown format `{name}` (known: {})", Format::names().join(", "))))
    }
}

impl Format {
    /// The format's request name (`"glb"`, `"stl-ascii"`, `"3mf"` …), as
    /// requests spell it: the one spelling the cache key, metrics labels and
    /// logs share, so a name cannot drift between them.
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// Every request name, in the registry's order.
    pub fn names() -> Vec<&'static str> {
        Format::ALL.iter().map(|f| f.name()).collect()
    }

    /// The MIME type of the format.
    pub fn content_type(self) -> &'static str {
        self.info().mime
    }

    /// The usual file extension (without the dot): the descriptor's first.
    pub fn extension(self) -> &'static str {
        self.info().extensions.first().copied().unwrap_or(self.name())
    }

    /// Whether the format's bytes are text (and worth compressing).
    pub fn is_text(self) -> bool {
        self.info().caps.text
    }

    /// Picks a format from an output file name's extension.
    pub fn from_extension(path: &std::path::Path) -> Option<Format> {
        Format::from_extension_name(path.extension()?.to_str()?)
    }

    /// The first format of the registry that claims extension `ext`
    /// (without the dot, case-insensitively): `.stl` is binary STL.
    pub fn from_extension_name(ext: &str) -> Option<Format> {
        let ext = ext.to_ascii_lowercase();
        Format::ALL.iter().copied().find(|f| f.info().extensions.contains(&ext.as_str()))
    }

    /// Reads a format as a request may spell it: its name or one of its
    /// extensions (`"scene"` or `"rmscene"`), case-insensitively.
    pub fn parse(text: &str) -> Option<Format> {
        let text = text.trim().to_ascii_lowercase();
        Format::ALL.iter().copied().find(|f| f.name() == text).or_else(|| Format::from_extension_name(&text))
    }

    /// Every extension a format claims, each once, in the registry's order.
    pub fn extensions() -> Vec<&'static str> {
        let mut exts: Vec<&'static str> = Vec::new();
        for ext in FORMATS.iter().flat_map(|f| f.extensions.iter().copied()) {
            if !exts.contains(&ext) {
                exts.push(ext);
            }
        }
        exts
    }

    /// The output file extensions [`Format::from_extension`] knows, with a dot
    /// each, for messages that list them.
    pub fn known_extensions() -> String {
        Format::extensions().iter().map(|e| format!(".{e}")).collect::<Vec<_>>().join(", ")
    }

    /// The picture format: the first that reads the preview options
    /// ([`OptionGroup::Preview`], `png`), which the `size`, `view` and
    /// `background` options need.
    pub fn picture() -> Option<Format> {
        Format::reading(OptionGroup::Preview).first().copied()
    }

    /// The formats that read the option group `group` (for messages and
    /// the schema's rules, e.g. the preview options need `png`).
    pub fn reading(group: OptionGroup) -> Vec<Format> {
        Format::ALL.iter().copied().filter(|f| f.info().options == group).collect()
    }
}

/// The sink that writes meshes in `format` (its merged-mesh writer behind
/// a [`FlatSink`], as every flat render writes them), with the request's
/// format options; or the typed refusal of a format that is not written
/// from meshes: a picture (the pipeline draws the preview stage's picture
/// first and encodes it; export does no stage work), a model, a drawing.
/// For meshes from outside a render (the CLI's `decode` of a strips file,
/// `pipeline::write_meshes`).
pub(crate) fn flat_sink(format: Format, options: &ExportOptions) -> Result<Box<dyn GeometrySink>, ExportError> {
    let info = format.info();
    match info.writer {
        Writer::Sink { flat: write, .. } | Writer::Instancing { meshes: write, .. } => Ok(Box::new(FlatSink::new(info.name, write, *options))),
        Writer::Picture(_) => Err(ExportError::InvalidOptions {
            format: info.name,
            detail: format!("the {} format is written from a picture, which the preview stage draws from meshes first", info.name),
        }),
        Writer::Model(_) => Err(ExportError::InvalidOptions {
            format: info.name,
            detail: format!("the {} format is written from the model (instances, hierarchy), not from meshes", info.name),
        }),
        Writer::Drawing(_) => Err(ExportError::InvalidOptions { format: info.name, detail: no_drawing(info.name, "meshes") }),
    }
}

/// Why a format written from a 2D drawing (`svg`) cannot be written from
/// `what` (a language's models, or meshes from outside a render): the
/// message of the typed refusal, naming the capability that is missing.
pub(crate) fn no_drawing(format: &str, what: &str) -> String {
    format!("the {format} format needs a 2D drawing (capability `drawing`), which only Context Free designs (language `cfdg`) have; {what} are 3D, with no drawing (`png` draws a picture of them)")
}

/// An upper bound on the encoded size of a model with this many vertices and
/// triangles in `format`, so the budget can be checked before encoding.
/// `estimated_size(format, 0, 0)` is the fixed per-file overhead.
pub fn estimated_size(format: Format, vertices: u64, triangles: u64) -> u64 {
    format.info().size.of(vertices, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_extensions_are_unique_and_lower_case() {
        let names = Format::names();
        for (i, n) in names.iter().enumerate() {
            assert!(!names[..i].contains(n), "{n} twice");
            assert_eq!(n.to_ascii_lowercase(), *n);
            assert_eq!(Format::parse(n).map(Format::name), Some(*n));
        }
        for f in Format::ALL {
            assert!(!f.info().extensions.is_empty(), "{f:?} has no extension");
            assert_eq!(Format::from_extension_name(f.extension()).map(Format::content_type), Some(f.content_type()), "{f:?}");
        }
        assert_eq!(Format::from_extension_name("STL"), Some(Format::Stl));
        assert_eq!(Format::parse(" RMSCENE "), Some(Format::Scene));
        assert_eq!(Format::default(), Format::Glb);
    }

    #[test]
    fn choice_names_are_serde_names() {
        for &f in Format::ALL {
            let json = serde_json::to_value(f).expect("serialises");
            assert_eq!(json, serde_json::Value::from(f.name()));
            assert_eq!(serde_json::from_value::<Format>(json).expect("deserialises"), f);
        }
    }
}
