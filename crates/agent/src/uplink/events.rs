//! What the uplink does with what happens on a connection: topics that appear locally
//! (announced to the hub; a mirror's subscriptions following local demand), topic events
//! and control frames from the hub, and the durable outbox's messages restored at start.

use super::*;

impl Uplink {
    /// Announces the topics that changed since the last look and are carried up, with a
    /// publisher here and a known encoding, but not yet announced on this connection (the
    /// writer skips those it has).
    /// A mirror also asks for its robot's topics local subscribers want, and lets go of
    /// those they no longer do.
    pub(super) fn announce_new(
        &self,
        watch: &TopicsWatch,
        namespace: &str,
        mut mirror: Option<&mut MirrorSubs>,
        session: &mut LinkSession,
    ) {
        for name in watch.take() {
            let t = self.router.snapshot(&name);
            if let Some(m) = mirror.as_deref_mut() {
                self.follow_local_demand(&name, t.as_ref(), namespace, m, session);
            }
            let Some(t) = t else {
                continue;
            };
            if !t.subscribers.contains(&self.client)
                || !t.publishers.iter().any(|p| *p != self.client)
            {
                continue;
            }
            if let Some(encoding) = t.topic.last_encoding() {
                session.send_control(Control::Announce {
                    meta: t.meta.clone(),
                    encoding,
                });
            }
        }
    }

    /// A mirror's subscription at the hub of the robot topic `name` (a local name): there
    /// while a local subscriber other than this uplink wants the topic.
    pub(super) fn follow_local_demand(
        &self,
        name: &TopicName,
        t: Option<&fleetlink_relay::router::TopicSnapshot>,
        namespace: &str,
        subs: &mut MirrorSubs,
        session: &mut LinkSession,
    ) {
        let wanted = t.is_some_and(|t| t.topic.wanted_by_others(self.client));
        match (wanted, subs.by_name.get(name).copied()) {
            (true, None) => {
                let hub = self.cfg.names.to_hub(name, namespace);
                // Only the robot's own topics; `subscribe:` names the others.
                if hub.strip_namespace(namespace).is_none()
                    || self.cfg.names.subscribe.iter().any(|(h, _)| *h == hub)
                {
                    return;
                }
                let id = subs.next_id;
                subs.next_id = subs.next_id.wrapping_add(1).max(MIRROR_SUBSCRIPTIONS);
                subs.by_name.insert(name.clone(), id);
                tracing::debug!("mirror: asking the hub for {hub}");
                session.send(Frame::Subscribe {
                    id,
                    pattern: hub.to_string(),
                    flags: 0,
                    throttle_ms: 0,
                    queue_length: 0,
                });
            }
            (false, Some(id)) => {
                subs.by_name.remove(name);
                tracing::debug!("mirror: {name} no longer wanted here");
                session.send(Frame::Unsubscribe { id });
            }
            _ => {}
        }
    }

