//! The session's writer, a task of its own: the client's outbox and the reader's replies
//! onto the socket, flushed once per burst. Apart because it shares nothing with the
//! reader but the reply channel, its copy of the gate and the `status` level.

use super::*;

/// Messages taken in one go that mean a burst is being read (`write_loop`).
const BURST: usize = 32;

/// Turns a writer gives the reader of a burst before it flushes (`write_loop`): each is
/// at most one tokio budget (128 operations) read, so a burst of up to about 500 small
/// messages goes out in one write, and nothing waits longer than four budgets' work.
const BURST_TURNS: u32 = 4;

/// The socket failed, or the session closed it: the writer is done.
struct Closed;

/// The writer's side of the socket and what it needs to frame the client's messages.
struct Writer<K> {
    sink: K,
    outbox: Arc<Outbox>,
    router: Arc<Router>,
    /// The client's `status` level (`set_level`), shared with the reader.
    level: Arc<std::sync::atomic::AtomicU8>,
    /// Topics whose messages could not be encoded for this client: warned about once each.
    warned: HashMap<TopicName, ()>,
    /// Negotiated at the handshake; a client without it costs this one check per message.
    deflate: Option<DeflateConfig>,
}

/// The writer task: the reader's replies and the client's outbox onto the socket,
/// until the socket fails or the reader asks for a close.
pub(super) async fn write_loop<K: PartsSink>(
    sink: K,
    outbox: Arc<Outbox>,
    mut replies: mpsc::Receiver<Reply>,
    router: Arc<Router>,
    batch: usize,
    gate: Arc<Mutex<Option<Box<dyn Gate>>>>,
    level: Arc<std::sync::atomic::AtomicU8>,
) {
    let deflate = sink.deflate();
    let mut w = Writer {
        sink,
        outbox,
        router,
        level,
        warned: HashMap::new(),
        deflate,
    };
    // Frames written since the last flush, and the turns this task has given the others
    // since (see below).
    let (mut unflushed, mut turns) = (false, 0u32);
    // The batch, kept across rounds so a busy writer does not allocate one per round.
    let mut items: Vec<crate::outbox::Taken> = Vec::new();
    loop {
        let Ok(mut wrote) = w.send_replies(&mut replies).await else {
            return;
        };
        let now = Instant::now();
        let wake_at = w.outbox.take_into(&mut items, batch, 8 << 20, now);
        let took = items.len();
        admit(&gate, &mut items);
        for (slot, delivery, msg) in items.drain(..) {
            match w.deliver(slot, delivery, msg).await {
                Ok(sent) => wrote |= sent,
                Err(Closed) => return,
            }
        }
        unflushed |= wrote;
        // While a burst is being read (a full run of a publisher's operations came in),
        // a turn for the other tasks before the flush lets the next run join this system
        // call: each flush wakes the client, and on a busy hub those wake-ups cost more
        // than the writes. A publisher's read yields after tokio's budget of operations,
        // so a burst of a few hundred comes as several runs; turns continue while runs
        // keep coming, up to `BURST_TURNS` (a bound on what waits unflushed). A trickle
        // (a few messages per wake-up, as each of many subscribers of a topic sees) is
        // flushed at once; a turn would only add work.
        if took >= BURST && unflushed && turns < BURST_TURNS {
            turns += 1;
            tokio::task::yield_now().await;
            continue;
        }
        if unflushed {
            if w.sink.flush().await.is_err() {
                return;
            }
            (unflushed, turns) = (false, 0);
        }
        if took > 0 {
            continue;
        }
        if !wait_for_work(&mut w.sink, &mut replies, &w.outbox, wake_at).await {
            return;
        }
    }
}

/// Keeps of a batch only what the client may still see: checked on delivery, so a rule
/// change reaches live subscriptions. Nothing before the client authenticates.
fn admit(gate: &Mutex<Option<Box<dyn Gate>>>, items: &mut Vec<crate::outbox::Taken>) {
    let mut g = gate.lock().unwrap_or_else(|p| p.into_inner());
    match g.as_mut() {
        Some(g) => {
            // A batch mostly holds runs of one topic: ask once per run.
            let mut last = None;
            items.retain(|(_, _, m)| match last {
                Some((id, ok)) if id == m.topic.id => ok,
                _ => {
                    let ok = g.allows_topic(m.topic.id.0, m.topic.name.as_str(), GateOp::Subscribe);
                    last = Some((m.topic.id, ok));
                    ok
                }
            })
        }
        None => items.clear(),
    }
}

