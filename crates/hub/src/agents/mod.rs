//! Agents on the hub: one `fleetlink.v1` link per robot.
//!
//! - [`serve_agent`] drives one link: the sans-IO [`LinkSession`] (handshake, calls,
//!   heartbeats, liveness) fed with what the socket reads and woken at its deadlines; the
//!   outbox writer ([`write_link`]) in a task of its own; the robot's topics and
//!   subscriptions applied to the hub's router ([`events`]).
//! - A link that is up is entered in the [`Registry`] of robots online
//!   ([`crate::registry`], a module of its own so `rosout` and `security` can read it
//!   without importing the sessions that fill it).

mod events;

use std::net::SocketAddr;
use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::{Duration, Instant};

use fleetlink_auth::{Credential, GroupName, Operation, RobotName, Token, TokenKind};
use fleetlink_proto::frame::{Frame, WELCOME_COMPRESSION, WELCOME_INTEREST};
use fleetlink_relay::calls::{ChannelPeer, PeerReceiver};
use fleetlink_relay::gate::Gate;
use fleetlink_relay::link::session::{
    Accept, CloseReason, Event, LinkSession, Role, SessionConfig, system_wall_clock,
};
use fleetlink_relay::link::{Control, ControlSender, ViaOut, drive, write_link};
use fleetlink_relay::link_calls::{LinkCalls, SameNames};
use fleetlink_relay::websocket::ClientMessage;
use fleetlink_relay::{ClientKind, Router};
use futures_util::future::BoxFuture;
use futures_util::{FutureExt, Sink, SinkExt, Stream, StreamExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};
use tokio_util::sync::CancellationToken;

use crate::delivery::DeliveryLedger;
use crate::registry::{LinkKind, LiveLink, LiveRobot, Registry};
use crate::store::Store;
use events::RobotLink;

/// How long a new connection has to send `HELLO` (and be authenticated).
const HELLO_TIMEOUT: Duration = Duration::from_secs(10);
/// Heartbeat bounds a robot may ask for.
const MIN_HEARTBEAT_MS: u32 = 50;
const MAX_HEARTBEAT_MS: u32 = 60_000;
/// Frames between the session and the link's writer. When the writer falls behind, the
/// session keeps what it has to send (bounded, see its docs) and stops taking call-table
/// news: nothing waits on the writer.
const WRITER_QUEUE: usize = 1024;

/// What an agent session needs from the hub.
pub struct AgentContext {
    pub router: Arc<Router>,
    pub registry: Arc<Registry>,
    pub store: Store,
    pub shutdown: CancellationToken,
    pub security: Arc<fleetlink_auth::Security>,
    /// Heartbeat used when the agent does not ask for one.
    pub default_heartbeat_ms: u32,
    /// How far each robot's no-drop topics were delivered.
    pub ledger: Arc<DeliveryLedger>,
    /// The hub's `/rosout`: robots connecting, leaving, refused.
    pub rosout: Arc<crate::rosout::RosOut>,
    /// This hub's id on links between hubs (`VIA`): a message that has passed it never
    /// comes back (docs/site-hubs.md).
    pub hub_id: u64,
}

/// What `HELLO` said, once authenticated.
struct Admitted {
    robot: String,
    heartbeat_ms: u32,
    identity: fleetlink_auth::Identity,
    outbox_epoch: u64,
    kind: LinkKind,
}

