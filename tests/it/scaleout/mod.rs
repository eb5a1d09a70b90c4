//! Scale-out end to end: a real `redis-server` and two real `rulemesh serve`
//! processes on loopback sharing it. `scripts/test` installs redis-server
//! and these tests fail (never skip) where it is missing. The
//! container image and deployment files are checked in [`deploy`] and, with
//! `scripts/image-check`'s recipes, in [`image`].

mod deploy;
mod image;

use crate::common;
use serde_json::json;
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A free loopback port (bound, then released).
pub(crate) fn free_port() -> u16 {
    let l = TcpListener::bind("127.0.0.1:0").expect("bind 127.0.0.1:0");
    l.local_addr().expect("addr").port()
}

/// Fails the calling test when `redis-server` is not installed: a test that
/// silently passed without it would check nothing (issue 17).
pub(crate) fn require_redis_server() {
    let found = Command::new("redis-server").arg("--version").stdout(Stdio::null()).stderr(Stdio::null()).status().is_ok_and(|s| s.success());
    assert!(found, "redis-server is not installed (scripts/test installs it: apt-get install redis-server)");
}

/// A `redis-server` on a loopback port, without persistence; killed on drop.
pub(crate) struct Redis {
    port: u16,
    child: Option<Child>,
}

impl Redis {
    pub(crate) fn start(port: u16) -> Redis {
        Redis::start_with(port, &[])
    }

    fn start_with(port: u16, extra: &[&str]) -> Redis {
        let child = Command::new("redis-server")
            .args(["--port", &port.to_string(), "--bind", "127.0.0.1", "--save", "", "--appendonly", "no", "--protected-mode", "yes"])
            .args(extra)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("spawn redis-server");
        let r = Redis { port, child: Some(child) };
        let deadline = Instant::now() + Duration::from_secs(10);
        while !r.pings() {
            assert!(Instant::now() < deadline, "redis-server did not start on {port}");
            std::thread::sleep(Duration::from_millis(20));
        }
        r
    }

    fn pings(&self) -> bool {
        use std::io::{Read, Write};
        let Ok(mut s) = TcpStream::connect(("127.0.0.1", self.port)) else { return false };
        let _ = s.set_read_timeout(Some(Duration::from_millis(500)));
        let mut buf = [0u8; 7];
        s.write_all(b"PING\r\n").is_ok() && s.read_exact(&mut buf).is_ok() && &buf == b"+PONG\r\n"
    }

    /// Sends one command and returns the raw RESP reply.
    fn command(&self, args: &[&str]) -> String {
        use std::io::{Read, Write};
        let mut s = TcpStream::connect(("127.0.0.1", self.port)).expect("connect to redis");
        let mut req = format!("*{}\r\n", args.len());
        for a in args {
            req.push_str(&format!("${}\r\n{a}\r\n", a.len()));
        }
        s.write_all(req.as_bytes()).expect("write");
        let _ = s.set_read_timeout(Some(Duration::from_millis(300)));
        let mut out = Vec::new();
        let mut buf = [0u8; 4096];
        while let Ok(n) = s.read(&mut buf) {
            if n == 0 {
                break;
            }
            out.extend_from_slice(&buf[..n]);
        }
        String::from_utf8_lossy(&out).into_owned()
    }

    pub(crate) fn url(&self) -> String {
        format!("redis://127.0.0.1:{}/", self.port)
    }

