//! Renders known to be quick run on the async worker, not the blocking pool
//! (issue 33, `service::inline`): such a render gives the bytes the CLI
//! gives, and a render of the same source that turns out slow (other
//! parameters) runs into the try's 1 ms deadline and is rendered again on
//! the pool under the request's own limits, with the whole model. How many
//! tries succeed depends on the machine's load (a pool render slower than
//! the memo's threshold makes no candidate), so the test repeats the quick
//! request until one try has run, and asserts the outcomes, never a time.

use super::*;
use serde_json::json;

/// A grammar whose cost grows with `n`: n boxes in a row.
const ROW: &str = "// quick-row\n@param int n 1 1 1000000\nstartshape A\nrule A { n * { x 1.5 } BOX {} }\n";

/// Posts the row with `n` and `seed` as a fresh render (`Cache-Control: no-cache`); the bytes.
async fn fresh(c: &reqwest::Client, base: &str, n: u32, seed: u64) -> Vec<u8> {
    let body = json!({"source": ROW, "format": "glb", "seed": seed, "params": {"n": n}});
    let r = c.post(format!("{base}/v1/render")).header("cache-control", "no-cache").json(&body).send().await.expect("post");
    assert_eq!(r.status(), 200, "n = {n}");
    assert_eq!(header(&r, "x-rulemesh-truncated"), "false", "the whole model, never one cut at the try's deadline");
    r.bytes().await.expect("body").to_vec()
}

/// The CLI's bytes for the row with `n` and `seed`.
fn cli(n: u32, seed: u64) -> Vec<u8> {
    let dir = crate::common::tempdir();
    let src = dir.path().join("row.mdg");
    let out = dir.path().join("row.glb");
    std::fs::write(&src, ROW).expect("write");
    let (s, o, seed, param) = (src.to_string_lossy(), out.to_string_lossy(), seed.to_string(), format!("n={n}"));
    let run = crate::common::run(&["render", &s, "--seed", &seed, "--param", &param, "-o", &o], None);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    std::fs::read(&out).expect("read")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn quick_renders_on_the_worker_give_the_pools_bytes_and_slow_ones_fall_back() {
    let (srv, url) = start(config()).await;
    let c = client();
    let done = "rulemesh_quick_renders_total{outcome=\"done\"}";
    let fell_back = "rulemesh_quick_renders_total{outcome=\"fell_back\"}";
    assert_eq!(sample(&metrics(&url).await, done), 0.0, "nothing has run yet");

    // Three boxes, new seeds, until one render has run on the worker: the
    // first goes to the pool (the source is unknown), and once a pool render
    // was quick the next is tried on the worker.
    let mut seed = 0;
    while sample(&metrics(&url).await, done) < 1.0 {
        seed += 1;
        assert!(seed <= 200, "no quick render ran in 200 fresh renders of three boxes");
        assert_eq!(fresh(&c, &url, 3, seed).await, cli(3, seed), "seed {seed}: the same bytes on either thread");
    }
    let before = sample(&metrics(&url).await, fell_back);

    // The same source with 100,000 boxes (about 30 ms): tried on the worker,
    // it runs into the try's deadline and is rendered again on the pool.
    assert_eq!(fresh(&c, &url, 100_000, 1).await, cli(100_000, 1), "the slow render is whole and equal to the CLI's");
    let m = metrics(&url).await;
    assert_eq!(sample(&m, fell_back), before + 1.0, "the slow render's try fell back to the pool once");
    stop(srv).await;
}
