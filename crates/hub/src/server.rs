//! The hub's listener: one port for WebSocket agents, rosbridge clients and HTTP.
//!
//! A request that asks for a WebSocket upgrade becomes an agent session when it offers
//! the `fleetlink.v1` subprotocol and a rosbridge session otherwise (rosbridge clients
//! send no subprotocol); everything else is plain HTTP routed by axum. Each connection is
//! its own task; shutdown cancels a token every session watches.

use std::future::Future;
use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use axum::Router as HttpRouter;
use axum::body::Body;
use axum::extract::{ConnectInfo, Request, State};
use axum::http::{HeaderMap, HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use fleetlink_proto::SUBPROTOCOL;
use fleetlink_relay::Router;
use fleetlink_relay::rosbridge::{self, SessionConfig};
use fleetlink_relay::transcode::Transcoder;
use hyper_util::rt::TokioIo;
use tokio::net::TcpListener;
use tokio_tungstenite::WebSocketStream;
use tokio_tungstenite::tungstenite::handshake::derive_accept_key;
use tokio_tungstenite::tungstenite::protocol::{Role, WebSocketConfig};
use tokio_util::sync::CancellationToken;

use crate::agents::{AgentContext, Registry};
use crate::store::{Store, StoreError};

/// Hub settings (`fleetlink hub` flags).
#[derive(Debug, Clone)]
pub struct HubConfig {
    pub listen: SocketAddr,
    pub data_dir: PathBuf,
    /// Heartbeat for agents that do not ask for one.
    pub heartbeat: Duration,
    /// Largest WebSocket message accepted from any client.
    pub max_message_size: usize,
    /// Queue length of subscriptions that do not set `queue_length`.
    pub default_queue: usize,
}

impl Default for HubConfig {
    fn default() -> Self {
        HubConfig {
            listen: SocketAddr::from(([127, 0, 0, 1], 8080)),
            data_dir: PathBuf::from("fleetlink-data"),
            heartbeat: Duration::from_secs(1),
            max_message_size: 16 << 20,
            default_queue: 100,
        }
    }
}

#[derive(Debug, thiserror::Error)]
pub enum HubError {
    #[error("cannot listen on {addr}: {source}")]
    Bind {
        addr: SocketAddr,
        source: std::io::Error,
    },
    #[error(transparent)]
    Store(#[from] StoreError),
    #[error("server failed: {0}")]
    Serve(std::io::Error),
}

/// Everything the HTTP handlers and sessions share.
pub struct HubState {
    pub router: Arc<Router>,
    pub registry: Arc<Registry>,
    pub store: Store,
    pub agents: Arc<AgentContext>,
    pub rosbridge: Arc<SessionConfig>,
    pub ws_config: WebSocketConfig,
    pub shutdown: CancellationToken,
    pub started: std::time::SystemTime,
}

/// A bound hub, ready to run.
pub struct Hub {
    listener: TcpListener,
    state: Arc<HubState>,
}

impl Hub {
    /// Binds the port and opens the data directory; the hub serves once [`Hub::run`] runs.
    pub async fn bind(cfg: HubConfig, transcoder: Arc<dyn Transcoder>) -> Result<Hub, HubError> {
        let listener = TcpListener::bind(cfg.listen)
            .await
            .map_err(|source| HubError::Bind {
                addr: cfg.listen,
                source,
            })?;
        let store = Store::open(&cfg.data_dir)?;
        let mut router = Router::new(transcoder);
        router.default_queue = cfg.default_queue;
        let router = Arc::new(router);
        let registry = Arc::new(Registry::default());
        let shutdown = CancellationToken::new();
        let agents = Arc::new(AgentContext {
            router: router.clone(),
            registry: registry.clone(),
            store: store.clone(),
            shutdown: shutdown.clone(),
            default_heartbeat_ms: cfg.heartbeat.as_millis() as u32,
        });
        let rosbridge = Arc::new(SessionConfig {
            node_name: "/fleetlink_hub".into(),
            max_message_size: cfg.max_message_size,
            ..SessionConfig::default()
        });
        let ws_config = WebSocketConfig::default()
            .max_message_size(Some(cfg.max_message_size))
            .max_frame_size(Some(cfg.max_message_size));
        let state = Arc::new(HubState {
            router,
            registry,
            store,
            agents,
            rosbridge,
            ws_config,
            shutdown,
            started: std::time::SystemTime::now(),
        });
        Ok(Hub { listener, state })
    }

    pub fn local_addr(&self) -> SocketAddr {
        self.listener
            .local_addr()
            .expect("a bound listener has an address")
    }

    pub fn state(&self) -> Arc<HubState> {
        self.state.clone()
    }

    /// Serves until `shutdown` completes, then closes every session.
    pub async fn run(
        self,
        shutdown: impl Future<Output = ()> + Send + 'static,
    ) -> Result<(), HubError> {
        let state = self.state.clone();
        let token = state.shutdown.clone();
        let app = HttpRouter::new()
            .route("/healthz", get(|| async { "ok\n" }))
            .route("/metrics", get(crate::metrics::handler))
            .merge(crate::api::routes())
            .route("/", get(root))
            .fallback(root)
            .with_state(state.clone());
        let listener = axum::serve::ListenerExt::tap_io(self.listener, |tcp| {
            let _ = tcp.set_nodelay(true);
        });
        let stop = token.clone();
        let serve = axum::serve(
            listener,
            app.into_make_service_with_connect_info::<SocketAddr>(),
        )
        .with_graceful_shutdown(async move {
            shutdown.await;
            stop.cancel();
        });
        let r = serve.await.map_err(HubError::Serve);
        token.cancel();
        r
    }
}

/// `/`: the status page, or a WebSocket session when the request is an upgrade.
async fn root(
    State(st): State<Arc<HubState>>,
    ConnectInfo(addr): ConnectInfo<SocketAddr>,
    req: Request,
) -> Response {
    if is_upgrade(req.headers()) {
        return upgrade(st, addr, req);
    }
    if req.uri().path() == "/" {
        return crate::api::page().into_response();
    }
    (
        StatusCode::NOT_FOUND,
        format!("no such page: {}\n", req.uri().path()),
    )
        .into_response()
}

fn is_upgrade(h: &HeaderMap) -> bool {
    let has = |name: header::HeaderName, want: &str| {
        h.get_all(name)
            .iter()
            .filter_map(|v| v.to_str().ok())
            .any(|v| v.split(',').any(|p| p.trim().eq_ignore_ascii_case(want)))
    };
    has(header::CONNECTION, "upgrade") && has(header::UPGRADE, "websocket")
}

fn upgrade(st: Arc<HubState>, addr: SocketAddr, mut req: Request) -> Response {
    let Some(key) = req.headers().get(header::SEC_WEBSOCKET_KEY).cloned() else {
        return (StatusCode::BAD_REQUEST, "missing Sec-WebSocket-Key\n").into_response();
    };
    let agent = req
        .headers()
        .get_all(header::SEC_WEBSOCKET_PROTOCOL)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .any(|v| v.split(',').any(|p| p.trim() == SUBPROTOCOL));
    let on_upgrade = hyper::upgrade::on(&mut req);
    let ws_config = st.ws_config;
    tokio::spawn(async move {
        let upgraded = match on_upgrade.await {
            Ok(u) => u,
            Err(e) => {
                tracing::debug!("upgrade from {addr} failed: {e}");
                return;
            }
        };
        let ws =
            WebSocketStream::from_raw_socket(TokioIo::new(upgraded), Role::Server, Some(ws_config))
                .await;
        if agent {
            crate::agents::serve_agent(ws, st.agents.clone(), Some(addr)).await;
        } else {
            rosbridge::serve(
                ws,
                st.router.clone(),
                Some(addr),
                st.rosbridge.clone(),
                st.shutdown.clone(),
            )
            .await;
        }
    });
    let mut res = Response::new(Body::empty());
    *res.status_mut() = StatusCode::SWITCHING_PROTOCOLS;
    let h = res.headers_mut();
    h.insert(header::CONNECTION, HeaderValue::from_static("upgrade"));
    h.insert(header::UPGRADE, HeaderValue::from_static("websocket"));
    if let Ok(v) = HeaderValue::from_str(&derive_accept_key(key.as_bytes())) {
        h.insert(header::SEC_WEBSOCKET_ACCEPT, v);
    }
    if agent {
        h.insert(
            header::SEC_WEBSOCKET_PROTOCOL,
            HeaderValue::from_static(SUBPROTOCOL),
        );
    }
    res
}
