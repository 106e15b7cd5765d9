//! What a client publishes: the topics it advertised (`Published`), the short path
//! that publishes a frame at once, and the waiting one for a full no-drop queue. Kept
//! apart from the session's other operations: nearly every frame comes here.

use super::*;

/// What [`Session::publish_on_known`] did.
enum Known {
    /// The topic is one this client publishes: the publish's outcome.
    Done(Result<Option<(Payload, Arc<Topic>)>, String>),
    /// It is not (under that spelling): the message, untouched.
    Not(Payload),
}

pub(super) struct Published {
    /// The name it is published under (this entry's key).
    name: TopicName,
    topic: Arc<Topic>,
    seq: u64,
    /// What the transcoder resolved for checking this topic's messages.
    normalize: NormalizeCache,
    /// This client's messages not yet added to the topic's counters
    /// ([`Session::flush_counts`]).
    counts: StatsBatch,
    /// The topic as of this client's last publish, held until the session waits.
    view: TopicView,
    /// In the session's `unflushed` list.
    listed: bool,
}

impl Published {
    fn new(name: TopicName, topic: Arc<Topic>) -> Published {
        Published {
            name,
            topic,
            seq: 0,
            normalize: NormalizeCache::default(),
            counts: StatsBatch::default(),
            view: TopicView::default(),
            listed: false,
        }
    }
}

impl Published {
    /// Lists the entry in `unflushed` (once), for the session to let go of its `view` and
    /// flush its counters when it next waits: done before a publish takes the view.
    fn list(&mut self, unflushed: &mut Vec<TopicName>) {
        if !self.listed {
            self.listed = true;
            unflushed.push(self.name.clone());
        }
    }

    /// Fans out `msg`, checked against the topic's type (its `view` read for that), as
    /// this client's next message on the topic; gives its size.
    fn publish(
        &mut self,
        client: ClientId,
        clock: &mut fleetlink_relay::StampClock,
        msg: Payload,
        json_text: bool,
    ) -> usize {
        self.seq += 1;
        let size = msg.len();
        let (received, stamp) = clock.arrival();
        self.topic.publish_framed(
            &self.view,
            client,
            self.seq,
            stamp,
            msg,
            received,
            json_text,
            &mut self.counts,
        );
        size
    }
}

impl Drop for Published {
    fn drop(&mut self) {
        self.topic.stats.flush(&mut self.counts);
    }
}

impl Session {
    /// Adds what this client published since the last call to its topics' counters, and
    /// lets go of the topics' snapshots (a subscriber that left is not kept alive by an
    /// idle publisher): done before the session waits for the client and every
    /// [`LOOK_AROUND`] frames, so the counters are never behind by more than a moment or
    /// a few dozen messages.
    pub(super) fn flush_counts(&mut self) {
        for name in self.unflushed.drain(..) {
            if let Some(p) = self.published.get_mut(&name) {
                p.topic.stats.flush(&mut p.counts);
                p.view.clear();
                p.listed = false;
            }
        }
    }

