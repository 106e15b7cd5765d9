//! Issue 9: no-drop topics across link deaths and restarts. The uplink must not stall when
//! a link dies with more than the in-flight window unacknowledged, a no-drop message must
//! arrive exactly once and in order whether it was lost in the dead connection or already
//! delivered when its confirmation was lost, and the durable outbox must carry queued
//! messages across an agent restart.

use std::time::Duration;

use fleetlink_agent::outbox_store::{Fsync, OutboxStoreConfig};
use fleetlink_agent::uplink::UplinkConfig;
use fleetlink_qos::TopicQosSpec;
use fleetlink_relay::TopicName;
use serde_json::json;

use crate::util::*;

const TOPIC: &str = "/nd";
const HUB_TOPIC: &str = "/robot1/nd";

fn no_drop_config(hub: &TestHub, proxy: &Blackhole) -> UplinkConfig {
    let mut cfg = uplink_config(hub, "robot1");
    cfg.hub_urls = vec![format!("ws://{}", proxy.addr)];
    cfg.heartbeat = Duration::from_millis(200);
    cfg.topic_qos = vec![(
        TopicName::parse(TOPIC).unwrap(),
        TopicQosSpec {
            no_drop: Some(true),
            queue: Some(1000),
            ..Default::default()
        },
    )];
    cfg
}

/// An operator subscribed to the robot's no-drop topic, the subscription in place.
async fn subscriber(hub: &TestHub) -> Rosbridge {
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": HUB_TOPIC}))
        .await;
    // Ops run in order: once this answers, the subscription exists.
    op.call("/rosapi/get_time", json!({}), "sync").await;
    op
}

/// A hub, a blackholing proxy in front of it, an agent linked through the proxy, and an
/// operator subscribed to the no-drop topic.
async fn setup(cfg: impl FnOnce(&TestHub, &Blackhole) -> UplinkConfig, local: bool) -> Fleet {
    let hub = start_hub().await;
    let proxy = Blackhole::start(hub.addr).await;
    let agent = start_agent_with(cfg(&hub, &proxy), local).await;
    agent.wait_connected().await;
    let op = subscriber(&hub).await;
    Fleet {
        hub,
        proxy,
        agent,
        op,
    }
}

struct Fleet {
    hub: TestHub,
    proxy: Blackhole,
    agent: TestAgent,
    op: Rosbridge,
}

fn publish(p: &mut LocalPublisher, range: std::ops::RangeInclusive<u64>) {
    for n in range {
        p.publish_json(&json!({"data": n.to_string()}));
    }
}

