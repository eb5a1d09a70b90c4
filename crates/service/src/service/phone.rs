//! Phone-facing requests get glTF every phone loader opens.
//!
//! docs/loaders.md reads the phone loaders' sources: Filament's gltfio (and
//! SceneView on top of it) ignores `EXT_mesh_gpu_instancing` and draws one
//! copy of each instanced mesh without an error, and GLTFKit2 and Unity's
//! glTFast drop per-instance colours. The service's default, `instancing:
//! gpu`, is right for browsers and wrong there. So a request that comes
//! from a phone and names no `instancing` is written flat (plain meshes,
//! core glTF 2.0), which every loader in that table reads; a request that
//! names one gets what it names, and so does every request from elsewhere.
//!
//! A request is from a phone when it says so with the standard client hint
//! `Sec-CH-UA-Mobile: ?1` (Chromium on phones sends it), or when its
//! `User-Agent` names a phone platform or a phone app's HTTP stack: Android
//! (`Android`, `Dalvik`, OkHttp's `okhttp/`), iOS (`iPhone`, `iPad`, `iOS`,
//! URLSession's `CFNetwork/`). The choice reaches the validated options, so
//! the cache key holds the variant and a phone and a browser asking for the
//! same flat model share one cache entry; responses that a phone could have
//! changed say `Vary: Sec-CH-UA-Mobile, User-Agent` for shared caches.

use super::request::RenderBody;
use axum::http::HeaderMap;

/// The `Vary` value of a response whose bytes depend on whether the caller is a phone.
pub(crate) const VARY: &str = "Sec-CH-UA-Mobile, User-Agent";

/// Adds `Vary: Sec-CH-UA-Mobile, User-Agent` to a response in `format`
/// when a phone's default could have changed its bytes (a format with GPU
/// instancing: glTF), so a shared cache keeps a phone's and a browser's apart.
pub fn vary(h: &mut axum::http::HeaderMap, format: crate::export::Format) {
    if format.info().caps.instancing {
        h.append(axum::http::header::VARY, axum::http::HeaderValue::from_static(VARY));
    }
}

/// `User-Agent` fragments that mark a phone: platforms and the HTTP stacks of phone apps.
const PHONE_AGENTS: &[&str] = &["Android", "Dalvik", "okhttp/", "iPhone", "iPad", "iOS", "CFNetwork/"];

/// Whether the request's headers say it comes from a phone (see the module documentation).
pub(crate) fn is_phone(headers: &HeaderMap) -> bool {
    let hint = headers.get("sec-ch-ua-mobile").and_then(|v| v.to_str().ok()).is_some_and(|v| v.trim() == "?1");
    let agent = headers.get("user-agent").and_then(|v| v.to_str().ok()).unwrap_or("");
    hint || PHONE_AGENTS.iter().any(|token| agent.contains(token))
}

impl RenderBody {
    /// The body with a phone's default filled in: `instancing: flat` when
    /// the caller is a phone and the body names no instancing. Applied
    /// before [`RenderBody::plan`], so the key and the bytes follow it.
    pub(crate) fn with_phone_default(mut self, phone: bool) -> RenderBody {
        if phone && self.options.instancing.is_none() {
            self.options.instancing = Some(crate::core::Choice::name(crate::export::Instancing::Flat).to_string());
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn headers(pairs: &[(&'static str, &'static str)]) -> HeaderMap {
        let mut h = HeaderMap::new();
        for (k, v) in pairs {
            h.insert(*k, v.parse().expect("header value"));
        }
        h
    }

    #[test]
    fn phones_are_known_by_the_client_hint_or_their_agent() {
        for phone in [
            &[("sec-ch-ua-mobile", "?1")][..],
            &[("user-agent", "Mozilla/5.0 (Linux; Android 14; Pixel 8) AppleWebKit/537.36 Chrome/131.0 Mobile Safari/537.36")],
            &[("user-agent", "okhttp/4.12.0")],
            &[("user-agent", "Dalvik/2.1.0 (Linux; U; Android 14)")],
            &[("user-agent", "Mozilla/5.0 (iPhone; CPU iPhone OS 18_1 like Mac OS X) AppleWebKit/605.1.15")],
            &[("user-agent", "MyApp/3 CFNetwork/1568.100.1 Darwin/24.0.0")],
        ] {
            assert!(is_phone(&headers(phone)), "{phone:?}");
        }
        for other in [
            &[][..],
            &[("sec-ch-ua-mobile", "?0"), ("user-agent", "Mozilla/5.0 (X11; Linux x86_64) Chrome/131.0")],
            &[("user-agent", "curl/8.5.0")],
            &[("user-agent", "Mozilla/5.0 (Macintosh; Intel Mac OS X 14_1) Safari/605.1.15")],
        ] {
            assert!(!is_phone(&headers(other)), "{other:?}");
        }
    }
}
