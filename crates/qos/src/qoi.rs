//! Quantity-of-Information evaluation of drop policies (the AFR paper's Figure 5) and the
//! offline Oracle it is measured against.
//!
//! Model (conventions in `docs/qos.md`): the link is down while messages `1..=T` arrive
//! into a queue of capacity L; message 0 is the last one delivered before the outage.
//! When the link returns, the queue's contents `i_1 < … < i_k` are delivered, worth
//! `QoI = Σ_j V(i_j − i_{j−1})` with `i_0 = 0`, where the value function `V` grows with
//! the gap `d` and saturates (default `V(d) = 1 − 0.618^d`).
//!
//! Design choice: AFR, drop-oldest and random are evaluated by running the real
//! [`TopicQueue`] on the message numbers, so the figure measures the shipped code. The
//! Oracle is a dynamic programme over (messages kept, last kept), valid for any `V`.

use crate::config::{Policy, TopicQos};
use crate::queue::TopicQueue;
use crate::time::Nanos;

/// The value `V(d)` of a delivered message whose predecessor is `d` messages earlier.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ValueFn {
    /// `V(d) = 1 − base^d` (`0 < base < 1`); the paper uses `base = 0.618`.
    Exp { base: f64 },
    /// `V(d) = ln(1 + d)`.
    Log,
    /// `V(d) = √d`.
    Sqrt,
}

impl ValueFn {
    pub const PAPER: ValueFn = ValueFn::Exp { base: 0.618 };

    pub fn value(self, d: u64) -> f64 {
        let d = d as f64;
        match self {
            ValueFn::Exp { base } => 1.0 - base.powf(d),
            ValueFn::Log => d.ln_1p(),
            ValueFn::Sqrt => d.sqrt(),
        }
    }

    /// Parses `exp:0.618`, `log` or `sqrt` (the `--v` option of `fleetlink qoi-sim`).
    pub fn parse(s: &str) -> Result<ValueFn, String> {
        match s {
            "log" => Ok(ValueFn::Log),
            "sqrt" => Ok(ValueFn::Sqrt),
            _ => {
                let base = s.strip_prefix("exp:").ok_or_else(|| {
                    format!("unknown value function `{s}` (exp:<base>, log, sqrt)")
                })?;
                let base: f64 = base
                    .parse()
                    .map_err(|e| format!("bad base in `{s}`: {e}"))?;
                if base > 0.0 && base < 1.0 {
                    Ok(ValueFn::Exp { base })
                } else {
                    Err(format!("base must be in (0, 1), got {base}"))
                }
            }
        }
    }
}

/// QoI of the delivered message numbers (ascending, all >= 1).
pub fn qoi(delivered: &[u64], v: ValueFn) -> f64 {
    let mut prev = 0;
    delivered
        .iter()
        .map(|&i| {
            let d = i - prev;
            prev = i;
            v.value(d)
        })
        .sum()
}

/// The Oracle's QoI for every `T` in `0..=t_max`: the best choice of at most `l` of the
/// messages `1..=T` with full knowledge of the future (not realisable online).
pub fn oracle_by_t(l: usize, t_max: u64, v: ValueFn) -> Vec<f64> {
    let n = t_max as usize;
    // best[t] for the current k: best QoI of exactly k kept messages, the last being t.
    let mut best = vec![f64::NEG_INFINITY; n + 1];
    best[0] = 0.0; // k = 0: nothing kept, "last" is message 0.
    let mut answer = vec![0.0f64; n + 1];
    for _k in 1..=l {
        let mut next = vec![f64::NEG_INFINITY; n + 1];
        for (t, slot) in next.iter_mut().enumerate().skip(1) {
            *slot = (0..t)
                .filter(|&s| best[s].is_finite())
                .map(|s| best[s] + v.value((t - s) as u64))
                .fold(f64::NEG_INFINITY, f64::max);
        }
        best = next;
        let mut running = f64::NEG_INFINITY;
        for (kept, best_at) in answer.iter_mut().zip(&best) {
            running = running.max(*best_at);
            *kept = kept.max(running);
        }
    }
    answer
}

/// The Oracle's choice for one `T` when `V` is concave and increasing (evaluation only).
pub fn oracle_select(l: usize, t: u64) -> Vec<u64> {
    // For a concave, increasing V the optimum spreads min(l, T) messages as evenly as
    // possible up to T; `oracle_by_t` (general V) checks this in the tests.
    let k = (l as u64).min(t);
    if k == 0 {
        return Vec::new();
    }
    let (q, r) = (t / k, t % k);
    let mut at = 0;
    (0..k)
        .map(|j| {
            at += q + u64::from(j >= k - r);
            at
        })
        .collect()
}

/// What a policy keeps of messages `1..=t` in a queue of `qos.queue`, run on the real
/// queue code with nothing sent in between.
pub fn survivors(qos: &TopicQos, seed: u64, t: u64) -> Vec<u64> {
    let mut queue = TopicQueue::with_seed(qos, seed);
    for m in 1..=t {
        let _ = queue.push(m, Nanos::ZERO);
    }
    std::iter::from_fn(|| queue.pop(Nanos::ZERO)).collect()
}

