//! The outbound half of a link driven by hand, without a socket or a clock to wait on:
//! what each round produces, in what order.

use std::sync::Arc;
use std::time::Instant;

use bytes::Bytes;
use fleetlink_proto::frame::{self, Frame};
use fleetlink_proto::{Payload, Schema};

use super::{Outbound, Transmit};
use crate::link::Control;
use crate::router::{SubOptions, Target, Topic};
use crate::{ClientId, ClientKind, Router, TopicName};

/// A hub-style link (a plain outbox) subscribed to everything on `router`, its outbound
/// half, and a publisher.
fn link(router: &Router) -> (Outbound, ClientId) {
    let (link, outbox) = router.connect(
        ClientKind::Internal {
            role: "link".into(),
        },
        None,
    );
    router
        .subscribe(
            link,
            Target::Pattern(Router::compile_pattern(".*").unwrap()),
            SubOptions::default(),
        )
        .unwrap();
    let (publisher, _) = router.connect(ClientKind::Internal { role: "pub".into() }, None);
    let namer: super::LinkNamer = Arc::new(|m| Some(m.name.to_string()));
    (
        Outbound::new(outbox, namer, Vec::new(), None, None),
        publisher,
    )
}

fn topic(router: &Router, publisher: ClientId, name: &str) -> Arc<Topic> {
    router
        .advertise(
            publisher,
            &TopicName::parse(name).unwrap(),
            Schema::named("t/T"),
            false,
        )
        .unwrap()
}

/// Everything ready to write, as frames (a pong or close as a marker frame of its own).
#[derive(Debug, PartialEq)]
enum Out {
    Frame(Frame),
    Pong(Bytes),
    Close,
}

fn drain(ob: &mut Outbound) -> Vec<Out> {
    let mut v = Vec::new();
    while let Some(t) = ob.poll_transmit() {
        match t {
            Transmit::Binary(b) => {
                for f in frame::frames(&b) {
                    v.push(Out::Frame(f.expect("valid frame")));
                }
            }
            Transmit::Pong(p) => v.push(Out::Pong(p)),
            Transmit::Close(_) => v.push(Out::Close),
        }
    }
    v
}

fn kinds(out: &[Out]) -> Vec<String> {
    out.iter()
        .map(|o| match o {
            Out::Frame(Frame::Advertise { topic, .. }) => format!("ADVERTISE {topic}"),
            Out::Frame(Frame::Unadvertise { .. }) => "UNADVERTISE".into(),
            Out::Frame(Frame::Message { seq, .. }) => format!("MESSAGE {seq}"),
            Out::Frame(Frame::Chunk { offset, .. }) => format!("CHUNK {offset}"),
            Out::Frame(Frame::Ping { id, .. }) => format!("PING {id}"),
            Out::Frame(f) => format!("{f:?}"),
            Out::Pong(_) => "PONG".into(),
            Out::Close => "CLOSE".into(),
        })
        .collect()
}

#[test]
fn a_message_goes_out_after_its_topic_is_announced() {
    let router = Router::default();
    let (mut ob, publisher) = link(&router);
    let pose = topic(&router, publisher, "/pose");
    pose.publish(publisher, 1, 0, Payload::json(Bytes::from_static(b"{}")));
    let r = ob.round();
    assert!(r.again, "it took a message: look again at once");
    assert_eq!(kinds(&drain(&mut ob)), ["ADVERTISE /pose", "MESSAGE 1"]);
    let r = ob.round();
    assert!(!r.again);
    assert_eq!(
        r.wake, None,
        "a plain outbox waits for data, not a deadline"
    );
    assert!(drain(&mut ob).is_empty());
}

