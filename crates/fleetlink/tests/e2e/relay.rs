//! Messages flow robot → hub → rosbridge client, and operator → hub → robot.

use serde_json::json;

use crate::util::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn robot_topic_reaches_hub_subscriber_under_robot_namespace() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "robot1").await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/robot1/chatter", "id": "s1"}))
        .await;
    let mut pubr = LocalPublisher::new(&agent.router, "/chatter", "std_msgs/msg/String");
    // Publish until the subscription is live end to end; bounded in count and time.
    let got = within("first message at the operator", async {
        for i in 0..2000 {
            pubr.publish_json(&json!({"data": format!("hello {i}")}));
            if let Ok(Some(v)) =
                tokio::time::timeout(std::time::Duration::from_millis(50), op.try_recv()).await
                && v["op"] == "publish"
            {
                return v;
            }
        }
        panic!("no message after 2000 publishes");
    })
    .await;
    assert_eq!(got["topic"], "/robot1/chatter");
    assert!(got["msg"]["data"].as_str().unwrap().starts_with("hello "));

    let topics = op.call("/rosapi/topics", json!({}), "t1").await;
    assert_eq!(topics["result"], true);
    let names: Vec<&str> = topics["values"]["topics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert!(names.contains(&"/robot1/chatter"), "{names:?}");
    let i = names.iter().position(|n| *n == "/robot1/chatter").unwrap();
    assert_eq!(topics["values"]["types"][i], "std_msgs/msg/String");

    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn operator_publish_reaches_robot_local_subscriber() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "robot2").await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    local
        .send(json!({"op": "subscribe", "topic": "/cmd_vel", "id": "l1"}))
        .await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(
        json!({"op": "advertise", "topic": "/robot2/cmd_vel", "type": "geometry_msgs/msg/Twist"}),
    )
    .await;
    let got = within("operator command at the robot", async {
        for _ in 0..2000 {
            op.send(json!({"op": "publish", "topic": "/robot2/cmd_vel", "msg": {"linear": {"x": 0.5, "y": 0, "z": 0}, "angular": {"x": 0, "y": 0, "z": 0.1}}})).await;
            if let Ok(Some(v)) = tokio::time::timeout(std::time::Duration::from_millis(50), local.try_recv()).await
                && v["op"] == "publish"
            {
                return v;
            }
        }
        panic!("no command after 2000 publishes");
    })
    .await;
    assert_eq!(got["topic"], "/cmd_vel");
    assert_eq!(got["msg"]["linear"]["x"], 0.5);
    agent.shutdown().await;
    hub.shutdown().await;
}
