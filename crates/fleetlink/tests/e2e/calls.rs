//! Services and actions across the fleet: rosbridge clients on the hub and on a robot's
//! local listener as callers and providers, calls crossing the agent link both ways,
//! deadlines, a provider leaving mid-call, concurrency, large bodies, and the simulated
//! robot's services and navigation action.

use std::time::{Duration, Instant};

use fleetlink_agent::config::SimConfig;
use serde_json::{Value, json};

use crate::util::*;

/// Serves `add_two_ints`-style calls on `client` until `n` have been answered.
async fn serve_adds(client: &mut Rosbridge, n: usize) {
    for _ in 0..n {
        let req = client.recv_op("call_service").await;
        let (a, b) = (
            req["args"]["a"].as_i64().unwrap(),
            req["args"]["b"].as_i64().unwrap(),
        );
        client
            .send(
                json!({"op": "service_response", "id": req["id"], "service": req["service"],
                         "values": {"sum": a + b}, "result": true}),
            )
            .await;
    }
}

async fn advertise(client: &mut Rosbridge, service: &str, type_name: &str) {
    client
        .send(json!({"op": "advertise_service", "service": service, "type": type_name}))
        .await;
}

/// Calls `service` until it answers something other than "not advertised" (an
/// advertisement takes a moment to cross a link).
async fn call_when_ready(client: &mut Rosbridge, service: &str, args: Value) -> Value {
    within("the service to be reachable", async {
        for i in 0.. {
            let r = client
                .call(service, args.clone(), &format!("ready-{i}"))
                .await;
            let text = r["values"].as_str().unwrap_or_default();
            if r["result"] == true || !text.contains("not advertised") {
                return r;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
        unreachable!()
    })
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_cloud_service_is_called_from_the_hub_and_from_a_robots_local_program() {
    let hub = start_hub().await;
    // Robots may call what is under /cloud (by default only their own namespace).
    hub.set_rules(
        "rules:\n  - subject: any_robot\n    names: \"/cloud/.*\"\n    ops: [call_service]\n",
    );
    let agent = start_agent(&hub, "r1").await;
    let mut provider = Rosbridge::connect(&hub.ws_url()).await;
    advertise(
        &mut provider,
        "/cloud/add",
        "example_interfaces/srv/AddTwoInts",
    )
    .await;
    let serving = tokio::spawn(async move {
        serve_adds(&mut provider, 2).await;
        provider
    });
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    let r = call_when_ready(&mut op, "/cloud/add", json!({"a": 2, "b": 3})).await;
    assert_eq!(r["result"], true, "{r}");
    assert_eq!(r["values"]["sum"], 5);
    // A program on the robot calls the same service by its fleet name.
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    let r = call_when_ready(&mut local, "/cloud/add", json!({"a": 40, "b": 2})).await;
    assert_eq!(r["result"], true, "{r}");
    assert_eq!(r["values"]["sum"], 42);
    assert_eq!(r["service"], "/cloud/add");
    let _provider = within("provider task", serving).await.unwrap();
    assert_eq!(hub.state.router.calls.bookkeeping(), 0);
    assert_eq!(agent.router.calls.bookkeeping(), 0);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_robots_local_service_is_called_from_the_hub_under_the_robots_namespace() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "r1").await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    advertise(&mut local, "/echo", "std_srvs/srv/Trigger").await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    let call = tokio::spawn(async move {
        let r = call_when_ready(&mut op, "/r1/echo", json!({})).await;
        (op, r)
    });
    // Early calls may arrive before the advertisement crossed; answer whatever comes.
    let req = local.recv_op("call_service").await;
    assert_eq!(req["service"], "/echo");
    local
        .send(json!({"op": "service_response", "id": req["id"],
                     "values": {"success": true, "message": "hello from r1"}, "result": true}))
        .await;
    let (mut op, r) = within("the call", call).await.unwrap();
    assert_eq!(r["values"]["message"], "hello from r1", "{r}");
    // Listed for the operator with its type and provider.
    let l = op.call("/rosapi/services", json!({}), "l").await;
    let names: Vec<&str> = l["values"]["services"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(Value::as_str)
        .collect();
    assert!(names.contains(&"/r1/echo"), "{names:?}");
    let t = op
        .call("/rosapi/service_type", json!({"service": "/r1/echo"}), "t")
        .await;
    assert_eq!(t["values"]["type"], "std_srvs/srv/Trigger");
    let p = op
        .call(
            "/rosapi/service_providers",
            json!({"service": "/r1/echo"}),
            "p",
        )
        .await;
    assert_eq!(p["values"]["providers"], json!(["/r1"]));
    // The provider leaves: the service disappears from the hub.
    drop(local);
    within("the service to be withdrawn", async {
        while hub
            .state
            .router
            .calls
            .service(&fleetlink_relay::TopicName::parse("/r1/echo").unwrap())
            .is_some()
        {
            tokio::time::sleep(Duration::from_millis(10)).await;
        }
    })
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn fifty_concurrent_calls_through_the_link_are_each_answered_to_their_caller() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "r1").await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    advertise(&mut local, "/add", "example_interfaces/srv/AddTwoInts").await;
    let mut warm = Rosbridge::connect(&hub.ws_url()).await;
    let serving = tokio::spawn(async move {
        serve_adds(&mut local, 51).await;
    });
    call_when_ready(&mut warm, "/r1/add", json!({"a": 0, "b": 0})).await;
    let mut clients = Vec::new();
    for _ in 0..5 {
        clients.push(Rosbridge::connect(&hub.ws_url()).await);
    }
    // 5 clients x 10 calls, all sent before any answer is read.
    for (c, client) in clients.iter_mut().enumerate() {
        for i in 0..10 {
            client
                .send(
                    json!({"op": "call_service", "service": "/r1/add", "id": format!("{c}-{i}"),
                             "args": {"a": c * 100, "b": i}}),
                )
                .await;
        }
    }
    for (c, client) in clients.iter_mut().enumerate() {
        let mut seen = std::collections::BTreeSet::new();
        while seen.len() < 10 {
            let r = client.recv_op("service_response").await;
            let id = r["id"].as_str().unwrap().to_owned();
            let i: usize = id.split('-').nth(1).unwrap().parse().unwrap();
            assert!(id.starts_with(&format!("{c}-")), "client {c} got {id}");
            assert_eq!(r["values"]["sum"], json!(c * 100 + i), "{r}");
            seen.insert(id);
        }
    }
    within("provider", serving).await.unwrap();
    eventually("no call state left", || {
        hub.state.router.calls.bookkeeping() == 0 && agent.router.calls.bookkeeping() == 0
    })
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_silent_provider_times_out_and_a_vanishing_one_fails_its_calls_at_once() {
    let hub = start_hub().await;
    let mut provider = Rosbridge::connect(&hub.ws_url()).await;
    advertise(&mut provider, "/slow", "std_srvs/srv/Trigger").await;
    // The provider's session and the caller's run apart: wait until the hub's call table
    // has the service (it never answers, so it cannot be called until it does).
    let slow = fleetlink_relay::TopicName::parse("/slow").unwrap();
    eventually("/slow advertised at the hub", || {
        hub.state.router.calls.service(&slow).is_some()
    })
    .await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    let t0 = Instant::now();
    op.send(json!({"op": "call_service", "service": "/slow", "id": "t", "timeout": 0.3}))
        .await;
    let r = op.recv_op("service_response").await;
    let waited = t0.elapsed();
    assert_eq!(r["result"], false);
    assert!(r["values"].as_str().unwrap().contains("timeout"), "{r}");
    assert!(
        waited >= Duration::from_millis(250) && waited < Duration::from_secs(3),
        "{waited:?}"
    );
    // The provider saw the request; its late answer is refused with a clear status.
    let req = provider.recv_op("call_service").await;
    provider
        .send(json!({"op": "service_response", "id": req["id"], "values": {}, "result": true}))
        .await;
    let s = provider.recv_op("status").await;
    assert!(
        s["msg"].as_str().unwrap().contains("no request with id"),
        "{s}"
    );
    // No timeout given: the provider leaving ends the call.
    op.send(json!({"op": "call_service", "service": "/slow", "id": "gone"}))
        .await;
    provider.recv_op("call_service").await;
    let t0 = Instant::now();
    drop(provider);
    let r = op.recv_op("service_response").await;
    assert_eq!(r["id"], "gone");
    assert_eq!(r["result"], false);
    assert!(r["values"].as_str().unwrap().contains("went away"), "{r}");
    assert!(t0.elapsed() < Duration::from_secs(2));
    assert_eq!(hub.state.router.calls.bookkeeping(), 0);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn malformed_call_operations_get_a_clear_answer_and_change_nothing() {
    let hub = start_hub().await;
    let mut c = Rosbridge::connect(&hub.ws_url()).await;
    c.send(json!({"op": "call_service", "id": "x"})).await;
    let s = c.recv_op("status").await;
    assert!(
        s["msg"]
            .as_str()
            .unwrap()
            .contains("missing field 'service'"),
        "{s}"
    );
    c.send(json!({"op": "service_response", "id": "nope", "values": {}, "result": true}))
        .await;
    let s = c.recv_op("status").await;
    assert!(
        s["msg"]
            .as_str()
            .unwrap()
            .contains("no request with id nope"),
        "{s}"
    );
    c.send(json!({"op": "advertise_service", "service": "/x"}))
        .await;
    let s = c.recv_op("status").await;
    assert!(
        s["msg"].as_str().unwrap().contains("missing field 'type'"),
        "{s}"
    );
    let r = c.call("/nobody/here", json!({}), "n").await;
    assert_eq!(r["result"], false);
    assert!(
        r["values"].as_str().unwrap().contains("not advertised"),
        "{r}"
    );
    c.send(json!({"op": "send_action_goal", "id": "g", "action": "/no/action", "args": {}}))
        .await;
    let r = c.recv_op("action_result").await;
    assert_eq!(
        (r["id"].clone(), r["result"].clone()),
        (json!("g"), json!(false))
    );
    assert_eq!(r["status"], 6);
    c.send(json!({"op": "cancel_action_goal", "id": "zzz", "action": "/no/action"}))
        .await;
    let s = c.recv_op("status").await;
    assert!(
        s["msg"]
            .as_str()
            .unwrap()
            .contains("no pending goal with id zzz"),
        "{s}"
    );
    c.send(json!({"op": "call_service", "service": "/rosapi/get_time", "id": "t", "args": [1]}))
        .await;
    let r = c.recv_op("service_response").await;
    assert_eq!(
        r["result"], true,
        "rosapi ignores args it does not read: {r}"
    );
    assert!(hub.state.router.calls.services().is_empty());
    assert_eq!(hub.state.router.calls.bookkeeping(), 0);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_large_request_and_response_cross_the_link_in_chunks() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "r1").await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    advertise(&mut local, "/map_echo", "x/srv/Echo").await;
    let blob = "m".repeat(300_000);
    let serving = tokio::spawn(async move {
        loop {
            let req = local.recv_op("call_service").await;
            let data = req["args"]["data"].as_str().unwrap_or_default().to_owned();
            local
                .send(json!({"op": "service_response", "id": req["id"],
                             "values": {"data": format!("{data}!")}, "result": true}))
                .await;
            if data.len() > 1000 {
                return;
            }
        }
    });
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    call_when_ready(&mut op, "/r1/map_echo", json!({"data": "x"})).await;
    let r = op
        .call("/r1/map_echo", json!({"data": blob.clone()}), "big")
        .await;
    assert_eq!(
        r["result"],
        true,
        "{}",
        &r.to_string()[..200.min(r.to_string().len())]
    );
    assert_eq!(r["values"]["data"].as_str().unwrap().len(), 300_001);
    within("provider", serving).await.unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_action_goal_gets_feedback_a_result_and_can_be_cancelled() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "r1").await;
    // The action server is a program on the robot.
    let mut server = Rosbridge::connect(&agent.local_url()).await;
    server
        .send(json!({"op": "advertise_action", "action": "/count", "type": "x/action/Count"}))
        .await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    within("the action to reach the hub", async {
        loop {
            let l = op.call("/rosapi/action_servers", json!({}), "a").await;
            if l["values"]["action_servers"] == json!(["/r1/count"]) {
                return;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    op.send(
        json!({"op": "send_action_goal", "id": "g1", "action": "/r1/count",
                   "action_type": "x/action/Count", "args": {"to": 2}, "feedback": true}),
    )
    .await;
    let goal = server.recv_op("send_action_goal").await;
    assert_eq!(goal["args"]["to"], 2);
    assert_eq!(goal["goal_id"].as_str().unwrap().len(), 36);
    for i in 1..=2 {
        server
            .send(
                json!({"op": "action_feedback", "id": goal["id"], "action": "/count",
                         "values": {"at": i}}),
            )
            .await;
    }
    server
        .send(
            json!({"op": "action_result", "id": goal["id"], "action": "/count",
                     "values": {"done": true}, "status": 4, "result": true}),
        )
        .await;
    for i in 1..=2 {
        let f = op.recv_op("action_feedback").await;
        assert_eq!(
            (f["id"].clone(), f["values"]["at"].clone()),
            (json!("g1"), json!(i))
        );
    }
    let r = op.recv_op("action_result").await;
    assert_eq!(
        (r["status"].clone(), r["result"].clone()),
        (json!(4), json!(true))
    );
    assert_eq!(r["values"]["done"], true);
    // A second goal, cancelled halfway: the server hears the cancel and confirms.
    op.send(
        json!({"op": "send_action_goal", "id": "g2", "action": "/r1/count",
                   "args": {"to": 100}, "feedback": true}),
    )
    .await;
    let goal = server.recv_op("send_action_goal").await;
    op.send(json!({"op": "cancel_action_goal", "id": "g2", "action": "/r1/count"}))
        .await;
    let c = server.recv_op("cancel_action_goal").await;
    assert_eq!(c["id"], goal["id"]);
    server
        .send(
            json!({"op": "action_result", "id": goal["id"], "action": "/count",
                     "values": {"done": false}, "status": 5, "result": true}),
        )
        .await;
    let r = op.recv_op("action_result").await;
    assert_eq!(
        (r["id"].clone(), r["status"].clone()),
        (json!("g2"), json!(5))
    );
    // A third goal whose caller disconnects: the server is told to cancel it.
    op.send(json!({"op": "send_action_goal", "id": "g3", "action": "/r1/count", "args": {}}))
        .await;
    let goal = server.recv_op("send_action_goal").await;
    drop(op);
    let c = server.recv_op("cancel_action_goal").await;
    assert_eq!(c["id"], goal["id"]);
    eventually("no call state left", || {
        hub.state.router.calls.bookkeeping() == 0
    })
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_simulated_robot_offers_set_mode_get_status_and_navigation() {
    let hub = start_hub().await;
    let sim = SimConfig {
        laser_scan: None,
        point_cloud: None,
        image: None,
        ..SimConfig::default()
    };
    let agent = start_agent_sim(uplink_config(&hub, "r1"), false, Some(sim)).await;
    agent.wait_connected().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    let r = call_when_ready(&mut op, "/r1/set_mode", json!({"data": false})).await;
    assert_eq!(r["values"]["success"], true, "{r}");
    assert_eq!(r["values"]["message"], "mode: idle");
    let s = op.call("/r1/get_status", json!({}), "s").await;
    let status: Value = serde_json::from_str(s["values"]["message"].as_str().unwrap()).unwrap();
    assert_eq!(status["mode"], "idle");
    let (x, y) = (status["x"].as_f64().unwrap(), status["y"].as_f64().unwrap());
    // Navigate 0.6 m away: feedback, then the result at the goal.
    let (gx, gy) = (x + 0.6_f64.copysign(-x), y);
    op.send(
        json!({"op": "send_action_goal", "id": "nav", "action": "/r1/navigate_to_pose",
                   "args": {"x": gx, "y": gy}, "feedback": true}),
    )
    .await;
    let f = op.recv_op("action_feedback").await;
    assert!(
        f["values"]["distance_remaining"].as_f64().unwrap() <= 0.61,
        "{f}"
    );
    let r = op.recv_op("action_result").await;
    assert_eq!(r["status"], 4, "{r}");
    assert_eq!(r["values"]["reached"], true);
    let s = op.call("/r1/get_status", json!({}), "s2").await;
    let status: Value = serde_json::from_str(s["values"]["message"].as_str().unwrap()).unwrap();
    assert!(
        (status["x"].as_f64().unwrap() - gx).abs() < 0.05,
        "{status}"
    );
    // A far goal, cancelled: the robot stops short of it.
    op.send(
        json!({"op": "send_action_goal", "id": "far", "action": "/r1/navigate_to_pose",
                   "args": {"x": -gx, "y": gy}, "feedback": true}),
    )
    .await;
    op.recv_op("action_feedback").await;
    op.send(json!({"op": "cancel_action_goal", "id": "far"}))
        .await;
    let r = op.recv_op("action_result").await;
    assert_eq!(
        (r["id"].clone(), r["status"].clone()),
        (json!("far"), json!(5)),
        "{r}"
    );
    assert_eq!(r["values"]["reached"], false);
    // Outside the room: aborted with the reason.
    op.send(
        json!({"op": "send_action_goal", "id": "out", "action": "/r1/navigate_to_pose",
                   "args": {"x": 50.0, "y": 0.0}}),
    )
    .await;
    let r = op.recv_op("action_result").await;
    assert_eq!(r["status"], 6, "{r}");
}

/// What the ROS 1 adapter does on a robot with `parameters: true`: rosapi's parameter
/// services in the agent's call table (here answered from a fixed set, since this test
/// is about the hub's routing; tests/interop/ros1 runs it against a real ROS master).
/// Returns the names the robot was asked about.
fn robot_parameters(agent: &TestAgent) -> std::sync::Arc<std::sync::Mutex<Vec<String>>> {
    use fleetlink_relay::calls::{CallStatus, ChannelPeer, PeerMsg};
    let router = agent.router.clone();
    let (client, _outbox) = router.connect(
        fleetlink_relay::ClientKind::Internal {
            role: "params".into(),
        },
        None,
    );
    let (peer, rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    for s in ["get_param", "set_param", "search_param", "get_param_names"] {
        router.calls.advertise(
            client,
            fleetlink_relay::TopicName::parse(&format!("/rosapi/{s}")).unwrap(),
            fleetlink_proto::Schema::named(format!("rosapi/srv/{s}")),
            false,
        );
    }
    let asked = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
    let seen = asked.clone();
    tokio::spawn(async move {
        let _outbox = _outbox;
        while let Some(m) = rx.recv().await {
            let PeerMsg::Call(req) = m else { continue };
            let args: Value = serde_json::from_slice(&req.payload.bytes).unwrap_or_default();
            let name = args["name"].as_str().unwrap_or_default().to_owned();
            seen.lock().unwrap().push(name.clone());
            let values = match req.service.name.as_str() {
                "/rosapi/get_param" if name == "/max_speed" => json!({"value": "1.5"}),
                "/rosapi/get_param" => json!({"value": "null"}),
                "/rosapi/search_param" => json!({"global_name": name}),
                "/rosapi/get_param_names" => json!({"names": ["/max_speed", "/nav/rate"]}),
                _ => json!({}),
            };
            router.calls.respond(
                client,
                req.id,
                CallStatus::Ok,
                Some(fleetlink_proto::Payload::json(
                    serde_json::to_vec(&values).unwrap(),
                )),
                String::new(),
            );
        }
    });
    asked
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_robots_parameters_are_read_and_changed_on_the_robot_under_the_acl() {
    let hub = start_hub().await;
    // Robots may call rosapi; their own namespace is theirs by default, r1's is not r2's.
    // r2 may also call r1's parameter services by name, but not read r1's parameters.
    hub.set_rules(
        "rules:\n  - subject: any_robot\n    names: \"/rosapi/.*\"\n    ops: [call_service]\n  - subject: {robot: r2}\n    names: \"/r1/rosapi/.*\"\n    ops: [call_service]\n",
    );
    let agent = start_agent(&hub, "r1").await;
    let asked = robot_parameters(&agent);
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    // Until the robot's services have crossed the link, the hub answers from its own
    // (empty) store.
    let r = within("the robot's parameters to be reachable", async {
        for i in 0.. {
            let r = op
                .call(
                    "/rosapi/get_param",
                    json!({"name": "/r1/max_speed"}),
                    &format!("g{i}"),
                )
                .await;
            if r["values"]["value"] != "null" {
                return r;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
        unreachable!()
    })
    .await;
    assert_eq!(r["result"], true, "{r}");
    assert_eq!(r["service"], "/rosapi/get_param");
    assert_eq!(r["values"]["value"], "1.5", "{r}");
    assert_eq!(asked.lock().unwrap().last().unwrap(), "/max_speed");
    // A found name comes back in the hub's names.
    let r = op
        .call("/rosapi/search_param", json!({"name": "r1/nav/rate"}), "s")
        .await;
    assert_eq!(r["values"]["global_name"], "/r1/nav/rate", "{r}");
    // The robot's namespace itself is its whole tree.
    op.call("/rosapi/get_param", json!({"name": "/r1"}), "all")
        .await;
    assert_eq!(asked.lock().unwrap().last().unwrap(), "/");
    // Outside any robot that provides parameters: the hub's own store.
    let r = op
        .call(
            "/rosapi/set_param",
            json!({"name": "/r9/x", "value": "2"}),
            "h",
        )
        .await;
    assert_eq!(r["result"], true, "{r}");
    let r = op
        .call("/rosapi/get_param", json!({"name": "/r9/x"}), "h2")
        .await;
    assert_eq!(r["values"]["value"], "2", "{r}");
    // The listing of names has the hub's and the robot's, in the hub's names.
    let r = op.call("/rosapi/get_param_names", json!({}), "n").await;
    assert_eq!(r["result"], true, "{r}");
    assert_eq!(
        r["values"]["names"],
        json!(["/r1/max_speed", "/r1/nav/rate", "/r9/x"]),
        "{r}"
    );
    // Another robot may neither read nor change r1's parameters; r1 never hears of it.
    let before = asked.lock().unwrap().len();
    let other = format!("ws://{}/?token={}", hub.addr, hub.robot_token("r2"));
    let mut r2 = Rosbridge::connect(&other).await;
    let refused = |r: &Value, why: &str| {
        assert_eq!(r["result"], false, "{r}");
        let text = r["values"].as_str().unwrap_or_default();
        assert!(text.contains(why), "{r}");
    };
    let r = r2
        .call("/rosapi/get_param", json!({"name": "/r1/max_speed"}), "x")
        .await;
    refused(&r, "not allowed to read parameter /r1/max_speed");
    let args = json!({"name": "/r1/max_speed", "value": "9"});
    let r = r2.call("/rosapi/set_param", args, "y").await;
    refused(&r, "not allowed to change parameter /r1/max_speed");
    // Nor does it see r1's names in a listing (r1 is asked, the ACL filters).
    let r = r2.call("/rosapi/get_param_names", json!({}), "l").await;
    assert_eq!(r["result"], true, "{r}");
    let names = r["values"]["names"].as_array().expect("names").clone();
    assert!(
        names
            .iter()
            .all(|n| !n.as_str().unwrap().starts_with("/r1/")),
        "{r}"
    );
    // Calling r1's parameter service by its own name is held to the same rule.
    let args = json!({"name": "max_speed"});
    let r = r2.call("/r1/rosapi/get_param", args, "z").await;
    refused(&r, "not allowed to read parameter /r1/max_speed");
    assert_eq!(
        asked.lock().unwrap().len(),
        before + 1,
        "r1 heard only of the listing"
    );
    // The operator may, by either name.
    let args = json!({"name": "/max_speed"});
    let r = op.call("/r1/rosapi/get_param", args, "direct").await;
    assert_eq!(r["values"]["value"], "1.5", "{r}");
}

/// A provider's `service_response` means what rosbridge makes it mean: `values` that are
/// an object are the answer whatever `result` says (roslibjs leaves `result` out and
/// roslibpy sends `null` when the callback returns nothing); only an answer without them
/// fails the call with `result: false`.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_provider_answer_is_read_as_rosbridge_reads_it() {
    let hub = start_hub().await;
    let mut provider = Rosbridge::connect(&hub.ws_url()).await;
    advertise(&mut provider, "/answers", "std_srvs/srv/Trigger").await;
    let name = fleetlink_relay::TopicName::parse("/answers").unwrap();
    eventually("/answers advertised at the hub", || {
        hub.state.router.calls.service(&name).is_some()
    })
    .await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    let values = json!({"success": true, "message": "done"});
    // (the answer's fields besides op and id, the caller's result, its values)
    let cases = [
        (
            json!({"values": values, "result": true}),
            true,
            values.clone(),
        ),
        (
            json!({"values": values, "result": false}),
            true,
            values.clone(),
        ),
        (json!({"values": values}), true, values.clone()),
        (
            json!({"values": values, "result": null}),
            true,
            values.clone(),
        ),
        (
            json!({"result": true}),
            true,
            json!({"success": false, "message": ""}),
        ),
        (
            json!({}),
            false,
            json!(
                "service /answers failed: the provider of /answers answered without a response (no 'values', no 'result')"
            ),
        ),
        (
            json!({"result": false}),
            false,
            json!("service /answers failed: the provider of /answers answered result: false"),
        ),
        (
            json!({"values": "disk full", "result": false}),
            false,
            json!("service /answers failed: disk full"),
        ),
    ];
    for (i, (answer, ok, want)) in cases.into_iter().enumerate() {
        let id = format!("c{i}");
        op.send(json!({"op": "call_service", "service": "/answers", "id": id}))
            .await;
        let req = provider.recv_op("call_service").await;
        let mut reply = answer.clone();
        reply["op"] = json!("service_response");
        reply["id"] = req["id"].clone();
        provider.send(reply).await;
        let r = op.recv_op("service_response").await;
        assert_eq!(r["id"], json!(id));
        assert_eq!(r["result"], json!(ok), "answer {answer}: {r}");
        assert_eq!(r["values"], want, "answer {answer}: {r}");
    }
    // Values that are neither a response nor a failure's text: the caller hears an error,
    // the provider a status naming the field.
    op.send(json!({"op": "call_service", "service": "/answers", "id": "bad"}))
        .await;
    let req = provider.recv_op("call_service").await;
    provider
        .send(json!({"op": "service_response", "id": req["id"], "values": [1, 2], "result": true}))
        .await;
    let r = op.recv_op("service_response").await;
    assert_eq!(r["result"], false, "{r}");
    let s = provider.recv_op("status").await;
    assert!(
        s["msg"]
            .as_str()
            .unwrap()
            .contains("'values' must be an object"),
        "{s}"
    );
    assert_eq!(hub.state.router.calls.bookkeeping(), 0);
}
