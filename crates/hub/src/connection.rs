//! One accepted socket, from admission to the end of its HTTP exchange: the front-door
//! limits, the TLS handshake, and hyper serving requests (or handing the socket over to
//! a WebSocket session).
//!
//! Design choice: the connection's permit ([`ConnPermit`]) lives in an [`OpenConn`] that
//! every request on the connection carries in its extensions; an upgraded WebSocket
//! session takes a clone, so the connection counts against the limits until the last of
//! the HTTP task and the session ends. A connection over a limit gets a short plain
//! answer saying which limit and which flag raises it, written under its own small
//! budget, because answering refusals must not become the next way to exhaust the hub.

use std::convert::Infallible;
use std::net::SocketAddr;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use axum::Router as HttpRouter;
use axum::body::Body;
use axum::extract::ConnectInfo;
use axum::http::{HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use hyper::body::Incoming;
use hyper_util::rt::{TokioIo, TokioTimer};
use tokio::io::{AsyncRead, AsyncWrite};
use tokio::net::TcpStream;
use tokio_util::sync::CancellationToken;

use crate::http_guards::{BodyVerdict, GuardedBody, IdleIo};
use crate::limits::{ConnPermit, Limits, Refusal};

/// The longest a refusal answer (TLS included) may take before the socket is dropped.
const REFUSAL_BUDGET: Duration = Duration::from_secs(2);

/// Per-connection facts handlers need: the peer, this end's address (which with the
/// peer's names the connection to the kernel, for a viewer's liveness), over mutual TLS
/// the robot its verified certificate names, and the connection's place under the limits.
#[derive(Clone)]
pub struct ConnMeta {
    pub peer: SocketAddr,
    pub local: Option<SocketAddr>,
    pub tls_name: Option<fleetlink_auth::RobotName>,
    pub open: Arc<OpenConn>,
}

impl std::fmt::Debug for ConnMeta {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ConnMeta")
            .field("peer", &self.peer)
            .field("tls_name", &self.tls_name)
            .finish_non_exhaustive()
    }
}

/// An open connection: holds its permit, and whether it still speaks HTTP.
pub struct OpenConn {
    _permit: ConnPermit,
    http_phase: Arc<AtomicBool>,
}

impl OpenConn {
    /// The connection becomes a WebSocket: HTTP's idle bound no longer applies.
    pub fn upgraded(&self) {
        self.http_phase.store(false, Ordering::Relaxed);
    }
}

/// What every connection task shares.
pub struct Door {
    pub app: HttpRouter,
    pub limits: Arc<Limits>,
    pub tls: Option<Arc<fleetlink_auth::tls::ReloadingServerConfig>>,
    pub security: Arc<fleetlink_auth::Security>,
    pub shutdown: CancellationToken,
}

impl Door {
    /// Serves one accepted socket to its end. `admitted` is [`Limits::admit`]'s answer,
    /// asked in the accept loop so connections are counted in the order they came.
    pub async fn serve(
        self: Arc<Self>,
        tcp: TcpStream,
        peer: SocketAddr,
        admitted: Result<ConnPermit, Refusal>,
    ) {
        let permit = match admitted {
            Ok(p) => p,
            Err(r) => return self.refuse(tcp, peer, r).await,
        };
        let http_phase = Arc::new(AtomicBool::new(true));
        let open = Arc::new(OpenConn {
            _permit: permit,
            http_phase: http_phase.clone(),
        });
        let local = tcp.local_addr().ok();
        let io = IdleIo::new(tcp, self.limits.cfg.idle_timeout, http_phase);
        let Some(tls) = self.tls.clone() else {
            let meta = ConnMeta {
                peer,
                local,
                tls_name: None,
                open,
            };
            return self.serve_http(io, meta).await;
        };
        let Some(stream) = self.tls_accept(&tls, io, peer).await else {
            return;
        };
        let tls_name =
            fleetlink_auth::tls::client_cert_name(stream.get_ref().1.peer_certificates());
        let meta = ConnMeta {
            peer,
            local,
            tls_name,
            open,
        };
        self.serve_http(stream, meta).await
    }

    /// The TLS handshake, inside an admission slot, all within the handshake timeout. A
    /// TLS client cannot be told "busy" in HTTP before its handshake, so it waits for a
    /// slot rather than being refused at once.
    async fn tls_accept<I>(
        &self,
        cfg: &fleetlink_auth::tls::ReloadingServerConfig,
        io: I,
        peer: SocketAddr,
    ) -> Option<tokio_rustls::server::TlsStream<I>>
    where
        I: AsyncRead + AsyncWrite + Unpin,
    {
        let limit = self.limits.cfg.tls_handshake_timeout;
        let deadline = tokio::time::Instant::now() + limit;
        let Ok(Some(_slot)) = tokio::time::timeout_at(deadline, self.limits.handshake()).await
        else {
            self.limits.note_refused(Refusal::Handshakes);
            return None;
        };
        let acceptor = tokio_rustls::TlsAcceptor::from(cfg.current());
        match tokio::time::timeout_at(deadline, acceptor.accept(io)).await {
            Ok(Ok(stream)) => Some(stream),
            // The peer went away mid-handshake: an abandoned connect (an agent keeps only
            // the first of its staggered connects) or a port probe, not a refused login.
            Ok(Err(e)) if e.kind() == std::io::ErrorKind::UnexpectedEof => {
                tracing::debug!("{peer} closed the connection during the TLS handshake");
                None
            }
            Ok(Err(e)) => {
                tracing::info!("TLS handshake with {peer} failed: {e}");
                // A missing or unverifiable client certificate is a refused
                // authentication; the audit log must show it.
                self.security.audit.record(fleetlink_auth::AuditRecord {
                    at: fleetlink_auth::UnixTime::now(),
                    principal: "unknown".into(),
                    client_ip: peer.ip(),
                    action: fleetlink_auth::audit::AuditAction::AuthFailure,
                    name: String::new(),
                    size: None,
                    allowed: false,
                    detail: Some(format!("TLS handshake: {e}")),
                });
                None
            }
            Err(_) => {
                tracing::info!("TLS handshake with {peer} took over {limit:?}; closed");
                None
            }
        }
    }

