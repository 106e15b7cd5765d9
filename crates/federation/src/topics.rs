//! Topics between hubs: what this hub offers and wants, what the others offer and want,
//! and the messages that cross because of it.
//!
//! One loop follows every topic of this router ([`Router::watch_topics`]) and the fleet's
//! liveliness tokens (`cat/**`, history included; a hub that dies takes its tokens with
//! it), and keeps, per topic name, four things true:
//!
//! 1. **Offer.** A topic with a publisher here other than the federation has an offer
//!    token (name, type, latched): the other hubs list it.
//! 2. **Import.** A topic other hubs offer is advertised here by the federation with
//!    its type and full definition (asked of an offering hub when this hub does not know
//!    the type): listings show it, pattern subscribers attach to it.
//! 3. **Want.** While someone here subscribes to a topic (a client other than the
//!    federation that is not one of its publishers, [`Topic::demand_besides`]), the
//!    federation holds one Zenoh subscriber for it — one per hub, however many subscribe
//!    here — and a want token. What is heard is taken only from admitted hubs that offer
//!    the topic, through this hub's rules for each ([`crate::inlet`]), and published here
//!    unchanged.
//! 4. **Send.** While another hub wants a topic, the federation subscribes to it here
//!    (quietly: the subscription does not list the topic) and puts each message into
//!    Zenoh once. It subscribes even before anyone publishes the topic here, so a robot
//!    that arrives (or moves here from a hub that died) hears the interest with its
//!    `ADVERTISE` and its first message — a no-drop message resent on arrival included —
//!    already goes to the hubs that want it.
//!
//! The robots online here are offered as tokens too, for the other hubs' listings, and
//! the keyframe asks of video topics cross both ways beside the messages
//! ([`crate::keyframes`]).

mod listen;
mod news;
mod outlet;
mod services;

use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};
use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::{Duration, Instant};

use fleetlink_hub::registry::Registry;
use fleetlink_proto::Schema;
use fleetlink_relay::router::{SubscriptionId, TopicsWatch};
use fleetlink_relay::{Outbox, Router, TopicId, TopicName};
use tokio_util::sync::CancellationToken;
use zenoh::Session;
use zenoh::liveliness::LivelinessToken;
use zenoh::pubsub::Subscriber;
use zenoh::sample::SampleKind;

use crate::keyframes::{self, Answerer, Asker};
use crate::keys::{self, Offer};
use crate::{ExportFigures, FederationError, ImportFigures, Peer, Shared, zerr};
use listen::Listening;
use news::{Inbox, News, NewsKey, Parked};
use outlet::Outlets;
use services::Services;

pub use services::Providers;

/// Everything the federation does about one topic name.
#[derive(Default)]
struct Entry {
    /// Offered here: the token's key (type and flags in it) and the token.
    offer: Option<(String, LivelinessToken)>,
    /// Offered by other hubs: their announced type and latch, by hub id.
    offered_by: HashMap<String, (String, bool)>,
    /// Advertised here by the federation (imported), and whether a definition was asked.
    imported: bool,
    asked_schema: bool,
    /// Wanted here: the want token (while someone here subscribes), and one Zenoh
    /// subscriber per admitted hub that offers the topic — nothing is heard from a hub
    /// that does not offer it.
    listening: Option<Listening>,
    /// Wanted by other hubs (their ids).
    wanted_by: HashSet<String>,
    /// Sent from here: the federation's subscription and the outlet's topic id.
    sending: Option<(SubscriptionId, TopicId)>,
    export_figures: Option<Arc<ExportFigures>>,
    import_figures: Option<Arc<ImportFigures>>,
}

impl Entry {
    fn is_empty(&self) -> bool {
        self.offer.is_none()
            && self.offered_by.is_empty()
            && !self.imported
            && self.listening.is_none()
            && self.wanted_by.is_empty()
            && self.sending.is_none()
    }
}