    /// A topic event or control frame from the hub.
    pub(super) fn on_event(
        &self,
        ev: LinkEvent,
        namespace: &str,
        down: &mut HashMap<u32, Arc<Topic>>,
        session: &mut LinkSession,
    ) {
        match ev {
            LinkEvent::Advertise { alias, topic, via } => {
                let Ok(hub) = TopicName::parse(&topic.name) else {
                    return;
                };
                let Some(local) = self.cfg.names.to_local(&hub, namespace) else {
                    tracing::debug!("hub sent {hub}, which has no local name here");
                    return;
                };
                let gate = session.gate();
                if !gate.allows(local.as_str(), fleetlink_relay::gate::Op::Publish) {
                    let text = format!("advertise {local}: not allowed for {}", gate.principal());
                    tracing::warn!("{text}");
                    return session.status(
                        fleetlink_proto::frame::Level::Error,
                        fleetlink_proto::frame::status_code::FORBIDDEN,
                        text,
                    );
                }
                let how = fleetlink_relay::router::Publication {
                    latch: topic.latched,
                    no_drop: false,
                    via,
                    encoding: None,
                };
                match self
                    .router
                    .advertise_as(self.client, &local, topic.schema, how)
                {
                    Ok(t) => {
                        down.insert(alias, t);
                    }
                    Err(e) => tracing::warn!("cannot deliver {hub} locally: {e}"),
                }
            }
            LinkEvent::Unadvertise { alias, .. } => {
                down.remove(&alias);
            }
            LinkEvent::Message {
                alias,
                seq,
                stamp_ns,
                payload,
                via,
                ..
            } => {
                if let Some(t) = down.get(&alias) {
                    // On a site hub, asked per message (a cached answer), so a rule change
                    // applies at once.
                    if self.cfg.upstream_gate.is_some() {
                        let meta = t.meta();
                        let op = fleetlink_relay::gate::Op::Publish;
                        let gate = session.gate();
                        if !gate.allows_topic(meta.id.0, meta.name.as_str(), op) {
                            return;
                        }
                        // A command to one of the hub's robots is audited, as an
                        // operator's on the hub is.
                        gate.done(meta.name.as_str(), op, payload.len());
                    }
                    if via.is_some() {
                        // Down from the hub upstream: it keeps the hubs it passed.
                        let msg = fleetlink_relay::Message::new(
                            t.meta(),
                            seq,
                            stamp_ns,
                            self.client,
                            payload,
                        )
                        .with_via(via);
                        t.deliver(&Arc::new(msg));
                    } else {
                        t.publish(self.client, seq, stamp_ns, payload);
                    }
                }
            }
            LinkEvent::Control(Frame::Status { level, text, .. }) => {
                tracing::warn!(level = level.as_str(), "hub: {text}");
            }
            LinkEvent::Control(Frame::Interest { alias, wanted }) => {
                self.outbox.set_wanted(alias, wanted, Instant::now());
                // On a site hub the topic's robot hears it (the subscription is passive).
                self.router.note_demand(TopicId(alias));
            }
            LinkEvent::Control(Frame::Pull { alias }) => {
                self.outbox.pull(alias, Instant::now());
                // On a video topic: the hub asks for a keyframe (docs/video.md). The
                // robot's encoder hears it through its demand watch; on a site hub the
                // topic wants one, which the site's link to its robot asks for.
                if let Some(t) = self.router.topic_by_id(TopicId(alias))
                    && fleetlink_relay::gop::is_video_type(&t.meta().schema.type_name)
                {
                    self.router.request_pull(&t.name());
                    t.want_keyframe();
                }
            }
            LinkEvent::Control(Frame::Delivered { alias, seq }) => {
                self.outbox.on_delivered(alias, seq);
            }
            LinkEvent::Control(Frame::Ack { frames, bytes }) => {
                self.outbox.on_acked(frames as usize, bytes, Instant::now());
            }
            LinkEvent::Control(Frame::Share { bytes_per_sec }) => {
                let share = (bytes_per_sec > 0).then_some(bytes_per_sec as f64);
                self.outbox.set_share(share, Instant::now());
                self.stats.share_bps.store(bytes_per_sec, Relaxed);
            }
            _ => {}
        }
    }
}

/// Queues what the durable outbox held from the last run, each message on its topic
/// (advertised locally by the uplink so it has a slot), before anything new.
pub(super) fn restore(
    router: &Router,
    client: ClientId,
    outbox: &Outbox,
    recovered: Vec<fleetlink_relay::reliable::Recovered>,
) {
    let mut lost = 0usize;
    for r in recovered {
        let topic = match router.advertise(client, &r.topic, r.schema.clone(), false) {
            Ok(t) => t,
            Err(e) => {
                tracing::error!("durable outbox: cannot restore {}: {e}", r.topic);
                lost += 1;
                continue;
            }
        };
        let msg = fleetlink_relay::Message::new(
            topic.meta(),
            r.seq,
            r.stamp_ns,
            client,
            fleetlink_proto::Payload::new(r.encoding, r.payload),
        );
        if !outbox.restore(Arc::new(msg), std::time::Instant::now()) {
            lost += 1;
        }
    }
    if lost > 0 {
        tracing::error!(
            "durable outbox: {lost} recovered messages could not be queued (their topics are \
             no longer no_drop in this configuration)"
        );
    }
}
