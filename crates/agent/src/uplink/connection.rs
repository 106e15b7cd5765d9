//! One connection to the hub: the socket (TCP, TLS, WebSocket with the `fleetlink.v1`
//! subprotocol), `HELLO` and the hub's `WELCOME`, what the hub must know once per
//! connection (local topics, subscriptions, services), the link's writer task, and the
//! loop that serves the open session until it ends.

use super::*;

/// The WebSocket to the hub.
type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;
/// Its writing half, which the link's writer task owns.
type WsSink = futures_util::stream::SplitSink<Ws, WsMessage>;
/// Its reading half, which the connection's loop reads.
type WsStream = futures_util::stream::SplitStream<Ws>;

/// A connection the hub welcomed.
struct Opened {
    sink: WsSink,
    stream: WsStream,
    session: LinkSession,
    /// The session's id, as the hub named it.
    id: String,
    namespace: String,
    /// The `WELCOME` features.
    features: u64,
}

impl Uplink {
    /// TCP connect with a short timeout, socket options for a low-latency link, then the
    /// WebSocket (and TLS) handshake.
    async fn open_socket(
        &self,
        url: &str,
        req: tokio_tungstenite::tungstenite::handshake::client::Request,
    ) -> Result<
        (
            tokio_tungstenite::WebSocketStream<
                tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>,
            >,
            tokio_tungstenite::tungstenite::handshake::client::Response,
        ),
        Failure,
    > {
        let host = req
            .uri()
            .host()
            .ok_or_else(|| Failure::hub(format!("hub URL {url} has no host")))?
            .trim_start_matches('[')
            .trim_end_matches(']')
            .to_owned();
        let tls = req.uri().scheme_str() == Some("wss");
        let port = req.uri().port_u16().unwrap_or(if tls { 443 } else { 80 });
        let tcp = match tokio::time::timeout(CONNECT_TIMEOUT, connect_staggered(&host, port)).await
        {
            Err(_) => {
                return Err(Failure::Link(format!(
                    "connecting to {url} timed out after {CONNECT_TIMEOUT:?}"
                )));
            }
            Ok(Err(e)) => {
                let reason = format!("cannot connect to {url}: {e}");
                use std::io::ErrorKind as K;
                return Err(match e.kind() {
                    // A reachable host answered: the hub is not there (restarting?).
                    K::ConnectionRefused => Failure::hub(reason),
                    K::NetworkUnreachable | K::NetworkDown => Failure::NoRoute(reason),
                    _ => Failure::Link(reason),
                });
            }
            Ok(Ok(s)) => s,
        };
        let _ = tcp.set_nodelay(true);
        // Keep the kernel's unsent backlog small so a priority message is never queued
        // behind megabytes of bulk data below the scheduler (Linux only).
        #[cfg(any(target_os = "linux", target_os = "android"))]
        if let Err(e) = socket2::SockRef::from(&tcp).set_tcp_notsent_lowat(NOTSENT_LOWAT) {
            tracing::debug!("TCP_NOTSENT_LOWAT not set: {e}");
        }
        let connector = self
            .cfg
            .tls
            .clone()
            .map(tokio_tungstenite::Connector::Rustls);
        tokio_tungstenite::client_async_tls_with_config(
            req,
            tcp,
            Some(uplink_ws_config()),
            connector,
        )
        .await
        .map_err(|e| handshake_failure(url, e))
    }

    /// One connection to the hub at `url`. `Err` if it never came up, `Ok(reason)` when it
    /// ended after `WELCOME`.
    pub(super) async fn connect_and_serve(
        &self,
        url: &str,
        shutdown: &CancellationToken,
    ) -> Result<String, Failure> {
        let Opened {
            sink,
            mut stream,
            mut session,
            id,
            namespace,
            features,
        } = self.handshake(url, shutdown).await?;
        self.stats.connects.fetch_add(1, Relaxed);
        tracing::info!(robot = %self.cfg.robot, %namespace, "connected to hub {url}");
        let (ctrl_tx, writer) = self.start_link(&mut session, sink, &namespace, features);
        self.state.send_replace(LinkState::Connected {
            session: id,
            namespace: namespace.clone(),
            hub: url.to_owned(),
        });
        self.offer_calls(&mut session);
        let reason = self
            .serve(&mut session, &mut stream, &ctrl_tx, &namespace, shutdown)
            .await;
        // Calls the local table queued for the hub meanwhile fail with the reason.
        while let Ok(Some(m)) = self.calls_rx.try_recv() {
            session.handle_peer_event(m);
        }
        drive::stop_writer(writer, ctrl_tx, &reason).await;
        Ok(reason.to_string())
    }

