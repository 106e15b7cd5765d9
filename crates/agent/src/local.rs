//! The agent's local rosbridge listener (default `127.0.0.1:9090`): local programs
//! (roslibpy, roslibjs, anything that speaks rosbridge v2) publish to and subscribe from
//! the fleet through it, exactly as they would talk to a rosbridge server.
//!
//! The same port answers plain HTTP requests with the configuration API
//! (`GET`/`PUT /api/v1/config`, docs/runtime-config.md): a connection whose request asks
//! for a WebSocket upgrade is a rosbridge client, any other is an HTTP client.
//!
//! A rosbridge client is pinged and closed after the silence limit without progress, as
//! the hub's viewers are (`SessionConfig::liveness`, docs/security.md "Viewer liveness"):
//! a local program that hangs does not keep the robot's topics flowing to the hub.

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_relay::Router;

use crate::runtime::RuntimeConfig;
use fleetlink_relay::websocket::deflate;
use fleetlink_relay::websocket::liveness::Peer;
use fleetlink_relay::websocket::tcp_progress;
use fleetlink_rosbridge::SessionConfig;
use tokio::io::AsyncReadExt;
use tokio::net::TcpListener;
use tokio_tungstenite::tungstenite::handshake::server::{Request, Response};
use tokio_tungstenite::tungstenite::http::HeaderValue;
use tokio_tungstenite::tungstenite::http::header::SEC_WEBSOCKET_EXTENSIONS;
use tokio_tungstenite::tungstenite::protocol::WebSocketConfig;
use tokio_util::sync::CancellationToken;
use tokio_util::task::TaskTracker;

/// Longest pause between accept attempts while accepting fails (out of file descriptors
/// and the like): the listener retries with backoff instead of spinning.
const ACCEPT_BACKOFF_MAX: Duration = Duration::from_secs(1);

/// Accepts local rosbridge clients until `shutdown`; their sessions are spawned on
/// `sessions`, which the agent waits for when it stops.
pub async fn serve(
    listener: TcpListener,
    router: Arc<Router>,
    cfg: Arc<SessionConfig>,
    runtime: Option<Arc<RuntimeConfig>>,
    shutdown: CancellationToken,
    sessions: TaskTracker,
) {
    let ws_config = WebSocketConfig::default()
        .max_message_size(Some(cfg.max_message_size))
        .max_frame_size(Some(cfg.max_message_size));
    let mut backoff = Duration::ZERO;
    let mut failures = 0u64;
    loop {
        let (tcp, addr) = tokio::select! {
            r = listener.accept() => match r {
                Ok(x) => x,
                Err(e) => {
                    // Said once when it starts failing, then only how often, when it
                    // recovers: a listener out of descriptors would otherwise log (and
                    // spin) as fast as the kernel refuses.
                    if failures == 0 {
                        tracing::warn!("local listener: accept failed: {e}; retrying with backoff");
                    }
                    failures += 1;
                    backoff = (backoff * 2).clamp(Duration::from_millis(10), ACCEPT_BACKOFF_MAX);
                    tokio::select! {
                        _ = tokio::time::sleep(backoff) => continue,
                        _ = shutdown.cancelled() => return,
                    }
                }
            },
            _ = shutdown.cancelled() => return,
        };
        if failures > 0 {
            tracing::info!("local listener: accepting again after {failures} failed attempts");
            failures = 0;
            backoff = Duration::ZERO;
        }
        let _ = tcp.set_nodelay(true);
        let (router, cfg, shutdown) = (router.clone(), cfg.clone(), shutdown.clone());
        let runtime = runtime.clone();
        sessions.spawn(async move {
            let local = tcp.local_addr().ok();
            let mut tcp = tcp;
            let (kind, head) = sniff(&mut tcp).await;
            // What was read to tell the two apart is read again by whoever serves it.
            let (r, w) = tcp.into_split();
            let tcp = tokio::io::join(std::io::Cursor::new(head).chain(r), w);
            match kind {
                Sniffed::WebSocket => {}
                Sniffed::Http => return serve_api(tcp, runtime, shutdown).await,
                Sniffed::Gone => return,
            }
            // tungstenite answers the handshake; the session then runs on the socket's
            // own halves (a client sends nothing more before the handshake's answer).
            // permessage-deflate for a client that offers it, as on the hub.
            let mut agreed = None;
            // The shape tungstenite's handshake callback must have (its error is a whole
            // HTTP response).
            #[allow(clippy::result_large_err)]
            let answer = |req: &Request, mut res: Response| {
                agreed = cfg.deflate.and_then(|c| {
                    let offers = req
                        .headers()
                        .get_all(SEC_WEBSOCKET_EXTENSIONS)
                        .iter()
                        .filter_map(|v| v.to_str().ok());
                    let a = deflate::negotiate(offers)?;
                    let v = HeaderValue::from_str(&a.response()).ok()?;
                    res.headers_mut().insert(SEC_WEBSOCKET_EXTENSIONS, v);
                    Some(c)
                });
                Ok(res)
            };
            let accepted =
                tokio_tungstenite::accept_hdr_async_with_config(tcp, answer, Some(ws_config)).await;
            match accepted {
                Ok(ws) => {
                    let auth = fleetlink_relay::gate::SessionAuth::open();
                    let max = cfg.max_message_size;
                    let (r, w) = ws.into_inner().into_inner();
                    let (mut sink, mut stream) =
                        fleetlink_relay::websocket::server_halves(r, w, bytes::Bytes::new(), max);
                    if let Some(c) = agreed {
                        (sink, stream) = (sink.deflating(c), stream.inflating());
                    }
                    // Pinged and dropped when silent as the hub's viewers are
                    // (`cfg.liveness`), its connection's draining counted as progress.
                    let peer = Peer {
                        addr: Some(addr),
                        progress: local.map(|l| tcp_progress::probe(l, addr, sink.written())),
                    };
                    fleetlink_rosbridge::serve(sink, stream, router, peer, cfg, shutdown, auth)
                        .await
                }
                Err(e) => tracing::debug!("local client {addr}: WebSocket handshake failed: {e}"),
            }
        });
    }
}

