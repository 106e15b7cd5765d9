//! Capacity sharing for robots behind one access link (Cloudroid Swarm, Algorithm 2), and
//! the per-robot offload decision signal (its inequality (5)).
//!
//! Every interval T the hub gives each robot of a site a share of the site's capacity C:
//! weights are a softmax of the robots' measured latencies, `w_i = exp(λ·lat_i) / Σ_j
//! exp(λ·lat_j)` (λ per second of latency; λ = 0 is an equal split, λ > 0 favours the
//! robots whose link is suffering), and the capacity is water-filled by those weights
//! against each robot's demand: nobody gets more than it asks for while others still
//! want more, and what is left over after every demand is met is handed out by weight
//! as headroom. The agent caps its scheduler's byte budget at its share.
//!
//! Design choice: one allocator per site, fed plain reports, returning plain shares —
//! the hub decides who is in a site and how shares travel; this stays a pure function of
//! the reports plus the update cadence.

use crate::error::QosError;
use crate::time::Nanos;

#[derive(Debug, Clone)]
pub struct CapacityConfig {
    /// C: capacity of the site's shared access link, bytes/s.
    pub site_capacity: f64,
    /// λ: softmax temperature, per second of latency.
    pub lambda: f64,
    /// T: shares are recomputed at most this often.
    pub interval: Nanos,
}

impl Default for CapacityConfig {
    fn default() -> Self {
        CapacityConfig {
            site_capacity: 12_500_000.0,
            lambda: 20.0,
            interval: Nanos::from_secs(1),
        }
    }
}

impl CapacityConfig {
    pub fn validate(&self) -> Result<(), QosError> {
        let bad = |what, reason: &str| {
            Err(QosError::InvalidParameter {
                what,
                reason: reason.to_string(),
            })
        };
        if !(self.site_capacity.is_finite() && self.site_capacity > 0.0) {
            return bad("site_capacity", "must be a finite number > 0");
        }
        if !self.lambda.is_finite() {
            return bad("lambda", "must be finite");
        }
        Ok(())
    }
}

/// What the hub knows about one robot's link this interval.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotLinkReport<R> {
    pub robot: R,
    /// What the robot would send if it could, bytes/s (sum of its queued topics' rates).
    pub demand: f64,
    /// Measured one-way latency (`LinkEstimator::latency`).
    pub latency: Nanos,
    /// Measured rate (`LinkEstimator::rate`), bytes/s; used by the offload signal.
    pub rate: f64,
}

/// A robot's capacity share, bytes/s.
#[derive(Debug, Clone, PartialEq)]
pub struct Share<R> {
    pub robot: R,
    pub bytes_per_sec: f64,
}

/// Capacity allocator for one site (see the module docs).
#[derive(Debug, Clone)]
pub struct CapacityAllocator<R> {
    config: CapacityConfig,
    next_due: Option<Nanos>,
    last: Vec<Share<R>>,
}

impl<R: Clone + PartialEq> CapacityAllocator<R> {
    pub fn new(config: CapacityConfig) -> Result<Self, QosError> {
        config.validate()?;
        Ok(CapacityAllocator {
            config,
            next_due: None,
            last: Vec::new(),
        })
    }

    /// Shares for the robots in `reports`. Recomputed when the interval T has elapsed or
    /// the set of robots changed; otherwise the previous shares are returned.
    pub fn update(&mut self, reports: &[RobotLinkReport<R>], now: Nanos) -> Vec<Share<R>> {
        let same_robots = self.last.len() == reports.len()
            && self
                .last
                .iter()
                .zip(reports)
                .all(|(s, r)| s.robot == r.robot);
        if same_robots && self.next_due.is_some_and(|due| now < due) {
            return self.last.clone();
        }
        self.next_due = Some(now + self.config.interval);
        self.last = allocate(self.config.site_capacity, self.config.lambda, reports);
        self.last.clone()
    }

    /// Inequality (5) for one robot with its measured link: true when relaying the
    /// cooperation traffic through the cloud and computing there beats doing it locally.
    pub fn offload_signal(&self, params: &OffloadParams, report: &RobotLinkReport<R>) -> bool {
        params.offload(report.rate, report.latency)
    }
}

/// Water-filling by softmax weights (see the module docs).
fn allocate<R: Clone>(capacity: f64, lambda: f64, reports: &[RobotLinkReport<R>]) -> Vec<Share<R>> {
    let n = reports.len();
    if n == 0 {
        return Vec::new();
    }
    let scores: Vec<f64> = reports
        .iter()
        .map(|r| lambda * r.latency.as_secs_f64())
        .collect();
    let max = scores.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let weights: Vec<f64> = scores.iter().map(|s| (s - max).exp()).collect();
    let demand: Vec<f64> = reports.iter().map(|r| r.demand.max(0.0)).collect();
    let mut share = vec![0.0; n];
    let mut open: Vec<usize> = (0..n).collect();
    let mut left = capacity;
    // Each round settles every robot whose demand fits its weighted part of what is left.
    loop {
        let total_w: f64 = open.iter().map(|&i| weights[i]).sum();
        let (fits, rest): (Vec<usize>, Vec<usize>) = open
            .iter()
            .partition(|&&i| demand[i] <= left * weights[i] / total_w);
        if fits.is_empty() {
            for &i in &open {
                share[i] = left * weights[i] / total_w;
            }
            break;
        }
        for &i in &fits {
            share[i] = demand[i];
            left -= demand[i];
        }
        open = rest;
        if open.is_empty() {
            // All demands met: hand the remainder out as headroom, by weight.
            let total_w: f64 = weights.iter().sum();
            for i in 0..n {
                share[i] += left.max(0.0) * weights[i] / total_w;
            }
            break;
        }
    }
    reports
        .iter()
        .zip(share)
        .map(|(r, s)| Share {
            robot: r.robot.clone(),
            bytes_per_sec: s,
        })
        .collect()
}

