//! Shared test helpers: proptest strategies for frames and JSON values, and small byte
//! builders for hand-made (usually hostile) inputs.

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{CallStatus, Frame, FrameKind, Level};
use fleetlink_proto::wire::{put_bytes, put_str, put_varint};
use fleetlink_proto::{Encoding, Schema};
use proptest::prelude::*;
use serde_json::Value;

pub fn hello() -> impl Strategy<Value = Frame> {
    (
        any::<u32>(),
        any::<String>(),
        any::<String>(),
        any::<u32>(),
        any::<u64>(),
        any::<String>(),
    )
        .prop_map(
            |(version, robot, token, heartbeat_ms, outbox_epoch, mirror)| Frame::Hello {
                version,
                robot,
                token,
                heartbeat_ms,
                outbox_epoch,
                mirror,
            },
        )
}

pub fn welcome() -> impl Strategy<Value = Frame> {
    (
        any::<String>(),
        any::<String>(),
        any::<u64>(),
        any::<u32>(),
        any::<u64>(),
    )
        .prop_map(
            |(session, namespace, hub_time_ns, heartbeat_ms, features)| Frame::Welcome {
                session,
                namespace,
                hub_time_ns,
                heartbeat_ms,
                features,
            },
        )
}

pub fn pull() -> impl Strategy<Value = Frame> {
    any::<u32>().prop_map(|alias| Frame::Pull { alias })
}

pub fn budget() -> impl Strategy<Value = Frame> {
    (
        any::<u64>(),
        any::<u64>(),
        any::<u64>(),
        prop::collection::vec(any::<u32>(), 0..20),
    )
        .prop_map(|(max_bps, day_bytes, used_bytes, thinned)| Frame::Budget {
            max_bps,
            day_bytes,
            used_bytes,
            thinned,
        })
}

pub fn topic_drops() -> impl Strategy<Value = Frame> {
    prop::collection::vec(
        (
            any::<u32>(),
            prop::collection::vec((any::<u8>(), any::<u64>()), 0..6),
        ),
        0..10,
    )
    .prop_map(|topics| Frame::TopicDrops { topics })
}

pub fn topic_load() -> impl Strategy<Value = Frame> {
    prop::collection::vec(
        (
            any::<u32>(),
            any::<u64>(),
            any::<u64>(),
            any::<u32>(),
            any::<u32>(),
            any::<u8>(),
        ),
        0..10,
    )
    .prop_map(|topics| Frame::TopicLoad {
        topics: topics
            .into_iter()
            .map(
                |(alias, rate_mhz, bytes_per_sec, priority_milli, queue, flags)| {
                    fleetlink_proto::frame::TopicLoadEntry {
                        alias,
                        rate_mhz,
                        bytes_per_sec,
                        priority_milli,
                        queue,
                        flags,
                    }
                },
            )
            .collect(),
    })
}

pub fn interest() -> impl Strategy<Value = Frame> {
    (any::<u32>(), any::<bool>()).prop_map(|(alias, wanted)| Frame::Interest { alias, wanted })
}

pub fn encoding() -> impl Strategy<Value = Encoding> {
    prop::sample::select(Encoding::ALL.to_vec())
}

pub fn advertise() -> impl Strategy<Value = Frame> {
    (
        any::<u32>(),
        any::<String>(),
        any::<String>(),
        any::<String>(),
        any::<String>(),
        encoding(),
        any::<u8>(),
    )
        .prop_map(
            |(alias, topic, type_name, schema_encoding, text, encoding, flags)| Frame::Advertise {
                alias,
                topic,
                schema: Schema {
                    type_name,
                    encoding: schema_encoding,
                    text,
                },
                encoding,
                flags,
            },
        )
}

pub fn unadvertise() -> impl Strategy<Value = Frame> {
    any::<u32>().prop_map(|alias| Frame::Unadvertise { alias })
}

