//! Cache keys: BLAKE3 of a canonical, length-prefixed encoding of everything
//! that determines a model's bytes.

use crate::core::{Limits, ParamValue};
use crate::export::{ExportOptions, GltfOptions, Instancing, OptionGroup, StripsOptions};
use crate::preview::PreviewOptions;
use crate::print::{PrintOptions, PrinterProfile};
use crate::mesh::MeshLayout;
use crate::lang::Language;
use crate::RenderRequest;
use std::borrow::Cow;
use std::collections::BTreeMap;

/// A 32-byte BLAKE3 digest identifying one model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CacheKey(pub [u8; 32]);

/// Hashes the digest's first eight bytes only. The key is a BLAKE3 digest
/// already, so those bytes are as evenly spread as all 32, and the tables
/// that hold keys seed their own hasher per process: a client choosing
/// sources would need 2^64 work to put two keys in one bucket on purpose.
/// Hashing all 32 bytes (the derived `Hash`, length prefix included) took
/// foldhash's long-input path on every cache insert and lookup (issue 33).
/// Equal keys have equal first bytes, so this agrees with `Eq`.
impl std::hash::Hash for CacheKey {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        let [a, b, c, d, e, f, g, h, ..] = self.0;
        state.write_u64(u64::from_le_bytes([a, b, c, d, e, f, g, h]));
    }
}

impl CacheKey {
    /// The key as lowercase hex.
    pub fn hex(&self) -> String {
        blake3::Hash::from_bytes(self.0).to_hex().to_string()
    }
}

/// Replaces every CRLF with LF, so the same grammar saved on Windows and on
/// Unix shares a key (and renders from identical bytes).
pub fn normalize_source(source: &[u8]) -> Cow<'_, [u8]> {
    // A carriage return at all is rare: one `contains` (a memchr) settles
    // most sources, where scanning every pair of bytes cost a fresh icon
    // request 1 % of its instructions, twice (issue 33).
    if !source.contains(&b'\r') || !source.windows(2).any(|w| w == b"\r\n") {
        return Cow::Borrowed(source);
    }
    let mut out = Vec::with_capacity(source.len());
    let mut i = 0;
    while i < source.len() {
        if source[i] == b'\r' && source.get(i + 1) == Some(&b'\n') {
            i += 1;
            continue;
        }
        out.push(source[i]);
        i += 1;
    }
    Cow::Owned(out)
}

/// A canonical encoder: every field is tagged and length-prefixed, so no two
/// different requests encode to the same bytes.
///
/// Small fields are gathered in a buffer and hashed in one `update`:
/// BLAKE3's digest does not depend on how its input is split, and some
/// eighty small updates per key cost more than the hashing itself (a few
/// per cent of a fresh icon render, issue 33). Large fields (the source)
/// go to the hasher directly, after what the buffer holds.
struct Encoder {
    hasher: blake3::Hasher,
    pending: Vec<u8>,
}

/// Fields at least this long are hashed in place rather than copied into the buffer.
const DIRECT_FROM: usize = 256;

impl Encoder {
    fn new() -> Encoder {
        Encoder { hasher: blake3::Hasher::new(), pending: Vec::with_capacity(1024) }
    }

    fn field(&mut self, tag: &str, bytes: &[u8]) {
        self.pending.extend_from_slice(&(tag.len() as u64).to_le_bytes());
        self.pending.extend_from_slice(tag.as_bytes());
        self.pending.extend_from_slice(&(bytes.len() as u64).to_le_bytes());
        if bytes.len() >= DIRECT_FROM {
            self.hasher.update(&self.pending);
            self.pending.clear();
            self.hasher.update(bytes);
        } else {
            self.pending.extend_from_slice(bytes);
        }
    }

    fn u64(&mut self, tag: &str, v: u64) {
        self.field(tag, &v.to_le_bytes());
    }

    fn finish(mut self) -> CacheKey {
        self.hasher.update(&self.pending);
        CacheKey(*self.hasher.finalize().as_bytes())
    }
}