    /// The socket, the subprotocol, `HELLO` and the hub's `WELCOME`.
    async fn handshake(&self, url: &str, shutdown: &CancellationToken) -> Result<Opened, Failure> {
        let mut req = url
            .into_client_request()
            .map_err(|e| Failure::hub(format!("bad hub URL {url}: {e}")))?;
        req.headers_mut().insert(
            "Sec-WebSocket-Protocol",
            HeaderValue::from_static(SUBPROTOCOL),
        );
        let (ws, response) = or_shutdown(
            shutdown,
            tokio::time::timeout(HANDSHAKE_TIMEOUT, self.open_socket(url, req)),
        )
        .await?
        .map_err(|_| {
            Failure::hub(format!(
                "the WebSocket handshake with {url} took longer than {HANDSHAKE_TIMEOUT:?}"
            ))
        })??;
        let agreed = response
            .headers()
            .get("Sec-WebSocket-Protocol")
            .and_then(|v| v.to_str().ok());
        if agreed != Some(SUBPROTOCOL) {
            return Err(Failure::hub(format!(
                "{url} does not speak {SUBPROTOCOL} (is it a fleetlink hub?)"
            )));
        }
        let (mut sink, mut stream) = ws.split();
        let mut session = self.new_session();
        // HELLO, straight to the socket: the writer starts once the hub has answered.
        while let Some(c) = session.poll_transmit() {
            if let Control::Frame(f) = c {
                sink.send(WsMessage::Binary(f.to_bytes()))
                    .await
                    .map_err(|e| Failure::Link(format!("sending HELLO: {e}")))?;
            }
        }
        loop {
            match session.poll_event() {
                Some(Event::Opened {
                    session: id,
                    namespace,
                    features,
                    ..
                }) => {
                    return Ok(Opened {
                        sink,
                        stream,
                        session,
                        id,
                        namespace,
                        features,
                    });
                }
                Some(Event::Closed(r)) => return Err(self.before_welcome(url, r)),
                Some(_) => continue,
                None => {}
            }
            tokio::select! {
                m = stream.next() => {
                    drive::feed(&mut session, m.map(|r| r.map(ClientMessage::from)), Instant::now());
                }
                _ = drive::timer(session.poll_timeout()) => session.handle_timeout(Instant::now()),
                _ = shutdown.cancelled() => {
                    return Err(Failure::hub("the agent is shutting down".to_owned()));
                }
            }
        }
    }

    /// The agent's end of a new session, with its `HELLO` queued.
    fn new_session(&self) -> LinkSession {
        let me = self.client;
        let (names, calls) = (self.cfg.names.clone(), self.router.calls.clone());
        let mut session = LinkSession::agent(
            SessionConfig {
                role: Role::Agent,
                heartbeat: self.cfg.heartbeat,
                handshake_timeout: HANDSHAKE_TIMEOUT,
                report_every: Some(LINK_REPORT_INTERVAL),
                wall: system_wall_clock(),
            },
            AgentHello {
                robot: self.cfg.robot.to_string(),
                token: self.cfg.token.clone(),
                outbox_epoch: self.outbox.outbox_epoch(),
                mirror: self
                    .cfg
                    .mirror
                    .as_ref()
                    .map(|m| m.to_string())
                    .unwrap_or_default(),
            },
            Box::new(move |namespace: &str| {
                let names = AgentNames {
                    names,
                    namespace: namespace.to_owned(),
                };
                LinkCalls::new(calls, me, Box::new(names))
            }),
            Instant::now(),
        );
        if let Some(id) = self.cfg.hub_id {
            session.set_local_hub(id);
        }
        if let Some(g) = &self.cfg.upstream_gate {
            session.set_gate((g.0)());
        }
        session
    }

