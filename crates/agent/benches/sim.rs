//! Cost of generating one simulated message, JSON included: a 10,000-point cloud, a
//! 720-beam scan and a 320 × 240 camera picture (the defaults: drawn, JPEG-encoded,
//! base64), as the robot-side CPU budget cares about.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use fleetlink_agent::config::{ImageSim, LaserScanSim, PointCloudSim, SimConfig};
use fleetlink_agent::sim::Sim;

fn generate(c: &mut Criterion) {
    let only = SimConfig {
        laser_scan: Some(LaserScanSim::default()),
        point_cloud: Some(PointCloudSim::default()),
        odometry: None,
        pose: None,
        image: Some(ImageSim::default()),
        ..SimConfig::default()
    };
    let mut sim = Sim::new(&only, "robot1", 0);
    let mut t = Duration::ZERO;
    c.bench_function("sim/laser_scan_720", |b| {
        b.iter(|| {
            t += Duration::from_millis(100);
            black_box(sim.generate(0, t))
        })
    });
    c.bench_function("sim/point_cloud_10000", |b| {
        b.iter(|| {
            t += Duration::from_millis(200);
            black_box(sim.generate(1, t))
        })
    });
    c.bench_function("sim/camera_320x240", |b| {
        b.iter(|| {
            t += Duration::from_millis(100);
            black_box(sim.generate(2, t))
        })
    });
}

criterion_group!(benches, generate);
criterion_main!(benches);