pub fn subscribe() -> impl Strategy<Value = Frame> {
    (
        any::<u32>(),
        any::<String>(),
        any::<u8>(),
        any::<u32>(),
        any::<u32>(),
    )
        .prop_map(
            |(id, pattern, flags, throttle_ms, queue_length)| Frame::Subscribe {
                id,
                pattern,
                flags,
                throttle_ms,
                queue_length,
            },
        )
}

pub fn unsubscribe() -> impl Strategy<Value = Frame> {
    any::<u32>().prop_map(|id| Frame::Unsubscribe { id })
}

pub fn payload(max: usize) -> impl Strategy<Value = Bytes> {
    prop::collection::vec(any::<u8>(), 0..max).prop_map(Bytes::from)
}

pub fn message() -> impl Strategy<Value = Frame> {
    (any::<u32>(), any::<u64>(), any::<u64>(), payload(300)).prop_map(
        |(alias, seq, stamp_ns, payload)| Frame::Message {
            alias,
            seq,
            stamp_ns,
            payload,
        },
    )
}

/// A `ZMESSAGE` (the frame layer does not look inside the envelope).
pub fn zmessage() -> impl Strategy<Value = Frame> {
    message().prop_map(|f| match f {
        Frame::Message {
            alias,
            seq,
            stamp_ns,
            payload,
        } => Frame::ZMessage {
            alias,
            seq,
            stamp_ns,
            payload,
        },
        other => other,
    })
}

/// A `ZCHUNK`, consistent as [`chunk`] is.
pub fn zchunk() -> impl Strategy<Value = Frame> {
    chunk().prop_map(|f| match f {
        Frame::Chunk {
            alias,
            seq,
            stamp_ns,
            total_len,
            offset,
            data,
        } => Frame::ZChunk {
            alias,
            seq,
            stamp_ns,
            total_len,
            offset,
            data,
        },
        other => other,
    })
}

/// A `CHUNK` whose fields are consistent: `offset + data.len() <= total_len`.
pub fn chunk() -> impl Strategy<Value = Frame> {
    (
        any::<u32>(),
        any::<u64>(),
        any::<u64>(),
        payload(300),
        0..u64::MAX / 2,
        0..u64::MAX / 2,
    )
        .prop_map(|(alias, seq, stamp_ns, data, offset, spare)| Frame::Chunk {
            alias,
            seq,
            stamp_ns,
            total_len: offset + data.len() as u64 + spare,
            offset,
            data,
        })
}

pub fn ping() -> impl Strategy<Value = Frame> {
    (any::<u64>(), any::<u64>()).prop_map(|(id, sent_ns)| Frame::Ping { id, sent_ns })
}

pub fn pong() -> impl Strategy<Value = Frame> {
    (any::<u64>(), any::<u64>(), any::<u64>()).prop_map(|(id, echo_ns, responder_ns)| Frame::Pong {
        id,
        echo_ns,
        responder_ns,
    })
}

pub fn ack() -> impl Strategy<Value = Frame> {
    (any::<u32>(), any::<u64>()).prop_map(|(frames, bytes)| Frame::Ack { frames, bytes })
}

pub fn status() -> impl Strategy<Value = Frame> {
    (
        prop::sample::select(vec![Level::Info, Level::Warning, Level::Error]),
        any::<u32>(),
        any::<u32>(),
        any::<String>(),
    )
        .prop_map(|(level, code, alias, text)| Frame::Status {
            level,
            code,
            alias,
            text,
        })
}

pub fn share() -> impl Strategy<Value = Frame> {
    any::<u64>().prop_map(|bytes_per_sec| Frame::Share { bytes_per_sec })
}

pub fn link_report() -> impl Strategy<Value = Frame> {
    (
        any::<u64>(),
        any::<u64>(),
        any::<u64>(),
        any::<u64>(),
        any::<u64>(),
    )
        .prop_map(
            |(demand_bps, rate_bps, latency_ns, capacity_bps, measured_at_ms)| Frame::LinkReport {
                demand_bps,
                rate_bps,
                latency_ns,
                capacity_bps,
                measured_at_ms,
            },
        )
}

pub fn delivered() -> impl Strategy<Value = Frame> {
    (any::<u32>(), any::<u64>()).prop_map(|(alias, seq)| Frame::Delivered { alias, seq })
}