    /// The short path of nearly every frame: a publish the topic takes at once is done
    /// here, without the future and the select of the waiting path (whose state is
    /// hundreds of bytes moved for each message). What it cannot finish comes back.
    /// `frame` is the frame's bytes when it is a JSON text frame.
    pub(super) fn publish_now<'a>(
        &mut self,
        p: Publish<'a>,
        frame: Option<&[u8]>,
    ) -> Option<Incoming<'a>> {
        if self.gate.is_none() {
            return Some(Incoming::Publish(p));
        }
        let Publish { id, topic, msg } = p;
        match self.try_publish(&topic, msg, frame) {
            Ok(None) => None,
            Ok(Some((msg, _full))) => Some(Incoming::Publish(Publish { id, topic, msg })),
            Err(text) => Some(Incoming::Refused(id, text)),
        }
    }

    /// A `publish` from the short path: what [`Session::handle`] does for one.
    pub(super) async fn handle_publish(&mut self, p: Publish<'_>) {
        if self.gate.is_none() {
            let msg =
                "publish: authentication required: send an 'auth' operation with a token first";
            return self
                .status("error", msg.into(), p.id.value().as_ref())
                .await;
        }
        if let Err(msg) = self.publish(&p.topic, p.msg).await {
            self.status("error", msg, p.id.value().as_ref()).await;
            self.clock.waited();
        }
    }

    pub(super) fn advertise(
        &mut self,
        topic: &str,
        type_name: &str,
        latch: bool,
    ) -> Result<(), String> {
        let name = TopicName::parse(topic).map_err(|e| format!("advertise: {e}"))?;
        if type_name.trim().is_empty() {
            return Err(format!("advertise {name}: field 'type' is empty"));
        }
        self.check("advertise", name.as_str(), GateOp::Publish)?;
        let t = self
            .router
            .advertise(self.client, &name, Schema::named(type_name), latch)
            .map_err(|e| format!("advertise: {e}"))?;
        self.published
            .entry(name.clone())
            .or_insert_with(|| Published::new(name, t));
        Ok(())
    }

    pub(super) fn unadvertise(&mut self, topic: &str) -> Result<(), String> {
        let name = TopicName::parse(topic).map_err(|e| format!("unadvertise: {e}"))?;
        if self.published.remove(&name).is_none() {
            return Err(format!(
                "unadvertise {name}: this client has not advertised it"
            ));
        }
        self.router.unadvertise(self.client, &name);
        Ok(())
    }

    /// Publishes `msg` on `topic`. Backpressure for no-drop topics: while a subscriber's
    /// no-drop queue of this topic is full (the robot's link is down and nothing spills to
    /// disk), the message waits here for room — and, because this loop is what reads the
    /// socket, the client's own sends slow down with it — instead of being refused.
    pub(super) async fn publish(&mut self, topic: &str, mut msg: Payload) -> Result<(), String> {
        loop {
            match self.try_publish(topic, msg, None)? {
                None => return Ok(()),
                Some((back, full)) => {
                    msg = back;
                    tracing::debug!("publish {topic}: no-drop queue full, waiting for room");
                    full.stats.no_drop_flow.wait_room().await;
                    self.clock.waited();
                }
            }
        }
    }

    /// Publishes `msg` on `topic` unless it is a no-drop topic whose queue is full; then
    /// hands the message back, with the topic to wait on. `frame` is the text frame
    /// `msg` came in, if it came in one (see [`Session::publish_on_known`]).
    fn try_publish(
        &mut self,
        topic: &str,
        msg: Payload,
        frame: Option<&[u8]>,
    ) -> Result<Option<(Payload, Arc<Topic>)>, String> {
        // Most publishes name a topic this client already publishes, spelled the same way:
        // one lookup by the client's spelling, no parse, no copy of the name.
        let msg = match self.publish_on_known(topic, msg, frame) {
            Known::Done(r) => return r,
            Known::Not(msg) => msg,
        };
        let name = TopicName::parse(topic).map_err(|e| format!("publish: {e}"))?;
        if !is_object(&msg) {
            return Err(format!("publish {name}: field 'msg' must be an object"));
        }
        self.check("publish", name.as_str(), GateOp::Publish)?;
        if !self.published.contains_key(name.as_str()) {
            self.start_publishing(name.as_str())?;
        }
        match self.publish_on_known(name.as_str(), msg, frame) {
            Known::Done(r) => r,
            Known::Not(_) => unreachable!("{name} was added to the published topics above"),
        }
    }

    /// [`Session::try_publish`] on a topic this client publishes under exactly this
    /// spelling; the message comes back untouched when it does not. When `msg` is still
    /// the JSON text it came in (a slice of `frame`, which the type check left as it
    /// was), the message is marked so: writers frame it as it is.
    fn publish_on_known(&mut self, name: &str, msg: Payload, frame: Option<&[u8]>) -> Known {
        let Session {
            published,
            gate,
            router,
            clock,
            client,
            unflushed,
            ..
        } = self;
        let Some(p) = published.get_mut(name) else {
            return Known::Not(msg);
        };
        Known::Done((|| {
            if !is_object(&msg) {
                return Err(format!("publish {name}: field 'msg' must be an object"));
            }
            // Asked for every message: rules can change while a client publishes, and the
            // gate's cache makes the repeat question cheap.
            let gate = check(gate, "publish", name, GateOp::Publish)?;
            if p.topic.stats.no_drop_flow.is_full() {
                return Ok(Some((msg, p.topic.clone())));
            }
            // Checked and completed once here, for every subscriber.
            p.list(unflushed);
            let meta = p.topic.view(&mut p.view).meta();
            let msg = router
                .transcoder()
                .normalize_cached(&meta.schema, msg, &mut p.normalize)
                .map_err(|e| {
                    format!(
                        "publish {name}: the message does not fit its type: {}",
                        e.cause_text()
                    )
                })?;
            // Still the text it came in: writers frame it as it is.
            let json_text = frame.is_some_and(|f| lies_within(f, &msg));
            let size = p.publish(*client, clock, msg, json_text);
            gate.done(name, GateOp::Publish, size);
            Ok(None)
        })())
    }

    /// A publish read by its envelope's shape (`m`, parts of `frame`), done at once when
    /// nothing stands in its way: the client publishes the topic under this spelling and
    /// may, the topic has room, and the message passes its check against the type —
    /// which is also what checks its syntax and UTF-8. The message is `frame` itself, cut
    /// down to the message, so it costs no new reference to the read buffer. Anything
    /// else hands the frame back, for the full read ([`Publish::from_json_text`]) to do
    /// and answer as for any publish.
    pub(super) fn publish_shaped(&mut self, frame: Bytes, m: Matched) -> Result<(), Bytes> {
        let Some(gate) = self.gate.as_mut() else {
            return Err(frame);
        };
        let Some(p) = std::str::from_utf8(&frame[m.topic])
            .ok()
            .and_then(|topic| self.published.get_mut(topic))
        else {
            return Err(frame);
        };
        // Asked for every message: rules can change while a client publishes.
        if !gate.allows_topic(p.topic.id().0, p.name.as_str(), GateOp::Publish)
            || p.topic.stats.no_drop_flow.is_full()
        {
            return Err(frame);
        }
        p.list(&mut self.unflushed);
        let meta = p.topic.view(&mut p.view).meta();
        let checked = self.router.transcoder().normalize_json_unchecked(
            &meta.schema,
            &frame[m.msg.clone()],
            &mut p.normalize,
        );
        let (msg, json_text) = match checked {
            Ok(None) => {
                let mut msg = frame;
                msg.truncate(m.msg.end);
                msg.advance(m.msg.start);
                (Payload::json(msg), true)
            }
            Ok(Some(normal)) => (Payload::json(normal), false),
            Err(_) => return Err(frame),
        };
        let size = p.publish(self.client, &mut self.clock, msg, json_text);
        gate.done(p.name.as_str(), GateOp::Publish, size);
        Ok(())
    }

    /// The first publish on `name` without an `advertise`: rosbridge allows it on a topic
    /// whose type is already known.
    fn start_publishing(&mut self, name: &str) -> Result<(), String> {
        let name = TopicName::parse(name).map_err(|e| format!("publish: {e}"))?;
        let Some(existing) = self
            .router
            .topic(&name)
            .filter(|t| !t.meta().schema.type_name.is_empty())
        else {
            return Err(format!(
                "publish {name}: topic is not advertised; send 'advertise' with its type first"
            ));
        };
        let schema = existing.meta().schema.clone();
        let t = self
            .router
            .advertise(self.client, &name, schema, false)
            .map_err(|e| format!("publish: {e}"))?;
        self.published.insert(name.clone(), Published::new(name, t));
        Ok(())
    }
}

/// A message object is a JSON object or a CBOR map.
fn is_object(p: &Payload) -> bool {
    match p.encoding {
        Encoding::Json => p.bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{'),
        Encoding::Cbor => p.bytes.first().is_some_and(|b| b >> 5 == 5),
        _ => true,
    }
}

/// Whether `p` is JSON lying within `frame` (a slice of the text frame it came in).
fn lies_within(frame: &[u8], p: &Payload) -> bool {
    if p.encoding != Encoding::Json {
        return false;
    }
    // Live buffers do not overlap: bytes inside the frame's are a slice of that frame.
    let start = p.bytes.as_ptr() as usize;
    let begin = frame.as_ptr() as usize;
    start >= begin && start + p.len() <= begin + frame.len()
}
