//! Structure Synth's JavaScript scripts (files starting with `#javascript`),
//! run in a sandboxed QuickJS interpreter.
//!
//! Structure Synth's GUI runs such a script with a global `Builder` object
//! that loads an EisenScript file, rewrites it (`define`, `prepend`,
//! `append`, `reset`), builds it and saves pictures of it. This module runs
//! the script and records, for every picture-saving call, the EisenScript
//! text that picture shows: a [`Movie`]. It draws nothing — the texts are
//! parsed and built by [`crate::eisen`] like any other script, so the data
//! flow stays source → script → scene → mesh → bytes.
//!
//! The sandbox (docs/eisenscript.md): no file system (only `Builder.load`,
//! through a [`Loader`] that the caller chooses), no network, no processes
//! (`Builder.execute` is ignored with a warning), no clock (`Date` is
//! removed) and a seeded `Math.random`. The interpreter's heap is limited to
//! half of the request's remaining memory budget (the memory is reserved in
//! the [`Budget`] while the script runs), its stack to [`JS_STACK_BYTES`],
//! and an interrupt handler charges [`JS_STEPS_PER_POLL`] budget steps every
//! time QuickJS polls it and checks the deadline, so `while (true) {}` ends
//! with the typed steps (or deadline) limit error — QuickJS makes that
//! interruption uncatchable by the script.

use crate::core::budget::{Budget, Limit, LimitExceeded};
use crate::core::rng::StreamKey;
use crate::model::EvalError;
use crate::core::{Diagnostic, Span};
use rquickjs::prelude::Opt;
use rquickjs::{Context, Ctx, Exception, Function, Runtime};
use std::cell::RefCell;
use std::path::{Component, Path, PathBuf};
use std::rc::Rc;

/// Budget steps charged each time QuickJS polls the interrupt handler; QuickJS
/// polls once every 10 000 loop iterations or calls (its `JS_INTERRUPT_COUNTER_INIT`).
pub(crate) const JS_STEPS_PER_POLL: u64 = 10_000;

/// The interpreter's stack limit in bytes: deep JavaScript recursion ends in
/// a `RangeError` long before it could overflow a 2 MiB thread stack.
pub(crate) const JS_STACK_BYTES: usize = 256 * 1024;

/// Most warnings kept from one script (`Debug.Info` in a loop must not grow without bound).
const MAX_WARNINGS: usize = 100;

/// The stream site of `Math.random` under the request's seed (no EisenScript action uses it).
const MATH_RANDOM_SITE: u32 = u32::MAX - 1;

pub use crate::eisen::syntax::is_javascript;

/// Where `Builder.load(name)` reads EisenScript from.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum Loader {
    /// No file system (the HTTP and gRPC service): only built-in library
    /// grammars written in EisenScript load, by name (with or without `.es`).
    #[default]
    Library,
    /// The CLI: plain relative paths inside the script's directory.
    Directory(PathBuf),
}

impl Loader {
    /// Reads `name`, refusing absolute paths, `..` and anything outside the
    /// directory, and anything larger than `max_bytes`.
    fn load(&self, name: &str, max_bytes: u64) -> Result<String, EvalError> {
        let fail = |reason: String| EvalError::Load { name: name.to_string(), reason };
        match self {
            Loader::Library => {
                let stem = name.strip_suffix(".es").unwrap_or(name);
                match crate::core::library::source(stem, "es").or(crate::core::library::source(stem, "mdg")).filter(|s| crate::eisen::syntax::looks_like_eisenscript(s)) {
                    Some(s) => Ok(s.to_string()),
                    None => Err(fail(
                        "the render service reads no files; Builder.load only loads built-in library grammars written in EisenScript, and there is none of that name".into(),
                    )),
                }
            }
            Loader::Directory(dir) => {
                let rel = Path::new(name);
                if name.is_empty() || !rel.components().all(|c| matches!(c, Component::Normal(_) | Component::CurDir)) {
                    return Err(fail("only plain relative paths inside the script's directory can be loaded (no `..`, no absolute paths)".into()));
                }
                let path = dir.join(rel);
                let meta = std::fs::metadata(&path).map_err(|e| fail(e.to_string()))?;
                if !meta.is_file() {
                    return Err(fail("not a file".into()));
                }
                Budget::check_value(Limit::SourceBytes, max_bytes, meta.len())?;
                let bytes = std::fs::read(&path).map_err(|e| fail(e.to_string()))?;
                String::from_utf8(bytes).map_err(|_| fail("the file is not valid UTF-8".into()))
            }
        }
    }
}

