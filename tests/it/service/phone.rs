//! Phones get glTF every phone loader opens (issue 36, docs/loaders.md):
//! a request from a phone (the `Sec-CH-UA-Mobile: ?1` client hint, or a
//! phone's `User-Agent`) that names no `instancing` is written flat, byte
//! for byte what `instancing: flat` gives; one that names it gets what it
//! names; every other caller keeps GPU instancing. Over `POST /v1/render`,
//! `GET /v1/models/NAME.glb` and the batch route, with `Vary` saying so.

use super::*;

const ANDROID_APP: &str = "okhttp/4.12.0";
const IPHONE: &str = "Mozilla/5.0 (iPhone; CPU iPhone OS 18_1 like Mac OS X) AppleWebKit/605.1.15 (KHTML, like Gecko) Version/18.1 Mobile/15E148 Safari/604.1";
const DESKTOP: &str = "Mozilla/5.0 (X11; Linux x86_64) AppleWebKit/537.36 (KHTML, like Gecko) Chrome/131.0.0.0 Safari/537.36";

/// Whether a glb's JSON chunk uses GPU instancing.
fn instanced(glb: &[u8]) -> bool {
    let json_len = u32::from_le_bytes(glb[12..16].try_into().expect("a glb header")) as usize;
    String::from_utf8_lossy(&glb[20..20 + json_len]).contains("EXT_mesh_gpu_instancing")
}

/// Sends `rq` with `headers`; the response's `Vary` and body (status 200 asserted).
async fn send(mut rq: reqwest::RequestBuilder, headers: &[(&str, &str)]) -> (String, Vec<u8>) {
    for (k, v) in headers {
        rq = rq.header(*k, *v);
    }
    let r = rq.send().await.expect("request");
    if r.status() != 200 {
        panic!("{headers:?}: {} {}", r.status(), r.text().await.unwrap_or_default());
    }
    let vary = r.headers().get_all("vary").iter().filter_map(|v| v.to_str().ok()).collect::<Vec<_>>().join(", ");
    (vary, r.bytes().await.expect("body").to_vec())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn phones_get_flat_gltf_unless_they_ask_for_instancing() {
    let (srv, base) = start(config()).await;
    let render = |body: Value| client().post(format!("{base}/v1/render")).json(&body);
    let source = small("phone");
    let body = json!({"source": source, "format": "glb"});
    let (_, flat) = send(render(json!({"source": source, "format": "glb", "instancing": "flat"})), &[]).await;
    let (vary, desktop) = send(render(body.clone()), &[("user-agent", DESKTOP)]).await;
    assert!(instanced(&desktop) && !instanced(&flat), "the default elsewhere is GPU instancing");
    assert!(vary.contains("Sec-CH-UA-Mobile, User-Agent"), "vary: {vary}");
    for phone in [&[("user-agent", ANDROID_APP)][..], &[("user-agent", IPHONE)], &[("sec-ch-ua-mobile", "?1"), ("user-agent", DESKTOP)]] {
        let (vary, bytes) = send(render(body.clone()), phone).await;
        assert_eq!(bytes, flat, "{phone:?}: a phone's default is the flat variant, byte for byte");
        assert!(vary.contains("User-Agent"), "{vary}");
    }
    // Asked for, instancing is what is asked for.
    let (_, asked) = send(render(json!({"source": source, "format": "glb", "instancing": "gpu"})), &[("user-agent", ANDROID_APP)]).await;
    assert_eq!(asked, desktop);
    // Formats without instancing are the same for everyone, and do not vary.
    let (vary, stl_phone) = send(render(json!({"source": source, "format": "stl"})), &[("user-agent", IPHONE)]).await;
    let (_, stl_desktop) = send(render(json!({"source": source, "format": "stl"})), &[("user-agent", DESKTOP)]).await;
    assert_eq!(stl_phone, stl_desktop);
    assert!(!vary.contains("User-Agent"), "{vary}");

    // The models route: what a phone app fetches.
    let model = |q: &str| client().get(format!("{base}/v1/models/gem.glb{q}"));
    let (vary, phone_gem) = send(model(""), &[("user-agent", ANDROID_APP)]).await;
    let (_, flat_gem) = send(model("?instancing=flat"), &[("user-agent", DESKTOP)]).await;
    let (_, desktop_gem) = send(model(""), &[("user-agent", DESKTOP)]).await;
    assert_eq!(phone_gem, flat_gem);
    assert!(instanced(&desktop_gem) && !instanced(&phone_gem));
    assert!(vary.contains("User-Agent"), "{vary}");

    // A batch: every member of a phone's batch is flat.
    let batch = client().post(format!("{base}/v1/render/batch")).json(&json!({"source": source, "format": "glb", "seeds": [1, 2]}));
    let (_, lines) = send(batch, &[("user-agent", IPHONE)]).await;
    let lines: Vec<Value> = String::from_utf8(lines).expect("ndjson").lines().map(|l| serde_json::from_str(l).expect("a JSON line")).collect();
    assert_eq!(lines.len(), 2, "{lines:?}");
    for line in &lines {
        use base64::Engine as _;
        let bytes = base64::engine::general_purpose::STANDARD.decode(line["bytes_base64"].as_str().expect("bytes_base64")).expect("valid base64");
        let seed: u64 = line["seed"].as_str().expect("a decimal seed").parse().expect("seed");
        let (_, flat) = send(render(json!({"source": source, "format": "glb", "seed": seed, "instancing": "flat"})), &[]).await;
        assert_eq!(bytes, flat, "batch member {line}");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
