//! The bridge's tasks: the router side (hub topics into the graph, service calls both
//! ways) and discovery (new publishers and services, a restarted master).
//!
//! Three kinds of task drive one [`Node`]: the loop in [`run`] that owns the router
//! client's outbox and call-table channel, [`discovery`] that talks to the master once
//! per period, and the connection tasks (slave API, TCPROS in and out). Master calls are
//! only made from spawned tasks, so a master that hangs never holds up messages.

use std::collections::HashSet;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::CallStatus;
use fleetlink_relay::calls::{CallRequest, ChannelPeer, PeerMsg, ServiceChange};
use fleetlink_relay::read_interest::{Look, ReadInterest};
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::{ClientKind, Message, Router, TopicName};
use tokio::net::TcpListener;
use tokio_util::sync::CancellationToken;

use crate::node::{
    Conn, Exposed, Node, Offered, PubOut, Publication, Ros1Stats, Subscription, srv_type_of,
};
use crate::options::Ros1Options;
use crate::outbound::{PullEnd, call_service, probe_service, pull};
use crate::tcpros::frame;

#[derive(Debug, thiserror::Error)]
pub enum Ros1Error {
    #[error("ros1: cannot listen on {what}: {source}")]
    Bind {
        what: &'static str,
        source: std::io::Error,
    },
}

/// Bridges the ROS 1 graph at `opts.master_uri` with `router` until `shutdown`.
pub async fn run(
    opts: Ros1Options,
    router: Arc<Router>,
    stats: Arc<Ros1Stats>,
    interest: Option<Arc<ReadInterest>>,
    shutdown: CancellationToken,
) -> Result<(), Ros1Error> {
    let bind = |what| move |source| Ros1Error::Bind { what, source };
    let slave = TcpListener::bind("0.0.0.0:0")
        .await
        .map_err(bind("the slave XML-RPC API"))?;
    let tcpros = TcpListener::bind("0.0.0.0:0")
        .await
        .map_err(bind("TCPROS"))?;
    let port = |l: &TcpListener| l.local_addr().map(|a| a.port()).unwrap_or(0);
    let (slave_port, tcpros_port) = (port(&slave), port(&tcpros));
    let (client, outbox) = router.connect(
        ClientKind::Internal {
            role: "ros1".into(),
        },
        None,
    );
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let node = Arc::new(Node::new(
        opts,
        router.clone(),
        client,
        slave_port,
        tcpros_port,
        stats,
    ));
    tracing::info!(
        "ros1: node {} at {} (TCPROS port {tcpros_port}), master {}",
        node.opts.node_name,
        node.master.caller_api,
        node.opts.master_uri
    );
    if node.opts.parameters {
        fleetlink_relay::params::advertise_services(&router.calls, client);
    }
    let mut changes = node.opts.changes.clone();
    if let Some(rx) = &mut changes {
        // A change made before the node started is in force from the start.
        *node.live.write().unwrap_or_else(|p| p.into_inner()) =
            Arc::new(rx.borrow_and_update().clone());
    }
    let mut subscribed = std::collections::HashMap::new();
    follow_offers(&node).await;
    follow_subscriptions(&node, &mut subscribed).await;
    let tasks = [
        tokio::spawn(crate::node::serve_slave(
            node.clone(),
            slave,
            shutdown.clone(),
        )),
        tokio::spawn(crate::inbound::serve(
            node.clone(),
            tcpros,
            shutdown.clone(),
        )),
        tokio::spawn(discovery(node.clone(), shutdown.clone())),
    ];
    // Topics nobody wants are not read (with an agent's uplink to ask).
    let mut look = tokio::time::interval(INTEREST_LOOK);
    look.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    loop {
        tokio::select! {
            _ = shutdown.cancelled() => break,
            // (A change between two turns of this loop is seen at the next look.)
            _ = ReadInterest::changed(&interest) => {
                if let Some(i) = &interest {
                    follow_interest(&node, i, Instant::now());
                }
            }
            _ = look.tick(), if interest.is_some() => {
                if let Some(i) = &interest {
                    follow_interest(&node, i, Instant::now());
                }
            }
            _ = outbox.ready() => loop {
                let batch = outbox.take(64, 8 << 20, Instant::now());
                if batch.items.is_empty() {
                    break;
                }
                for (_, _, msg) in batch.items {
                    down(&node, &msg);
                }
            },
            lists = node.updates.next() => {
                for (topic, list) in lists {
                    reconcile(&node, &topic, &list, true);
                }
            }
            Some(m) = peer_rx.recv() => on_peer(&node, m),
            new = fleetlink_relay::live::next_change(&mut changes) => {
                tracing::info!("ros1: what crosses changed (runtime configuration)");
                *node.live.write().unwrap_or_else(|p| p.into_inner()) = Arc::new(new);
                follow_offers(&node).await;
                follow_subscriptions(&node, &mut subscribed).await;
                node.rediscover.notify_one();
            }
        }
    }
    for t in tasks {
        let _ = t.await;
    }
    for sub in node.lock().subs.values() {
        for c in sub.conns.values() {
            c.abort.abort();
        }
    }
    unregister_all(&node).await;
    router.disconnect(client);
    Ok(())
}