#[test]
fn a_small_message_overtakes_a_large_one_a_chunk_per_round() {
    let router = Router::default();
    let (mut ob, publisher) = link(&router);
    let cloud = topic(&router, publisher, "/cloud");
    let pose = topic(&router, publisher, "/pose");
    let chunks = 4;
    let big = Bytes::from(vec![7u8; chunks * frame::DEFAULT_CHUNK_SIZE]);
    cloud.publish(publisher, 1, 0, Payload::json(big));
    assert!(ob.round().again);
    assert_eq!(
        kinds(&drain(&mut ob)),
        ["ADVERTISE /cloud"],
        "a lane, no chunk yet"
    );
    assert!(ob.round().again, "a lane with chunks to go");
    assert_eq!(kinds(&drain(&mut ob)), ["CHUNK 0"]);
    pose.publish(publisher, 1, 0, Payload::json(Bytes::from_static(b"{}")));
    ob.round();
    assert_eq!(
        kinds(&drain(&mut ob)),
        ["CHUNK 16384", "ADVERTISE /pose", "MESSAGE 1"],
        "the small message goes out between chunks"
    );
    let mut rest = Vec::new();
    while ob.round().again {
        rest.extend(kinds(&drain(&mut ob)));
    }
    rest.extend(kinds(&drain(&mut ob)));
    assert_eq!(rest, ["CHUNK 32768", "CHUNK 49152"]);
}

#[test]
fn control_frames_go_first_a_pong_keeps_its_place_and_a_close_is_last() {
    let router = Router::default();
    let (mut ob, publisher) = link(&router);
    let pose = topic(&router, publisher, "/pose");
    pose.publish(publisher, 1, 0, Payload::json(Bytes::from_static(b"{}")));
    ob.on_control(Some(Control::Frame(Frame::Ping { id: 5, sent_ns: 0 })));
    ob.on_control(Some(Control::Pong(Bytes::from_static(b"p"))));
    ob.round();
    let out = drain(&mut ob);
    assert_eq!(
        kinds(&out),
        ["PING 5", "PONG", "ADVERTISE /pose", "MESSAGE 1"]
    );
    assert_eq!(out[1], Out::Pong(Bytes::from_static(b"p")));

    pose.publish(publisher, 2, 0, Payload::json(Bytes::from_static(b"{}")));
    ob.on_control(Some(Control::Frame(Frame::Ping { id: 6, sent_ns: 0 })));
    ob.on_control(Some(Control::Close(None)));
    assert!(ob.is_closing());
    let r = ob.round();
    assert!(!r.again);
    assert_eq!(
        kinds(&drain(&mut ob)),
        ["PING 6", "CLOSE"],
        "what was queued before the close goes, no message after it"
    );
    ob.on_control(Some(Control::Frame(Frame::Ping { id: 7, sent_ns: 0 })));
    ob.round();
    assert!(drain(&mut ob).is_empty(), "nothing after a close");
}

#[test]
fn a_topic_is_unadvertised_after_its_last_message_and_kept_if_published_again() {
    let router = Router::default();
    let (mut ob, publisher) = link(&router);
    let pose = topic(&router, publisher, "/pose");
    let odom = topic(&router, publisher, "/odom");
    pose.publish(publisher, 1, 0, Payload::json(Bytes::from_static(b"{}")));
    odom.publish(publisher, 1, 0, Payload::json(Bytes::from_static(b"{}")));
    let since = Instant::now();
    for t in [&pose, &odom] {
        ob.on_control(Some(Control::Unadvertise {
            topic: t.id(),
            since,
        }));
    }
    // /odom published again after its publisher was seen gone: it stays.
    odom.publish(publisher, 2, 0, Payload::json(Bytes::from_static(b"{}")));
    ob.round();
    let out = drain(&mut ob);
    assert_eq!(
        kinds(&out),
        [
            "ADVERTISE /pose",
            "MESSAGE 1",
            "ADVERTISE /odom",
            "MESSAGE 1",
            "MESSAGE 2",
            "UNADVERTISE"
        ]
    );
    let Some(Out::Frame(Frame::Unadvertise { alias })) = out.last() else {
        unreachable!()
    };
    assert_eq!(*alias, pose.id().0);
}