fn layout_name(l: MeshLayout) -> &'static str {
    match l {
        MeshLayout::Merged => "merged",
        MeshLayout::PerKind => "per-kind",
    }
}

/// The limits that can change a successful model or decide whether there is
/// one. The wall-clock timeout is left out: a model that finished in time is
/// the same model under any longer timeout, and deadline-truncated models are
/// never cached.
fn encode_limits(e: &mut Encoder, l: &Limits) {
    let Limits { max_depth, max_primitives, max_triangles, max_memory, timeout_ms: _, max_source_bytes, max_steps } = *l;
    e.u64("limits.max_depth", max_depth.into());
    e.u64("limits.max_primitives", max_primitives);
    e.u64("limits.max_triangles", max_triangles);
    e.u64("limits.max_memory", max_memory);
    e.u64("limits.max_source_bytes", max_source_bytes);
    e.u64("limits.max_steps", max_steps);
}

/// The key of rendering `source` (already normalised with
/// [`normalize_source`]) as `req` says, with this engine version.
pub fn cache_key(source: &[u8], req: &RenderRequest) -> CacheKey {
    cache_key_of_engine(crate::ENGINE_VERSION, source, req)
}

/// [`cache_key`] as engine version `engine` computes it. The disk and
/// Redis tiers outlive one binary, so a new engine must not find the old
/// one's models: this is how a test checks that the version is part of
/// the key without building a second engine (issue 33).
pub fn cache_key_of_engine(engine: &str, source: &[u8], req: &RenderRequest) -> CacheKey {
    let mut e = model_encoder(engine, source, req, &req.params);
    encode_limits(&mut e, &req.limits);
    e.field("on_limit", if req.on_limit == crate::core::OnLimit::Truncate { b"truncate" } else { b"error" });
    e.finish()
}

/// The key of the model's content: [`cache_key`] without the limits and
/// the `on_limit` mode. Outputs record this one (their provenance): limits
/// differ between doors (the service clamps them to its ceilings), and a
/// model that finished is the same model under any limits that let it, so
/// recording the cache key would make the same model's bytes differ by door.
/// `params` stand in for the request's (the pipeline passes them in their
/// canonical spelling, [`ParamValue::canonical`]).
pub fn model_key(source: &[u8], req: &RenderRequest, params: &BTreeMap<String, ParamValue>) -> CacheKey {
    model_encoder(crate::ENGINE_VERSION, source, req, params).finish()
}

