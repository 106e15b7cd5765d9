//! The agent's local rosbridge listener (default `127.0.0.1:9090`): local programs
//! (roslibpy, roslibjs, anything that speaks rosbridge v2) publish to and subscribe from
//! the fleet through it, exactly as they would talk to a rosbridge server.

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_relay::Router;
use fleetlink_relay::rosbridge::{self, SessionConfig};
use tokio::net::TcpListener;
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
        sessions.spawn(async move {
            // tungstenite answers the handshake; the session then runs on the socket's
            // own halves (a client sends nothing more before the handshake's answer).
            match tokio_tungstenite::accept_async_with_config(tcp, Some(ws_config)).await {
                Ok(ws) => {
                    let auth = fleetlink_relay::gate::SessionAuth::open();
                    let max = cfg.max_message_size;
                    let (sink, stream) = fleetlink_relay::websocket::server(ws.into_inner(), max);
                    rosbridge::serve(sink, stream, router, Some(addr), cfg, shutdown, auth).await
                }
                Err(e) => tracing::debug!("local client {addr}: WebSocket handshake failed: {e}"),
            }
        });
    }
}

/// Binds the local listener address.
pub async fn bind(addr: SocketAddr) -> std::io::Result<TcpListener> {
    TcpListener::bind(addr).await
}
