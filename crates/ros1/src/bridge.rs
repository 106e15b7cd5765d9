//! The bridge's tasks: the router side (hub topics into the graph, service calls both
//! ways) and discovery (new publishers and services, a restarted master).
//!
//! Three kinds of task drive one [`Node`]: the loop in [`run`] that owns the router
//! client's outbox and call-table channel, [`discovery`] that talks to the master once
//! per period, and the connection tasks (slave API, TCPROS in and out). Master calls are
//! only made from spawned tasks, so a master that hangs never holds up messages.
//!
//! # Layout
//!
//! - [`down`](mod@down): hub topics published into the graph.
//! - [`up`]: local topics read from their publishers and sent to the hub.
//! - [`calls`]: service calls both ways, fleet services offered to local nodes.
//! - [`discovery`]: the master's lists followed once per period; a restarted master.

mod calls;
mod discovery;
mod down;
mod up;

use std::sync::Arc;
use std::time::{Duration, Instant};

use fleetlink_relay::calls::ChannelPeer;
use fleetlink_relay::read_interest::ReadInterest;
use fleetlink_relay::{ClientKind, Router};
use tokio::net::TcpListener;
use tokio_util::sync::CancellationToken;

use crate::node::{Node, Ros1Stats};
use crate::options::Ros1Options;
use calls::{follow_offers, on_peer};
use down::{down, follow_subscriptions};
use up::{follow_interest, reconcile};

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
        tokio::spawn(discovery::discovery(node.clone(), shutdown.clone())),
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

/// How often the bridge looks at what is wanted, besides when the hub's demand changes.
const INTEREST_LOOK: Duration = Duration::from_secs(1);

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
