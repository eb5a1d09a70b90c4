//! The HTTP door: routes, formats, caching headers, errors, shedding,
//! truncation, single flight, shutdown, the OpenAPI document and compression.

use super::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn health_grammars_metrics_and_404s() {
    let (srv, base) = start(config()).await;
    let c = client();
    assert_eq!(c.get(format!("{base}/healthz")).send().await.expect("get").status(), 200);
    assert_eq!(c.get(format!("{base}/readyz")).send().await.expect("get").status(), 200);

    let list: Value = c.get(format!("{base}/v1/grammars")).send().await.expect("get").json().await.expect("json");
    let grammars = list["grammars"].as_array().expect("array");
    let names: Vec<&str> = grammars.iter().filter_map(|g| g["name"].as_str()).collect();
    for n in ["gem", "menger", "tree", "stochastic"] {
        assert!(names.contains(&n), "{names:?}");
    }
    // The printable collection is marked, and nothing else is.
    let printable: Vec<&str> = grammars.iter().filter(|g| g["printable"] == true).filter_map(|g| g["name"].as_str()).collect();
    assert_eq!(printable, rulemesh::core::library::PRINTABLE, "{list}");
    for g in grammars {
        // Every language is in the library (tests/it/service/library.rs checks each against its file).
        assert!(rulemesh::lang::Language::ALL.iter().any(|l| g["language"].as_str() == Some(l.name())), "{g}");
        assert!(g["printable"].is_boolean(), "{g}");
        assert!(g["params"].is_array());
        assert!(!g["description"].as_str().unwrap_or("").is_empty(), "{g}");
        assert!(g.get("error").is_none(), "built-in grammar does not parse: {g}");
    }

    let src = c.get(format!("{base}/v1/grammars/gem")).send().await.expect("get");
    assert_eq!(src.status(), 200);
    assert_eq!(src.text().await.expect("text"), std::fs::read_to_string(common::repo().join("grammars/gem.mdg")).expect("file"));

    for path in ["/v1/grammars/nope", "/v1/models/nope.glb", "/v1/models/gem.obj", "/v1/models/gem", "/nowhere"] {
        let r = c.get(format!("{base}{path}")).send().await.expect("get");
        assert_eq!(r.status(), 404, "{path}");
        assert_eq!(error_body(r).await["code"], "not_found");
    }

    let m = c.get(format!("{base}/metrics")).send().await.expect("get");
    assert!(header(&m, "content-type").starts_with("text/plain"));
    let text = m.text().await.expect("text");
    for name in [
        "rulemesh_requests_total{protocol=\"http\",route=\"/v1/grammars\",status=\"200\"} 1",
        "rulemesh_requests_total{protocol=\"http\",route=\"unmatched\",status=\"404\"}",
        "rulemesh_render_duration_seconds_bucket",
        "rulemesh_cache_hits_total",
        "rulemesh_cache_misses_total",
        "rulemesh_cache_evictions_total",
        "rulemesh_cache_bytes",
        "rulemesh_renders_in_flight",
        "rulemesh_render_queue_depth",
    ] {
        assert!(text.contains(name), "metrics lack {name}:\n{text}");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn lsystems_render_as_scenes_and_instanced_or_flat_gltf() {
    let (srv, base) = start(config()).await;
    let source = std::fs::read_to_string(common::repo().join("grammars/sierpinski-tetrahedron.ls")).expect("grammar");
    let r = post(&base, "/v1/render", &json!({"source": source, "format": "scene"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/vnd.rulemesh.scene");
    assert_eq!(header(&r, "x-rulemesh-primitives"), "4096");
    let scene = r.bytes().await.expect("body");
    assert_eq!(rulemesh::decode::scene::decode_scene(&scene).expect("decodes").leaves(), 4096);
    let gpu = post(&base, "/v1/render", &json!({"source": source, "format": "glb"})).await.bytes().await.expect("body");
    let flat = post(&base, "/v1/render", &json!({"source": source, "format": "glb", "instancing": "flat"})).await;
    assert_eq!(flat.status(), 200);
    let flat = flat.bytes().await.expect("body");
    let has_ext = |b: &[u8]| String::from_utf8_lossy(&b[..b.len().min(4096)]).contains("EXT_mesh_gpu_instancing");
    assert!(has_ext(&gpu) && !has_ext(&flat));
    assert!(gpu.len() * 20 < flat.len());
    let bad = post(&base, "/v1/render", &json!({"source": source, "instancing": "sometimes"})).await;
    assert_eq!(bad.status(), 400);
    // Every language renders as a scene (version 2): the MDG's primitives as instances.
    let mdg = post(&base, "/v1/render", &json!({"source": small("scene"), "format": "scene"})).await;
    assert_eq!(mdg.status(), 200);
    assert_eq!(header(&mdg, "content-type"), "application/vnd.rulemesh.scene");
    let meshes = rulemesh::decode::scene::decode_scene_meshes(&mdg.bytes().await.expect("body"), 16, 1_000_000).expect("decodes").meshes;
    assert!(meshes.iter().any(|m| !m.mesh.indices.is_empty()));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn render_formats_headers_cache_and_bypass() {
    let (srv, base) = start(config()).await;
    let source = small("formats");
    for (format, ctype) in [("glb", "model/gltf-binary"), ("gltf", "model/gltf+json"), ("stl", "model/stl"), ("stl-ascii", "model/stl")] {
        let r = post(&base, "/v1/render", &json!({"source": source, "format": format, "seed": 3})).await;
        assert_eq!(r.status(), 200, "{format}");
        assert_eq!(header(&r, "content-type"), ctype);
        assert_eq!(header(&r, "x-rulemesh-cache"), "miss");
        assert_eq!(header(&r, "x-rulemesh-primitives"), "6");
        assert_eq!(header(&r, "x-rulemesh-truncated"), "false");
        assert!(header(&r, "x-rulemesh-triangles").parse::<u64>().expect("number") > 0);
        let etag = header(&r, "etag").to_string();
        assert!(etag.starts_with('"') && etag.ends_with('"') && etag.len() == 34, "{etag}");
        let bytes = r.bytes().await.expect("body");
        assert_eq!(etag.trim_matches('"'), &blake3::hash(&bytes).to_hex()[..32], "the ETag is the content hash");
        if format == "stl" {
            assert_eq!(common::decode_stl(&bytes).len() as u64 * 50 + 84, bytes.len() as u64);
        }
    }

    // Same request again: a hit with the same bytes and no render.
    let body = json!({"source": source, "seed": 3});
    let first = post(&base, "/v1/render", &body).await;
    assert_eq!(header(&first, "x-rulemesh-cache"), "hit");
    let renders = srv.state.metrics.renders();
    let again = post(&base, "/v1/render", &body).await;
    assert_eq!(header(&again, "x-rulemesh-cache"), "hit");
    assert_eq!(srv.state.metrics.renders(), renders);
    // CRLF line endings share the cache entry.
    let crlf = post(&base, "/v1/render", &json!({"source": source.replace('\n', "\r\n"), "seed": 3})).await;
    assert_eq!(header(&crlf, "x-rulemesh-cache"), "hit");
    let (e1, e2) = (header(&first, "etag").to_string(), header(&crlf, "etag").to_string());
    assert_eq!(e1, e2);

    // Cache-Control: no-cache renders afresh, with identical bytes.
    let fresh = client().post(format!("{base}/v1/render")).header("cache-control", "no-cache").json(&body).send().await.expect("post");
    assert_eq!(fresh.status(), 200);
    assert_eq!(header(&fresh, "x-rulemesh-cache"), "miss");
    assert_eq!(header(&fresh, "etag"), e1);
    assert_eq!(srv.state.metrics.renders(), renders + 1);
    assert_eq!(fresh.bytes().await.expect("body"), first.bytes().await.expect("body"));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn error_statuses() {
    let (srv, base) = start(config()).await;
    let c = client();
    // 400: malformed JSON, unknown field, bad value, parse error with position.
    let r = c.post(format!("{base}/v1/render")).body("{not json").send().await.expect("post");
    assert_eq!(r.status(), 400);
    assert_eq!(error_body(r).await["code"], "bad_request");
    for bad in [json!({"src": "x"}), json!({"source": small("f"), "format": "obj"}), json!({"source": small("d"), "detail": 100000})] {
        let r = post(&base, "/v1/render", &bad).await;
        assert_eq!(r.status(), 400, "{bad}");
        assert_eq!(error_body(r).await["code"], "bad_request", "{bad}");
    }
    // A Structure Synth JavaScript script is refused unless the operator allows
    // it (harden::access::javascript_switch_over_http_and_grpc has both cases).
    let js = json!({"source": "#javascript\nBuilder.load(\"NouveauMovie.es\");\nBuilder.build();\n", "language": "eisenscript"});
    let r = post(&base, "/v1/render", &js).await;
    assert_eq!(r.status(), 403);
    assert_eq!(error_body(r).await["code"], "javascript_disabled");
    let r = post(&base, "/v1/render", &json!({"source": "startshape A\nrule A {\n  BOX { x }\n}\n"})).await;
    assert_eq!(r.status(), 400);
    let e = error_body(r).await;
    assert_eq!(e["code"], "parse_error");
    assert_eq!((e["line"].as_u64(), e["column"].as_u64().is_some()), (Some(3), true), "{e}");

    // 413: body over the limit.
    let huge = json!({"source": format!("startshape A\nrule A {{ BOX {{}} }}\n//{}", "x".repeat(100 * 1024))});
    let r = post(&base, "/v1/render", &huge).await;
    assert_eq!(r.status(), 413);
    assert_eq!(error_body(r).await["code"], "payload_too_large");

    // 422: a limit, named with its configured and reached values.
    let r = post(&base, "/v1/render", &json!({"source": small("limit"), "limits": {"max_primitives": 3}})).await;
    assert_eq!(r.status(), 422);
    let e = error_body(r).await;
    assert_eq!((e["code"].as_str(), e["limit"].as_str(), e["configured"].as_u64(), e["reached"].as_u64()), (Some("limit_exceeded"), Some("primitives"), Some(3), Some(4)));

    // 504: the deadline.
    let r = post(&base, "/v1/render", &json!({"source": SLOW, "limits": {"timeout_ms": 50, "max_steps": 2_000_000_000u64}})).await;
    assert_eq!(r.status(), 504);
    let e = error_body(r).await;
    assert_eq!((e["code"].as_str(), e["limit"].as_str()), (Some("deadline_exceeded"), Some("deadline")));

    // Failures are not cached: the same bad request fails the same way again, and a good one after it works.
    let r = post(&base, "/v1/render", &json!({"source": small("limit"), "limits": {"max_primitives": 3}})).await;
    assert_eq!(r.status(), 422);
    let r = post(&base, "/v1/render", &json!({"source": small("limit"), "limits": {"max_primitives": 10}})).await;
    assert_eq!(r.status(), 200);

    let text = c.get(format!("{base}/metrics")).send().await.expect("get").text().await.expect("text");
    assert!(text.contains("rulemesh_budget_rejections_total{limit=\"primitives\"} 2"), "{text}");
    assert!(text.contains("rulemesh_budget_rejections_total{limit=\"deadline\"} 1"), "{text}");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn overload_sheds_with_503_and_retry_after() {
    let (srv, base) = start(ServeConfig { max_concurrency: 1, queue: 0, ..config() }).await;
    let slow = json!({"source": SLOW, "limits": {"timeout_ms": 1500, "max_steps": 2_000_000_000u64}, "on_limit": "truncate"});
    let b2 = base.clone();
    let hog = tokio::spawn(async move { post(&b2, "/v1/render", &slow).await });
    tokio::time::sleep(Duration::from_millis(300)).await;
    let r = post(&base, "/v1/render", &json!({"source": small("shed")})).await;
    assert_eq!(r.status(), 503);
    assert_eq!(header(&r, "retry-after"), "1");
    assert_eq!(error_body(r).await["code"], "overloaded");
    let hog = hog.await.expect("task");
    assert_eq!(hog.status(), 200);
    // Truncated: flagged, never stored, never marked cacheable.
    assert_eq!(header(&hog, "x-rulemesh-truncated"), "true");
    assert_eq!(header(&hog, "x-rulemesh-truncated-limit"), "deadline");
    assert_eq!(header(&hog, "cache-control"), "no-store");
    assert_eq!(srv.state.engine.cache().entry_count(), 0);
    // Once the slot is free the shed request succeeds.
    assert_eq!(post(&base, "/v1/render", &json!({"source": small("shed")})).await.status(), 200);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn truncation_is_flagged_and_not_cached() {
    let (srv, base) = start(config()).await;
    let body = json!({"source": small("trunc"), "limits": {"max_primitives": 4}, "on_limit": "truncate"});
    for _ in 0..2 {
        let r = post(&base, "/v1/render", &body).await;
        assert_eq!(r.status(), 200);
        assert_eq!(header(&r, "x-rulemesh-truncated"), "true");
        assert_eq!(header(&r, "x-rulemesh-truncated-limit"), "primitives");
        assert_eq!(header(&r, "x-rulemesh-primitives"), "4");
        assert_eq!(header(&r, "x-rulemesh-cache"), "miss");
    }
    assert_eq!(srv.state.engine.cache().entry_count(), 0);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn models_etag_304_and_cache_control() {
    let (srv, base) = start(config()).await;
    let c = client();
    let r = c.get(format!("{base}/v1/models/gem.glb?seed=7")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "model/gltf-binary");
    assert_eq!(header(&r, "cache-control"), "public, max-age=31536000, immutable");
    let etag = header(&r, "etag").to_string();
    let bytes = r.bytes().await.expect("body");

    let r = c.get(format!("{base}/v1/models/gem.glb?seed=7")).header("if-none-match", &etag).send().await.expect("get");
    assert_eq!(r.status(), 304);
    assert_eq!(header(&r, "etag"), etag);
    assert!(r.bytes().await.expect("body").is_empty());
    let r = c.get(format!("{base}/v1/models/gem.glb?seed=7")).header("if-none-match", "\"other\"").send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-rulemesh-cache"), "hit");

    // The same model through POST /v1/render has the same bytes.
    let source = std::fs::read_to_string(common::repo().join("grammars/gem.mdg")).expect("gem");
    let p = post(&base, "/v1/render", &json!({"source": source, "seed": 7, "language": "mdg"})).await;
    assert_eq!(p.bytes().await.expect("body"), bytes);

    let r = c.get(format!("{base}/v1/models/tree.stl?detail=8")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "model/stl");
    assert_eq!(header(&r, "cache-control"), "public, max-age=300");
    let r = c.get(format!("{base}/v1/models/tower.gltf?seed=1")).send().await.expect("get");
    assert_eq!(header(&r, "content-type"), "model/gltf+json");

    for bad in ["gem.glb?seed=x", "gem.glb?colour=red", "gem.glb?p.size=3", "gem.glb?detail=1"] {
        let r = c.get(format!("{base}/v1/models/{bad}")).send().await.expect("get");
        assert_eq!(r.status(), 400, "{bad}");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn check_reports_diagnostics_with_positions() {
    let (srv, base) = start(config()).await;
    let r = post(&base, "/v1/check", &json!({"source": small("check")})).await;
    assert_eq!(r.status(), 200);
    let v: Value = r.json().await.expect("json");
    assert_eq!((v["ok"].as_bool(), v["language"].as_str()), (Some(true), Some("mdg")));
    let r = post(&base, "/v1/check", &json!({"source": "startshape A\nrule A { BOX { x } }\n"})).await;
    let v: Value = r.json().await.expect("json");
    assert_eq!(v["ok"], false);
    let d = &v["diagnostics"][0];
    assert_eq!((d["severity"].as_str(), d["line"].as_u64()), (Some("error"), Some(2)), "{v}");
    assert!(d["column"].as_u64().is_some_and(|c| c > 1));
    assert_eq!(post(&base, "/v1/check", &json!({"source": "x", "language": "nope"})).await.status(), 400);
    assert_eq!(post(&base, "/v1/check", &json!({"text": "x"})).await.status(), 400);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn single_flight_100_concurrent_misses_render_once() {
    let (srv, base) = start(config()).await;
    // Big enough to take a while, so the requests overlap the render.
    let source = "// single flight\nstartshape A\nrule A { 40 * { x 1 } 40 * { y 1 } SPHERE {} }\n";
    let before = srv.state.metrics.renders();
    let c = client();
    let tasks: Vec<_> = (0..100)
        .map(|_| {
            let (c, base) = (c.clone(), base.clone());
            tokio::spawn(async move {
                let r = c.post(format!("{base}/v1/render")).json(&json!({"source": source, "detail": 24})).send().await.expect("post");
                assert_eq!(r.status(), 200);
                r.bytes().await.expect("body")
            })
        })
        .collect();
    let mut bodies = Vec::new();
    for t in tasks {
        bodies.push(t.await.expect("task"));
    }
    assert_eq!(srv.state.metrics.renders() - before, 1, "100 identical misses must render once");
    assert!(bodies.iter().all(|b| b == &bodies[0]));
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn http_bytes_equal_cli_bytes() {
    let (srv, base) = start(config()).await;
    let source = std::fs::read_to_string(common::repo().join("grammars/stochastic.mdg")).expect("grammar");
    for (format, seed, detail) in [("glb", 5u64, 16u32), ("stl", 9, 8), ("gltf", 1, 12)] {
        let r = post(&base, "/v1/render", &json!({"source": source, "format": format, "seed": seed, "detail": detail})).await;
        assert_eq!(r.status(), 200);
        let http = r.bytes().await.expect("body");
        let cli = common::render_source(&source, &["--format", format, "--seed", &seed.to_string(), "--detail", &detail.to_string()]);
        assert!(http.as_ref() == cli.as_slice(), "{format}: HTTP and CLI bytes differ");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn graceful_shutdown_finishes_in_flight_render() {
    let (srv, base) = start(config()).await;
    let slow = json!({"source": SLOW, "limits": {"timeout_ms": 1200, "max_steps": 2_000_000_000u64}, "on_limit": "truncate"});
    let b2 = base.clone();
    let inflight = tokio::spawn(async move { post(&b2, "/v1/render", &slow).await });
    tokio::time::sleep(Duration::from_millis(300)).await;
    srv.shutdown();
    assert!(!srv.state.is_ready());
    let r = inflight.await.expect("task");
    assert_eq!(r.status(), 200, "the in-flight render finishes");
    assert_eq!(header(&r, "x-rulemesh-truncated"), "true");
    srv.wait().await.expect("clean shutdown");
    // Nothing listens any more.
    assert!(client().get(format!("{base}/healthz")).send().await.is_err());
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn openapi_document_lists_every_route_with_methods_and_errors() {
    let (srv, base) = start(config()).await;
    let c = client();
    let r = c.get(format!("{base}/openapi.json")).send().await.expect("get");
    assert_eq!(r.status(), 200);
    assert!(header(&r, "content-type").starts_with("application/json"));
    let text = r.text().await.expect("text");
    // An OpenAPI 3.1 document: utoipa's, with the request schemas
    // tightened to what the server accepts (schema::tighten_openapi; its
    // if/then rules are JSON Schema 2020-12, beyond utoipa's own model, so
    // schemathesis, which loads and checks it, is the parser:
    // tests/it/harden/schema.rs).
    let doc: Value = serde_json::from_str(&text).expect("JSON");
    assert_eq!(doc["openapi"], "3.1.0");
    let mut generated = serde_json::to_value(service::http::openapi()).expect("value");
    service::schema::tighten_openapi(&mut generated);
    assert_eq!(&doc, &generated, "served = generated, tightened");
    assert_eq!(doc["components"]["schemas"]["RenderBody"]["properties"]["format"]["anyOf"][0]["enum"][0], "glb", "{}", doc["components"]["schemas"]["RenderBody"]);

    // Every $ref points at a schema that exists.
    fn refs(v: &Value, out: &mut Vec<String>) {
        match v {
            Value::Object(m) => {
                for (k, x) in m {
                    match (k.as_str(), x) {
                        ("$ref", Value::String(r)) => out.push(r.clone()),
                        _ => refs(x, out),
                    }
                }
            }
            Value::Array(a) => a.iter().for_each(|x| refs(x, out)),
            _ => {}
        }
    }
    let mut all = Vec::new();
    refs(&doc, &mut all);
    assert!(!all.is_empty());
    for r in &all {
        let name = r.strip_prefix("#/components/schemas/").unwrap_or_else(|| panic!("unexpected $ref {r}"));
        assert!(doc["components"]["schemas"].get(name).is_some(), "dangling $ref {r}");
    }

    // The routes the issue asks for, with their methods and error statuses.
    let expected: &[(&str, &str, &[u16])] = &[
        ("/v1/render", "post", &[200, 400, 413, 422, 503, 504]),
        ("/v1/render/batch", "post", &[200, 400, 404, 413]),
        ("/v1/models/{file}", "get", &[200, 304, 400, 404, 422, 503, 504]),
        ("/v1/grammars", "get", &[200]),
        ("/v1/grammars/{name}", "get", &[200, 404]),
        ("/v1/grammars/{name}/schema", "get", &[200, 404]),
        ("/v1/schema", "post", &[200, 400, 413, 422]),
        ("/v1/check", "post", &[200, 400, 413]),
        ("/healthz", "get", &[200]),
        ("/readyz", "get", &[200, 503]),
        ("/metrics", "get", &[200]),
        ("/openapi.json", "get", &[200]),
    ];
    let paths = doc["paths"].as_object().expect("paths");
    let mut documented: Vec<&str> = paths.keys().map(String::as_str).collect();
    documented.sort_unstable();
    let mut wanted: Vec<&str> = expected.iter().map(|e| e.0).collect();
    wanted.sort_unstable();
    assert_eq!(documented, wanted, "documented paths");
    for (path, method, statuses) in expected {
        let op = &paths[*path];
        let methods: Vec<&str> = op.as_object().expect("operations").keys().map(String::as_str).collect();
        assert_eq!(methods, vec![*method], "{path}");
        for st in *statuses {
            let resp = &op[*method]["responses"][st.to_string()];
            assert!(resp.is_object(), "{method} {path} does not document {st}");
            if *st >= 400 {
                assert_eq!(resp["content"]["application/json"]["schema"]["$ref"], "#/components/schemas/ErrorBody", "{method} {path} {st}");
            }
        }
    }
    for schema in ["RenderBody", "LimitsBody", "CheckBody", "CheckReport", "GrammarList", "GrammarInfo", "ParamInfo", "ErrorBody", "ErrorDetail", "Diagnostic"] {
        assert!(doc["components"]["schemas"].get(schema).is_some(), "schema {schema}");
    }
    assert!(doc["components"]["schemas"]["RenderBody"]["properties"]["on_limit"].is_object());
    assert_eq!(doc["components"]["schemas"]["GrammarInfo"]["properties"]["printable"]["type"], "boolean");
    // The batch body is the render body with `source` optional, plus the batch's own fields.
    let batch = &doc["components"]["schemas"]["BatchBody"];
    for field in ["source", "grammar", "seeds", "sweep", "on_limit", "limits"] {
        assert!(batch["properties"][field].is_object(), "BatchBody.{field}: {batch}");
    }
    assert!(!batch["required"].as_array().is_some_and(|r| r.iter().any(|f| f == "source")), "{batch}");
    assert_eq!(batch["properties"]["seeds"]["maxItems"], 256);
    let render_200 = &paths["/v1/render"]["post"]["responses"]["200"];
    assert!(render_200["headers"]["X-Rulemesh-Seed"].is_object(), "{render_200}");

    // Each documented path and method is served by the router (not the 404
    // fallback), and other methods on it answer 405.
    for (path, method, _) in expected {
        let url = format!("{base}{}", path.replace("{file}", "gem.glb").replace("{name}", "gem"));
        let r = match *method {
            "get" => c.get(&url).send().await,
            _ => c.post(&url).header("content-type", "application/json").body("{\"source\":\"\"}").send().await,
        }
        .expect("request");
        assert_ne!(header(&r, "x-rulemesh-error"), "not_found", "{method} {path} is documented but not routed");
        assert!(r.status().as_u16() < 500, "{method} {path}: {}", r.status());
        let other = if *method == "get" { c.delete(&url) } else { c.get(&url) };
        assert_eq!(other.send().await.expect("request").status(), 405, "{path}");
    }
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn compression_is_negotiated_for_text_and_decodes() {
    let (srv, base) = start(config()).await;
    let plain = client();
    let source = small("compression");
    // Reference bodies in identity encoding.
    let gltf_url = format!("{base}/v1/models/tower.gltf?seed=2");
    let reference_gltf = plain.get(&gltf_url).send().await.expect("get");
    let gltf_etag = header(&reference_gltf, "etag").to_string();
    let reference_gltf = reference_gltf.bytes().await.expect("body");
    let ascii = json!({"source": source, "format": "stl-ascii", "seed": 1});
    let reference_ascii = post(&base, "/v1/render", &ascii).await.bytes().await.expect("body");
    let reference_list = plain.get(format!("{base}/v1/grammars")).send().await.expect("get").bytes().await.expect("body");
    assert!(reference_gltf.len() > 1000 && reference_ascii.len() > 1000 && reference_list.len() > 1000);

    for enc in ["gzip", "br", "zstd"] {
        // The raw response: encoded, with its own ETag and Vary.
        let r = plain.get(&gltf_url).header("accept-encoding", enc).send().await.expect("get");
        assert_eq!(header(&r, "content-encoding"), enc);
        // Every Vary line (glTF says Sec-CH-UA-Mobile, User-Agent too: docs/loaders.md).
        let vary: Vec<String> = r.headers().get_all("vary").iter().filter_map(|v| v.to_str().ok()).map(str::to_ascii_lowercase).collect();
        assert!(vary.iter().any(|v| v.contains("accept-encoding")) && vary.iter().any(|v| v.contains("user-agent")), "{enc}: {vary:?}");
        let tagged = header(&r, "etag").to_string();
        assert_eq!(tagged, format!("{}-{enc}\"", gltf_etag.trim_end_matches('"')));
        let raw = r.bytes().await.expect("body");
        assert!(raw.len() < reference_gltf.len() / 2, "{enc}: {} of {} bytes", raw.len(), reference_gltf.len());
        // A client holding the encoded variant's ETag gets 304.
        let r = plain.get(&gltf_url).header("if-none-match", &tagged).send().await.expect("get");
        assert_eq!(r.status(), 304, "{enc}");

        // A real client that decodes only this encoding gets the same bytes back.
        let decoding = reqwest::Client::builder()
            .gzip(enc == "gzip")
            .brotli(enc == "br")
            .zstd(enc == "zstd")
            .build()
            .expect("client");
        let r = decoding.get(&gltf_url).send().await.expect("get");
        assert!(header(&r, "etag").ends_with(&format!("-{enc}\"")), "{enc}: compressed on the wire");
        assert_eq!(r.bytes().await.expect("body"), reference_gltf, "{enc}: glTF");
        let r = decoding.post(format!("{base}/v1/render")).json(&ascii).send().await.expect("post");
        assert!(header(&r, "etag").ends_with(&format!("-{enc}\"")), "{enc}: ASCII STL compressed");
        assert_eq!(r.bytes().await.expect("body"), reference_ascii, "{enc}: ASCII STL");
        let r = decoding.get(format!("{base}/v1/grammars")).send().await.expect("get");
        assert_eq!(r.bytes().await.expect("body"), reference_list, "{enc}: JSON");
    }

    // Binary models go out as they are, whatever the client accepts.
    for url in [format!("{base}/v1/models/gem.glb?seed=1"), format!("{base}/v1/models/gem.stl?seed=1")] {
        let r = plain.get(&url).header("accept-encoding", "gzip, br, zstd").send().await.expect("get");
        assert_eq!(r.status(), 200);
        assert_eq!(header(&r, "content-encoding"), "", "{url}");
    }
    let r = plain.post(format!("{base}/v1/render")).header("accept-encoding", "gzip").json(&json!({"source": source})).send().await.expect("post");
    assert_eq!(header(&r, "content-type"), "model/gltf-binary");
    assert_eq!(header(&r, "content-encoding"), "");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn print_3mf_ug_stack_and_report_over_http() {
    let (srv, base) = start(config()).await;
    let source = "rule R { BOX {} BOX { x 0.5 } }";
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "size_mm": 30, "format": "3mf"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "model/3mf");
    assert!(r.bytes().await.expect("body").starts_with(b"PK"));
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "size_mm": 30, "print_report": true})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "content-type"), "application/json");
    let report: Value = r.json().await.expect("report");
    assert_eq!(report["is_watertight"], true);
    assert_eq!(report["shells"], 1);
    assert!((report["bbox_mm"][0].as_f64().expect("mm") - 30.0).abs() < 1e-3, "{report}");
    // STL responses carry the report as headers.
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "format": "stl"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(header(&r, "x-print-watertight"), "true");
    assert_eq!(header(&r, "x-print-shells"), "1");
    assert_eq!(header(&r, "x-print-volume-mm3"), "1.500");
    assert_eq!(header(&r, "x-print-bbox-mm"), "1.500 1.000 1.000");
    // size_mm without print is a 400, as is a nonsense size.
    let r = post(&base, "/v1/render", &json!({"source": source, "size_mm": 30})).await;
    assert_eq!(r.status(), 400);
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "size_mm": -1})).await;
    assert_eq!(r.status(), 400);
    // The other new languages and format.
    let r = post(&base, "/v1/render", &json!({"source": "b1.5s1.4w0.1", "language": "stack", "format": "stl"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(common::decode_stl(&r.bytes().await.expect("body")).len(), 144);
    let r = post(&base, "/v1/render", &json!({"source": source, "format": "ug"})).await;
    assert_eq!(r.status(), 200);
    let ug = r.text().await.expect("text");
    let r = post(&base, "/v1/render", &json!({"source": ug, "language": "ug", "format": "stl"})).await;
    assert_eq!(r.status(), 200);
    assert_eq!(common::decode_stl(&r.bytes().await.expect("body")).len(), 24);
    // Built-in grammars print through the models route too.
    let r = client().get(format!("{base}/v1/models/tower.stl?print=true&size_mm=40")).send().await.expect("request");
    assert_eq!(r.status(), 200);
    // The printer profile: the test plate's 0.5 mm wall (at 20 mm) is thin
    // against the default 0.8 mm, not against 0.4 mm; a small build volume
    // and a low triangle ceiling are findings too.
    let plate = std::fs::read_to_string(common::repo().join("tests/data/print/thin-plate.mdg")).expect("plate");
    let report = |extra: Value| {
        let mut body = json!({"source": plate, "print": true, "size_mm": 20, "print_report": true});
        body.as_object_mut().expect("object").extend(extra.as_object().expect("object").clone());
        let base = base.clone();
        async move {
            let r = post(&base, "/v1/render", &body).await;
            assert_eq!(r.status(), 200, "{body}");
            r.json::<Value>().await.expect("report")
        }
    };
    let codes = |r: &Value| r["findings"].as_array().expect("findings").iter().map(|f| f["code"].as_str().expect("code").to_string()).collect::<Vec<_>>();
    let r = report(json!({})).await;
    assert_eq!(codes(&r), ["thin_wall"], "{r}");
    assert!((r["thinnest_wall_mm"].as_f64().expect("mm") - 0.5).abs() < 0.1, "{r}");
    let r = report(json!({"min_wall_mm": 0.4})).await;
    assert_eq!(codes(&r), Vec::<String>::new(), "{r}");
    let r = report(json!({"min_wall_mm": 0.4, "build_volume_mm": [10, 10, 10], "triangle_ceiling": 4})).await;
    assert_eq!(codes(&r), ["too_big", "too_many_triangles"], "{r}");
    assert_eq!(r["profile"]["build_volume_mm"], json!([10.0, 10.0, 10.0]));
    // The models route takes the profile as query parameters.
    let r = client().get(format!("{base}/v1/models/rook.stl?print=true&print_report=true&build_volume_mm=10x10x10")).send().await.expect("request");
    assert_eq!(r.status(), 200);
    let r: Value = r.json().await.expect("report");
    assert!(codes(&r).contains(&"too_big".to_string()), "{r}");
    // Out of range, malformed, or without print: 400.
    for bad in [json!({"min_wall_mm": 0}), json!({"min_wall_mm": 101}), json!({"build_volume_mm": [1, 2]}), json!({"build_volume_mm": [1, 2, -3]}), json!({"triangle_ceiling": 0})] {
        let mut body = json!({"source": source, "print": true});
        body.as_object_mut().expect("object").extend(bad.as_object().expect("object").clone());
        let r = post(&base, "/v1/render", &body).await;
        assert_eq!(r.status(), 400, "{body}");
    }
    let r = post(&base, "/v1/render", &json!({"source": source, "min_wall_mm": 0.4})).await;
    assert_eq!(r.status(), 400);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