/// Runs one agent connection to the end. `slot` (the hub's handshake admission) is held
/// until the hub answers `HELLO`.
pub async fn serve_agent<R, W, P>(
    mut reader: R,
    mut sink: W,
    ctx: Arc<AgentContext>,
    addr: Option<SocketAddr>,
    conn: fleetlink_auth::ConnInfo,
    slot: P,
) where
    R: Stream<Item = Result<ClientMessage, WsError>> + Unpin + Send,
    W: Sink<WsMessage, Error = WsError> + Unpin + Send + 'static,
    P: Send,
{
    let who = addr.map_or_else(|| "(unknown address)".to_owned(), |a| a.to_string());
    let mut session = hub_session(&ctx);
    let admitted = match handshake(&mut reader, &mut sink, &mut session, &ctx, conn).await {
        Ok(a) => a,
        Err(Ended::Gone(reason)) => {
            // Closed or broken before HELLO: the close is answered (RFC 6455, 5.5.1), with
            // the protocol error's code where there was one.
            if let Some(f) = drive::close_frame(&reason) {
                let _ = sink.send(WsMessage::Close(Some(f))).await;
            }
            let _ = sink.close().await;
            return;
        }
        Err(Ended::Refuse(reason, robot)) => {
            let who = match robot {
                Some(r) => format!("{r} from {who}"),
                None => who,
            };
            return refuse(sink, &mut session, reason, &who, &ctx.rosout).await;
        }
    };
    let Admitted {
        robot,
        heartbeat_ms,
        identity,
        outbox_epoch,
        kind,
    } = admitted;
    // A mirror's topics live in its robot's namespace.
    let namespace = format!("/{}", kind.acts_in(&robot));
    let what = kind.describe(&robot);
    let book = ctx.ledger.open(&robot, outbox_epoch).await;
    let (client, outbox) = ctx.router.connect(
        ClientKind::Agent {
            robot: robot.clone(),
        },
        addr,
    );
    let (peer, peer_rx) = ChannelPeer::new();
    ctx.router.calls.attach(client, peer);
    let (ctrl_tx, ctrl_rx) = mpsc::channel::<Box<Control>>(WRITER_QUEUE);
    // Cancelled by a newer connection of the robot, and with the hub's shutdown: the
    // session's loop waits on this one token of its own instead of two, one of them
    // shared (and locked on every turn) by every connection.
    let replaced = ctx.shutdown.child_token();
    let session_no = ctx.registry.next_session();
    let live = Arc::new(LiveRobot::new(LiveLink {
        name: robot.clone(),
        kind: kind.clone(),
        client,
        session: session_no,
        addr,
        heartbeat_ms,
        replaced: replaced.clone(),
    }));
    register(&ctx, &live, &kind, &robot, &what, &who, addr);

    let gate = link_gate(&ctx, &kind, identity, &robot);
    let writer_gate = gate.fork();
    let calls = ctx.router.calls.clone();
    session.accept(
        Accept {
            session: session_no.to_string(),
            namespace,
            heartbeat: Duration::from_millis(u64::from(heartbeat_ms)),
            gate: Box::new(gate),
            calls: Box::new(move |_| LinkCalls::new(calls, client, Box::new(SameNames))),
            features: WELCOME_INTEREST | WELCOME_COMPRESSION,
        },
        Instant::now(),
    );
    // A peer that turns out to be a site hub (it sends `VIA`) gets its messages marked
    // with the hubs they passed, and none that passed it.
    let via = ViaOut {
        me: ctx.hub_id,
        peer: session.link_in().peer_hub.clone(),
        always: false,
    };
    let writer = tokio::spawn(write_link(
        sink,
        outbox,
        ctrl_rx,
        Arc::new(|m| Some(m.name.to_string())),
        Vec::new(),
        Some(writer_gate),
        Some(via),
    ));
    // WELCOME is on its way: the hub has answered.
    drop(slot);

    let mut link = RobotLink::new(ctx.router.clone(), client, live.clone(), book);
    let reason = serve_open(
        &mut reader,
        &mut session,
        &mut link,
        &peer_rx,
        &ctrl_tx,
        &ctx,
        &replaced,
    )
    .await;
    // Calls the table queued for the link meanwhile fail with the reason, then the robot
    // leaves the router (its topics, subscriptions and services with it).
    while let Ok(Some(m)) = peer_rx.try_recv() {
        session.handle_peer_event(m);
    }
    ctx.router.disconnect(client);
    match kind {
        LinkKind::Mirror { .. } => ctx.registry.remove_mirror_if_session(&robot, session_no),
        LinkKind::Robot => ctx.registry.remove_if_session(&robot, session_no),
    }
    log_disconnected(&ctx, &robot, &what, &reason);
    drive::stop_writer(writer, ctrl_tx, &reason).await;
    if kind == LinkKind::Robot {
        record_seen(&ctx.store, &robot, addr, false);
    }
}

/// The hub's side of a new link, waiting for `HELLO`.
fn hub_session(ctx: &AgentContext) -> LinkSession {
    let mut session = LinkSession::hub(
        SessionConfig {
            role: Role::Hub,
            heartbeat: Duration::from_millis(u64::from(ctx.default_heartbeat_ms)),
            handshake_timeout: HELLO_TIMEOUT,
            report_every: None,
            wall: system_wall_clock(),
        },
        Instant::now(),
    );
    session.set_local_hub(ctx.hub_id);
    session
}

