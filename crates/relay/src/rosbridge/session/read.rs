//! The session's reader: `serve`, the loop that runs one connection, reads the client's
//! frames and hands each operation to `Session`. Apart from what the operations do
//! (session.rs and its other modules), which this loop only calls.

use super::*;
use std::pin::Pin;
use std::time::Duration;

use fleetlink_proto::rosbridge::EnvelopeShapes;
use tokio::task::JoinHandle;
use tokio_util::sync::WaitForCancellationFuture;

use crate::calls::PeerReceiver;

/// Why a session's reader stopped.
enum Stop {
    /// The client left or broke the protocol, or the server is shutting down.
    Ended,
    /// The client showed no progress for this long (`SessionConfig::liveness`).
    Silent(Duration),
}

/// What one frame came to.
#[allow(
    clippy::large_enum_variant,
    reason = "moved once per frame on the hot path; boxing the operation would allocate"
)]
enum Read<'f> {
    /// An operation to apply, or why it could not be read.
    Op(Result<Incoming<'f>, ParseError>),
    /// A publish done on the short path: nothing left to apply.
    Published,
    /// Nothing to apply: a control frame answered, a fragment kept for later.
    Skip,
    /// The connection is closing (a close frame queued for the writer) or failed.
    Stop,
}

/// Runs a session until the client leaves: `stream` gives the client's messages, `sink`
/// takes what is sent to it (an accepted WebSocket's halves, see [`crate::websocket`]).
/// Ends when the client leaves, when it shows no progress for the silence limit
/// (`cfg.liveness`; `conn` says how to sample its connection), or when `shutdown` is
/// cancelled.
///
/// Control frames are answered here: a `Ping` with a `Pong`, a `Close` with a `Close`
/// echoing its code; a frame that breaks the protocol closes the connection with the
/// code that says why (1002, 1007 for text that is not UTF-8, 1009 when too large).
pub async fn serve<K, S>(
    sink: K,
    stream: S,
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
    let (client, outbox) = router.connect(ClientKind::Rosbridge, addr);
    if sink.deflate().is_some() {
        router.note_deflate(client);
    }
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let (reply_tx, reply_rx) = mpsc::channel(REPLY_QUEUE);
    let mut watch = Watch::new(cfg.liveness, conn.progress, reply_tx.clone());
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
    let mut session = Session {
        router: router.clone(),
        client,
        cfg,
        published: HashMap::default(),
        subs: HashMap::new(),
        replies: reply_tx,
        gate: auth.gate,
        guard: auth.guard,
        writer_gate,
        calls: crate::rosbridge::calls::SessionCalls::default(),
        level,
        fragments: Fragments::default(),
        clock: crate::StampClock::default(),
        unflushed: Vec::new(),
    };
    let stop = session
        .read_frames(stream, &peer_rx, &mut watch, &shutdown)
        .await;
    session.finish(&stop, &shutdown, addr);
    drop(session);
    drop(watch);
    end_writer(writer, &stop).await;
}

/// Waits for the writer once the session is over; one behind a client that went silent
/// is not waited for, since its socket may never drain.
async fn end_writer(writer: JoinHandle<()>, stop: &Stop) {
    if matches!(stop, Stop::Silent(_)) {
        writer.abort();
    }
    let _ = writer.await;
}

impl Session {
    /// The reader's loop: takes the client's frames and applies them until the client
    /// leaves, goes silent or breaks the protocol, or `shutdown` is cancelled.
    async fn read_frames<S>(
        &mut self,
        mut stream: S,
        peer_rx: &PeerReceiver,
        watch: &mut Watch,
        shutdown: &CancellationToken,
    ) -> Stop
    where
        S: Stream<Item = Result<ClientMessage, WsError>> + Unpin + Send,
    {
        // The client's recent publish envelopes (kept here, beside the session, because the
        // frame that is read with them borrows them while the session publishes).
        let mut shapes = EnvelopeShapes::default();
        // One wait for the shutdown, registered once: a fresh `cancelled()` per frame costs a
        // lock and a waker registration on every operation.
        let cancelled = shutdown.cancelled();
        tokio::pin!(cancelled);
        // Frames are taken first while the client has some queued: a frame already read is
        // taken without a select, since polling every branch for each of thousands of small
        // operations in a read costs more than handling them. So that a flooding client still
        // sees its call replies and a shutdown, both are looked at every `LOOK_AROUND` frames
        // without waiting.
        let mut frames = 0u32;
        loop {
            frames += 1;
            if frames.is_multiple_of(LOOK_AROUND)
                && let Err(stop) = self.look_around(peer_rx, watch, shutdown).await
            {
                return stop;
            }
            let frame = match stream.next().now_or_never() {
                Some(Some(f)) => f,
                Some(None) => return Stop::Ended,
                None => match self
                    .wait_for_frame(&mut stream, peer_rx, watch, cancelled.as_mut())
                    .await
                {
                    Ok(Some(f)) => f,
                    // A call reply was served: look around before waiting again.
                    Ok(None) => continue,
                    Err(stop) => return stop,
                },
            };
            if matches!(frame, Ok(ClientMessage::Binary(_))) {
                self.calls.binary = true;
            }
            // The frame's bytes, which the operation read from them borrows.
            let mut held = None;
            let req = match self.read_frame(frame, &mut shapes, &mut held).await {
                Read::Op(req) => req,
                Read::Published => {
                    tokio::task::consume_budget().await;
                    continue;
                }
                Read::Skip => continue,
                Read::Stop => return Stop::Ended,
            };
            // A publish may wait for room on a no-drop topic (`Session::wait_for_room`); a
            // shutdown must not wait for it. `biased`: the step nearly always finishes at
            // once.
            tokio::select! {
                biased;
                _ = self.apply(req) => {}
                _ = &mut cancelled => return Stop::Ended,
                silent = watch.gone() => return Stop::Silent(silent),
            }
            // One socket read can hold thousands of small operations; counting each against
            // the task's budget makes a flooding client give way to the writers that deliver
            // its messages (without it, a woken writer waits behind the whole read and the
            // subscribers' queues overflow).
            tokio::task::consume_budget().await;
        }
    }