/// What a new connection's first request is.
enum Sniffed {
    WebSocket,
    Http,
    /// Closed, or silent for [`SNIFF_TIMEOUT`].
    Gone,
}

/// How long a new connection may take to send its request's head.
const SNIFF_TIMEOUT: Duration = Duration::from_secs(10);
/// Most bytes of a request head looked at; a longer head is left to the WebSocket
/// handshake, which refuses it.
const SNIFF_MAX: usize = 8192;

/// Reads the request head (and whatever came with it, at most [`SNIFF_MAX`] bytes): a
/// WebSocket upgrade, or not. The bytes read are handed back to be read again. Each read
/// waits for the socket, so a head that comes in pieces costs one wake per piece.
async fn sniff(tcp: &mut (impl tokio::io::AsyncRead + Unpin)) -> (Sniffed, Vec<u8>) {
    let mut buf = Vec::with_capacity(1024);
    let look = async {
        let mut chunk = [0u8; 2048];
        loop {
            let room = (SNIFF_MAX - buf.len()).min(chunk.len());
            let n = match tcp.read(&mut chunk[..room]).await {
                Ok(0) | Err(_) => return Sniffed::Gone,
                Ok(n) => n,
            };
            buf.extend_from_slice(&chunk[..n]);
            if let Some(end) = buf.windows(4).position(|w| w == b"\r\n\r\n") {
                let text = String::from_utf8_lossy(&buf[..end]).to_ascii_lowercase();
                let upgrade = text.lines().any(|l| {
                    l.strip_prefix("upgrade:")
                        .is_some_and(|v| v.contains("websocket"))
                });
                return if upgrade {
                    Sniffed::WebSocket
                } else {
                    Sniffed::Http
                };
            }
            if buf.len() == SNIFF_MAX {
                return Sniffed::WebSocket;
            }
        }
    };
    let kind = tokio::time::timeout(SNIFF_TIMEOUT, look)
        .await
        .unwrap_or(Sniffed::Gone);
    (kind, buf)
}

/// Largest change accepted by the configuration API.
const MAX_CHANGE_BYTES: usize = 1 << 20;

/// Serves HTTP/1.1 on `tcp`: the configuration API.
async fn serve_api(
    tcp: impl tokio::io::AsyncRead + tokio::io::AsyncWrite + Unpin + Send + 'static,
    runtime: Option<Arc<RuntimeConfig>>,
    shutdown: CancellationToken,
) {
    let service = hyper::service::service_fn(move |req| {
        let runtime = runtime.clone();
        async move { Ok::<_, std::convert::Infallible>(config_api(req, runtime).await) }
    });
    let conn = hyper::server::conn::http1::Builder::new()
        .serve_connection(hyper_util::rt::TokioIo::new(tcp), service);
    tokio::select! {
        r = conn => if let Err(e) = r {
            tracing::debug!("local configuration API: {e}");
        },
        _ = shutdown.cancelled() => {}
    }
}

type ApiBody = http_body_util::Full<bytes::Bytes>;

fn answer(status: u16, body: serde_json::Value) -> hyper::Response<ApiBody> {
    hyper::Response::builder()
        .status(status)
        .header("content-type", "application/json")
        .body(ApiBody::from(body.to_string()))
        .unwrap_or_else(|_| hyper::Response::new(ApiBody::default()))
}

