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
    // No seed: the grammar's own `randseed 46`, or 0 for a grammar without one.
    let listing = library_source("listing-4-1");
    assert!(listing.contains("\nrandseed 46\n"));
    let r = post(&base, "/v1/render", &json!({"source": listing})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-rulemesh-seed"), "46");
    let r = c.get(format!("{base}/v1/models/listing-4-1.stl")).send().await.expect("get");
    assert_eq!(header(&r, "x-rulemesh-seed"), "46");
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
    for (source, seed, want) in [(gem.clone(), Some(BIG_SEED), BIG_SEED), (listing.clone(), None, 46)] {
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
