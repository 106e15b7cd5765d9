//! The writer of a `fleetlink.v1` link: an outbox and the session's frames onto the
//! socket, large messages cut into chunks that take turns, within the window a scheduled
//! outbox allows.

use std::collections::{HashMap, VecDeque};
use std::sync::Arc;
use std::sync::atomic::AtomicU64;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Instant;

use bytes::{Bytes, BytesMut};
use fleetlink_proto::Encoding;
use fleetlink_proto::frame::{ADVERTISE_LATCHED, ADVERTISE_RELIABLE, DEFAULT_CHUNK_SIZE, Frame};
use futures_util::{Sink, SinkExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

use super::compress::Compressor;
use super::{Control, ControlReceiver, LinkNamer};
use crate::message::{Message, TopicMeta, Via};
use crate::names::TopicId;
use crate::outbox::Outbox;

/// Most bulk bytes one round of a scheduled outbox's writer puts out before it looks at
/// its queue and control frames again (its window usually stops it well before).
const MAX_ROUND_BYTES: usize = 1 << 20;
/// Payloads up to this size are framed straight into each link's pack instead of through
/// the message's shared frames ([`Message::link_frames`]).
const ENCODE_IN_PLACE: usize = 1024;
/// How long a writer whose outbox was closed waits for its owner's close frame.
const CLOSE_REASON_WAIT: std::time::Duration = std::time::Duration::from_millis(500);

/// A large message being sent one chunk per round, and messages of the same topic
/// waiting behind it.
struct Lane {
    topic: TopicId,
    msg: Arc<Message>,
    /// The message's cached frames, on links whose outbox does not size chunks (the
    /// hub's: the same frames serve every link), and the next one to send.
    cached: Option<Arc<[Bytes]>>,
    next: usize,
    /// Payload bytes sent so far, when chunks are cut for this link as they go.
    offset: usize,
    /// The payload is a compression envelope: its pieces go out as `ZCHUNK`s.
    compressed: bool,
    waiting: VecDeque<Arc<Message>>,
}

impl Lane {
    fn start(topic: TopicId, msg: Arc<Message>, sized: bool, compressed: bool) -> Lane {
        Lane {
            topic,
            cached: (!sized).then(|| msg.link_frames()),
            msg,
            next: 0,
            offset: 0,
            compressed,
            waiting: VecDeque::new(),
        }
    }

    /// Marks the message as sent without sending it (its topic is not carried here).
    fn skip(&mut self) {
        self.next = usize::MAX / 2;
        self.offset = self.msg.payload.len();
    }

    fn is_done(&self) -> bool {
        match &self.cached {
            Some(frames) => self.next >= frames.len(),
            None => self.offset >= self.msg.payload.len() && self.next > 0,
        }
    }

    /// The next frame and the payload bytes it carries (what the peer's `ACK.bytes`
    /// counts). `chunk` is the link's chunk size now, for a lane that cuts its own.
    fn next_frame(&mut self, chunk: usize) -> (Bytes, usize) {
        let total = self.msg.payload.len();
        if let Some(frames) = &self.cached {
            let i = self.next;
            self.next += 1;
            let n = if frames.len() == 1 {
                total
            } else {
                total
                    .saturating_sub(i * DEFAULT_CHUNK_SIZE)
                    .min(DEFAULT_CHUNK_SIZE)
            };
            return (frames[i].clone(), n);
        }
        self.next += 1;
        let m = &self.msg;
        let end = (self.offset + chunk.max(1)).min(total);
        let data = &m.payload.bytes[self.offset..end];
        let mut b = BytesMut::with_capacity(data.len() + 40);
        fleetlink_proto::frame::encode_chunk(
            &mut b,
            self.compressed,
            m.topic.id.0,
            m.seq,
            m.stamp_ns,
            total as u64,
            self.offset as u64,
            data,
        );
        self.offset = end;
        (b.freeze(), data.len())
    }
}

/// `ADVERTISE` flags of a topic on this link: reliable (the outbox's no-drop streams) and
/// latched (the topic's own).
fn advertise_flags(outbox: &Outbox, meta: &TopicMeta) -> u8 {
    let latched = if meta.latched { ADVERTISE_LATCHED } else { 0 };
    outbox.advertise_flags(meta.id.0) | latched
}

/// Writes `outbox` and `control` (the session's frames) onto the link until either side
/// closes. `announce_first` topics are advertised before anything else; `gate`, if any,
/// must allow each message's topic for it to be sent. A scheduled outbox's estimator
/// probes (`PING`s below [`super::HEARTBEAT_ID_BASE`]) go out from here; the heartbeat is
/// the session's.
///
/// Small messages go out as soon as they are taken. A larger one (a payload over the
/// link's chunk size: 16 KiB, or less on a slow uplink) gets a lane and goes out a chunk
/// per round, each chunk only when the outbox allows bulk data now (see
/// [`crate::link_control`]); its topic is held in the scheduler until the lane is done, so
/// the next large message of that topic is chosen by the topic's drop policy when the link
/// can take it.
pub async fn write_link<K>(
    mut sink: K,
    outbox: Arc<Outbox>,
    mut control: ControlReceiver,
    namer: LinkNamer,
    announce_first: Vec<(Arc<TopicMeta>, Encoding)>,
    mut gate: Option<Box<dyn crate::gate::Gate>>,
    via: Option<ViaOut>,
) where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    let mut via = ViaMark {
        out: via,
        written: None,
    };
    let mut advertised: HashMap<TopicId, Encoding> = HashMap::new();
    let mut buf = BytesMut::new();
    // Topics the peer should know before any message flows (e.g. after a reconnect).
    for (meta, enc) in announce_first {
        announce_before_messages(
            &mut buf,
            &mut advertised,
            &mut gate,
            &meta,
            enc,
            &namer,
            &outbox,
            &mut via,
        );
    }
    let mut lanes: Vec<Lane> = Vec::new();
    // Each topic's compression on this link, looked up on its first message.
    let mut compressors: HashMap<TopicId, Option<Compressor>> = HashMap::new();
    // Topics to unadvertise once nothing of theirs is queued or in a lane, with when
    // they were last seen without a publisher.
    let mut unadvertise: Vec<(TopicId, Instant)> = Vec::new();
    // Large call bodies in progress, a frame of each per round.
    let mut sequences: VecDeque<VecDeque<Frame>> = VecDeque::new();
    // Small frames are packed into one WebSocket message up to this size.
    const PACK: usize = 64 * 1024;
    // The outbox batch, kept across rounds so a busy writer does not allocate one per round.
    let mut items: Vec<crate::outbox::Taken> = Vec::new();
    let mut held: Vec<Arc<crate::Message>> = Vec::new();
    // What the wait at the end of a round received from `control` (`Some(None)`: closed),
    // handled first in the next round like everything else `control` holds.
    let mut received: Option<Option<Control>> = None;
    // The wait for the outbox, made once and kept across rounds (made again after it
    // fires): a fresh one each round joined and left the outbox's waiters, under their
    // lock, at every heartbeat of every idle link.
    let mut ready = std::pin::pin!(outbox.ready());
    loop {
        // 1. Control frames first: they are small and often answers the peer waits for.
        loop {
            let c = match received.take() {
                Some(c) => c,
                None => match control.try_recv() {
                    Ok(c) => Some(*c),
                    Err(mpsc::error::TryRecvError::Disconnected) => None,
                    Err(mpsc::error::TryRecvError::Empty) => break,
                },
            };
            match c {
                Some(Control::Frame(f)) => f.encode(&mut buf),
                Some(Control::Sequence(s)) => sequences.push_back(s),
                Some(Control::Unadvertise { topic, since }) => unadvertise.push((topic, since)),
                Some(Control::Announce { meta, encoding }) => {
                    announce_before_messages(
                        &mut buf,
                        &mut advertised,
                        &mut gate,
                        &meta,
                        encoding,
                        &namer,
                        &outbox,
                        &mut via,
                    );
                }
                Some(Control::Pong(p)) => {
                    if pong(&mut sink, &mut buf, p).await.is_err() {
                        return;
                    }
                }
                Some(Control::Close(frame)) => return finish(&mut sink, &mut buf, frame).await,
                None => return finish(&mut sink, &mut buf, None).await,
            }
        }
        // Echo probes of a scheduled outbox's link estimator.
        if let Some(id) = outbox.poll_probe(Instant::now()) {
            Frame::Ping {
                id,
                sent_ns: crate::unix_nanos(),
            }
            .encode(&mut buf);
        }
        // Then a frame of every large call body in progress.
        for seq in sequences.iter_mut() {
            if let Some(f) = seq.pop_front() {
                f.encode(&mut buf);
            }
        }
        sequences.retain(|s| !s.is_empty());
        // 2. Chunks from the lanes in progress, a chunk from each in turn, while the
        // link's window allows. A plain outbox's lanes take one turn per round, so small
        // messages queued meanwhile go out between chunks. A scheduled outbox's window
        // already bounds what a round may write (about `QUEUE_TARGET` of link time), so
        // its lanes take turns until the window is full and the round ends in one flush:
        // a fast link is not driven one chunk per system call.
        let mut gated: Option<Option<Instant>> = None;
        let mut round_bytes = 0usize;
        'turns: loop {
            let mut wrote = false;
            let mut i = 0;
            while i < lanes.len() {
                if flush_if_full(&mut sink, &mut buf, PACK).await.is_err() {
                    return;
                }
                let lane = &mut lanes[i];
                if !lane.is_done() {
                    let now = Instant::now();
                    if let Err(wake) = outbox.bulk_check(now) {
                        gated = Some(wake);
                        // The next round resumes the turns here: the lanes before this one
                        // had theirs, so a gate after every chunk (a capacity share, a
                        // small window) still gives each lane a chunk in turn rather than
                        // the first lane all of them.
                        lanes.rotate_left(i);
                        break 'turns;
                    }
                    let chunk = outbox.chunk_size().unwrap_or(DEFAULT_CHUNK_SIZE);
                    via.mark(&mut buf, &lane.msg);
                    let (f, n) = lane.next_frame(chunk);
                    if send_large(&mut sink, &mut buf, &f, PACK).await.is_err() {
                        return;
                    }
                    outbox.on_written(n);
                    round_bytes += f.len();
                    wrote = true;
                }
                if lane.is_done() {
                    // Done: start the next waiting message of the same topic, if any.
                    match lane.waiting.pop_front() {
                        Some(m) => {
                            let (topic, sized) = (lane.topic, lane.cached.is_none());
                            let waiting = std::mem::take(&mut lane.waiting);
                            let carried =
                                announce(&mut buf, &mut advertised, &m, &namer, &outbox, &mut via);
                            let (m, compressed) = if carried {
                                for_link(&mut compressors, &outbox, m)
                            } else {
                                (m, false)
                            };
                            *lane = Lane {
                                waiting,
                                ..Lane::start(topic, m, sized, compressed)
                            };
                            if !carried {
                                lane.skip();
                            }
                        }
                        None => {
                            outbox.hold(lane.topic.0, false, Instant::now());
                            lanes.swap_remove(i);
                            continue;
                        }
                    }
                }
                i += 1;
            }
            if !wrote || !outbox.is_scheduled() || round_bytes >= MAX_ROUND_BYTES {
                break;
            }
        }
        // 3. Topics a demand-driven uplink holds back are announced all the same, so the
        // peer can ask for them.
        outbox.take_unannounced(&mut held);
        for msg in held.drain(..) {
            if may_see(&mut gate, &msg.topic) {
                announce(&mut buf, &mut advertised, &msg, &namer, &outbox, &mut via);
            }
        }
        // 4. A batch from the outbox.
        // When it takes nothing, the time its data budget next lets something go.
        let budget_wake = outbox.take_into(&mut items, 512, 4 << 20, Instant::now());
        let took = items.len();
        for (_, _, msg) in items.drain(..) {
            // Checked on delivery, so a rule change reaches live subscriptions.
            if let Some(g) = gate.as_mut()
                && !g.allows_topic(
                    msg.topic.id.0,
                    msg.topic.name.as_str(),
                    crate::gate::Op::Subscribe,
                )
            {
                continue;
            }
            if !via.sends(&msg) {
                continue;
            }
            let tid = msg.topic.id;
            if !unadvertise.is_empty() {
                // Published again since it was seen without a publisher: keep it.
                unadvertise.retain(|(t, since)| *t != tid || msg.received() <= *since);
            }
            if let Some(lane) = lanes.iter_mut().find(|l| l.topic == tid) {
                lane.waiting.push_back(msg);
                continue;
            }
            if !announce(&mut buf, &mut advertised, &msg, &namer, &outbox, &mut via) {
                continue;
            }
            // Per message on the hub's fan-out path: these calls read no clock and take no
            // lock unless the outbox is the agent's scheduled uplink.
            let (msg, compressed) = for_link(&mut compressors, &outbox, msg);
            via.mark(&mut buf, &msg);
            let sized = outbox.chunk_size();
            let whole = sized.unwrap_or(DEFAULT_CHUNK_SIZE);
            if compressed && msg.payload.len() <= whole {
                // The agent's link is the only one a compressed message goes out on:
                // framed in place, never through the shared frames.
                let p = &msg.payload.bytes;
                fleetlink_proto::frame::encode_message_kind(
                    &mut buf,
                    true,
                    tid.0,
                    msg.seq,
                    msg.stamp_ns,
                    p,
                );
                if flush_if_full(&mut sink, &mut buf, PACK).await.is_err() {
                    return;
                }
                outbox.on_written(p.len());
            } else if msg.payload.len() <= ENCODE_IN_PLACE.min(whole) {
                // A small message's MESSAGE frame is written straight into the pack: a
                // few dozen bytes copied per link cost less than building a frame to
                // share (the payload's bytes are copied as they are, never re-encoded).
                let p = &msg.payload.bytes;
                fleetlink_proto::frame::encode_message(&mut buf, tid.0, msg.seq, msg.stamp_ns, p);
                if flush_if_full(&mut sink, &mut buf, PACK).await.is_err() {
                    return;
                }
                outbox.on_written(p.len());
            } else if msg.payload.len() <= whole {
                // One MESSAGE frame (payloads up to DEFAULT_CHUNK_SIZE are never chunked),
                // built once and shared by every link it goes out on.
                let frames = msg.link_frames();
                if send_large(&mut sink, &mut buf, &frames[0], PACK)
                    .await
                    .is_err()
                {
                    return;
                }
                outbox.on_written(msg.payload.len());
            } else {
                outbox.hold(tid.0, true, Instant::now());
                lanes.push(Lane::start(tid, msg, sized.is_some(), compressed));
            }
        }
        // 5. Topics whose publishers are gone, after their last message.
        if !unadvertise.is_empty() {
            unadvertise.retain(|(t, _)| {
                if !advertised.contains_key(t)
                    || outbox.advertise_flags(t.0) & ADVERTISE_RELIABLE != 0
                {
                    return false; // never announced here, or a no-drop stream
                }
                if lanes.iter().any(|l| l.topic == *t) || outbox.queued_for(t.0) > 0 {
                    return true; // its messages first
                }
                Frame::Unadvertise { alias: t.0 }.encode(&mut buf);
                advertised.remove(t);
                // Published again later, a held-back topic is announced again.
                outbox.forget_announced(t.0);
                false
            });
        }
        if flush_buf(&mut sink, &mut buf).await.is_err() || sink.flush().await.is_err() {
            return;
        }
        if took > 0 || !sequences.is_empty() || (!lanes.is_empty() && gated.is_none()) {
            continue;
        }
        if outbox.is_closed() {
            // The router let the client go; its owner ends the link with its reason
            // (`Control::Close`) right after. Wait a moment for it, so the peer learns the
            // close code (1007, 1001, ...) instead of a bare close.
            let until = tokio::time::Instant::now() + CLOSE_REASON_WAIT;
            while let Ok(Some(c)) = tokio::time::timeout_at(until, control.recv()).await {
                match *c {
                    Control::Close(frame) => return finish(&mut sink, &mut buf, frame).await,
                    Control::Frame(f) => f.encode(&mut buf),
                    _ => {}
                }
            }
            return finish(&mut sink, &mut buf, None).await;
        }
        // A scheduled outbox wakes when its next probe is due (none while its link is idle:
        // new data wakes it); a plain one (the hub's) sleeps until there is something to
        // write.
        let mut wake: Option<tokio::time::Instant> = None;
        for at in [outbox.probe_timeout(), gated.flatten(), budget_wake]
            .into_iter()
            .flatten()
        {
            let at = tokio::time::Instant::from_std(at);
            wake = Some(wake.map_or(at, |w| w.min(at)));
        }
        tokio::select! {
            c = control.recv() => received = Some(c.map(|c| *c)),
            _ = ready.as_mut() => ready.set(outbox.ready()),
            _ = sleep_until(wake) => {}
        }
    }
}