pub struct Topics {
    session: Session,
    router: Arc<Router>,
    shared: Arc<Shared>,
    watch: Arc<TopicsWatch>,
    outbox: Arc<Outbox>,
    /// One per topic another hub wants ([`outlet`]).
    outlets: Outlets,
    /// One per topic name that something is done about: offered here or by an admitted
    /// hub, wanted here or by one, imported or sent; let go when nothing is
    /// ([`Entry::is_empty`]).
    entries: HashMap<TopicName, Entry>,
    /// Names published here that cannot be key expressions, logged once: one per such
    /// name for the hub's life (names of this hub's publishers, not of other hubs).
    refused: BTreeSet<String>,
    /// Coalesced by token ([`Inbox`]).
    inbox: Arc<Inbox>,
    _catalog: Subscriber<()>,
    /// Keyframe asks of the topics wanted here, and the other hubs' asks heard.
    asker: Arc<Asker>,
    _keyframes: Subscriber<()>,
    /// The robots online here, offered as tokens.
    robots: HashMap<String, LivelinessToken>,
    /// One per service or action an admitted hub offers.
    services: Services,
    /// Tokens of hubs not admitted (yet), by hub: taken when the hub is admitted; bounded
    /// in hubs and in tokens per hub ([`Parked`]).
    parked: Parked,
}

impl Topics {
    pub async fn start(
        session: Session,
        router: Arc<Router>,
        shared: Arc<Shared>,
        outbox: Arc<Outbox>,
    ) -> Result<Topics, FederationError> {
        let inbox = Arc::new(Inbox::default());
        let posted = inbox.clone();
        let fleet = shared.fleet.clone();
        let me = shared.me.clone();
        let catalog = session
            .liveliness()
            .declare_subscriber(format!("{}/cat/**", keys::root(&shared.fleet)))
            .history(true)
            .callback(move |sample| {
                let Some((hub, offer)) = keys::parse_offer(&fleet, sample.key_expr().as_str())
                else {
                    return;
                };
                if hub != me {
                    let put = sample.kind() == SampleKind::Put;
                    let key = NewsKey::Token(sample.key_expr().as_str().to_owned());
                    posted.post(key, News::Token { hub, offer, put });
                }
            })
            .await
            .map_err(zerr)?;
        let answerer = Arc::new(Answerer::new(router.clone(), shared.clone()));
        let keyframes = keyframes::answer(&session, answerer).await?;
        Ok(Topics {
            watch: router.watch_topics(),
            services: Services::new(router.clone(), shared.client),
            session,
            router,
            shared,
            outbox,
            outlets: Outlets::default(),
            entries: HashMap::new(),
            refused: BTreeSet::new(),
            inbox,
            _catalog: catalog,
            asker: Arc::default(),
            _keyframes: keyframes,
            robots: HashMap::new(),
            parked: Parked::default(),
        })
    }

    pub fn providers(&self) -> Providers {
        self.services.providers()
    }

    pub async fn run(mut self, registry: Arc<Registry>, stop: CancellationToken) {
        let pump = outlet::pump(
            self.session.clone(),
            self.outbox.clone(),
            self.outlets.clone(),
            self.shared.clone(),
            stop.clone(),
        );
        let asks = keyframes::ask_loop(
            self.session.clone(),
            self.asker.clone(),
            self.shared.clone(),
            stop.clone(),
        );
        let mut admitted = self.shared.admission.subscribe();
        let work = async {
            // The robots online are compared with what was offered whenever they change
            // (and once at the start).
            let mut robots = registry.watch();
            robots.mark_changed();
            loop {
                tokio::select! {
                    _ = stop.cancelled() => break,
                    _ = self.watch.changed() => {
                        for name in self.watch.take() {
                            self.evaluate(&name).await;
                        }
                    }
                    () = self.inbox.ready.notified() => {
                        // A hub joining offers a burst: apply it whole, then act once per topic.
                        let mut touched = HashSet::new();
                        for news in self.inbox.take() {
                            self.on_news(news, &mut touched);
                        }
                        for name in touched {
                            self.evaluate(&name).await;
                        }
                    }
                    Ok(()) = admitted.changed() => {
                        let mut touched = HashSet::new();
                        self.unpark(&mut touched);
                        for name in touched {
                            self.evaluate(&name).await;
                        }
                    }
                    Ok(()) = robots.changed() => {
                        self.sync_robots(&registry).await;
                    }
                }
            }
            for (_, e) in self.entries.drain() {
                if let Some((sid, _)) = e.sending {
                    self.router.unsubscribe(self.shared.client, sid);
                }
            }
        };
        tokio::join!(pump, asks, work);
    }

