//! Build script: embeds the built-in grammar library (`grammars/` at the
//! workspace root) as `core::library::BUILTIN`.

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // The workspace root: this crate sits at `crates/core`.
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR")?).join("../..").canonicalize()?;
    println!("cargo:rerun-if-changed=../../grammars");
    println!("cargo:rerun-if-changed=../../grammars/icons");
    // The library: every grammar file in `grammars/` under its file stem,
    // and the icon set `grammars/icons/` as `icon-STEM` (a flat name, so it
    // is one path segment in every route; see docs/icons.md), with its file
    // extension. This crate is below the languages, so it does not know
    // which extension is which language: rulemesh-lang's registry
    // (`Language::from_extension`) reads them, and the service lists only
    // the files some language claims. Notes beside the grammars (`.md`,
    // `.txt`) are not embedded.
    let mut entries: Vec<(String, String, PathBuf)> = Vec::new();
    for (dir, prefix) in [("grammars", ""), ("grammars/icons", "icon-")] {
        for f in std::fs::read_dir(root.join(dir))?.filter_map(|e| e.ok().map(|e| e.path())) {
            let Some(extension) = f.extension().and_then(|x| x.to_str()).map(str::to_ascii_lowercase) else {
                continue;
            };
            if !f.is_file() || ["md", "txt"].contains(&extension.as_str()) {
                continue;
            }
            let stem = f.file_stem().and_then(|s| s.to_str()).ok_or("grammar file name is not UTF-8")?;
            entries.push((format!("{prefix}{stem}"), extension, f));
        }
    }
    entries.sort();
    if let Some(w) = entries.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(format!("two library grammars are called `{}`: {} and {}", w[0].0, w[0].2.display(), w[1].2.display()).into());
    }
    let mut out = String::from("/// The built-in grammars: (name, file extension, source), sorted by name.\npub static BUILTIN: &[(&str, &str, &str)] = &[\n");
    for (name, extension, f) in &entries {
        writeln!(out, "    ({name:?}, {extension:?}, include_str!({:?})),", f.display().to_string())?;
    }
    out.push_str("];\n");
    std::fs::write(PathBuf::from(std::env::var("OUT_DIR")?).join("grammars.rs"), out)?;
    Ok(())
}