/// How a link between hubs marks its messages with the hubs they passed (`VIA`, docs/
/// protocol.md §1.8d): a site hub's uplink, and a hub's end of a link whose peer turned
/// out to be a hub.
pub struct ViaOut {
    /// This hub, the last one in every `VIA` it writes.
    pub me: u64,
    /// The peer hub, once its own `VIA` said which it is (0: not known).
    pub peer: Arc<AtomicU64>,
    /// Mark messages even before the peer is known to be a hub (an uplink's peer is one).
    pub always: bool,
}

/// The `VIA` state of one connection's writer.
struct ViaMark {
    out: Option<ViaOut>,
    /// The hubs before this one in the last `VIA` written, if one was.
    written: Option<Option<Arc<Via>>>,
}

impl ViaMark {
    /// Whether `msg` goes on this link: not to a hub it has passed, nor past the longest
    /// chain a `VIA` may name.
    fn sends(&self, msg: &Message) -> bool {
        let (Some(out), Some(v)) = (&self.out, msg.via()) else {
            return true;
        };
        let peer = out.peer.load(Relaxed);
        !(peer != 0 && v.contains(peer)) && v.hubs().len() < fleetlink_proto::frame::MAX_VIA
    }

    /// Writes a `VIA` before `msg` when this link marks messages and the last one written
    /// named other hubs.
    fn mark(&mut self, buf: &mut BytesMut, msg: &Message) {
        self.mark_path(buf, msg.via());
    }

