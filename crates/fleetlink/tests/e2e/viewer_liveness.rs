//! Issue 56: a viewer that stops reading without closing its connection is closed after
//! the silence limit, and what it held goes with it — its subscription (the demand), its
//! service with the call waiting on it, its advertisement — while a viewer that reads
//! but never sends stays.

use std::time::{Duration, Instant};

use fleetlink_relay::TopicName;
use fleetlink_relay::websocket::liveness::LivenessConfig;
use serde_json::json;

use crate::util::*;

const LIVENESS: LivenessConfig = LivenessConfig {
    ping_every: Duration::from_millis(300),
    silence: Duration::from_millis(1500),
};

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_56_a_viewer_that_stops_reading_is_closed_and_releases_what_it_held() {
    let hub = start_hub_with(|c| c.viewer_liveness = LIVENESS).await;
    let router = hub.state.router.clone();
    let scan = TopicName::parse("/liveness/scan").unwrap();
    let own = TopicName::parse("/liveness/own").unwrap();
    let ask = TopicName::parse("/liveness/ask").unwrap();
    let mut frozen = Rosbridge::connect(&hub.ws_url()).await;
    frozen
        .send_all([
            json!({"op": "subscribe", "topic": "/liveness/scan", "id": "s"}),
            json!({"op": "advertise", "topic": "/liveness/own", "type": "std_msgs/msg/String"}),
            json!({"op": "advertise_service", "service": "/liveness/ask",
                   "type": "std_srvs/srv/Trigger"}),
        ])
        .await;
    eventually("the frozen viewer's subscription", || {
        router
            .topic(&scan)
            .is_some_and(|t| t.subscriber_count() == 1)
    })
    .await;
    eventually("its service", || router.calls.service(&ask).is_some()).await;
    // From here on it reads nothing (its pings go unanswered) while messages keep coming,
    // which its kernel acknowledges until its receive buffer is full.
    let mut publisher = hub_publisher(&hub, "/liveness/scan", "std_msgs/msg/String");
    let filler = "x".repeat(2000);
    let feed = tokio::spawn(async move {
        loop {
            publisher.publish_json(&json!({ "data": filler }));
            tokio::time::sleep(Duration::from_millis(5)).await;
        }
    });
    // A viewer that reads and sends nothing but a call, which waits on the frozen one.
    let mut caller = Rosbridge::connect(&hub.ws_url()).await;
    let asked = Instant::now();
    let answer = caller.call("/liveness/ask", json!({}), "c1").await;
    let waited = asked.elapsed();
    feed.abort();
    assert_eq!(answer["result"], false, "{answer}");
    assert!(
        waited >= LIVENESS.silence - LIVENESS.ping_every && waited < Duration::from_secs(10),
        "the call ended {waited:?} after it was made: when its provider was closed, not at \
         its deadline"
    );
    assert!(
        router
            .topic(&scan)
            .is_none_or(|t| t.subscriber_count() == 0)
    );
    let publishers = |name: &TopicName| -> usize {
        router
            .topics()
            .iter()
            .filter(|t| t.meta.name == *name)
            .map(|t| t.publishers.len())
            .sum()
    };
    assert_eq!(publishers(&own), 0, "its advertisement is withdrawn");
    assert!(
        router.calls.service(&ask).is_none(),
        "its service is withdrawn"
    );
    // The caller, which read all along, is still served: longer than the silence limit
    // after it connected, it sent nothing but the call.
    let topics = caller.call("/rosapi/topics", json!({}), "c2").await;
    assert_eq!(topics["result"], true, "{topics}");
    // And the frozen viewer's connection was closed: once it reads again it finds the end.
    within("the frozen viewer's connection to end", async {
        while frozen.try_recv().await.is_some() {}
    })
    .await;
    hub.stop.cancel();
}