/// Everything but the limits and the `on_limit` mode, encoded, with
/// `params` as the parameters, as engine version `engine` encodes it.
///
/// The request is taken apart field by field, with no `..`: a field added
/// to [`RenderRequest`] or to one of its option structs does not compile
/// until it is encoded here or left out with its reason. Options are
/// encoded only where they apply and only when they differ from what a
/// request had before they existed, so older requests keep their keys (and
/// the golden table its rows).
fn model_encoder(engine: &str, source: &[u8], req: &RenderRequest, params: &BTreeMap<String, ParamValue>) -> Encoder {
    let RenderRequest {
        language,
        seed,
        // Given separately, in their canonical spelling for the model key.
        params: _,
        format,
        // `cache_key` adds the limits and the mode; the model key leaves them out.
        limits: _,
        on_limit: _,
        detail,
        layout,
        export_options,
        // Where the CLI's scripts load files from. The service, whose cache
        // the key serves, always has none (it reads library grammars only).
        script_dir: _,
        frame,
        files,
    } = req;
    let ExportOptions { strips, gltf, fit_unit_box, instancing, print, preview, checksum } = export_options;
    let format = *format;
    let mut e = Encoder::new();
    e.field("engine", engine.as_bytes());
    let language = language.or_else(|| Language::detect(source));
    e.field("language", language.map_or("unknown", Language::name).as_bytes());
    e.field("source", source);
    match seed {
        Some(s) => e.u64("seed", *s),
        None => e.field("seed", b"grammar"),
    }
    e.u64("params", params.len() as u64);
    // BTreeMap iterates in sorted key order.
    for (k, v) in params {
        e.field("param.name", k.as_bytes());
        match v {
            ParamValue::Number(n) => e.field("param.number", &n.to_bits().to_le_bytes()),
            ParamValue::Bool(b) => e.field("param.bool", &[u8::from(*b)]),
            ParamValue::Text(t) => e.field("param.text", t.as_bytes()),
        }
    }
    // Only when given, so every other request keeps its key.
    if let Some(k) = frame {
        e.u64("frame", (*k).into());
    }
    // The files sent with the source (cpfg's view, colour map, includes),
    // in name order; only when there are some, so other keys are unchanged.
    if !files.is_empty() {
        e.u64("files", files.len() as u64);
        for (name, bytes) in files {
            e.field("file.name", name.as_bytes());
            e.field("file.bytes", bytes);
        }
    }
    e.field("format", format.name().as_bytes());
    // The options of the format's own group (the registry's), each only
    // when it can change the bytes; destructured, so a new option field
    // does not compile until it is encoded here.
    let StripsOptions { position_bits, normal_bits, zstd } = *strips;
    let GltfOptions { weld, quantize, compress } = *gltf;
    let PreviewOptions { size, view, background } = *preview;
    match format.info().options {
        OptionGroup::Strips => e.field("strips", &[position_bits, normal_bits, u8::from(zstd)]),
        OptionGroup::Gltf => {
            if !gltf.is_plain() {
                e.field("gltf", &[u8::from(weld), u8::from(quantize), compress as u8]);
            }
            if *instancing == Instancing::Flat {
                e.field("instancing", b"flat");
            }
        }
        OptionGroup::Preview => {
            e.u64("preview.size", size.into());
            e.field("preview.view", view.name().as_bytes());
            e.field("preview.background", crate::preview::background_name(background).as_bytes());
        }
        // Only when asked for, so every scene without it keeps its key.
        OptionGroup::Scene => {
            if *checksum {
                e.field("scene.checksum", b"crc32");
            }
        }
        OptionGroup::None => {}
    }
    if *fit_unit_box {
        e.field("fit", b"unit");
    }
    let PrintOptions { enabled, size_um, report, profile } = *print;
    if enabled {
        e.u64("print.size_um", size_um.into());
        e.field("print.report", &[u8::from(report)]);
        // Only a profile other than the default: requests that name none
        // (or name the default) keep the keys they had before profiles.
        if profile != PrinterProfile::default() {
            let PrinterProfile { min_wall_um, build_um, triangle_ceiling } = profile;
            e.u64("print.min_wall_um", min_wall_um.into());
            for side in build_um {
                e.u64("print.build_um", side.into());
            }
            e.u64("print.triangle_ceiling", triangle_ceiling.into());
        }
    }
    e.u64("detail", (*detail).into());
    e.field("layout", layout_name(*layout).as_bytes());
    e
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::Format;

    #[test]
    fn crlf_is_normalised() {
        assert_eq!(&*normalize_source(b"a\r\nb\rc\n"), b"a\nb\rc\n");
        assert!(matches!(normalize_source(b"a\nb"), Cow::Borrowed(_)));
    }

    #[test]
    fn every_field_changes_the_key() {
        let src = b"startshape A\nrule A { BOX {} }\n";
        let base = RenderRequest::default();
        let k = cache_key(src, &base);
        assert_eq!(k, cache_key(src, &base.clone()));
        let variants: Vec<RenderRequest> = vec![
            RenderRequest { seed: Some(1), ..base.clone() },
            RenderRequest { format: Format::Stl, ..base.clone() },
            RenderRequest { detail: 17, ..base.clone() },
            RenderRequest { layout: MeshLayout::PerKind, ..base.clone() },
            RenderRequest { on_limit: crate::core::OnLimit::Truncate, ..base.clone() },
            RenderRequest { limits: Limits { max_primitives: 5, ..Limits::default() }, ..base.clone() },
            RenderRequest { params: [("n".to_string(), ParamValue::Number(1.0))].into(), ..base.clone() },
        ];
        for v in &variants {
            assert_ne!(k, cache_key(src, v), "{v:?}");
        }
        assert_ne!(k, cache_key(b"startshape B\nrule B { BOX {} }\n", &base));
        // One source byte, the language, the files and the engine version, each alone.
        assert_ne!(k, cache_key(b"startshape A\nrule A { BOX {} }\n ", &base));
        assert_ne!(k, cache_key(src, &RenderRequest { language: Some(Language::Cfdg), ..base.clone() }));
        assert_ne!(k, cache_key(src, &RenderRequest { files: [("a".to_string(), b"x".to_vec())].into(), ..base.clone() }));
        assert_eq!(k, cache_key_of_engine(crate::ENGINE_VERSION, src, &base));
        assert_ne!(k, cache_key_of_engine("0.0.0-other", src, &base));
        // Strips precision is part of a strips model's key.
        let strips = RenderRequest { format: Format::Strips, ..base.clone() };
        let mut coarse = strips.clone();
        coarse.export_options.strips.position_bits = 12;
        assert_ne!(cache_key(src, &strips), cache_key(src, &coarse));
        // Each preview option is part of a png's key (and of no other format's).
        let png = RenderRequest { format: Format::Png, ..base.clone() };
        let previews = [
            crate::preview::PreviewOptions { size: 64, ..Default::default() },
            crate::preview::PreviewOptions { view: crate::preview::View::Top, ..Default::default() },
            crate::preview::PreviewOptions { background: Some([255, 255, 255]), ..Default::default() },
        ];
        for o in previews {
            let mut p = png.clone();
            p.export_options.preview = o;
            assert_ne!(cache_key(src, &png), cache_key(src, &p), "{o:?}");
            let mut g = base.clone();
            g.export_options.preview = o;
            assert_eq!(k, cache_key(src, &g), "{o:?}");
        }
        // The model key leaves the limits and the mode out, and nothing else.
        let limited = RenderRequest { limits: Limits { max_primitives: 5, ..Limits::default() }, on_limit: crate::core::OnLimit::Truncate, ..base.clone() };
        assert_eq!(model_key(src, &base, &base.params), model_key(src, &limited, &limited.params));
        assert_ne!(model_key(src, &base, &base.params), model_key(src, &variants[0], &variants[0].params));
        assert_ne!(model_key(src, &base, &base.params), k);
        // The timeout does not change a finished model.
        let t = RenderRequest { limits: Limits { timeout_ms: 1, ..Limits::default() }, ..base.clone() };
        assert_eq!(k, cache_key(src, &t));
    }

    #[test]
    fn each_printer_profile_value_changes_a_print_key_and_the_default_changes_none() {
        use crate::print::{PrintOptions, PrinterProfile};
        let src = b"startshape A\nrule A { BOX {} }\n";
        let mut print = RenderRequest { format: Format::Stl, ..RenderRequest::default() };
        print.export_options.print = PrintOptions { enabled: true, ..PrintOptions::default() };
        let k = cache_key(src, &print);
        let d = PrinterProfile::default();
        for profile in [PrinterProfile { min_wall_um: 400, ..d }, PrinterProfile { build_um: [250_000, 210_000, 200_000], ..d }, PrinterProfile { triangle_ceiling: 10, ..d }] {
            let mut p = print.clone();
            p.export_options.print.profile = profile;
            assert_ne!(k, cache_key(src, &p), "{profile:?}");
        }
        // The default named explicitly is the same request.
        let named = PrinterProfile::from_request(Some(0.8), Some(&[250.0, 210.0, 210.0]), Some(1_000_000)).expect("valid");
        let mut p = print.clone();
        p.export_options.print.profile = named;
        assert_eq!(k, cache_key(src, &p));
    }
}
