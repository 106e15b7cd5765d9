//! The bridge against fleetlink's own rosbridge server, in process: a "robot" router
//! served over a real WebSocket on port 0, and the agent's router the bridge feeds.
//! Every wait is bounded; nothing sleeps to let things propagate.

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::{Duration, Instant};

use fleetlink_proto::{Payload, Schema};
use fleetlink_relay::calls::{CallEvent, CallOptions, CallStatus, ChannelPeer, PeerMsg};
use fleetlink_relay::outbox::Outbox;
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::transcode::RegistryTranscoder;
use fleetlink_relay::{ClientKind, Router, TopicName};
use fleetlink_rosbridge::SessionConfig;
use fleetlink_rosbridge_client::{NameFilter, RosbridgeClientOptions, RosbridgeClientStats, run};
use tokio::net::TcpListener;
use tokio_util::sync::CancellationToken;

const WAIT: Duration = Duration::from_secs(10);

fn router() -> Arc<Router> {
    Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())))
}

fn name(n: &str) -> TopicName {
    TopicName::parse(n).unwrap()
}

/// Serves `router` as a rosbridge server on `listener` until `stop`.
fn serve(listener: TcpListener, router: Arc<Router>, stop: CancellationToken) {
    tokio::spawn(async move {
        loop {
            let (tcp, addr) = tokio::select! {
                r = listener.accept() => r.expect("accept"),
                _ = stop.cancelled() => return,
            };
            let (router, stop) = (router.clone(), stop.clone());
            tokio::spawn(async move {
                let Ok(ws) = tokio_tungstenite::accept_async(tcp).await else {
                    return;
                };
                let cfg = Arc::new(SessionConfig::default());
                let (sink, stream) =
                    fleetlink_relay::websocket::server(ws.into_inner(), cfg.max_message_size);
                let auth = fleetlink_relay::gate::SessionAuth::open();
                fleetlink_rosbridge::serve(sink, stream, router, Some(addr), cfg, stop, auth).await;
            });
        }
    });
}

/// The robot's programs: a `/chatter` publisher and a `/set_flag` provider whose answer
/// names the request, on the server's router.
struct Robot {
    router: Arc<Router>,
    chatter: Arc<fleetlink_relay::router::Topic>,
    client: fleetlink_relay::ClientId,
}

