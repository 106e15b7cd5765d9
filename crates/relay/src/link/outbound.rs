//! The outbound half of a `fleetlink.v1` link, without I/O: what goes on the link next
//! — the session's control frames, an outbox's messages, large messages cut into chunks
//! that take turns within the window a scheduled outbox allows, topics announced and
//! unannounced, `VIA` marks between hubs, compression on the agent's uplink — as
//! WebSocket messages to write ([`Transmit`]). The link's writer task
//! ([`super::write_link`]) only writes them and waits; tests drive an [`Outbound`] by
//! hand.

use std::collections::{HashMap, VecDeque};
use std::sync::Arc;
use std::sync::atomic::AtomicU64;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Instant;

use bytes::{Bytes, BytesMut};
use fleetlink_proto::Encoding;
use fleetlink_proto::frame::{ADVERTISE_LATCHED, ADVERTISE_RELIABLE, DEFAULT_CHUNK_SIZE, Frame};
use tokio_tungstenite::tungstenite::protocol::CloseFrame;

use super::compress::Compressor;
use super::{Control, LinkNamer};
use crate::gate::Gate;
use crate::message::{Message, TopicMeta, Via};
use crate::names::TopicId;
use crate::outbox::{Outbox, Taken};

/// Most bulk bytes one round of a scheduled outbox's writer puts out before it looks at
/// its queue and control frames again (its window usually stops it well before).
const MAX_ROUND_BYTES: usize = 1 << 20;
/// Payloads up to this size are framed straight into each link's pack instead of through
/// the message's shared frames ([`Message::link_frames`]).
const ENCODE_IN_PLACE: usize = 1024;
/// Small frames are packed into one WebSocket message up to this size.
const PACK: usize = 64 * 1024;

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

/// What the link's writer puts on the socket next, in order.
#[derive(Debug)]
pub enum Transmit {
    /// One WebSocket binary message: small frames packed together, or one large frame
    /// (its bytes shared with every link it goes out on, not copied).
    Binary(Bytes),
    /// A WebSocket pong answering the peer's ping.
    Pong(Bytes),
    /// Close the WebSocket, with this close frame if any: the last thing written.
    Close(Option<CloseFrame>),
}

/// What a round left: whether another should follow at once (more is ready), else when
/// the outbox next wants one without being woken (a probe due, a window or budget that
/// opens; `None`: only new data, an acknowledgement or a control frame).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Round {
    pub again: bool,
    pub wake: Option<Instant>,
}

/// One link's outbound state: its outbox and what the session hands it ([`Control`]), in,
/// WebSocket messages ([`Transmit`]), out.
///
/// Small messages go out as soon as they are taken. A larger one (a payload over the
/// link's chunk size: 16 KiB, or less on a slow uplink) gets a lane and goes out a chunk
/// per round, each chunk only when the outbox allows bulk data now (see
/// [`crate::link_control`]); its topic is held in the scheduler until the lane is done, so
/// the next large message of that topic is chosen by the topic's drop policy when the link
/// can take it. A scheduled outbox's estimator probes (`PING`s below
/// [`super::HEARTBEAT_ID_BASE`]) go out from here; the heartbeat is the session's.
pub struct Outbound {
    outbox: Arc<Outbox>,
    /// Must allow each message's topic for it to be sent, checked on delivery so a rule
    /// change reaches live subscriptions.
    gate: Option<Box<dyn Gate>>,
    topics: Announcer,
    lanes: Vec<Lane>,
    /// Each topic's compression on this link, looked up on its first message.
    compressors: HashMap<TopicId, Option<Compressor>>,
    /// Topics to unadvertise once nothing of theirs is queued or in a lane, with when
    /// they were last seen without a publisher.
    unadvertise: Vec<(TopicId, Instant)>,
    /// Large call bodies in progress, a frame of each per round.
    sequences: VecDeque<VecDeque<Frame>>,
    /// The outbox batch and held-back topics, kept across rounds so a busy link does not
    /// allocate them every round.
    items: Vec<Taken>,
    held: Vec<Arc<Message>>,
    /// Small frames being packed into one WebSocket message.
    buf: BytesMut,
    /// WebSocket messages ready to write, before what `buf` holds.
    out: VecDeque<Transmit>,
    /// A close was queued: nothing more goes out after it.
    closing: bool,
}

