//! Where the hub gets the JSON Web Key Set that OIDC bearer tokens are checked against:
//! a file, or the provider's JWKS URL fetched over HTTPS. The security core caches the
//! keys and says when they are due for a refresh (`JwksCache::needs_refresh`: after their
//! time to live, or sooner when a token names a key it does not know); this module only
//! fetches.

use std::path::PathBuf;
use std::sync::Arc;

use bytes::Bytes;
use http_body_util::{BodyExt, Empty, Limited};
use hyper_util::rt::TokioIo;

/// Largest JWKS document accepted.
const MAX_JWKS: usize = 1 << 20;

#[derive(Debug, Clone)]
pub enum JwksSource {
    File(PathBuf),
    Url(String),
}

impl std::str::FromStr for JwksSource {
    type Err = String;

    fn from_str(s: &str) -> Result<JwksSource, String> {
        if s.starts_with("https://") || s.starts_with("http://") {
            Ok(JwksSource::Url(s.to_owned()))
        } else {
            Ok(JwksSource::File(PathBuf::from(s)))
        }
    }
}

impl JwksSource {
    /// The current document.
    pub async fn fetch(&self) -> Result<String, String> {
        match self {
            JwksSource::File(p) => {
                let p = p.clone();
                tokio::task::spawn_blocking(move || {
                    fleetlink_auth::jwt::read_jwks_file(&p).map_err(|e| e.to_string())
                })
                .await
                .map_err(|e| e.to_string())?
            }
            JwksSource::Url(u) => {
                tokio::time::timeout(std::time::Duration::from_secs(10), fetch_url(u))
                    .await
                    .map_err(|_| format!("fetching {u} timed out"))?
            }
        }
    }
}

async fn fetch_url(url: &str) -> Result<String, String> {
    let uri: hyper::Uri = url
        .parse()
        .map_err(|e| format!("bad JWKS URL {url}: {e}"))?;
    let https = uri.scheme_str() == Some("https");
    let host = uri
        .host()
        .ok_or_else(|| format!("JWKS URL {url} has no host"))?
        .to_owned();
    let port = uri.port_u16().unwrap_or(if https { 443 } else { 80 });
    let path = uri.path_and_query().map_or("/", |p| p.as_str()).to_owned();
    let tcp = tokio::net::TcpStream::connect((host.as_str(), port))
        .await
        .map_err(|e| format!("connecting to {host}:{port}: {e}"))?;
    if https {
        // System roots, the agent's defaults (no client certificate).
        let files = fleetlink_auth::tls::ClientTlsFiles {
            roots: fleetlink_auth::tls::HubRoots::System,
            client_cert: None,
        };
        let cfg =
            fleetlink_auth::tls::client_config(&files).map_err(|e| format!("TLS setup: {e}"))?;
        let name = tokio_rustls::rustls::pki_types::ServerName::try_from(host.clone())
            .map_err(|e| format!("server name {host}: {e}"))?;
        let tls = tokio_rustls::TlsConnector::from(Arc::clone(&cfg))
            .connect(name, tcp)
            .await
            .map_err(|e| format!("TLS to {host}: {e}"))?;
        get(TokioIo::new(tls), &host, &path).await
    } else {
        get(TokioIo::new(tcp), &host, &path).await
    }
}

async fn get<I>(io: TokioIo<I>, host: &str, path: &str) -> Result<String, String>
where
    I: tokio::io::AsyncRead + tokio::io::AsyncWrite + Unpin + Send + 'static,
{
    let (mut sender, conn) = hyper::client::conn::http1::handshake(io)
        .await
        .map_err(|e| format!("HTTP to {host}: {e}"))?;
    tokio::spawn(async move {
        let _ = conn.await;
    });
    let req = hyper::Request::get(path)
        .header(hyper::header::HOST, host)
        .header(hyper::header::ACCEPT, "application/json")
        .body(Empty::<Bytes>::new())
        .map_err(|e| e.to_string())?;
    let res = sender
        .send_request(req)
        .await
        .map_err(|e| format!("GET {path} from {host}: {e}"))?;
    if !res.status().is_success() {
        return Err(format!("GET {path} from {host}: HTTP {}", res.status()));
    }
    let body = Limited::new(res.into_body(), MAX_JWKS)
        .collect()
        .await
        .map_err(|e| format!("reading the JWKS from {host}: {e}"))?
        .to_bytes();
    String::from_utf8(body.to_vec()).map_err(|e| format!("JWKS from {host} is not UTF-8: {e}"))
}

/// Loads the keys into the security core if they are due (first call, expiry, or an
/// unknown key id seen). Errors are logged; the cached keys stay in use.
pub async fn refresh_if_due(security: &fleetlink_auth::Security, source: &JwksSource) {
    let now = fleetlink_auth::UnixTime::now();
    let Some(cfg) = security.authn.policy().jwt.as_ref() else {
        return;
    };
    if !security.authn.jwks().needs_refresh(cfg, now) {
        return;
    }
    match source.fetch().await {
        Ok(doc) => match security.authn.jwks().install(&doc, now) {
            Ok(n) => tracing::info!("loaded {n} OIDC signing keys"),
            Err(e) => tracing::warn!("cannot use the JWKS: {e}"),
        },
        Err(e) => tracing::warn!("cannot fetch the JWKS: {e}"),
    }
}
