//! The agent's node in the ROS graph: what it publishes, subscribes and serves, shared by
//! the tasks that drive it, and its slave XML-RPC API.
//!
//! State lives behind one `std::sync::Mutex` ([`Node::state`]): every critical section is
//! a few map operations, never held across an `.await`.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};

use bytes::Bytes;
use fleetlink_relay::calls::{CallEvent, CallId};
use fleetlink_relay::stats::{AdapterReport, Problems};
use fleetlink_relay::transcode::Ros1Identity;
use fleetlink_relay::{ClientId, Router, Topic};
use tokio::net::TcpListener;
use tokio::sync::{mpsc, oneshot};
use tokio::task::AbortHandle;
use tokio_util::sync::CancellationToken;

use crate::http::{Reader, write_response};
use crate::master::Master;
use crate::options::Ros1Options;
use crate::xmlrpc::{Value, decode_call, encode_fault, encode_response};

/// Frames queued per local subscriber before newer ones are dropped (a subscriber that
/// stops reading must not hold memory without bound).
pub const SUBSCRIBER_QUEUE: usize = 64;
/// Bytes queued per local subscriber before newer frames are dropped: eight 1 MiB point
/// clouds, not 64. A frame larger than this still goes to a subscriber with nothing queued.
pub const SUBSCRIBER_QUEUE_BYTES: usize = 8 << 20;

/// One local subscriber's queue: the frames, and how many bytes they hold.
pub struct SubscriberTx {
    pub conn: u64,
    pub tx: mpsc::Sender<Bytes>,
    /// Bytes sent into `tx` and not yet written to the subscriber's socket.
    pub queued: Arc<std::sync::atomic::AtomicUsize>,
}

/// A topic this node publishes into the graph (hub → robot).
pub struct Publication {
    pub topic: String,
    pub identity: Ros1Identity,
    pub latched: bool,
    /// Connections of local subscribers and the latched frame. std Mutex: pushes only.
    pub out: Mutex<PubOut>,
    /// Frames dropped because a local subscriber's queue was full.
    pub dropped: AtomicU64,
    /// The adapter's counters: its drops are added to `dropped_down` there too.
    pub stats: Arc<Ros1Stats>,
}

#[derive(Default)]
pub struct PubOut {
    pub conns: Vec<SubscriberTx>,
    pub last: Option<Bytes>,
    /// Set while a new publication waits for the subscribers the master knew of.
    pub held: Option<Held>,
}

/// How long a new publication's first messages wait for the local subscribers the
/// master listed when it was registered.
pub const HOLD_FOR_SUBSCRIBERS: std::time::Duration = std::time::Duration::from_secs(1);

/// A new publication's messages, held until the subscribers the master listed when it
/// was registered have connected (or [`HOLD_FOR_SUBSCRIBERS`] has passed). A ROS 1
/// subscriber connects only after the master tells it of the publisher, so without this
/// a node waiting for a hub topic missed its first message (latched topics are not
/// held: a subscriber that connects gets their last message anyway).
pub struct Held {
    /// How many subscribers to wait for; `None` until the registration answered.
    pub expect: Option<usize>,
    pub until: std::time::Instant,
    pub frames: std::collections::VecDeque<Bytes>,
}

/// How many messages a new publication holds at most (the oldest go first).
const HELD_MAX: usize = 10;

impl Publication {
    /// Ends the publication: its subscribers' connections close (their queues' senders
    /// go) and nothing is kept for late ones.
    pub fn close(&self) {
        let mut out = self.out.lock().unwrap_or_else(|p| p.into_inner());
        out.conns.clear();
        out.last = None;
        out.held = None;
    }

    /// Queues a framed message for every connected subscriber (never waits), or holds it
    /// while the publication waits for its subscribers ([`Held`]).
    pub fn publish(&self, frame: Bytes) {
        let mut out = self.out.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(h) = &mut out.held {
            h.frames.push_back(frame);
            if h.frames.len() > HELD_MAX {
                h.frames.pop_front();
                self.drop_one();
            }
            self.release_held(&mut out);
            return;
        }
        self.send(&mut out, frame);
    }

    /// Sends the held messages once every expected subscriber has connected or the wait
    /// is over.
    pub fn release_held(&self, out: &mut PubOut) {
        let Some(h) = &out.held else {
            return;
        };
        let connected = h.expect.is_some_and(|n| out.conns.len() >= n);
        if !connected && std::time::Instant::now() < h.until {
            return;
        }
        let frames = out.held.take().map(|h| h.frames).unwrap_or_default();
        for f in frames {
            self.send(out, f);
        }
    }

