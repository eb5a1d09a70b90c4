//! Which files of a vlab object go with an L-system file: the names a
//! door (the CLI) reads from the main file's folder, so `rulemesh render
//! model/plant.l` finds `model/plant.v`, as cpfg is run on a vlab object
//! (`cpfg -m plant.map plant.l plant.v plant.a`, each object's
//! `specifications`). This module only chooses names; the caller reads.

use std::collections::BTreeMap;

/// Reads the file called `name` beside the main file, if there is one.
pub type Reader<'a> = dyn Fn(&str) -> Option<Vec<u8>> + 'a;

/// Whether `name` is a plain file name (no folder, no `..`), the only
/// names a companion may have.
pub(crate) fn plain_name(name: &str) -> bool {
    !name.is_empty() && !name.contains(['/', '\\']) && name != "." && name != ".."
}

/// The companions of main file `stem.l` with source `source`: `stem.v`,
/// `stem.a`, `stem.map`, the files its `#include` lines name (and theirs),
/// and the files the view names (surfaces, contours, functions), read with
/// `read`; at most `max_bytes` in all.
pub fn companions(stem: &str, source: &[u8], read: &Reader<'_>, max_bytes: u64) -> BTreeMap<String, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut total = 0u64;
    let mut add = |name: String, out: &mut BTreeMap<String, Vec<u8>>| -> Option<Vec<u8>> {
        if !plain_name(&name) || out.contains_key(&name) {
            return None;
        }
        let bytes = read(&name)?;
        total = total.saturating_add(bytes.len() as u64);
        if total > max_bytes {
            return None;
        }
        out.insert(name, bytes.clone());
        Some(bytes)
    };
    let mut pending = vec![source.to_vec()];
    while let Some(text) = pending.pop() {
        for line in String::from_utf8_lossy(&text).lines() {
            let t = line.trim_start();
            if let Some(rest) = t.strip_prefix('#').map(str::trim_start).and_then(|r| r.strip_prefix("include")) {
                let name: String = rest.trim().trim_matches(['"', '<', '>']).to_string();
                if let Some(b) = add(name, &mut out) {
                    pending.push(b);
                }
            }
        }
    }
    for ext in ["a", "map"] {
        add(format!("{stem}.{ext}"), &mut out);
    }
    if let Some(v) = add(format!("{stem}.v"), &mut out) {
        for line in String::from_utf8_lossy(&v).lines() {
            let Some((cmd, rest)) = line.split_once(':') else { continue };
            let words: Vec<&str> = rest.split(|c: char| c.is_whitespace() || c == ',').filter(|w| !w.is_empty()).collect();
            let name = match cmd.trim().to_ascii_lowercase().as_str() {
                "surface" | "contour" | "line" | "tsurface" => words.get(1),
                "function" | "function set" | "background scene" => words.first(),
                _ => None,
            };
            if let Some(n) = name {
                add((*n).to_string(), &mut out);
            }
        }
    }
    out
}
