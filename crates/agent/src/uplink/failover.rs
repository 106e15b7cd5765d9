//! Where and when the uplink connects next: which hub of its list, after what wait.
//!
//! The policy is sticky. The agent stays on the hub it is connected to; when that session
//! ends it tries the same hub once more after a short jittered wait (a robot's link blips
//! far more often than a hub dies). An attempt that fails moves on to the next hub of the
//! list at once, so a robot whose hub was killed is on the next one within a fraction of a
//! second. Waiting happens per full round through the list: only when every hub has failed
//! once in a row does the agent wait, as [`Backoff`] says for what the round's failures
//! show. A hub that comes back does not pull its robots back: they stay where they are
//! until their hub fails, so a restarted hub is not hit by a whole fleet at once.
//!
//! Sans-IO: no clock and no socket, only [`jitter`]'s randomness, so the tests drive it
//! with made-up failures.

use std::time::Duration;

use super::Failure;

/// Longest wait between attempts while the robot's own link is down.
const LINK_RETRY_MAX: Duration = Duration::from_millis(500);
/// Wait between attempts while the robot has no route at all (interface down): such an
/// attempt fails in the local kernel without sending anything, so it is free to repeat.
const NO_ROUTE_RETRY: Duration = Duration::from_millis(100);
/// Wait between attempts after a permanent failure (credentials or certificate refused):
/// nothing changes by itself, but an operator may fix the hub side, so the robot comes
/// back within this without a restart.
const PERMANENT_RETRY: Duration = Duration::from_secs(60);

/// The hub to try and the backoff state, across attempts.
#[derive(Debug)]
pub(super) struct Failover {
    hubs: usize,
    /// Index of the hub the next attempt goes to.
    current: usize,
    /// Attempts failed in a row since the last session or the last full round.
    failed: usize,
    round: Round,
    backoff: Backoff,
}

/// What the failed attempts of one round through the list said.
#[derive(Debug, Default)]
struct Round {
    /// A hub answered and failed or was busy: the robot's own link works.
    hub: bool,
    /// A hub refused for good (credentials, certificate): the robot's link works too.
    permanent: bool,
    /// A connect timed out or the host was unreachable.
    link: bool,
    /// An attempt found no route at all.
    no_route: bool,
    /// The longest `Retry-After` a hub of this round asked for.
    retry_after: Option<Duration>,
}

impl Failover {
    /// A policy over `hubs` URLs (at least one is assumed), starting with the first.
    pub(super) fn new(hubs: usize, backoff: Backoff) -> Failover {
        Failover {
            hubs: hubs.max(1),
            current: 0,
            failed: 0,
            round: Round::default(),
            backoff,
        }
    }

    /// Index of the hub to try next.
    pub(super) fn hub(&self) -> usize {
        self.current
    }

    /// A session that was up has ended: the same hub again, almost at once.
    pub(super) fn after_session(&mut self) -> Duration {
        self.failed = 0;
        self.round = Round::default();
        self.backoff.after_session()
    }

    /// An attempt failed: the next hub at once, or, when this completed a round through
    /// the list, the round's wait, after which the next round starts where this one did.
    pub(super) fn after_failure(&mut self, failure: &Failure) -> Duration {
        let r = &mut self.round;
        match failure {
            Failure::NoRoute(_) => r.no_route = true,
            Failure::Link(_) => r.link = true,
            Failure::Hub { retry_after, .. } => {
                r.hub = true;
                r.retry_after = r.retry_after.max(*retry_after);
            }
            Failure::Permanent(_) => r.permanent = true,
        }
        self.current = (self.current + 1) % self.hubs;
        self.failed += 1;
        if self.failed < self.hubs {
            return Duration::ZERO;
        }
        self.failed = 0;
        let round = std::mem::take(&mut self.round);
        // A hub that answered shows the robot's link works: the hubs are what failed, so
        // back off as for a failing hub (a fleet must not stampede them), whatever the
        // others of the round did. Only a round of nothing but permanent refusals waits
        // as long as those deserve.
        if round.permanent && !(round.hub || round.link || round.no_route) {
            jitter(PERMANENT_RETRY)
        } else if round.hub || round.permanent {
            self.backoff.after_hub_failure(round.retry_after)
        } else if round.link {
            self.backoff.after_link_failure()
        } else {
            jitter(NO_ROUTE_RETRY)
        }
    }
}

/// When to try again: fast while the robot's own link is down, exponential with full
/// jitter while the hubs refuse or fail (see the module docs). Sans-IO: tests drive it.
#[derive(Debug)]
pub(super) struct Backoff {
    initial: Duration,
    max: Duration,
    hub: Duration,
    link: Duration,
}

impl Backoff {
    pub(super) fn new(initial: Duration, max: Duration) -> Backoff {
        Backoff {
            initial,
            max: max.max(initial),
            hub: initial,
            link: initial.min(LINK_RETRY_MAX),
        }
    }

