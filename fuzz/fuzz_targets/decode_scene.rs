//! The scene decoder on arbitrary bytes (versions 1 and 2): a hierarchy and
//! meshes, or a typed error, never a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(h) = rulemesh::decode::scene::decode_scene(data) {
        // Counting leaves walks every reference the decoder accepted.
        let _ = h.leaves();
    }
    // Tessellating every record, under a triangle cap so a tiny file cannot ask for hours.
    let _ = rulemesh::decode::scene::decode_scene_meshes(data, 16, 1_000_000);
});
