//! A running hub as the command line reaches it: its address, the caller's token, the CA
//! its certificate is checked against; its JSON API over HTTP(S) and its WebSocket port.
//! Shared by `fleetlink record` and `fleetlink play` (the `fleetlink` package) and by
//! `fleetlink bench record` (the `fleetlink-bench` package), so neither depends on the
//! other for it.

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use anyhow::{Context, bail};
use bytes::Bytes;
use http_body_util::{BodyExt, Full};
use hyper_util::rt::TokioIo;

/// How long one API request may take (a download: each piece of it).
const REQUEST_TIMEOUT: Duration = Duration::from_secs(30);

#[derive(clap::Args, Debug, Clone)]
pub struct Remote {
    /// The hub: ws://HOST:PORT, wss://…, http(s)://…, or HOST:PORT.
    #[arg(long, value_name = "URL")]
    pub hub: String,
    /// The caller's token (a user's, from `fleetlink admin token` or the login API). Also
    /// read from FLEETLINK_TOKEN.
    #[arg(
        long,
        env = "FLEETLINK_TOKEN",
        hide_env_values = true,
        default_value = ""
    )]
    pub token: String,
    /// Check a wss:// or https:// hub's certificate against this CA file instead of the
    /// system's roots.
    #[arg(long, value_name = "FILE")]
    pub ca: Option<PathBuf>,
}

/// An answer of the API: its status and body.
pub struct Answer {
    pub status: hyper::StatusCode,
    pub body: Bytes,
}

impl Answer {
    /// The body as JSON when the status is a success; otherwise the API's `error` text.
    pub fn json(self, what: &str) -> anyhow::Result<serde_json::Value> {
        let v: serde_json::Value = serde_json::from_slice(&self.body).unwrap_or_default();
        if !self.status.is_success() {
            let why = v
                .get("error")
                .and_then(|e| e.as_str())
                .map(str::to_owned)
                .unwrap_or_else(|| String::from_utf8_lossy(&self.body).into_owned());
            bail!("{what}: HTTP {}: {why}", self.status.as_u16());
        }
        Ok(v)
    }
}

struct Target {
    https: bool,
    host: String,
    port: u16,
}

impl Remote {
    fn target(&self) -> anyhow::Result<Target> {
        let (scheme, rest) = match self.hub.split_once("://") {
            Some((s, r)) => (s.to_ascii_lowercase(), r),
            None => ("ws".to_owned(), self.hub.as_str()),
        };
        let https = match scheme.as_str() {
            "ws" | "http" => false,
            "wss" | "https" => true,
            s => bail!(
                "--hub {}: unknown scheme {s:?} (use ws://, wss://, http:// or https://)",
                self.hub
            ),
        };
        let authority = rest.split('/').next().unwrap_or_default();
        let (host, port) = match authority.rsplit_once(':') {
            Some((h, p)) if !h.ends_with(']') || authority.starts_with('[') => (
                h.trim_matches(|c| c == '[' || c == ']').to_owned(),
                p.parse::<u16>()
                    .with_context(|| format!("--hub {}: bad port {p:?}", self.hub))?,
            ),
            _ => (authority.to_owned(), if https { 443 } else { 80 }),
        };
        if host.is_empty() {
            bail!("--hub {}: no host", self.hub);
        }
        Ok(Target { https, host, port })
    }

    /// The hub's WebSocket URL with the token as a query parameter.
    pub fn ws_url(&self) -> anyhow::Result<String> {
        let t = self.target()?;
        let scheme = if t.https { "wss" } else { "ws" };
        let host = if t.host.contains(':') {
            format!("[{}]", t.host)
        } else {
            t.host.clone()
        };
        let mut url = format!("{scheme}://{host}:{}/", t.port);
        if !self.token.is_empty() {
            url.push_str("?token=");
            url.push_str(&self.token);
        }
        Ok(url)
    }

    /// The TLS client configuration for a wss/https hub.
    pub fn tls(&self) -> anyhow::Result<Arc<tokio_rustls::rustls::ClientConfig>> {
        use fleetlink_auth::tls::{ClientTlsFiles, HubRoots};
        let files = ClientTlsFiles {
            roots: match &self.ca {
                Some(ca) => HubRoots::CaFile(ca.clone()),
                None => HubRoots::System,
            },
            client_cert: None,
        };
        fleetlink_auth::tls::client_config(&files).map_err(|e| anyhow::anyhow!("TLS setup: {e}"))
    }

    /// One API request; `body` is sent as JSON. The answer's body is read whole.
    pub async fn request(
        &self,
        method: hyper::Method,
        path: &str,
        body: Option<serde_json::Value>,
    ) -> anyhow::Result<Answer> {
        let res = tokio::time::timeout(REQUEST_TIMEOUT, async {
            let res = self.send(method.clone(), path, body).await?;
            let status = res.status();
            let body = res
                .into_body()
                .collect()
                .await
                .with_context(|| format!("reading the answer to {method} {path}"))?
                .to_bytes();
            anyhow::Ok(Answer { status, body })
        })
        .await
        .map_err(|_| anyhow::anyhow!("{method} {path}: no answer within {REQUEST_TIMEOUT:?}"))??;
        Ok(res)
    }

