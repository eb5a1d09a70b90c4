//! The `rulemesh` command-line tool (CLI being implemented).

fn main() {
    println!("rulemesh {}", rulemesh::ENGINE_VERSION);
}