    /// Writes a `VIA` for what comes by way of `via` (a message, or a topic announced).
    fn mark_path(&mut self, buf: &mut BytesMut, via: Option<&Arc<Via>>) {
        let Some(out) = &self.out else {
            return;
        };
        if !out.always && out.peer.load(Relaxed) == 0 {
            return;
        }
        if let Some(last) = &self.written {
            let same = match (last, via) {
                (None, None) => true,
                (Some(a), Some(b)) => Arc::ptr_eq(a, b) || a == b,
                _ => false,
            };
            if same {
                return;
            }
        }
        let mut hubs = via.map_or_else(Vec::new, |v| v.hubs().to_vec());
        hubs.push(out.me);
        Frame::Via { hubs }.encode(buf);
        self.written = Some(via.cloned());
    }
}

/// The message as it goes on this link, and whether it is compressed: the agent's
/// uplink compresses where the topic's `compression` says so and it pays; a plain
/// outbox's (the hub's) messages go as they are, without a lookup.
fn for_link(
    compressors: &mut HashMap<TopicId, Option<Compressor>>,
    outbox: &Outbox,
    msg: Arc<Message>,
) -> (Arc<Message>, bool) {
    if !outbox.is_scheduled() {
        return (msg, false);
    }
    let c = compressors
        .entry(msg.topic.id)
        .or_insert_with(|| outbox.compression(msg.topic.id.0).and_then(Compressor::new));
    match c
        .as_mut()
        .and_then(|c| c.apply(&msg.payload.bytes, Instant::now()))
    {
        Some(envelope) => {
            // The data budget counted the message at its full size.
            outbox.on_compressed(msg.payload.len(), envelope.len());
            (Arc::new(msg.with_link_bytes(envelope)), true)
        }
        None => (msg, false),
    }
}

