//! The playground: a page at `/playground` where a developer picks a library
//! grammar or pastes source, edits its parameters through a form built from
//! the parameter schema (`POST /v1/schema`), and sees the model live in
//! three.js, with diagnostics marked at their line, the response headers,
//! the size of every format and the PNG preview.
//!
//! Every file is embedded in the binary (`include_bytes!`), three.js too
//! (vendored in `vendor/three/`, 0.187.0, MIT): the page needs no build step
//! at run time, no CDN and no network beyond this server, so it works on an
//! air-gapped machine and cannot drift from the API it was tested against.
//! The routes are not `/v1/` routes: they stay open when API keys are
//! configured (the page asks for a key and sends it with its API calls) and
//! are not in the OpenAPI document, which describes the API only.

use axum::extract::Path;
use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Redirect, Response};
use axum::routing::get;
use axum::Router;

/// `Cache-Control` of the playground's files: they change only with the binary.
const CACHE_FILES: &str = "public, max-age=3600";

/// One embedded file: its path under `/playground/`, media type and bytes.
struct Asset {
    path: &'static str,
    media_type: &'static str,
    bytes: &'static [u8],
}

/// A JavaScript module's media type.
const JS: &str = "text/javascript; charset=utf-8";

/// Every file the page loads, the vendored three.js modules among them
/// (only those the page imports, and what they import in turn).
const ASSETS: &[Asset] = &[
    Asset { path: "", media_type: "text/html; charset=utf-8", bytes: include_bytes!("playground/index.html") },
    Asset { path: "app.js", media_type: JS, bytes: include_bytes!("playground/app.js") },
    Asset { path: "style.css", media_type: "text/css; charset=utf-8", bytes: include_bytes!("playground/style.css") },
    Asset { path: "three/build/three.module.js", media_type: JS, bytes: include_bytes!("../../../../vendor/three/build/three.module.js") },
    Asset { path: "three/build/three.core.js", media_type: JS, bytes: include_bytes!("../../../../vendor/three/build/three.core.js") },
    Asset { path: "three/examples/jsm/loaders/GLTFLoader.js", media_type: JS, bytes: include_bytes!("../../../../vendor/three/examples/jsm/loaders/GLTFLoader.js") },
    Asset { path: "three/examples/jsm/utils/BufferGeometryUtils.js", media_type: JS, bytes: include_bytes!("../../../../vendor/three/examples/jsm/utils/BufferGeometryUtils.js") },
    Asset { path: "three/examples/jsm/utils/SkeletonUtils.js", media_type: JS, bytes: include_bytes!("../../../../vendor/three/examples/jsm/utils/SkeletonUtils.js") },
    Asset { path: "three/examples/jsm/controls/OrbitControls.js", media_type: JS, bytes: include_bytes!("../../../../vendor/three/examples/jsm/controls/OrbitControls.js") },
    Asset { path: "three/examples/jsm/libs/meshopt_decoder.module.js", media_type: JS, bytes: include_bytes!("../../../../vendor/three/examples/jsm/libs/meshopt_decoder.module.js") },
    Asset { path: "three/LICENSE", media_type: "text/plain; charset=utf-8", bytes: include_bytes!("../../../../vendor/three/LICENSE") },
];

/// The playground's routes, merged into the HTTP router beside the API.
pub fn router<S: Clone + Send + Sync + 'static>() -> Router<S> {
    Router::new()
        // Relative URLs in the page (`app.js`, `three/…`) need the trailing slash.
        .route("/playground", get(|| async { Redirect::permanent("/playground/") }))
        .route("/playground/", get(|| async { asset("") }))
        .route("/playground/{*path}", get(|Path(path): Path<String>| async move { asset(&path) }))
}

/// The embedded file at `path`, or 404.
fn asset(path: &str) -> Response {
    match ASSETS.iter().find(|a| a.path == path) {
        Some(a) => ([(header::CONTENT_TYPE, a.media_type), (header::CACHE_CONTROL, CACHE_FILES)], a.bytes).into_response(),
        None => (StatusCode::NOT_FOUND, [(header::CONTENT_TYPE, "text/plain; charset=utf-8")], "no such playground file\n").into_response(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_asset_path_is_unique_and_every_import_of_a_vendored_module_is_served() {
        let mut paths: Vec<&str> = ASSETS.iter().map(|a| a.path).collect();
        paths.sort_unstable();
        let before = paths.len();
        paths.dedup();
        assert_eq!(paths.len(), before);
        // Relative imports (`from '../utils/X.js'`, `from './three.core.js'`)
        // of every served module resolve to a served module.
        for a in ASSETS.iter().filter(|a| a.path.ends_with(".js")) {
            let text = std::str::from_utf8(a.bytes).expect("utf-8 module");
            let dir = a.path.rsplit_once('/').map_or("", |(d, _)| d);
            for spec in text.split("from '").skip(1).filter_map(|s| s.split('\'').next()).filter(|s| s.starts_with('.')) {
                let mut parts: Vec<&str> = dir.split('/').filter(|p| !p.is_empty()).collect();
                for seg in spec.split('/') {
                    match seg {
                        "." => {}
                        ".." => {
                            parts.pop();
                        }
                        s => parts.push(s),
                    }
                }
                let target = parts.join("/");
                assert!(ASSETS.iter().any(|b| b.path == target), "{} imports {spec} ({target}), which is not served", a.path);
            }
        }
    }
}