/// The operator's numbers for the offload decision (our reading of Cloudroid Swarm's
/// inequality (5); see `docs/qos.md`).
#[derive(Debug, Clone, PartialEq)]
pub struct OffloadParams {
    /// h: robots that need each piece of cooperation data (local exchange sends it h
    /// times over the shared radio; the cloud relay receives it once).
    pub h: f64,
    /// s_m: the robot's computing speed, operations/s.
    pub s_m: f64,
    /// s_s: the server's computing speed, operations/s.
    pub s_s: f64,
    /// d: data per task, bytes.
    pub d: f64,
    /// x: computation per task, operations.
    pub x: f64,
}

impl OffloadParams {
    /// `x/s_s + d/R + lat  <  x/s_m + h·d/R`: offloading (upload once, compute on the
    /// server) finishes before local computing with h local exchanges.
    pub fn offload(&self, rate: f64, latency: Nanos) -> bool {
        if !(rate > 0.0 && self.s_m > 0.0 && self.s_s > 0.0) {
            return false;
        }
        let cloud = self.x / self.s_s + self.d / rate + latency.as_secs_f64();
        let local = self.x / self.s_m + self.h * self.d / rate;
        cloud < local
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(robot: u32, demand: f64, latency_ms: u64) -> RobotLinkReport<u32> {
        RobotLinkReport {
            robot,
            demand,
            latency: Nanos::from_millis(latency_ms),
            rate: 1e6,
        }
    }

    fn alloc(lambda: f64) -> CapacityAllocator<u32> {
        CapacityAllocator::new(CapacityConfig {
            site_capacity: 1000.0,
            lambda,
            interval: Nanos::from_secs(1),
        })
        .unwrap()
    }

    fn amounts(shares: &[Share<u32>]) -> Vec<f64> {
        shares
            .iter()
            .map(|s| (s.bytes_per_sec * 1000.0).round() / 1000.0)
            .collect()
    }

    #[test]
    fn equal_latency_splits_evenly_and_never_exceeds_capacity() {
        let reports = [report(1, 800.0, 50), report(2, 800.0, 50)];
        let shares = alloc(20.0).update(&reports, Nanos::ZERO);
        assert_eq!(amounts(&shares), vec![500.0, 500.0]);
    }

    #[test]
    fn small_demands_are_met_and_the_rest_goes_to_the_hungry() {
        let reports = [
            report(1, 100.0, 50),
            report(2, 5000.0, 50),
            report(3, 5000.0, 50),
        ];
        let shares = alloc(0.0).update(&reports, Nanos::ZERO);
        assert_eq!(amounts(&shares), vec![100.0, 450.0, 450.0]);
    }

    #[test]
    fn softmax_of_latency_favours_the_slower_link_more_as_lambda_grows() {
        let reports = [report(1, 5000.0, 20), report(2, 5000.0, 120)];
        let mild = alloc(5.0).update(&reports, Nanos::ZERO);
        let strong = alloc(20.0).update(&reports, Nanos::ZERO);
        assert!(mild[1].bytes_per_sec > mild[0].bytes_per_sec);
        assert!(strong[1].bytes_per_sec > mild[1].bytes_per_sec);
        let total: f64 = strong.iter().map(|s| s.bytes_per_sec).sum();
        assert!((total - 1000.0).abs() < 1e-6);
    }

    #[test]
    fn shares_change_only_once_per_interval() {
        let mut a = alloc(20.0);
        let first = a.update(&[report(1, 100.0, 50), report(2, 5000.0, 50)], Nanos::ZERO);
        let later = [report(1, 5000.0, 50), report(2, 5000.0, 50)];
        assert_eq!(a.update(&later, Nanos::from_millis(500)), first);
        assert_ne!(a.update(&later, Nanos::from_secs(1)), first);
    }

    #[test]
    fn offload_signal_follows_the_inequality() {
        let p = OffloadParams {
            h: 3.0,
            s_m: 1e9,
            s_s: 1e10,
            d: 1e6,
            x: 2e9,
        };
        let a = alloc(0.0);
        // Fast link: 1e6/1e7 = 0.1 s per transfer. cloud 0.2+0.1+0.05 < local 2+0.3.
        assert!(a.offload_signal(
            &p,
            &RobotLinkReport {
                rate: 1e7,
                ..report(1, 0.0, 50)
            }
        ));
        // Tiny computation, slow link with high latency: stay local.
        let small = OffloadParams {
            h: 1.0,
            x: 1e6,
            ..p.clone()
        };
        assert!(!a.offload_signal(
            &small,
            &RobotLinkReport {
                rate: 1e5,
                ..report(1, 0.0, 500)
            }
        ));
        assert!(
            CapacityAllocator::<u32>::new(CapacityConfig {
                site_capacity: 0.0,
                ..Default::default()
            })
            .is_err()
        );
    }
}
