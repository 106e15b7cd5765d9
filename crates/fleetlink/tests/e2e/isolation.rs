//! A subscriber that stops reading loses its own messages; the publisher and every other
//! subscriber carry on at full rate.

use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use fleetlink_relay::queue::DropReason;
use serde_json::json;

use crate::util::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn stalled_subscriber_does_not_slow_publisher_or_others() {
    let hub = start_hub().await;
    let mut stalled = Rosbridge::connect(&hub.ws_url()).await;
    stalled
        .send(json!({"op": "subscribe", "topic": "/bulk", "queue_length": 10, "id": "stalled"}))
        .await;
    let mut fast = Rosbridge::connect(&hub.ws_url()).await;
    fast.send(json!({"op": "subscribe", "topic": "/bulk", "queue_length": 100000, "id": "fast"}))
        .await;
    // Both subscriptions are in place once the topic lists two subscribers.
    within("two subscribers", async {
        loop {
            if hub
                .state
                .router
                .topic(&fleetlink_relay::TopicName::parse("/bulk").unwrap())
                .is_some_and(|t| t.subscriber_count() == 2)
            {
                return;
            }
            tokio::time::sleep(Duration::from_millis(10)).await;
        }
    })
    .await;

    // 20 MB in 20,000 messages: far more than the stalled client's socket buffers hold.
    let n = 20_000u32;
    let filler = "x".repeat(1000);
    let mut pubr = hub_publisher(&hub, "/bulk", "std_msgs/msg/String");
    let reader = tokio::spawn(async move {
        let mut next = 0u32;
        while next < n {
            let v = fast.recv_op("publish").await;
            let i: u32 = v["msg"]["i"].as_u64().unwrap() as u32;
            assert_eq!(
                i, next,
                "fast subscriber got messages out of order or lost one"
            );
            next += 1;
        }
        next
    });
    // Publishing is a synchronous push into each subscriber's queue: it cannot wait for a
    // subscriber, so this loop finishing while one client reads nothing is the point.
    for i in 0..n {
        pubr.publish_json(&json!({"i": i, "data": filler}));
        if i % 500 == 0 {
            tokio::task::yield_now().await;
        }
    }
    let got = within("fast subscriber to receive everything", reader)
        .await
        .unwrap();
    assert_eq!(got, n);

    // The stalled subscriber lost messages, counted against the topic and reason.
    let topic = hub
        .state
        .router
        .topic(&fleetlink_relay::TopicName::parse("/bulk").unwrap())
        .unwrap();
    assert!(
        topic.stats.drops(DropReason::Policy) > 0,
        "the stalled subscriber's queue never overflowed"
    );
    let clients = hub.state.router.clients();
    let dropped: Vec<u64> = clients
        .iter()
        .map(|(_, o, _)| o.dropped.load(Relaxed))
        .collect();
    assert_eq!(
        dropped.iter().filter(|d| **d > 0).count(),
        1,
        "exactly one client lost messages: {dropped:?}"
    );
    drop(stalled);
    hub.shutdown().await;
}
