//! The session's reader: `serve`, the loop that runs one connection, reads the client's
//! frames and hands each operation to `Session`. Apart from what the operations do
//! (session.rs and its other modules), which this loop only calls. What runs once or
//! rarely (the setup, the end, control frames, the look around every `LOOK_AROUND`
//! frames) is in functions of its own; what runs for each frame stays in the loop.

use std::ops::ControlFlow::{self, Break, Continue};
use std::time::Duration;

use fleetlink_relay::calls::PeerReceiver;
use tokio::task::JoinHandle;

use super::*;

/// Runs a session until the client leaves: `stream` gives the client's messages, `sink`
/// takes what is sent to it (an accepted WebSocket's halves, see
/// [`fleetlink_relay::websocket`]). Ends when the client leaves, when it shows no progress
/// for the silence limit (`cfg.liveness`; `conn` says how to sample its connection), or
/// when `shutdown` is cancelled.
///
/// Control frames are answered here: a `Ping` with a `Pong`, a `Close` with a `Close`
/// echoing its code; a frame that breaks the protocol closes the connection with the
/// code that says why (1002, 1007 for text that is not UTF-8, 1009 when too large).
pub async fn serve<K, S>(
    sink: K,
    mut stream: S,
    router: Arc<Router>,
    conn: impl Into<Peer>,
    cfg: Arc<SessionConfig>,
    shutdown: CancellationToken,
    auth: SessionAuth,
) where
    K: PartsSink + Send + 'static,
    S: Stream<Item = Result<ClientMessage, WsError>> + Unpin + Send,
{
    let conn: Peer = conn.into();
    let addr = conn.addr;
    let (mut session, mut watch, peer_rx, writer) = open(sink, &router, conn, cfg, auth);
    // The client's recent publish envelopes (kept here, beside the session, because the
    // frame that is read with them borrows them while the session publishes).
    let mut shapes = fleetlink_proto::rosbridge::EnvelopeShapes::default();
    // One wait for the shutdown, registered once: a fresh `cancelled()` per frame costs a
    // lock and a waker registration on every operation.
    let mut cancelled = std::pin::pin!(shutdown.cancelled());
    // For the look around every `LOOK_AROUND` frames (`look_around` says why).
    let mut frames = 0u32;
    // Set when the client showed no progress for the silence limit: how long.
    let mut gone = None;
    loop {
        frames += 1;
        if frames.is_multiple_of(LOOK_AROUND)
            && let Break(silent) = look_around(&shutdown, &mut session, &mut watch, &peer_rx).await
        {
            gone = silent;
            break;
        }
        let frame = match stream.next().now_or_never() {
            Some(f) => f,
            None => {
                // Nothing more has come: the counters catch up before the wait, and the
                // next message's arrival is a new clock reading.
                session.flush_counts();
                let f = tokio::select! {
                    biased;
                    f = stream.next() => f,
                    m = peer_rx.recv() => {
                        if let Some(m) = m
                            && let Err(silent) = watch.race(session.on_peer(m)).await
                        {
                            gone = Some(silent);
                            break;
                        }
                        continue;
                    }
                    _ = &mut cancelled => break,
                    silent = watch.gone() => {
                        gone = Some(silent);
                        break;
                    }
                };
                session.clock.waited();
                watch.read();
                f
            }
        };
        let Some(frame) = frame else {
            break;
        };
        let (text, binary);
        let req = match frame {
            Ok(ClientMessage::Text(t)) => {
                // Nearly all traffic: a publish in one of the client's recent envelopes
                // (`EnvelopeShapes`), read by comparing text, its UTF-8 and syntax
                // checked by its check against the type.
                let (t, fitted) = match shapes.fit(&t) {
                    Some(m) => match session.publish_shaped(t, m) {
                        Ok(()) => {
                            tokio::task::consume_budget().await;
                            continue;
                        }
                        // Not published at once (refused, or to wait): read again in
                        // full, so that what follows is what the full read gives, the
                        // precise error included.
                        Err(back) => (back, true),
                    },
                    None => (t, false),
                };
                text = t;
                let Ok(utf8) = std::str::from_utf8(&text) else {
                    let close = closing(CloseCode::Invalid, "a text message is not UTF-8");
                    let _ = session.replies.send(close).await;
                    break;
                };
                let publish = if fitted {
                    Publish::from_json_text(utf8, &text)
                } else {
                    Publish::from_json_text_shaped(utf8, &text, &mut shapes)
                };
                match publish {
                    Some(p) => match session.publish_now(p, Some(&text)) {
                        Some(rest) => Ok(rest),
                        None => {
                            tokio::task::consume_budget().await;
                            continue;
                        }
                    },
                    None => match Request::from_json(&text) {
                        Ok(r) if matches!(r.op, Op::Fragment { .. }) => match session.fragment(r) {
                            Some(whole) => whole.map(Incoming::Other),
                            None => continue,
                        },
                        other => other.map(Incoming::Other),
                    },
                }
            }
            Ok(ClientMessage::Binary(b)) => {
                session.calls.binary = true;
                binary = b;
                match Publish::from_cbor_frame(&binary) {
                    Some(p) => match session.publish_now(p, None) {
                        Some(rest) => Ok(rest),
                        None => {
                            tokio::task::consume_budget().await;
                            continue;
                        }
                    },
                    None => Request::from_cbor(&binary).map(Incoming::Other),
                }
            }
            other => match answer_control(&session, other).await {
                Continue(()) => continue,
                Break(()) => break,
            },
        };
        // A publish may wait for room on a no-drop topic (`Session::wait_for_room`); a
        // shutdown must not wait for it. `biased`: the step nearly always finishes at once.
        tokio::select! {
            biased;
            _ = step(&mut session, req) => {}
            _ = &mut cancelled => break,
            silent = watch.gone() => {
                gone = Some(silent);
                break;
            }
        }
        // One socket read can hold thousands of small operations; counting each against
        // the task's budget makes a flooding client give way to the writers that deliver
        // its messages (without it, a woken writer waits behind the whole read and the
        // subscribers' queues overflow).
        tokio::task::consume_budget().await;
    }
    finish(session, watch, writer, gone, &shutdown, &router, addr).await;
}

