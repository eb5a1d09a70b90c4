//! gRPC load for `rulemesh serve` (there is no `ghz` in Debian or on npm):
//! `cargo run --release --example grpc_load -- ADDR SECONDS CONCURRENCY`
//! (defaults http://127.0.0.1:18051, 10, 8) calls `Render` from CONCURRENCY
//! tasks for SECONDS, half of them with a fresh seed (a render) and half a
//! repeated one (a cache hit), on loopback only, and prints requests/s,
//! latency percentiles, status counts, and the mean of each `server-timing`
//! part the server sent back.

use rulemesh::service::grpc::pb;
use rulemesh::service::grpc::pb::rulemesh_client::RulemeshClient;
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

const SOURCE: &str = "startshape A\nrule A { 4 * { x 1.2 ry 20 } Pick {} }\nrule Pick 0.5 { SPHERE { s 0.6 } }\nrule Pick 0.5 { BOX { s 0.8 } }\n";

#[derive(Default)]
struct Tally {
    latencies: Vec<Duration>,
    statuses: BTreeMap<String, u64>,
    timing: BTreeMap<String, (f64, u64)>,
}

async fn worker(addr: String, until: Instant, id: u64) -> Tally {
    let mut tally = Tally::default();
    let Ok(mut client) = RulemeshClient::connect(addr).await else {
        tally.statuses.insert("connect-error".into(), 1);
        return tally;
    };
    let mut n = 0u64;
    while Instant::now() < until {
        n += 1;
        // Odd calls repeat a seed (hits after the first), even ones never do (renders).
        let seed = if n % 2 == 1 { n % 4 } else { 1_000_000 + id * 1_000_000 + n };
        let request = pb::RenderRequest { source: SOURCE.into(), seed: Some(seed), format: "glb".into(), ..Default::default() };
        let started = Instant::now();
        let reply = client.render(request).await;
        tally.latencies.push(started.elapsed());
        match reply {
            Ok(r) => {
                *tally.statuses.entry("ok".into()).or_default() += 1;
                let value = r.metadata().get("server-timing").and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
                for part in value.split(", ") {
                    let mut fields = part.split(';');
                    let name = fields.next().unwrap_or("").to_string();
                    if let Some(ms) = fields.find_map(|f| f.strip_prefix("dur=")).and_then(|d| d.parse::<f64>().ok()) {
                        let e = tally.timing.entry(name).or_default();
                        e.0 += ms;
                        e.1 += 1;
                    }
                }
            }
            Err(s) => *tally.statuses.entry(format!("{:?}", s.code())).or_default() += 1,
        }
    }
    tally
}

fn percentile(sorted: &[Duration], p: f64) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    let i = ((sorted.len() as f64 - 1.0) * p).round() as usize;
    sorted[i.min(sorted.len() - 1)].as_secs_f64() * 1000.0
}

#[tokio::main]
async fn main() {
    let args: Vec<String> = std::env::args().collect();
    let addr = args.get(1).cloned().unwrap_or_else(|| "http://127.0.0.1:18051".into());
    let secs: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(10);
    let concurrency: u64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(8);
    let started = Instant::now();
    let until = started + Duration::from_secs(secs);
    let tasks: Vec<_> = (0..concurrency).map(|id| tokio::spawn(worker(addr.clone(), until, id))).collect();
    let mut all = Tally::default();
    for t in tasks {
        let Ok(t) = t.await else { continue };
        all.latencies.extend(t.latencies);
        for (k, v) in t.statuses {
            *all.statuses.entry(k).or_default() += v;
        }
        for (k, (sum, n)) in t.timing {
            let e = all.timing.entry(k).or_default();
            e.0 += sum;
            e.1 += n;
        }
    }
    let took = started.elapsed().as_secs_f64();
    all.latencies.sort();
    println!("requests {} in {took:.1} s: {:.0} req/s ({concurrency} concurrent calls)", all.latencies.len(), all.latencies.len() as f64 / took);
    println!(
        "latency ms: p50 {:.2} p90 {:.2} p99 {:.2} max {:.2}",
        percentile(&all.latencies, 0.5),
        percentile(&all.latencies, 0.9),
        percentile(&all.latencies, 0.99),
        percentile(&all.latencies, 1.0)
    );
    println!("statuses {}", all.statuses.iter().map(|(k, v)| format!("{k}={v}")).collect::<Vec<_>>().join(" "));
    let means: Vec<String> = all.timing.iter().map(|(k, (sum, n))| format!("{k} {:.3}", sum / *n as f64)).collect();
    println!("server-timing mean ms (over the calls that had the part): {}", means.join(", "));
}
