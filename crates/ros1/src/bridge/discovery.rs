//! Discovery: one look at the master per period. A (re)started master gets every
//! registration again; the graph's publishers and services are followed, each new one
//! bridged and each vanished one let go.

use std::sync::Arc;
use std::sync::atomic::AtomicU64;

use fleetlink_proto::Schema;
use fleetlink_relay::TopicName;
use tokio_util::sync::CancellationToken;

use super::calls::register_service;
use super::down::register_publication;
use super::up::reconcile;
use crate::node::{Exposed, Node, Subscription, srv_type_of};
use crate::outbound::probe_service;

/// Once per period: notices a (re)started master and registers everything with it, then
/// follows the graph's publishers and services.
pub(super) async fn discovery(node: Arc<Node>, shutdown: CancellationToken) {
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
