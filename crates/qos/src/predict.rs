//! Receive-rate prediction: how many messages per second of each topic a robot's link can
//! deliver, given what the robot offers, the size of its messages on the link and what
//! the link carries (our reading of ROS Gateway's equations 3–5, extended to several
//! topics sharing one link under the uplink scheduler).
//!
//! For one topic alone on a link of capacity `C` bytes/s, publishing `f` messages/s of
//! `s` bytes each on the wire, the link needs `f·s` bytes/s (eq. 3), can carry at most
//! `C/s` messages/s (eq. 4), so the subscriber receives `min(f, C/s)` (eq. 5).
//!
//! With several topics two rules apply on the agent's uplink (the hub's `rates` module
//! combines them):
//!
//! - Messages the writer sends whole are taken one at a time as the scheduler picks
//!   them: among topics with a message waiting, the one with the largest
//!   `priority × time since its last message went` ([`crate::scheduler`]). No closed form
//!   follows that rule well once a message takes the link a while — two saturated topics
//!   of priorities 1 and 0.5 alternate message for message rather than 2:1 — so
//!   [`receive_rates`] replays it on virtual time (every topic publishing periodically at
//!   its offered rate into a drop-oldest queue of its length, the link serving one
//!   message after another at `C` bytes/s) and reports the rates the replay delivered.
//!   `receive_rate_prediction_matches_what_the_scheduler_sends` checks the replay
//!   against the scheduler itself.
//! - Large messages go out a chunk of each in turn, one message per topic at a time, so
//!   those topics share the link byte for byte ([`byte_fair_rates`]).
//!
//! When what is offered fits the link, every topic is predicted at its offered rate.
//!
//! Design choice: a pure function of figures the hub already has (the agent's reports and
//! the hub's own byte counts), so the API can show the inputs beside the result and a
//! reader can redo the sum. The replay is bounded (at most [`REPLAY_MESSAGES`] messages
//! or [`REPLAY_SECS`] of virtual time), and runs only for a robot whose topics do not
//! fit its link.

/// Messages the replay serves at most.
pub const REPLAY_MESSAGES: u64 = 20_000;
/// Virtual seconds the replay covers at most.
pub const REPLAY_SECS: f64 = 60.0;

/// One topic's load on a robot's link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TopicLoad {
    /// Messages per second the robot's publishers offer (`f`).
    pub offered_hz: f64,
    /// Bytes one message takes on the link, after compression (`s`).
    pub wire_bytes: f64,
    /// The scheduler priority of the topic (`p`, > 0).
    pub priority: f64,
    /// Messages its queue on the robot holds (the oldest goes when it is full).
    pub queue: u32,
}

/// Messages per second of each topic the link delivers, in the order of `loads`, for a
/// link that carries `capacity` bytes/s (see the module docs).
pub fn receive_rates(capacity: f64, loads: &[TopicLoad]) -> Vec<f64> {
    let offered = |l: &TopicLoad| l.offered_hz.max(0.0);
    let need: f64 = loads
        .iter()
        .map(|l| offered(l) * l.wire_bytes.max(0.0))
        .sum();
    if need <= capacity.max(0.0) {
        return loads.iter().map(offered).collect();
    }
    if capacity <= 0.0 {
        return vec![0.0; loads.len()];
    }
    replay(capacity, loads)
}