/// Sets a session up: the client known to the router and its call tables (their
/// messages for it come out of the `PeerReceiver`), the reply channel, the liveness watch,
/// and the writer task (spawned here, with `sink`).
fn open<K: PartsSink + Send + 'static>(
    sink: K,
    router: &Arc<Router>,
    conn: Peer,
    cfg: Arc<SessionConfig>,
    auth: SessionAuth,
) -> (Session, Watch, PeerReceiver, JoinHandle<()>) {
    let (client, outbox) = router.connect(ClientKind::Rosbridge, conn.addr);
    if sink.deflate().is_some() {
        router.note_deflate(client);
    }
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let (reply_tx, reply_rx) = mpsc::channel(REPLY_QUEUE);
    let watch = Watch::new(cfg.liveness, conn.progress, reply_tx.clone());
    let writer_gate = Arc::new(Mutex::new(auth.gate.as_ref().map(|g| g.fork())));
    let level = Arc::new(std::sync::atomic::AtomicU8::new(DEFAULT_LEVEL));
    let writer = tokio::spawn(write_loop(
        sink,
        outbox.clone(),
        reply_rx,
        router.clone(),
        cfg.batch,
        writer_gate.clone(),
        level.clone(),
    ));
    let session = Session {
        router: router.clone(),
        client,
        cfg,
        published: HashMap::default(),
        subs: HashMap::new(),
        replies: reply_tx,
        gate: auth.gate,
        guard: auth.guard,
        writer_gate,
        calls: crate::calls::SessionCalls::default(),
        level,
        fragments: Fragments::default(),
        clock: fleetlink_relay::StampClock::default(),
        unflushed: Vec::new(),
    };
    (session, watch, peer_rx, writer)
}

/// The look around `serve` takes every `LOOK_AROUND` frames, without waiting: the
/// shutdown, the counters, the client's liveness, and the call replies queued for it.
/// `Break` ends the session, with how long the client showed no progress when that is
/// why.
///
/// Frames are taken first while the client has some queued: a frame already read is
/// taken without a select, since polling every branch for each of thousands of small
/// operations in a read costs more than handling them. So that a flooding client still
/// sees its call replies and a shutdown, both are looked at here.
async fn look_around(
    shutdown: &CancellationToken,
    session: &mut Session,
    watch: &mut Watch,
    peer_rx: &PeerReceiver,
) -> ControlFlow<Option<Duration>> {
    if shutdown.is_cancelled() {
        return Break(None);
    }
    session.flush_counts();
    // A client sending without pause is read without waiting: it is alive, and its pings
    // fall due here.
    watch.read();
    if let Some(silent) = watch.check() {
        return Break(Some(silent));
    }
    while let Ok(Some(m)) = peer_rx.try_recv() {
        if let Err(silent) = watch.race(session.on_peer(m)).await {
            return Break(Some(silent));
        }
    }
    Continue(())
}

