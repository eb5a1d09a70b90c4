//! Decode-time benchmark of the Rust strips decoder (run by `scripts/bench-sizes`):
//! `decode_strips FILE...` decodes each file repeatedly for at least 0.2 s and
//! prints `FILE triangles ns_per_decode`, one line per file.

use std::time::{Duration, Instant};

fn main() -> std::process::ExitCode {
    for path in std::env::args().skip(1) {
        let bytes = match std::fs::read(&path) {
            Ok(b) => b,
            Err(e) => {
                eprintln!("{path}: {e}");
                return std::process::ExitCode::FAILURE;
            }
        };
        let triangles = match rulemesh::decode::decode_strips(&bytes) {
            Ok(m) => m.triangle_count(),
            Err(e) => {
                eprintln!("{path}: {e}");
                return std::process::ExitCode::FAILURE;
            }
        };
        let start = Instant::now();
        let mut runs = 0u32;
        while start.elapsed() < Duration::from_millis(200) || runs < 5 {
            let m = rulemesh::decode::decode_strips(std::hint::black_box(&bytes));
            std::hint::black_box(&m);
            runs += 1;
        }
        println!("{path} {triangles} {}", start.elapsed().as_nanos() / u128::from(runs));
    }
    std::process::ExitCode::SUCCESS
}
