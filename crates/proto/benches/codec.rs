//! Codec speed: the fleetlink.v1 frame encoder/decoder, chunking and reassembly, and the
//! rosbridge builders and parser. Results are recorded in `docs/benchmarks/proto.md`.

use std::hint::black_box;

use bytes::{Bytes, BytesMut};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fleetlink_proto::frame::{self, Frame, chunk_frames, encode_message};
use fleetlink_proto::reassembly::Reassembler;
use fleetlink_proto::rosbridge::{Publish, Request, outbound};

fn message_frame(c: &mut Criterion) {
    let payload = vec![0x5a; 64];
    c.bench_function("message_64B_encode_decode", |b| {
        let mut buf = BytesMut::with_capacity(128);
        b.iter(|| {
            buf.clear();
            encode_message(&mut buf, 42, 1000, 1_700_000_000, black_box(&payload));
            let bytes = buf.split().freeze();
            let (f, _) = Frame::decode(&bytes, 0).expect("valid frame");
            black_box(f);
        });
    });
}

fn packed_frames(c: &mut Criterion) {
    let mut buf = BytesMut::new();
    for i in 0..1000u32 {
        if i % 10 == 0 {
            Frame::Ack {
                frames: i,
                bytes: 0,
            }
            .encode(&mut buf);
        } else {
            encode_message(&mut buf, i % 16, u64::from(i), 5, &[7; 24]);
        }
    }
    let buf = buf.freeze();
    let mut g = c.benchmark_group("packed");
    g.throughput(Throughput::Elements(1000));
    g.bench_function("decode_1000_small_frames", |b| {
        b.iter(|| {
            let mut n = 0;
            for f in frame::frames(black_box(&buf)) {
                black_box(f.expect("valid frame"));
                n += 1;
            }
            assert_eq!(n, 1000);
        });
    });
    g.finish();
}

fn chunking(c: &mut Criterion) {
    let payload = Bytes::from(vec![0xc3; 1 << 20]);
    let mut g = c.benchmark_group("chunking");
    g.throughput(Throughput::Bytes(payload.len() as u64));
    g.bench_function("chunk_reassemble_1MiB_64KiB", |b| {
        let mut wire = BytesMut::with_capacity(payload.len() + 1024);
        let mut r = Reassembler::new(4 << 20, 16 << 20);
        b.iter(|| {
            for f in chunk_frames(3, 9, 0, &payload, 64 * 1024) {
                f.encode(&mut wire);
            }
            let bytes = wire.split().freeze();
            let mut done = None;
            for f in frame::frames(&bytes) {
                let Ok(Frame::Chunk {
                    alias,
                    seq,
                    stamp_ns,
                    total_len,
                    offset,
                    data,
                }) = f
                else {
                    panic!("expected chunks");
                };
                done = r
                    .push(alias, seq, stamp_ns, total_len, offset, &data)
                    .expect("in order");
            }
            assert_eq!(done.expect("complete").payload.len(), 1 << 20);
        });
    });
    g.finish();
}

fn rosbridge_publish(c: &mut Criterion) {
    let mut g = c.benchmark_group("rosbridge_publish");
    for size in [64usize, 1 << 20] {
        let json = format!(r#"{{"data":"{}"}}"#, "x".repeat(size - 11));
        let mut cbor = Vec::new();
        ciborium::into_writer(
            &ciborium::Value::Map(vec![(
                ciborium::Value::Text("data".into()),
                ciborium::Value::Bytes(vec![1; size - 9]),
            )]),
            &mut cbor,
        )
        .expect("CBOR encodes");
        g.throughput(Throughput::Bytes(size as u64));
        g.bench_with_input(BenchmarkId::new("publish_json", size), &json, |b, m| {
            b.iter(|| black_box(outbound::publish_json("/camera/points", m.as_bytes())));
        });
        g.bench_with_input(BenchmarkId::new("publish_cbor", size), &cbor, |b, m| {
            b.iter(|| black_box(outbound::publish_cbor("/camera/points", m)));
        });
    }
    g.finish();
}

fn rosbridge_parse(c: &mut Criterion) {
    let text = br#"{"op":"publish","id":"p-1","topic":"/cmd_vel","msg":{"linear":{"x":0.5,"y":0.0,"z":0.0},"angular":{"x":0.0,"y":0.0,"z":0.1}}}"#;
    c.bench_function("request_from_json_small_publish", |b| {
        b.iter(|| black_box(Request::from_json(black_box(text)).expect("valid request")));
    });
    // The hub's short path for the publish of `fleetlink bench delivery` (64 bytes of
    // data) and for roslibjs' shape of the same (an id before the topic).
    let data = "x".repeat(64);
    for (name, text) in [
        (
            "publish_from_json_text_64B",
            format!(r#"{{"op":"publish","topic":"/bench","msg":{{"data":"{data}"}}}}"#),
        ),
        (
            "publish_from_json_text_64B_with_id",
            format!(
                r#"{{"op":"publish","id":"publish:/bench:17","topic":"/bench","msg":{{"data":"{data}"}},"latch":false}}"#
            ),
        ),
    ] {
        // `from_json_text` wants the text as a view of the frame's own bytes.
        let frame = Bytes::from(text);
        let view = std::str::from_utf8(&frame).expect("ASCII");
        c.bench_function(name, |b| {
            b.iter(|| {
                black_box(Publish::from_json_text(black_box(view), &frame).expect("a publish"))
            });
        });
    }
}

criterion_group!(
    benches,
    message_frame,
    packed_frames,
    chunking,
    rosbridge_publish,
    rosbridge_parse
);
criterion_main!(benches);
