//! The bridge against an in-process ROS graph: a fake master and a fake publisher node
//! speaking the same XML-RPC and TCPROS as rosmaster and rospy (built from this crate's
//! codecs), so the whole path runs in `cargo test` without a ROS installation. The
//! interop suite (tests/interop/ros1) does the same against Debian's real ROS 1.
//!
//! Ports are chosen by the OS; every wait is bounded and event-driven (polling a
//! condition), never a fixed sleep to "let things propagate".

use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::transcode::RegistryTranscoder;
use fleetlink_relay::{ClientKind, Router, TopicName};
use fleetlink_ros1::http::{Reader, write_response};
use fleetlink_ros1::tcpros::{Header, frame, read_header, read_message, write_header};
use fleetlink_ros1::xmlrpc::{Value, decode_call, encode_response};
use fleetlink_ros1::{NameFilter, Ros1Options};
use tokio::io::AsyncWriteExt;
use tokio::net::{TcpListener, TcpStream};
use tokio_util::sync::CancellationToken;

const TWIST_MD5: &str = "9f195f881246fdfa2798d1d3eebca84a";
const CUSTOM_DEF: &str = "string label\nint32 count\n";

/// What the fake master knows: the graph's registrations, by topic/service.
#[derive(Default)]
struct Graph {
    pid: i32,
    /// topic → (node, api, type)
    publishers: HashMap<String, Vec<(String, String, String)>>,
    subscribers: HashMap<String, Vec<(String, String)>>,
    /// how many registerPublisher calls each topic saw
    registrations: HashMap<String, usize>,
    /// service → (node, rosrpc uri)
    services: HashMap<String, (String, String)>,
}

type Shared = Arc<Mutex<Graph>>;

/// Answers one XML-RPC call (method, params).
type Handler = Arc<dyn Fn(&str, &[Value]) -> Value + Send + Sync>;

fn ok(v: Value) -> Value {
    Value::Array(vec![Value::Int(1), "".into(), v])
}

fn master_call(g: &Shared, method: &str, p: &[Value]) -> Value {
    let s = |i: usize| p.get(i).and_then(|v| v.as_str()).unwrap_or("").to_owned();
    let mut g = g.lock().unwrap();
    match method {
        "getPid" => ok(Value::Int(g.pid)),
        "registerPublisher" => {
            let (node, topic, ty, api) = (s(0), s(1), s(2), s(3));
            *g.registrations.entry(topic.clone()).or_default() += 1;
            let list = g.publishers.entry(topic.clone()).or_default();
            list.retain(|(n, _, _)| *n != node);
            list.push((node, api, ty));
            let subs = g.subscribers.get(&topic).cloned().unwrap_or_default();
            ok(Value::Array(
                subs.into_iter().map(|(_, a)| a.into()).collect(),
            ))
        }
        "registerSubscriber" => {
            let (node, topic, api) = (s(0), s(1), s(3));
            g.subscribers
                .entry(topic.clone())
                .or_default()
                .push((node, api));
            let pubs = g.publishers.get(&topic).cloned().unwrap_or_default();
            ok(Value::Array(
                pubs.into_iter().map(|(_, a, _)| a.into()).collect(),
            ))
        }
        "registerService" => {
            let (node, service, uri) = (s(0), s(1), s(2));
            g.services.insert(service, (node, uri));
            ok(Value::Int(1))
        }
        "lookupService" => match g.services.get(&s(1)) {
            Some((_, uri)) => ok(uri.as_str().into()),
            None => Value::Array(vec![Value::Int(-1), "no provider".into(), "".into()]),
        },
        "getSystemState" => {
            let pubs = g
                .publishers
                .iter()
                .map(|(t, l)| {
                    Value::Array(vec![
                        t.as_str().into(),
                        Value::Array(l.iter().map(|(n, _, _)| n.as_str().into()).collect()),
                    ])
                })
                .collect();
            let services = g
                .services
                .iter()
                .map(|(name, (node, _))| {
                    Value::Array(vec![
                        name.as_str().into(),
                        Value::Array(vec![node.as_str().into()]),
                    ])
                })
                .collect();
            ok(Value::Array(vec![
                Value::Array(pubs),
                Value::Array(vec![]),
                Value::Array(services),
            ]))
        }
        "getTopicTypes" => ok(Value::Array(
            g.publishers
                .iter()
                .filter_map(|(t, l)| l.first().map(|(_, _, ty)| (t, ty)))
                .map(|(t, ty)| Value::Array(vec![t.as_str().into(), ty.as_str().into()]))
                .collect(),
        )),
        _ => ok(Value::Int(0)),
    }
}