/// Simulation parameters of Figure 5.
#[derive(Debug, Clone)]
pub struct QoiParams {
    pub l: usize,
    pub t_min: u64,
    pub t_max: u64,
    pub v: ValueFn,
    /// Runs of the random policy per T.
    pub runs: u32,
    pub seed: u64,
}

impl Default for QoiParams {
    fn default() -> Self {
        QoiParams {
            l: 8,
            t_min: 1,
            t_max: 200,
            v: ValueFn::PAPER,
            runs: 10_000,
            seed: 1,
        }
    }
}

/// One row of `qoi.csv`.
#[derive(Debug, Clone, PartialEq)]
pub struct QoiRow {
    pub t: u64,
    pub oracle: f64,
    pub afr: f64,
    pub drop_oldest: f64,
    pub random_mean: f64,
    /// Sample standard deviation (n − 1) over the runs.
    pub random_sd: f64,
}

impl QoiRow {
    pub const CSV_HEADER: &'static str = "T,oracle,afr,drop_oldest,random_mean,random_sd";

    pub fn to_csv(&self) -> String {
        format!(
            "{},{:.6},{:.6},{:.6},{:.6},{:.6}",
            self.t, self.oracle, self.afr, self.drop_oldest, self.random_mean, self.random_sd
        )
    }
}

fn qos(policy: Policy, l: usize) -> TopicQos {
    TopicQos {
        policy,
        queue: l,
        ..TopicQos::default()
    }
}

/// Computes Figure 5: one row per `T` in `t_min..=t_max`.
pub fn simulate(p: &QoiParams) -> Vec<QoiRow> {
    let oracle = oracle_by_t(p.l, p.t_max, p.v);
    let (afr, oldest) = (qos(Policy::Afr, p.l), qos(Policy::DropOldest, p.l));
    let random = random_stats(p);
    (p.t_min..=p.t_max)
        .map(|t| {
            let (mean, sd) = random[t as usize];
            QoiRow {
                t,
                oracle: oracle[t as usize],
                afr: qoi(&survivors(&afr, 0, t), p.v),
                drop_oldest: qoi(&survivors(&oldest, 0, t), p.v),
                random_mean: mean,
                random_sd: sd,
            }
        })
        .collect()
}

/// Mean and sample standard deviation of the random policy's QoI for every `T` up to
/// `t_max`. Each run feeds messages `1..=t_max` once and reads the queue after each
/// arrival, so run `r` of every `T` is the same seeded sequence cut at `T` (seed
/// `p.seed + r`).
fn random_stats(p: &QoiParams) -> Vec<(f64, f64)> {
    let n = p.t_max as usize;
    let mut sum = vec![0.0f64; n + 1];
    let mut sum_sq = vec![0.0f64; n + 1];
    let policy = qos(Policy::Random, p.l);
    let mut kept: Vec<u64> = Vec::with_capacity(p.l);
    for run in 0..p.runs {
        let mut queue = TopicQueue::with_seed(&policy, p.seed.wrapping_add(run as u64));
        for t in 1..=p.t_max {
            let _ = queue.push(t, Nanos::ZERO);
            // Read the contents without disturbing the queue: pop all, push back.
            kept.clear();
            kept.extend(std::iter::from_fn(|| queue.pop(Nanos::ZERO)));
            let q = qoi(&kept, p.v);
            for &m in &kept {
                let _ = queue.push(m, Nanos::ZERO);
            }
            sum[t as usize] += q;
            sum_sq[t as usize] += q * q;
        }
    }
    let runs = p.runs.max(1) as f64;
    (0..=n)
        .map(|t| {
            let mean = sum[t] / runs;
            let var = if p.runs > 1 {
                (sum_sq[t] - runs * mean * mean) / (runs - 1.0)
            } else {
                0.0
            };
            (mean, var.max(0.0).sqrt())
        })
        .collect()
}

/// The `T` at which AFR's QoI equals the Oracle's (within `1e-9`), excluding `T <= L`
/// where every policy keeps everything.
pub fn special_t_values(rows: &[QoiRow], l: usize) -> Vec<u64> {
    rows.iter()
        .filter(|r| r.t > l as u64 && (r.afr - r.oracle).abs() < 1e-9)
        .map(|r| r.t)
        .collect()
}

/// Theorem 2's lower bound on AFR/Oracle: `2(√2 − 1) · L / (L + 1)`.
pub fn theorem2_bound(l: usize) -> f64 {
    2.0 * (2f64.sqrt() - 1.0) * l as f64 / (l as f64 + 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn oracle_dynamic_programme_agrees_with_even_spreading_for_concave_v() {
        for v in [ValueFn::PAPER, ValueFn::Log, ValueFn::Sqrt] {
            for l in [1, 3, 8] {
                let dp = oracle_by_t(l, 60, v);
                for t in 0..=60 {
                    let closed = qoi(&oracle_select(l, t), v);
                    assert!((dp[t as usize] - closed).abs() < 1e-9, "l={l} t={t} {v:?}");
                }
            }
        }
    }

    #[test]
    fn value_function_option_parses() {
        assert_eq!(ValueFn::parse("exp:0.5"), Ok(ValueFn::Exp { base: 0.5 }));
        assert_eq!(ValueFn::parse("log"), Ok(ValueFn::Log));
        assert!(ValueFn::parse("exp:1.5").is_err());
        assert!(ValueFn::parse("cubic").is_err());
    }
}