/// Sleeps until `at`, or forever.
async fn sleep_until(at: Option<tokio::time::Instant>) {
    match at {
        Some(at) => tokio::time::sleep_until(at).await,
        None => std::future::pending().await,
    }
}

/// Sends a WebSocket pong after what is packed.
async fn pong<K>(sink: &mut K, buf: &mut BytesMut, payload: Bytes) -> Result<(), WsError>
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    flush_buf(sink, buf).await?;
    sink.feed(WsMessage::Pong(payload)).await
}

/// Flushes what is packed, then closes the WebSocket (with `frame`, if any).
async fn finish<K>(sink: &mut K, buf: &mut BytesMut, frame: Option<CloseFrame>)
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    if flush_buf(sink, buf).await.is_err() {
        return;
    }
    if frame.is_some() {
        let _ = sink.send(WsMessage::Close(frame)).await;
    }
    let _ = sink.close().await;
}

/// Sends `ADVERTISE` for the message's topic the first time (or when its encoding
/// changes). Returns false when the topic is not carried on this link.
fn announce(
    buf: &mut BytesMut,
    advertised: &mut HashMap<TopicId, Encoding>,
    msg: &Message,
    namer: &LinkNamer,
    outbox: &Outbox,
    via: &mut ViaMark,
) -> bool {
    let enc = msg.payload.encoding;
    if advertised.get(&msg.topic.id) == Some(&enc) {
        return true;
    }
    announce_topic(buf, advertised, &msg.topic, enc, namer, outbox, via)
}