/// An XML-RPC server answering with `handle` (the master, or a node's slave API).
async fn xmlrpc_server(handle: Handler) -> String {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let uri = format!("http://{}/", listener.local_addr().unwrap());
    tokio::spawn(async move {
        loop {
            let (stream, _) = listener.accept().await.unwrap();
            let handle = handle.clone();
            tokio::spawn(async move {
                let mut r = Reader::new(stream);
                while let Ok(Some(head)) = r.head().await {
                    let body = r.body(head.content_length.unwrap_or(0)).await.unwrap();
                    let call = decode_call(std::str::from_utf8(&body).unwrap()).unwrap();
                    let reply = encode_response(&handle(&call.method, &call.params));
                    if write_response(r.get_mut(), &reply, head.close)
                        .await
                        .is_err()
                        || head.close
                    {
                        return;
                    }
                }
            });
        }
    });
    uri
}

/// A publisher node `/talker` of `/custom` (a type only it knows), latched, sending
/// `frames` to every subscriber that connects.
async fn talker(frames: Vec<Bytes>) -> String {
    let tcpros = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let port = tcpros.local_addr().unwrap().port();
    tokio::spawn(async move {
        loop {
            let (mut s, _) = tcpros.accept().await.unwrap();
            let frames = frames.clone();
            tokio::spawn(async move {
                let h = read_header(&mut s).await.unwrap();
                assert_eq!(h.text("md5sum"), "*", "the bridge accepts any type");
                let reply = Header::new()
                    .with("callerid", "/talker")
                    .with("topic", "/custom")
                    .with("type", "fltest/Custom")
                    .with("md5sum", "0123456789abcdef0123456789abcdef")
                    .with("message_definition", CUSTOM_DEF)
                    .with("latching", "1");
                write_header(&mut s, &reply).await.unwrap();
                for f in frames {
                    s.write_all(&frame(&f)).await.unwrap();
                }
                // Stay connected, like a publisher with nothing more to say.
                tokio::time::sleep(Duration::from_secs(3600)).await;
            });
        }
    });
    xmlrpc_server(Arc::new(move |method, _| match method {
        "requestTopic" => ok(Value::Array(vec![
            "TCPROS".into(),
            "127.0.0.1".into(),
            Value::Int(i32::from(port)),
        ])),
        _ => ok(Value::Int(0)),
    }))
    .await
}

async fn eventually<T>(what: &str, mut f: impl FnMut() -> Option<T>) -> T {
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        if let Some(v) = f() {
            return v;
        }
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
}

fn options(master: &str) -> Ros1Options {
    Ros1Options {
        master_uri: master.trim_end_matches('/').to_owned(),
        node_name: "/fleetlink_test".into(),
        host: "127.0.0.1".into(),
        publish: NameFilter::new(&["/custom".into()], &[]).unwrap(),
        subscribe: vec![TopicName::parse("/cmd_vel").unwrap()],
        expose: NameFilter::default(),
        offer: NameFilter::default(),
        discovery_period: Duration::from_millis(50),
        call_timeout: Duration::from_secs(2),
        parameters: true,
        changes: None,
    }
}