/// The scheduler's rule on virtual time, for a link that cannot carry everything.
fn replay(capacity: f64, loads: &[TopicLoad]) -> Vec<f64> {
    struct T {
        hz: f64,
        secs_per_msg: f64,
        priority: f64,
        queue: u64,
        /// Offers sent or dropped so far (publications at 0, 1/hz, 2/hz, …).
        taken: u64,
        last: f64,
        sent: u64,
    }
    let mut topics: Vec<T> = loads
        .iter()
        .map(|l| T {
            hz: if l.priority > 0.0 {
                l.offered_hz.max(0.0)
            } else {
                0.0
            },
            secs_per_msg: l.wire_bytes.max(0.0) / capacity,
            priority: l.priority,
            queue: u64::from(l.queue.max(1)),
            taken: 0,
            last: 0.0,
            sent: 0,
        })
        .collect();
    // Offers made up to time `t` by a topic publishing `hz` times a second; a topic has a
    // message waiting when its next offer's time has come.
    let made = |hz: f64, t: f64| (t * hz).floor() as u64 + 1;
    let waiting = |x: &T, t: f64| x.hz > 0.0 && x.taken as f64 / x.hz <= t;
    let (mut t, mut served) = (0.0f64, 0u64);
    while served < REPLAY_MESSAGES && t < REPLAY_SECS {
        // Largest priority × wait among the topics with a message; ties go to the higher
        // priority, then to the one served longer ago.
        let mut best: Option<usize> = None;
        for (i, x) in topics.iter().enumerate() {
            if !waiting(x, t) {
                continue;
            }
            let better = match best {
                None => true,
                Some(b) => {
                    let y = &topics[b];
                    let (sx, sy) = (x.priority * (t - x.last), y.priority * (t - y.last));
                    sx > sy
                        || (sx == sy
                            && (x.priority > y.priority
                                || (x.priority == y.priority && x.last < y.last)))
                }
            };
            if better {
                best = Some(i);
            }
        }
        match best {
            Some(i) => {
                let x = &mut topics[i];
                // A full queue has lost its oldest; the next in line goes.
                let made = made(x.hz, t).max(x.taken + 1);
                x.taken = x.taken.max(made.saturating_sub(x.queue)) + 1;
                x.last = t;
                x.sent += 1;
                served += 1;
                t += x.secs_per_msg;
            }
            // Nothing waiting: on to the next publication.
            None => {
                t = topics
                    .iter()
                    .filter(|x| x.hz > 0.0)
                    .map(|x| x.taken as f64 / x.hz)
                    .fold(f64::INFINITY, f64::min);
                if !t.is_finite() {
                    break;
                }
            }
        }
    }
    topics
        .iter()
        .zip(loads)
        .map(|(x, l)| {
            if t > 0.0 {
                (x.sent as f64 / t).min(l.offered_hz.max(0.0))
            } else {
                0.0
            }
        })
        .collect()
}

