//! `rulemesh::render` of cpfg L-systems under tight limits: preprocess,
//! parse, derive (with `{ }` blocks), interpret, mesh and export must end in
//! a model or a typed error, never a panic or a hang.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| rulemesh_fuzz::render(rulemesh::lang::Language::Cpfg, data));