impl Outbound {
    /// The outbound half of a link writing `outbox`; `announce_first` topics are
    /// advertised before anything else (e.g. after a reconnect); `namer` gives each topic
    /// its name on the link; `via` marks messages between hubs.
    pub fn new(
        outbox: Arc<Outbox>,
        namer: LinkNamer,
        announce_first: Vec<(Arc<TopicMeta>, Encoding)>,
        gate: Option<Box<dyn Gate>>,
        via: Option<ViaOut>,
    ) -> Outbound {
        let mut ob = Outbound {
            topics: Announcer {
                advertised: HashMap::new(),
                namer,
                outbox: outbox.clone(),
                via: ViaMark {
                    out: via,
                    written: None,
                },
            },
            outbox,
            gate,
            lanes: Vec::new(),
            compressors: HashMap::new(),
            unadvertise: Vec::new(),
            sequences: VecDeque::new(),
            items: Vec::new(),
            held: Vec::new(),
            buf: BytesMut::new(),
            out: VecDeque::new(),
            closing: false,
        };
        for (meta, enc) in announce_first {
            ob.topics
                .announce_before_messages(&mut ob.buf, &mut ob.gate, &meta, enc);
        }
        ob
    }

    /// Takes what the session handed the writer; `None`: the session's queue closed, which
    /// ends the link like a close without a frame. Control frames go before the next
    /// round's messages: they are small and often answers the peer waits for.
    pub fn on_control(&mut self, c: Option<Control>) {
        if self.closing {
            return;
        }
        match c {
            Some(Control::Frame(f)) => f.encode(&mut self.buf),
            Some(Control::Sequence(s)) => self.sequences.push_back(s),
            Some(Control::Unadvertise { topic, since }) => self.unadvertise.push((topic, since)),
            Some(Control::Announce { meta, encoding }) => {
                self.topics.announce_before_messages(
                    &mut self.buf,
                    &mut self.gate,
                    &meta,
                    encoding,
                );
            }
            Some(Control::Pong(p)) => {
                self.seal();
                self.out.push_back(Transmit::Pong(p));
            }
            Some(Control::Close(frame)) => self.close(frame),
            None => self.close(None),
        }
    }

    /// Ends the link after what is queued, with `frame` if any.
    fn close(&mut self, frame: Option<CloseFrame>) {
        self.seal();
        self.out.push_back(Transmit::Close(frame));
        self.closing = true;
    }

    /// Whether a close is queued (nothing more will be produced).
    pub fn is_closing(&self) -> bool {
        self.closing
    }

    /// The next WebSocket message to write, if any.
    pub fn poll_transmit(&mut self) -> Option<Transmit> {
        if let Some(t) = self.out.pop_front() {
            return Some(t);
        }
        (!self.buf.is_empty()).then(|| Transmit::Binary(self.buf.split().freeze()))
    }

    /// One round: the outbox's probe, a frame of each large call body, a chunk of each
    /// lane (while the link's window allows), topics held back announced, a batch from the
    /// outbox, topics whose publishers left unannounced. What it produced waits in
    /// [`Outbound::poll_transmit`].
    pub fn round(&mut self) -> Round {
        if self.closing {
            return Round {
                again: false,
                wake: None,
            };
        }
        // Echo probes of a scheduled outbox's link estimator.
        if let Some(id) = self.outbox.poll_probe(Instant::now()) {
            Frame::Ping {
                id,
                sent_ns: crate::unix_nanos(),
            }
            .encode(&mut self.buf);
        }
        for seq in self.sequences.iter_mut() {
            if let Some(f) = seq.pop_front() {
                f.encode(&mut self.buf);
            }
        }
        self.sequences.retain(|s| !s.is_empty());
        let gated = self.lane_turns();
        self.announce_held();
        // When it takes nothing, the time its data budget next lets something go.
        let (took, budget_wake) = self.take_batch();
        self.unadvertise_done();
        if took > 0 || !self.sequences.is_empty() || (!self.lanes.is_empty() && gated.is_none()) {
            return Round {
                again: true,
                wake: None,
            };
        }
        // A scheduled outbox wakes when its next probe is due (none while its link is idle:
        // new data wakes it); a plain one (the hub's) sleeps until there is something to
        // write.
        let wake = [self.outbox.probe_timeout(), gated.flatten(), budget_wake]
            .into_iter()
            .flatten()
            .min();
        Round { again: false, wake }
    }

    /// Moves what is packed behind what is ready to write.
    fn seal(&mut self) {
        if !self.buf.is_empty() {
            self.out
                .push_back(Transmit::Binary(self.buf.split().freeze()));
        }
    }

    /// Seals the pack once it is full.
    fn seal_if_full(&mut self) {
        if self.buf.len() >= PACK {
            self.seal();
        }
    }

    /// Packs a small frame, or queues a large one as its own message after what is
    /// packed (to keep order). The large frame's bytes are shared, not copied.
    fn push_frame(&mut self, frame: &Bytes) {
        if frame.len() < PACK / 4 {
            self.buf.extend_from_slice(frame);
            self.seal_if_full();
            return;
        }
        self.seal();
        self.out.push_back(Transmit::Binary(frame.clone()));
    }

