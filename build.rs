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
    println!("cargo:rerun-if-changed=grammars/icons");
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR")?);
    // The library: `grammars/*.mdg` under their file stems, and the icon set
    // `grammars/icons/*.mdg` as `icon-STEM` (a flat name, so it is one path
    // segment in every route; see docs/icons.md).
    let mut entries: Vec<(String, PathBuf)> = Vec::new();
    for (dir, prefix) in [("grammars", ""), ("grammars/icons", "icon-")] {
        for f in std::fs::read_dir(root.join(dir))?.filter_map(|e| e.ok().map(|e| e.path())) {
            if f.extension().is_some_and(|x| x == "mdg") {
                let stem = f.file_stem().and_then(|s| s.to_str()).ok_or("grammar file name is not UTF-8")?;
                entries.push((format!("{prefix}{stem}"), f));
            }
        }
    }
    entries.sort();
    if let Some(w) = entries.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(format!("two library grammars are called `{}`: {} and {}", w[0].0, w[0].1.display(), w[1].1.display()).into());
    }
    let mut out = String::from("/// The built-in grammars: (name, language, source), sorted by name.\npub static BUILTIN: &[(&str, &str, &str)] = &[\n");
    for (name, f) in &entries {
        writeln!(out, "    ({name:?}, \"mdg\", include_str!({:?})),", f.display().to_string())?;
    }
    out.push_str("];\n");
    std::fs::write(PathBuf::from(std::env::var("OUT_DIR")?).join("grammars.rs"), out)?;
    Ok(())
}
