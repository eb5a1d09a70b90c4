//! `rulemesh::render` of Context Free designs (CFDG 2.x and 3.x) under
//! tight limits: lex, parse (both syntaxes, the 2.x restart), check,
//! expand, frame and write in every registered format (the options byte
//! picks it, `fuzz/src/lib.rs`) — `svg` and the 2D `png` from the model's
//! drawing as well as the flat 3D formats — must end in a model or a typed
//! error, never a panic or a hang.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| rulemesh_fuzz::render(rulemesh::lang::Language::Cfdg, data));