impl<K: PartsSink> Writer<K> {
    /// Feeds the reader's replies queued so far; `true` when any was written. A `Close`
    /// reply closes the socket and ends the writer.
    async fn send_replies(&mut self, replies: &mut mpsc::Receiver<Reply>) -> Result<bool, Closed> {
        let mut wrote = false;
        while let Ok(r) = replies.try_recv() {
            match r {
                Reply::Frame(m) => {
                    if self.sink.feed(m).await.is_err() {
                        return Err(Closed);
                    }
                    wrote = true;
                }
                Reply::Close(c) => {
                    close_with(&mut self.sink, c).await;
                    return Err(Closed);
                }
            }
        }
        Ok(wrote)
    }

    /// Feeds one message of the outbox in the form its subscription asked for; `false`
    /// when it could not be encoded (dropped, and the client warned once per topic).
    async fn deliver(
        &mut self,
        slot: crate::outbox::SlotId,
        delivery: Delivery,
        msg: Arc<Message>,
    ) -> Result<bool, Closed> {
        let kind = match delivery.compression {
            Compression::Cbor => FrameKind::RosbridgeCbor,
            Compression::CborRaw => FrameKind::RosbridgeCborRaw,
            Compression::Png => FrameKind::RosbridgePng,
            Compression::None => FrameKind::RosbridgeJson,
        };
        let fragment = delivery
            .fragment_size
            .map(|s| s as usize)
            .filter(|s| *s > 0);
        // A client that negotiated permessage-deflate gets a large message compressed:
        // once per message and kind, the same bytes for every such subscriber. The
        // rest (small, not worth it, or cut in rosbridge fragments) goes as below.
        if let Some(cfg) = self.deflate
            && fragment.is_none()
            && let Ok(Some((text, z))) = msg.deflated_frame(kind, self.router.transcoder(), cfg)
        {
            if crate::websocket::feed_deflated(&mut self.sink, text, &[], &z)
                .await
                .is_err()
            {
                return Err(Closed);
            }
            return Ok(true);
        }
        // Most messages: JSON text as its publisher sent it, framed into the socket
        // buffer; or a frame already built, sent whole. A large message is framed
        // once for all its subscribers instead (below), and each writes that frame
        // from where it lies.
        if fragment.is_none()
            && kind == FrameKind::RosbridgeJson
            && let Some(parts) = msg.json_parts()
            && msg.payload.len() <= crate::websocket::COPY_UP_TO
        {
            if crate::websocket::feed_parts(&mut self.sink, &parts)
                .await
                .is_err()
            {
                return Err(Closed);
            }
            return Ok(true);
        }
        let msg = match fragment {
            None => match Message::take_built_frame(msg, kind) {
                Ok(frame) => {
                    if self.sink.feed(frame).await.is_err() {
                        return Err(Closed);
                    }
                    return Ok(true);
                }
                Err(msg) => msg,
            },
            Some(_) => msg,
        };
        let mut frame = msg.rosbridge_frame(kind, self.router.transcoder());
        if frame.is_err() && kind == FrameKind::RosbridgeCborRaw {
            // No raw serialization for this message: the CBOR form is the closest.
            frame = msg.rosbridge_frame(FrameKind::RosbridgeCbor, self.router.transcoder());
        }
        let frame = match frame {
            Ok(f) => f,
            Err(e) => {
                self.outbox.record_drop(slot, DropReason::Encode);
                let wants = self.level.load(std::sync::atomic::Ordering::Relaxed) <= 1;
                if wants && self.warned.insert(msg.topic.name.clone(), ()).is_none() {
                    let text = outbound::status("warning", &e.to_string(), None);
                    if self.sink.feed(WsMessage::text(text)).await.is_err() {
                        return Err(Closed);
                    }
                }
                return Ok(false);
            }
        };
        match (fragment, &frame) {
            (Some(size), WsMessage::Text(t)) if t.len() > size => {
                let fid = format!("{}_{}", msg.topic.name, msg.seq);
                for piece in outbound::fragments(&fid, t.as_str(), size) {
                    if self.sink.feed(WsMessage::text(piece)).await.is_err() {
                        return Err(Closed);
                    }
                }
            }
            _ => {
                if self.sink.feed(frame).await.is_err() {
                    return Err(Closed);
                }
            }
        }
        Ok(true)
    }
}