    fn send(&self, out: &mut PubOut, frame: Bytes) {
        out.conns.retain(|s| {
            let queued = s.queued.load(Relaxed);
            if queued > 0 && queued + frame.len() > SUBSCRIBER_QUEUE_BYTES {
                self.drop_one();
                return !s.tx.is_closed();
            }
            match s.tx.try_send(frame.clone()) {
                Ok(()) => {
                    s.queued.fetch_add(frame.len(), Relaxed);
                    true
                }
                Err(mpsc::error::TrySendError::Full(_)) => {
                    self.drop_one();
                    true
                }
                Err(mpsc::error::TrySendError::Closed(_)) => false,
            }
        });
        if self.latched {
            out.last = Some(frame);
        }
    }

    fn drop_one(&self) {
        self.dropped.fetch_add(1, Relaxed);
        self.stats.dropped_down.fetch_add(1, Relaxed);
    }
}

/// A topic this node subscribes to in the graph (robot → hub).
pub struct Subscription {
    pub ros_type: String,
    /// Open connections by publisher API URI.
    pub conns: HashMap<String, Conn>,
    /// Sequence numbers of messages published into the router, shared by connections.
    pub seq: Arc<AtomicU64>,
    /// The publishers' APIs the master last listed, kept while reading is paused.
    pub publishers: Vec<String>,
    /// Not read for now: nobody wants the topic ([`crate::bridge`], `follow_interest`).
    pub paused: bool,
    /// Since when nobody has wanted it, while that lasts.
    pub unwanted_since: Option<std::time::Instant>,
}

pub struct Conn {
    pub id: u64,
    pub abort: AbortHandle,
}

/// A fleet service this node serves to local callers.
pub struct Offered {
    /// `pkg/srv/T` as the call table names it.
    pub srv_type: String,
    pub identity: Ros1Identity,
}

/// A local ROS service this node offers to the fleet.
pub struct Exposed {
    pub srv_type: String,
    pub md5sum: String,
}

#[derive(Default)]
pub struct State {
    pub pubs: HashMap<String, Arc<Publication>>,
    pub subs: HashMap<String, Subscription>,
    pub offered: HashMap<String, Offered>,
    pub exposed: HashMap<String, Exposed>,
    /// What is registered with the current master (cleared when it restarts).
    pub registered_pubs: std::collections::HashSet<String>,
    pub registered_services: std::collections::HashSet<String>,
    /// Topics whose type conflicts (local vs hub), reported once each.
    pub mismatched: std::collections::HashSet<String>,
}

/// A call to a fleet service: its answer may arrive before the waiter is registered, or
/// after the waiter gave up (the table always ends a call, at its deadline at the latest,
/// so every entry is removed eventually).
enum Waiter {
    Waiting(oneshot::Sender<CallEvent>),
    Arrived(CallEvent),
    Abandoned,
}

/// Counters and problems, for logs, tests and the agent's status topic.
#[derive(Default, Debug)]
pub struct Ros1Stats {
    pub messages_up: AtomicU64,
    pub messages_down: AtomicU64,
    pub type_mismatches: AtomicU64,
    pub master_registrations: AtomicU64,
    /// Hub messages a slow local subscriber missed (its queue was full).
    pub dropped_down: AtomicU64,
    /// Each type mismatch as its log line says it.
    pub problems: Problems,
    /// Times a topic stopped being read because nobody wanted it.
    pub paused: AtomicU64,
}

impl AdapterReport for Ros1Stats {
    fn counters(&self) -> Vec<(&'static str, u64)> {
        let get = |c: &AtomicU64| c.load(Relaxed);
        vec![
            ("messages_up", get(&self.messages_up)),
            ("messages_down", get(&self.messages_down)),
            ("dropped_down", get(&self.dropped_down)),
            ("type_mismatches", get(&self.type_mismatches)),
            ("master_registrations", get(&self.master_registrations)),
            ("paused_reading", get(&self.paused)),
        ]
    }

    fn problems(&self) -> Vec<String> {
        self.problems.list()
    }
}