/// An operation that needs more than the short path of a publish (`Incoming`), as one
/// step of `serve`'s loop (which stops waiting for it on a shutdown).
async fn step(session: &mut Session, req: Result<Incoming<'_>, ParseError>) {
    match req {
        Ok(Incoming::Publish(p)) => session.handle_publish(p).await,
        Ok(Incoming::Refused(id, msg)) => {
            session.status("error", msg, id.value().as_ref()).await;
            session.clock.waited();
        }
        // Other operations are rare and may wait (a reply queue, a call): the next
        // message's arrival is read from the clock again.
        Ok(Incoming::Other(req)) => {
            session.handle(req).await;
            session.clock.waited();
        }
        Err(e) => {
            session.parse_error(e).await;
            session.clock.waited();
        }
    }
}

/// A close frame with `code` and `reason`, as the writer takes it.
fn closing(code: CloseCode, reason: &str) -> Reply {
    Reply::Close(Some(CloseFrame {
        code,
        reason: reason.into(),
    }))
}

/// Answers a frame that is neither text nor binary, or a read that failed. `Break` ends
/// the session.
async fn answer_control(
    session: &Session,
    frame: Result<ClientMessage, WsError>,
) -> ControlFlow<()> {
    match frame {
        Ok(ClientMessage::Ping(p)) => {
            session.send(WsMessage::Pong(p)).await;
            Continue(())
        }
        Ok(ClientMessage::Close(c)) => {
            // The close handshake: the client's code echoed back.
            let echo = c.map(|c| CloseFrame {
                code: c.code,
                reason: "".into(),
            });
            let _ = session.replies.send(Reply::Close(echo)).await;
            Break(())
        }
        Ok(_) => Continue(()),
        Err(e) => {
            let (code, reason) = match &e {
                WsError::Capacity(e) => (CloseCode::Size, format!("frame too large: {e}")),
                WsError::Protocol(e) => (CloseCode::Protocol, e.to_string()),
                WsError::Utf8(e) => (CloseCode::Invalid, e.clone()),
                // A compressed message that does not inflate.
                WsError::Io(e) if e.kind() == std::io::ErrorKind::InvalidData => {
                    (CloseCode::Protocol, e.to_string())
                }
                _ => return Break(()),
            };
            let close = CloseFrame {
                code,
                reason: reason.into(),
            };
            let _ = session.replies.send(Reply::Close(Some(close))).await;
            Break(())
        }
    }
}

/// The end of a session, once its loop stopped: a shutdown told to the client, what it
/// held released, and its writer finished (`gone`: it showed no progress for that long).
async fn finish(
    mut session: Session,
    watch: Watch,
    writer: JoinHandle<()>,
    gone: Option<Duration>,
    shutdown: &CancellationToken,
    router: &Router,
    addr: Option<std::net::SocketAddr>,
) {
    session.flush_counts();
    if shutdown.is_cancelled() {
        // Going away (RFC 6455, 7.4.1), after what is queued; a writer too backed up to
        // take it is closed by the end of the reply channel anyway.
        let away = CloseFrame {
            code: CloseCode::Away,
            reason: "the server is shutting down".into(),
        };
        let _ = session.replies.try_send(Reply::Close(Some(away)));
    }
    if let Some(silent) = gone {
        tracing::info!(
            "rosbridge client {}: no progress for {} ms (no bytes read, its connection not \
             draining); closing it and releasing what it held",
            addr.map_or_else(|| "?".into(), |a| a.to_string()),
            silent.as_millis()
        );
    }
    // What the client held goes now: its subscriptions (and the demand they made), its
    // advertisements, its calls and goals, their callers and providers told.
    router.disconnect(session.client);
    drop(session);
    drop(watch);
    if gone.is_some() {
        // Its socket may never drain: the writer is not waited for.
        writer.abort();
    }
    let _ = writer.await;
}

#[cfg(test)]
mod tests {
    /// The session hands `Publish::from_json_text` a WebSocket text frame and the bytes
    /// it converts into: they must be one buffer, or every publish takes the full parse.
    #[test]
    fn a_websocket_text_frame_takes_the_publish_short_path() {
        use tokio_tungstenite::tungstenite::Utf8Bytes;
        let text = Utf8Bytes::from(r#"{"op":"publish","topic":"/a","msg":{"data":1}}"#.to_owned());
        let bytes = bytes::Bytes::from(text.clone());
        let p = fleetlink_proto::rosbridge::Publish::from_json_text(text.as_str(), &bytes)
            .expect("the short path");
        assert_eq!(&p.msg.bytes[..], br#"{"data":1}"#);
    }
}
