//! Local topics sent up to the hub: a subscription's connections to its publishers,
//! kept in line with the master's lists and paused while nobody wants the topic.

use std::collections::HashSet;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Instant;

use fleetlink_relay::TopicName;
use fleetlink_relay::read_interest::{Look, ReadInterest};

use crate::node::{Conn, Node};
use crate::outbound::{PullEnd, pull};

/// Brings a subscription's connections in line with its publishers' APIs. `prune` drops
/// connections to publishers not listed (a `publisherUpdate`); registration answers only
/// add, so publishers that outlived a master restart keep flowing.
pub(super) fn reconcile(node: &Arc<Node>, topic: &str, publishers: &[String], prune: bool) {
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

/// Pauses reading the topics nobody has wanted for a while ([`ReadInterest::look`]) (their
/// publisher connections closed; the master registration kept, so publisher lists stay
/// current) and resumes those wanted again (connected to their publishers at once).
pub(super) fn follow_interest(node: &Arc<Node>, interest: &ReadInterest, now: Instant) {
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
