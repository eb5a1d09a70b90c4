//! Bad input over the wire: typed errors with positions, never a 500.

use super::*;
use serde_json::json;

/// Issue 17: `@macro A()` then a body line whose ninth byte falls inside
/// `é` panicked in the MDG preprocessor (a 500 `internal` over HTTP). Now
/// it is the 400 `parse_error` of an unclosed macro, with line and column.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn mdg_preprocessor_multibyte_macro_body_over_http_is_400_with_position() {
    let (srv, base) = start(config()).await;
    let c = client();
    for path in ["/v1/render", "/v1/check"] {
        let r = c.post(format!("{base}{path}")).json(&json!({"source": "@macro A()\nabcdefgh\u{e9}", "language": "mdg"})).send().await.expect("post");
        if path == "/v1/check" {
            assert_eq!(r.status(), 200);
            let v: Value = r.json().await.expect("json");
            assert_eq!(v["ok"], false, "{v}");
            assert_eq!((v["diagnostics"][0]["line"].as_u64(), v["diagnostics"][0]["column"].as_u64()), (Some(1), Some(1)), "{v}");
            continue;
        }
        assert_eq!(r.status(), 400);
        let e = error_of(r).await;
        assert_eq!(e["code"], "parse_error", "{e}");
        assert_eq!((e["line"].as_u64(), e["column"].as_u64()), (Some(1), Some(1)), "{e}");
        assert_eq!(e["message"].as_str().map(|m| m.contains("`@macro A` is not closed by `@endmacro`")), Some(true), "{e}");
    }
    // The same over gRPC: InvalidArgument with the position in the details.
    let err = grpc(&srv)
        .await
        .render(rulemesh::service::grpc::pb::RenderRequest { source: "@macro A()\nabcdefgh\u{e9}".into(), language: "mdg".into(), ..Default::default() })
        .await
        .expect_err("a parse error");
    assert_eq!(err.code(), tonic::Code::InvalidArgument);
    let details: Value = serde_json::from_slice(err.details()).expect("JSON details");
    assert_eq!((details["error"]["line"].as_u64(), details["error"]["column"].as_u64()), (Some(1), Some(1)), "{details}");
    let m = metrics(&base).await;
    assert_eq!(sample(&m, "rulemesh_requests_total{protocol=\"http\",route=\"/v1/render\",status=\"500\"}"), 0.0, "{m}");
    stop(srv).await;
}

/// Found by the `http_request` fuzz target: `format: "scene"` for a source
/// detected as EisenScript (only L-systems make object hierarchies) was a
/// 500 `internal`; it is the client's request that cannot be honoured, a
/// 400 `bad_request` (gRPC InvalidArgument).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn http_request_scene_format_for_a_mesh_language_is_400_not_500() {
    let (srv, base) = start(config()).await;
    let fuzzed = "#define _nF -6 Fngumessage3333333333333333333330000m00000000000000se~e89161220]()475278678lrystem";
    // Every language renders as a scene (version 2) now: the fuzzed source
    // reads as EisenScript and is answered without an internal error; a bare
    // `box` is no language the detector knows (a 400 parse_error at 1:1 saying that).
    let r = client().post(format!("{base}/v1/render")).json(&json!({"source": fuzzed, "format": "scene"})).send().await.expect("post");
    assert_ne!(r.status(), 500, "{fuzzed}");
    let r = client().post(format!("{base}/v1/render")).json(&json!({"source": "box\n", "format": "scene"})).send().await.expect("post");
    assert_eq!(r.status(), 400);
    let e = error_of(r).await;
    assert_eq!(e["code"], "parse_error", "{e}");
    assert!(e["message"].as_str().is_some_and(|m| m.contains("cannot detect the language")), "{e}");
    let reply = grpc(&srv)
        .await
        .render(rulemesh::service::grpc::pb::RenderRequest { source: "box\n".into(), language: "eisenscript".into(), format: "scene".into(), ..Default::default() })
        .await
        .expect("an EisenScript box renders as a scene")
        .into_inner();
    let d = rulemesh::decode::scene::decode_scene_meshes(&reply.model, 16, 1_000).expect("decodes");
    assert_eq!(d.meshes.iter().map(|m| m.mesh.indices.len() / 3).sum::<usize>(), 12);
    stop(srv).await;
}