    /// Chunks from the lanes in progress, a chunk from each in turn, while the link's
    /// window allows. A plain outbox's lanes take one turn per round, so small messages
    /// queued meanwhile go out between chunks. A scheduled outbox's window already bounds
    /// what a round may write (about `QUEUE_TARGET` of link time), so its lanes take turns
    /// until the window is full: a fast link is not driven one chunk per write. Returns
    /// `Some(wake)` when the window stopped the turns.
    fn lane_turns(&mut self) -> Option<Option<Instant>> {
        let mut round_bytes = 0usize;
        loop {
            let mut wrote = false;
            let mut i = 0;
            while i < self.lanes.len() {
                self.seal_if_full();
                if !self.lanes[i].is_done() {
                    if let Err(wake) = self.outbox.bulk_check(Instant::now()) {
                        // The next round resumes the turns here: the lanes before this one
                        // had theirs, so a gate after every chunk (a capacity share, a
                        // small window) still gives each lane a chunk in turn rather than
                        // the first lane all of them.
                        self.lanes.rotate_left(i);
                        return Some(wake);
                    }
                    let chunk = self.outbox.chunk_size().unwrap_or(DEFAULT_CHUNK_SIZE);
                    let lane = &mut self.lanes[i];
                    self.topics.via.mark(&mut self.buf, &lane.msg);
                    let (f, n) = lane.next_frame(chunk);
                    self.push_frame(&f);
                    self.outbox.on_written(n);
                    round_bytes += f.len();
                    wrote = true;
                }
                if self.lanes[i].is_done() && !self.next_in_lane(i) {
                    self.outbox
                        .hold(self.lanes[i].topic.0, false, Instant::now());
                    self.lanes.swap_remove(i);
                    continue;
                }
                i += 1;
            }
            if !wrote || !self.outbox.is_scheduled() || round_bytes >= MAX_ROUND_BYTES {
                return None;
            }
        }
    }

    /// Starts lane `i`'s next waiting message (of the same topic) once its message is
    /// done; false when none waits.
    fn next_in_lane(&mut self, i: usize) -> bool {
        let lane = &mut self.lanes[i];
        let Some(m) = lane.waiting.pop_front() else {
            return false;
        };
        let (topic, sized) = (lane.topic, lane.cached.is_none());
        let waiting = std::mem::take(&mut lane.waiting);
        let carried = self.topics.announce(&mut self.buf, &m);
        let (m, compressed) = if carried {
            for_link(&mut self.compressors, &self.outbox, m)
        } else {
            (m, false)
        };
        let lane = &mut self.lanes[i];
        *lane = Lane {
            waiting,
            ..Lane::start(topic, m, sized, compressed)
        };
        if !carried {
            lane.skip();
        }
        true
    }

    /// Topics a demand-driven uplink holds back are announced all the same, so the peer
    /// can ask for them.
    fn announce_held(&mut self) {
        self.outbox.take_unannounced(&mut self.held);
        for msg in self.held.drain(..) {
            if may_see(&mut self.gate, &msg.topic) {
                self.topics.announce(&mut self.buf, &msg);
            }
        }
    }

    /// A batch from the outbox: how many messages it took and, when it took none, when
    /// its data budget next lets one go.
    fn take_batch(&mut self) -> (usize, Option<Instant>) {
        let mut items = std::mem::take(&mut self.items);
        let budget_wake = self
            .outbox
            .take_into(&mut items, 512, 4 << 20, Instant::now());
        let took = items.len();
        for (_, _, msg) in items.drain(..) {
            self.send_message(msg);
        }
        self.items = items;
        (took, budget_wake)
    }

