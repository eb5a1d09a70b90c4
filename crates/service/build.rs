//! Build script: compiles the gRPC protocol (`proto/` at the workspace root)
//! with a vendored `protoc`, so no system install is needed.

use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let protoc = protoc_bin_vendored::protoc_bin_path()?;
    std::env::set_var("PROTOC", protoc);
    println!("cargo:rerun-if-changed=../../proto");
    let out_dir = PathBuf::from(std::env::var("OUT_DIR")?);
    tonic_prost_build::configure()
        // For gRPC server reflection.
        .file_descriptor_set_path(out_dir.join("rulemesh_descriptor.bin"))
        .build_client(true)
        .build_server(true)
        .compile_protos(&["../../proto/rulemesh/v1/rulemesh.proto"], &["../../proto"])?;
    Ok(())
}