pub fn service_advertise() -> impl Strategy<Value = Frame> {
    (
        any::<u32>(),
        any::<String>(),
        any::<String>(),
        any::<String>(),
        any::<String>(),
        any::<u8>(),
    )
        .prop_map(|(alias, name, type_name, schema_encoding, text, flags)| {
            Frame::ServiceAdvertise {
                alias,
                name,
                schema: Schema {
                    type_name,
                    encoding: schema_encoding,
                    text,
                },
                flags,
            }
        })
}

pub fn service_unadvertise() -> impl Strategy<Value = Frame> {
    any::<u32>().prop_map(|alias| Frame::ServiceUnadvertise { alias })
}

pub fn call() -> impl Strategy<Value = Frame> {
    (
        any::<u64>(),
        any::<u32>(),
        any::<u64>(),
        encoding(),
        payload(300),
    )
        .prop_map(
            |(call_id, alias, deadline_ms, encoding, payload)| Frame::Call {
                call_id,
                alias,
                deadline_ms,
                encoding,
                payload,
            },
        )
}

pub fn goal() -> impl Strategy<Value = Frame> {
    (
        any::<u64>(),
        any::<u32>(),
        any::<u64>(),
        any::<[u8; 16]>(),
        encoding(),
        payload(300),
    )
        .prop_map(
            |(call_id, alias, deadline_ms, goal_id, encoding, payload)| Frame::Goal {
                call_id,
                alias,
                deadline_ms,
                goal_id,
                encoding,
                payload,
            },
        )
}

pub fn call_status() -> impl Strategy<Value = CallStatus> {
    (0u8..=7).prop_map(CallStatus::from_u8)
}

pub fn reply() -> impl Strategy<Value = Frame> {
    (any::<u64>(), call_status(), encoding(), payload(300)).prop_map(
        |(call_id, status, encoding, payload)| Frame::Reply {
            call_id,
            status,
            encoding,
            payload,
        },
    )
}

pub fn feedback() -> impl Strategy<Value = Frame> {
    (any::<u64>(), encoding(), payload(300)).prop_map(|(call_id, encoding, payload)| {
        Frame::Feedback {
            call_id,
            encoding,
            payload,
        }
    })
}

pub fn cancel() -> impl Strategy<Value = Frame> {
    any::<u64>().prop_map(|call_id| Frame::Cancel { call_id })
}

/// The kinds whose bodies may be cut into `CALL_CHUNK`s.
pub const CALL_BODY_KINDS: [FrameKind; 4] = [
    FrameKind::Call,
    FrameKind::Goal,
    FrameKind::Reply,
    FrameKind::Feedback,
];

/// A `CALL_CHUNK` whose fields are consistent: a body kind, and
/// `offset + data.len() <= total_len`.
pub fn call_chunk() -> impl Strategy<Value = Frame> {
    (
        any::<u64>(),
        prop::sample::select(CALL_BODY_KINDS.to_vec()),
        payload(300),
        0..u64::MAX / 2,
        0..u64::MAX / 2,
    )
        .prop_map(|(call_id, kind, data, offset, spare)| Frame::CallChunk {
            call_id,
            kind: kind as u8,
            total_len: offset + data.len() as u64 + spare,
            offset,
            data,
        })
}

/// A frame of a kind this decoder does not know: encoded with an empty body.
pub fn unknown() -> impl Strategy<Value = Frame> {
    prop_oneof![Just(0u8), 0x20u8..=0xff].prop_map(|kind| Frame::Unknown { kind })
}

pub fn via() -> impl Strategy<Value = Frame> {
    prop::collection::vec(any::<u64>(), 0..=fleetlink_proto::frame::MAX_VIA)
        .prop_map(|hubs| Frame::Via { hubs })
}

