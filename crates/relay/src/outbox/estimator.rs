//! How an uplink measures its link: echo probes and heartbeat echoes fed to its
//! `LinkEstimator`, the hub's capacity share, and the `LinkFigures` reported to the hub.
//! Apart from the queues: none of it touches a message.

use std::collections::VecDeque;

use fleetlink_qos::{Nanos, Scheduler};

use crate::link_control::LinkControl;

use super::uplink::Uplink;
use super::*;

/// Whether an uplink has something to measure its link with: data waiting (queued, or
/// pulled for the peer) or sent and not yet acknowledged.
fn link_busy(
    sched: &Scheduler<Arc<Message>>,
    link: &LinkControl,
    pulled: &VecDeque<Arc<Message>>,
) -> bool {
    sched.has_queued() || link.unacked_bytes() > 0 || !pulled.is_empty()
}

/// What a link may carry by rule, bytes/s: the smaller of the hub's capacity share and the
/// data budget's rate; `None` without either.
fn limit_by_rule(link: &LinkControl, sched: &Scheduler<Arc<Message>>) -> Option<f64> {
    [
        link.share,
        sched
            .data_budget()
            .and_then(|b| b.config().max_bytes_per_sec),
    ]
    .into_iter()
    .flatten()
    .reduce(f64::min)
}

/// A link report for the hub: demand, delivered rate and one-way latency.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LinkFigures {
    pub demand_bps: f64,
    pub rate_bps: f64,
    pub latency: Option<Duration>,
    pub rtt: Option<Duration>,
    /// Hub clock minus robot clock.
    pub clock_offset_ns: Option<i64>,
    pub share_bps: Option<f64>,
    pub in_flight_bytes: usize,
    /// What the robot may send now, bytes/s: the smallest of its capacity share, its data
    /// budget's rate and the link's best measured rate (the rate over the estimator's
    /// window or the best 50 ms of the last half second, whichever is higher, when data
    /// last flowed); `None` until something was measured.
    pub capacity_bps: Option<f64>,
    /// When the link's rate was last measured with data on it (`None`: never). An idle
    /// link is not probed: its capacity figure is the one measured then.
    pub measured_at: Option<Instant>,
}

impl Uplink {
    /// The hub's capacity share for this robot (bytes per second; `None` = no cap).
    pub(super) fn set_share(&mut self, bytes_per_sec: Option<f64>, now: Instant) {
        let t = Nanos::since(self.origin, now);
        self.link.set_share(bytes_per_sec, t);
    }

    /// Runs `f` on the uplink's estimator with the outbox's clock origin and whether the
    /// link is busy (data queued, pulled or unacknowledged).
    pub(super) fn with_estimator<R>(
        &mut self,
        f: impl FnOnce(&mut fleetlink_qos::LinkEstimator, Instant, bool) -> R,
    ) -> R {
        let busy = link_busy(&self.sched, &self.link, &self.pulled);
        f(&mut self.link.est, self.origin, busy)
    }

    /// What the link looks like now; restarts the demand measurement.
    pub(super) fn link_figures(&mut self, now: Instant) -> LinkFigures {
        let Uplink {
            origin,
            link,
            sched,
            ..
        } = self;
        let t = Nanos::since(*origin, now);
        // Measured only while data flows; an idle link keeps its last figure, and its age.
        if std::mem::take(&mut link.acked_since_report) {
            link.measured = Some((link.est.rate().max(link.delivered_rate(t)), t));
        }
        let capacity = [
            link.measured.map(|(r, _)| r).filter(|r| *r > 0.0),
            limit_by_rule(link, sched),
        ]
        .into_iter()
        .flatten()
        .reduce(f64::min);
        let span = t.saturating_sub(link.offered_since).as_secs_f64();
        let demand = if span > 0.0 {
            link.offered as f64 / span
        } else {
            0.0
        };
        link.offered = 0;
        link.offered_since = t;
        let d = |n: Nanos| Duration::from_nanos(n.0);
        LinkFigures {
            demand_bps: demand,
            rate_bps: link.est.rate(),
            latency: link.est.latency().map(d),
            rtt: link.est.rtt().map(d),
            clock_offset_ns: link.est.clock_offset(),
            share_bps: link.share,
            in_flight_bytes: link.unacked_bytes(),
            capacity_bps: capacity,
            measured_at: link.measured.map(|(_, at)| *origin + d(at)),
        }
    }
}