    /// A session that was up has ended: start over, almost at once.
    fn after_session(&mut self) -> Duration {
        self.hub = self.initial;
        self.link = self.initial.min(LINK_RETRY_MAX);
        jitter(self.initial.min(LINK_RETRY_MAX))
    }

    fn after_link_failure(&mut self) -> Duration {
        let w = jitter(self.link);
        self.link = (self.link * 2).min(LINK_RETRY_MAX);
        w
    }

    fn after_hub_failure(&mut self, retry_after: Option<Duration>) -> Duration {
        let w = jitter(self.hub);
        self.hub = (self.hub * 2).min(self.max);
        match retry_after {
            // Spread a fleet told the same time over half of it again.
            Some(at_least) => w.max(at_least + jitter(at_least / 2)),
            None => w,
        }
    }
}

/// Full jitter in `[d/2, d]`, so a fleet does not retry in step.
fn jitter(d: Duration) -> Duration {
    d.mul_f64(0.5 + fastrand::f64() * 0.5)
}

#[cfg(test)]
mod backoff_tests {
    use super::*;

    #[test]
    fn a_dead_robot_link_is_retried_within_half_a_second() {
        let mut b = Backoff::new(Duration::from_millis(250), Duration::from_secs(10));
        for _ in 0..50 {
            assert!(b.after_link_failure() <= LINK_RETRY_MAX);
        }
    }

    #[test]
    fn a_failing_hub_backs_off_to_the_maximum_and_a_session_resets_it() {
        let mut b = Backoff::new(Duration::from_millis(250), Duration::from_secs(10));
        let waits: Vec<Duration> = (0..10).map(|_| b.after_hub_failure(None)).collect();
        assert!(waits[0] <= Duration::from_millis(250));
        assert!(waits[9] >= Duration::from_secs(5), "{waits:?}");
        assert!(waits.iter().all(|w| *w <= Duration::from_secs(10)));
        assert!(b.after_session() <= LINK_RETRY_MAX);
        assert!(b.after_hub_failure(None) <= Duration::from_millis(250));
    }

    #[test]
    fn retry_after_is_a_floor_spread_by_jitter() {
        let mut b = Backoff::new(Duration::from_millis(250), Duration::from_secs(10));
        let waits: Vec<Duration> = (0..200)
            .map(|_| {
                let mut b2 = Backoff::new(Duration::from_millis(250), Duration::from_secs(10));
                b2.after_hub_failure(Some(Duration::from_secs(4)))
            })
            .collect();
        assert!(waits.iter().all(|w| *w >= Duration::from_secs(4)));
        assert!(waits.iter().all(|w| *w <= Duration::from_secs(6)));
        let distinct: std::collections::HashSet<_> = waits.iter().collect();
        assert!(distinct.len() > 100, "attempts must not be in step");
        assert!(b.after_hub_failure(None) <= Duration::from_millis(250));
    }
}

/// Issue 38 item 4: failover between hubs.
#[cfg(test)]
mod failover_tests {
    use super::*;

    fn policy(hubs: usize) -> Failover {
        Failover::new(
            hubs,
            Backoff::new(Duration::from_millis(250), Duration::from_secs(10)),
        )
    }

    fn refused() -> Failure {
        Failure::hub("cannot connect: connection refused".into())
    }

    fn timed_out() -> Failure {
        Failure::Link("connecting timed out".into())
    }

    /// Runs `failures` in turn: (hub each was made to, wait after it).
    fn run(f: &mut Failover, failures: &[Failure]) -> Vec<(usize, Duration)> {
        failures
            .iter()
            .map(|e| {
                let hub = f.hub();
                (hub, f.after_failure(e))
            })
            .collect()
    }

    #[test]
    fn issue38_a_dead_hub_is_retried_once_then_the_next_is_tried_at_once() {
        let mut f = policy(3);
        assert_eq!(f.hub(), 0, "the first attempt goes to the first hub");
        // Connected to hub 0; the session ends (kill -9): the same hub after a short wait.
        let wait = f.after_session();
        assert!(wait <= LINK_RETRY_MAX, "{wait:?}");
        assert_eq!(f.hub(), 0);
        // It refuses: hub 1 with no wait at all.
        assert_eq!(f.after_failure(&refused()), Duration::ZERO);
        assert_eq!(f.hub(), 1);
        // Hub 1 takes the robot, and stays its hub through session ends.
        for _ in 0..5 {
            f.after_session();
            assert_eq!(
                f.hub(),
                1,
                "sticky: a session's end does not move the robot"
            );
        }
    }