pub fn any_frame() -> impl Strategy<Value = Frame> {
    prop_oneof![
        hello(),
        welcome(),
        advertise(),
        unadvertise(),
        subscribe(),
        unsubscribe(),
        message(),
        chunk(),
        ping(),
        pong(),
        ack(),
        status(),
        share(),
        link_report(),
        delivered(),
        service_advertise(),
        service_unadvertise(),
        call(),
        goal(),
        reply(),
        feedback(),
        cancel(),
        call_chunk(),
        interest(),
        pull(),
        zmessage(),
        zchunk(),
        budget(),
        topic_drops(),
        topic_load(),
        via(),
        unknown(),
    ]
}

/// One hand-written frame of every known kind, for tests that walk every byte.
pub fn one_of_each_kind() -> Vec<Frame> {
    vec![
        Frame::Hello {
            version: 1,
            robot: "robot-7".into(),
            token: "secret".into(),
            heartbeat_ms: 1000,
            outbox_epoch: 0x0123_4567_89ab_cdef,
            mirror: "robot-6".into(),
        },
        Frame::Welcome {
            session: "s-1".into(),
            namespace: "/fleet/robot-7".into(),
            hub_time_ns: 1_700_000_000_000_000_000,
            heartbeat_ms: 1000,
            features: 1,
        },
        Frame::Interest {
            alias: 300,
            wanted: true,
        },
        Frame::Pull { alias: 300 },
        Frame::Advertise {
            alias: 300,
            topic: "/scan".into(),
            schema: Schema {
                type_name: "sensor_msgs/msg/LaserScan".into(),
                encoding: "ros2msg".into(),
                text: "float32 angle_min\nfloat32 angle_max\n".into(),
            },
            encoding: Encoding::Cdr,
            flags: 1,
        },
        Frame::Unadvertise { alias: 300 },
        Frame::Subscribe {
            id: 4,
            pattern: "/cam/.*".into(),
            flags: 1,
            throttle_ms: 100,
            queue_length: 10,
        },
        Frame::Unsubscribe { id: 4 },
        Frame::Message {
            alias: 300,
            seq: 70_000,
            stamp_ns: 5,
            // Long enough that body_len needs a two-byte varint.
            payload: Bytes::from(vec![0xab; 200]),
        },
        Frame::Chunk {
            alias: 2,
            seq: 9,
            stamp_ns: 5,
            total_len: 1000,
            offset: 500,
            data: Bytes::from(vec![7; 150]),
        },
        Frame::ZMessage {
            alias: 300,
            seq: 70_001,
            stamp_ns: 5,
            payload: Bytes::from(vec![0x02, 0x80, 0x01, 0xcd]),
        },
        Frame::ZChunk {
            alias: 2,
            seq: 10,
            stamp_ns: 5,
            total_len: 1000,
            offset: 0,
            data: Bytes::from(vec![0x01; 150]),
        },
        Frame::Budget {
            max_bps: 25_000,
            day_bytes: 500_000_000,
            used_bytes: 1 << 40,
            thinned: vec![3, 300],
        },
        Frame::TopicDrops {
            topics: vec![(300, vec![(1, 5), (4, 1 << 33)]), (2, vec![])],
        },
        Frame::TopicLoad {
            topics: vec![fleetlink_proto::frame::TopicLoadEntry {
                alias: 300,
                rate_mhz: 29_970,
                bytes_per_sec: 9_000_000,
                priority_milli: 2_500,
                queue: 16,
                flags: fleetlink_proto::frame::TOPIC_LOAD_NO_DROP,
            }],
        },
        Frame::Via {
            hubs: vec![0x0123_4567_89ab_cdef, 7],
        },
        Frame::Ping { id: 1, sent_ns: 2 },
        Frame::Pong {
            id: 1,
            echo_ns: 2,
            responder_ns: 3,
        },
        Frame::Ack {
            frames: 129,
            bytes: 300_000,
        },
        Frame::Status {
            level: Level::Warning,
            code: 403,
            alias: 300,
            text: "not allowed".into(),
        },
        Frame::Share {
            bytes_per_sec: 500_000,
        },
        Frame::LinkReport {
            demand_bps: 2_000_000,
            rate_bps: 480_000,
            latency_ns: 41_000_000,
            capacity_bps: 500_000,
            measured_at_ms: 1_796_000_000_000,
        },
        Frame::Delivered {
            alias: 300,
            seq: 1 << 40,
        },
        Frame::ServiceAdvertise {
            alias: 2,
            name: "/robot-7/set_mode".into(),
            schema: Schema {
                type_name: "fleet_msgs/srv/SetMode".into(),
                encoding: "ros2srv".into(),
                text: "string mode\n---\nbool ok\n".into(),
            },
            flags: fleetlink_proto::frame::SERVICE_ACTION,
        },
        Frame::ServiceUnadvertise { alias: 2 },
        Frame::Call {
            call_id: 1 << 35,
            alias: 2,
            deadline_ms: 5000,
            encoding: Encoding::Json,
            payload: Bytes::from_static(br#"{"mode":"dock"}"#),
        },
        Frame::Goal {
            call_id: 17,
            alias: 300,
            deadline_ms: 0,
            goal_id: *b"0123456789abcdef",
            encoding: Encoding::Cdr,
            payload: Bytes::from(vec![0, 1, 0, 0, 42, 0, 0, 0]),
        },
        Frame::Reply {
            call_id: 17,
            status: CallStatus::Aborted,
            encoding: Encoding::Json,
            payload: Bytes::from_static(b"link to robot-7 lost"),
        },
        Frame::Feedback {
            call_id: 17,
            encoding: Encoding::Cbor,
            payload: Bytes::from(vec![0xa0; 150]),
        },
        Frame::Cancel { call_id: 17 },
        Frame::CallChunk {
            call_id: 17,
            kind: FrameKind::Reply as u8,
            total_len: 40_000,
            offset: 16_384,
            data: Bytes::from(vec![9; 150]),
        },
    ]
}

/// A frame with a hand-made body: `kind | body_len | body`.
pub fn raw_frame(kind: u8, body: &[u8]) -> Bytes {
    let mut b = BytesMut::new();
    b.extend_from_slice(&[kind]);
    put_varint(&mut b, body.len() as u64);
    b.extend_from_slice(body);
    b.freeze()
}

/// Builds a body field by field.
#[derive(Default)]
pub struct Body(pub BytesMut);

impl Body {
    pub fn varint(mut self, v: u64) -> Self {
        put_varint(&mut self.0, v);
        self
    }
    pub fn str(mut self, s: &str) -> Self {
        put_str(&mut self.0, s);
        self
    }
    pub fn bytes(mut self, b: &[u8]) -> Self {
        put_bytes(&mut self.0, b);
        self
    }
    pub fn raw(mut self, b: &[u8]) -> Self {
        self.0.extend_from_slice(b);
        self
    }
    pub fn u64_le(self, v: u64) -> Self {
        self.raw(&v.to_le_bytes())
    }
}

/// Any JSON value, nested a few levels. Floats are finite (JSON has no NaN or infinity).
pub fn json_value() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        any::<i64>().prop_map(Value::from),
        any::<u64>().prop_map(Value::from),
        any::<f64>()
            .prop_filter("JSON numbers are finite", |f| f.is_finite())
            .prop_map(Value::from),
        any::<String>().prop_map(Value::String),
    ];
    leaf.prop_recursive(4, 64, 8, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..8).prop_map(Value::Array),
            prop::collection::btree_map(any::<String>(), inner, 0..8)
                .prop_map(|m| Value::Object(m.into_iter().collect())),
        ]
    })
}

/// JSON text to CBOR bytes, for building CBOR requests from readable JSON.
pub fn cbor_of(json: &str) -> Vec<u8> {
    fleetlink_proto::rosbridge::convert::json_to_cbor(json.as_bytes()).expect("test JSON is valid")
}

/// Runs `f` on a thread with a deliberately small stack (1 MiB, half of a tokio
/// worker's), so a recursion guard that only just holds still shows up: an overflow
/// aborts the whole test binary.
pub fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(1024 * 1024)
        .spawn(f)
        .expect("spawn test thread")
        .join()
        .expect("no panic or stack overflow on a small stack")
}
