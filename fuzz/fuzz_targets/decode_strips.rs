//! The strips decoder on arbitrary bytes: a mesh or a typed error, never a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(d) = rulemesh::decode::strips::decode_strips_full(data) {
        // Whatever decodes must be a consistent mesh: every index in range.
        let n = d.mesh.positions.len();
        assert!(d.mesh.indices.iter().all(|&i| (i as usize) < n), "index out of range in a decoded mesh");
    }
});
