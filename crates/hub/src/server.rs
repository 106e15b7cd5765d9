//! The hub's listener: one port for WebSocket agents, rosbridge clients and HTTP.
//!
//! A request that asks for a WebSocket upgrade becomes an agent session when it offers
//! the `fleetlink.v1` subprotocol, a Foxglove session when it offers `foxglove.sdk.v1`
//! or `foxglove.websocket.v1` ([`fleetlink_foxglove`]), and a rosbridge session otherwise
//! (rosbridge clients send no subprotocol); everything else is plain HTTP routed by axum
//! ([`crate::http`]).
//! Each connection is its own task; shutdown cancels a token every session watches.
//!
//! The top of the crate's layering: [`Hub::bind`] builds the shared
//! [`HubState`](crate::state::HubState) and [`Hub::run`] wires the parts together; no
//! other module imports this one.

use std::future::Future;
use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use axum::body::Body;
use axum::extract::{ConnectInfo, Request, State};
use axum::http::{HeaderMap, HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use fleetlink_proto::SUBPROTOCOL;
use fleetlink_relay::Router;
use fleetlink_relay::transcode::Transcoder;
use fleetlink_relay::websocket::deflate::{self, DeflateConfig};
use fleetlink_relay::websocket::liveness::{LivenessConfig, Peer};
use fleetlink_rosbridge::SessionConfig;
use tokio::net::TcpListener;
use tokio_tungstenite::tungstenite::handshake::derive_accept_key;
use tokio_util::sync::CancellationToken;

use crate::agents::AgentContext;
use crate::connection::ConnMeta;
use crate::registry::Registry;
use crate::state::{HubState, SiteConfig};
use crate::store::{Store, StoreError};

/// How long a stopping hub waits for its sessions to close.
pub const SHUTDOWN_GRACE: Duration = Duration::from_secs(5);

/// Hub settings (`fleetlink hub` flags).
#[derive(Debug, Clone)]
pub struct HubConfig {
    pub listen: SocketAddr,
    pub data_dir: PathBuf,
    /// Keep the durable state (credentials, rules, audit log, robots, delivery marks,
    /// parameters) in this PostgreSQL database, shared with other hubs, instead of
    /// SQLite in `data_dir`.
    pub database: Option<String>,
    /// Heartbeat for agents that do not ask for one.
    pub heartbeat: Duration,
    /// Largest WebSocket message accepted from any client.
    pub max_message_size: usize,
    /// Queue length of subscriptions that do not set `queue_length`.
    pub default_queue: usize,
    /// And the payload bytes such a queue holds at most.
    pub default_queue_bytes: usize,
    /// Who may connect: anonymous access, trusted proxies, robot networks, OIDC.
    pub auth: fleetlink_auth::AuthPolicy,
    /// Built-in grants (admin group, robots in their namespace, anonymous read).
    pub acl: fleetlink_auth::AclDefaults,
    /// Serve `wss://`/`https://` with these files (reloaded when they change).
    pub tls: Option<fleetlink_auth::tls::ServerTlsFiles>,
    /// Sites whose robots share one access link; the hub divides its capacity.
    pub sites: Vec<SiteConfig>,
    /// Where the OIDC signing keys come from (with `auth.jwt` set).
    pub jwks: Option<crate::jwks::JwksSource>,
    /// Timeouts and connection limits at the front door.
    pub door: crate::limits::FrontDoor,
    /// Service and action calls: default deadline, pending-call bounds.
    pub calls: fleetlink_relay::calls::CallLimits,
    /// Where MCAP recordings go; `None`: `recordings` in `data_dir`.
    pub recordings_dir: Option<PathBuf>,
    /// How often rosbridge and Foxglove clients are pinged, and how long one may show no
    /// progress before it is closed and what it held released.
    pub viewer_liveness: LivenessConfig,
    /// permessage-deflate for rosbridge and Foxglove clients that offer it; `None`: never.
    pub viewer_deflate: Option<DeflateConfig>,
}

impl Default for HubConfig {
    fn default() -> Self {
        HubConfig {
            listen: SocketAddr::from(([127, 0, 0, 1], 8080)),
            data_dir: PathBuf::from("fleetlink-data"),
            database: None,
            heartbeat: Duration::from_secs(1),
            max_message_size: 16 << 20,
            default_queue: 1000,
            default_queue_bytes: 2 << 20,
            auth: fleetlink_auth::AuthPolicy::default(),
            acl: fleetlink_auth::AclDefaults::default(),
            tls: None,
            sites: Vec::new(),
            jwks: None,
            door: crate::limits::FrontDoor::default(),
            calls: fleetlink_relay::calls::CallLimits::default(),
            recordings_dir: None,
            viewer_liveness: LivenessConfig::default(),
            viewer_deflate: Some(DeflateConfig::default()),
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
    #[error("security store: {0}")]
    Security(#[from] fleetlink_auth::SecurityError),
    #[error("security store: {0}")]
    SecurityStore(#[from] fleetlink_auth::StoreError),
    #[error("TLS: {0}")]
    Tls(#[from] fleetlink_auth::tls::TlsError),
    #[error("recordings directory {dir}: {source}")]
    Recordings {
        dir: PathBuf,
        source: std::io::Error,
    },
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
        let (store, security, params) = open_state(&cfg).await?;
        let tls = match &cfg.tls {
            Some(files) => Some(Arc::new(fleetlink_auth::tls::ReloadingServerConfig::load(
                files.clone(),
            )?)),
            None => None,
        };
        let mut router = Router::with_call_limits(transcoder, cfg.calls.clone());
        router.default_queue = cfg.default_queue;
        router.default_queue_bytes = cfg.default_queue_bytes;
        router.params = Arc::new(params);
        let router = Arc::new(router);
        let registry = Arc::new(Registry::default());
        let shutdown = CancellationToken::new();
        let agents = Arc::new(AgentContext {
            router: router.clone(),
            registry: registry.clone(),
            store: store.clone(),
            shutdown: shutdown.clone(),
            security: security.clone(),
            default_heartbeat_ms: cfg.heartbeat.as_millis() as u32,
            ledger: Arc::new(crate::delivery::DeliveryLedger::new(store.clone())),
            rosout: crate::rosout::RosOut::start(router.clone()),
            hub_id: this_run(),
        });
        let rosbridge = Arc::new(SessionConfig {
            node_name: "/fleetlink_hub".into(),
            max_message_size: cfg.max_message_size,
            liveness: cfg.viewer_liveness,
            deflate: cfg.viewer_deflate,
            ..SessionConfig::default()
        });
        let recordings_dir = cfg
            .recordings_dir
            .clone()
            .unwrap_or_else(|| cfg.data_dir.join("recordings"));
        let recordings = {
            let (dir, router) = (recordings_dir.clone(), router.clone());
            tokio::task::spawn_blocking(move || {
                fleetlink_record::Recordings::open(&dir, router, "fleetlink hub")
            })
            .await
            .map_err(|e| HubError::Serve(std::io::Error::other(e)))?
            .map_err(|source| HubError::Recordings {
                dir: recordings_dir,
                source,
            })?
        };
        let state = Arc::new(HubState {
            recordings: Arc::new(recordings),
            router,
            registry,
            store,
            agents,
            rosbridge,
            foxglove: Arc::new(fleetlink_foxglove::SessionConfig {
                name: "fleetlink hub".into(),
                liveness: cfg.viewer_liveness,
                deflate: cfg.viewer_deflate,
                ..fleetlink_foxglove::SessionConfig::default()
            }),
            shutdown,
            tasks: tokio_util::task::TaskTracker::new(),
            security,
            tls,
            sites: cfg.sites.clone(),
            jwks: cfg.jwks.clone(),
            started: std::time::SystemTime::now(),
            limits: Arc::new(crate::limits::Limits::new(cfg.door.clone())),
            federation: std::sync::OnceLock::new(),
        });
        Ok(Hub { listener, state })
    }

    /// The hub's router, for a participant that runs beside it (the federation).
    pub fn router(&self) -> &Arc<Router> {
        &self.state.router
    }

    /// The robots online on this hub.
    pub fn registry(&self) -> &Arc<Registry> {
        &self.state.registry
    }

    /// Cancelled when the hub stops.
    pub fn shutdown_token(&self) -> CancellationToken {
        self.state.shutdown.clone()
    }

    /// Joins the hub to a federation: its API lists the other hubs' robots and the
    /// federation's state. Once; a second call is ignored.
    pub fn federate(&self, federation: Arc<dyn crate::federated::Federated>) {
        let _ = self.state.federation.set(federation);
    }

    pub fn local_addr(&self) -> SocketAddr {
        self.listener
            .local_addr()
            .expect("a bound listener has an address")
    }

    pub fn state(&self) -> Arc<HubState> {
        self.state.clone()
    }

    /// Serves until `shutdown` completes, then closes every session and waits for them
    /// (at most [`SHUTDOWN_GRACE`]) and for the database writers.
    pub async fn run(
        self,
        shutdown: impl Future<Output = ()> + Send + 'static,
    ) -> Result<(), HubError> {
        let state = self.state.clone();
        let token = state.shutdown.clone();
        // Call deadlines: one timer task for the hub's call table.
        tokio::spawn(state.router.calls.clone().run_deadlines(token.clone()));
        tokio::spawn(
            state
                .agents
                .rosout
                .clone()
                .run(state.registry.clone(), token.clone()),
        );
        // Robots' kept configuration changes, applied again as they connect.
        tokio::spawn(crate::http::robot_config::keep_applied(
            state.clone(),
            token.clone(),
        ));
        let app = crate::http::routes(state.clone())
            .route("/", get(root))
            .fallback(root)
            .with_state(state.clone());
        if let Some(src) = &state.jwks {
            crate::jwks::refresh_if_due(&state.security, src).await;
        }
        let door = Arc::new(crate::connection::Door {
            app,
            limits: state.limits.clone(),
            tls: state.tls.clone(),
            security: state.security.clone(),
            shutdown: token.clone(),
        });
        let housekeeping = tokio::spawn(housekeeping(state.clone()));
        let capacity = tokio::spawn(crate::capacity::share_sites(state.clone()));
        tokio::pin!(shutdown);
        loop {
            let (tcp, peer) = tokio::select! {
                r = self.listener.accept() => match r {
                    Ok(x) => x,
                    Err(e) => {
                        // Out of file descriptors and the like: keep serving the others.
                        tracing::warn!("accept failed: {e}");
                        tokio::time::sleep(Duration::from_millis(50)).await;
                        continue;
                    }
                },
                _ = &mut shutdown => break,
            };
            let _ = tcp.set_nodelay(true);
            let admitted = door.limits.admit(peer.ip());
            state.tasks.spawn(door.clone().serve(tcp, peer, admitted));
        }
        // Stop: no new connections (the listener goes), every session told to close (agents
        // and rosbridge clients get close 1001), and the hub waits for them to finish what
        // they were doing — a robot's delivery marks written, its calls failed with the
        // reason — within the grace time.
        drop(self.listener);
        token.cancel();
        // Recordings end with finished files (summary and indexes), not cut off.
        state.recordings.stop_all().await;
        housekeeping.abort();
        capacity.abort();
        state.tasks.close();
        if tokio::time::timeout(SHUTDOWN_GRACE, state.tasks.wait())
            .await
            .is_err()
        {
            tracing::warn!(
                "{} connections did not close within {SHUTDOWN_GRACE:?}; stopping anyway",
                state.tasks.len()
            );
        }
        // What was answered before the stop is on disk when `run` returns: parameters
        // and the audit log are written by their own threads.
        let (params, audit) = (state.router.params.clone(), state.security.clone());
        let _ = tokio::task::spawn_blocking(move || {
            params.flush();
            audit.audit.flush();
        })
        .await;
        Ok(())
    }
}

/// Opens the durable state: SQLite in the data directory, or the PostgreSQL database
/// shared with other hubs. On a blocking thread, since opening reads (and may migrate)
/// the database.
async fn open_state(
    cfg: &HubConfig,
) -> Result<
    (
        Store,
        Arc<fleetlink_auth::Security>,
        crate::params::DurableParams,
    ),
    HubError,
> {
    let (dir, url) = (cfg.data_dir.clone(), cfg.database.clone());
    let (auth, acl) = (cfg.auth.clone(), cfg.acl.clone());
    tokio::task::spawn_blocking(move || {
        let (store, auth_store) = match url {
            None => (
                Store::open(&dir)?,
                fleetlink_auth::Store::open(&dir.join("hub.sqlite3"))?,
            ),
            Some(url) => {
                let db = fleetlink_postgres::Database::connect(&url).map_err(StoreError::from)?;
                tracing::info!("shared state in PostgreSQL at {}", db.url());
                (
                    Store::postgres(db.clone())?,
                    fleetlink_auth::Store::postgres(db)?,
                )
            }
        };
        let security = Arc::new(fleetlink_auth::Security::new(auth_store, auth, acl)?);
        let params = crate::params::DurableParams::open(store.clone())?;
        Ok((store, security, params))
    })
    .await
    .map_err(|e| HubError::Serve(std::io::Error::other(e)))?
}

/// Periodic work: pick up rule edits made by `fleetlink admin` on the same database,
/// reload changed TLS files, prune an old audit log.
async fn housekeeping(st: Arc<HubState>) {
    let mut tick = tokio::time::interval(Duration::from_secs(1));
    let mut n: u64 = 0;
    loop {
        tick.tick().await;
        n += 1;
        if let Some(src) = &st.jwks {
            crate::jwks::refresh_if_due(&st.security, src).await;
        }
        let sec = st.security.clone();
        let tls = st.tls.clone();
        let _ = tokio::task::spawn_blocking(move || {
            if let Err(e) = sec.reload_rules_if_changed() {
                tracing::warn!("cannot reload access rules: {e}");
            }
            if n.is_multiple_of(5)
                && let Some(t) = tls
                && let Err(e) = t.reload_if_changed()
            {
                tracing::warn!("cannot reload TLS files (keeping the old ones): {e}");
            }
        })
        .await;
    }
}

/// `/`: a WebSocket session when the request is an upgrade, else the dashboard's files.
async fn root(
    State(st): State<Arc<HubState>>,
    ConnectInfo(addr): ConnectInfo<SocketAddr>,
    req: Request,
) -> Response {
    if is_upgrade(req.headers()) {
        return upgrade(st, addr, req).await;
    }
    if let Some(page) = crate::http::dashboard::serve(req.uri().path(), req.headers()) {
        return page;
    }
    (
        StatusCode::NOT_FOUND,
        format!("no such page: {}\n", req.uri().path()),
    )
        .into_response()
}

/// 503 with a jittered `Retry-After`: too many handshakes in progress.
fn busy(st: &HubState, r: crate::limits::Refusal) -> Response {
    st.limits.note_refused(r);
    let secs = st.limits.retry_after_secs();
    let text = format!(
        "the hub is busy with {} connections still handshaking; retry in {secs}s \
         (the hub's operator can raise the limit with {})\n",
        st.limits.limit(r),
        r.flag()
    );
    let mut res = (r.status(), text).into_response();
    res.headers_mut()
        .insert(header::RETRY_AFTER, HeaderValue::from(secs));
    res
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

async fn upgrade(st: Arc<HubState>, addr: SocketAddr, mut req: Request) -> Response {
    let Some(key) = req.headers().get(header::SEC_WEBSOCKET_KEY).cloned() else {
        return (StatusCode::BAD_REQUEST, "missing Sec-WebSocket-Key\n").into_response();
    };
    // The slot is held through authentication and, for agents, until HELLO is answered:
    // that is the work a reconnecting fleet piles onto a restarted hub.
    let slot = match st.limits.try_handshake() {
        Ok(s) => s,
        Err(r) => return busy(&st, r),
    };
    let open = req.extensions().get::<ConnMeta>().map(|m| m.open.clone());
    let local = req.extensions().get::<ConnMeta>().and_then(|m| m.local);
    // The offered subprotocols, read before any await: a borrow of the request (whose
    // body is not `Sync`) must not live across one.
    let (agent, foxglove) = offered_subprotocol(req.headers());
    let deflate = negotiate_deflate(&st, req.headers(), agent, foxglove);
    // Authenticate before switching protocols: a bad credential gets a plain 401 the
    // client can show; no credential means the client authenticates in-band (agents in
    // HELLO, rosbridge clients with an `auth` operation) or reads anonymously where that
    // is allowed.
    let tls_name = req
        .extensions()
        .get::<ConnMeta>()
        .and_then(|m| m.tls_name.clone());
    let conn = crate::security::conn_info(addr, req.headers(), tls_name);
    let credential = crate::security::request_credential(req.headers(), req.uri().query());
    let presented = !matches!(credential, fleetlink_auth::Credential::None);
    let identity = if agent && !presented {
        None
    } else {
        match crate::security::authenticate(&st.security, credential, conn.clone()).await {
            Ok(id) => Some(id),
            Err(e) if presented => {
                return (
                    StatusCode::UNAUTHORIZED,
                    format!("{}\n", e.public_message()),
                )
                    .into_response();
            }
            Err(_) => None,
        }
    };
    let on_upgrade = hyper::upgrade::on(&mut req);
    let deflate_cfg = deflate.as_ref().map(|(cfg, _)| *cfg);
    st.tasks.clone().spawn(async move {
        let upgraded = match on_upgrade.await {
            Ok(u) => u,
            Err(e) => {
                tracing::debug!("upgrade from {addr} failed: {e}");
                return;
            }
        };
        if let Some(o) = &open {
            o.upgraded();
        }
        // Held until the session ends: the connection counts against the limits.
        let _open = open;
        let max = st.rosbridge.max_message_size;
        let (r, w, read) = crate::upgraded::split(upgraded);
        let (mut sink, mut stream) = fleetlink_relay::websocket::server_halves(r, w, read, max);
        if let Some(cfg) = deflate_cfg {
            (sink, stream) = (sink.deflating(cfg), stream.inflating());
        }
        // Each kind of session boxed on its own: the task holds the one it runs, not
        // room for the largest of the three (10,000 idle robots' links each paid for a
        // viewer's session).
        if agent {
            Box::pin(crate::agents::serve_agent(
                stream,
                sink,
                st.agents.clone(),
                Some(addr),
                conn,
                slot,
            ))
            .await;
        } else {
            drop(slot);
            // A viewer's liveness counts its connection draining, not only what it sends.
            let peer = Peer {
                addr: Some(addr),
                progress: local.map(|local| {
                    fleetlink_relay::websocket::tcp_progress::probe(local, addr, sink.written())
                }),
            };
            let gate = identity.map(|id| {
                Box::new(crate::security::HubGate::new(
                    st.security.clone(),
                    st.registry.clone(),
                    id,
                )) as Box<dyn fleetlink_relay::gate::Gate>
            });
            let guard = crate::security::HubGuard {
                security: st.security.clone(),
                registry: st.registry.clone(),
                conn,
            };
            let auth = fleetlink_relay::gate::SessionAuth {
                gate,
                guard: Some(Arc::new(guard)),
            };
            if foxglove.is_some() {
                // The same gate as a rosbridge client's: rules and audit apply alike.
                return Box::pin(fleetlink_foxglove::serve(
                    sink,
                    stream,
                    st.router.clone(),
                    peer,
                    st.foxglove.clone(),
                    st.shutdown.clone(),
                    auth,
                ))
                .await;
            }
            Box::pin(fleetlink_rosbridge::serve(
                sink,
                stream,
                st.router.clone(),
                peer,
                st.rosbridge.clone(),
                st.shutdown.clone(),
                auth,
            ))
            .await;
        }
    });
    switching_protocols(&key, agent, foxglove, deflate)
}

/// The subprotocol the client asks for: whether it is the agent link's, and otherwise
/// the client's first Foxglove subprotocol, echoed in the answer (neither: rosbridge).
fn offered_subprotocol(headers: &HeaderMap) -> (bool, Option<&'static str>) {
    let offered = || {
        headers
            .get_all(header::SEC_WEBSOCKET_PROTOCOL)
            .iter()
            .filter_map(|v| v.to_str().ok())
            .flat_map(|v| v.split(','))
            .map(str::trim)
    };
    let agent = offered().any(|p| p == SUBPROTOCOL);
    let foxglove = if agent {
        None
    } else {
        fleetlink_foxglove::choose_subprotocol(offered())
    };
    (agent, foxglove)
}

/// Compression for a viewer that offers it and a hub that allows it (never on a robot's
/// link, which compresses its own way): the settings, and the extension to answer.
fn negotiate_deflate(
    st: &HubState,
    headers: &HeaderMap,
    agent: bool,
    foxglove: Option<&'static str>,
) -> Option<(DeflateConfig, String)> {
    if agent {
        None
    } else if foxglove.is_some() {
        st.foxglove.deflate
    } else {
        st.rosbridge.deflate
    }
    .and_then(|cfg| {
        let offers = headers
            .get_all(header::SEC_WEBSOCKET_EXTENSIONS)
            .iter()
            .filter_map(|v| v.to_str().ok());
        deflate::negotiate(offers).map(|agreed| (cfg, agreed.response()))
    })
}

/// The `101 Switching Protocols` answer: the accept key, the chosen subprotocol and the
/// agreed compression.
fn switching_protocols(
    key: &HeaderValue,
    agent: bool,
    foxglove: Option<&'static str>,
    deflate: Option<(DeflateConfig, String)>,
) -> Response {
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
    } else if let Some(p) = foxglove {
        h.insert(header::SEC_WEBSOCKET_PROTOCOL, HeaderValue::from_static(p));
    }
    if let Some((_, answer)) = deflate
        && let Ok(v) = HeaderValue::from_str(&answer)
    {
        h.insert(header::SEC_WEBSOCKET_EXTENSIONS, v);
    }
    res
}

/// This run's id among hubs (`VIA`): random, so two hubs never share one, and new for each
/// run (a message in flight across a restart counts the hub's earlier run as another).
fn this_run() -> u64 {
    use std::hash::BuildHasher;
    let seed = (std::process::id(), std::time::SystemTime::now());
    std::collections::hash_map::RandomState::new().hash_one(seed) | 1
}
