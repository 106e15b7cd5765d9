//! Issue 36, item 5: a stopping hub or agent closes its sessions with a close code and
//! returns, having waited for them.

use std::time::Duration;

use futures_util::StreamExt;
use serde_json::json;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;

use crate::util::*;

/// Reads `client` until its close frame; returns (code, reason).
async fn close_of(client: &mut Rosbridge) -> (CloseCode, String) {
    within("a close frame", async {
        loop {
            match client.raw().next().await {
                Some(Ok(Message::Close(Some(c)))) => return (c.code, c.reason.to_string()),
                Some(Ok(Message::Close(None))) => panic!("a close frame without a code"),
                Some(Ok(_)) => continue,
                other => panic!("the connection ended without a close frame: {other:?}"),
            }
        }
    })
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue36_a_stopping_hub_closes_agents_and_clients_with_1001_and_returns() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "robot_sd").await;
    let mut client = Rosbridge::connect(&hub.ws_url()).await;
    // A live session, not a half-open one: it has been answered once.
    let topics = client.call("/rosapi/topics", json!({}), "t").await;
    assert_eq!(topics["result"], true);

    // `within` bounds it: the hub returns once its sessions are closed.
    hub.shutdown().await;

    let (code, reason) = close_of(&mut client).await;
    assert_eq!(code, CloseCode::Away, "{reason}");
    assert!(reason.contains("shutting down"), "{reason}");
    let why = agent.wait_disconnected().await;
    assert!(why.contains("the hub is shutting down"), "{why}");
    agent.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue36_a_stopping_agent_closes_its_link_and_local_clients_with_1001() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "robot_sa").await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    let answered = local.call("/rosapi/topics", json!({}), "t").await;
    assert_eq!(answered["result"], true);
    // The hub's /rosout says why the robot left.
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/rosout", "id": "r"}))
        .await;
    let _ = op.call("/rosapi/topics", json!({}), "sync").await;

    agent.shutdown().await;

    let (code, reason) = close_of(&mut local).await;
    assert_eq!(code, CloseCode::Away, "{reason}");
    let said = within("the hub's /rosout to tell why robot_sa left", async {
        loop {
            let m = op.recv_op("publish").await;
            let text = m["msg"]["msg"].as_str().unwrap_or_default().to_owned();
            if text.contains("robot robot_sa disconnected") {
                return text;
            }
        }
    })
    .await;
    assert!(said.contains("the agent is shutting down"), "{said}");
    assert!(!hub.state.registry.is_online("robot_sa"));
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue36_a_stopping_hub_returns_within_its_grace_time_when_a_peer_never_reads() {
    let hub = start_hub().await;
    // A rosbridge client that subscribes to everything and never reads again: its
    // session's writer blocks on a full socket, and the hub must not wait for it forever.
    let mut stuck = Rosbridge::connect(&hub.ws_url()).await;
    stuck
        .send(json!({"op": "subscribe", "topic": ".*", "regex": true, "id": "all"}))
        .await;
    let mut publisher = hub_publisher(&hub, "/flood", "std_msgs/msg/String");
    let big = "x".repeat(60_000);
    for _ in 0..400 {
        publisher.publish_json(&json!({ "data": big }));
    }
    hub.stop.cancel();
    // The stuck session is waited for only as long as the grace time (plus slack for a
    // loaded machine), never for ever.
    let bound = fleetlink_hub::server::SHUTDOWN_GRACE + Duration::from_secs(10);
    tokio::time::timeout(bound, hub.task)
        .await
        .expect("the hub returned within its grace time")
        .expect("the hub's task ended cleanly");
    drop(stuck);
}
