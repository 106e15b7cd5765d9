//! The uplink's periodic reports to the hub (`LINK_REPORT`, `TOPIC_DROPS`, `TOPIC_LOAD`,
//! `BUDGET`): what the robot would send, what its link carries, what each topic lost here,
//! and which local topics lost their last publisher; only what changed is sent again.

use super::*;

/// What the periodic reports last told the hub on this connection: an idle robot's
/// figures do not change, and what did not change is not sent again.
#[derive(Default)]
pub(super) struct Told {
    /// Each topic's drop counts.
    pub(super) drops: HashMap<TopicId, [u64; DropReason::ALL.len()]>,
    /// `LINK_REPORT`'s demand, rate, latency and capacity.
    pub(super) link: Option<[u64; 4]>,
    pub(super) budget: Option<Frame>,
}

/// Whether link figures (`[demand_bps, rate_bps, latency_ns, capacity_bps]`) moved
/// enough to tell the hub: a figure that became or stopped being zero, or one that
/// changed by more than a quarter and by more than the noise of an idle link (2 kB/s of a
/// rate, whose heartbeats alone wobble it; 5 ms of latency). The hub keeps the last
/// figures it was told, and shares a site's capacity by them.
pub(super) fn link_figures_moved(told: &[u64; 4], now: &[u64; 4]) -> bool {
    told.iter().zip(now).enumerate().any(|(i, (&a, &b))| {
        let noise = if i == 2 { 5_000_000 } else { 2_000 };
        (a == 0) != (b == 0) || (a.abs_diff(b) > noise && a.abs_diff(b) * 4 > a.max(b))
    })
}

impl Uplink {
    /// Once a second: the hub hears what this robot would send and what its link carries
    /// (for sharing a site's access link among its robots), which local topics lost
    /// their last publisher, so it stops listing them, and what each topic lost here
    /// (`TOPIC_DROPS`, for the topics whose counts changed), and what it offers of each
    /// topic that flows to the hub (`TOPIC_LOAD`, for the hub's receive-rate prediction).
    pub(super) fn report(
        &self,
        session: &mut LinkSession,
        unpublished: &mut HashSet<TopicId>,
        told: &mut Told,
    ) {
        let me = self.client;
        let mut drops = Vec::new();
        let mut loads = Vec::new();
        let now_ns = fleetlink_relay::unix_nanos();
        for t in self.router.topics() {
            if !t.subscribers.contains(&me) {
                continue; // not carried up
            }
            let id = t.meta.id;
            if !self.outbox.is_held_back(id.0)
                && let Some(load) = self.topic_load(&t.meta, &t.stats, now_ns)
            {
                loads.push(load);
            }
            let counts = DropReason::ALL.map(|r| t.stats.drops(r));
            if counts.iter().any(|n| *n > 0) && told.drops.get(&id) != Some(&counts) {
                told.drops.insert(id, counts);
                let by_reason = DropReason::ALL
                    .iter()
                    .zip(counts)
                    .filter(|(_, n)| *n > 0)
                    .map(|(r, n)| (r.index() as u8, n))
                    .collect();
                drops.push((id.0, by_reason));
            }
            if t.publishers.iter().any(|c| *c != me) {
                unpublished.remove(&id);
            } else if !unpublished.contains(&id) {
                // An instruction to the writer, through the session like every frame:
                // `UNADVERTISE` after the topic's queued messages.
                session.send_control(Control::Unadvertise {
                    topic: id,
                    since: Instant::now(),
                });
                unpublished.insert(id);
            }
        }
        if let Some(f) = self.outbox.link_figures(Instant::now()) {
            let figures = [
                f.demand_bps as u64,
                f.rate_bps as u64,
                f.latency.map_or(0, |l| l.as_nanos() as u64),
                f.capacity_bps.map_or(0, |c| c.round() as u64),
            ];
            if told.link.is_none_or(|t| link_figures_moved(&t, &figures)) {
                told.link = Some(figures);
                let [demand_bps, rate_bps, latency_ns, capacity_bps] = figures;
                // On the hub's clock, so the hub can tell its age at any later time.
                let measured_at_ms = f.measured_at.map_or(0, |at| {
                    let unix = fleetlink_relay::instant_to_unix_nanos(at) as i128;
                    let hub = unix + i128::from(f.clock_offset_ns.unwrap_or(0));
                    (hub.max(1_000_000) / 1_000_000) as u64
                });
                session.send(Frame::LinkReport {
                    demand_bps,
                    rate_bps,
                    latency_ns,
                    capacity_bps,
                    measured_at_ms,
                });
            }
        }
        if !drops.is_empty() {
            session.send(Frame::TopicDrops { topics: drops });
        }
        if !loads.is_empty() {
            session.send(Frame::TopicLoad { topics: loads });
        }
        if let Some(b) = self.outbox.budget_figures(Instant::now()) {
            let budget = Frame::Budget {
                max_bps: b.max_bytes_per_sec.map_or(0, |r| r.round() as u64),
                day_bytes: b.bytes_per_day.map_or(0, |d| d.round() as u64),
                used_bytes: b.used_bytes,
                thinned: b.thinned,
            };
            if told.budget.as_ref() != Some(&budget) {
                told.budget = Some(budget.clone());
                session.send(budget);
            }
        }
    }