    /// One message taken from the outbox: framed into the pack, sent as its shared
    /// frame, or given a lane.
    fn send_message(&mut self, msg: Arc<Message>) {
        let topic = &msg.topic;
        if !may_see(&mut self.gate, topic) || !self.topics.via.sends(&msg) {
            return;
        }
        let tid = topic.id;
        if !self.unadvertise.is_empty() {
            // Published again since it was seen without a publisher: keep it.
            self.unadvertise
                .retain(|(t, since)| *t != tid || msg.received() <= *since);
        }
        if let Some(lane) = self.lanes.iter_mut().find(|l| l.topic == tid) {
            lane.waiting.push_back(msg);
            return;
        }
        if !self.topics.announce(&mut self.buf, &msg) {
            return;
        }
        // Per message on the hub's fan-out path: these calls read no clock and take no
        // lock unless the outbox is the agent's scheduled uplink.
        let (msg, compressed) = for_link(&mut self.compressors, &self.outbox, msg);
        self.topics.via.mark(&mut self.buf, &msg);
        let sized = self.outbox.chunk_size();
        let whole = sized.unwrap_or(DEFAULT_CHUNK_SIZE);
        let p = &msg.payload.bytes;
        if compressed && p.len() <= whole {
            // The agent's link is the only one a compressed message goes out on: framed
            // in place, never through the shared frames.
            fleetlink_proto::frame::encode_message_kind(
                &mut self.buf,
                true,
                tid.0,
                msg.seq,
                msg.stamp_ns,
                p,
            );
            self.seal_if_full();
            self.outbox.on_written(p.len());
        } else if p.len() <= ENCODE_IN_PLACE.min(whole) {
            // A small message's MESSAGE frame is written straight into the pack: a few
            // dozen bytes copied per link cost less than building a frame to share (the
            // payload's bytes are copied as they are, never re-encoded).
            fleetlink_proto::frame::encode_message(&mut self.buf, tid.0, msg.seq, msg.stamp_ns, p);
            self.seal_if_full();
            self.outbox.on_written(p.len());
        } else if p.len() <= whole {
            // One MESSAGE frame (payloads up to DEFAULT_CHUNK_SIZE are never chunked),
            // built once and shared by every link it goes out on.
            let frames = msg.link_frames();
            self.push_frame(&frames[0]);
            self.outbox.on_written(msg.payload.len());
        } else {
            self.outbox.hold(tid.0, true, Instant::now());
            self.lanes
                .push(Lane::start(tid, msg, sized.is_some(), compressed));
        }
    }

    /// Topics whose publishers are gone, after their last message.
    fn unadvertise_done(&mut self) {
        if self.unadvertise.is_empty() {
            return;
        }
        let (lanes, outbox, topics, buf) =
            (&self.lanes, &self.outbox, &mut self.topics, &mut self.buf);
        self.unadvertise.retain(|(t, _)| {
            if !topics.advertised.contains_key(t)
                || outbox.advertise_flags(t.0) & ADVERTISE_RELIABLE != 0
            {
                return false; // never announced here, or a no-drop stream
            }
            if lanes.iter().any(|l| l.topic == *t) || outbox.queued_for(t.0) > 0 {
                return true; // its messages first
            }
            Frame::Unadvertise { alias: t.0 }.encode(buf);
            topics.advertised.remove(t);
            // Published again later, a held-back topic is announced again.
            outbox.forget_announced(t.0);
            false
        });
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

/// What the peer has been told of topics on this link (`ADVERTISE`), and the `VIA` marks
/// that go before announcements and messages between hubs.
struct Announcer {
    advertised: HashMap<TopicId, Encoding>,
    namer: LinkNamer,
    outbox: Arc<Outbox>,
    via: ViaMark,
}

impl Announcer {
    /// Sends `ADVERTISE` for the message's topic the first time (or when its encoding
    /// changes). Returns false when the topic is not carried on this link.
    fn announce(&mut self, buf: &mut BytesMut, msg: &Message) -> bool {
        let enc = msg.payload.encoding;
        if self.advertised.get(&msg.topic.id) == Some(&enc) {
            return true;
        }
        self.announce_topic(buf, &msg.topic, enc)
    }

    /// Announces `meta` before any message of it goes (a reconnect's topics, a site hub's
    /// new ones): once per link, and only to a peer the gate lets receive it.
    fn announce_before_messages(
        &mut self,
        buf: &mut BytesMut,
        gate: &mut Option<Box<dyn Gate>>,
        meta: &TopicMeta,
        enc: Encoding,
    ) {
        if !self.advertised.contains_key(&meta.id) && may_see(gate, meta) {
            self.announce_topic(buf, meta, enc);
        }
    }

    /// Writes `ADVERTISE` of `meta` in `enc` (and notes it announced); false if the topic
    /// has no name on this link.
    fn announce_topic(&mut self, buf: &mut BytesMut, meta: &TopicMeta, enc: Encoding) -> bool {
        let Some(name) = (self.namer)(meta) else {
            return false;
        };
        // Between hubs, a topic is announced with the hubs its publisher is behind.
        self.via.mark_path(buf, meta.via.as_ref());
        // Reliable: the outbox's no-drop streams; latched: the topic's own.
        let latched = if meta.latched { ADVERTISE_LATCHED } else { 0 };
        Frame::Advertise {
            alias: meta.id.0,
            topic: name,
            schema: meta.schema.clone(),
            encoding: enc,
            flags: self.outbox.advertise_flags(meta.id.0) | latched,
        }
        .encode(buf);
        self.advertised.insert(meta.id, enc);
        true
    }
}

/// Whether the link's gate (if any) lets the peer see `meta`'s topic.
fn may_see(gate: &mut Option<Box<dyn Gate>>, meta: &TopicMeta) -> bool {
    gate.as_mut()
        .is_none_or(|g| g.allows_topic(meta.id.0, meta.name.as_str(), crate::gate::Op::Subscribe))
}

#[cfg(test)]
#[path = "outbound_tests.rs"]
mod tests;
