//! The in-process fan-out path, without sockets: what the hub does between decoding a
//! publisher's frame and handing bytes to a subscriber's socket writer. Results are
//! recorded in `docs/benchmarks/log.md` ("Criterion: the fan-out path without sockets").
//!
//! - `fanout/S`: one `Topic::publish` of a 64-byte JSON message to S subscribers, then
//!   every subscriber's outbox drained with `Outbox::take`, as its link writer would.
//!   Throughput is per delivery, so the per-element time is the cost of one delivery.
//! - `link_frames/SIZE`: building a message's `fleetlink.v1` frames (one `MESSAGE`, or
//!   `CHUNK`s for 1 MiB), which happens once per message whatever the subscriber count.
//! - `rosbridge_frame/*`: a rosbridge `publish` frame built for one subscriber versus
//!   asked for by 100 subscribers of the same message: encode-once means the second costs
//!   one conversion plus 99 cache hits.

use std::hint::black_box;
use std::sync::Arc;
use std::time::Instant;

use bytes::Bytes;
use criterion::{BatchSize, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fleetlink_proto::{Payload, Schema};
use fleetlink_relay::message::{FrameKind, TopicMeta};
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::{
    ClientId, ClientKind, GenericTranscoder, Message, Outbox, Router, TopicId, TopicName,
};

/// A 64-byte rosbridge-JSON `geometry_msgs/Twist`-like object.
fn json_64() -> Bytes {
    let body = br#"{"linear":{"x":0.5,"y":0.0,"z":0.0},"angular":{"z":0.25},"k":12}"#;
    assert_eq!(body.len(), 64);
    Bytes::from_static(body)
}

fn internal(role: &str) -> ClientKind {
    ClientKind::Internal { role: role.into() }
}

fn fanout(c: &mut Criterion) {
    let mut g = c.benchmark_group("fanout");
    for subscribers in [1usize, 10, 100] {
        let router = Router::default();
        let name = TopicName::parse("/bench/cmd_vel").expect("valid name");
        let (publisher, _) = router.connect(internal("publisher"), None);
        let topic = router
            .advertise(
                publisher,
                &name,
                Schema::named("geometry_msgs/msg/Twist"),
                false,
            )
            .expect("advertise");
        let outboxes: Vec<Arc<Outbox>> = (0..subscribers)
            .map(|i| {
                let (id, outbox) = router.connect(internal(&format!("sub{i}")), None);
                router
                    .subscribe(id, Target::Exact(name.clone()), SubOptions::default())
                    .expect("subscribe");
                outbox
            })
            .collect();
        let payload = json_64();
        let mut seq = 0u64;
        g.throughput(Throughput::Elements(subscribers as u64));
        g.bench_function(BenchmarkId::from_parameter(subscribers), |b| {
            b.iter(|| {
                seq += 1;
                topic.publish(publisher, seq, seq, Payload::json(payload.clone()));
                let now = Instant::now();
                for o in &outboxes {
                    let batch = o.take(512, 4 << 20, now);
                    debug_assert_eq!(batch.items.len(), 1);
                    black_box(batch);
                }
            });
        });
    }
    g.finish();
}

fn message(payload: &Bytes) -> Message {
    let meta = Arc::new(TopicMeta::new(
        TopicId(7),
        TopicName::parse("/bench/topic").expect("valid name"),
        Schema::named("geometry_msgs/msg/Twist"),
        false,
    ));
    Message::new(
        meta,
        42,
        1_700_000_000_000_000_000,
        ClientId(1),
        Payload::json(payload.clone()),
    )
}

fn link_frames(c: &mut Criterion) {
    let mut g = c.benchmark_group("link_frames");
    for size in [64usize, 1 << 20] {
        let payload = Bytes::from(vec![0x5a; size]);
        g.throughput(Throughput::Bytes(size as u64));
        g.bench_function(BenchmarkId::from_parameter(size), |b| {
            b.iter_batched(
                || message(&payload),
                |m| black_box(m.link_frames()),
                BatchSize::SmallInput,
            );
        });
    }
    g.finish();
}

fn rosbridge_frame(c: &mut Criterion) {
    let tc = GenericTranscoder;
    let payload = json_64();
    let mut g = c.benchmark_group("rosbridge_frame");
    for (label, kind) in [
        ("json", FrameKind::RosbridgeJson),
        ("cbor", FrameKind::RosbridgeCbor),
    ] {
        g.bench_function(format!("{label}/1_subscriber"), |b| {
            b.iter_batched(
                || message(&payload),
                |m| black_box(m.rosbridge_frame(kind, &tc).expect("converts")),
                BatchSize::SmallInput,
            );
        });
        g.bench_function(format!("{label}/100_subscribers"), |b| {
            b.iter_batched(
                || message(&payload),
                |m| {
                    for _ in 0..100 {
                        black_box(m.rosbridge_frame(kind, &tc).expect("converts"));
                    }
                },
                BatchSize::SmallInput,
            );
        });
    }
    g.finish();
}

criterion_group!(benches, fanout, link_frames, rosbridge_frame);
criterion_main!(benches);
