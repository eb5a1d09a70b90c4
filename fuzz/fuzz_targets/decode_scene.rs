//! The scene (object-instancing hierarchy) decoder on arbitrary bytes: a
//! hierarchy or a typed error, never a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(h) = rulemesh::export::scene::decode_scene(data) {
        // Counting leaves walks every reference the decoder accepted.
        let _ = h.leaves();
    }
});
