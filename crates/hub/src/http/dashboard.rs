//! The fleet dashboard (`web/`), served at `/` from files embedded in the binary.
//!
//! Design choice: the built bundle is committed under `crates/hub/assets/dashboard/` and
//! pulled in with `include_bytes!`, so building the hub needs no Node and running it needs
//! no internet; `web/build.sh` rebuilds the bundle and the dashboard interop suite fails
//! when the committed one is stale. The file names are fixed (no content hash in them),
//! so every response says `Cache-Control: no-cache` and carries an `ETag`: browsers keep
//! their copy and revalidate it with one cheap `304` per load.

use std::sync::LazyLock;

use axum::http::{HeaderMap, HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};

/// One embedded file: the URL path it answers, its bytes and content type.
struct Asset {
    path: &'static str,
    body: &'static [u8],
    content_type: &'static str,
}

const ASSETS: [Asset; 3] = [
    Asset {
        path: "/",
        body: include_bytes!("../../assets/dashboard/index.html"),
        content_type: "text/html; charset=utf-8",
    },
    Asset {
        path: "/app.js",
        body: include_bytes!("../../assets/dashboard/app.js"),
        content_type: "text/javascript; charset=utf-8",
    },
    Asset {
        path: "/app.css",
        body: include_bytes!("../../assets/dashboard/app.css"),
        content_type: "text/css; charset=utf-8",
    },
];

/// Strong validators, one per asset: FNV-1a of the bytes, computed once.
static ETAGS: LazyLock<[HeaderValue; 3]> = LazyLock::new(|| {
    ASSETS.each_ref().map(|a| {
        let h = a.body.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
            (h ^ u64::from(*b)).wrapping_mul(0x0100_0000_01b3)
        });
        HeaderValue::from_str(&format!("\"{h:016x}\"")).expect("hex is a valid header value")
    })
});

/// The response for `path` (`/index.html` is `/`), or `None` when it is not a dashboard
/// file. Answers `304 Not Modified` when `If-None-Match` names the current version.
pub fn serve(path: &str, request: &HeaderMap) -> Option<Response> {
    let path = if path == "/index.html" { "/" } else { path };
    let i = ASSETS.iter().position(|a| a.path == path)?;
    let asset = &ASSETS[i];
    let etag = ETAGS[i].clone();
    let fresh = request
        .get_all(header::IF_NONE_MATCH)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .flat_map(|v| v.split(','))
        .any(|t| t.trim() == etag.to_str().unwrap_or_default() || t.trim() == "*");
    let headers = [
        (header::CACHE_CONTROL, HeaderValue::from_static("no-cache")),
        (header::ETAG, etag),
        (
            header::HeaderName::from_static("x-content-type-options"),
            HeaderValue::from_static("nosniff"),
        ),
    ];
    Some(if fresh {
        (StatusCode::NOT_MODIFIED, headers).into_response()
    } else {
        (
            headers,
            [(
                header::CONTENT_TYPE,
                HeaderValue::from_static(asset.content_type),
            )],
            asset.body,
        )
            .into_response()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serves_each_asset_with_its_type_and_revalidates() {
        let none = HeaderMap::new();
        for (path, ty) in [
            ("/", "text/html; charset=utf-8"),
            ("/index.html", "text/html; charset=utf-8"),
            ("/app.js", "text/javascript; charset=utf-8"),
            ("/app.css", "text/css; charset=utf-8"),
        ] {
            let r = serve(path, &none).expect(path);
            assert_eq!(r.status(), StatusCode::OK, "{path}");
            assert_eq!(r.headers()[header::CONTENT_TYPE], ty, "{path}");
            assert_eq!(r.headers()[header::CACHE_CONTROL], "no-cache", "{path}");
            let mut again = HeaderMap::new();
            again.insert(header::IF_NONE_MATCH, r.headers()[header::ETAG].clone());
            assert_eq!(
                serve(path, &again).expect(path).status(),
                StatusCode::NOT_MODIFIED
            );
        }
        assert!(serve("/nope.js", &none).is_none());
    }

    #[test]
    fn the_page_loads_only_embedded_files() {
        let html = std::str::from_utf8(ASSETS[0].body).expect("utf-8 index.html");
        assert!(html.contains("src=\"app.js\"") && html.contains("href=\"app.css\""));
        assert!(
            !html.contains("http://") && !html.contains("https://"),
            "no CDN"
        );
    }
}