/// Enters an admitted link in the registry of robots online, closing the connection it
/// replaces, and tells the logs (and, for a robot, the store) that it connected.
fn register(
    ctx: &AgentContext,
    live: &Arc<LiveRobot>,
    kind: &LinkKind,
    robot: &str,
    what: &str,
    who: &str,
    addr: Option<SocketAddr>,
) {
    // A mirror replaces an older connection of the same mirror, never its robot's.
    let old = match kind {
        LinkKind::Mirror { .. } => ctx.registry.insert_mirror(live.clone()),
        LinkKind::Robot => ctx.registry.insert(live.clone()),
    };
    if let Some(old) = old {
        tracing::info!(robot = %robot, "{what} reconnected; replacing its previous connection");
        ctx.rosout.log(
            crate::rosout::Level::Info,
            "connected",
            format!("{what} reconnected from {who}; its previous connection is closed"),
        );
        old.replace();
        ctx.router.disconnect(old.client);
    }
    tracing::info!(robot = %robot, ?addr, "{what} connected");
    ctx.rosout.log(
        crate::rosout::Level::Info,
        "connected",
        format!("{what} connected from {who}"),
    );
    if *kind == LinkKind::Robot {
        record_seen(&ctx.store, robot, addr, true);
    }
}

/// The gate the link's traffic passes. What a mirror publishes in its robot's namespace
/// is input to that robot (audited as an operator's is): it speaks for no robot of its
/// own.
fn link_gate(
    ctx: &AgentContext,
    kind: &LinkKind,
    identity: fleetlink_auth::Identity,
    robot: &str,
) -> crate::security::HubGate {
    match kind {
        LinkKind::Mirror { .. } => {
            crate::security::HubGate::new(ctx.security.clone(), ctx.registry.clone(), identity)
        }
        LinkKind::Robot => crate::security::HubGate::for_agent(
            ctx.security.clone(),
            ctx.registry.clone(),
            identity,
            robot,
        ),
    }
}

/// Logs the end of a link: a warning when the robot went silent or its socket broke.
fn log_disconnected(ctx: &AgentContext, robot: &str, what: &str, reason: &CloseReason) {
    let level = match reason {
        CloseReason::Silent { .. } | CloseReason::ReadError(_) => crate::rosout::Level::Warn,
        _ => crate::rosout::Level::Info,
    };
    tracing::info!(robot = %robot, "{what} disconnected: {reason}");
    ctx.rosout.log(
        level,
        "disconnected",
        format!("{what} disconnected: {reason}"),
    );
}

/// How a handshake ended without admitting the robot.
enum Ended {
    /// The connection closed or broke the WebSocket protocol first.
    Gone(CloseReason),
    /// Refused, with this reason (and the robot's name, once known).
    Refuse(String, Option<String>),
}

