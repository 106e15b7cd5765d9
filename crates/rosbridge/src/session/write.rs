//! The session's writer, a task of its own: the client's outbox and the reader's replies
//! onto the socket, flushed once per burst. Apart because it shares nothing with the
//! reader but the reply channel, its copy of the gate and the `status` level.

use fleetlink_relay::gate::retain_allowed;
use fleetlink_relay::outbox::Taken;

use super::*;

/// Messages taken in one go that mean a burst is being read (`write_loop`).
const BURST: usize = 32;

/// Turns a writer gives the reader of a burst before it flushes (`write_loop`): each is
/// at most one tokio budget (128 operations) read, so a burst of up to about 500 small
/// messages goes out in one write, and nothing waits longer than four budgets' work.
const BURST_TURNS: u32 = 4;

pub(super) async fn write_loop<K: PartsSink>(
    mut sink: K,
    outbox: Arc<Outbox>,
    mut replies: mpsc::Receiver<Reply>,
    router: Arc<Router>,
    batch: usize,
    gate: Arc<Mutex<Option<Box<dyn Gate>>>>,
    level: Arc<std::sync::atomic::AtomicU8>,
) {
    let mut warned: HashMap<TopicName, ()> = HashMap::new();
    // Negotiated at the handshake; a client without it costs this one check per message.
    let deflate = sink.deflate();
    // Frames written since the last flush, and the turns this task has given the others
    // since (see below).
    let (mut unflushed, mut turns) = (false, 0u32);
    // The batch, kept across rounds so a busy writer does not allocate one per round.
    let mut items: Vec<fleetlink_relay::outbox::Taken> = Vec::new();
    loop {
        let mut wrote = false;
        while let Ok(r) = replies.try_recv() {
            match r {
                Reply::Frame(m) => {
                    if sink.feed(m).await.is_err() {
                        return;
                    }
                    wrote = true;
                }
                Reply::Close(c) => return close_with(&mut sink, c).await,
            }
        }
        let now = Instant::now();
        let wake_at = outbox.take_into(&mut items, batch, 8 << 20, now);
        let took = items.len();
        keep_allowed(&gate, &mut items);
        for (slot, delivery, msg) in items.drain(..) {
            let kind = frame_kind(delivery.compression);
            let fragment = delivery
                .fragment_size
                .map(|s| s as usize)
                .filter(|s| *s > 0);
            // A client that negotiated permessage-deflate gets a large message compressed:
            // once per message and kind, the same bytes for every such subscriber. The
            // rest (small, not worth it, or cut in rosbridge fragments) goes as below.
            if let Some(cfg) = deflate
                && fragment.is_none()
                && let Ok(Some((text, z))) = msg.deflated_frame(kind, router.transcoder(), cfg)
            {
                if fleetlink_relay::websocket::feed_deflated(&mut sink, text, &[], &z)
                    .await
                    .is_err()
                {
                    return;
                }
                wrote = true;
                continue;
            }
            // Most messages: JSON text as its publisher sent it, framed into the socket
            // buffer; or a frame already built, sent whole. A large message is framed
            // once for all its subscribers instead (below), and each writes that frame
            // from where it lies.
            if fragment.is_none()
                && kind == FrameKind::RosbridgeJson
                && let Some(parts) = msg.json_parts()
                && msg.payload.len() <= fleetlink_relay::websocket::COPY_UP_TO
            {
                if fleetlink_relay::websocket::feed_parts(&mut sink, &parts)
                    .await
                    .is_err()
                {
                    return;
                }
                wrote = true;
                continue;
            }
            let msg = match fragment {
                None => match Message::take_built_frame(msg, kind) {
                    Ok(frame) => {
                        if sink.feed(frame).await.is_err() {
                            return;
                        }
                        wrote = true;
                        continue;
                    }
                    Err(msg) => msg,
                },
                Some(_) => msg,
            };
            let mut frame = msg.rosbridge_frame(kind, router.transcoder());
            if frame.is_err() && kind == FrameKind::RosbridgeCborRaw {
                // No raw serialization for this message: the CBOR form is the closest.
                frame = msg.rosbridge_frame(FrameKind::RosbridgeCbor, router.transcoder());
            }
            let frame = match frame {
                Ok(f) => f,
                Err(e) => {
                    outbox.record_drop(slot, DropReason::Encode);
                    if let Some(warning) = encode_warning(&level, &mut warned, &msg, &e)
                        && sink.feed(warning).await.is_err()
                    {
                        return;
                    }
                    continue;
                }
            };
            match (fragment, &frame) {
                (Some(size), WsMessage::Text(t)) if t.len() > size => {
                    let fid = format!("{}_{}", msg.topic.name, msg.seq);
                    for piece in outbound::fragments(&fid, t.as_str(), size) {
                        if sink.feed(WsMessage::text(piece)).await.is_err() {
                            return;
                        }
                    }
                }
                _ => {
                    if sink.feed(frame).await.is_err() {
                        return;
                    }
                }
            }
            wrote = true;
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
            if sink.flush().await.is_err() {
                return;
            }
            (unflushed, turns) = (false, 0);
        }
        if took > 0 {
            continue;
        }
        if !wait_for_work(&mut sink, &mut replies, &outbox, wake_at).await {
            return;
        }
    }
}

/// The client's gate applied to a batch at take time (see [`retain_allowed`]).
fn keep_allowed(gate: &Mutex<Option<Box<dyn Gate>>>, items: &mut Vec<Taken>) {
    let mut g = gate.lock().unwrap_or_else(|p| p.into_inner());
    retain_allowed(g.as_deref_mut(), items);
}

/// The frame kind a subscription's `compression` asks for.
fn frame_kind(compression: Compression) -> FrameKind {
    match compression {
        Compression::Cbor => FrameKind::RosbridgeCbor,
        Compression::CborRaw => FrameKind::RosbridgeCborRaw,
        Compression::Png => FrameKind::RosbridgePng,
        Compression::None => FrameKind::RosbridgeJson,
    }
}

/// The `status` warning for a message that could not be encoded for this client: once
/// per topic, and only if the client's level asks for warnings.
fn encode_warning(
    level: &std::sync::atomic::AtomicU8,
    warned: &mut HashMap<TopicName, ()>,
    msg: &Message,
    e: &impl std::fmt::Display,
) -> Option<WsMessage> {
    let wants = level.load(std::sync::atomic::Ordering::Relaxed) <= 1;
    if wants && warned.insert(msg.topic.name.clone(), ()).is_none() {
        let text = outbound::status("warning", &e.to_string(), None);
        return Some(WsMessage::text(text));
    }
    None
}
