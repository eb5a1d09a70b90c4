//! Variations (issue 20): every model response says which seed made it
//! (`x-rulemesh-seed`, gRPC metadata and `RenderMeta.seed`).

use super::*;

/// 2^63 + 1: beyond what a JSON number keeps exactly in most clients.
const BIG_SEED: u64 = (1 << 63) + 1;

fn library_source(name: &str) -> String {
    std::fs::read_to_string(common::repo().join("grammars").join(format!("{name}.mdg"))).expect("library grammar")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_seed_a_model_was_made_with_comes_back_in_headers_and_metadata() {
    let (srv, base) = start(config()).await;
    let gem = library_source("gem");
    // HTTP: sent as a decimal string, back unchanged, on the miss and on the hit.
    for cache in ["miss", "hit"] {
        let r = post(&base, "/v1/render", &json!({"source": gem, "seed": BIG_SEED.to_string()})).await;
        assert_eq!(r.status(), 200);
        assert_eq!(header(&r, "x-rulemesh-cache"), cache);
        assert_eq!(header(&r, "x-rulemesh-seed"), "9223372036854775809");
    }
    // The GET route, its 304 included.
    let c = client();
    let r = c.get(format!("{base}/v1/models/gem.glb?seed={BIG_SEED}")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-rulemesh-seed"), "9223372036854775809");
    let etag = header(&r, "etag").to_string();
    let r = c.get(format!("{base}/v1/models/gem.glb?seed={BIG_SEED}")).header("if-none-match", etag).send().await.expect("get");
    assert_eq!(r.status(), 304);
    assert_eq!(header(&r, "x-rulemesh-seed"), "9223372036854775809");
    // No seed: the grammar's own `randseed 2`, or 0 for a grammar without one.
    let listing = library_source("listing-4-1");
    assert!(listing.contains("\nrandseed 2\n"));
    let r = post(&base, "/v1/render", &json!({"source": listing})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-rulemesh-seed"), "2");
    let r = c.get(format!("{base}/v1/models/listing-4-1.stl")).send().await.expect("get");
    assert_eq!(header(&r, "x-rulemesh-seed"), "2");
    let r = post(&base, "/v1/render", &json!({"source": gem})).await;
    assert_eq!(header(&r, "x-rulemesh-seed"), "0");
    // An explicit seed wins over the directive.
    let directed = format!("randseed 12\n{}", small("directed"));
    let r = post(&base, "/v1/render", &json!({"source": directed})).await;
    assert_eq!((r.status().as_u16(), header(&r, "x-rulemesh-seed")), (200, "12"));
    let r = post(&base, "/v1/render", &json!({"source": directed, "seed": 7})).await;
    assert_eq!((r.status().as_u16(), header(&r, "x-rulemesh-seed")), (200, "7"));

    // gRPC: Render and RenderStream, as metadata and in RenderMeta.
    let mut g = grpc_client(&srv).await;
    let seed_of = |m: &tonic::metadata::MetadataMap| m.get("x-rulemesh-seed").and_then(|v| v.to_str().ok()).map(str::to_string);
    for (source, seed, want) in [(gem.clone(), Some(BIG_SEED), BIG_SEED), (listing.clone(), None, 2)] {
        let req = pb::RenderRequest { source, seed, ..Default::default() };
        let reply = g.render(req.clone()).await.expect("Render");
        assert_eq!(seed_of(reply.metadata()), Some(want.to_string()));
        assert_eq!(reply.into_inner().meta.expect("meta").seed, want);
        let stream = g.render_stream(req).await.expect("RenderStream");
        assert_eq!(seed_of(stream.metadata()), Some(want.to_string()));
        let first = stream.into_inner().message().await.expect("chunk").expect("a first chunk");
        assert_eq!(first.meta.expect("meta in the first chunk").seed, want);
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

/// The lines of an NDJSON batch answer, after checking its status and type.
async fn batch_lines(base: &str, body: &Value) -> Vec<Value> {
    let r = post(base, "/v1/render/batch", body).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/x-ndjson");
    let text = r.text().await.expect("body");
    assert!(text.ends_with('\n'), "every line ends with a newline");
    text.lines().map(|l| serde_json::from_str(l).expect("each line is one JSON object")).collect()
}

/// A successful line's decoded bytes, checked against its etag and size.
fn decoded(line: &Value) -> Vec<u8> {
    use base64::Engine as _;
    let bytes = base64::engine::general_purpose::STANDARD.decode(line["bytes_base64"].as_str().expect("bytes_base64")).expect("valid base64");
    assert_eq!(line["etag"], blake3::hash(&bytes).to_hex()[..32], "{}", line["index"]);
    assert_eq!(line["size"], bytes.len());
    bytes
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_batch_of_100_seeds_streams_100_distinct_models_then_100_hits() {
    let (srv, base) = start(config()).await;
    // Seeds from 2^63 up, half sent as decimal text.
    let seeds: Vec<u64> = (0..100).map(|i| BIG_SEED + i * 7).collect();
    let wire: Vec<Value> = seeds.iter().enumerate().map(|(i, s)| if i % 2 == 0 { json!(s.to_string()) } else { json!(s) }).collect();
    let body = json!({"grammar": "gem", "seeds": wire});
    let first = batch_lines(&base, &body).await;
    assert_eq!(first.len(), 100);
    let mut models = std::collections::BTreeSet::new();
    for (i, line) in first.iter().enumerate() {
        assert_eq!(line["index"], i);
        assert_eq!(line["seed"], seeds[i].to_string());
        assert_eq!(line["cache"], "miss");
        assert_eq!(line["content_type"], "model/gltf-binary");
        assert!(line.get("error").is_none(), "{line}");
        models.insert(decoded(line));
    }
    assert_eq!(models.len(), 100, "100 distinct byte strings");
    // A member is the very model a single render of its seed makes.
    let single = post(&base, "/v1/render", &json!({"source": library_source("gem"), "seed": seeds[37].to_string()})).await;
    assert_eq!(header(&single, "x-rulemesh-cache"), "hit", "the member was cached under the single render's key");
    assert!(single.bytes().await.expect("body").as_ref() == decoded(&first[37]).as_slice());
    // The same batch again: every member a hit, every byte the same.
    let again = batch_lines(&base, &body).await;
    assert_eq!(again.len(), 100);
    for (a, b) in first.iter().zip(&again) {
        assert_eq!(b["cache"], "hit");
        assert_eq!((&a["index"], &a["seed"], &a["etag"]), (&b["index"], &b["seed"], &b["etag"]));
        assert!(decoded(a) == decoded(b));
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_failing_member_fails_alone_and_an_oversized_batch_is_refused() {
    let (srv, base) = start(config()).await;
    let source = "@param int n 3 1 50\nstartshape A\nrule A { n * { x 1 } BOX {} }\n";
    let body = json!({"source": source, "seed": 5, "limits": {"max_primitives": 10}, "sweep": {"n": [2, 20, 99, "3"]}});
    let lines = batch_lines(&base, &body).await;
    assert_eq!(lines.len(), 4);
    assert_eq!(lines.iter().map(|l| l["index"].clone()).collect::<Vec<_>>(), [0, 1, 2, 3]);
    // Parameters in one spelling (the text "3" is the number 3), as in the models' provenance.
    assert_eq!(lines.iter().map(|l| l["params"]["n"].as_f64()).collect::<Vec<_>>(), [Some(2.0), Some(20.0), Some(99.0), Some(3.0)]);
    for i in [0, 3] {
        assert!(lines[i].get("error").is_none(), "{}", lines[i]);
        assert_eq!(lines[i]["seed"], "5");
        assert_eq!(lines[i]["primitives"], if i == 0 { 2 } else { 3 });
        assert!(!decoded(&lines[i]).is_empty());
    }
    // Over max_primitives: this member alone, with the limit's details.
    let e = &lines[1]["error"];
    assert_eq!((e["code"].as_str(), e["limit"].as_str(), e["configured"].as_u64()), (Some("limit_exceeded"), Some("primitives"), Some(10)), "{}", lines[1]);
    assert!(lines[1].get("bytes_base64").is_none());
    // Outside the parameter's declared range: refused, this member alone.
    assert!(lines[2]["error"]["code"].is_string() && lines[2]["error"]["message"].as_str().is_some_and(|m| m.contains('n')), "{}", lines[2]);
    assert_eq!(lines[2]["seed"], "5");

    // Over the cap of 256, by seeds or by a sweep's product: 413 naming the cap
    // (a request too large to take; the schema cannot bound a product).
    let seeds: Vec<u64> = (0..257).collect();
    for body in [json!({"grammar": "gem", "seeds": seeds}), json!({"grammar": "gem", "sweep": {"a": (0..17).collect::<Vec<u32>>(), "b": (0..17).collect::<Vec<u32>>()}})] {
        let r = post(&base, "/v1/render/batch", &body).await;
        assert_eq!(r.status(), 413);
        let e = error_body(r).await;
        assert_eq!(e["code"], "too_many_members", "{e}");
        assert!(e["message"].as_str().is_some_and(|m| m.contains("cap of 256")), "{e}");
    }
    // Exactly the cap is accepted.
    let seeds: Vec<u64> = (0..256).collect();
    let lines = batch_lines(&base, &json!({"grammar": "gem", "seeds": seeds, "format": "stl"})).await;
    assert_eq!(lines.len(), 256);
    assert!(lines.iter().all(|l| l.get("error").is_none()));
    // Malformed whole: unknown grammar 404, bad format 400, nothing streamed.
    let r = post(&base, "/v1/render/batch", &json!({"grammar": "nope", "seeds": [1]})).await;
    assert_eq!(r.status(), 404);
    let r = post(&base, "/v1/render/batch", &json!({"grammar": "gem", "seeds": [1], "format": "obj"})).await;
    assert_eq!(r.status(), 400);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn grpc_render_batch_streams_the_same_members_and_bytes_as_http() {
    let (srv, base) = start(config()).await;
    let seeds: Vec<u64> = (0..100).map(|i| BIG_SEED - 50 + i * 3).collect();
    let mut g = grpc_client(&srv).await;
    let request = pb::RenderBatchRequest { grammar: "gem".into(), seeds: seeds.clone(), ..Default::default() };
    let mut stream = g.render_batch(request).await.expect("RenderBatch").into_inner();
    let mut items = Vec::new();
    while let Some(item) = stream.message().await.expect("item") {
        items.push(item);
    }
    assert_eq!(items.len(), 100);
    let mut models = Vec::new();
    for (i, item) in items.iter().enumerate() {
        assert_eq!(item.index as usize, i);
        assert_eq!(item.seed, Some(seeds[i]));
        let Some(pb::render_batch_item::Result::Model(reply)) = &item.result else { panic!("member {i} failed: {item:?}") };
        let meta = reply.meta.as_ref().expect("meta");
        assert_eq!((meta.seed, meta.cache_hit), (seeds[i], false));
        assert_eq!(meta.etag, blake3::hash(&reply.model).to_hex()[..32]);
        models.push(reply.model.clone());
    }
    assert_eq!(models.iter().collect::<std::collections::BTreeSet<_>>().len(), 100, "100 distinct models");
    // The HTTP batch of the same seeds: every member a hit, byte for byte the same.
    let lines = batch_lines(&base, &json!({"grammar": "gem", "seeds": seeds})).await;
    assert_eq!(lines.len(), 100);
    for (line, model) in lines.iter().zip(&models) {
        assert_eq!(line["cache"], "hit");
        assert!(decoded(line) == *model);
    }
    // A sweep's member errors and a malformed batch, as over HTTP.
    let render = pb::RenderRequest {
        source: "@param int n 3 1 50\nstartshape A\nrule A { n * { x 1 } BOX {} }\n".into(),
        limits: Some(pb::Limits { max_primitives: Some(10), ..Default::default() }),
        ..Default::default()
    };
    let sweep = [("n".to_string(), pb::SweepValues { values: vec!["2".into(), "20".into()] })].into_iter().collect();
    let mut stream = g.render_batch(pb::RenderBatchRequest { render: Some(render), sweep, ..Default::default() }).await.expect("RenderBatch").into_inner();
    let first = stream.message().await.expect("item").expect("first");
    assert_eq!(first.params.get("n").map(String::as_str), Some("2"));
    assert!(matches!(first.result, Some(pb::render_batch_item::Result::Model(_))));
    let second = stream.message().await.expect("item").expect("second");
    let Some(pb::render_batch_item::Result::Error(e)) = second.result else { panic!("{second:?}") };
    assert_eq!(e.code, "limit_exceeded");
    let details: Value = serde_json::from_slice(&e.details).expect("JSON details");
    assert_eq!(details["error"]["limit"], "primitives");
    assert!(stream.message().await.expect("end").is_none());
    let over = pb::RenderBatchRequest { grammar: "gem".into(), seeds: (0..257).collect(), ..Default::default() };
    let err = g.render_batch(over).await.expect_err("over the cap");
    assert_eq!(err.code(), tonic::Code::ResourceExhausted);
    assert!(err.message().contains("cap of 256"), "{}", err.message());
    let err = g.render_batch(pb::RenderBatchRequest { grammar: "nope".into(), seeds: vec![1], ..Default::default() }).await.expect_err("unknown");
    assert_eq!(err.code(), tonic::Code::NotFound);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

/// A Context Free design's response names its variation code
/// (`x-rulemesh-variation`, HTTP and gRPC), and the code drawn back with
/// `variation` is the same model: seed 5 is variation 6, `F`.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_context_free_design_says_its_variation_code() {
    let (srv, base) = start(config()).await;
    let c = client();
    let r = c.get(format!("{base}/v1/models/cfdg-spiral.svg?p.variation=XYZ")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-rulemesh-variation"), "XYZ");
    let by_seed = c.get(format!("{base}/v1/models/cfdg-spiral.svg?seed=5")).send().await.expect("get");
    assert_eq!((by_seed.status().as_u16(), header(&by_seed, "x-rulemesh-variation")), (200, "F"));
    let seed_bytes = by_seed.bytes().await.expect("body");
    let by_code = c.get(format!("{base}/v1/models/cfdg-spiral.svg?p.variation=F")).send().await.expect("get");
    assert_eq!(header(&by_code, "x-rulemesh-variation"), "F");
    assert_eq!(by_code.bytes().await.expect("body"), seed_bytes);
    // Another language has no variation code.
    let r = c.get(format!("{base}/v1/models/gem.glb")).send().await.expect("get");
    assert!(r.headers().get("x-rulemesh-variation").is_none());
    let source = std::fs::read_to_string(common::repo().join("grammars/cfdg-spiral.cfdg")).expect("grammar");
    let mut g = grpc_client(&srv).await;
    let reply = g.render(pb::RenderRequest { source, seed: Some(5), ..Default::default() }).await.expect("Render");
    assert_eq!(reply.metadata().get("x-rulemesh-variation").and_then(|v| v.to_str().ok()), Some("F"));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