impl Outbox {
    /// The hub's capacity share for this robot (bytes per second; `None` = no cap): the
    /// scheduler keeps the sending rate within it.
    pub fn set_share(&self, bytes_per_sec: Option<f64>, now: Instant) {
        if self
            .with_uplink(|u| u.set_share(bytes_per_sec, now))
            .is_some()
        {
            self.notify.notify_one();
        }
    }

    /// What the link may carry by rule, bytes/s: the smaller of the hub's capacity share
    /// and the data budget's rate; `None` without either (and for a plain outbox).
    pub fn send_limit(&self) -> Option<f64> {
        self.with_uplink(|u| limit_by_rule(&u.link, &u.sched))
            .flatten()
    }

    /// An echo probe due now, if any (scheduled outboxes only): its id goes out in a PING.
    /// Probes go out while data waits or is unacknowledged (and until the first echo); an
    /// idle link is measured by its heartbeat alone ([`Self::on_heartbeat_echo`]).
    pub fn poll_probe(&self, now: Instant) -> Option<u64> {
        self.with_estimator(|est, origin, busy| {
            est.poll_probe(Nanos::since(origin, now), busy)
                .map(|p| p.id)
        })
        .flatten()
    }

    /// When the writer should look for a probe next ([`Self::poll_probe`]); `None` while
    /// the link is idle (new data wakes the writer through [`Self::ready`]).
    pub fn probe_timeout(&self) -> Option<Instant> {
        self.with_estimator(|est, origin, busy| {
            let at = est.poll_timeout(busy)?;
            Some(origin + Duration::from_nanos(at.0))
        })
        .flatten()
    }

    /// [`Uplink::with_estimator`] under the lock; `None` for a round-robin outbox, which
    /// has no link.
    fn with_estimator<R>(
        &self,
        f: impl FnOnce(&mut fleetlink_qos::LinkEstimator, Instant, bool) -> R,
    ) -> Option<R> {
        self.with_uplink(|u| u.with_estimator(f))
    }

    /// The hub echoed probe `id`, reading `hub_ns` (Unix ns) on its clock.
    pub fn on_echo(&self, id: u64, hub_ns: u64, now: Instant) {
        self.echoed(now, hub_ns, |est, t, hub| est.handle_echo(id, hub, t));
    }

    /// The hub answered a heartbeat `PING` after `rtt`, reading `hub_ns` on its clock: on
    /// an idle link, the sample that keeps the round trip and clock offset current.
    pub fn on_heartbeat_echo(&self, rtt: Duration, hub_ns: u64, now: Instant) {
        let rtt = Nanos(rtt.as_nanos().min(u128::from(u64::MAX)) as u64);
        self.echoed(now, hub_ns, |est, t, hub| {
            est.handle_heartbeat_echo(rtt, hub, t)
        });
    }

    fn echoed(
        &self,
        now: Instant,
        hub_ns: u64,
        f: impl FnOnce(&mut fleetlink_qos::LinkEstimator, Nanos, Nanos),
    ) {
        self.with_estimator(|est, origin, _| {
            let t = Nanos::since(origin, now);
            // The estimator runs on this outbox's clock (ns since `origin`); the hub's
            // reading is put on the same scale, so the offset it finds is hub − robot.
            let origin_unix = crate::instant_to_unix_nanos(origin);
            f(est, t, Nanos(hub_ns.saturating_sub(origin_unix)));
        });
    }

    /// What the link looks like now; restarts the demand measurement (call about once a
    /// second, for the hub's capacity sharing).
    pub fn link_figures(&self, now: Instant) -> Option<LinkFigures> {
        self.with_uplink(|u| u.link_figures(now))
    }
}
