//! Capacity sharing among robots behind one access link (Cloudroid Swarm, Algorithm 2).
//!
//! Once a second, for each configured site, the hub gathers its online robots' link
//! reports (demand and latency, from their `LINK_REPORT` frames), asks the QoS engine's
//! [`CapacityAllocator`] for shares of the site's capacity, and sends every robot its
//! share in a `SHARE` frame; each agent's scheduler keeps its sending rate within it.
//! The allocator itself is sans-IO; this task only drives it.

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::{Duration, Instant};

use fleetlink_qos::{CapacityAllocator, CapacityConfig, Nanos, RobotLinkReport};

use crate::registry::LiveRobot;
use crate::state::HubState;

/// Softmax temperature: per second of latency (see docs/qos.md).
const LAMBDA: f64 = 20.0;

/// A robot's link as the allocator sees it.
pub fn report(r: &LiveRobot) -> RobotLinkReport<String> {
    let latency = match r.latency_ns.load(Relaxed) {
        0 => r.rtt_ns.load(Relaxed) / 2,
        l => l,
    };
    RobotLinkReport {
        robot: r.name.clone(),
        demand: r.demand_bps.load(Relaxed) as f64,
        latency: Nanos(latency),
        rate: r.rate_bps.load(Relaxed) as f64,
    }
}

pub async fn share_sites(st: Arc<HubState>) {
    if st.sites.is_empty() {
        return;
    }
    let origin = Instant::now();
    let mut allocators: HashMap<String, CapacityAllocator<String>> = HashMap::new();
    let mut tick = tokio::time::interval(Duration::from_secs(1));
    loop {
        tick.tick().await;
        let now = Nanos::since(origin, Instant::now());
        let online = st.registry.list();
        for site in &st.sites {
            let robots: Vec<&Arc<LiveRobot>> = online
                .iter()
                .filter(|r| site.robots.is_match(&r.name))
                .collect();
            if robots.is_empty() {
                continue;
            }
            let alloc = match allocators.get_mut(&site.name) {
                Some(a) => a,
                None => {
                    let cfg = CapacityConfig {
                        site_capacity: site.capacity_bps,
                        lambda: LAMBDA,
                        interval: Nanos::from_secs(1),
                    };
                    match CapacityAllocator::new(cfg) {
                        Ok(a) => allocators.entry(site.name.clone()).or_insert(a),
                        Err(e) => {
                            tracing::warn!("site {}: {e}", site.name);
                            continue;
                        }
                    }
                }
            };
            let reports: Vec<RobotLinkReport<String>> = robots.iter().map(|r| report(r)).collect();
            for share in alloc.update(&reports, now) {
                if let Some(r) = robots.iter().find(|r| r.name == share.robot) {
                    r.send_share(share.bytes_per_sec.max(1.0) as u64);
                }
            }
        }
    }
}