/// Reads until `HELLO`, checks it and authenticates it, all within the handshake
/// deadline. WebSocket pings meanwhile are answered on `sink`.
async fn handshake<R, W>(
    reader: &mut R,
    sink: &mut W,
    session: &mut LinkSession,
    ctx: &AgentContext,
    conn: fleetlink_auth::ConnInfo,
) -> Result<Admitted, Ended>
where
    R: Stream<Item = Result<ClientMessage, WsError>> + Unpin,
    W: Sink<WsMessage, Error = WsError> + Unpin,
{
    let (robot, token, hb, outbox_epoch, mirror) = loop {
        match session.poll_event() {
            Some(Event::Hello {
                robot,
                token,
                heartbeat_ms,
                outbox_epoch,
                mirror,
            }) => break (robot, token, heartbeat_ms, outbox_epoch, mirror),
            Some(Event::Closed(r)) => {
                return Err(match r {
                    r @ (CloseReason::PeerClosed(_)
                    | CloseReason::ReadError(_)
                    | CloseReason::Invalid { .. }) => Ended::Gone(r),
                    other => Ended::Refuse(other.to_string(), None),
                });
            }
            Some(_) => continue,
            None => {}
        }
        tokio::select! {
            m = reader.next() => {
                if let Some(ping) = drive::feed(session, m, Instant::now()) {
                    let _ = sink.send(WsMessage::Pong(ping)).await;
                }
            }
            _ = drive::timer(session.poll_timeout()) => session.handle_timeout(Instant::now()),
            _ = ctx.shutdown.cancelled() => {
                return Err(Ended::Refuse("the hub is shutting down".into(), None));
            }
        }
    };
    // The name is parsed here, at the edge; a refusal quotes the rule.
    let name = RobotName::new(&robot).map_err(|e| Ended::Refuse(e.to_string(), None))?;
    let kind = match mirror.as_str() {
        "" => LinkKind::Robot,
        m => match RobotName::new(m) {
            Ok(_) if m == robot => {
                let reason = format!(
                    "mirror {robot} names itself as the robot it mirrors: give the mirror a name of its own (e.g. {robot}_mirror)"
                );
                return Err(Ended::Refuse(reason, Some(robot)));
            }
            Ok(_) => LinkKind::Mirror { of: mirror },
            Err(e) => return Err(Ended::Refuse(format!("mirror of {m:?}: {e}"), Some(robot))),
        },
    };
    let heartbeat_ms = if hb == 0 {
        ctx.default_heartbeat_ms
    } else {
        hb.clamp(MIN_HEARTBEAT_MS, MAX_HEARTBEAT_MS)
    };
    // A robot token (or a certificate, or a trusted robot network) names the robot. An
    // operator token of the admin group may also open an agent link, for tools such as
    // `fleetlink bench relay`. Anything but a robot token (operator, session, OIDC) is a
    // bearer credential; the token module tells them apart, not string prefixes here.
    let operator =
        !token.is_empty() && Token::parse(&token).map_or(true, |t| t.kind() != TokenKind::Robot);
    let credential = if operator {
        Credential::Bearer(token)
    } else {
        Credential::Agent {
            robot: name,
            token: (!token.is_empty()).then_some(token),
        }
    };
    let authenticated = tokio::select! {
        r = crate::security::authenticate(&ctx.security, credential, conn) => r,
        _ = drive::timer(session.poll_timeout()) => {
            return Err(Ended::Refuse("no HELLO within 10 s".into(), Some(robot)));
        }
        _ = ctx.shutdown.cancelled() => {
            return Err(Ended::Refuse("the hub is shutting down".into(), Some(robot)));
        }
    };
    let admin = GroupName::new("admin").expect("a valid group name");
    // The namespace the link acts in: a mirror's is its robot's.
    let acts_in = kind.acts_in(&robot);
    match authenticated {
        // Anyone else acting as a robot needs a rule letting it publish under that
        // robot's namespace: otherwise a viewer's token could evict a robot. So does any
        // mirror, whatever its credential: a robot token names the mirror, not the robot.
        Ok(identity)
            if (operator || kind != LinkKind::Robot)
                && !identity.in_group(&admin)
                && !may_publish_under(&ctx.security, &identity, acts_in) =>
        {
            let what = match kind {
                LinkKind::Mirror { .. } => "mirror",
                LinkKind::Robot => "act as",
            };
            let reason = format!(
                "{} may not {what} robot {acts_in}: no rule lets it publish under /{acts_in}",
                identity.principal()
            );
            Err(Ended::Refuse(reason, Some(robot)))
        }
        Ok(identity) => Ok(Admitted {
            robot,
            heartbeat_ms,
            identity,
            outbox_epoch,
            kind,
        }),
        // The public message alone ("authentication failed", "authentication required",
        // a rate limit): the agent turns it into advice.
        Err(e) => Err(Ended::Refuse(e.public_message(), Some(robot))),
    }
}

/// Whether a rule lets `identity` publish in `robot`'s namespace (`/robot` or
/// `/robot/…`, so that both `"/r1(/.*)?"` and `"/r1/.*"` rules count).
fn may_publish_under(
    security: &fleetlink_auth::Security,
    identity: &fleetlink_auth::Identity,
    robot: &str,
) -> bool {
    let mut access = security.access(identity.clone());
    access.allows(&format!("/{robot}"), Operation::Publish)
        || access.allows(&format!("/{robot}/"), Operation::Publish)
}

