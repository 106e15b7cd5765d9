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

use std::collections::{BTreeSet, HashMap, HashSet};
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_hub::registry::Registry;
use fleetlink_proto::Schema;
use fleetlink_relay::outbox::Taken;
use fleetlink_relay::router::{SubOptions, SubscriptionId, Target, TopicsWatch};
use fleetlink_relay::{Outbox, Router, Topic, TopicId, TopicName};
use tokio::sync::Notify;
use tokio_util::sync::CancellationToken;
use zenoh::Session;
use zenoh::liveliness::LivelinessToken;
use zenoh::pubsub::{Publisher, Subscriber};
use zenoh::qos::CongestionControl;
use zenoh::sample::{Locality, SampleKind};

use crate::inlet::Inlet;
use crate::keyframes::{self, Answerer, Asker};
use crate::keys::{self, MessageHeader, Offer};
use crate::{ExportFigures, FederationError, ImportFigures, Shared, zerr};

/// Tokens kept per hub not admitted yet (its links' certificates not seen yet): a hub
/// joining offers its whole catalog at once; beyond this it is offering too much to be one.
const PARKED_PER_HUB: usize = 100_000;

/// Which hub provides each remote service or action this hub routes calls to.
pub type Providers = Arc<Mutex<HashMap<TopicName, String>>>;

/// What the catalog's tokens and the definitions asked of other hubs tell the topic loop.
enum News {
    Token {
        hub: String,
        offer: Offer,
        put: bool,
    },
    Schema {
        name: TopicName,
        schema: Schema,
    },
}

/// The topic loop's news, coalesced. Zenoh hands the catalog's tokens to a callback on its
/// own threads, which must not wait; rather than queueing every change there, a token's
/// latest state replaces the one not read yet (a hub offering and withdrawing a topic a
/// thousand times leaves one entry), so what waits is bounded by the tokens there are and
/// the definitions asked for. They are read in the order each was first heard; one
/// token's state never depends on another's, so the end state is the one a queue gives.
#[derive(Default)]
struct Inbox {
    pending: Mutex<Pending>,
    ready: Notify,
}

#[derive(Default)]
struct Pending {
    order: Vec<NewsKey>,
    latest: HashMap<NewsKey, News>,
}

/// What a piece of news replaces: a token by its key expression, a definition by topic.
#[derive(Clone, PartialEq, Eq, Hash)]
enum NewsKey {
    Token(String),
    Schema(TopicName),
}

impl Inbox {
    fn post(&self, key: NewsKey, news: News) {
        let mut p = self.pending.lock().unwrap_or_else(|p| p.into_inner());
        if p.latest.insert(key.clone(), news).is_none() {
            p.order.push(key);
        }
        drop(p);
        self.ready.notify_one();
    }

    /// Everything posted since the last call, oldest first.
    fn take(&self) -> Vec<News> {
        let Pending { order, mut latest } =
            std::mem::take(&mut *self.pending.lock().unwrap_or_else(|p| p.into_inner()));
        order.iter().filter_map(|k| latest.remove(k)).collect()
    }
}

/// What the pump needs of a topic this hub sends.
///
/// Design choice: a declared `Publisher` only for a topic that is both wanted elsewhere
/// and published here; the quiet subscriptions a hub holds for topics nobody publishes
/// there (yet) send through `Session::put` if a message comes before the publisher.
/// Zenoh 1.10 matches every new declaration against all it knows
/// (`Resource::get_matches`), so a publisher declared for each of 10,000 topics wanted
/// elsewhere kept an idle hub busy for many seconds; a declared publisher is cheaper per
/// message than a put. A no-drop topic's messages always go by put with congestion
/// control `Block` (they wait for room in Zenoh's queues); the rest drop under
/// congestion rather than stall every topic behind one slow hub. Whether a topic is
/// no-drop is known only when its robot advertises, possibly after another hub wanted it.
struct Outlet {
    key: zenoh::key_expr::KeyExpr<'static>,
    publisher: Option<Publisher<'static>>,
    topic: Arc<Topic>,
    figures: Arc<ExportFigures>,
}

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