    /// A GET whose body is written to `out` as it arrives; returns the bytes written.
    pub async fn download(&self, path: &str, out: &std::path::Path) -> anyhow::Result<u64> {
        use tokio::io::AsyncWriteExt;
        let res = self.send(hyper::Method::GET, path, None).await?;
        if !res.status().is_success() {
            let status = res.status();
            let body = res
                .into_body()
                .collect()
                .await
                .map(|b| b.to_bytes())
                .unwrap_or_default();
            return Answer { status, body }
                .json(&format!("GET {path}"))
                .map(|_| 0);
        }
        let mut file = tokio::fs::File::create(out)
            .await
            .with_context(|| format!("creating {}", out.display()))?;
        let mut body = res.into_body();
        let mut n = 0u64;
        loop {
            let frame = tokio::time::timeout(REQUEST_TIMEOUT, body.frame())
                .await
                .map_err(|_| anyhow::anyhow!("GET {path}: stalled for {REQUEST_TIMEOUT:?}"))?;
            let Some(frame) = frame else { break };
            let frame = frame.with_context(|| format!("GET {path}"))?;
            if let Ok(data) = frame.into_data() {
                file.write_all(&data)
                    .await
                    .with_context(|| format!("writing {}", out.display()))?;
                n += data.len() as u64;
            }
        }
        file.flush().await?;
        Ok(n)
    }

    async fn send(
        &self,
        method: hyper::Method,
        path: &str,
        body: Option<serde_json::Value>,
    ) -> anyhow::Result<hyper::Response<hyper::body::Incoming>> {
        let t = self.target()?;
        let tcp = tokio::net::TcpStream::connect((t.host.as_str(), t.port))
            .await
            .with_context(|| format!("connecting to {}:{}", t.host, t.port))?;
        let mut req = hyper::Request::builder()
            .method(method.clone())
            .uri(path)
            .header(hyper::header::HOST, format!("{}:{}", t.host, t.port))
            .header(hyper::header::ACCEPT, "application/json");
        if !self.token.is_empty() {
            req = req.header(
                hyper::header::AUTHORIZATION,
                format!("Bearer {}", self.token),
            );
        }
        let body = match body {
            Some(v) => {
                req = req.header(hyper::header::CONTENT_TYPE, "application/json");
                Full::new(Bytes::from(serde_json::to_vec(&v)?))
            }
            None => Full::new(Bytes::new()),
        };
        let req = req.body(body)?;
        let what = format!("{method} {path}");
        if t.https {
            let name = tokio_rustls::rustls::pki_types::ServerName::try_from(t.host.clone())
                .with_context(|| format!("server name {}", t.host))?;
            let tls = tokio_rustls::TlsConnector::from(self.tls()?)
                .connect(name, tcp)
                .await
                .with_context(|| format!("TLS to {}", t.host))?;
            exchange(TokioIo::new(tls), req, &what).await
        } else {
            exchange(TokioIo::new(tcp), req, &what).await
        }
    }
}

async fn exchange<I>(
    io: TokioIo<I>,
    req: hyper::Request<Full<Bytes>>,
    what: &str,
) -> anyhow::Result<hyper::Response<hyper::body::Incoming>>
where
    I: tokio::io::AsyncRead + tokio::io::AsyncWrite + Unpin + Send + 'static,
{
    let (mut sender, conn) = hyper::client::conn::http1::handshake(io)
        .await
        .with_context(|| what.to_owned())?;
    tokio::spawn(async move {
        let _ = conn.await;
    });
    sender
        .send_request(req)
        .await
        .with_context(|| what.to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn remote(hub: &str) -> Remote {
        Remote {
            hub: hub.into(),
            token: "t0k".into(),
            ca: None,
        }
    }

    #[test]
    fn hub_addresses_read_in_every_spelling() {
        let t = remote("127.0.0.1:8080").target().unwrap();
        assert_eq!(
            (t.https, t.host.as_str(), t.port),
            (false, "127.0.0.1", 8080)
        );
        let t = remote("wss://hub.example.com/").target().unwrap();
        assert_eq!(
            (t.https, t.host.as_str(), t.port),
            (true, "hub.example.com", 443)
        );
        let t = remote("http://[::1]:9000").target().unwrap();
        assert_eq!((t.https, t.host.as_str(), t.port), (false, "::1", 9000));
        assert_eq!(remote("ws://h:1").ws_url().unwrap(), "ws://h:1/?token=t0k");
        assert!(remote("ftp://h").target().is_err());
        assert!(remote("ws://h:notaport").target().is_err());
    }
}
