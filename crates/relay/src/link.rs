//! The parts of a `fleetlink.v1` link that hub and agent share: turning received frames
//! into topic events ([`LinkIn`]) and writing an outbox onto the link ([`write_link`]).
//!
//! On every link a topic's alias is its id in the *sending* router, so a message's frames
//! ([`Message::link_frames`]) are the same bytes for every link it goes out on. Large
//! messages go out as `CHUNK`s, one chunk per topic per round, so a small message on
//! another topic overtakes a large one that is half sent.

use std::collections::{HashMap, VecDeque};
use std::sync::Arc;
use std::time::{Duration, Instant};

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{ADVERTISE_LATCHED, ADVERTISE_RELIABLE, DEFAULT_CHUNK_SIZE, Frame};
use fleetlink_proto::reassembly::{Reassembler, ReassemblyError};
use fleetlink_proto::{Encoding, Payload, Schema};
use futures_util::{Sink, SinkExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

use crate::message::{Message, TopicMeta};
use crate::names::TopicId;
use crate::outbox::Outbox;

/// Ids of heartbeat `PING`s start here; lower ids are link-estimator probes.
pub const HEARTBEAT_ID_BASE: u64 = 1 << 62;
/// Most bulk bytes one round of a scheduled outbox's writer puts out before it looks at
/// its queue and control frames again (its window usually stops it well before).
const MAX_ROUND_BYTES: usize = 1 << 20;
/// How often an idle writer looks whether an estimator probe is due.
const PROBE_TICK: Duration = Duration::from_millis(50);

/// Largest message reassembled from chunks.
pub const MAX_LINK_MESSAGE: usize = 64 << 20;
/// Largest total of partially received chunked messages on one link.
pub const MAX_LINK_REASSEMBLY: usize = 128 << 20;

/// A topic the peer announced on this link.
#[derive(Debug, Clone)]
pub struct InTopic {
    pub name: String,
    pub schema: Schema,
    pub encoding: Encoding,
    pub latched: bool,
    /// No-drop: sequence numbers are the sender's stream numbering; confirm with
    /// `DELIVERED`.
    pub reliable: bool,
}

/// What a received frame means for the router.
#[derive(Debug)]
pub enum LinkEvent {
    Advertise {
        alias: u32,
        topic: InTopic,
    },
    Unadvertise {
        alias: u32,
        topic: InTopic,
    },
    Message {
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
        /// Its topic was advertised reliable (no-drop): `seq` is the sender's stream
        /// number, to be confirmed with `DELIVERED`.
        reliable: bool,
    },
    /// Every other frame (HELLO, SUBSCRIBE, PING, ACK, SHARE, ...), as decoded: there is
    /// nothing to resolve on the link for them.
    Control(Frame),
    /// Nothing for the router (an unknown frame, a chunk that is not complete).
    None,
}

#[derive(Debug, thiserror::Error)]
pub enum LinkError {
    #[error("message on alias {0} that was never advertised")]
    UnknownAlias(u32),
    #[error(transparent)]
    Reassembly(#[from] ReassemblyError),
}

/// Per-link receive state: the peer's aliases and partially received chunked messages.
pub struct LinkIn {
    aliases: HashMap<u32, InTopic>,
    reassembly: Reassembler,
    /// Whole messages received since the last `ACK` we sent.
    pub unacked: u32,
    /// Payload bytes (message payloads, chunk data) received since the last `ACK`.
    pub unacked_bytes: u64,
}

impl Default for LinkIn {
    fn default() -> Self {
        LinkIn {
            aliases: HashMap::new(),
            reassembly: Reassembler::new(MAX_LINK_MESSAGE, MAX_LINK_REASSEMBLY),
            unacked: 0,
            unacked_bytes: 0,
        }
    }
}

impl LinkIn {
    pub fn topic(&self, alias: u32) -> Option<&InTopic> {
        self.aliases.get(&alias)
    }

    pub fn on_frame(&mut self, frame: Frame) -> Result<LinkEvent, LinkError> {
        Ok(match frame {
            Frame::Advertise {
                alias,
                topic,
                schema,
                encoding,
                flags,
            } => {
                let t = InTopic {
                    name: topic,
                    schema,
                    encoding,
                    latched: flags & ADVERTISE_LATCHED != 0,
                    reliable: flags & ADVERTISE_RELIABLE != 0,
                };
                self.aliases.insert(alias, t.clone());
                LinkEvent::Advertise { alias, topic: t }
            }
            Frame::Unadvertise { alias } => {
                self.reassembly.forget(alias);
                match self.aliases.remove(&alias) {
                    Some(topic) => LinkEvent::Unadvertise { alias, topic },
                    None => LinkEvent::None,
                }
            }
            Frame::Message {
                alias,
                seq,
                stamp_ns,
                payload,
            } => {
                self.unacked += 1;
                self.unacked_bytes += payload.len() as u64;
                let t = self
                    .aliases
                    .get(&alias)
                    .ok_or(LinkError::UnknownAlias(alias))?;
                LinkEvent::Message {
                    alias,
                    seq,
                    stamp_ns,
                    payload: Payload::new(t.encoding, payload),
                    reliable: t.reliable,
                }
            }
            Frame::Chunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            } => {
                self.unacked_bytes += data.len() as u64;
                let t = self
                    .aliases
                    .get(&alias)
                    .ok_or(LinkError::UnknownAlias(alias))?;
                let (encoding, reliable) = (t.encoding, t.reliable);
                match self
                    .reassembly
                    .push(alias, seq, stamp_ns, total_len, offset, &data)?
                {
                    Some(done) => {
                        self.unacked += 1;
                        LinkEvent::Message {
                            alias,
                            seq: done.seq,
                            stamp_ns: done.stamp_ns,
                            payload: Payload::new(encoding, done.payload),
                            reliable,
                        }
                    }
                    None => LinkEvent::None,
                }
            }
            Frame::Unknown { .. } => LinkEvent::None,
            other => LinkEvent::Control(other),
        })
    }
}

/// Maps a router topic to the name it has on this link; `None` keeps it off the link.
pub type LinkNamer = Arc<dyn Fn(&TopicMeta) -> Option<String> + Send + Sync>;

/// Frames written on a link besides messages (replies, subscriptions, status).
#[derive(Debug)]
pub enum Control {
    Frame(Frame),
    /// Frames of one large call body (its `CALL_CHUNK`s, then the frame they belong to):
    /// sent one per writer round, between other traffic, in order.
    Sequence(VecDeque<Frame>),
    /// The topic has had no publisher since `since`: tell the peer (`UNADVERTISE`) once
    /// what was queued for it has been sent. Ignored for a topic never advertised on this
    /// link and for no-drop (reliable) topics, whose streams outlive their publishers;
    /// dropped when a message of the topic received after `since` comes (published
    /// again). A later message of the topic advertises it again.
    Unadvertise {
        topic: TopicId,
        since: Instant,
    },
    /// Close the link (after flushing what is queued).
    Close,
}

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
    waiting: VecDeque<Arc<Message>>,
}