    /// Takes the parked tokens of hubs admitted since. Hubs refused keep nothing parked;
    /// a hub that left withdrew its tokens, which let it go already.
    fn unpark(&mut self, touched: &mut HashSet<TopicName>) {
        let admission = self.shared.admission.clone();
        let now = self.parked.take(
            |h| admission.is_admitted(h),
            |h| admission.refusal(h).is_some(),
        );
        for (hub, offers) in now {
            for offer in offers {
                self.on_news(
                    News::Token {
                        hub: hub.clone(),
                        offer,
                        put: true,
                    },
                    touched,
                );
            }
        }
    }

    fn on_news(&mut self, news: News, touched: &mut HashSet<TopicName>) {
        if let News::Token { hub, offer, put } = &news
            && !self.shared.admission.is_admitted(hub)
        {
            // Nothing a hub offers or wants counts before a link shows its certificate.
            self.parked.note(hub, offer, *put);
            return;
        }
        match news {
            News::Token { hub, offer, put } => match offer {
                Offer::Topic {
                    name,
                    type_name,
                    latched,
                } => {
                    let Ok(name) = TopicName::parse(&name) else {
                        return;
                    };
                    let e = self.entries.entry(name.clone()).or_default();
                    if put {
                        e.offered_by.insert(hub, (type_name, latched));
                    } else if e.offered_by.get(&hub).is_some_and(|(t, _)| *t == type_name) {
                        // (A hub that changed a topic's type withdraws the old offer after
                        // making the new one: only an offer of that type goes.)
                        e.offered_by.remove(&hub);
                    }
                    touched.insert(name);
                }
                Offer::Want { name } => {
                    let Ok(name) = TopicName::parse(&name) else {
                        return;
                    };
                    let e = self.entries.entry(name.clone()).or_default();
                    if put {
                        e.wanted_by.insert(hub);
                    } else {
                        e.wanted_by.remove(&hub);
                    }
                    touched.insert(name);
                }
                Offer::Service { name, type_name } => {
                    self.services.offer(hub, name, type_name, false, put)
                }
                Offer::Action { name, type_name } => {
                    self.services.offer(hub, name, type_name, true, put)
                }
                Offer::Robot { name } => {
                    let mut peers = self.shared.peers.lock().unwrap_or_else(|p| p.into_inner());
                    note_robot(&mut peers, hub, name, put);
                }
                Offer::Hub { name } => {
                    // Over TLS a hub is known by its certificate's name, not by this token.
                    let certified = self
                        .shared
                        .admission
                        .admitted(&hub)
                        .map(|a| a.name)
                        .filter(|n| !n.is_empty());
                    if let Some(cert) = &certified
                        && *cert != name
                    {
                        tracing::warn!(
                            "federation: hub {hub} calls itself {name:?}, its certificate names it {cert:?}: known as {cert:?}"
                        );
                    }
                    let name = certified.unwrap_or(name);
                    let mut peers = self.shared.peers.lock().unwrap_or_else(|p| p.into_inner());
                    if put {
                        tracing::info!("federation: hub {name} ({hub}) joined");
                        peers.entry(hub).or_default().name = name;
                    } else if let Some(p) = peers.remove(&hub) {
                        tracing::info!("federation: hub {} ({hub}) left", p.name);
                    }
                }
            },
            News::Schema { name, schema } => {
                if self.entries.get(&name).is_some_and(|e| e.imported) {
                    let latched = self.router.topic(&name).is_some_and(|t| t.is_latched());
                    if let Err(e) =
                        self.router
                            .advertise(self.shared.client, &name, schema, latched)
                    {
                        tracing::debug!("federation: definition of {name}: {e}");
                    }
                }
            }
        }
    }