pub struct Node {
    /// The options the node started with (what crosses is [`Node::live`]'s).
    pub opts: Ros1Options,
    /// The options in force: `opts`, or the last runtime change of them.
    pub live: std::sync::RwLock<Arc<Ros1Options>>,
    /// Woken when what crosses changed: the discovery looks at once.
    pub rediscover: tokio::sync::Notify,
    pub router: Arc<Router>,
    pub client: ClientId,
    pub master: Master,
    /// `rosrpc://host:port` of this node's TCPROS listener (services).
    pub service_api: String,
    pub tcpros_port: u16,
    pub state: Mutex<State>,
    waiters: Mutex<HashMap<CallId, Waiter>>,
    pub stats: Arc<Ros1Stats>,
    next_conn: AtomicU64,
    /// Publisher lists from `publisherUpdate` for the bridge loop.
    pub updates: PublisherUpdates,
}

/// Publisher lists the master sent (`publisherUpdate`, from the network) that the bridge
/// loop has not acted on yet. Only the current list of a topic matters, so a newer one
/// replaces an older one still waiting (counted in `coalesced`); and only topics this node
/// subscribes to are kept (the others mean nothing here), so what waits is bounded by the
/// node's subscriptions whatever the network sends.
#[derive(Default)]
pub struct PublisherUpdates {
    // std Mutex: an insert or a take, never held across an await.
    pending: Mutex<HashMap<String, Vec<String>>>,
    ready: tokio::sync::Notify,
    /// Lists replaced by a newer one before the bridge loop took them.
    pub coalesced: AtomicU64,
}

impl PublisherUpdates {
    /// The newest publisher list of `topic`.
    pub fn put(&self, topic: String, list: Vec<String>) {
        let replaced = self
            .pending
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(topic, list)
            .is_some();
        if replaced {
            self.coalesced.fetch_add(1, Relaxed);
        }
        self.ready.notify_one();
    }

    /// Every list waiting, once at least one is.
    pub async fn next(&self) -> Vec<(String, Vec<String>)> {
        loop {
            let ready = self.ready.notified();
            let taken: Vec<_> = self
                .pending
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .drain()
                .collect();
            if !taken.is_empty() {
                return taken;
            }
            ready.await;
        }
    }
}

impl Node {
    pub fn new(
        opts: Ros1Options,
        router: Arc<Router>,
        client: ClientId,
        slave_port: u16,
        tcpros_port: u16,
        stats: Arc<Ros1Stats>,
    ) -> Node {
        let caller_api = format!("http://{}:{slave_port}/", opts.host);
        let master = Master {
            uri: opts.master_uri.clone(),
            caller_id: opts.node_name.clone(),
            caller_api,
        };
        Node {
            service_api: format!("rosrpc://{}:{tcpros_port}", opts.host),
            tcpros_port,
            live: std::sync::RwLock::new(Arc::new(opts.clone())),
            rediscover: tokio::sync::Notify::new(),
            opts,
            router,
            client,
            master,
            state: Mutex::new(State::default()),
            waiters: Mutex::new(HashMap::new()),
            stats,
            next_conn: AtomicU64::new(1),
            updates: PublisherUpdates::default(),
        }
    }

    /// The options in force (what crosses may change while the node runs).
    pub fn live(&self) -> Arc<Ros1Options> {
        self.live.read().unwrap_or_else(|p| p.into_inner()).clone()
    }

    pub fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    pub fn next_conn_id(&self) -> u64 {
        self.next_conn.fetch_add(1, Relaxed)
    }

    /// The answer to call `id`, whenever it arrives.
    pub fn wait_for(&self, id: CallId) -> oneshot::Receiver<CallEvent> {
        let (tx, rx) = oneshot::channel();
        let mut w = self.waiters.lock().unwrap_or_else(|p| p.into_inner());
        match w.remove(&id) {
            Some(Waiter::Arrived(ev)) => {
                let _ = tx.send(ev);
            }
            _ => {
                w.insert(id, Waiter::Waiting(tx));
            }
        }
        rx
    }

    /// Hands a call's final event to its waiter (or keeps it until one comes).
    pub fn answer(&self, ev: CallEvent) {
        let mut w = self.waiters.lock().unwrap_or_else(|p| p.into_inner());
        match w.remove(&ev.id()) {
            Some(Waiter::Waiting(tx)) => {
                let _ = tx.send(ev);
            }
            Some(Waiter::Abandoned) => {}
            Some(Waiter::Arrived(_)) | None => {
                w.insert(ev.id(), Waiter::Arrived(ev));
            }
        }
    }

    /// A waiter that gave up (timeout): its answer, if one still comes, is dropped.
    pub fn forget(&self, id: CallId) {
        let mut w = self.waiters.lock().unwrap_or_else(|p| p.into_inner());
        if !matches!(w.remove(&id), Some(Waiter::Arrived(_))) {
            w.insert(id, Waiter::Abandoned);
        }
    }

