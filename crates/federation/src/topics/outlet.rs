//! The sending side of the topics: an outlet for each topic another hub wants, and the
//! pump that puts what the federation's subscriptions receive into Zenoh.
//!
//! Design choice: a declared `Publisher` only for a topic that is both wanted elsewhere
//! and published here; the quiet subscriptions a hub holds for topics nobody publishes
//! there (yet) send through `Session::put` if a message comes before the publisher.
//! Zenoh 1.10 matches every new declaration against all it knows
//! (`Resource::get_matches`), so a publisher declared for each of 10,000 topics wanted
//! elsewhere kept an idle hub busy for many seconds; a declared publisher is cheaper per
//! message than a put. A no-drop topic's messages always go by put with congestion
//! control `Block` (they wait for room in Zenoh's queues); the rest drop under
//! congestion rather than stall every topic behind one slow hub. Whether a topic is
//! no-drop is known only when its robot advertises, possibly after another hub wanted it.

use std::collections::HashMap;
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use fleetlink_relay::outbox::Taken;
use fleetlink_relay::router::{SubOptions, SubscriptionId, Target};
use fleetlink_relay::{Outbox, Router, Topic, TopicId, TopicName};
use tokio_util::sync::CancellationToken;
use zenoh::Session;
use zenoh::pubsub::Publisher;
use zenoh::qos::CongestionControl;
use zenoh::sample::Locality;

use crate::keys::{self, MessageHeader};
use crate::{ExportFigures, FederationError, Shared, zerr};

/// What the pump needs of a topic this hub sends.
struct Outlet {
    key: zenoh::key_expr::KeyExpr<'static>,
    publisher: Option<Publisher<'static>>,
    topic: Arc<Topic>,
    figures: Arc<ExportFigures>,
}

/// The outlets of the topics this hub sends, by topic id: opened and closed by the topics
/// loop, read by the pump. One per topic another hub wants (the loop closes it when none
/// does).
#[derive(Clone, Default)]
pub(super) struct Outlets(Arc<Mutex<HashMap<TopicId, Arc<Outlet>>>>);

impl Outlets {
    fn lock(&self) -> MutexGuard<'_, HashMap<TopicId, Arc<Outlet>>> {
        self.0.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Subscribes here on behalf of the hubs that want `name`, with a Zenoh key (and
    /// later a publisher) for what arrives.
    pub(super) async fn open(
        &self,
        router: &Router,
        shared: &Shared,
        name: &TopicName,
    ) -> Result<(SubscriptionId, TopicId, Arc<ExportFigures>), FederationError> {
        let key = keys::topic_key(&shared.fleet, &shared.me, name.as_str())
            .ok_or_else(|| FederationError::Zenoh(format!("{name} cannot be a Zenoh key")))?;
        let sid = router
            .subscribe(
                shared.client,
                Target::Exact(name.clone()),
                SubOptions {
                    unlisted: true,
                    ..SubOptions::default()
                },
            )
            .map_err(|e| FederationError::Zenoh(e.to_string()))?;
        let topic = router.topic(name).expect("a subscription keeps its topic");
        let key = match zenoh::key_expr::KeyExpr::try_from(key) {
            Ok(k) => k,
            Err(e) => {
                router.unsubscribe(shared.client, sid);
                return Err(zerr(e));
            }
        };
        let figures = Arc::new(ExportFigures::default());
        let id = topic.id();
        self.lock().insert(
            id,
            Arc::new(Outlet {
                key,
                publisher: None,
                topic,
                figures: figures.clone(),
            }),
        );
        Ok((sid, id, figures))
    }

    /// Lets go of the outlet of topic `id` (no hub wants it any more).
    pub(super) fn close(&self, id: TopicId) {
        self.lock().remove(&id);
    }

    /// Gives the outlet of topic `id` a declared publisher, once.
    pub(super) async fn declare_publisher(&self, session: &Session, id: TopicId) {
        let Some(o) = self
            .lock()
            .get(&id)
            .filter(|o| o.publisher.is_none())
            .cloned()
        else {
            return;
        };
        let declared = session
            .declare_publisher(o.key.clone())
            .congestion_control(CongestionControl::Drop)
            .allowed_destination(Locality::Remote)
            .await;
        match declared {
            Ok(p) => {
                let with = Arc::new(Outlet {
                    key: o.key.clone(),
                    publisher: Some(p),
                    topic: o.topic.clone(),
                    figures: o.figures.clone(),
                });
                let mut outlets = self.lock();
                // Still the same outlet (not withdrawn meanwhile).
                if outlets.get(&id).is_some_and(|cur| Arc::ptr_eq(cur, &o)) {
                    outlets.insert(id, with);
                }
            }
            Err(e) => tracing::debug!("federation: publisher for {}: {e}", o.key),
        }
    }
}

/// Puts what the federation's subscriptions receive into Zenoh: each message once, its
/// payload as it is (a reference to the received bytes, no copy), the header beside it.
pub(super) async fn pump(
    session: Session,
    outbox: Arc<Outbox>,
    outlets: Outlets,
    shared: Arc<Shared>,
    stop: CancellationToken,
) {
    let mut items: Vec<Taken> = Vec::new();
    let mut batch: Vec<(Arc<Outlet>, Arc<fleetlink_relay::Message>)> = Vec::new();
    loop {
        outbox.take_into(&mut items, 256, 1 << 20, Instant::now());
        if items.is_empty() {
            if outbox.is_closed() {
                return;
            }
            tokio::select! {
                _ = stop.cancelled() => return,
                _ = outbox.ready() => continue,
            }
        }
        {
            let outlets = outlets.lock();
            for (_, _, msg) in items.drain(..) {
                if let Some(o) = outlets.get(&msg.topic.id) {
                    batch.push((o.clone(), msg));
                }
            }
        }
        for (o, msg) in batch.drain(..) {
            let epoch = o.topic.reliable_epoch();
            let header = MessageHeader {
                encoding: msg.payload.encoding,
                seq: msg.seq,
                stamp_ns: msg.stamp_ns,
                reliable: epoch,
            };
            let len = msg.payload.len() as u64;
            let payload = zenoh::bytes::ZBytes::from(msg.payload.bytes.clone());
            let put = match (&o.publisher, epoch) {
                (Some(p), None) => p.put(payload).attachment(header.encode()).await,
                (_, reliable) => {
                    let congestion = if reliable.is_some() {
                        CongestionControl::Block
                    } else {
                        CongestionControl::Drop
                    };
                    session
                        .put(&o.key, payload)
                        .attachment(header.encode())
                        .congestion_control(congestion)
                        .allowed_destination(Locality::Remote)
                        .await
                }
            };
            match put {
                Ok(()) => {
                    o.figures.sent.fetch_add(1, Relaxed);
                    shared.counters.sent.fetch_add(1, Relaxed);
                    shared.counters.sent_bytes.fetch_add(len, Relaxed);
                }
                Err(e) => {
                    shared.counters.send_failed.fetch_add(1, Relaxed);
                    tracing::debug!("federation: put on {} failed: {e}", msg.topic.name);
                }
            }
        }
    }
}