/// Watches the fleet services the options offer to local nodes, and withdraws from the
/// master those they no longer do (after a runtime change).
async fn follow_offers(node: &Arc<Node>) {
    let opts = node.live();
    let gone: Vec<String> = {
        let mut st = node.lock();
        let names: Vec<String> = st
            .offered
            .keys()
            .filter(|n| !opts.offer.matches(n))
            .cloned()
            .collect();
        for n in &names {
            st.offered.remove(n);
            st.registered_services.remove(n);
        }
        names
    };
    for name in gone {
        let _ = node
            .master
            .unregister_service(&name, &node.service_api)
            .await;
        tracing::info!("ros1: fleet service {name} no longer offered to local nodes");
    }
    // Watched anew: the services that match now are told at once.
    node.router.calls.unwatch(node.client);
    for re in &opts.offer.include {
        node.router.calls.watch(node.client, re.clone());
    }
}

/// Subscribes the router topics the options publish into the graph, and lets go of those
/// they no longer do (unregistered as publisher, their subscribers' connections closed).
async fn follow_subscriptions(
    node: &Arc<Node>,
    subscribed: &mut std::collections::HashMap<String, fleetlink_relay::router::SubscriptionId>,
) {
    let opts = node.live();
    let gone: Vec<String> = subscribed
        .keys()
        .filter(|k| !opts.subscribe.iter().any(|n| n.as_str() == k.as_str()))
        .cloned()
        .collect();
    for name in gone {
        if let Some(sid) = subscribed.remove(&name) {
            node.router.unsubscribe(node.client, sid);
        }
        let publication = {
            let mut st = node.lock();
            st.registered_pubs.remove(&name);
            st.pubs.remove(&name)
        };
        if let Some(p) = publication {
            p.close();
        }
        let _ = node.master.unregister_publisher(&name).await;
        tracing::info!("ros1: no longer publishing {name} into the graph");
    }
    for name in &opts.subscribe {
        if subscribed.contains_key(name.as_str()) {
            continue;
        }
        match node.router.subscribe(
            node.client,
            Target::Exact(name.clone()),
            SubOptions::default(),
        ) {
            Ok(sid) => {
                subscribed.insert(name.to_string(), sid);
            }
            Err(e) => tracing::warn!("ros1: cannot subscribe to {name}: {e}"),
        }
    }
}

