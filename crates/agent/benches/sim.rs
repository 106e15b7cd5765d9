//! Cost of generating one simulated message, JSON included: a 10,000-point cloud and a
//! 720-beam scan (the defaults), as the robot-side CPU budget cares about.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use fleetlink_agent::config::{LaserScanSim, PointCloudSim, SimConfig};
use fleetlink_agent::sim::Sim;

fn generate(c: &mut Criterion) {
    let only = SimConfig {
        laser_scan: Some(LaserScanSim::default()),
        point_cloud: Some(PointCloudSim::default()),
        odometry: None,
        pose: None,
        image: None,
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
}

criterion_group!(benches, generate);
criterion_main!(benches);
