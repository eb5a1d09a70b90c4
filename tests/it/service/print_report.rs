//! A print's figures travel with its bytes (issue 32): the print stage
//! measures the solid once, every cache tier keeps the figures beside the
//! model, and HTTP (STL and 3MF, as `X-Print-*` headers) and gRPC
//! (`RenderMeta.print`) serve the same values, on a miss, on a memory hit
//! and on a disk hit after a restart. No door measures served bytes: the
//! STL re-reader the headers once came from no longer exists.

use super::*;

const HEADERS: [&str; 5] = ["x-print-volume-mm3", "x-print-surface-area-mm2", "x-print-bbox-mm", "x-print-shells", "x-print-watertight"];

fn print_headers(r: &reqwest::Response) -> Vec<String> {
    HEADERS.iter().map(|h| header(r, h).to_string()).collect()
}

/// The figures a gRPC `RenderMeta` carries, formatted as the HTTP headers are.
fn grpc_headers(p: &pb::PrintSummary) -> Vec<String> {
    assert_eq!(p.bbox_mm.len(), 3, "{p:?}");
    vec![
        format!("{:.3}", p.volume_mm3),
        format!("{:.3}", p.surface_area_mm2),
        format!("{:.3} {:.3} {:.3}", p.bbox_mm[0], p.bbox_mm[1], p.bbox_mm[2]),
        p.shells.to_string(),
        p.watertight.to_string(),
    ]
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_print_report_is_stored_with_the_model_and_served_alike_by_every_door_and_tier() {
    let dir = common::tempdir();
    let disk = || ServeConfig { cache_dir: Some(dir.path().join("cache")), ..config() };
    let (srv, base) = start(disk()).await;
    // Two overlapping unit boxes: one shell of 1.5 × 1 × 1 units, printed 30 mm long.
    let source = "rule R { BOX {} BOX { x 0.5 } }";
    let body = |format: &str| json!({"source": source, "print": true, "size_mm": 30, "format": format, "seed": 1});

    // The JSON report is what the stage measured; the headers are its figures.
    let r = post(&base, "/v1/render", &json!({"source": source, "print": true, "size_mm": 30, "print_report": true, "seed": 1})).await;
    assert_eq!(r.status(), 200);
    let report: Value = r.json().await.expect("report");
    let f = |k: &str| report[k].as_f64().unwrap_or_else(|| panic!("{k}: {report}"));
    let b = |i: usize| report["bbox_mm"][i].as_f64().expect("bbox");
    let expected = vec![
        format!("{:.3}", f("volume_mm3")),
        format!("{:.3}", f("surface_area_mm2")),
        format!("{:.3} {:.3} {:.3}", b(0), b(1), b(2)),
        report["shells"].to_string(),
        report["is_watertight"].to_string(),
    ];
    assert_eq!(expected, ["12000.000", "3200.000", "30.000 20.000 20.000", "1", "true"], "{report}");

    for format in ["stl", "3mf"] {
        let miss = post(&base, "/v1/render", &body(format)).await;
        assert_eq!((miss.status().as_u16(), header(&miss, "x-rulemesh-cache")), (200, "miss"), "{format}");
        assert_eq!(print_headers(&miss), expected, "{format} miss");
        let hit = post(&base, "/v1/render", &body(format)).await;
        assert_eq!(header(&hit, "x-rulemesh-cache"), "hit", "{format}");
        assert_eq!(print_headers(&hit), expected, "{format} memory hit");
    }
    // A model that is not printed carries no figures.
    let plain = post(&base, "/v1/render", &json!({"source": source, "format": "stl"})).await;
    assert_eq!(plain.status(), 200);
    assert!(HEADERS.iter().all(|h| header(&plain, h).is_empty()), "{:?}", plain.headers());

    let mut g = grpc_client(&srv).await;
    for format in ["stl", "3mf"] {
        let req = pb::RenderRequest { source: source.into(), format: format.into(), print: Some(true), size_mm: Some(30.0), seed: Some(1), ..Default::default() };
        let meta = g.render(req).await.expect("Render").into_inner().meta.expect("meta");
        assert!(meta.cache_hit, "{format}: the HTTP render's entry");
        assert_eq!(grpc_headers(&meta.print.expect("print figures")), expected, "gRPC {format}");
    }
    let meta = g.render(pb::RenderRequest { source: source.into(), format: "stl".into(), ..Default::default() }).await.expect("Render").into_inner().meta.expect("meta");
    assert_eq!(meta.print, None);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");

    // A new process: its memory tier is empty, so the hit is the disk
    // entry's, whose header kept the figures.
    let (srv, base) = start(disk()).await;
    for format in ["stl", "3mf"] {
        let hit = post(&base, "/v1/render", &body(format)).await;
        assert_eq!(header(&hit, "x-rulemesh-cache"), "hit", "{format} from disk");
        assert_eq!(print_headers(&hit), expected, "{format} disk hit");
    }
    let mut g = grpc_client(&srv).await;
    let req = pb::RenderRequest { source: source.into(), format: "3mf".into(), print: Some(true), size_mm: Some(30.0), seed: Some(1), ..Default::default() };
    assert_eq!(grpc_headers(&g.render(req).await.expect("Render").into_inner().meta.expect("meta").print.expect("print")), expected);
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