/// A hub message for the graph: published as it arrived when it is ROS 1 already,
/// converted once otherwise.
fn down(node: &Arc<Node>, msg: &Message) {
    let name = msg.topic.name.as_str();
    let existing = node.lock().pubs.get(name).cloned();
    let Some(publication) = existing.or_else(|| create_publication(node, msg)) else {
        return;
    };
    let body = if msg.payload.encoding == Encoding::Ros1 {
        msg.payload.bytes.clone()
    } else {
        let schema = Schema {
            type_name: publication.identity.type_name.clone(),
            encoding: "ros1msg".into(),
            text: String::new(),
        };
        match node
            .router
            .transcoder()
            .convert(&schema, &msg.payload, Encoding::Ros1)
        {
            Ok(b) => b,
            Err(e) => {
                tracing::debug!("ros1: dropping a message of {name}: {e}");
                return;
            }
        }
    };
    publication.publish(frame(&body));
    node.stats.messages_down.fetch_add(1, Relaxed);
}

fn create_publication(node: &Arc<Node>, msg: &Message) -> Option<Arc<Publication>> {
    let name = msg.topic.name.as_str();
    let type_name = &msg.topic.schema.type_name;
    let Some(identity) = node.router.transcoder().ros1_identity(type_name) else {
        if node.lock().mismatched.insert(name.to_owned()) {
            node.stats.type_mismatches.fetch_add(1, Relaxed);
            let text = format!(
                "cannot publish {name} into the ROS graph: type {type_name:?} has no ROS 1 identity \
                 (unknown to the agent's registry); other topics are unaffected"
            );
            tracing::warn!("ros1: {text}");
            node.stats.problems.note(&text);
        }
        return None;
    };
    let latched = node.router_topic(name).is_some_and(|t| t.is_latched());
    let publication = Arc::new(Publication {
        topic: name.to_owned(),
        identity,
        latched,
        out: std::sync::Mutex::new(PubOut {
            held: (!latched).then(|| crate::node::Held {
                expect: None,
                until: std::time::Instant::now() + crate::node::HOLD_FOR_SUBSCRIBERS,
                frames: Default::default(),
            }),
            ..PubOut::default()
        }),
        dropped: AtomicU64::new(0),
        stats: node.stats.clone(),
    });
    node.lock()
        .pubs
        .insert(name.to_owned(), publication.clone());
    tracing::info!(
        "ros1: publishing {name} ({}{}) into the graph",
        publication.identity.type_name,
        if latched { ", latched" } else { "" }
    );
    let (task_node, task_pub) = (node.clone(), publication.clone());
    tokio::spawn(async move { register_publication(&task_node, &task_pub).await });
    if !latched {
        // Whatever is still held goes when the wait is over.
        let held = publication.clone();
        tokio::spawn(async move {
            tokio::time::sleep(crate::node::HOLD_FOR_SUBSCRIBERS).await;
            let mut out = held.out.lock().unwrap_or_else(|p| p.into_inner());
            held.release_held(&mut out);
        });
    }
    Some(publication)
}

async fn register_publication(node: &Node, p: &Publication) {
    match node
        .master
        .register_publisher(&p.topic, &p.identity.type_name)
        .await
    {
        Ok(subscribers) => {
            node.lock().registered_pubs.insert(p.topic.clone());
            node.stats.master_registrations.fetch_add(1, Relaxed);
            // The subscribers already waiting (not this node's own, if it subscribes
            // the same topic): held messages wait for them to connect.
            let own = node.master.caller_api.trim_end_matches('/');
            let waiting = subscribers
                .iter()
                .filter(|s| s.trim_end_matches('/') != own)
                .count();
            let mut out = p.out.lock().unwrap_or_else(|e| e.into_inner());
            if let Some(h) = &mut out.held {
                h.expect = Some(waiting);
            }
            p.release_held(&mut out);
        }
        Err(e) => tracing::debug!("ros1: registering publisher {}: {e}", p.topic),
    }
}

