//! The hub's black-box fetch against a stand-in robot on one router, on a paused clock:
//! pieces that stop coming are asked for again when the stall deadline comes (the fetch
//! sleeps until then, it does not tick), and the slice is kept whole.

use std::collections::BTreeMap;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_record::blackbox::fetch::{FetchSpec, STALL};
use fleetlink_record::blackbox::{
    DATA_TOPIC, FETCH_SERVICE, FETCH_TYPE, FetchReply, FetchRequest, PIECE_BYTES, PIECE_TYPE, Piece,
};
use fleetlink_record::{Recordings, State};
use fleetlink_relay::calls::{CallId, CallStatus, ChannelPeer, PeerMsg, PeerReceiver};
use fleetlink_relay::gate::AllowAll;
use fleetlink_relay::router::{ClientKind, Topic};
use fleetlink_relay::transcode::RegistryTranscoder;
use fleetlink_relay::{ClientId, Router, TopicName};
use tokio::time::Instant;

/// A small MCAP file of three 40 kB messages: four pieces.
fn slice_bytes() -> Vec<u8> {
    let mut out = std::io::Cursor::new(Vec::new());
    let mut w = mcap::WriteOptions::new()
        .compression(None)
        .create(&mut out)
        .unwrap();
    let schema = w
        .add_schema("std_msgs/msg/String", "ros2msg", b"string data")
        .unwrap();
    let channel = w
        .add_channel(schema, "/scan", "cdr", &BTreeMap::new())
        .unwrap();
    for i in 0..3u32 {
        let header = mcap::records::MessageHeader {
            channel_id: channel,
            sequence: i,
            log_time: 1_000 + u64::from(i),
            publish_time: 1_000 + u64::from(i),
        };
        let data: Vec<u8> = (0..40_000u32).map(|b| (b * 7 + i) as u8).collect();
        w.write_to_known_channel(&header, &data).unwrap();
    }
    w.finish().unwrap();
    drop(w);
    out.into_inner()
}

/// The robot's side of the fetch, driven by the test: it offers the fetch service and
/// publishes the pieces it is told to.
struct Robot {
    client: ClientId,
    data: Arc<Topic>,
    calls: PeerReceiver,
    router: Arc<Router>,
    seq: u64,
}

impl Robot {
    fn start(router: &Arc<Router>, name: &str) -> Robot {
        let (client, _) = router.connect(
            ClientKind::Internal {
                role: "robot".into(),
            },
            None,
        );
        let topic = TopicName::parse(&format!("/{name}{DATA_TOPIC}")).unwrap();
        let data = router
            .advertise(client, &topic, Schema::named(PIECE_TYPE), false)
            .unwrap();
        let (peer, calls) = ChannelPeer::new();
        router.calls.attach(client, peer);
        let service = TopicName::parse(&format!("/{name}{FETCH_SERVICE}")).unwrap();
        router
            .calls
            .advertise(client, service, Schema::named(FETCH_TYPE), false);
        Robot {
            client,
            data,
            calls,
            router: router.clone(),
            seq: 0,
        }
    }

    /// The next fetch call.
    async fn next_call(&mut self) -> (CallId, FetchRequest) {
        loop {
            match self.calls.recv().await.expect("the router lives") {
                PeerMsg::Call(req) => {
                    let body = serde_json::from_slice(&req.payload.bytes).unwrap();
                    return (req.id, body);
                }
                _ => continue,
            }
        }
    }

    /// Publishes the pieces of `slice` that start in `from..to`.
    fn send(&mut self, id: &str, slice: &[u8], from: usize, to: usize) {
        for offset in (from..to.min(slice.len())).step_by(PIECE_BYTES) {
            let end = (offset + PIECE_BYTES).min(slice.len());
            let p = Piece {
                slice: id,
                offset: offset as u64,
                size: slice.len() as u64,
                data: &slice[offset..end],
            };
            self.seq += 1;
            self.data.publish(
                self.client,
                self.seq,
                0,
                Payload::new(Encoding::Cdr, p.encode()),
            );
        }
    }

    fn answer(&self, call: CallId, reply: &FetchReply) {
        let body = serde_json::to_vec(reply).unwrap();
        self.router.calls.respond(
            self.client,
            call,
            CallStatus::Ok,
            Some(Payload::json(body)),
            String::new(),
        );
    }
}

/// The recording once its fetch has ended, looked at every (paused-clock) 100 ms.
async fn ended(recs: &Recordings, id: &str) -> fleetlink_record::RecordingInfo {
    tokio::time::timeout(Duration::from_secs(60), async {
        loop {
            let info = recs.get(id).unwrap();
            if info.state != State::Fetching {
                return info;
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
    })
    .await
    .expect("the fetch ends")
}

#[tokio::test(start_paused = true)]
async fn pieces_that_stop_are_asked_for_again_at_the_stall_deadline() {
    let dir = tempfile::tempdir().unwrap();
    let router = Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())));
    let recs = Recordings::open(dir.path(), router.clone(), "hub").unwrap();
    let mut robot = Robot::start(&router, "robot1");
    let slice = slice_bytes();
    assert!(slice.len() > 3 * PIECE_BYTES, "{} bytes", slice.len());
    let (size, sha256) = {
        let path = dir.path().join("robot-slice.mcap");
        std::fs::write(&path, &slice).unwrap();
        fleetlink_record::blackbox::slice::digest(&path).unwrap()
    };
    let reply = FetchReply {
        size,
        sha256,
        messages: 3,
        ..FetchReply::default()
    };
    let spec = FetchSpec {
        robot: "robot1".into(),
        last_s: Some(60.0),
        from_ns: None,
        to_ns: None,
        topics: Vec::new(),
        name: None,
    };
    let info = recs
        .fetch(spec, "test".into(), Box::new(AllowAll), Box::new(|_| true))
        .unwrap();

    // The first call asks from the start; only its first piece arrives.
    let (call, first) = robot.next_call().await;
    assert_eq!((first.slice.as_str(), first.offset), (info.id.as_str(), 0));
    robot.send(&info.id, &slice, 0, PIECE_BYTES);
    robot.answer(call, &reply);
    let lost_at = Instant::now();

    // Asked again from where the hub's file ends, when the stall deadline comes.
    let (call, again) = robot.next_call().await;
    let waited = lost_at.elapsed();
    assert_eq!(again.offset, PIECE_BYTES as u64);
    assert!(
        waited >= STALL && waited < STALL + Duration::from_secs(1),
        "asked again after {waited:?}"
    );
    robot.send(&info.id, &slice, PIECE_BYTES, slice.len());
    robot.answer(call, &reply);

    let done = ended(&recs, &info.id).await;
    assert_eq!(done.state, State::Stopped, "{:?}", done.error);
    let bb = done.blackbox.expect("a black-box fetch");
    assert_eq!((bb.received, bb.calls, bb.resumed), (size, 2, 1));
    let kept = recs.file(&info.id, &done.files[0].name).unwrap();
    assert_eq!(std::fs::read(kept).unwrap(), slice);
}
