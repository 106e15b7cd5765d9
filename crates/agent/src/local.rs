//! The agent's local rosbridge listener (default `127.0.0.1:9090`): local programs
//! (roslibpy, roslibjs, anything that speaks rosbridge v2) publish to and subscribe from
//! the fleet through it, exactly as they would talk to a rosbridge server.

use std::net::SocketAddr;
use std::sync::Arc;

use fleetlink_relay::Router;
use fleetlink_relay::rosbridge::{self, SessionConfig};
use tokio::net::TcpListener;
use tokio_tungstenite::tungstenite::protocol::WebSocketConfig;
use tokio_util::sync::CancellationToken;

/// Accepts local rosbridge clients until `shutdown`.
pub async fn serve(
    listener: TcpListener,
    router: Arc<Router>,
    cfg: Arc<SessionConfig>,
    shutdown: CancellationToken,
) {
    let ws_config = WebSocketConfig::default()
        .max_message_size(Some(cfg.max_message_size))
        .max_frame_size(Some(cfg.max_message_size));
    loop {
        let (tcp, addr) = tokio::select! {
            r = listener.accept() => match r {
                Ok(x) => x,
                Err(e) => {
                    tracing::warn!("local listener: accept failed: {e}");
                    continue;
                }
            },
            _ = shutdown.cancelled() => return,
        };
        let _ = tcp.set_nodelay(true);
        let (router, cfg, shutdown) = (router.clone(), cfg.clone(), shutdown.clone());
        tokio::spawn(async move {
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