    /// The router topic of a subscription, once its first publisher said its type.
    pub fn router_topic(&self, name: &str) -> Option<Arc<Topic>> {
        fleetlink_relay::TopicName::parse(name)
            .ok()
            .and_then(|n| self.router.topic(&n))
    }

    /// One slave API call.
    fn handle_slave(&self, method: &str, params: &[Value]) -> Value {
        let ok = |v: Value| Value::Array(vec![Value::Int(1), Value::from(""), v]);
        let fail =
            |text: String| Value::Array(vec![Value::Int(-1), Value::from(text), Value::Int(0)]);
        let param = |i: usize| params.get(i).and_then(|v| v.as_str()).unwrap_or("");
        match method {
            "getPid" => ok(Value::Int(std::process::id() as i32)),
            "getMasterUri" => ok(Value::from(self.opts.master_uri.as_str())),
            "getBusStats" => ok(Value::Array(vec![
                Value::Array(vec![]),
                Value::Array(vec![]),
                Value::Array(vec![]),
            ])),
            "getBusInfo" => ok(Value::Array(vec![])),
            "shutdown" => {
                tracing::warn!(
                    "ros1: {} asked this node to shut down ({}); the agent keeps running",
                    param(0),
                    param(1)
                );
                ok(Value::Int(0))
            }
            "paramUpdate" => ok(Value::Int(0)),
            "getPublications" => {
                let st = self.lock();
                ok(Value::Array(
                    st.pubs
                        .values()
                        .map(|p| {
                            Value::Array(vec![
                                p.topic.as_str().into(),
                                p.identity.type_name.as_str().into(),
                            ])
                        })
                        .collect(),
                ))
            }
            "getSubscriptions" => {
                let st = self.lock();
                ok(Value::Array(
                    st.subs
                        .iter()
                        .map(|(t, s)| {
                            Value::Array(vec![t.as_str().into(), s.ros_type.as_str().into()])
                        })
                        .collect(),
                ))
            }
            "publisherUpdate" => {
                let topic = param(1).to_owned();
                let list = params
                    .get(2)
                    .and_then(|v| v.as_str_list())
                    .unwrap_or_default();
                // A topic this node does not subscribe to is not its business.
                if self.lock().subs.contains_key(&topic) {
                    self.updates.put(topic, list);
                }
                ok(Value::Int(0))
            }
            "requestTopic" => {
                let topic = param(1);
                let tcpros = params.get(2).and_then(|v| v.as_array()).is_some_and(|ps| {
                    ps.iter().any(|p| {
                        p.as_array()
                            .and_then(|a| a.first())
                            .and_then(|v| v.as_str())
                            == Some("TCPROS")
                    })
                });
                if !tcpros {
                    return fail("only TCPROS is supported".into());
                }
                if !self.lock().pubs.contains_key(topic) {
                    return fail(format!("{} does not publish {topic}", self.opts.node_name));
                }
                ok(Value::Array(vec![
                    "TCPROS".into(),
                    self.opts.host.as_str().into(),
                    Value::Int(i32::from(self.tcpros_port)),
                ]))
            }
            m => fail(format!("unknown method {m}")),
        }
    }
}

/// `pkg/T` (a ROS 1 service type) as the call table names it: `pkg/srv/T`.
pub fn srv_type_of(ros_type: &str) -> String {
    match ros_type.split_once('/') {
        Some((pkg, t)) if !t.contains('/') => format!("{pkg}/srv/{t}"),
        _ => ros_type.to_owned(),
    }
}

/// Serves the slave XML-RPC API until `shutdown`.
pub async fn serve_slave(node: Arc<Node>, listener: TcpListener, shutdown: CancellationToken) {
    loop {
        let (stream, _) = tokio::select! {
            r = listener.accept() => match r {
                Ok(s) => s,
                Err(e) => {
                    tracing::warn!("ros1: slave API accept: {e}");
                    tokio::time::sleep(std::time::Duration::from_millis(100)).await;
                    continue;
                }
            },
            _ = shutdown.cancelled() => return,
        };
        let node = node.clone();
        let shutdown = shutdown.clone();
        tokio::spawn(async move {
            tokio::select! {
                _ = slave_connection(&node, stream) => {}
                _ = shutdown.cancelled() => {}
            }
        });
    }
}