/// The open link, until its session ends: returns why.
async fn serve_open<R>(
    reader: &mut R,
    session: &mut LinkSession,
    link: &mut RobotLink,
    peer_rx: &PeerReceiver,
    ctrl_tx: &ControlSender,
    ctx: &AgentContext,
    stop: &CancellationToken,
) -> CloseReason
where
    R: Stream<Item = Result<ClientMessage, WsError>> + Unpin + Send,
{
    let mut timer = drive::Timer::default();
    // Delivery marks being written, and what to confirm when they are.
    let mut recording: Option<BoxFuture<'static, ()>> = None;
    let mut confirming: Vec<(u32, u64)> = Vec::new();
    // The waits other than the socket's are made once and kept across turns (each
    // fresh one registered and unregistered a waiter on every WebSocket message), and
    // made again only after they fire.
    let stopped = stop.cancelled();
    tokio::pin!(stopped);
    let demand = link.demand.clone();
    let mut demand_changed = std::pin::pin!(demand.changed());
    let mut call_news = std::pin::pin!(peer_rx.recv());
    let live = link.live.clone();
    let mut share_news = std::pin::pin!(live.share_news.notified());
    loop {
        while let Some(ev) = session.poll_event() {
            match ev {
                Event::Closed(r) => {
                    link.end_of_read();
                    return r;
                }
                ev => link.apply(ev, session),
            }
        }
        link.end_of_read();
        if recording.is_none() && !link.confirm.is_empty() {
            confirming = link.confirm.drain().collect();
            let (ledger, robot, book) = (
                ctx.ledger.clone(),
                link.live.name.clone(),
                link.book.clone(),
            );
            recording = Some(async move { ledger.record(&robot, &book).await }.boxed());
        }
        drive::pump(session, ctrl_tx);
        let deadline = session.poll_timeout();
        tokio::select! {
            m = reader.next() => {
                let (now, unix_ns) = (Instant::now(), fleetlink_relay::unix_nanos());
                link.live.last_seen_ns.store(unix_ns, Relaxed);
                link.read_at(now, unix_ns);
                if let Some(ping) = drive::feed(session, m, now) {
                    let _ = ctrl_tx.try_send(Box::new(Control::Pong(ping)));
                }
            }
            m = &mut call_news, if session.wants_peer_events() => {
                call_news.set(peer_rx.recv());
                if let Some(m) = m {
                    session.handle_peer_event(m);
                }
            }
            permit = ctrl_tx.reserve(), if session.has_transmit() => {
                if let (Ok(p), Some(c)) = (permit, session.poll_transmit()) {
                    p.send(Box::new(c));
                }
            }
            () = async { recording.as_mut().expect("guarded").await }, if recording.is_some() => {
                recording = None;
                for (alias, seq) in confirming.drain(..) {
                    session.delivered(alias, seq);
                }
            }
            _ = timer.wait(deadline) => session.handle_timeout(Instant::now()),
            () = &mut share_news => {
                share_news.set(live.share_news.notified());
                let bytes_per_sec = live.share_bps.load(Relaxed);
                session.send(Frame::Share { bytes_per_sec });
            }
            () = &mut demand_changed => {
                demand_changed.set(demand.changed());
                link.on_demand_changed(session);
            }
            _ = &mut stopped => {
                let why = if ctx.shutdown.is_cancelled() {
                    "the hub is shutting down"
                } else {
                    "replaced by a newer connection of the robot"
                };
                session.close(CloseReason::Local(why.into()));
            }
        }
        // Deadlines are kept whichever branch ran: with reads, calls and writes all ready
        // at once, the timer's branch may not be the one chosen.
        if session.poll_timeout().is_some_and(|t| Instant::now() >= t) {
            session.handle_timeout(Instant::now());
        }
    }
}

fn record_seen(store: &Store, robot: &str, addr: Option<SocketAddr>, online: bool) {
    let (store, r) = (store.clone(), robot.to_owned());
    let a = addr.map(|a| a.to_string()).unwrap_or_default();
    tokio::task::spawn_blocking(move || {
        if let Err(e) = store.robot_seen(&r, &a, online) {
            tracing::warn!("cannot record robot {r}: {e}");
        }
    });
}

/// Tells a connection why it is not accepted, then closes it: the session's refusal (a
/// `STATUS` 401 with the reason, queued by the session itself when it refused a malformed
/// `HELLO`), then a close frame (1008 with the reason).
async fn refuse<K>(
    mut sink: K,
    session: &mut LinkSession,
    reason: String,
    who: &str,
    rosout: &crate::rosout::RosOut,
) where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    tracing::warn!("refusing agent: {reason}");
    rosout.log(
        crate::rosout::Level::Warn,
        "refused",
        format!("refused agent {who}: {reason}"),
    );
    session.refuse(reason.clone());
    while let Some(c) = session.poll_transmit() {
        if let Control::Frame(f) = c
            && sink.feed(WsMessage::Binary(f.to_bytes())).await.is_err()
        {
            return;
        }
    }
    let close = drive::close_frame(&CloseReason::Refused(reason));
    let _ = sink.send(WsMessage::Close(close)).await;
    let _ = sink.close().await;
}
