//! The icon set is served by name like the rest of the library:
//! `icon-STEM` in the list, its source, its schema and its models.

use super::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_icon_is_served_by_name() {
    let (srv, base) = start(config()).await;
    let c = client();
    let list: Value = c.get(format!("{base}/v1/grammars")).send().await.expect("get").json().await.expect("json");
    let names: Vec<&str> = list["grammars"].as_array().expect("array").iter().filter_map(|g| g["name"].as_str()).collect();
    assert!(names.contains(&"icon-coin") && names.contains(&"gem"), "{names:?}");
    let src = c.get(format!("{base}/v1/grammars/icon-coin")).send().await.expect("get");
    assert_eq!(src.status(), 200);
    assert_eq!(src.text().await.expect("text"), std::fs::read_to_string(common::repo().join("grammars/icons/coin.mdg")).expect("file"));
    let schema: Value = c.get(format!("{base}/v1/grammars/icon-coin/schema")).send().await.expect("get").json().await.expect("json");
    assert!(schema["properties"]["params"]["properties"]["points"].is_object(), "{schema}");
    let glb = c.get(format!("{base}/v1/models/icon-coin.glb?seed=1&p.preset=silver")).send().await.expect("get");
    assert_eq!(glb.status(), 200);
    let triangles: u64 = header(&glb, "x-rulemesh-triangles").parse().expect("count");
    assert!(triangles > 0 && triangles < 5000, "{triangles}");
    let bytes = glb.bytes().await.expect("body");
    assert_eq!(&bytes[..4], b"glTF");
    let png = c.get(format!("{base}/v1/models/icon-coin.png?seed=1")).send().await.expect("get");
    assert_eq!(png.status(), 200);
    assert_eq!(&png.bytes().await.expect("body")[..8], b"\x89PNG\r\n\x1a\n");
    srv.shutdown();
    srv.wait().await.expect("clean shutdown");
}