async fn slave_connection(node: &Node, stream: tokio::net::TcpStream) {
    let mut reader = Reader::new(stream);
    loop {
        let head = match reader.head().await {
            Ok(Some(h)) => h,
            Ok(None) => return,
            Err(e) => {
                tracing::debug!("ros1: slave API request: {e}");
                return;
            }
        };
        let Some(len) = head.content_length else {
            return;
        };
        let body = match reader.body(len).await {
            Ok(b) => b,
            Err(e) => {
                tracing::debug!("ros1: slave API body: {e}");
                return;
            }
        };
        let reply = match std::str::from_utf8(&body)
            .map_err(|e| e.to_string())
            .and_then(|t| decode_call(t).map_err(|e| e.to_string()))
        {
            Ok(call) => encode_response(&node.handle_slave(&call.method, &call.params)),
            Err(e) => encode_fault(-1, &e),
        };
        if write_response(reader.get_mut(), &reply, head.close)
            .await
            .is_err()
            || head.close
        {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A publication not latched, `held` as given.
    fn publication(held: Option<Held>) -> Publication {
        Publication {
            topic: "/t".into(),
            identity: Ros1Identity {
                type_name: "std_msgs/String".into(),
                md5sum: "x".into(),
                definition: String::new(),
            },
            latched: false,
            out: Mutex::new(PubOut {
                held,
                ..PubOut::default()
            }),
            dropped: AtomicU64::new(0),
            stats: Arc::default(),
        }
    }

    #[test]
    fn a_subscriber_that_stops_reading_holds_at_most_the_byte_bound() {
        let publication = publication(None);
        let (tx, mut rx) = mpsc::channel(SUBSCRIBER_QUEUE);
        let queued = Arc::new(std::sync::atomic::AtomicUsize::new(0));
        publication.out.lock().unwrap().conns.push(SubscriberTx {
            conn: 1,
            tx,
            queued: queued.clone(),
        });
        let cloud = Bytes::from(vec![0u8; 1 << 20]);
        for _ in 0..20 {
            publication.publish(cloud.clone());
        }
        let fits = SUBSCRIBER_QUEUE_BYTES / cloud.len();
        assert_eq!(queued.load(Relaxed), fits * cloud.len());
        assert_eq!(publication.dropped.load(Relaxed), (20 - fits) as u64);
        assert_eq!(
            publication.stats.dropped_down.load(Relaxed),
            (20 - fits) as u64,
            "the adapter's status counts them too"
        );
        let mut held = 0;
        while rx.try_recv().is_ok() {
            held += 1;
        }
        assert_eq!(held, fits, "frames in the queue");
        // A frame larger than the bound still reaches a subscriber with nothing queued.
        queued.store(0, Relaxed);
        publication.publish(Bytes::from(vec![0u8; SUBSCRIBER_QUEUE_BYTES + 1]));
        assert!(rx.try_recv().is_ok(), "an oversized frame is not starved");
    }

    #[test]
    fn a_new_publication_holds_its_first_messages_for_the_subscribers_the_master_listed() {
        let publication = publication(Some(Held {
            expect: None,
            until: std::time::Instant::now() + HOLD_FOR_SUBSCRIBERS,
            frames: Default::default(),
        }));
        let frame = |n: u8| Bytes::from(vec![n]);
        for n in 0..12 {
            publication.publish(frame(n));
        }
        // The registration answers: two subscribers are waiting.
        let mut rxs = Vec::new();
        let mut connect = |conn| {
            let (tx, rx) = mpsc::channel(SUBSCRIBER_QUEUE);
            rxs.push(rx);
            let mut out = publication.out.lock().unwrap();
            out.conns.push(SubscriberTx {
                conn,
                tx,
                queued: Arc::default(),
            });
            publication.release_held(&mut out);
        };
        publication
            .out
            .lock()
            .unwrap()
            .held
            .as_mut()
            .unwrap()
            .expect = Some(2);
        connect(1);
        assert!(
            publication.out.lock().unwrap().held.is_some(),
            "still waiting for the second subscriber"
        );
        connect(2);
        assert!(publication.out.lock().unwrap().held.is_none());
        for rx in &mut rxs {
            let got: Vec<u8> = std::iter::from_fn(|| rx.try_recv().ok().map(|b| b[0])).collect();
            assert_eq!(got, (2..12).collect::<Vec<u8>>(), "the newest 10, in order");
        }
        assert_eq!(publication.dropped.load(Relaxed), 2, "the two oldest");
        // After that, messages go straight out.
        publication.publish(frame(99));
        assert_eq!(rxs[0].try_recv().ok(), Some(frame(99)));
    }

    #[test]
    fn held_messages_go_when_the_wait_is_over_even_if_a_subscriber_never_came() {
        let publication = publication(Some(Held {
            expect: Some(2),
            until: std::time::Instant::now(),
            frames: Default::default(),
        }));
        let (tx, mut rx) = mpsc::channel(SUBSCRIBER_QUEUE);
        publication.out.lock().unwrap().conns.push(SubscriberTx {
            conn: 1,
            tx,
            queued: Arc::default(),
        });
        publication.publish(Bytes::from_static(b"a"));
        assert_eq!(rx.try_recv().ok(), Some(Bytes::from_static(b"a")));
        assert!(publication.out.lock().unwrap().held.is_none());
    }

    fn done(id: CallId) -> CallEvent {
        CallEvent::Done {
            id,
            status: fleetlink_relay::calls::CallStatus::Ok,
            payload: None,
            text: String::new(),
        }
    }

    fn node() -> Node {
        let router = Arc::new(Router::default());
        let (client, _) = router.connect(
            fleetlink_relay::ClientKind::Internal { role: "t".into() },
            None,
        );
        let opts = Ros1Options {
            master_uri: "http://127.0.0.1:1".into(),
            node_name: "/n".into(),
            host: "127.0.0.1".into(),
            publish: Default::default(),
            subscribe: Vec::new(),
            expose: Default::default(),
            offer: Default::default(),
            discovery_period: std::time::Duration::from_secs(1),
            call_timeout: std::time::Duration::from_secs(1),
            parameters: false,
            changes: None,
        };
        Node::new(opts, router, client, 1, 2, Arc::default())
    }

    /// Issue 36: `publisherUpdate` comes from the network; what waits for the bridge loop
    /// is the newest list of each subscribed topic, never a backlog.
    #[tokio::test]
    async fn issue36_publisher_updates_keep_the_newest_list_of_subscribed_topics_only() {
        let n = node();
        n.lock().subs.insert(
            "/chatter".into(),
            Subscription {
                ros_type: "std_msgs/String".into(),
                conns: HashMap::new(),
                seq: Arc::default(),
                publishers: Vec::new(),
                paused: false,
                unwanted_since: None,
            },
        );
        let update = |topic: &str, i: usize| {
            let list = Value::Array(vec![format!("http://pub{i}:1/").as_str().into()]);
            n.handle_slave("publisherUpdate", &["/master".into(), topic.into(), list])
        };
        for i in 0..10_000 {
            update("/chatter", i);
            update(&format!("/unsubscribed/{i}"), i);
        }
        let got = n.updates.next().await;
        assert_eq!(
            got,
            [("/chatter".to_owned(), vec!["http://pub9999:1/".to_owned()])]
        );
        assert_eq!(n.updates.coalesced.load(Relaxed), 9_999);
    }

    #[tokio::test]
    async fn answers_reach_waiters_registered_before_or_after_them() {
        let n = node();
        let rx = n.wait_for(1);
        n.answer(done(1));
        assert_eq!(rx.await.unwrap().id(), 1);
        n.answer(done(2));
        assert_eq!(n.wait_for(2).await.unwrap().id(), 2);
        assert!(n.waiters.lock().unwrap().is_empty());
    }

    #[test]
    fn late_answers_to_abandoned_calls_are_not_kept() {
        let n = node();
        drop(n.wait_for(3));
        n.forget(3);
        n.answer(done(3));
        assert!(n.waiters.lock().unwrap().is_empty());
    }

    #[test]
    fn request_topic_offers_tcpros_only_for_own_publications() {
        let n = node();
        let tcpros = Value::Array(vec![Value::Array(vec!["TCPROS".into()])]);
        let r = n.handle_slave("requestTopic", &["/x".into(), "/nope".into(), tcpros]);
        assert_eq!(r.as_array().unwrap()[0], Value::Int(-1));
        let r = n.handle_slave("getPid", &["/x".into()]);
        assert_eq!(
            r.as_array().unwrap()[2],
            Value::Int(std::process::id() as i32)
        );
        let r = n.handle_slave("noSuchMethod", &[]);
        assert_eq!(r.as_array().unwrap()[0], Value::Int(-1));
    }

    #[test]
    fn service_types_gain_their_srv_part() {
        assert_eq!(srv_type_of("std_srvs/SetBool"), "std_srvs/srv/SetBool");
        assert_eq!(srv_type_of("std_srvs/srv/SetBool"), "std_srvs/srv/SetBool");
    }
}