    /// What the robot offers of a flowing topic: its local publish rate (within its rate
    /// limit) and bytes, and how the uplink queues it.
    pub(super) fn topic_load(
        &self,
        meta: &TopicMeta,
        stats: &fleetlink_relay::stats::TopicStats,
        now_ns: u64,
    ) -> Option<fleetlink_proto::frame::TopicLoadEntry> {
        let qos = self.outbox.topic_qos(meta)?;
        let (hz, bps) = stats.rates(now_ns);
        if hz <= 0.0 {
            return None;
        }
        let kept = qos.rate_limit_hz.map_or(hz, |limit| hz.min(limit));
        Some(fleetlink_proto::frame::TopicLoadEntry {
            alias: meta.id.0,
            rate_mhz: (kept * 1000.0).round() as u64,
            bytes_per_sec: (bps * kept / hz).round() as u64,
            priority_milli: (f64::from(qos.priority) * 1000.0).round() as u32,
            queue: u32::try_from(qos.queue).unwrap_or(u32::MAX),
            flags: if qos.no_drop {
                fleetlink_proto::frame::TOPIC_LOAD_NO_DROP
            } else {
                0
            },
        })
    }
}

/// Issue 61: an idle robot's reports are not sent again when nothing changed.
#[cfg(test)]
mod report_tests {
    use super::link_figures_moved;

    #[test]
    fn link_figures_are_told_again_only_when_they_moved() {
        // Idle: demand 0, heartbeats wobbling the rate, latency jitter of a few ms.
        let idle = [0, 96, 20_000_000, 50_000];
        assert!(!link_figures_moved(&idle, &[0, 64, 23_000_000, 52_000]));
        assert!(!link_figures_moved(&idle, &idle));
        // Demand appears (a viewer came), or the latency doubles: told.
        assert!(link_figures_moved(&idle, &[1_500, 96, 20_000_000, 50_000]));
        assert!(link_figures_moved(&idle, &[0, 96, 40_000_000, 50_000]));
        // A rate that moved by more than a quarter, and one that stopped: told.
        let busy = [400_000, 390_000, 20_000_000, 1_000_000];
        assert!(link_figures_moved(
            &busy,
            &[400_000, 250_000, 20_000_000, 1_000_000]
        ));
        assert!(link_figures_moved(
            &busy,
            &[0, 390_000, 20_000_000, 1_000_000]
        ));
        // Within a quarter: not told.
        assert!(!link_figures_moved(
            &busy,
            &[420_000, 380_000, 21_000_000, 950_000]
        ));
    }
}