#[tokio::test]
async fn bridges_both_ways_and_registers_again_after_a_master_restart() {
    let graph: Shared = Arc::new(Mutex::new(Graph {
        pid: 100,
        ..Graph::default()
    }));
    let g = graph.clone();
    let master = xmlrpc_server(Arc::new(move |m, p| master_call(&g, m, p))).await;
    let sent = vec![
        Bytes::from_static(b"\x03\0\0\0one\x01\0\0\0"),
        Bytes::from_static(b"\x03\0\0\0two\x02\0\0\0"),
    ];
    let talker_api = talker(sent.clone()).await;
    graph.lock().unwrap().publishers.insert(
        "/custom".into(),
        vec![("/talker".into(), talker_api, "fltest/Custom".into())],
    );

    let router = Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())));
    let (watcher, outbox) = router.connect(ClientKind::Internal { role: "hub".into() }, None);
    let custom = TopicName::parse("/custom").unwrap();
    router
        .subscribe(
            watcher,
            Target::Exact(custom.clone()),
            SubOptions::default(),
        )
        .unwrap();
    let shutdown = CancellationToken::new();
    let bridge = tokio::spawn(fleetlink_ros1::run(
        options(&master),
        router.clone(),
        Arc::default(),
        None,
        shutdown.clone(),
    ));

    // Up: raw bytes as they were sent, with the publisher's definition and latch flag.
    let mut got = Vec::new();
    eventually("two /custom messages in the router", || {
        let batch = outbox.take(16, 1 << 20, Instant::now());
        got.extend(batch.items.into_iter().map(|(_, _, m)| m));
        (got.len() >= 2).then_some(())
    })
    .await;
    for (m, want) in got.iter().zip(&sent) {
        assert_eq!(m.payload.encoding, Encoding::Ros1);
        assert_eq!(&m.payload.bytes, want, "forwarded unchanged");
    }
    let meta = router.topic(&custom).unwrap().meta();
    assert_eq!(meta.schema.type_name, "fltest/Custom");
    assert_eq!(meta.schema.encoding, "ros1msg");
    assert_eq!(meta.schema.text, CUSTOM_DEF);
    assert!(meta.latched);
    // The learned definition lets the router convert it when a subscriber asks.
    let json = router
        .transcoder()
        .convert(&meta.schema, &got[0].payload, Encoding::Json)
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&json).unwrap();
    assert_eq!(v, serde_json::json!({"label": "one", "count": 1}));

    // Down: a hub message (JSON) on /cmd_vel becomes a ROS 1 publication.
    let (operator, _) = router.connect(ClientKind::Internal { role: "op".into() }, None);
    let cmd = router
        .advertise(
            operator,
            &TopicName::parse("/cmd_vel").unwrap(),
            Schema::named("geometry_msgs/Twist"),
            false,
        )
        .unwrap();
    let agent_api = eventually("the bridge registers /cmd_vel", || {
        cmd.publish(
            operator,
            1,
            0,
            Payload::json(Bytes::from_static(
                br#"{"linear":{"x":1.5},"angular":{"z":-0.5}}"#,
            )),
        );
        let g = graph.lock().unwrap();
        g.publishers
            .get("/cmd_vel")
            .and_then(|l| l.first().cloned())
            .map(|(n, api, ty)| {
                assert_eq!(
                    (n.as_str(), ty.as_str()),
                    ("/fleetlink_test", "geometry_msgs/Twist")
                );
                api
            })
    })
    .await;
    let answer = fleetlink_ros1::master::call(
        &agent_api,
        "requestTopic",
        &[
            "/listener".into(),
            "/cmd_vel".into(),
            Value::Array(vec![Value::Array(vec!["TCPROS".into()])]),
        ],
    )
    .await
    .unwrap();
    let ep = answer.as_array().unwrap();
    let addr = format!("{}:{}", ep[1].as_str().unwrap(), ep[2].as_i32().unwrap());

    // A subscriber with the wrong md5sum is refused with both types named.
    let mut wrong = TcpStream::connect(&addr).await.unwrap();
    let hello = |md5: &str| {
        Header::new()
            .with("callerid", "/listener")
            .with("topic", "/cmd_vel")
            .with("md5sum", md5)
            .with("type", "geometry_msgs/Twist")
    };
    write_header(&mut wrong, &hello("ffffffffffffffffffffffffffffffff"))
        .await
        .unwrap();
    let refused = read_header(&mut wrong).await.unwrap();
    assert!(
        refused.text("error").contains("type mismatch on /cmd_vel"),
        "{refused:?}"
    );

    let mut sub = TcpStream::connect(&addr).await.unwrap();
    write_header(&mut sub, &hello(TWIST_MD5)).await.unwrap();
    let reply = read_header(&mut sub).await.unwrap();
    assert_eq!(reply.text("md5sum"), TWIST_MD5);
    assert_eq!(reply.text("type"), "geometry_msgs/Twist");
    assert!(
        reply
            .text("message_definition")
            .contains("MSG: geometry_msgs/Vector3")
    );
    let body = tokio::time::timeout(Duration::from_secs(10), async {
        loop {
            cmd.publish(
                operator,
                2,
                0,
                Payload::json(Bytes::from_static(
                    br#"{"linear":{"x":1.5},"angular":{"z":-0.5}}"#,
                )),
            );
            if let Ok(Ok(b)) =
                tokio::time::timeout(Duration::from_millis(100), read_message(&mut sub)).await
            {
                return b;
            }
        }
    })
    .await
    .expect("a /cmd_vel message");
    assert_eq!(body.len(), 48, "six float64");
    assert_eq!(f64::from_le_bytes(body[..8].try_into().unwrap()), 1.5);
    assert_eq!(f64::from_le_bytes(body[40..48].try_into().unwrap()), -0.5);

    // The master restarts (new pid, empty tables): the bridge registers again.
    {
        let mut g = graph.lock().unwrap();
        g.pid = 200;
        g.publishers.remove("/cmd_vel");
    }
    eventually("/cmd_vel registered with the restarted master", || {
        let g = graph.lock().unwrap();
        g.publishers.contains_key("/cmd_vel").then_some(())
    })
    .await;
    assert!(graph.lock().unwrap().registrations["/cmd_vel"] >= 2);

    shutdown.cancel();
    tokio::time::timeout(Duration::from_secs(10), bridge)
        .await
        .expect("the bridge stops")
        .unwrap()
        .unwrap();
}

