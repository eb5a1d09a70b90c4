//! In-process throughput of fresh renders (issue 33), run by
//! `scripts/bench throughput`: `throughput GRAMMAR [SECONDS] [FORMAT,...]` renders
//! the grammar (grammars/gem.mdg) in every phone and print format (or the
//! formats listed; the first is the one the export ratios divide by), each render
//! with a new seed so that nothing a cache could keep is reused, and prints
//! one Markdown table: CPU per render, renders a second per core, and the
//! median of each stage.
//!
//! The formats take turns in rounds of [`BATCH`] renders until SECONDS have
//! passed, so that a change in the machine's load (it is shared) falls on
//! every format alike and the ratios between formats (strips export over
//! glb export) are measured under the same conditions. CPU time is this
//! thread's own (`CLOCK_THREAD_CPUTIME_ID`), not wall time: a render runs
//! on the calling thread, and time the thread spent waiting for a core
//! another process held is not the render's cost. The stage columns are
//! medians of the pipeline's own wall-clock laps (`PhaseTimes`).

use rulemesh::core::timing::Phase;
use rulemesh::export::Format;
use rulemesh::lang::Language;
use rulemesh::{render, RenderRequest};
use std::process::ExitCode;
use std::time::{Duration, Instant};

/// Renders per turn of one format.
const BATCH: u64 = 20;

/// The formats measured, in table order: every format issue 33 names.
const FORMATS: [&str; 7] = ["glb", "gltf", "stl", "strips", "scene", "3mf", "png"];

/// This thread's CPU time so far (`CLOCK_THREAD_CPUTIME_ID`). Not
/// `/proc/thread-self/schedstat`: the kernel brings that figure up to date
/// only at a scheduler tick (4 ms at 250 Hz), longer than a turn of the
/// cheap formats, whereas `clock_gettime` adds the running slice.
fn thread_cpu() -> Result<Duration, String> {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `ts` is a valid, writable `timespec` that outlives the call,
    // and CLOCK_THREAD_CPUTIME_ID is a clock every Linux kernel since 2.6.12 has.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    if rc != 0 {
        return Err(format!("clock_gettime: {}", std::io::Error::last_os_error()));
    }
    Ok(Duration::new(ts.tv_sec as u64, ts.tv_nsec as u32))
}

/// What one format's renders added up to.
#[derive(Default)]
struct Tally {
    renders: u64,
    cpu: Duration,
    bytes: usize,
    triangles: u64,
    /// Every render's wall time of each stage, by [`Phase::ALL`]'s order.
    stages: Vec<[Duration; 6]>,
}

/// The median of a list of durations (zero for none).
fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v.get(v.len() / 2).copied().unwrap_or_default()
}

fn ms(d: Duration) -> String {
    format!("{:.3}", d.as_secs_f64() * 1000.0)
}

fn run() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let path = args.next().ok_or("usage: throughput GRAMMAR [SECONDS] [FORMAT,...]")?;
    let seconds: f64 = args.next().map(|s| s.parse().map_err(|e| format!("SECONDS: {e}"))).transpose()?.unwrap_or(10.0);
    let source = std::fs::read(&path).map_err(|e| format!("{path}: {e}"))?;
    // Named by the file's extension, as the service names every request's
    // language: without it each render would sniff the source
    // (`Language::detect`, about 6K instructions a render), which no
    // request the service serves pays.
    let language = Language::from_extension(std::path::Path::new(&path));
    let names: Vec<String> = match args.next() {
        Some(list) => list.split(',').map(str::to_owned).collect(),
        None => FORMATS.iter().map(|n| n.to_string()).collect(),
    };
    let formats: Vec<Format> = names.iter().map(|n| Format::parse(n).ok_or(format!("unknown format {n}"))).collect::<Result<_, _>>()?;
    let mut tallies: Vec<Tally> = formats.iter().map(|_| Tally::default()).collect();
    let mut seed = 1u64;
    // Warm up: code, allocator and page faults, once per format, not counted.
    for &format in &formats {
        for _ in 0..BATCH {
            let req = RenderRequest { format, seed: Some(seed), language, ..RenderRequest::default() };
            render(&source, &req).map_err(|e| format!("{}: {e}", format.name()))?;
            seed += 1;
        }
    }
    let start = Instant::now();
    while start.elapsed().as_secs_f64() < seconds {
        for (format, tally) in formats.iter().zip(tallies.iter_mut()) {
            let cpu0 = thread_cpu()?;
            for _ in 0..BATCH {
                let req = RenderRequest { format: *format, seed: Some(seed), language, ..RenderRequest::default() };
                seed += 1;
                let out = render(&source, &req).map_err(|e| format!("{}: {e}", format.name()))?;
                tally.bytes = out.bytes.len();
                tally.triangles = out.triangles;
                tally.stages.push(Phase::ALL.map(|p| out.phases.get(p)));
            }
            tally.cpu += thread_cpu()?.saturating_sub(cpu0);
            tally.renders += BATCH;
        }
    }
    println!("| format | bytes | triangles | renders | CPU ms / render | renders/s per core | parse | eval | mesh | preview | export | export / glb's | mesh + export / glb's |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let stage = |t: &Tally, p: Phase| median(t.stages.iter().map(|s| s[Phase::ALL.iter().position(|q| *q == p).unwrap_or(0)]).collect());
    let glb_export = stage(&tallies[0], Phase::Export);
    let glb_both = glb_export + stage(&tallies[0], Phase::Mesh);
    for (format, t) in formats.iter().zip(&tallies) {
        let per = t.cpu.as_secs_f64() / t.renders.max(1) as f64;
        let export = stage(t, Phase::Export);
        println!(
            "| {} | {} | {} | {} | {:.3} | {:.0} | {} | {} | {} | {} | {} | {:.2} | {:.2} |",
            format.name(),
            t.bytes,
            t.triangles,
            t.renders,
            per * 1000.0,
            1.0 / per.max(1e-12),
            ms(stage(t, Phase::Parse)),
            ms(stage(t, Phase::Eval)),
            ms(stage(t, Phase::Mesh)),
            ms(stage(t, Phase::Preview)),
            ms(export),
            export.as_secs_f64() / glb_export.as_secs_f64().max(1e-12),
            (export + stage(t, Phase::Mesh)).as_secs_f64() / glb_both.as_secs_f64().max(1e-12),
        );
    }
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("throughput: {e}");
            ExitCode::FAILURE
        }
    }
}
