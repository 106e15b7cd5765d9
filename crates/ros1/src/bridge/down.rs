//! Hub topics published into the graph: the router topics the options subscribe, and a
//! [`Publication`] per topic, registered with the master, whose first messages wait for
//! the subscribers the master named.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

use fleetlink_proto::{Encoding, Schema};
use fleetlink_relay::Message;
use fleetlink_relay::router::{SubOptions, Target};

use crate::node::{Node, PubOut, Publication};
use crate::tcpros::frame;

/// Subscribes the router topics the options publish into the graph, and lets go of those
/// they no longer do (unregistered as publisher, their subscribers' connections closed).
pub(super) async fn follow_subscriptions(
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
pub(super) fn down(node: &Arc<Node>, msg: &Message) {
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

pub(super) async fn register_publication(node: &Node, p: &Publication) {
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