const ADD_MD5: &str = "6a2e34150c00229791cc89ff309fff21";

/// A local service provider `/adder` of `/add_two_ints` (example_interfaces/AddTwoInts),
/// answering probes as rospy does; returns its `rosrpc://` URI.
async fn adder() -> String {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let uri = format!("rosrpc://{}", listener.local_addr().unwrap());
    tokio::spawn(async move {
        loop {
            let (mut s, _) = listener.accept().await.unwrap();
            tokio::spawn(async move {
                let h = read_header(&mut s).await.unwrap();
                let reply = Header::new()
                    .with("callerid", "/adder")
                    .with("type", "example_interfaces/AddTwoInts")
                    .with("md5sum", ADD_MD5)
                    .with("request_type", "example_interfaces/AddTwoIntsRequest")
                    .with("response_type", "example_interfaces/AddTwoIntsResponse");
                write_header(&mut s, &reply).await.unwrap();
                if h.flag("probe") {
                    return;
                }
                assert_eq!(
                    h.text("md5sum"),
                    ADD_MD5,
                    "the bridge calls with the probed md5sum"
                );
                let req = read_message(&mut s).await.unwrap();
                let a = i64::from_le_bytes(req[..8].try_into().unwrap());
                let b = i64::from_le_bytes(req[8..16].try_into().unwrap());
                fleetlink_ros1::tcpros::write_service_response(&mut s, Ok(&(a + b).to_le_bytes()))
                    .await
                    .unwrap();
            });
        }
    });
    uri
}