    /// Brings what the federation does about `name` in line with the router and the
    /// fleet's tokens. Idempotent: what it changes on the router comes back as a change
    /// of the topic and finds nothing more to do.
    async fn evaluate(&mut self, name: &TopicName) {
        let me = self.shared.client;
        let snap = self.router.snapshot(name);
        let mut e = self.entries.remove(name).unwrap_or_default();

        // 1. Offer what is published here.
        let offer_key = snap.as_ref().and_then(|s| {
            if !s.publishers.iter().any(|c| *c != me) {
                return None;
            }
            if fleetlink_relay::names::hub_only(name.as_str()).is_some() {
                return None; // read by this hub only (a robot's black box)
            }
            let offer = Offer::Topic {
                name: name.as_str().to_owned(),
                type_name: s.meta.schema.type_name.clone(),
                latched: s.meta.latched,
            };
            let key = keys::offer_key(&self.shared.fleet, &self.shared.me, &offer);
            if key.is_none() && self.refused.insert(name.as_str().to_owned()) {
                tracing::warn!(
                    "federation: topic {name} (type {:?}) cannot be named in Zenoh; it stays on this hub",
                    s.meta.schema.type_name
                );
            }
            key
        });
        if e.offer.as_ref().map(|(k, _)| k) != offer_key.as_ref() {
            e.offer = None;
            if let Some(key) = offer_key {
                match self.session.liveliness().declare_token(key.clone()).await {
                    Ok(t) => e.offer = Some((key, t)),
                    Err(err) => tracing::warn!("federation: cannot offer {name}: {err}"),
                }
            }
        }

        // 2. Import what others offer.
        if !e.offered_by.is_empty() && !e.imported {
            let (hub, (type_name, latched)) = e
                .offered_by
                .iter()
                .next()
                .map(|(h, t)| (h.clone(), t.clone()))
                .expect("not empty");
            let known = self.router.transcoder().schema_for(&type_name);
            let schema = known
                .clone()
                .unwrap_or_else(|| Schema::named(type_name.clone()));
            match self.router.advertise(me, name, schema, latched) {
                Ok(_) => {
                    e.imported = true;
                    if known.is_none() && !e.asked_schema && !type_name.is_empty() {
                        e.asked_schema = true;
                        self.ask_schema(hub, name.clone());
                    }
                }
                Err(err) => tracing::warn!(
                    "federation: {name} offered by hub {}: {err}",
                    self.shared.peer_name(&hub)
                ),
            }
        } else if e.offered_by.is_empty() && e.imported {
            e.imported = false;
            e.asked_schema = false;
            self.router.unadvertise(me, name);
        }
        if !e.offered_by.is_empty() || e.listening.is_some() {
            let f = e.import_figures.get_or_insert_with(Arc::default).clone();
            let mut from: Vec<String> = e
                .offered_by
                .keys()
                .map(|h| self.shared.peer_name(h))
                .collect();
            from.sort();
            *f.from.lock().unwrap_or_else(|p| p.into_inner()) = from;
        }

        // 3. Listen while someone here wants it.
        let topic = self.router.topic(name);
        let demand = match (&snap, &topic) {
            (Some(s), Some(t)) => t.demand_besides(me, &s.publishers),
            _ => false,
        };
        if demand && e.listening.is_none() {
            if let Some(t) = &topic {
                let figures = e.import_figures.get_or_insert_with(Arc::default).clone();
                let want = listen::want(
                    &self.session,
                    &self.shared,
                    &self.asker,
                    name,
                    t.clone(),
                    figures,
                );
                match want.await {
                    Ok(l) => e.listening = Some(l),
                    Err(err) => tracing::warn!("federation: cannot subscribe to {name}: {err}"),
                }
            }
        } else if !demand && e.listening.is_some() {
            e.listening = None;
        }
        if let Some(l) = &e.listening {
            l.inlet.set_offerers(e.offered_by.keys(), Instant::now());
            if let Some(f) = &e.import_figures {
                f.subscribed.store(l.inlet.has_sources(), Relaxed);
            }
        } else if let Some(f) = &e.import_figures {
            f.subscribed.store(false, Relaxed);
        }

        // 4. Send while another hub wants it.
        let wanted = !e.wanted_by.is_empty();
        if wanted && e.sending.is_none() {
            match self.outlets.open(&self.router, &self.shared, name).await {
                Ok((sid, id, figures)) => {
                    e.sending = Some((sid, id));
                    e.export_figures = Some(figures);
                }
                Err(err) => tracing::warn!("federation: cannot send {name}: {err}"),
            }
        } else if !wanted && let Some((sid, id)) = e.sending.take() {
            self.router.unsubscribe(me, sid);
            self.outlets.close(id);
        }
        if let (Some((_, id)), Some(_)) = (e.sending, &e.offer) {
            self.outlets.declare_publisher(&self.session, id).await;
        }
        if e.offer.is_some() || e.sending.is_some() {
            let f = e.export_figures.get_or_insert_with(Arc::default);
            f.wanted.store(wanted, Relaxed);
        } else {
            e.export_figures = None;
        }
        if e.offered_by.is_empty() && e.listening.is_none() {
            e.import_figures = None;
        }

        self.publish_figures(name, &e);
        if !e.is_empty() {
            self.entries.insert(name.clone(), e);
        }
    }

