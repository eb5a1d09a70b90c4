//! Build script: compiles the gRPC protocol (with a vendored `protoc`, so no
//! system install is needed) and embeds the built-in grammar library.

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let protoc = protoc_bin_vendored::protoc_bin_path()?;
    std::env::set_var("PROTOC", protoc);
    println!("cargo:rerun-if-changed=proto");
    let out_dir = PathBuf::from(std::env::var("OUT_DIR")?);
    tonic_prost_build::configure()
        // For gRPC server reflection.
        .file_descriptor_set_path(out_dir.join("rulemesh_descriptor.bin"))
        .build_client(true)
        .build_server(true)
        .compile_protos(&["proto/rulemesh/v1/rulemesh.proto"], &["proto"])?;

    println!("cargo:rerun-if-changed=grammars");
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR")?);
    let mut files: Vec<PathBuf> = std::fs::read_dir(root.join("grammars"))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "mdg"))
        .collect();
    files.sort();
    let mut out = String::from("/// The built-in grammars: (name, language, source), sorted by name.\npub static BUILTIN: &[(&str, &str, &str)] = &[\n");
    for f in &files {
        let name = f.file_stem().and_then(|s| s.to_str()).ok_or("grammar file name is not UTF-8")?;
        writeln!(out, "    ({name:?}, \"mdg\", include_str!({:?})),", f.display().to_string())?;
    }
    out.push_str("];\n");
    std::fs::write(PathBuf::from(std::env::var("OUT_DIR")?).join("grammars.rs"), out)?;
    Ok(())
}
