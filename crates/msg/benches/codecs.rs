//! Codec benchmarks for the issue-4 targets (results in docs/benchmarks/msg.md):
//! a 1 MB PointCloud2 read through the zero-copy view, converted CDR → JSON and
//! CDR → CBOR; a 720-range LaserScan CDR → JSON → CDR round trip.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use fleetlink_msg::{CdrView, Dialect, Registry, Wire, encode, from_json};
use serde_json::json;

fn cloud_cdr(reg: &Registry) -> Vec<u8> {
    let points = 65_536usize; // 16 bytes each: 1 MiB of data
    let data: Vec<u8> = (0..points * 16).map(|i| (i * 31 % 251) as u8).collect();
    let mut v = from_json(
        reg,
        "sensor_msgs/PointCloud2",
        Dialect::Ros2,
        &json!({
            "header": {"stamp": {"sec": 1_700_000_000, "nanosec": 5}, "frame_id": "lidar_top"},
            "height": 1, "width": points,
            "fields": [
                {"name": "x", "offset": 0, "datatype": 7, "count": 1},
                {"name": "y", "offset": 4, "datatype": 7, "count": 1},
                {"name": "z", "offset": 8, "datatype": 7, "count": 1},
                {"name": "intensity", "offset": 12, "datatype": 7, "count": 1}
            ],
            "point_step": 16, "row_step": points * 16, "is_dense": true
        }),
    )
    .expect("cloud JSON");
    if let fleetlink_msg::Value::Struct(s) = &mut v {
        for (name, field) in &mut s.fields {
            if &**name == "data" {
                *field = fleetlink_msg::Value::Array(fleetlink_msg::Array::U8(data.clone()));
            }
        }
    }
    encode(reg, "sensor_msgs/PointCloud2", Wire::Cdr, &v).expect("encodes")
}

/// A 720-beam scan; `with_intensities` adds the optional 720 intensities.
fn scan_cdr(reg: &Registry, with_intensities: bool) -> Vec<u8> {
    let ranges: Vec<f32> = (0..720).map(|i| 0.5 + (i as f32) * 0.013).collect();
    let v = from_json(
        reg,
        "sensor_msgs/LaserScan",
        Dialect::Ros2,
        &json!({
            "header": {"stamp": {"sec": 10, "nanosec": 20}, "frame_id": "laser"},
            "angle_min": -std::f32::consts::PI, "angle_max": std::f32::consts::PI, "angle_increment": 0.00872,
            "time_increment": 0.0001, "scan_time": 0.1, "range_min": 0.1, "range_max": 30.0,
            "intensities": if with_intensities { ranges.clone() } else { Vec::new() }, "ranges": ranges
        }),
    )
    .expect("scan JSON");
    encode(reg, "sensor_msgs/LaserScan", Wire::Cdr, &v).expect("encodes")
}

fn point_cloud(c: &mut Criterion) {
    let reg = Registry::bundled();
    let cdr = cloud_cdr(&reg);
    let mut g = c.benchmark_group("pointcloud2_1mb");
    g.throughput(Throughput::Bytes(cdr.len() as u64));
    g.bench_function("view_header_and_data", |b| {
        b.iter(|| {
            let view =
                CdrView::new(&reg, "sensor_msgs/PointCloud2", black_box(&cdr)).expect("view");
            let h = view.header().expect("header");
            let d = view.primitive_array("data").expect("data");
            black_box((h.sec, h.frame_id.len(), d.bytes.len()))
        })
    });
    g.bench_function("decode_cdr", |b| {
        b.iter(|| {
            fleetlink_msg::decode(&reg, "sensor_msgs/PointCloud2", Wire::Cdr, black_box(&cdr))
                .expect("decodes")
        })
    });
    g.bench_function("cdr_to_json", |b| {
        b.iter(|| {
            fleetlink_msg::cdr_to_json_bytes(&reg, "sensor_msgs/PointCloud2", black_box(&cdr))
                .expect("json")
        })
    });
    g.bench_function("cdr_to_cbor", |b| {
        b.iter(|| {
            fleetlink_msg::cdr_to_cbor_bytes(&reg, "sensor_msgs/PointCloud2", black_box(&cdr))
                .expect("cbor")
        })
    });
    g.finish();
}

fn laser_scan(c: &mut Criterion) {
    let reg = Registry::bundled();
    for (group, with_intensities) in [
        ("laserscan_720", false),
        ("laserscan_720_with_intensities", true),
    ] {
        let cdr = scan_cdr(&reg, with_intensities);
        let json =
            fleetlink_msg::cdr_to_json_bytes(&reg, "sensor_msgs/LaserScan", &cdr).expect("json");
        let mut g = c.benchmark_group(group);
        g.bench_function("cdr_json_cdr_round_trip", |b| {
            b.iter(|| {
                let json = fleetlink_msg::cdr_to_json_bytes(
                    &reg,
                    "sensor_msgs/LaserScan",
                    black_box(&cdr),
                )
                .expect("json");
                let v = fleetlink_msg::from_json_bytes(
                    &reg,
                    "sensor_msgs/LaserScan",
                    Dialect::Ros2,
                    &json,
                )
                .expect("parses");
                encode(&reg, "sensor_msgs/LaserScan", Wire::Cdr, &v).expect("encodes")
            })
        });
        g.bench_function("cdr_to_json", |b| {
            b.iter(|| {
                fleetlink_msg::cdr_to_json_bytes(&reg, "sensor_msgs/LaserScan", black_box(&cdr))
                    .expect("json")
            })
        });
        g.bench_function("json_to_cdr", |b| {
            b.iter(|| {
                let v = fleetlink_msg::from_json_bytes(
                    &reg,
                    "sensor_msgs/LaserScan",
                    Dialect::Ros2,
                    black_box(&json),
                )
                .expect("parses");
                encode(&reg, "sensor_msgs/LaserScan", Wire::Cdr, &v).expect("encodes")
            })
        });
        g.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = point_cloud, laser_scan
}
criterion_main!(benches);
