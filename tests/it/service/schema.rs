//! Parameter schemas (issue 20): `GET /v1/grammars/{name}/schema` and
//! `POST /v1/schema` return JSON Schemas (2020-12) that a real validator
//! (Python's `jsonschema`, installed with schemathesis by scripts/test)
//! accepts as schemas, and whose verdicts on requests agree with the
//! server's: what the schema accepts renders, what it rejects is refused.
//! Also: seeds are full 64-bit values, as JSON numbers or decimal text.

use super::*;

/// `jsonschema`'s verdicts on `instances` against `schema`, after checking
/// the schema itself against the 2020-12 meta-schema.
pub(super) fn validator_verdicts(schema: &Value, instances: &[Value]) -> Vec<bool> {
    let python = std::env::var("TRIMESH_PYTHON").unwrap_or_else(|_| common::repo().join(".tools/venv/bin/python").display().to_string());
    let code = "import json, sys, jsonschema\n\
        doc = json.load(sys.stdin)\n\
        jsonschema.Draft202012Validator.check_schema(doc['schema'])\n\
        v = jsonschema.Draft202012Validator(doc['schema'])\n\
        print(json.dumps([v.is_valid(i) for i in doc['instances']]))";
    let mut child = std::process::Command::new(&python)
        .args(["-c", code])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("python with jsonschema (scripts/test installs it)");
    use std::io::Write as _;
    child.stdin.take().expect("stdin").write_all(json!({ "schema": schema, "instances": instances }).to_string().as_bytes()).expect("write");
    let out = child.wait_with_output().expect("python runs");
    assert!(out.status.success(), "jsonschema: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("a JSON list of verdicts")
}

/// A source with an integer parameter, a float with a range and named presets.
const PARAMS: &str = "@param int n 3 1 8\n@param float r 0.25 0 1.5\n@presets round princess emerald\nstartshape A\nrule A { (n + preset) * { x r } BOX {} }\n";

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn schemas_validate_and_agree_with_the_server() {
    let (srv, base) = start(config()).await;
    // Every library grammar has a schema the meta-schema accepts.
    let list: Value = client().get(format!("{base}/v1/grammars")).send().await.expect("list").json().await.expect("json");
    let names: Vec<String> = list["grammars"].as_array().expect("grammars").iter().map(|g| g["name"].as_str().expect("name").to_string()).collect();
    assert!(names.len() >= 19, "{names:?}");
    for name in &names {
        let r = client().get(format!("{base}/v1/grammars/{name}/schema")).send().await.expect("schema");
        assert_eq!(r.status(), 200, "{name}");
        assert_eq!(header(&r, "content-type"), "application/schema+json");
        let schema: Value = r.json().await.expect("json");
        assert_eq!(validator_verdicts(&schema, &[json!({})]), vec![true], "{name}");
    }
    // The library grammar with a parameter: in range renders, out of range is refused by both.
    let schema: Value = client().get(format!("{base}/v1/grammars/icosahedron-transformations/schema")).send().await.expect("schema").json().await.expect("json");
    assert_eq!(schema["properties"]["params"]["properties"]["phase"], json!({ "type": "number", "default": 0, "minimum": 0, "maximum": 2 }));
    let good = json!({ "params": { "phase": 1.5 }, "seed": "9223372036854775809", "format": "stl" });
    let bad = json!({ "params": { "phase": 2.5 } });
    assert_eq!(validator_verdicts(&schema, &[good.clone(), bad.clone()]), vec![true, false]);
    let source = client().get(format!("{base}/v1/grammars/icosahedron-transformations")).send().await.expect("source").text().await.expect("text");
    let with_source = |mut v: Value| {
        v["source"] = Value::from(source.clone());
        v
    };
    assert_eq!(post(&base, "/v1/render", &with_source(good)).await.status(), 200);
    assert_eq!(post(&base, "/v1/render", &with_source(bad)).await.status(), 400);
    // A posted source: integer, float and preset parameters, and the options.
    let r = post(&base, "/v1/schema", &json!({ "source": PARAMS })).await;
    assert_eq!(r.status(), 200);
    let schema: Value = r.json().await.expect("json");
    let cases = [
        (json!({ "params": { "n": 8, "r": 0.5, "preset": "emerald" } }), true),
        (json!({ "params": { "preset": 2 } }), true),
        (json!({ "params": { "preset": 3 } }), false),
        (json!({ "params": { "n": 9 } }), false),
        (json!({ "params": { "n": 2.5 } }), false),
        (json!({ "params": { "preset": "marquise" } }), false),
        (json!({ "params": { "nope": 1 } }), false),
        (json!({ "format": "obj" }), false),
        (json!({ "detail": 1000 }), false),
        (json!({ "size_mm": 40 }), false),
        (json!({ "print": true, "size_mm": 40, "format": "3mf" }), true),
        (json!({ "print": true, "min_wall_mm": 0.4, "build_volume_mm": [100, 100, 50], "triangle_ceiling": 5000, "format": "stl" }), true),
        (json!({ "min_wall_mm": 0.4 }), false),
        (json!({ "print": true, "build_volume_mm": [100, 100] }), false),
        (json!({ "print": true, "triangle_ceiling": 0 }), false),
        (json!({ "seed": "-1" }), false),
    ];
    let instances: Vec<Value> = cases.iter().map(|(v, _)| v.clone()).collect();
    let verdicts = validator_verdicts(&schema, &instances);
    for ((case, want), got) in cases.iter().zip(&verdicts) {
        assert_eq!(got, want, "schema verdict on {case}");
        let mut body = case.clone();
        body["source"] = Value::from(PARAMS);
        let status = post(&base, "/v1/render", &body).await.status();
        assert_eq!(status.is_success(), *want, "server on {case}: {status}");
    }
    // A source that does not parse: a 400 with line and column.
    let r = post(&base, "/v1/schema", &json!({ "source": "startshape A\nrule A {\n", "language": "mdg" })).await;
    assert_eq!(r.status(), 400);
    let e = error_body(r).await;
    assert!(e["diagnostics"][0]["line"].as_u64().is_some(), "{e}");
    // 404 for an unknown grammar.
    assert_eq!(client().get(format!("{base}/v1/grammars/nope/schema")).send().await.expect("404").status(), 404);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_seed_beyond_2_to_the_53_is_exact_as_number_or_text_and_in_the_cli() {
    let (srv, base) = start(config()).await;
    let random = "startshape A\nrule A { B {} }\nrule B 1 { BOX {} }\nrule B 1 { SPHERE {} }\nrule B 1 { CONE {} }\n";
    let model = |seed: Value| {
        let base = base.clone();
        async move {
            let r = post(&base, "/v1/render", &json!({ "source": random, "seed": seed, "format": "stl" })).await;
            assert_eq!(r.status(), 200);
            r.bytes().await.expect("bytes").to_vec()
        }
    };
    let big = (1u64 << 63) + 1;
    let as_number = model(json!(big)).await;
    let as_text = model(json!(big.to_string())).await;
    assert_eq!(as_number, as_text);
    // The CLI reads the same seed to the same model.
    let dir = common::tempdir();
    let src = dir.path().join("random.mdg");
    std::fs::write(&src, random).expect("write");
    let out = dir.path().join("random.stl");
    let run = common::run(&["render", src.to_str().expect("utf-8"), "--seed", &big.to_string(), "-o", out.to_str().expect("utf-8")], None);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert_eq!(std::fs::read(&out).expect("stl"), as_number);
    // Seeds 2^63 + 1 … 2^63 + 8 are one double apart from none of them (the
    // doubles there are 2048 apart): distinct models among them show that no
    // door rounded the seed to a double.
    let mut models = std::collections::BTreeSet::new();
    for k in 1..=8u64 {
        models.insert(model(json!((1u64 << 63) + k)).await);
    }
    assert!(models.len() > 1, "eight seeds near 2^63 gave one model");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