/// Every number the subscriber receives until it has seen `last`.
async fn received_until(op: &mut Rosbridge, last: u64) -> Vec<u64> {
    within(&format!("message {last} on {HUB_TOPIC}"), async {
        let mut got = Vec::new();
        loop {
            let v = op.recv_op("publish").await;
            if v["topic"] != HUB_TOPIC {
                continue;
            }
            let n: u64 = v["msg"]["data"].as_str().unwrap().parse().unwrap();
            got.push(n);
            if n == last {
                return got;
            }
        }
    })
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue9_link_dying_with_more_than_the_window_unacknowledged_neither_stalls_nor_loses() {
    let Fleet {
        hub,
        proxy,
        agent,
        mut op,
    } = setup(no_drop_config, false).await;
    let mut p = LocalPublisher::new(&agent.router, TOPIC, "std_msgs/msg/String");
    publish(&mut p, 1..=10);
    assert_eq!(
        received_until(&mut op, 10).await,
        (1..=10).collect::<Vec<_>>()
    );

    // The link dies silently; 100 messages follow, more than the 32-message window: the
    // first ones vanish into the dead connection.
    proxy.cut();
    publish(&mut p, 11..=110);
    let reason = agent.wait_disconnected().await;
    assert!(reason.contains("declared dead"), "{reason}");
    proxy.restore();
    agent.wait_connected().await;
    publish(&mut p, 111..=120);
    assert_eq!(
        received_until(&mut op, 120).await,
        (11..=120).collect::<Vec<_>>(),
        "every message exactly once, in order, after the link came back"
    );
    // A second death, to be sure the first left nothing counted in flight.
    proxy.cut();
    publish(&mut p, 121..=200);
    agent.wait_disconnected().await;
    proxy.restore();
    agent.wait_connected().await;
    assert_eq!(
        received_until(&mut op, 200).await,
        (121..=200).collect::<Vec<_>>()
    );
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue9_a_resent_message_the_hub_already_delivered_is_not_delivered_again() {
    let Fleet {
        hub,
        proxy,
        agent,
        mut op,
    } = setup(no_drop_config, false).await;
    let mut p = LocalPublisher::new(&agent.router, TOPIC, "std_msgs/msg/String");
    publish(&mut p, 1..=5);
    assert_eq!(
        received_until(&mut op, 5).await,
        (1..=5).collect::<Vec<_>>()
    );

    // The hub gets everything but its confirmations never reach the robot, which must
    // therefore send them all again on the next connection.
    // (Fewer than the 32-message window, so all of them go out unacknowledged.)
    proxy.cut_downstream();
    publish(&mut p, 6..=30);
    assert_eq!(
        received_until(&mut op, 30).await,
        (6..=30).collect::<Vec<_>>()
    );
    agent.wait_disconnected().await;
    proxy.restore();
    agent.wait_connected().await;
    publish(&mut p, 31..=40);
    assert_eq!(
        received_until(&mut op, 40).await,
        (31..=40).collect::<Vec<_>>(),
        "the resent 6..=30 must not be delivered a second time"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue9_durable_outbox_delivers_what_was_queued_before_an_agent_restart() {
    let hub = start_hub().await;
    let proxy = Blackhole::start(hub.addr).await;
    let dir = temp_dir("outbox");
    let mut cfg = no_drop_config(&hub, &proxy);
    cfg.outbox = Some(OutboxStoreConfig {
        dir: dir.clone(),
        max_bytes: 1 << 20,
        fsync: Fsync::Batch,
    });
    let agent = start_agent_with(cfg.clone(), false).await;
    agent.wait_connected().await;
    let mut op = subscriber(&hub).await;
    let mut p = LocalPublisher::new(&agent.router, TOPIC, "std_msgs/msg/String");
    publish(&mut p, 1..=3);
    assert_eq!(
        received_until(&mut op, 3).await,
        (1..=3).collect::<Vec<_>>()
    );

    // An outage; 50 messages wait; the agent stops before the link returns.
    proxy.cut();
    publish(&mut p, 4..=53);
    agent.wait_disconnected().await;
    drop(p);
    agent.shutdown().await;

    proxy.restore();
    let agent = start_agent_with(cfg, false).await;
    agent.wait_connected().await;
    let mut p = LocalPublisher::new(&agent.router, TOPIC, "std_msgs/msg/String");
    // New messages of the same topic come after the recovered ones.
    for n in 54..=60u64 {
        p.publish_json(&json!({"data": n.to_string()}));
    }
    assert_eq!(
        received_until(&mut op, 60).await,
        (4..=60).collect::<Vec<_>>(),
        "recovered messages first, in order, once; then the new ones"
    );
    agent.shutdown().await;
    hub.shutdown().await;
    let _ = std::fs::remove_dir_all(dir);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue9_a_full_no_drop_queue_slows_the_local_rosbridge_publisher_instead_of_dropping() {
    let short_queue = |hub: &TestHub, proxy: &Blackhole| {
        let mut cfg = no_drop_config(hub, proxy);
        // A short queue, so the outage fills it: 32 messages in flight, then 5 queued.
        cfg.topic_qos[0].1.queue = Some(5);
        cfg
    };
    let Fleet {
        hub,
        proxy,
        agent,
        mut op,
    } = setup(short_queue, true).await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    local
        .send(json!({"op": "advertise", "topic": TOPIC, "type": "std_msgs/msg/String"}))
        .await;
    let send = |n: u64| json!({"op": "publish", "topic": TOPIC, "msg": {"data": n.to_string()}});
    local.send(send(1)).await;
    assert_eq!(received_until(&mut op, 1).await, vec![1]);

    proxy.cut();
    for n in 2..=80 {
        local.send(send(n)).await;
    }
    agent.wait_disconnected().await;
    // A call after the publishes can only be answered once the session got past all of
    // them: while the queue is full, it is not.
    local
        .send(
            json!({"op": "call_service", "service": "/rosapi/get_time", "args": {}, "id": "after"}),
        )
        .await;
    let early = tokio::time::timeout(
        Duration::from_millis(500),
        local.recv_op("service_response"),
    )
    .await;
    assert!(
        early.is_err(),
        "the session answered past a full no-drop queue instead of waiting: {early:?}"
    );
    proxy.restore();
    agent.wait_connected().await;
    assert_eq!(
        received_until(&mut op, 80).await,
        (2..=80).collect::<Vec<_>>(),
        "the publisher was held back, not dropped"
    );
    assert_eq!(local.recv_op("service_response").await["id"], "after");
    let topic = agent
        .router
        .topic(&TopicName::parse(TOPIC).unwrap())
        .expect("topic");
    assert_eq!(
        topic.stats.drops(fleetlink_relay::DropReason::Backpressure),
        0
    );
    agent.shutdown().await;
    hub.shutdown().await;
}