    /// Everything the hub must know, exactly once on this connection (the local topics,
    /// the subscriptions), and the link's writer started on `sink`.
    fn start_link(
        &self,
        session: &mut LinkSession,
        sink: WsSink,
        namespace: &str,
        features: u64,
    ) -> (ControlSender, tokio::task::JoinHandle<()>) {
        let me = self.client;
        // This connection owns the in-flight state from here on.
        self.outbox.on_link_reset();
        // A hub that says which topics it wants gets only those (and `always` ones); an
        // older one gets everything.
        self.outbox
            .set_demand_driven(features & WELCOME_INTEREST != 0);
        // Compressed messages only to a hub that takes them.
        self.outbox
            .set_compression_allowed(features & WELCOME_COMPRESSION != 0);
        let names = self.cfg.names.clone();
        let ns = namespace.to_owned();
        let namer: LinkNamer =
            Arc::new(move |meta: &TopicMeta| Some(names.to_hub(&meta.name, &ns).to_string()));
        let announce: Vec<(Arc<TopicMeta>, Encoding)> = self
            .router
            .topics()
            .into_iter()
            .filter(|t| t.publishers.iter().any(|p| *p != me))
            .map(|t| {
                (
                    t.meta.clone(),
                    t.topic.last_encoding().unwrap_or(Encoding::Json),
                )
            })
            .collect();
        for (id, pattern, flags) in self.subscriptions(namespace) {
            session.send(Frame::Subscribe {
                id,
                pattern,
                flags,
                throttle_ms: 0,
                queue_length: 0,
            });
        }
        let (ctrl_tx, ctrl_rx) = mpsc::channel::<Box<Control>>(WRITER_QUEUE);
        let via = self.cfg.hub_id.map(|me| ViaOut {
            me,
            peer: session.link_in().peer_hub.clone(),
            always: true,
        });
        // What the hub upstream may receive (checked per message, so a rule change
        // applies at once).
        let writer_gate = self.cfg.upstream_gate.as_ref().map(|g| (g.0)());
        let writer = tokio::spawn(write_link(
            sink,
            self.outbox.clone(),
            ctrl_rx,
            namer,
            announce,
            writer_gate,
            via,
        ));
        (ctrl_tx, writer)
    }

    /// The subscriptions a connection starts with: a robot hears everything sent to its
    /// namespace (commands; a mirror asks for each of its robot's topics while a local
    /// subscriber wants it, [`MirrorSubs`]), the configured `subscribe` topics, and the
    /// fleet's services.
    fn subscriptions(&self, namespace: &str) -> Vec<(u32, String, u8)> {
        let mut subs = Vec::new();
        if self.cfg.mirror.is_none() {
            subs.push((
                1u32,
                format!("{}/.*", regex::escape(namespace)),
                SUBSCRIBE_REGEX,
            ));
        }
        for (i, (hub, _)) in self.cfg.names.subscribe.iter().enumerate() {
            subs.push((i as u32 + 2, hub.to_string(), 0));
        }
        subs.push((
            SERVICES_SUBSCRIPTION,
            ".*".to_owned(),
            SUBSCRIBE_REGEX | SUBSCRIBE_SERVICES,
        ));
        subs
    }

    /// Calls: what the local table queued while the link was down is stale (its calls
    /// were to services that are gone); every local service is offered anew.
    fn offer_calls(&self, session: &mut LinkSession) {
        let me = self.client;
        while let Ok(Some(m)) = self.calls_rx.try_recv() {
            if let PeerMsg::Call(req) = m {
                let text = format!("{}: the link to the hub was down", req.service.name);
                self.router
                    .calls
                    .respond(me, req.id, CallStatus::NoProvider, None, text);
            }
        }
        for s in self.router.calls.services() {
            if s.provider != me {
                session.handle_peer_event(PeerMsg::Changed(ServiceChange::Added(s)));
            }
        }
    }