    fn publish_figures(&self, name: &TopicName, e: &Entry) {
        let key = name.as_str().to_owned();
        let mut ex = self
            .shared
            .exports
            .lock()
            .unwrap_or_else(|p| p.into_inner());
        match &e.export_figures {
            Some(f) => {
                ex.insert(key.clone(), f.clone());
            }
            None => {
                ex.remove(&key);
            }
        }
        drop(ex);
        let mut im = self
            .shared
            .imports
            .lock()
            .unwrap_or_else(|p| p.into_inner());
        match &e.import_figures {
            Some(f) => {
                im.insert(key, f.clone());
            }
            None => {
                im.remove(&key);
            }
        }
    }
    /// Asks `hub` for the full definition of `name`'s type; the answer comes back as news.
    fn ask_schema(&self, hub: String, name: TopicName) {
        let Some(chunks) = keys::name_chunks(name.as_str()) else {
            return;
        };
        let key = format!("{}/schema/{hub}/{chunks}", keys::root(&self.shared.fleet));
        let session = self.session.clone();
        let inbox = self.inbox.clone();
        tokio::spawn(async move {
            let replies = match session.get(key).timeout(Duration::from_secs(5)).await {
                Ok(r) => r,
                Err(e) => {
                    tracing::debug!("federation: asking the definition of {name}: {e}");
                    return;
                }
            };
            while let Ok(reply) = replies.recv_async().await {
                let Ok(sample) = reply.result() else { continue };
                let Ok(v) =
                    serde_json::from_slice::<serde_json::Value>(&sample.payload().to_bytes())
                else {
                    continue;
                };
                let field = |k: &str| v.get(k).and_then(|s| s.as_str()).unwrap_or("").to_owned();
                let schema = Schema {
                    type_name: field("type"),
                    encoding: field("encoding"),
                    text: field("text"),
                };
                if !schema.text.is_empty() {
                    inbox.post(NewsKey::Schema(name.clone()), News::Schema { name, schema });
                    return;
                }
            }
        });
    }
    /// Offers the robots online here, withdraws those that left.
    async fn sync_robots(&mut self, registry: &Registry) {
        let online: BTreeSet<String> = registry.list().iter().map(|r| r.name.clone()).collect();
        self.robots.retain(|name, _| online.contains(name));
        for name in online {
            if self.robots.contains_key(&name) {
                continue;
            }
            let offer = Offer::Robot { name: name.clone() };
            let Some(key) = keys::offer_key(&self.shared.fleet, &self.shared.me, &offer) else {
                continue;
            };
            match self.session.liveliness().declare_token(key).await {
                Ok(token) => {
                    self.robots.insert(name, token);
                }
                Err(e) => tracing::warn!("federation: cannot offer robot {name}: {e}"),
            }
        }
    }
}

/// Hub `hub` offers (`put`) or withdrew robot `name`. A withdrawal never makes an entry:
/// a hub that left is removed with its robots, whatever order the ends of its tokens
/// come in, and leaves nothing behind.
fn note_robot(peers: &mut BTreeMap<String, Peer>, hub: String, name: String, put: bool) {
    if put {
        peers.entry(hub).or_default().robots.insert(name);
    } else if let Some(peer) = peers.get_mut(&hub) {
        peer.robots.remove(&name);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hub_that_left_leaves_no_peer_behind_whatever_the_order_of_its_tokens() {
        let mut peers = BTreeMap::new();
        note_robot(&mut peers, "h1".into(), "r1".into(), true);
        note_robot(&mut peers, "h1".into(), "r2".into(), true);
        // The hub's own token ends first: it is removed with its robots ...
        peers.remove("h1");
        // ... and the ends of its robots' tokens that come after bring nothing back.
        note_robot(&mut peers, "h1".into(), "r1".into(), false);
        note_robot(&mut peers, "h1".into(), "r2".into(), false);
        assert!(peers.is_empty());

        note_robot(&mut peers, "h2".into(), "r3".into(), true);
        note_robot(&mut peers, "h2".into(), "r3".into(), false);
        assert!(peers["h2"].robots.is_empty(), "a hub still there stays");
    }
}