/// Brings a subscription's connections in line with its publishers' APIs. `prune` drops
/// connections to publishers not listed (a `publisherUpdate`); registration answers only
/// add, so publishers that outlived a master restart keep flowing.
fn reconcile(node: &Arc<Node>, topic: &str, publishers: &[String], prune: bool) {
    let own = node.master.caller_api.trim_end_matches('/');
    let wanted: HashSet<&str> = publishers
        .iter()
        .map(|s| s.trim_end_matches('/'))
        .filter(|s| *s != own)
        .collect();
    let mut st = node.lock();
    let Some(sub) = st.subs.get_mut(topic) else {
        return;
    };
    if prune || sub.publishers.is_empty() {
        sub.publishers = wanted.iter().map(|s| (*s).to_owned()).collect();
    } else {
        for api in &wanted {
            if !sub.publishers.iter().any(|p| p == api) {
                sub.publishers.push((*api).to_owned());
            }
        }
    }
    if sub.paused {
        return; // connected again when someone wants the topic
    }
    if prune {
        sub.conns.retain(|api, c| {
            let keep = wanted.contains(api.as_str());
            if !keep {
                c.abort.abort();
            }
            keep
        });
    }
    for api in wanted {
        if sub.conns.contains_key(api) {
            continue;
        }
        let id = node.next_conn_id();
        let task = tokio::spawn(run_pull(
            node.clone(),
            topic.to_owned(),
            api.to_owned(),
            sub.seq.clone(),
            id,
        ));
        sub.conns.insert(
            api.to_owned(),
            Conn {
                id,
                abort: task.abort_handle(),
            },
        );
    }
}

/// How often the bridge looks at what is wanted, besides when the hub's demand changes.
const INTEREST_LOOK: Duration = Duration::from_secs(1);

/// Pauses reading the topics nobody has wanted for a while ([`ReadInterest::look`]) (their
/// publisher connections closed; the master registration kept, so publisher lists stay
/// current) and resumes those wanted again (connected to their publishers at once).
fn follow_interest(node: &Arc<Node>, interest: &ReadInterest, now: Instant) {
    let mut resume = Vec::new();
    {
        let mut st = node.lock();
        for (topic, sub) in st.subs.iter_mut() {
            let Ok(name) = TopicName::parse(topic) else {
                continue;
            };
            match interest.look(&name, node.client, &mut sub.unwanted_since, now) {
                Look::Read if sub.paused => {
                    sub.paused = false;
                    tracing::info!("ros1: {topic} is wanted again; reading it");
                    resume.push((topic.clone(), sub.publishers.clone()));
                }
                Look::Stop if !sub.paused => {
                    sub.paused = true;
                    for c in sub.conns.values() {
                        c.abort.abort();
                    }
                    sub.conns.clear();
                    interest.stopped_reading(&name);
                    node.stats.paused.fetch_add(1, Relaxed);
                    tracing::info!("ros1: nobody wants {topic}; no longer reading it");
                }
                _ => {}
            }
        }
    }
    for (topic, publishers) in resume {
        reconcile(node, &topic, &publishers, true);
    }
}

async fn run_pull(node: Arc<Node>, topic: String, api: String, seq: Arc<AtomicU64>, id: u64) {
    match pull(node.clone(), topic.clone(), api.clone(), seq).await {
        PullEnd::Gone(why) => {
            tracing::info!("ros1: stopped receiving {topic} from {api}: {why}");
            let mut st = node.lock();
            if let Some(sub) = st.subs.get_mut(&topic)
                && sub.conns.get(&api).is_some_and(|c| c.id == id)
            {
                sub.conns.remove(&api);
            }
        }
        PullEnd::Refused(why) => tracing::debug!("ros1: not receiving {topic} from {api}: {why}"),
    }
}