#[tokio::test]
async fn services_cross_both_ways() {
    use fleetlink_relay::calls::{CallEvent, CallOptions, CallStatus, ChannelPeer, PeerMsg};

    let graph: Shared = Arc::new(Mutex::new(Graph {
        pid: 7,
        ..Graph::default()
    }));
    let g = graph.clone();
    let master = xmlrpc_server(Arc::new(move |m, p| master_call(&g, m, p))).await;
    let adder_uri = adder().await;
    graph
        .lock()
        .unwrap()
        .services
        .insert("/add_two_ints".into(), ("/adder".into(), adder_uri));

    let router = Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())));
    // The fleet: a client that calls robot services and provides /cloud/greet.
    let (fleet, _) = router.connect(
        ClientKind::Internal {
            role: "fleet".into(),
        },
        None,
    );
    let (peer, fleet_rx) = ChannelPeer::new();
    router.calls.attach(fleet, peer);
    router.calls.advertise(
        fleet,
        TopicName::parse("/cloud/greet").unwrap(),
        Schema::named("std_srvs/srv/Trigger"),
        false,
    );
    let opts = Ros1Options {
        publish: NameFilter::default(),
        subscribe: Vec::new(),
        expose: NameFilter::new(&["/add_two_ints".into()], &[]).unwrap(),
        offer: NameFilter::new(&["/cloud/.*".into()], &[]).unwrap(),
        ..options(&master)
    };
    let shutdown = CancellationToken::new();
    let bridge = tokio::spawn(fleetlink_ros1::run(
        opts,
        router.clone(),
        Arc::default(),
        None,
        shutdown.clone(),
    ));

    // Fleet → local service: a JSON request, a ROS 1 answer from the local provider.
    let add = TopicName::parse("/add_two_ints").unwrap();
    eventually("/add_two_ints exposed in the call table", || {
        router.calls.service(&add).map(|_| ())
    })
    .await;
    let id = router
        .calls
        .call(
            fleet,
            &add,
            Payload::json(Bytes::from_static(br#"{"a": 2, "b": 40}"#)),
            CallOptions::default(),
        )
        .unwrap();
    let done = tokio::time::timeout(Duration::from_secs(10), fleet_rx.recv())
        .await
        .expect("an answer")
        .expect("open");
    match done {
        PeerMsg::Event(CallEvent::Done {
            id: got,
            status: CallStatus::Ok,
            payload: Some(p),
            ..
        }) => {
            assert_eq!(got, id);
            assert_eq!(p.encoding, Encoding::Ros1);
            assert_eq!(&p.bytes[..], &42i64.to_le_bytes());
        }
        other => panic!("{other:?}"),
    }

    // Local caller → fleet service: registered with the master, answered by the fleet.
    let uri = eventually("/cloud/greet registered with the master", || {
        graph
            .lock()
            .unwrap()
            .services
            .get("/cloud/greet")
            .map(|(_, u)| u.clone())
    })
    .await;
    let addr = uri.trim_start_matches("rosrpc://").to_owned();
    let caller = tokio::spawn(async move {
        let mut s = TcpStream::connect(&addr).await.unwrap();
        let hello = Header::new()
            .with("callerid", "/rosservice")
            .with("service", "/cloud/greet")
            .with("md5sum", "*");
        write_header(&mut s, &hello).await.unwrap();
        let h = read_header(&mut s).await.unwrap();
        assert_eq!(h.text("type"), "std_srvs/Trigger");
        s.write_all(&frame(b"")).await.unwrap();
        fleetlink_ros1::tcpros::read_service_response(&mut s)
            .await
            .unwrap()
    });
    let call = loop {
        match tokio::time::timeout(Duration::from_secs(10), fleet_rx.recv())
            .await
            .expect("a call")
            .expect("open")
        {
            PeerMsg::Call(c) => break c,
            _ => continue,
        }
    };
    assert_eq!(call.service.name.as_str(), "/cloud/greet");
    router.calls.respond(
        fleet,
        call.id,
        CallStatus::Ok,
        Some(Payload::json(Bytes::from_static(
            br#"{"success": true, "message": "hi"}"#,
        ))),
        String::new(),
    );
    let answer = tokio::time::timeout(Duration::from_secs(10), caller)
        .await
        .expect("the caller gets its answer")
        .unwrap()
        .expect("ok");
    assert_eq!(&answer[..], b"\x01\x02\0\0\0hi", "bool true, string \"hi\"");

    shutdown.cancel();
    tokio::time::timeout(Duration::from_secs(10), bridge)
        .await
        .expect("the bridge stops")
        .unwrap()
        .unwrap();
}