impl Robot {
    fn start(router: Arc<Router>) -> Robot {
        let (client, _) = router.connect(
            ClientKind::Internal {
                role: "robot".into(),
            },
            None,
        );
        let chatter = router
            .advertise(
                client,
                &name("/chatter"),
                Schema::named("std_msgs/msg/String"),
                false,
            )
            .unwrap();
        let (peer, rx) = ChannelPeer::new();
        router.calls.attach(client, peer);
        router.calls.advertise(
            client,
            name("/set_flag"),
            Schema::named("std_srvs/srv/SetBool"),
            false,
        );
        let r = router.clone();
        tokio::spawn(async move {
            while let Some(m) = rx.recv().await {
                if let PeerMsg::Call(req) = m {
                    let asked = String::from_utf8_lossy(&req.payload.bytes).into_owned();
                    let data = asked.contains("true");
                    let body = format!(r#"{{"success":true,"message":"flag {data}"}}"#);
                    r.calls.respond(
                        client,
                        req.id,
                        CallStatus::Ok,
                        Some(Payload::json(body.into_bytes())),
                        String::new(),
                    );
                }
            }
        });
        Robot {
            router,
            chatter,
            client,
        }
    }

    fn say(&self, n: u64) {
        let body = format!(r#"{{"data":"hello {n}"}}"#);
        self.chatter
            .publish(self.client, n, 0, Payload::json(body.into_bytes()));
    }
}

/// Texts of the messages waiting in `outbox`, waiting at most until `until`.
async fn texts(outbox: &Outbox, until: Instant) -> Vec<String> {
    let left = until.saturating_duration_since(Instant::now());
    if tokio::time::timeout(left, outbox.ready()).await.is_err() {
        return Vec::new();
    }
    outbox
        .take(64, 1 << 20, Instant::now())
        .items
        .into_iter()
        .map(|(_, _, m)| String::from_utf8_lossy(&m.payload.bytes).into_owned())
        .collect()
}

/// Robot messages reach the agent's router: keeps publishing until one arrives.
async fn expect_chatter(robot: &Robot, agent_side: &Outbox, from: u64) -> String {
    let until = Instant::now() + WAIT;
    let mut n = from;
    while Instant::now() < until {
        robot.say(n);
        n += 1;
        let got = texts(
            agent_side,
            (Instant::now() + Duration::from_millis(100)).min(until),
        )
        .await;
        if let Some(t) = got.into_iter().find(|t| t.contains("hello")) {
            return t;
        }
    }
    panic!("no /chatter message reached the agent's router within {WAIT:?}");
}

fn options(addr: SocketAddr) -> RosbridgeClientOptions {
    let mut o = RosbridgeClientOptions::new(format!("ws://{addr}"));
    o.publish = NameFilter::new(&["/chatter".into()], &[]).unwrap();
    o.expose = NameFilter::new(&["/set_.*".into()], &[]).unwrap();
    o.subscribe = vec![name("/cmd")];
    o.discovery_period = Duration::from_millis(100);
    o.reconnect_initial = Duration::from_millis(50);
    o.reconnect_max = Duration::from_millis(400);
    o
}

/// Calls `/set_flag` through the agent's router; the provider's answer or the failure.
async fn call_set_flag(agent: &Router) -> Result<String, String> {
    let (client, _) = agent.connect(
        ClientKind::Internal {
            role: "caller".into(),
        },
        None,
    );
    let (peer, rx) = ChannelPeer::new();
    agent.calls.attach(client, peer);
    let until = Instant::now() + WAIT;
    // The service appears once discovery has found it.
    let id = loop {
        match agent.calls.call(
            client,
            &name("/set_flag"),
            Payload::json(&br#"{"data":true}"#[..]),
            CallOptions::default(),
        ) {
            Ok(id) => break id,
            Err(e) if Instant::now() > until => return Err(e.text),
            Err(_) => tokio::time::sleep(Duration::from_millis(20)).await,
        }
    };
    let left = until.saturating_duration_since(Instant::now());
    let answer = match tokio::time::timeout(left, rx.recv()).await {
        Ok(Some(PeerMsg::Event(CallEvent::Done {
            id: done,
            status,
            payload,
            text,
        }))) if done == id => match (status, payload) {
            (CallStatus::Ok, Some(p)) => Ok(String::from_utf8_lossy(&p.bytes).into_owned()),
            (s, _) => Err(format!("{s:?}: {text}")),
        },
        other => Err(format!("no answer: {other:?}")),
    };
    agent.disconnect(client);
    answer
}

#[tokio::test]
async fn topics_and_services_cross_both_ways_and_survive_a_server_restart() {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    let server_stop = CancellationToken::new();
    let robot = Robot::start(router());
    serve(listener, robot.router.clone(), server_stop.clone());

    let agent = router();
    let (watcher, watched) = agent.connect(ClientKind::Internal { role: "hub".into() }, None);
    agent
        .subscribe(
            watcher,
            Target::Exact(name("/chatter")),
            SubOptions::default(),
        )
        .unwrap();
    let stop = CancellationToken::new();
    let stats = Arc::new(RosbridgeClientStats::default());
    let bridge = tokio::spawn(run(
        options(addr),
        agent.clone(),
        stats.clone(),
        stop.clone(),
    ));

    // Up: the robot's /chatter, with the registry's definition.
    let got = expect_chatter(&robot, &watched, 0).await;
    assert!(got.contains("hello"), "{got}");
    let meta = agent.topic(&name("/chatter")).unwrap().meta();
    assert_eq!(meta.schema.type_name, "std_msgs/msg/String");
    assert!(
        meta.schema.text.contains("string data"),
        "{:?}",
        meta.schema
    );

    // Services: the robot's /set_flag called from the agent side.
    assert_eq!(
        call_set_flag(&agent).await.unwrap(),
        r#"{"success":true,"message":"flag true"}"#
    );

    // Down: the agent's /cmd published on the server.
    let (listener_client, robot_side) = robot.router.connect(
        ClientKind::Internal {
            role: "listener".into(),
        },
        None,
    );
    robot
        .router
        .subscribe(
            listener_client,
            Target::Exact(name("/cmd")),
            SubOptions::default(),
        )
        .unwrap();
    let (sender, _) = agent.connect(
        ClientKind::Internal {
            role: "fleet".into(),
        },
        None,
    );
    let cmd = agent
        .advertise(
            sender,
            &name("/cmd"),
            Schema::named("std_msgs/msg/String"),
            false,
        )
        .unwrap();
    let until = Instant::now() + WAIT;
    let mut seen = false;
    while !seen && Instant::now() < until {
        cmd.publish(sender, 1, 0, Payload::json(&br#"{"data":"go"}"#[..]));
        let got = texts(
            &robot_side,
            (Instant::now() + Duration::from_millis(100)).min(until),
        )
        .await;
        seen = got.iter().any(|t| t.contains("go"));
    }
    assert!(
        seen,
        "the agent's /cmd did not reach the server within {WAIT:?}"
    );

    // The server restarts (a new process: a new router, the robot's programs again).
    server_stop.cancel();
    let listener = loop {
        match TcpListener::bind(addr).await {
            Ok(l) => break l,
            Err(_) if Instant::now() < until + WAIT => {
                tokio::time::sleep(Duration::from_millis(20)).await
            }
            Err(e) => panic!("cannot listen on {addr} again: {e}"),
        }
    };
    let robot = Robot::start(router());
    serve(listener, robot.router.clone(), CancellationToken::new());
    let got = expect_chatter(&robot, &watched, 1000).await;
    assert!(got.contains("hello 1"), "after the restart: {got}");
    assert_eq!(
        call_set_flag(&agent).await.unwrap(),
        r#"{"success":true,"message":"flag true"}"#
    );
    assert!(
        stats.connects.load(std::sync::atomic::Ordering::Relaxed) >= 2,
        "connected again"
    );

    stop.cancel();
    tokio::time::timeout(WAIT, bridge)
        .await
        .expect("the bridge stops when told")
        .unwrap()
        .unwrap();
}

#[tokio::test]
async fn a_url_that_cannot_work_is_an_error_at_start() {
    let opts = RosbridgeClientOptions::new("tcp://robot:9090");
    let stats = Arc::new(RosbridgeClientStats::default());
    let r = tokio::time::timeout(
        Duration::from_secs(1),
        run(opts, router(), stats, CancellationToken::new()),
    )
    .await
    .expect("returns at once, not retried");
    assert_eq!(
        r.unwrap_err().to_string(),
        "rosbridge: url \"tcp://robot:9090\" must start with ws:// or wss://"
    );
}

/// A goal from the fleet to the robot's action server: `send_action_goal` on the server,
/// its feedback and its result come back; a second goal is cancelled.
#[tokio::test]
async fn action_goals_reach_the_servers_action_with_feedback_result_and_cancel() {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    let robot = router();
    serve(listener, robot.clone(), CancellationToken::new());
    // The robot's action server: one feedback, then the result (order 0: never ends,
    // waits to be cancelled).
    let (server, _) = robot.connect(ClientKind::Internal { role: "fib".into() }, None);
    let (peer, rx) = ChannelPeer::new();
    robot.calls.attach(server, peer);
    robot.calls.advertise(
        server,
        name("/fibonacci"),
        Schema::named("example_interfaces/action/Fibonacci"),
        true,
    );
    let r = robot.clone();
    tokio::spawn(async move {
        while let Some(m) = rx.recv().await {
            match m {
                PeerMsg::Call(req) => {
                    let forever =
                        String::from_utf8_lossy(&req.payload.bytes).contains("\"order\":0");
                    r.calls
                        .feedback(server, req.id, Payload::json(&br#"{"sequence":[0,1]}"#[..]));
                    if !forever {
                        r.calls.respond(
                            server,
                            req.id,
                            CallStatus::Ok,
                            Some(Payload::json(&br#"{"sequence":[0,1,1,2]}"#[..])),
                            String::new(),
                        );
                    }
                }
                PeerMsg::Cancel(id) => {
                    r.calls
                        .respond(server, id, CallStatus::Cancelled, None, "cancelled".into());
                }
                _ => {}
            }
        }
    });

    let agent = router();
    let stop = CancellationToken::new();
    let mut opts = options(addr);
    opts.expose_actions = NameFilter::new(&["/fib.*".into()], &[]).unwrap();
    let stats = Arc::new(RosbridgeClientStats::default());
    tokio::spawn(run(opts, agent.clone(), stats, stop.clone()));

    let (caller, _) = agent.connect(ClientKind::Internal { role: "op".into() }, None);
    let (peer, events) = ChannelPeer::new();
    agent.calls.attach(caller, peer);
    let goal = |order: i32| {
        agent.calls.call(
            caller,
            &name("/fibonacci"),
            Payload::json(format!(r#"{{"order":{order}}}"#).into_bytes()),
            CallOptions {
                goal: true,
                ..CallOptions::default()
            },
        )
    };
    let until = Instant::now() + WAIT;
    let first = loop {
        match goal(3) {
            Ok(id) => break id,
            Err(e) if Instant::now() > until => panic!("the action never appeared: {}", e.text),
            Err(_) => tokio::time::sleep(Duration::from_millis(20)).await,
        }
    };
    let next = || async {
        let left = until.saturating_duration_since(Instant::now());
        match tokio::time::timeout(left, events.recv()).await {
            Ok(Some(PeerMsg::Event(e))) => e,
            other => panic!("no call event within {WAIT:?}: {other:?}"),
        }
    };
    match next().await {
        CallEvent::Feedback { id, payload } => {
            assert_eq!(id, first);
            assert_eq!(&payload.bytes[..], br#"{"sequence":[0,1]}"#);
        }
        other => panic!("expected feedback, got {other:?}"),
    }
    match next().await {
        CallEvent::Done {
            id,
            status,
            payload,
            ..
        } => {
            assert_eq!((id, status), (first, CallStatus::Ok));
            assert_eq!(&payload.unwrap().bytes[..], br#"{"sequence":[0,1,1,2]}"#);
        }
        other => panic!("expected the result, got {other:?}"),
    }

    let second = goal(0).expect("a second goal");
    assert!(matches!(next().await, CallEvent::Feedback { id, .. } if id == second));
    assert!(agent.calls.cancel(caller, second));
    match next().await {
        CallEvent::Done { id, status, .. } => {
            assert_eq!((id, status), (second, CallStatus::Cancelled))
        }
        other => panic!("expected the cancelled goal's end, got {other:?}"),
    }
    stop.cancel();
}

/// A robot type the agent has never seen: its definition comes from the server's
/// `/rosapi/message_details` typedefs, and the agent's registry learns it.
#[tokio::test]
async fn an_unknown_type_is_defined_from_the_servers_typedefs() {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    let robot = router();
    serve(listener, robot.clone(), CancellationToken::new());
    let (program, _) = robot.connect(ClientKind::Internal { role: "bms".into() }, None);
    let schema = Schema {
        type_name: "acme_msgs/msg/Battery".into(),
        encoding: "ros2msg".into(),
        text: "float32 voltage\nstring[] cells\n".into(),
    };
    robot
        .advertise(program, &name("/battery"), schema, false)
        .unwrap();

    let agent = router();
    assert!(
        agent
            .transcoder()
            .schema_for("acme_msgs/msg/Battery")
            .is_none()
    );
    let mut opts = options(addr);
    opts.publish = NameFilter::new(&["/battery".into()], &[]).unwrap();
    let stop = CancellationToken::new();
    let stats = Arc::new(RosbridgeClientStats::default());
    tokio::spawn(run(opts, agent.clone(), stats, stop.clone()));
    let until = Instant::now() + WAIT;
    let meta = loop {
        if let Some(t) = agent.topic(&name("/battery")) {
            break t.meta();
        }
        assert!(
            Instant::now() < until,
            "/battery was not bridged within {WAIT:?}"
        );
        tokio::time::sleep(Duration::from_millis(20)).await;
    };
    assert_eq!(meta.schema.type_name, "acme_msgs/msg/Battery");
    assert_eq!(meta.schema.text, "float32 voltage\nstring[] cells\n");
    let learned = agent
        .transcoder()
        .schema_for("acme_msgs/msg/Battery")
        .expect("the agent's registry learned the type");
    assert!(learned.text.contains("string[] cells"), "{learned:?}");
    stop.cancel();
}

/// A fleet service offered on the robot's server (`advertise_service`): a program there
/// calls it and gets the fleet provider's answer.
#[tokio::test]
async fn a_fleet_service_is_offered_on_the_server_and_answers_its_callers() {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    let robot = router();
    serve(listener, robot.clone(), CancellationToken::new());

    // The fleet's /cloud/greet, provided on the agent's side.
    let agent = router();
    let (cloud, _) = agent.connect(
        ClientKind::Internal {
            role: "cloud".into(),
        },
        None,
    );
    let (peer, rx) = ChannelPeer::new();
    agent.calls.attach(cloud, peer);
    agent.calls.advertise(
        cloud,
        name("/cloud/greet"),
        Schema::named("std_srvs/srv/Trigger"),
        false,
    );
    let a = agent.clone();
    tokio::spawn(async move {
        while let Some(m) = rx.recv().await {
            if let PeerMsg::Call(req) = m {
                let body = br#"{"success":true,"message":"hello from the cloud"}"#;
                a.calls.respond(
                    cloud,
                    req.id,
                    CallStatus::Ok,
                    Some(Payload::json(&body[..])),
                    String::new(),
                );
            }
        }
    });
    let mut opts = options(addr);
    opts.offer = NameFilter::new(&["/cloud/.*".into()], &[]).unwrap();
    let stop = CancellationToken::new();
    let stats = Arc::new(RosbridgeClientStats::default());
    tokio::spawn(run(opts, agent.clone(), stats, stop.clone()));

    // A program on the robot's server calls it once it is advertised there.
    let (program, _) = robot.connect(
        ClientKind::Internal {
            role: "program".into(),
        },
        None,
    );
    let (peer, events) = ChannelPeer::new();
    robot.calls.attach(program, peer);
    let until = Instant::now() + WAIT;
    let id = loop {
        match robot.calls.call(
            program,
            &name("/cloud/greet"),
            Payload::json(&b"{}"[..]),
            CallOptions::default(),
        ) {
            Ok(id) => break id,
            Err(e) if Instant::now() > until => panic!("never offered on the server: {}", e.text),
            Err(_) => tokio::time::sleep(Duration::from_millis(20)).await,
        }
    };
    let left = until.saturating_duration_since(Instant::now());
    match tokio::time::timeout(left, events.recv()).await {
        Ok(Some(PeerMsg::Event(CallEvent::Done {
            id: done,
            status,
            payload,
            text,
        }))) => {
            assert_eq!((done, status), (id, CallStatus::Ok), "{text}");
            let body: serde_json::Value = serde_json::from_slice(&payload.unwrap().bytes).unwrap();
            assert_eq!(body["message"], "hello from the cloud");
        }
        other => panic!("no answer within {WAIT:?}: {other:?}"),
    }
    stop.cancel();
}