/// A topic wanted here: the want token, the Zenoh subscriber to every hub's key for it,
/// and the intake that decides what of it is taken ([`Inlet`]).
struct Listening {
    _want: LivelinessToken,
    _sub: Subscriber<()>,
    inlet: Arc<Inlet>,
}

/// A remote service or action: the hubs offering it, with type and kind.
#[derive(Default)]
struct RemoteService {
    from: HashMap<String, (String, bool)>,
}

pub struct Topics {
    session: Session,
    router: Arc<Router>,
    shared: Arc<Shared>,
    watch: Arc<TopicsWatch>,
    outbox: Arc<Outbox>,
    outlets: Arc<Mutex<HashMap<TopicId, Arc<Outlet>>>>,
    entries: HashMap<TopicName, Entry>,
    /// Names that cannot be key expressions, logged once.
    refused: BTreeSet<String>,
    inbox: Arc<Inbox>,
    _catalog: Subscriber<()>,
    /// Keyframe asks of the topics wanted here, and the other hubs' asks heard.
    asker: Arc<Asker>,
    _keyframes: Subscriber<()>,
    robots: HashMap<String, LivelinessToken>,
    services: HashMap<TopicName, RemoteService>,
    providers: Providers,
    /// Tokens of hubs not admitted (yet), by hub: taken when the hub is admitted.
    parked: HashMap<String, Vec<(Offer, bool)>>,
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
            session,
            router,
            shared,
            outbox,
            outlets: Arc::default(),
            entries: HashMap::new(),
            refused: BTreeSet::new(),
            inbox,
            _catalog: catalog,
            asker: Arc::default(),
            _keyframes: keyframes,
            robots: HashMap::new(),
            services: HashMap::new(),
            providers: Arc::default(),
            parked: HashMap::new(),
        })
    }

    pub fn providers(&self) -> Providers {
        self.providers.clone()
    }

    pub async fn run(mut self, registry: Arc<Registry>, stop: CancellationToken) {
        let pump = pump(
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

    /// Takes the parked tokens of hubs admitted since.
    fn unpark(&mut self, touched: &mut HashSet<TopicName>) {
        let now: Vec<String> = self
            .parked
            .keys()
            .filter(|h| self.shared.admission.is_admitted(h))
            .cloned()
            .collect();
        for hub in now {
            for (offer, put) in self.parked.remove(&hub).unwrap_or_default() {
                self.on_news(
                    News::Token {
                        hub: hub.clone(),
                        offer,
                        put,
                    },
                    touched,
                );
            }
        }
        // Hubs refused or gone for good keep nothing parked for long.
        let admission = &self.shared.admission;
        self.parked
            .retain(|hub, _| admission.refusal(hub).is_none());
    }

    fn on_news(&mut self, news: News, touched: &mut HashSet<TopicName>) {
        if let News::Token { hub, offer, put } = &news
            && !self.shared.admission.is_admitted(hub)
        {
            // Nothing a hub offers or wants counts before a link shows its certificate.
            let tokens = self.parked.entry(hub.clone()).or_default();
            if *put {
                if tokens.len() < PARKED_PER_HUB {
                    tokens.push((offer.clone(), true));
                }
            } else {
                tokens.retain(|(o, _)| o != offer);
            }
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
                    self.service(hub, name, type_name, false, put)
                }
                Offer::Action { name, type_name } => self.service(hub, name, type_name, true, put),
                Offer::Robot { name } => {
                    let mut peers = self.shared.peers.lock().unwrap_or_else(|p| p.into_inner());
                    let peer = peers.entry(hub).or_default();
                    if put {
                        peer.robots.insert(name);
                    } else {
                        peer.robots.remove(&name);
                    }
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
                match self.want(name, t.clone(), figures).await {
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
            match self.send(name).await {
                Ok((sid, id, figures)) => {
                    e.sending = Some((sid, id));
                    e.export_figures = Some(figures);
                }
                Err(err) => tracing::warn!("federation: cannot send {name}: {err}"),
            }
        } else if !wanted && let Some((sid, id)) = e.sending.take() {
            self.router.unsubscribe(me, sid);
            self.outlets
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .remove(&id);
        }
        if let (Some((_, id)), Some(_)) = (e.sending, &e.offer) {
            self.declare_publisher(id).await;
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

    /// The want token that tells the hubs with publishers to send `name`, and one Zenoh
    /// subscriber to what any hub puts of it, taken by an [`Inlet`] (declared while
    /// someone here subscribes, whether or not a hub offers it yet).
    async fn want(
        &self,
        name: &TopicName,
        topic: Arc<Topic>,
        figures: Arc<ImportFigures>,
    ) -> Result<Listening, FederationError> {
        let not_a_key = || FederationError::Zenoh(format!("{name} cannot be a Zenoh key"));
        let want = keys::offer_key(
            &self.shared.fleet,
            &self.shared.me,
            &Offer::Want {
                name: name.as_str().to_owned(),
            },
        )
        .ok_or_else(not_a_key)?;
        let key = keys::topic_key(&self.shared.fleet, "*", name.as_str()).ok_or_else(not_a_key)?;
        let inlet = Inlet::new(topic, self.shared.clone(), figures, self.asker.clone());
        let prefix = format!("{}/t/", keys::root(&self.shared.fleet));
        let shared = self.shared.clone();
        let into = inlet.clone();
        let sub = self
            .session
            .declare_subscriber(key)
            .allowed_origin(Locality::Remote)
            .callback(move |sample| {
                let counters = &shared.counters;
                let Some(hub) = sample
                    .key_expr()
                    .as_str()
                    .strip_prefix(&prefix)
                    .and_then(|rest| rest.split('/').next())
                else {
                    counters.malformed.fetch_add(1, Relaxed);
                    return;
                };
                let header = match sample
                    .attachment()
                    .map(|a| MessageHeader::decode(&a.to_bytes()))
                {
                    Some(Ok(h)) => h,
                    Some(Err(e)) => {
                        counters.malformed.fetch_add(1, Relaxed);
                        tracing::debug!("federation: message on {}: {e}", sample.key_expr());
                        return;
                    }
                    None => {
                        counters.malformed.fetch_add(1, Relaxed);
                        return;
                    }
                };
                let bytes = bytes::Bytes::from(sample.payload().to_bytes().into_owned());
                into.take(hub, header, bytes, Instant::now());
            })
            .await
            .map_err(zerr)?;
        let token = self
            .session
            .liveliness()
            .declare_token(want)
            .await
            .map_err(zerr)?;
        Ok(Listening {
            _want: token,
            _sub: sub,
            inlet,
        })
    }

    /// Subscribes here on behalf of the hubs that want `name`, with a Zenoh publisher for
    /// what arrives.
    async fn send(
        &self,
        name: &TopicName,
    ) -> Result<(SubscriptionId, TopicId, Arc<ExportFigures>), FederationError> {
        let key = keys::topic_key(&self.shared.fleet, &self.shared.me, name.as_str())
            .ok_or_else(|| FederationError::Zenoh(format!("{name} cannot be a Zenoh key")))?;
        let sid = self
            .router
            .subscribe(
                self.shared.client,
                Target::Exact(name.clone()),
                SubOptions {
                    unlisted: true,
                    ..SubOptions::default()
                },
            )
            .map_err(|e| FederationError::Zenoh(e.to_string()))?;
        let topic = self
            .router
            .topic(name)
            .expect("a subscription keeps its topic");
        let key = match zenoh::key_expr::KeyExpr::try_from(key) {
            Ok(k) => k,
            Err(e) => {
                self.router.unsubscribe(self.shared.client, sid);
                return Err(zerr(e));
            }
        };
        let figures = Arc::new(ExportFigures::default());
        let id = topic.id();
        self.outlets
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(
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

    /// Gives the outlet of topic `id` a declared publisher, once.
    async fn declare_publisher(&self, id: TopicId) {
        let Some(o) = self
            .outlets
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(&id)
            .filter(|o| o.publisher.is_none())
            .cloned()
        else {
            return;
        };
        let declared = self
            .session
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
                let mut outlets = self.outlets.lock().unwrap_or_else(|p| p.into_inner());
                // Still the same outlet (not withdrawn meanwhile).
                if outlets.get(&id).is_some_and(|cur| Arc::ptr_eq(cur, &o)) {
                    outlets.insert(id, with);
                }
            }
            Err(e) => tracing::debug!("federation: publisher for {}: {e}", o.key),
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

    /// A remote hub offers (or withdrew) a service or action: this hub provides it through
    /// the federation while no client here provides it itself.
    fn service(&mut self, hub: String, name: String, type_name: String, action: bool, put: bool) {
        let Ok(name) = TopicName::parse(&name) else {
            return;
        };
        let me = self.shared.client;
        let calls = &self.router.calls;
        let entry = self.services.entry(name.clone()).or_default();
        if put {
            entry.from.insert(hub, (type_name, action));
        } else if entry
            .from
            .get(&hub)
            .is_some_and(|(t, a)| *t == type_name && *a == action)
        {
            entry.from.remove(&hub);
        } else {
            return;
        }
        let mut providers = self.providers.lock().unwrap_or_else(|p| p.into_inner());
        // Keep the current provider hub while it offers; otherwise take any other.
        let next = match providers.get(&name) {
            Some(h) if entry.from.contains_key(h) => Some(h.clone()),
            _ => entry.from.keys().next().cloned(),
        };
        match next {
            Some(h) => {
                if calls.service(&name).is_some_and(|s| s.provider != me) {
                    return; // a client here provides it: calls stay on this hub
                }
                let (type_name, action) = entry.from[&h].clone();
                providers.insert(name.clone(), h);
                drop(providers);
                calls.advertise(me, name, Schema::named(type_name), action);
            }
            None => {
                providers.remove(&name);
                drop(providers);
                self.services.remove(&name);
                calls.unadvertise(me, &name);
            }
        }
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

/// Puts what the federation's subscriptions receive into Zenoh: each message once, its
/// payload as it is (a reference to the received bytes, no copy), the header beside it.
async fn pump(
    session: Session,
    outbox: Arc<Outbox>,
    outlets: Arc<Mutex<HashMap<TopicId, Arc<Outlet>>>>,
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
            let outlets = outlets.lock().unwrap_or_else(|p| p.into_inner());
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

#[cfg(test)]
mod tests {
    use super::*;

    fn token(inbox: &Inbox, key: &str, name: &str, put: bool) {
        let offer = Offer::Want { name: name.into() };
        let news = News::Token {
            hub: "h1".into(),
            offer,
            put,
        };
        inbox.post(NewsKey::Token(key.into()), news);
    }

    /// (name, put) of each token read.
    fn read(inbox: &Inbox) -> Vec<(String, bool)> {
        inbox
            .take()
            .into_iter()
            .map(|n| match n {
                News::Token {
                    offer: Offer::Want { name },
                    put,
                    ..
                } => (name, put),
                _ => panic!("only wants were posted"),
            })
            .collect()
    }

    #[test]
    fn news_of_one_token_coalesce_to_its_latest_state_in_first_heard_order() {
        let inbox = Inbox::default();
        for i in 0..1000 {
            token(&inbox, "k/a", "/a", i % 2 == 0);
        }
        token(&inbox, "k/b", "/b", true);
        token(&inbox, "k/a", "/a", true);
        token(&inbox, "k/b", "/b", false);
        assert_eq!(
            read(&inbox),
            [("/a".to_owned(), true), ("/b".to_owned(), false)]
        );
        assert!(read(&inbox).is_empty(), "what was read is gone");
        token(&inbox, "k/a", "/a", false);
        assert_eq!(read(&inbox), [("/a".to_owned(), false)]);
    }
}