impl Lane {
    fn start(topic: TopicId, msg: Arc<Message>, sized: bool) -> Lane {
        Lane {
            topic,
            cached: (!sized).then(|| msg.link_frames()),
            msg,
            next: 0,
            offset: 0,
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

/// Writes `outbox` and `control` onto the link until either side closes; sends a `PING`
/// every `heartbeat`. `announce_first` topics are advertised before anything else;
/// `gate`, if any, must allow each message's topic for it to be sent.
///
/// Small messages go out as soon as they are taken. A larger one (a payload over the
/// link's chunk size: 16 KiB, or less on a slow uplink) gets a lane and goes out a chunk
/// per round, each chunk only when the outbox allows bulk data now (see
/// [`crate::link_control`]); its topic is held in the scheduler until the lane is done, so
/// the next large message of that topic is chosen by the topic's drop policy when the link
/// can take it.
/// `ADVERTISE` flags of a topic on this link: reliable (the outbox's no-drop streams) and
/// latched (the topic's own).
fn advertise_flags(outbox: &Outbox, meta: &TopicMeta) -> u8 {
    let latched = if meta.latched { ADVERTISE_LATCHED } else { 0 };
    outbox.advertise_flags(meta.id.0) | latched
}

pub async fn write_link<K>(
    mut sink: K,
    outbox: Arc<Outbox>,
    mut control: mpsc::Receiver<Control>,
    heartbeat: Duration,
    namer: LinkNamer,
    announce_first: Vec<(Arc<TopicMeta>, Encoding)>,
    mut gate: Option<Box<dyn crate::gate::Gate>>,
) where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    let mut advertised: HashMap<TopicId, Encoding> = HashMap::new();
    let mut buf = BytesMut::new();
    // Topics the peer should know before any message flows (e.g. after a reconnect).
    for (meta, enc) in announce_first {
        if let Some(name) = namer(&meta) {
            Frame::Advertise {
                alias: meta.id.0,
                topic: name,
                schema: meta.schema.clone(),
                encoding: enc,
                flags: advertise_flags(&outbox, &meta),
            }
            .encode(&mut buf);
            advertised.insert(meta.id, enc);
        }
    }
    let mut lanes: Vec<Lane> = Vec::new();
    // Topics to unadvertise once nothing of theirs is queued or in a lane, with when
    // they were last seen without a publisher.
    let mut unadvertise: Vec<(TopicId, Instant)> = Vec::new();
    // Large call bodies in progress, a frame of each per round.
    let mut sequences: VecDeque<VecDeque<Frame>> = VecDeque::new();
    // Heartbeat ids live far from the link estimator's probe ids (which count from 0).
    let mut ping_id = HEARTBEAT_ID_BASE;
    let mut next_ping = tokio::time::Instant::now() + heartbeat;
    // Small frames are packed into one WebSocket message up to this size.
    const PACK: usize = 64 * 1024;
    // The outbox batch, kept across rounds so a busy writer does not allocate one per round.
    let mut items: Vec<crate::outbox::Taken> = Vec::new();
    loop {
        // 1. Control frames first: they are small and often answers the peer waits for.
        loop {
            match control.try_recv() {
                Ok(Control::Frame(f)) => f.encode(&mut buf),
                Ok(Control::Sequence(s)) => sequences.push_back(s),
                Ok(Control::Unadvertise { topic, since }) => unadvertise.push((topic, since)),
                Ok(Control::Close) | Err(mpsc::error::TryRecvError::Disconnected) => {
                    let _ = flush_buf(&mut sink, &mut buf).await;
                    let _ = sink.close().await;
                    return;
                }
                Err(mpsc::error::TryRecvError::Empty) => break,
            }
        }
        // Echo probes of a scheduled outbox's link estimator also serve as heartbeats.
        if let Some(id) = outbox.poll_probe(Instant::now()) {
            Frame::Ping {
                id,
                sent_ns: crate::unix_nanos(),
            }
            .encode(&mut buf);
            next_ping = tokio::time::Instant::now() + heartbeat;
        } else if tokio::time::Instant::now() >= next_ping {
            ping_id += 1;
            Frame::Ping {
                id: ping_id,
                sent_ns: crate::unix_nanos(),
            }
            .encode(&mut buf);
            next_ping = tokio::time::Instant::now() + heartbeat;
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
                        break 'turns;
                    }
                    let chunk = outbox.chunk_size().unwrap_or(DEFAULT_CHUNK_SIZE);
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
                            let carried = announce(&mut buf, &mut advertised, &m, &namer, &outbox);
                            *lane = Lane {
                                waiting,
                                ..Lane::start(topic, m, sized)
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
        // 3. A batch from the outbox.
        outbox.take_into(&mut items, 512, 4 << 20, Instant::now());
        let took = items.len();
        for (_, _, msg) in items.drain(..) {
            // Checked on delivery, so a rule change reaches live subscriptions.
            if let Some(g) = gate.as_mut()
                && !g.allows(msg.topic.name.as_str(), crate::gate::Op::Subscribe)
            {
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
            if !announce(&mut buf, &mut advertised, &msg, &namer, &outbox) {
                continue;
            }
            // Per message on the hub's fan-out path: these calls read no clock and take no
            // lock unless the outbox is the agent's scheduled uplink.
            let sized = outbox.chunk_size();
            if msg.payload.len() <= sized.unwrap_or(DEFAULT_CHUNK_SIZE) {
                // One MESSAGE frame (payloads up to DEFAULT_CHUNK_SIZE are never chunked).
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
                lanes.push(Lane::start(tid, msg, sized.is_some()));
            }
        }
        // 4. Topics whose publishers are gone, after their last message.
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
            let _ = sink.close().await;
            return;
        }
        let mut wake = next_ping.min(tokio::time::Instant::now() + PROBE_TICK);
        if let Some(Some(at)) = gated {
            wake = wake.min(tokio::time::Instant::from_std(at));
        }
        tokio::select! {
            c = control.recv() => match c {
                Some(Control::Frame(f)) => f.encode(&mut buf),
                Some(Control::Sequence(s)) => sequences.push_back(s),
                Some(Control::Unadvertise { topic, since }) => unadvertise.push((topic, since)),
                Some(Control::Close) | None => {
                    let _ = flush_buf(&mut sink, &mut buf).await;
                    let _ = sink.close().await;
                    return;
                }
            },
            _ = outbox.ready() => {}
            _ = tokio::time::sleep_until(wake) => {}
        }
    }
}

/// Sends `ADVERTISE` for the message's topic the first time (or when its encoding
/// changes). Returns false when the topic is not carried on this link.
fn announce(
    buf: &mut BytesMut,
    advertised: &mut HashMap<TopicId, Encoding>,
    msg: &Message,
    namer: &LinkNamer,
    outbox: &Outbox,
) -> bool {
    let enc = msg.payload.encoding;
    if advertised.get(&msg.topic.id) == Some(&enc) {
        return true;
    }
    let Some(name) = namer(&msg.topic) else {
        return false;
    };
    Frame::Advertise {
        alias: msg.topic.id.0,
        topic: name,
        schema: msg.topic.schema.clone(),
        encoding: enc,
        flags: advertise_flags(outbox, &msg.topic),
    }
    .encode(buf);
    advertised.insert(msg.topic.id, enc);
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

/// Parses every frame of one received WebSocket message.
impl LinkIn {
    /// An `ACK` for what arrived since the last one, if anything did.
    pub fn take_ack(&mut self) -> Option<Frame> {
        let n = std::mem::take(&mut self.unacked);
        let bytes = std::mem::take(&mut self.unacked_bytes);
        (n > 0 || bytes > 0).then_some(Frame::Ack { frames: n, bytes })
    }
}

pub fn decode_all(data: &Bytes) -> Result<Vec<Frame>, fleetlink_proto::DecodeError> {
    fleetlink_proto::frame::frames(data).collect()
}