/// What a JavaScript script made: one EisenScript text per movie frame.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Movie {
    /// The text each picture-saving call showed, in call order.
    pub frames: Vec<String>,
    /// The text of the last `Builder.build()` (what a script that saves no picture shows).
    pub last_build: Option<String>,
    /// Bytes of `frames` and `last_build`, reserved in the budget by [`run`]; the caller releases them.
    pub held_bytes: u64,
    /// Notes: ignored calls (`execute`, GUI-only members), `Debug.Info` messages.
    pub warnings: Vec<Diagnostic>,
    /// Set when a limit stopped the script and the caller asked to truncate:
    /// the frames recorded before it are kept.
    pub truncated: Option<LimitExceeded>,
}

/// The Builder's state, shared by the native functions and the interrupt handler.
struct Shared {
    budget: Budget,
    loader: Loader,
    /// The loaded system as rewritten so far, and as loaded.
    loaded: String,
    original: String,
    movie: Movie,
    /// A limit hit inside a native call: the next poll interrupts the script (uncatchable).
    limit: Option<LimitExceeded>,
    /// A load failure, reported as itself even if the script catches it and fails later.
    load_error: Option<EvalError>,
    random: StreamKey,
    draws: u32,
    warned: Vec<&'static str>,
}

impl Shared {
    /// A fresh Builder state: nothing loaded, no frames, `Math.random` under `seed`.
    fn new(budget: Budget, loader: Loader, seed: u64) -> Shared {
        Shared {
            budget,
            loader,
            loaded: String::new(),
            original: String::new(),
            movie: Movie::default(),
            limit: None,
            load_error: None,
            random: StreamKey::root(seed).child(MATH_RANDOM_SITE, 0),
            draws: 0,
            warned: Vec::new(),
        }
    }

    fn warn(&mut self, message: String) {
        if self.movie.warnings.len() < MAX_WARNINGS {
            self.movie.warnings.push(Diagnostic::warning(Span::new(1, 1), message));
        }
    }

    fn warn_once(&mut self, what: &'static str, message: &str) {
        if !self.warned.contains(&what) {
            self.warned.push(what);
            self.warn(message.to_string());
        }
    }

    /// Records `text` as a frame (or the last build), reserving its bytes.
    fn hold(&mut self, text: String, frame: bool) -> Result<(), LimitExceeded> {
        let bytes = text.len() as u64 + 32;
        self.budget.reserve_memory(bytes)?;
        self.movie.held_bytes += bytes;
        if frame {
            self.movie.frames.push(text);
        } else if let Some(old) = self.movie.last_build.replace(text) {
            let freed = old.len() as u64 + 32;
            self.budget.release_memory(freed);
            self.movie.held_bytes -= freed;
        }
        Ok(())
    }

    /// One Builder call. Errors are limits or load failures.
    fn call(&mut self, op: &str, a: Option<String>, b: Option<String>) -> Result<(), EvalError> {
        let work = 1 + self.loaded.len() as u64 / 64;
        self.budget.charge_steps(work)?;
        let max = self.budget.limits().max_source_bytes;
        let a = a.unwrap_or_default();
        match op {
            "load" => {
                let text = self.loader.load(&a, max)?;
                self.loaded = text.clone();
                self.original = text;
            }
            "define" => self.loaded = define(&self.loaded, &a, &b.unwrap_or_default()),
            "prepend" => self.loaded = format!("{a}\n{}", self.loaded),
            "append" => self.loaded = format!("{}\n{a}", self.loaded),
            "reset" => self.loaded = self.original.clone(),
            "setSize" => {}
            "build" => self.hold(self.loaded.clone(), false)?,
            "renderToFile" | "templateRenderToFile" => {
                // Both build the loaded system and picture it.
                self.hold(self.loaded.clone(), false)?;
                self.hold(self.loaded.clone(), true)?;
            }
            // Raytraces what was built last (nothing built: an empty picture).
            "raytraceToFile" => self.hold(self.movie.last_build.clone().unwrap_or_default(), true)?,
            "execute" => self.warn(format!("Builder.execute(\"{a}\", …) is ignored: rulemesh runs no programs")),
            "world" => self.warn_once("world", "World.addSphere, World.setColor and World.clear draw into Structure Synth's viewer and are ignored"),
            "info" => self.warn(format!("Debug: {a}")),
            _ => {}
        }
        Budget::check_value(Limit::SourceBytes, max, self.loaded.len() as u64)?;
        Ok(())
    }
}

/// Structure Synth's `Builder.define`: replaces `name` by `value` on every
/// line that is not a `#define` line (so the script's own `#define` of the
/// name no longer applies). Whole words only, like rulemesh's `#define`.
fn define(text: &str, name: &str, value: &str) -> String {
    if name.is_empty() {
        return text.to_string();
    }
    let word = |c: char| c.is_alphanumeric() || c == '_';
    let mut out = String::with_capacity(text.len());
    for (i, line) in text.split('\n').enumerate() {
        if i > 0 {
            out.push('\n');
        }
        if line.to_ascii_lowercase().contains("#define") {
            out.push_str(line);
            continue;
        }
        let mut rest = line;
        while let Some(at) = rest.find(name) {
            let before = rest[..at].chars().next_back();
            let after = rest[at + name.len()..].chars().next();
            out.push_str(&rest[..at]);
            if before.is_some_and(word) || after.is_some_and(word) {
                out.push_str(name);
            } else {
                out.push_str(value);
            }
            rest = &rest[at + name.len()..];
        }
        out.push_str(rest);
    }
    out
}