/// The `render_mdg` fuzz target (2026-12-02, 1.9 M executions): a rule
/// animated by itself (`rule X2 : X2 { … }`) made each evaluation of the
/// path evaluate the path again, until the stack overflowed (the process
/// died). Now the cycle is a typed evaluation error naming the rule, and so
/// is a chain of path rules deeper than the evaluator allows.
#[test]
fn mdg_path_rule_animated_by_itself_is_an_error_not_a_stack_overflow() {
    let found = "// Listing 4.2: A\nfps 25\nduration 2\nrule A : X2 : X2 { BOX {} B { x 2 } }\nrule B : X1 { SPHERE { s 0.5 } }\nrule X1 { 48/48 * { rz 360 } FRAME {} }\nrule X2 : X2 { BOX {} B { x 2 } }\n";
    let req = rulemesh::RenderRequest { language: Some(rulemesh::lang::Language::Mdg), ..Default::default() };
    let e = rulemesh::render(found.as_bytes(), &req).expect_err("a cycle");
    assert!(e.to_string().contains("path rule `X2` is used inside its own evaluation"), "{e}");
    // A chain P0 : P1, P1 : P2, …, P(n-1) : Pn: each path animated by the next, no cycle.
    let chain = |n: usize| {
        let mut s = String::from("fps 10\nduration 1\nrule A : P0 { BOX {} }\n");
        for i in 0..n {
            s.push_str(&format!("rule P{i} : P{} {{ FRAME {{}} }}\n", i + 1));
        }
        s + &format!("rule P{n} {{ FRAME {{}} }}\n")
    };
    let e = rulemesh::render(chain(200).as_bytes(), &req).expect_err("too deep");
    assert!(e.to_string().contains("nest more than 32 deep"), "{e}");
    // Nesting within the bound still renders.
    let out = rulemesh::render(chain(3).as_bytes(), &req).expect("renders");
    assert_eq!(out.primitives, 1);
}

/// The `http_request` fuzz target (2026-12-02, session 8, about 39 000
/// executions): an L-system whose axiom draws nothing
/// (`axiom:278670lrys#scene`: digits and letters no turtle command reads)
/// is a hierarchy with no leaves, and the instanced glTF writer refused it
/// ("an instanced model needs a buffer"), which the service answered with a
/// 500. Now an empty hierarchy is written as the flat writers write an empty
/// model: valid glTF with no meshes, over HTTP, gRPC and the CLI alike.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn lsystem_that_draws_nothing_is_an_empty_model_not_a_500() {
    let (srv, base) = start(config()).await;
    let found = "axiom:278670lrys#scene";
    for format in ["glb", "gltf"] {
        let r = client().post(format!("{base}/v1/render")).json(&json!({"source": found, "format": format})).send().await.expect("post");
        assert_eq!(r.status(), 200, "{format}");
        assert_eq!(r.headers().get("x-rulemesh-triangles").and_then(|v| v.to_str().ok()), Some("0"), "{format}");
        let bytes = r.bytes().await.expect("body");
        let doc: serde_json::Value = if format == "glb" {
            assert_eq!(&bytes[..4], b"glTF");
            let len = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]) as usize;
            serde_json::from_slice(&bytes[20..20 + len]).expect("glb JSON chunk")
        } else {
            serde_json::from_slice(&bytes).expect("glTF JSON")
        };
        assert_eq!(doc["asset"]["version"], "2.0", "{doc}");
        assert!(doc["meshes"].as_array().is_none_or(|m| m.is_empty()), "{doc}");
    }
    let reply = grpc(&srv)
        .await
        .render(rulemesh::service::grpc::pb::RenderRequest { source: found.into(), format: "glb".into(), ..Default::default() })
        .await
        .expect("a model");
    assert_eq!(&reply.into_inner().model[..4], b"glTF");
    let dir = crate::common::tempdir();
    let (src, out) = (dir.path().join("found.ls"), dir.path().join("found.glb"));
    std::fs::write(&src, found).expect("write");
    let run = crate::common::run(&["render", src.to_str().expect("utf-8"), "-o", out.to_str().expect("utf-8")], None);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert_eq!(&std::fs::read(&out).expect("glb")[..4], b"glTF");
    stop(srv).await;
}