/// `GET /api/v1/config` (the configuration in force) and `PUT /api/v1/config` (a change,
/// YAML or JSON), with `Authorization: Bearer <local_rosbridge.config_token>`.
async fn config_api(
    req: hyper::Request<hyper::body::Incoming>,
    runtime: Option<Arc<RuntimeConfig>>,
) -> hyper::Response<ApiBody> {
    use http_body_util::BodyExt;
    use serde_json::json;
    if req.uri().path() != "/api/v1/config" {
        return answer(
            404,
            json!({"error": "this is a rosbridge WebSocket endpoint; the one HTTP resource here is /api/v1/config"}),
        );
    }
    let Some(runtime) = runtime else {
        return answer(
            404,
            json!({"error": "this agent's configuration cannot change while it runs"}),
        );
    };
    let token = runtime.current().local_config_token().to_owned();
    if token.is_empty() {
        return answer(
            403,
            json!({"error": "the configuration API is closed: set local_rosbridge.config_token in the agent's YAML to open it"}),
        );
    }
    let given = req
        .headers()
        .get(hyper::header::AUTHORIZATION)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.strip_prefix("Bearer "))
        .unwrap_or_default();
    if !constant_time_eq(given.as_bytes(), token.as_bytes()) {
        return answer(
            401,
            json!({"error": "authentication required: Authorization: Bearer <local_rosbridge.config_token>"}),
        );
    }
    match *req.method() {
        hyper::Method::GET => answer(200, runtime.view()),
        hyper::Method::PUT | hyper::Method::PATCH | hyper::Method::POST => {
            let limited = http_body_util::Limited::new(req.into_body(), MAX_CHANGE_BYTES);
            let body = match limited.collect().await {
                Ok(b) => b.to_bytes(),
                Err(e) => {
                    return answer(
                        413,
                        json!({"error": format!("the change could not be read (at most {MAX_CHANGE_BYTES} bytes): {e}")}),
                    );
                }
            };
            let Ok(text) = std::str::from_utf8(&body) else {
                return answer(
                    400,
                    json!({"error": "a change is YAML or JSON text, in UTF-8"}),
                );
            };
            // Kept on disk (written and synced) off the runtime's thread.
            let text = text.to_owned();
            let applied =
                tokio::task::spawn_blocking(move || runtime.apply(&text, "the local API")).await;
            match applied {
                Ok(Ok(view)) => answer(200, view),
                Ok(Err(refusal)) => answer(400, serde_json::to_value(refusal).unwrap_or_default()),
                Err(e) => answer(500, json!({"error": format!("the change failed: {e}")})),
            }
        }
        _ => answer(405, json!({"error": "use GET or PUT"})),
    }
}

/// Compares a presented token with the configured one in time independent of where they
/// differ.
fn constant_time_eq(a: &[u8], b: &[u8]) -> bool {
    a.len() == b.len() && a.iter().zip(b).fold(0u8, |acc, (x, y)| acc | (x ^ y)) == 0
}

/// Binds the local listener address.
pub async fn bind(addr: SocketAddr) -> std::io::Result<TcpListener> {
    TcpListener::bind(addr).await
}

#[cfg(test)]
mod tests {
    use super::*;
    use tokio::io::AsyncWriteExt;

    /// The head the listener must see whole before it can tell a WebSocket client from an
    /// HTTP one, sent in two pieces: it waits for the second without a timer, and hands
    /// back every byte it read.
    #[tokio::test]
    async fn a_request_head_in_pieces_is_read_as_it_comes_and_handed_back() {
        let head = b"GET / HTTP/1.1\r\nHost: robot\r\nUpgrade: websocket\r\n\r\n";
        let (mut client, mut server) = tokio::io::duplex(1024);
        client.write_all(&head[..20]).await.unwrap();
        let sniffing = sniff(&mut server);
        tokio::pin!(sniffing);
        tokio::select! {
            biased;
            _ = &mut sniffing => panic!("half a head was taken for a whole one"),
            () = std::future::ready(()) => {}
        }
        client.write_all(&head[20..]).await.unwrap();
        let (kind, read) = sniffing.await;
        assert!(matches!(kind, Sniffed::WebSocket));
        assert_eq!(read, head);
    }

    #[tokio::test]
    async fn a_plain_request_is_http_and_a_closed_connection_is_gone() {
        let (mut client, mut server) = tokio::io::duplex(1024);
        client
            .write_all(b"GET /api/v1/config HTTP/1.1\r\nHost: robot\r\n\r\n")
            .await
            .unwrap();
        assert!(matches!(sniff(&mut server).await.0, Sniffed::Http));
        let (client, mut server) = tokio::io::duplex(1024);
        drop(client);
        assert!(matches!(sniff(&mut server).await.0, Sniffed::Gone));
    }
}