    /// The look every `LOOK_AROUND` frames, for a client whose frames come without a
    /// wait: the shutdown, the counters, the client's liveness, its call replies.
    async fn look_around(
        &mut self,
        peer_rx: &PeerReceiver,
        watch: &mut Watch,
        shutdown: &CancellationToken,
    ) -> Result<(), Stop> {
        if shutdown.is_cancelled() {
            return Err(Stop::Ended);
        }
        self.flush_counts();
        // A client sending without pause is read without waiting: it is alive, and its
        // pings fall due here.
        watch.read();
        if let Some(silent) = watch.check() {
            return Err(Stop::Silent(silent));
        }
        while let Ok(Some(m)) = peer_rx.try_recv() {
            watch.race(self.on_peer(m)).await.map_err(Stop::Silent)?;
        }
        Ok(())
    }

    /// Waits for the client's next frame when none is ready, serving call replies
    /// meanwhile. `None`: a call reply was served (the caller looks around again).
    async fn wait_for_frame<S>(
        &mut self,
        stream: &mut S,
        peer_rx: &PeerReceiver,
        watch: &mut Watch,
        cancelled: Pin<&mut WaitForCancellationFuture<'_>>,
    ) -> Result<Option<Result<ClientMessage, WsError>>, Stop>
    where
        S: Stream<Item = Result<ClientMessage, WsError>> + Unpin + Send,
    {
        // Nothing more has come: the counters catch up before the wait, and the next
        // message's arrival is a new clock reading.
        self.flush_counts();
        let f = tokio::select! {
            biased;
            f = stream.next() => f,
            m = peer_rx.recv() => {
                if let Some(m) = m {
                    watch.race(self.on_peer(m)).await.map_err(Stop::Silent)?;
                }
                return Ok(None);
            }
            _ = cancelled => return Err(Stop::Ended),
            silent = watch.gone() => return Err(Stop::Silent(silent)),
        };
        self.clock.waited();
        watch.read();
        f.map(Some).ok_or(Stop::Ended)
    }