    fn kill(&mut self) {
        if let Some(mut c) = self.child.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

impl Drop for Redis {
    fn drop(&mut self) {
        self.kill();
    }
}

/// A `rulemesh serve` process on loopback ports; killed on drop.
struct Worker {
    base: String,
    child: Child,
}

impl Worker {
    /// Starts a worker named `id`, giving the Redis URL by flag or (`by_env`) by environment variable.
    fn start(id: &str, redis_url: &str, by_env: bool, extra: &[&str]) -> Worker {
        let http = SocketAddr::from(([127, 0, 0, 1], free_port()));
        let grpc = SocketAddr::from(([127, 0, 0, 1], free_port()));
        let mut cmd = Command::new(common::bin());
        cmd.args(["serve", "--http", &http.to_string(), "--grpc", &grpc.to_string(), "--worker-id", id, "--log", "warn"]);
        cmd.args(["--cache-redis-timeout-ms", "200", "--max-concurrency", "2"]);
        if by_env {
            cmd.env("RULEMESH_CACHE_REDIS", redis_url);
        } else {
            cmd.args(["--cache-redis", redis_url]);
        }
        cmd.args(extra).stdout(Stdio::null()).stderr(Stdio::inherit());
        let child = cmd.spawn().expect("spawn rulemesh serve");
        let w = Worker { base: format!("http://{http}"), child };
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            if TcpStream::connect(http).is_ok() {
                break;
            }
            assert!(Instant::now() < deadline, "worker {id} did not start");
            std::thread::sleep(Duration::from_millis(20));
        }
        w
    }

    async fn render(&self, c: &reqwest::Client, source: &str) -> (u16, String, Vec<u8>) {
        let r = c.post(format!("{}/v1/render", self.base)).json(&json!({"source": source, "format": "glb"})).send().await.expect("request");
        let status = r.status().as_u16();
        let cache = r.headers().get("x-rulemesh-cache").and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
        (status, cache, r.bytes().await.expect("body").to_vec())
    }

    async fn metrics(&self, c: &reqwest::Client) -> String {
        c.get(format!("{}/metrics", self.base)).send().await.expect("metrics").text().await.expect("text")
    }

    /// The value of `name` (labelled by this worker) in /metrics.
    async fn metric(&self, c: &reqwest::Client, name: &str) -> u64 {
        let text = self.metrics(c).await;
        let prefix = format!("{name}{{worker=");
        text.lines()
            .find(|l| l.starts_with(&prefix))
            .and_then(|l| l.rsplit(' ').next())
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("{name} missing from metrics:\n{text}"))
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A grammar of 1600 boxes; `tag` makes its cache key unique.
fn grammar(tag: &str) -> String {
    format!("// {tag}\nstartshape A\nrule A {{ 20 * {{ x 1.1 }} B {{}} }}\nrule B {{ 20 * {{ y 1.1 }} C {{}} }}\nrule C {{ 4 * {{ z 1.1 }} BOX {{}} }}\n")
}

fn client() -> reqwest::Client {
    reqwest::Client::builder().timeout(Duration::from_secs(60)).no_gzip().no_brotli().no_zstd().build().expect("client")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn two_workers_share_redis_and_survive_its_loss() {
    require_redis_server();
    let port = free_port();
    let mut redis = Redis::start(port);
    let a = Worker::start("a", &redis.url(), false, &[]);
    let b = Worker::start("b", &redis.url(), true, &[]);
    let c = client();

    // A render on worker A is a hit on worker B, with the same bytes.
    let src = grammar("shared-1");
    let (s, cache, on_a) = a.render(&c, &src).await;
    assert_eq!((s, cache.as_str()), (200, "miss"));
    let (s, cache, on_b) = b.render(&c, &src).await;
    assert_eq!((s, cache.as_str()), (200, "hit"), "worker B did not find worker A's model in Redis");
    assert_eq!(on_a, on_b);
    assert_eq!(b.metric(&c, "rulemesh_renders_total").await, 0);
    assert_eq!(b.metric(&c, "rulemesh_redis_hits_total").await, 1);
    assert_eq!(a.metric(&c, "rulemesh_redis_writes_total").await, 1);
    assert!(a.metrics(&c).await.contains("rulemesh_requests_total{worker=\"a\",protocol=\"http\",route=\"/v1/render\",status=\"200\"} 1"));

    // Kill Redis while both workers are busy: every request still succeeds.
    let load = {
        let (a, b) = (a.base.clone(), b.base.clone());
        tokio::spawn(async move {
            let c = client();
            let mut statuses = Vec::new();
            for i in 0..40 {
                let base = if i % 2 == 0 { &a } else { &b };
                let r = c.post(format!("{base}/v1/render")).json(&json!({"source": grammar(&format!("during-{i}")), "format": "glb"})).send().await;
                statuses.push(r.map(|r| r.status().as_u16()).unwrap_or(0));
                tokio::time::sleep(Duration::from_millis(10)).await;
            }
            statuses
        })
    };
    tokio::time::sleep(Duration::from_millis(100)).await;
    redis.kill();
    let statuses = load.await.expect("load task");
    assert!(statuses.iter().all(|s| *s == 200), "requests failed while Redis went away: {statuses:?}");

    // With Redis gone: both answer, caching locally (a repeat on the same worker is a hit).
    for (w, tag) in [(&a, "down-a"), (&b, "down-b")] {
        let src = grammar(tag);
        let started = Instant::now();
        assert_eq!(w.render(&c, &src).await.0, 200);
        let (s, cache, _) = w.render(&c, &src).await;
        assert_eq!((s, cache.as_str()), (200, "hit"));
        assert!(started.elapsed() < Duration::from_secs(3), "a dead Redis slowed requests: {:?}", started.elapsed());
        assert!(w.metric(&c, "rulemesh_redis_errors_total").await > 0);
    }
    assert_eq!(a.metric(&c, "rulemesh_redis_up").await, 0);

    // Restart Redis on the same port: sharing comes back (within the retry interval).
    let _redis = Redis::start(port);
    let deadline = Instant::now() + Duration::from_secs(15);
    let mut n = 0;
    loop {
        n += 1;
        let src = grammar(&format!("restored-{n}"));
        assert_eq!(a.render(&c, &src).await.0, 200);
        let (s, cache, _) = b.render(&c, &src).await;
        assert_eq!(s, 200);
        if cache == "hit" {
            break;
        }
        assert!(Instant::now() < deadline, "sharing did not come back after Redis restarted");
        tokio::time::sleep(Duration::from_millis(200)).await;
    }
    assert_eq!(a.metric(&c, "rulemesh_redis_up").await, 1);
}

/// Fires 50 identical requests for a new model, alternating between the
/// two workers, and returns the pipeline runs they caused.
async fn burst(a: &Worker, b: &Worker, tag: &str) -> u64 {
    let c = client();
    let before = a.metric(&c, "rulemesh_renders_total").await + b.metric(&c, "rulemesh_renders_total").await;
    let src = grammar(tag);
    let mut tasks = Vec::new();
    for i in 0..50 {
        let base = if i % 2 == 0 { a.base.clone() } else { b.base.clone() };
        let (c, src) = (c.clone(), src.clone());
        tasks.push(tokio::spawn(async move {
            let r = c.post(format!("{base}/v1/render")).json(&json!({"source": src, "format": "glb"})).send().await.expect("request");
            let status = r.status().as_u16();
            let etag = r.headers().get("etag").and_then(|v| v.to_str().ok()).unwrap_or("").to_string();
            (status, etag)
        }));
    }
    let mut etags = std::collections::BTreeSet::new();
    for t in tasks {
        let (status, etag) = t.await.expect("task");
        assert_eq!(status, 200);
        etags.insert(etag);
    }
    assert_eq!(etags.len(), 1, "workers answered different bytes");
    a.metric(&c, "rulemesh_renders_total").await + b.metric(&c, "rulemesh_renders_total").await - before
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn fifty_identical_misses_render_at_most_twice_and_once_with_the_lock() {
    require_redis_server();
    let redis = Redis::start(free_port());
    {
        let a = Worker::start("a", &redis.url(), false, &[]);
        let b = Worker::start("b", &redis.url(), false, &[]);
        let renders = burst(&a, &b, "burst-unlocked").await;
        assert!((1..=2).contains(&renders), "without the lock: {renders} renders");
    }
    let lock = ["--cache-redis-lock-ms", "10000"];
    let a = Worker::start("a", &redis.url(), false, &lock);
    let b = Worker::start("b", &redis.url(), true, &lock);
    for round in 0..3 {
        let renders = burst(&a, &b, &format!("burst-locked-{round}")).await;
        assert_eq!(renders, 1, "with the lock, round {round}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn redis_values_have_a_ttl_and_a_size_cap_and_a_full_or_slow_redis_is_survived() {
    require_redis_server();
    let c = client();
    // TTL: the stored model expires (PX) within the configured lifetime.
    let redis = Redis::start(free_port());
    let a = Worker::start("a", &redis.url(), false, &["--cache-redis-ttl-secs", "120"]);
    assert_eq!(a.render(&c, &grammar("ttl")).await.0, 200);
    let keys = redis.command(&["KEYS", "rulemesh:m:*"]);
    let key = keys.lines().find(|l| l.starts_with("rulemesh:m:")).unwrap_or_else(|| panic!("no model key in Redis: {keys:?}")).to_string();
    let pttl: i64 = redis.command(&["PTTL", &key]).trim().trim_start_matches(':').parse().expect("PTTL reply");
    assert!(pttl > 100_000 && pttl <= 120_000, "PTTL {pttl}");
    drop(a);

    // Size cap: a model larger than the cap is not written, and is not shared.
    let a = Worker::start("a", &redis.url(), false, &["--cache-redis-max-bytes", "1000"]);
    let b = Worker::start("b", &redis.url(), false, &["--cache-redis-max-bytes", "1000"]);
    let src = grammar("capped");
    assert_eq!(a.render(&c, &src).await.0, 200);
    assert_eq!(a.metric(&c, "rulemesh_redis_skipped_total").await, 1);
    assert_eq!(a.metric(&c, "rulemesh_redis_writes_total").await, 0);
    assert_eq!(b.render(&c, &src).await.1, "miss");
    drop((a, b));

    // A full Redis (maxmemory without eviction refuses writes): requests
    // succeed, the failure is counted, local caching goes on.
    let full = Redis::start_with(free_port(), &["--maxmemory", "1mb", "--maxmemory-policy", "noeviction"]);
    let a = Worker::start("a", &full.url(), false, &[]);
    for i in 0..3 {
        let src = grammar(&format!("full-{i}"));
        assert_eq!(a.render(&c, &src).await.0, 200);
        let (status, cache, _) = a.render(&c, &src).await;
        assert_eq!((status, cache.as_str()), (200, "hit"));
    }
    assert!(a.metric(&c, "rulemesh_redis_errors_total").await > 0, "an OOM refusal is counted");
    drop(a);

    // A slow Redis (blocked by DEBUG SLEEP): requests go on after the
    // command timeout (200 ms here) instead of waiting for it.
    let slow = Redis::start_with(free_port(), &["--enable-debug-command", "yes"]);
    let a = Worker::start("a", &slow.url(), false, &[]);
    assert_eq!(a.render(&c, &grammar("before-slow")).await.0, 200);
    let port = slow.port;
    let sleeper = std::thread::spawn(move || Redis { port, child: None }.command(&["DEBUG", "SLEEP", "3"]));
    tokio::time::sleep(Duration::from_millis(100)).await;
    let started = Instant::now();
    assert_eq!(a.render(&c, &grammar("while-slow")).await.0, 200);
    assert!(started.elapsed() < Duration::from_millis(1500), "a slow Redis held a request {:?}", started.elapsed());
    assert!(a.metric(&c, "rulemesh_redis_errors_total").await > 0, "the timeout is counted");
    let _ = sleeper.join();
}