    /// The open link, until its session ends: returns why.
    async fn serve(
        &self,
        session: &mut LinkSession,
        stream: &mut WsStream,
        ctrl_tx: &ControlSender,
        namespace: &str,
        shutdown: &CancellationToken,
    ) -> CloseReason {
        let mut mirror_subs = self.cfg.mirror.as_ref().map(|_| MirrorSubs {
            next_id: MIRROR_SUBSCRIPTIONS,
            ..MirrorSubs::default()
        });
        let mut down: HashMap<u32, Arc<Topic>> = HashMap::new();
        // Topics that appear later are announced as they do, before any message of theirs
        // flows (a site hub's robots send nothing nobody wants).
        let topics = self.router.watch_topics();
        // Local topics carried up that have lost their last publisher (a ROS node gone).
        let mut unpublished: HashSet<TopicId> = HashSet::new();
        // What the reports told the hub on this connection (only changes are sent again).
        let mut told = Told::default();
        let mut timer = drive::Timer::default();
        loop {
            while let Some(ev) = session.poll_event() {
                match ev {
                    Event::Closed(r) => return r,
                    Event::Link(ev) => self.on_event(ev, namespace, &mut down, session),
                    Event::Pong {
                        id,
                        responder_ns,
                        rtt,
                        ..
                    } => {
                        if id < fleetlink_relay::link::HEARTBEAT_ID_BASE {
                            self.outbox.on_echo(id, responder_ns, Instant::now());
                        } else {
                            self.outbox
                                .on_heartbeat_echo(rtt, responder_ns, Instant::now());
                        }
                        self.stats.rtt_ns.store(rtt.as_nanos() as u64, Relaxed);
                    }
                    Event::ReportDue => self.report(session, &mut unpublished, &mut told),
                    Event::Hello { .. } | Event::Opened { .. } => {}
                }
            }
            drive::pump(session, ctrl_tx);
            let deadline = session.poll_timeout();
            tokio::select! {
                m = stream.next() => {
                    let m = m.map(|r| r.map(ClientMessage::from));
                    if let Some(ping) = drive::feed(session, m, Instant::now()) {
                        let _ = ctrl_tx.try_send(Box::new(Control::Pong(ping)));
                    }
                }
                m = self.calls_rx.recv(), if session.wants_peer_events() => {
                    if let Some(m) = m {
                        session.handle_peer_event(m);
                    }
                }
                permit = ctrl_tx.reserve(), if session.has_transmit() => {
                    if let (Ok(p), Some(c)) = (permit, session.poll_transmit()) {
                        p.send(Box::new(c));
                    }
                }
                _ = timer.wait(deadline) => session.handle_timeout(Instant::now()),
                () = self.control.renamed.notified() => {
                    session.close(CloseReason::Local(RENAMED.into()));
                }
                () = topics.changed() => {
                    self.announce_new(&topics, namespace, mirror_subs.as_mut(), session)
                }
                _ = shutdown.cancelled() => {
                    session.close(CloseReason::Local("the agent is shutting down".into()));
                }
            }
            // Deadlines are kept whichever branch ran (see the hub's driver).
            if session.poll_timeout().is_some_and(|t| Instant::now() >= t) {
                session.handle_timeout(Instant::now());
            }
        }
    }

    /// Why a connection that never got `WELCOME` failed, and so how soon to retry.
    fn before_welcome(&self, url: &str, r: CloseReason) -> Failure {
        match r {
            CloseReason::Refused(text) => {
                refusal(&text, url, self.cfg.robot.as_str(), &self.cfg.token)
            }
            CloseReason::HandshakeTimeout { .. } => {
                Failure::hub("no WELCOME from the hub within 10 s".to_owned())
            }
            CloseReason::ReadError(e) => Failure::Link(format!("reading WELCOME: {e}")),
            CloseReason::PeerClosed(_) => {
                Failure::hub("the hub closed the connection before WELCOME".to_owned())
            }
            other => Failure::hub(other.to_string()),
        }
    }
}

/// Runs `fut` unless the agent shuts down first.
async fn or_shutdown<T>(
    shutdown: &CancellationToken,
    fut: impl std::future::Future<Output = T>,
) -> Result<T, Failure> {
    tokio::select! {
        r = fut => Ok(r),
        _ = shutdown.cancelled() => Err(Failure::hub("the agent is shutting down".to_owned())),
    }
}