/// Messages per second of each topic when the link is shared byte for byte among the
/// topics with a message in progress (the uplink's large messages go out a chunk of each
/// in turn): a max-min fair share of `capacity` in bytes, each topic getting what it
/// offers if that is less than an equal share of what is left.
pub fn byte_fair_rates(capacity: f64, loads: &[TopicLoad]) -> Vec<f64> {
    let need = |l: &TopicLoad| l.offered_hz.max(0.0) * l.wire_bytes.max(0.0);
    let mut order: Vec<usize> = (0..loads.len()).collect();
    order.sort_by(|&a, &b| need(&loads[a]).total_cmp(&need(&loads[b])));
    let mut out = vec![0.0; loads.len()];
    let mut left = capacity.max(0.0);
    for (k, &i) in order.iter().enumerate() {
        let l = &loads[i];
        let fair = left / (order.len() - k) as f64;
        let bytes = need(l).min(fair);
        left -= bytes;
        out[i] = if l.wire_bytes > 0.0 {
            bytes / l.wire_bytes
        } else {
            l.offered_hz.max(0.0)
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn load(offered_hz: f64, wire_bytes: f64, priority: f64) -> TopicLoad {
        TopicLoad {
            offered_hz,
            wire_bytes,
            priority,
            queue: 16,
        }
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-6 * b.abs().max(1.0)
    }

    #[test]
    fn one_topic_gets_the_smaller_of_its_rate_and_what_the_link_carries() {
        // ROS Gateway's frame experiment: 509,848-byte pairs over 100 Mbit/s.
        let link = 12_500_000.0;
        let r = receive_rates(link, &[load(60.0, 509_848.0, 1.0)]);
        assert!(close(r[0], link / 509_848.0), "{r:?}");
        let r = receive_rates(link, &[load(10.0, 509_848.0, 1.0)]);
        assert_eq!(r, vec![10.0]);
    }

    #[test]
    fn everything_that_fits_is_predicted_at_its_offered_rate() {
        let loads = [load(10.0, 1000.0, 1.0), load(30.0, 100.0, 0.2)];
        assert_eq!(receive_rates(13_000.0, &loads), vec![10.0, 30.0]);
    }

    fn near(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs().max(1e-9)
    }

    #[test]
    fn saturated_topics_of_equal_priority_get_equal_message_rates() {
        let loads = [load(1000.0, 1000.0, 1.0), load(1000.0, 2000.0, 1.0)];
        let r = receive_rates(30_000.0, &loads);
        assert!(near(r[0], 10.0, 0.01) && near(r[1], 10.0, 0.01), "{r:?}");
    }

    #[test]
    fn a_far_higher_priority_takes_most_of_a_saturated_link() {
        // Equal sizes, priorities 1 and 0.1: the low one goes about once in ten.
        let loads = [load(1000.0, 1000.0, 1.0), load(1000.0, 1000.0, 0.1)];
        let r = receive_rates(30_000.0, &loads);
        assert!(r[0] > 8.0 * r[1] && r[1] > 0.0, "{r:?}");
        assert!(near(r[0] + r[1], 30.0, 0.01), "{r:?}");
    }

    #[test]
    fn a_small_topic_keeps_its_rate_and_leaves_the_rest_to_the_big_one() {
        // Pose at 10 Hz of 200 bytes, a camera wanting 30 × 100 kB over 1 MB/s.
        let loads = [load(10.0, 200.0, 1.0), load(30.0, 100_000.0, 0.5)];
        let r = receive_rates(1_000_000.0, &loads);
        assert!(near(r[0], 10.0, 0.01), "{r:?}");
        assert!(
            near(r[1], (1_000_000.0 - 2000.0) / 100_000.0, 0.02),
            "{r:?}"
        );
    }

    #[test]
    fn byte_fair_sharing_gives_small_needs_their_bytes_and_splits_the_rest() {
        // The simulated robot over 4 Mbit/s: a 50 kB/s camera and a 29 kB/s scan fit an
        // equal share; the point cloud takes the rest.
        let loads = [
            load(10.0, 5000.0, 2.0),
            load(5.0, 159_000.0, 1.0),
            load(10.0, 2900.0, 3.0),
        ];
        let r = byte_fair_rates(492_000.0, &loads);
        assert!(close(r[0], 10.0) && close(r[2], 10.0), "{r:?}");
        assert!(close(r[1], (492_000.0 - 79_000.0) / 159_000.0), "{r:?}");
        // Two saturated topics get equal bytes, whatever their message sizes.
        let r = byte_fair_rates(
            30_000.0,
            &[load(100.0, 1000.0, 1.0), load(100.0, 3000.0, 1.0)],
        );
        assert!(
            close(r[0] * 1000.0, 15_000.0) && close(r[1] * 3000.0, 15_000.0),
            "{r:?}"
        );
    }

    #[test]
    fn a_dead_link_delivers_nothing_and_silent_topics_predict_zero() {
        let loads = [load(5.0, 10.0, 1.0), load(0.0, 10.0, 1.0)];
        assert_eq!(receive_rates(0.0, &loads), vec![0.0, 0.0]);
        assert_eq!(receive_rates(1e9, &loads), vec![5.0, 0.0]);
    }

    #[test]
    fn predictions_never_exceed_the_offer_or_the_link() {
        let mut rng = crate::rng::SplitMix64::new(7);
        for _ in 0..300 {
            let n = 1 + (rng.next_u64() % 6) as usize;
            let loads: Vec<TopicLoad> = (0..n)
                .map(|_| {
                    load(
                        (rng.next_u64() % 100) as f64,
                        1.0 + (rng.next_u64() % 50_000) as f64,
                        0.1 + (rng.next_u64() % 10) as f64 / 10.0,
                    )
                })
                .collect();
            let cap = (rng.next_u64() % 2_000_000) as f64;
            let r = receive_rates(cap, &loads);
            let bytes: f64 = r.iter().zip(&loads).map(|(r, l)| r * l.wire_bytes).sum();
            let need: f64 = loads.iter().map(|l| l.offered_hz * l.wire_bytes).sum();
            // What fits goes whole; a link that cannot carry everything is used to the
            // full and no further.
            let expect = need.min(cap);
            assert!(
                bytes <= expect * 1.001 && (need <= cap || bytes >= cap * 0.97),
                "{loads:?} {cap}: {bytes} vs {expect}"
            );
            for (r, l) in r.iter().zip(&loads) {
                assert!(*r <= l.offered_hz + 1e-9, "{loads:?}");
            }
        }
    }
}