fn on_peer(node: &Arc<Node>, m: PeerMsg) {
    match m {
        PeerMsg::Call(req) => {
            let node = node.clone();
            tokio::spawn(async move { serve_call(&node, req).await });
        }
        PeerMsg::Event(ev) => node.answer(ev),
        PeerMsg::Cancel(_) => {}
        PeerMsg::Changed(ServiceChange::Added(info)) => {
            let name = info.name.as_str();
            if info.action || info.provider == node.client || !node.live().offer.matches(name) {
                return;
            }
            let srv_type = srv_type_of(&info.schema.type_name);
            let Some(identity) = node.router.transcoder().ros1_identity(&srv_type) else {
                tracing::warn!(
                    "ros1: cannot offer fleet service {name} to local nodes: type {:?} is unknown to the registry",
                    info.schema.type_name
                );
                return;
            };
            tracing::info!(
                "ros1: offering fleet service {name} ({}) to local nodes",
                identity.type_name
            );
            node.lock()
                .offered
                .insert(name.to_owned(), Offered { srv_type, identity });
            let node = node.clone();
            let name = name.to_owned();
            tokio::spawn(async move { register_service(&node, &name).await });
        }
        PeerMsg::Changed(ServiceChange::Removed(info)) => {
            let name = info.name.as_str().to_owned();
            let removed = {
                let mut st = node.lock();
                st.registered_services.remove(&name);
                st.offered.remove(&name).is_some()
            };
            if removed {
                let node = node.clone();
                tokio::spawn(async move {
                    let _ = node
                        .master
                        .unregister_service(&name, &node.service_api)
                        .await;
                });
            }
        }
    }
}

async fn register_service(node: &Node, name: &str) {
    match node.master.register_service(name, &node.service_api).await {
        Ok(()) => {
            node.lock().registered_services.insert(name.to_owned());
            node.stats.master_registrations.fetch_add(1, Relaxed);
        }
        Err(e) => tracing::debug!("ros1: registering service {name}: {e}"),
    }
}

/// A fleet caller's call of a local ROS service.
async fn serve_call(node: &Node, req: CallRequest) {
    let name = req.service.name.as_str();
    if node.opts.parameters && fleetlink_relay::params::is_param_service(name) {
        return crate::params::serve(node, &req).await;
    }
    let found = node
        .lock()
        .exposed
        .get(name)
        .map(|e| (e.srv_type.clone(), e.md5sum.clone()));
    let respond = |status, payload, text: String| {
        node.router
            .calls
            .respond(node.client, req.id, status, payload, text);
    };
    let Some((srv_type, md5sum)) = found else {
        respond(
            CallStatus::NoProvider,
            None,
            format!("{name} is not exposed by the ROS 1 bridge"),
        );
        return;
    };
    let schema = Schema {
        type_name: format!("{srv_type}_Request"),
        encoding: "ros1msg".into(),
        text: String::new(),
    };
    let request = match node
        .router
        .transcoder()
        .convert(&schema, &req.payload, Encoding::Ros1)
    {
        Ok(b) => b,
        Err(e) => {
            respond(CallStatus::Failed, None, e.to_string());
            return;
        }
    };
    // A provider that never answers must not hold this task past the caller's deadline.
    let limit = req.deadline.map_or(node.opts.call_timeout, |d| {
        d.saturating_duration_since(Instant::now())
    });
    match tokio::time::timeout(limit, call_service(node, name, &md5sum, &request)).await {
        Ok(Ok(body)) => respond(
            CallStatus::Ok,
            Some(Payload::new(Encoding::Ros1, body)),
            String::new(),
        ),
        Ok(Err(text)) => respond(CallStatus::Failed, None, text),
        Err(_) => respond(
            CallStatus::Timeout,
            None,
            format!("{name} did not answer within {limit:?}"),
        ),
    }
}

/// Once per period: notices a (re)started master and registers everything with it, then
/// follows the graph's publishers and services.
async fn discovery(node: Arc<Node>, shutdown: CancellationToken) {
    let mut master_pid: Option<i32> = None;
    let mut reachable = true;
    let mut tick = tokio::time::interval(node.opts.discovery_period);
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    loop {
        tokio::select! {
            _ = tick.tick() => {}
            _ = node.rediscover.notified() => {}
            _ = shutdown.cancelled() => return,
        }
        let pid = match node.master.pid().await {
            Ok(p) => p,
            Err(e) => {
                if reachable {
                    tracing::warn!(
                        "ros1: master unreachable ({e}); retrying every {:?}",
                        node.opts.discovery_period
                    );
                    reachable = false;
                }
                continue;
            }
        };
        if master_pid != Some(pid) {
            if master_pid.is_some() || !reachable {
                tracing::info!(
                    "ros1: master at {} is back (pid {pid}): registering again",
                    node.opts.master_uri
                );
            }
            register_again(&node).await;
            master_pid = Some(pid);
        }
        reachable = true;
        follow_graph(&node).await;
    }
}

