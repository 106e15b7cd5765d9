//! The writer of a Foxglove session: the client's outbox as `MessageData`, and the
//! reader's replies.
//!
//! Encode once: a message's payload in its channel's encoding is the bytes it arrived in,
//! or a conversion made once per message and shared by every subscriber
//! ([`Message::payload_in`]). What differs per subscription is 13 bytes (opcode,
//! subscription id, receive time), written in front of the shared payload as one
//! WebSocket message ([`feed_binary_parts`]): a large payload is written from where it
//! lies, never copied per subscriber.
//!
//! A client that negotiated permessage-deflate gets a large payload compressed once for
//! all such subscribers ([`Message::deflated_payload`]); its 13 bytes go in front as a
//! stored deflate block, so the shared compressed bytes need no per-subscriber work.

use std::collections::{HashMap, HashSet};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use fleetlink_proto::Encoding;
use fleetlink_relay::gate::{Gate, retain_allowed};
use fleetlink_relay::outbox::Taken;
use fleetlink_relay::websocket::deflate::stored_block;
use fleetlink_relay::websocket::replies::{close_with, wait_for_work};
use fleetlink_relay::websocket::{PartsSink, feed_binary_parts, feed_deflated};
use fleetlink_relay::{DropReason, Outbox, Router, TopicId};
use futures_util::SinkExt;
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use crate::protocol::{self, Level};

/// What the writer sends for one topic: the channel's encoding and the client's
/// subscription ids on it (shared, so a batch reads them without copying).
#[derive(Debug, Clone)]
pub(crate) struct Delivering {
    pub encoding: Encoding,
    pub subs: Arc<[u32]>,
}

/// The subscriptions as the reader last set them. std Mutex: the reader takes it when a
/// subscription changes, the writer once per batch; neither holds it across an await.
pub(crate) type Deliveries = Arc<Mutex<HashMap<TopicId, Delivering>>>;

pub(crate) use fleetlink_relay::websocket::replies::Reply;

/// Bytes of messages one batch takes at most.
const BATCH_BYTES: usize = 8 << 20;

pub(crate) async fn write_loop<K: PartsSink>(
    mut sink: K,
    outbox: Arc<Outbox>,
    mut replies: mpsc::Receiver<Reply>,
    router: Arc<Router>,
    batch: usize,
    mut gate: Option<Box<dyn Gate>>,
    deliveries: Deliveries,
) {
    let mut items: Vec<Taken> = Vec::new();
    let mut sends: Vec<(Taken, Delivering)> = Vec::new();
    // Topics whose messages could not be given in their channel's encoding: the client
    // hears it once per topic, each message is counted as dropped.
    let mut warned: HashSet<TopicId> = HashSet::new();
    // Negotiated at the handshake; a client without it costs one check per message.
    let deflate = sink.deflate();
    let mut stored = bytes::BytesMut::new();
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
        let wake_at = outbox.take_into(&mut items, batch, BATCH_BYTES, Instant::now());
        let took = items.len();
        retain_allowed(gate.as_deref_mut(), &mut items);
        {
            let d = deliveries.lock().unwrap_or_else(|p| p.into_inner());
            sends.extend(
                items
                    .drain(..)
                    .filter_map(|t| d.get(&t.2.topic.id).cloned().map(|to| (t, to))),
            );
        }
        for ((slot, _, msg), to) in sends.drain(..) {
            let payload = match msg.payload_in(to.encoding, router.transcoder()) {
                Ok(p) => p,
                Err(e) => {
                    outbox.record_drop(slot, DropReason::Encode);
                    if warned.insert(msg.topic.id) {
                        let text = format!(
                            "{}: a message cannot be sent as {}: {e}",
                            msg.topic.name,
                            crate::channels::wire_name(to.encoding)
                        );
                        if sink
                            .feed(WsMessage::text(protocol::status(Level::Warning, &text)))
                            .await
                            .is_err()
                        {
                            return;
                        }
                    }
                    continue;
                }
            };
            let deflated = match deflate {
                Some(cfg) => msg
                    .deflated_payload(to.encoding, router.transcoder(), cfg)
                    .ok()
                    .flatten(),
                None => None,
            };
            for sub in to.subs.iter() {
                let head = protocol::message_data_header(*sub, msg.received_unix_ns());
                let sent = match &deflated {
                    Some(z) => {
                        stored.clear();
                        stored_block(&mut stored, &head);
                        feed_deflated(&mut sink, false, &stored, z).await
                    }
                    None => feed_binary_parts(&mut sink, &head, &payload).await,
                };
                if sent.is_err() {
                    return;
                }
            }
            wrote = true;
        }
        if wrote && sink.flush().await.is_err() {
            return;
        }
        if took > 0 {
            continue;
        }
        if !wait_for_work(&mut sink, &mut replies, &outbox, wake_at).await {
            return;
        }
    }
}