    /// Reads one frame: a publish that can go on the short path is published here,
    /// control frames are answered, anything else is returned to be applied. `held`
    /// keeps the frame's bytes, which what is returned borrows.
    async fn read_frame<'f>(
        &mut self,
        frame: Result<ClientMessage, WsError>,
        shapes: &mut EnvelopeShapes,
        held: &'f mut Option<Bytes>,
    ) -> Read<'f> {
        match frame {
            Ok(ClientMessage::Text(t)) => self.read_text(t, shapes, held).await,
            Ok(ClientMessage::Binary(b)) => self.read_binary(held.insert(b)),
            Ok(ClientMessage::Ping(p)) => {
                self.send(WsMessage::Pong(p)).await;
                Read::Skip
            }
            Ok(ClientMessage::Close(c)) => {
                // The close handshake: the client's code echoed back.
                let echo = c.map(|c| CloseFrame {
                    code: c.code,
                    reason: "".into(),
                });
                let _ = self.replies.send(Reply::Close(echo)).await;
                Read::Stop
            }
            Ok(_) => Read::Skip,
            Err(e) => self.transport_error(e).await,
        }
    }

    /// A text frame. Nearly all traffic is a publish in one of the client's recent
    /// envelopes (`EnvelopeShapes`), read by comparing text, its UTF-8 and syntax checked
    /// by its check against the type.
    async fn read_text<'f>(
        &mut self,
        t: Bytes,
        shapes: &mut EnvelopeShapes,
        held: &'f mut Option<Bytes>,
    ) -> Read<'f> {
        let (t, fitted) = match shapes.fit(&t) {
            Some(m) => match self.publish_shaped(t, m) {
                Ok(()) => return Read::Published,
                // Not published at once (refused, or to wait): read again in full, so
                // that what follows is what the full read gives, the precise error
                // included.
                Err(back) => (back, true),
            },
            None => (t, false),
        };
        let text: &'f Bytes = held.insert(t);
        let Ok(utf8) = std::str::from_utf8(text) else {
            let close = CloseFrame {
                code: CloseCode::Invalid,
                reason: "a text message is not UTF-8".into(),
            };
            let _ = self.replies.send(Reply::Close(Some(close))).await;
            return Read::Stop;
        };
        let publish = if fitted {
            Publish::from_json_text(utf8, text)
        } else {
            Publish::from_json_text_shaped(utf8, text, shapes)
        };
        match publish {
            Some(p) => match self.publish_now(p, Some(text)) {
                Some(rest) => Read::Op(Ok(rest)),
                None => Read::Published,
            },
            None => match Request::from_json(text) {
                Ok(r) if matches!(r.op, Op::Fragment { .. }) => match self.fragment(r) {
                    Some(whole) => Read::Op(whole.map(Incoming::Other)),
                    None => Read::Skip,
                },
                other => Read::Op(other.map(Incoming::Other)),
            },
        }
    }

    /// A binary frame: a CBOR publish on the short path, or another CBOR operation.
    fn read_binary<'f>(&mut self, binary: &'f Bytes) -> Read<'f> {
        match Publish::from_cbor_frame(binary) {
            Some(p) => match self.publish_now(p, None) {
                Some(rest) => Read::Op(Ok(rest)),
                None => Read::Published,
            },
            None => Read::Op(Request::from_cbor(binary).map(Incoming::Other)),
        }
    }

    /// A frame the transport refused: the connection is closed with the code that says
    /// why; a socket that failed outright is left as it is.
    async fn transport_error(&self, e: WsError) -> Read<'static> {
        let (code, reason) = match &e {
            WsError::Capacity(e) => (CloseCode::Size, format!("frame too large: {e}")),
            WsError::Protocol(e) => (CloseCode::Protocol, e.to_string()),
            WsError::Utf8(e) => (CloseCode::Invalid, e.clone()),
            // A compressed message that does not inflate.
            WsError::Io(e) if e.kind() == std::io::ErrorKind::InvalidData => {
                (CloseCode::Protocol, e.to_string())
            }
            _ => return Read::Stop,
        };
        let close = CloseFrame {
            code,
            reason: reason.into(),
        };
        let _ = self.replies.send(Reply::Close(Some(close))).await;
        Read::Stop
    }

    /// Applies one operation read from a frame.
    async fn apply(&mut self, req: Result<Incoming<'_>, ParseError>) {
        match req {
            Ok(Incoming::Publish(p)) => self.handle_publish(p).await,
            Ok(Incoming::Refused(id, msg)) => {
                self.status("error", msg, id.value().as_ref()).await;
                self.clock.waited();
            }
            // Other operations are rare and may wait (a reply queue, a call): the next
            // message's arrival is read from the clock again.
            Ok(Incoming::Other(req)) => {
                self.handle(req).await;
                self.clock.waited();
            }
            Err(e) => {
                self.parse_error(e).await;
                self.clock.waited();
            }
        }
    }

    /// The session's end, once the reader has stopped: the counters flushed, a going-away
    /// close on shutdown, and what the client held released.
    fn finish(
        &mut self,
        stop: &Stop,
        shutdown: &CancellationToken,
        addr: Option<std::net::SocketAddr>,
    ) {
        self.flush_counts();
        if shutdown.is_cancelled() {
            // Going away (RFC 6455, 7.4.1), after what is queued; a writer too backed up to
            // take it is closed by the end of the reply channel anyway.
            let away = CloseFrame {
                code: CloseCode::Away,
                reason: "the server is shutting down".into(),
            };
            let _ = self.replies.try_send(Reply::Close(Some(away)));
        }
        if let Stop::Silent(silent) = stop {
            tracing::info!(
                "rosbridge client {}: no progress for {} ms (no bytes read, its connection not \
                 draining); closing it and releasing what it held",
                addr.map_or_else(|| "?".into(), |a| a.to_string()),
                silent.as_millis()
            );
        }
        // What the client held goes now: its subscriptions (and the demand they made), its
        // advertisements, its calls and goals, their callers and providers told.
        self.router.disconnect(self.client);
    }
}