/// Everything this node publishes, subscribes and serves, registered with a new master.
async fn register_again(node: &Arc<Node>) {
    let (pubs, subs, services) = {
        let mut st = node.lock();
        st.registered_pubs.clear();
        st.registered_services.clear();
        (
            st.pubs.values().cloned().collect::<Vec<_>>(),
            st.subs
                .iter()
                .map(|(t, s)| (t.clone(), s.ros_type.clone()))
                .collect::<Vec<_>>(),
            st.offered.keys().cloned().collect::<Vec<_>>(),
        )
    };
    for p in pubs {
        register_publication(node, &p).await;
    }
    for (topic, ty) in subs {
        match node.master.register_subscriber(&topic, &ty).await {
            Ok(list) => reconcile(node, &topic, &list, false),
            Err(e) => tracing::debug!("ros1: registering subscriber {topic}: {e}"),
        }
    }
    for name in services {
        register_service(node, &name).await;
    }
}

async fn follow_graph(node: &Arc<Node>) {
    // Registrations that failed earlier (master busy) are retried.
    let (pubs, services) = {
        let st = node.lock();
        (
            st.pubs
                .values()
                .filter(|p| !st.registered_pubs.contains(&p.topic))
                .cloned()
                .collect::<Vec<_>>(),
            st.offered
                .keys()
                .filter(|s| !st.registered_services.contains(*s))
                .cloned()
                .collect::<Vec<_>>(),
        )
    };
    for p in pubs {
        register_publication(node, &p).await;
    }
    for s in services {
        register_service(node, &s).await;
    }
    let opts = node.live();
    let following = {
        let st = node.lock();
        !st.subs.is_empty() || !st.exposed.is_empty()
    };
    if opts.publish.is_empty() && opts.expose.is_empty() && !following {
        return;
    }
    let state = match node.master.system_state().await {
        Ok(s) => s,
        Err(e) => {
            tracing::debug!("ros1: getSystemState: {e}");
            return;
        }
    };
    let me = node.opts.node_name.as_str();
    {
        let candidates = state
            .publishers
            .iter()
            .filter(|(t, nodes)| opts.publish.matches(t) && nodes.iter().any(|n| n != me));
        // Types are needed only for topics not bridged yet: a steady graph costs one call
        // a period, not two.
        let new_topic = {
            let st = node.lock();
            candidates.clone().any(|(t, _)| !st.subs.contains_key(t))
        };
        let types = if new_topic {
            node.master.topic_types().await.unwrap_or_default()
        } else {
            Vec::new()
        };
        let wanted: Vec<(String, String)> = candidates
            .map(|(t, _)| {
                let ty = types
                    .iter()
                    .find(|(n, _)| n == t)
                    .map_or("*", |(_, ty)| ty.as_str());
                (t.clone(), ty.to_owned())
            })
            .collect();
        follow_topics(node, &wanted).await;
    }
    {
        let wanted: Vec<String> = state
            .services
            .iter()
            .filter(|(s, nodes)| opts.expose.matches(s) && !nodes.iter().any(|n| n == me))
            .map(|(s, _)| s.clone())
            .collect();
        follow_services(node, &wanted).await;
    }
}