    #[test]
    fn issue38_a_hub_that_comes_back_does_not_pull_the_robot_back() {
        let mut f = policy(2);
        f.after_session();
        f.after_failure(&refused()); // hub 0 died
        assert_eq!(f.hub(), 1);
        // Hub 0 is back; nothing about the robot's session on hub 1 consults it.
        for _ in 0..100 {
            f.after_session();
            assert_eq!(f.hub(), 1);
        }
        // Only when hub 1 fails (and its retry too) does the robot go back to hub 0.
        assert_eq!(f.after_failure(&refused()), Duration::ZERO);
        assert_eq!(f.hub(), 0);
    }

    #[test]
    fn issue38_backoff_applies_per_full_round_through_the_list() {
        let mut f = policy(3);
        let attempts = run(&mut f, &[refused(), refused(), refused()]);
        assert_eq!(
            attempts.iter().map(|(h, _)| *h).collect::<Vec<_>>(),
            [0, 1, 2]
        );
        assert_eq!(attempts[0].1, Duration::ZERO);
        assert_eq!(attempts[1].1, Duration::ZERO);
        assert!(attempts[2].1 > Duration::ZERO && attempts[2].1 <= Duration::from_millis(250));
        assert_eq!(f.hub(), 0, "the next round starts over at the first hub");
        // Round after round the wait doubles (full jitter: in [d/2, d]) up to the maximum.
        let mut ends = Vec::new();
        for _ in 0..10 {
            let waits = run(&mut f, &[refused(), refused(), refused()]);
            assert!(waits[..2].iter().all(|(_, w)| w.is_zero()), "{waits:?}");
            ends.push(waits[2].1);
        }
        assert!(ends[0] >= Duration::from_millis(250) && ends[0] <= Duration::from_millis(500));
        assert!(ends[9] >= Duration::from_secs(5), "{ends:?}");
        assert!(
            ends.iter().all(|w| *w <= Duration::from_secs(10)),
            "{ends:?}"
        );
        // A session anywhere resets it.
        f.after_session();
        let waits = run(&mut f, &[refused(), refused(), refused()]);
        assert!(waits[2].1 <= Duration::from_millis(250), "{waits:?}");
    }

    #[test]
    fn issue38_one_hub_behaves_as_before_the_list() {
        let mut f = policy(1);
        let waits: Vec<Duration> = (0..10).map(|_| f.after_failure(&refused())).collect();
        assert!(
            waits.iter().all(|w| !w.is_zero()),
            "every attempt is a round"
        );
        assert!(waits[0] <= Duration::from_millis(250));
        assert!(waits[9] >= Duration::from_secs(5), "{waits:?}");
        assert_eq!(f.hub(), 0);
        let w = f.after_failure(&Failure::NoRoute("no route".into()));
        assert!(w <= NO_ROUTE_RETRY, "{w:?}");
    }

    #[test]
    fn issue38_retry_after_is_honoured_at_the_end_of_the_round() {
        let busy = Failure::Hub {
            reason: "the hub answered HTTP 503".into(),
            retry_after: Some(Duration::from_secs(4)),
        };
        for _ in 0..50 {
            let mut f = policy(2);
            // Hub 0 asks for 4 s; hub 1 is tried at once all the same.
            assert_eq!(f.after_failure(&busy), Duration::ZERO);
            let w = f.after_failure(&refused());
            assert!(
                w >= Duration::from_secs(4) && w <= Duration::from_secs(6),
                "{w:?}"
            );
        }
    }

    #[test]
    fn issue38_the_round_waits_by_whose_fault_its_failures_show() {
        // Nothing reachable (the robot's link is down): retried fast.
        for _ in 0..50 {
            let mut f = policy(2);
            let w = run(&mut f, &[timed_out(), timed_out()]);
            assert!(w[1].1 <= LINK_RETRY_MAX, "{w:?}");
            let w = run(
                &mut f,
                &[Failure::NoRoute("a".into()), Failure::NoRoute("b".into())],
            );
            assert!(w[1].1 <= NO_ROUTE_RETRY, "{w:?}");
        }
        // One hub answered, so the robot's link works: the hubs back off.
        let mut f = policy(2);
        for _ in 0..10 {
            run(&mut f, &[refused(), timed_out()]);
        }
        let w = run(&mut f, &[timed_out(), refused()]);
        assert!(w[1].1 >= Duration::from_secs(5), "{w:?}");
        // Every hub refused for good (credentials): the slow permanent retry.
        let mut f = policy(2);
        let bad = || Failure::Permanent("token refused".into());
        let w = run(&mut f, &[bad(), bad()]);
        assert!(w[1].1 >= PERMANENT_RETRY / 2, "{w:?}");
        // One refused for good, the other is merely down: retried as a failing hub.
        let mut f = policy(2);
        let w = run(&mut f, &[bad(), refused()]);
        assert!(w[1].1 <= Duration::from_millis(250), "{w:?}");
        let mut f = policy(2);
        let w = run(&mut f, &[refused(), bad()]);
        assert!(w[1].1 <= Duration::from_millis(250), "{w:?}");
    }
}