/// The JavaScript side of the Builder: thin wrappers that turn every
/// argument into a string (as Qt's slots receive them) and call the native
/// function. `Date` is removed so no output depends on the clock.
const PRELUDE: &str = r#"(function (native) {
  const S = (v) => String(v);
  // A number within rounding noise of a whole number is written whole, so
  // `define("_md", 20 + c * 3000)` gives `set maxdepth` the integer it needs.
  const N = (v) => (typeof v === "number" && isFinite(v) && Math.abs(v - Math.round(v)) <= 1e-9 * Math.max(1, Math.abs(v))) ? String(Math.round(v)) : String(v);
  const B = {
    load: (f) => native("load", S(f)),
    define: (n, v) => native("define", S(n), N(v)),
    prepend: (t) => native("prepend", S(t)),
    append: (t) => native("append", S(t)),
    reset: () => native("reset"),
    setSize: (w, h) => native("setSize", S(w), S(h)),
    build: () => native("build"),
    render: () => native("build"),
    renderToFile: (f, o) => native("renderToFile", S(f)),
    raytraceToFile: (f, o) => native("raytraceToFile", S(f)),
    templateRenderToFile: (t, f, o) => native("templateRenderToFile", S(f)),
    execute: (f, a, w) => native("execute", S(f)),
  };
  const D = {
    Info: (m) => native("info", S(m)),
    Message: (m) => native("info", S(m)),
    ShowProgress: () => {}, SetProgress: () => {}, HideProgress: () => {},
    Sleep: () => {}, waitForMouseButton: () => {},
  };
  const W = { addSphere: () => native("world"), setColor: () => native("world"), clear: () => native("world") };
  function Vector3(x, y, z) {
    if (!(this instanceof Vector3)) return new Vector3(x, y, z);
    this.x = +x || 0; this.y = +y || 0; this.z = +z || 0;
  }
  Vector3.prototype.length = function () { return Math.sqrt(this.x * this.x + this.y * this.y + this.z * this.z); };
  Vector3.prototype.add = function (v) { this.x += v.x; this.y += v.y; this.z += v.z; };
  Vector3.prototype.toString = function () { return "(" + this.x + "," + this.y + "," + this.z + ")"; };
  globalThis.Builder = Object.freeze(B);
  globalThis.Debug = Object.freeze(D);
  globalThis.World = Object.freeze(W);
  globalThis.Vector3 = Vector3;
  delete globalThis.Date;
})(__rulemesh_builder);
delete globalThis.__rulemesh_builder;
"#;

/// Runs the JavaScript `source` (its `#javascript` line included) under
/// `budget`: memory, steps, deadline and source size are charged as the
/// script runs. `seed` seeds `Math.random`; `truncate` keeps the frames made
/// before a limit instead of failing.
pub fn run(source: &str, loader: Loader, seed: u64, truncate: bool, budget: &mut Budget) -> Result<Movie, EvalError> {
    let remaining = budget.limits().max_memory.saturating_sub(budget.memory());
    let heap = remaining / 2;
    budget.reserve_memory(heap)?;
    let shared = Rc::new(RefCell::new(Shared::new(budget.take(), loader, seed)));
    let result = run_in_sandbox(source, heap, &shared);
    let Shared { budget: mut inner, mut movie, limit, load_error, .. } = shared.replace_with(|s| Shared::new(s.budget.spent(), Loader::Library, 0));
    inner.release_memory(heap);
    *budget = inner;
    let failure = match (limit, load_error, result) {
        (Some(l), _, _) => Some(EvalError::Limit(l)),
        (None, Some(e), Err(_)) => Some(e),
        (None, _, Err(e)) => Some(e),
        (None, _, Ok(())) => None,
    };
    match failure {
        None => Ok(movie),
        Some(EvalError::Limit(l)) if truncate => {
            movie.truncated = Some(l);
            Ok(movie)
        }
        Some(e) => {
            budget.release_memory(movie.held_bytes);
            Err(e)
        }
    }
}