/// Whether the link's gate (if any) lets the peer see `meta`'s topic: topics are announced
/// without a message only to a peer that may receive them.
fn may_see(gate: &mut Option<Box<dyn crate::gate::Gate>>, meta: &TopicMeta) -> bool {
    gate.as_mut()
        .is_none_or(|g| g.allows_topic(meta.id.0, meta.name.as_str(), crate::gate::Op::Subscribe))
}

/// Announces `meta` before any message of it goes (a reconnect's topics, a site hub's
/// new ones): once per link, and only to a peer the gate lets receive it.
#[allow(clippy::too_many_arguments)]
fn announce_before_messages(
    buf: &mut BytesMut,
    advertised: &mut HashMap<TopicId, Encoding>,
    gate: &mut Option<Box<dyn crate::gate::Gate>>,
    meta: &TopicMeta,
    enc: Encoding,
    namer: &LinkNamer,
    outbox: &Outbox,
    via: &mut ViaMark,
) {
    if !advertised.contains_key(&meta.id) && may_see(gate, meta) {
        announce_topic(buf, advertised, meta, enc, namer, outbox, via);
    }
}

/// Writes `ADVERTISE` of `meta` in `enc` (and notes it announced); false if the topic
/// has no name on this link.
fn announce_topic(
    buf: &mut BytesMut,
    advertised: &mut HashMap<TopicId, Encoding>,
    meta: &TopicMeta,
    enc: Encoding,
    namer: &LinkNamer,
    outbox: &Outbox,
    via: &mut ViaMark,
) -> bool {
    let Some(name) = namer(meta) else {
        return false;
    };
    // Between hubs, a topic is announced with the hubs its publisher is behind.
    via.mark_path(buf, meta.via.as_ref());
    Frame::Advertise {
        alias: meta.id.0,
        topic: name,
        schema: meta.schema.clone(),
        encoding: enc,
        flags: advertise_flags(outbox, meta),
    }
    .encode(buf);
    advertised.insert(meta.id, enc);
    true
}

/// Appends a small frame to the pack buffer, or sends a large one as its own message
/// (after what is packed, to keep order). The large frame's bytes are shared, not copied.
async fn send_large<K>(
    sink: &mut K,
    buf: &mut BytesMut,
    frame: &Bytes,
    pack: usize,
) -> Result<(), WsError>
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    if frame.len() < pack / 4 {
        buf.extend_from_slice(frame);
        return flush_if_full(sink, buf, pack).await;
    }
    flush_buf(sink, buf).await?;
    sink.feed(WsMessage::Binary(frame.clone())).await
}

async fn flush_if_full<K>(sink: &mut K, buf: &mut BytesMut, pack: usize) -> Result<(), WsError>
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    if buf.len() >= pack {
        flush_buf(sink, buf).await
    } else {
        Ok(())
    }
}

async fn flush_buf<K>(sink: &mut K, buf: &mut BytesMut) -> Result<(), WsError>
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    if buf.is_empty() {
        return Ok(());
    }
    let b = buf.split().freeze();
    sink.feed(WsMessage::Binary(b)).await
}