    /// Tells a connection over a limit which one, then closes it.
    async fn refuse(&self, tcp: TcpStream, peer: SocketAddr, r: Refusal) {
        self.limits.note_refused(r);
        let Some(_slot) = self.limits.try_refusing() else {
            return; // many refusals in flight already: just close
        };
        let limit = self.limits.limit(r);
        let text = match r {
            Refusal::PerIp => format!(
                "too many connections from {}: the limit is {limit} per address; \
                 the hub's operator can raise it with {}\n",
                peer.ip(),
                r.flag()
            ),
            _ => format!(
                "the hub is at its limit of {limit} open connections; \
                 the hub's operator can raise it with {}\n",
                r.flag()
            ),
        };
        let res = plain(r.status(), text);
        let _ = tokio::time::timeout(REFUSAL_BUDGET, async {
            match &self.tls {
                None => answer_once(TokioIo::new(tcp), res).await,
                Some(cfg) => {
                    let acceptor = tokio_rustls::TlsAcceptor::from(cfg.current());
                    if let Ok(s) = acceptor.accept(tcp).await {
                        answer_once(TokioIo::new(s), res).await;
                    }
                }
            }
        })
        .await;
    }

    /// HTTP/1.1 (with upgrades) until the connection ends or the hub shuts down.
    async fn serve_http<I>(self: Arc<Self>, io: I, meta: ConnMeta)
    where
        I: AsyncRead + AsyncWrite + Unpin + Send + 'static,
    {
        let door = self.clone();
        let svc = hyper::service::service_fn(move |req: hyper::Request<Incoming>| {
            let (door, meta) = (door.clone(), meta.clone());
            async move { Ok::<_, Infallible>(door.request(req, meta).await) }
        });
        let conn = hyper::server::conn::http1::Builder::new()
            .timer(TokioTimer::new())
            .header_read_timeout(self.limits.cfg.header_timeout)
            .serve_connection(TokioIo::new(io), svc)
            .with_upgrades();
        tokio::select! {
            r = conn => {
                if let Err(e) = r {
                    tracing::debug!("HTTP connection ended: {e}");
                }
            }
            _ = self.shutdown.cancelled() => {}
        }
    }

    /// One request: body bounds first, then the router; a body cut off by a bound is
    /// answered 413 or 408 whatever the handler said.
    async fn request(&self, req: hyper::Request<Incoming>, meta: ConnMeta) -> Response {
        use tower::ServiceExt;
        let cfg = &self.limits.cfg;
        let declared = req
            .headers()
            .get(header::CONTENT_LENGTH)
            .and_then(|v| v.to_str().ok())
            .and_then(|v| v.parse::<u64>().ok());
        if declared.is_some_and(|n| n > cfg.max_body) {
            self.limits.note_body(true);
            return body_refused(true, cfg.max_body, cfg.body_timeout);
        }
        let verdict = Arc::new(BodyVerdict::default());
        let mut req = if hyper::body::Body::is_end_stream(req.body()) {
            req.map(Body::new)
        } else {
            let (max, after) = (cfg.max_body, cfg.body_timeout);
            req.map(|b| Body::new(GuardedBody::new(b, max, after, verdict.clone())))
        };
        req.extensions_mut().insert(ConnectInfo(meta.peer));
        req.extensions_mut().insert(meta);
        let res = match self.app.clone().oneshot(req).await {
            Ok(r) => r,
            Err(never) => match never {},
        };
        match verdict.too_large() {
            None => res,
            Some(large) => {
                self.limits.note_body(large);
                body_refused(large, cfg.max_body, cfg.body_timeout)
            }
        }
    }
}

/// 413 or 408 with `Connection: close`: the rest of the body is never read.
fn body_refused(too_large: bool, max: u64, after: Duration) -> Response {
    let mut res = if too_large {
        plain(
            StatusCode::PAYLOAD_TOO_LARGE,
            format!(
                "request body over the hub's {max}-byte limit; \
                 the hub's operator can raise it with --max-body-bytes\n"
            ),
        )
    } else {
        plain(
            StatusCode::REQUEST_TIMEOUT,
            format!(
                "request body not received within {}s; \
                 the hub's operator can raise it with --body-timeout-secs\n",
                after.as_secs_f64()
            ),
        )
    };
    res.headers_mut()
        .insert(header::CONNECTION, HeaderValue::from_static("close"));
    res
}

fn plain(status: StatusCode, text: String) -> Response {
    (
        status,
        [(header::CONTENT_TYPE, "text/plain; charset=utf-8")],
        text,
    )
        .into_response()
}

/// Reads one request head and answers `res` to it, then closes.
async fn answer_once<I>(io: TokioIo<I>, res: Response)
where
    I: AsyncRead + AsyncWrite + Unpin + Send + 'static,
{
    let res = std::sync::Mutex::new(Some(res));
    let svc = hyper::service::service_fn(move |_req: hyper::Request<Incoming>| {
        let r = res
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .take()
            .unwrap_or_else(|| StatusCode::SERVICE_UNAVAILABLE.into_response());
        async move { Ok::<_, Infallible>(r) }
    });
    let _ = hyper::server::conn::http1::Builder::new()
        .timer(TokioTimer::new())
        .header_read_timeout(REFUSAL_BUDGET)
        .keep_alive(false)
        .serve_connection(io, svc)
        .await;
}
