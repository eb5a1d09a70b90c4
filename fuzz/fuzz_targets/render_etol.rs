//! `rulemesh::render` of Etol sources under tight limits: parse, evaluate,
//! mesh and export must end in a model or a typed error, never a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| rulemesh_fuzz::render(rulemesh::lang::Language::Etol, data));