/// Sets up the interpreter and evaluates the script. Errors other than
/// limits and loads (which `shared` records) are script errors.
fn run_in_sandbox(source: &str, heap: u64, shared: &Rc<RefCell<Shared>>) -> Result<(), EvalError> {
    let script_error = |message: String| EvalError::Script { message };
    let rt = Runtime::new().map_err(|e| script_error(format!("cannot start the JavaScript interpreter: {e}")))?;
    rt.set_memory_limit(usize::try_from(heap).unwrap_or(usize::MAX).max(1));
    rt.set_max_stack_size(JS_STACK_BYTES);
    let poll = Rc::clone(shared);
    rt.set_interrupt_handler(Some(Box::new(move || {
        let Ok(mut s) = poll.try_borrow_mut() else { return false };
        if s.limit.is_some() {
            return true;
        }
        match s.budget.charge_steps(JS_STEPS_PER_POLL) {
            Ok(()) => false,
            Err(l) => {
                s.limit = Some(l);
                true
            }
        }
    })));
    let ctx = Context::full(&rt).map_err(|e| script_error(format!("cannot start the JavaScript interpreter: {e}")))?;
    // The `#javascript` line becomes a comment, so line numbers stay the script's.
    let start = source.len() - source.trim_start().len();
    let body = format!("{}//{}", &source[..start], source.get(start + 1..).unwrap_or(""));
    let outcome = ctx.with(|ctx| -> Result<(), EvalError> {
        let setup = || -> rquickjs::Result<()> {
            let native = Rc::clone(shared);
            let builder = Function::new(ctx.clone(), move |ctx: Ctx<'_>, op: String, a: Opt<String>, b: Opt<String>| -> rquickjs::Result<()> {
                let Ok(mut s) = native.try_borrow_mut() else { return Ok(()) };
                match s.call(&op, a.0, b.0) {
                    Ok(()) => Ok(()),
                    Err(EvalError::Limit(l)) => {
                        s.limit = Some(l);
                        Err(Exception::throw_internal(&ctx, &l.to_string()))
                    }
                    Err(e) => {
                        let message = e.to_string();
                        s.load_error = Some(e);
                        Err(Exception::throw_message(&ctx, &message))
                    }
                }
            })?;
            ctx.globals().set("__rulemesh_builder", builder)?;
            let random = Rc::clone(shared);
            let math: rquickjs::Object = ctx.globals().get("Math")?;
            math.set(
                "random",
                Function::new(ctx.clone(), move || -> f64 {
                    let Ok(mut s) = random.try_borrow_mut() else { return 0.0 };
                    s.draws = s.draws.wrapping_add(1);
                    let slot = s.draws;
                    s.random.uniform(slot)
                })?,
            )?;
            ctx.eval::<(), _>(PRELUDE)
        };
        setup().map_err(|e| script_error(format!("cannot set up the Builder: {e}")))?;
        // Sloppy mode, as Qt Script runs them: Structure Synth's examples assign undeclared globals.
        let mut options = rquickjs::context::EvalOptions::default();
        options.strict = false;
        options.filename = Some("script".into());
        match ctx.eval_with_options::<(), _>(body, options) {
            Ok(()) => Ok(()),
            Err(rquickjs::Error::Exception) => {
                let thrown = ctx.catch();
                let text = match Exception::from_value(thrown.clone()) {
                    Ok(ex) => {
                        let message = ex.message().unwrap_or_default();
                        let at = ex.stack().and_then(|s| s.lines().find_map(|l| l.rsplit_once(':').map(|(a, _)| a.rsplit(':').next().unwrap_or("").to_string())));
                        match at.filter(|l| l.parse::<u32>().is_ok()) {
                            Some(line) => format!("line {line}: {message}"),
                            None => message,
                        }
                    }
                    Err(_) => format!("uncaught {:?}", thrown.type_name()),
                };
                if text.contains("out of memory") {
                    // The sandbox's allocator ran out of the memory budget it was given.
                    if let Ok(s) = shared.try_borrow() {
                        return Err(EvalError::Limit(s.budget.memory_refused(0)));
                    }
                }
                Err(script_error(text))
            }
            Err(e) => Err(script_error(e.to_string())),
        }
    });
    drop(ctx);
    drop(rt);
    outcome
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn define_rewrites_whole_words_outside_define_lines() {
        let t = "#define _md 1000\nset maxdepth _md\n_mdx _md";
        assert_eq!(define(t, "_md", "20"), "#define _md 1000\nset maxdepth 20\n_mdx 20");
    }

    #[test]
    fn detection() {
        assert!(is_javascript(b"  #JavaScript\nBuilder.build();"));
        assert!(!is_javascript(b"#define x 1\nbox"));
        assert!(!is_javascript(b""));
    }

    #[test]
    fn directory_loader_rejects_escapes() {
        let l = Loader::Directory(PathBuf::from("."));
        for bad in ["../x.es", "/etc/passwd", "a/../../x.es", ""] {
            assert!(matches!(l.load(bad, 1000), Err(EvalError::Load { .. })), "{bad}");
        }
        assert!(matches!(Loader::Library.load("menger", 1000), Err(EvalError::Load { .. })));
    }
}
