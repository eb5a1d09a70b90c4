//! `rulemesh::render` of Context Free designs (CFDG 2.x and 3.x) under
//! tight limits: lex, parse (both syntaxes, the 2.x restart), check,
//! expand, frame and write — SVG and the 2D PNG from the model's drawing as
//! well as the flat 3D formats — must end in a model or a typed error,
//! never a panic or a hang.
#![no_main]
use libfuzzer_sys::fuzz_target;
use rulemesh::export::Format;

/// The drawing formats first: they are CFDG's own route.
const FORMATS: [Format; 6] = [Format::Svg, Format::Png, Format::Glb, Format::Stl, Format::Scene, Format::Strips];

fuzz_target!(|data: &[u8]| rulemesh_fuzz::render_as(rulemesh::lang::Language::Cfdg, data, &FORMATS));