async fn follow_topics(node: &Arc<Node>, wanted: &[(String, String)]) {
    let (new, gone): (Vec<(String, String)>, Vec<String>) = {
        let st = node.lock();
        let new = wanted
            .iter()
            .filter(|(t, _)| !st.subs.contains_key(t))
            .cloned()
            .collect();
        // A topic whose publishers all left the master's list is dropped once its
        // connections ended too (publishers that outlived a master restart keep it).
        // A topic the options no longer include goes at once, connections and all.
        let opts = node.live();
        let gone = st
            .subs
            .iter()
            .filter(|(t, s)| {
                !wanted.iter().any(|(w, _)| w == *t)
                    && (s.conns.is_empty() || !opts.publish.matches(t))
            })
            .map(|(t, _)| t.clone())
            .collect();
        (new, gone)
    };
    for (topic, ty) in new {
        node.lock().subs.insert(
            topic.clone(),
            Subscription {
                ros_type: ty.clone(),
                conns: Default::default(),
                seq: Arc::new(AtomicU64::new(0)),
                publishers: Vec::new(),
                paused: false,
                unwanted_since: None,
            },
        );
        match node.master.register_subscriber(&topic, &ty).await {
            Ok(list) => {
                tracing::info!("ros1: bridging {topic} ({ty}) up to the hub");
                reconcile(node, &topic, &list, true);
            }
            Err(e) => {
                tracing::debug!("ros1: registering subscriber {topic}: {e}");
                node.lock().subs.remove(&topic);
            }
        }
    }
    for topic in gone {
        if let Some(sub) = node.lock().subs.remove(&topic) {
            for c in sub.conns.values() {
                c.abort.abort();
            }
        }
        let _ = node.master.unregister_subscriber(&topic).await;
        if let Ok(name) = TopicName::parse(&topic) {
            node.router.unadvertise(node.client, &name);
        }
        tracing::info!("ros1: {topic} is no longer bridged (no publisher, or not in ros1.publish)");
    }
}

async fn follow_services(node: &Arc<Node>, wanted: &[String]) {
    let (new, gone): (Vec<String>, Vec<String>) = {
        let st = node.lock();
        (
            wanted
                .iter()
                .filter(|s| !st.exposed.contains_key(*s))
                .cloned()
                .collect(),
            st.exposed
                .keys()
                .filter(|s| !wanted.contains(*s))
                .cloned()
                .collect(),
        )
    };
    for service in new {
        let probe = match probe_service(node, &service).await {
            Ok(p) => p,
            Err(e) => {
                tracing::debug!("ros1: probing {service}: {e}");
                continue;
            }
        };
        let Ok(name) = TopicName::parse(&service) else {
            continue;
        };
        let srv_type = srv_type_of(&probe.ros_type);
        tracing::info!(
            "ros1: exposing local service {service} ({}) to the fleet",
            probe.ros_type
        );
        node.lock().exposed.insert(
            service.clone(),
            Exposed {
                srv_type: srv_type.clone(),
                md5sum: probe.md5sum,
            },
        );
        let schema = node
            .router
            .transcoder()
            .schema_for(&srv_type)
            .unwrap_or_else(|| Schema::named(srv_type.clone()));
        node.router
            .calls
            .advertise(node.client, name, schema, false);
    }
    for service in gone {
        node.lock().exposed.remove(&service);
        if let Ok(name) = TopicName::parse(&service) {
            node.router.calls.unadvertise(node.client, &name);
        }
        tracing::info!("ros1: local service {service} went away");
    }
}

/// Best effort on the way out: tell the master this node is gone (bounded).
async fn unregister_all(node: &Node) {
    let (pubs, subs, services) = {
        let st = node.lock();
        (
            st.pubs.keys().cloned().collect::<Vec<_>>(),
            st.subs.keys().cloned().collect::<Vec<_>>(),
            st.offered.keys().cloned().collect::<Vec<_>>(),
        )
    };
    let work = async {
        for t in pubs {
            let _ = node.master.unregister_publisher(&t).await;
        }
        for t in subs {
            let _ = node.master.unregister_subscriber(&t).await;
        }
        for s in services {
            let _ = node.master.unregister_service(&s, &node.service_api).await;
        }
    };
    let _ = tokio::time::timeout(Duration::from_secs(2), work).await;
}
