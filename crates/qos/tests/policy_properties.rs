//! Property tests over every drop policy: bounds, no loss for no-drop, order, accounting.

use fleetlink_qos::{Nanos, Policy, Push, TopicQos, TopicQueue};
use proptest::prelude::*;

const POLICIES: [Policy; 6] = [
    Policy::Fifo,
    Policy::Latest,
    Policy::DropOldest,
    Policy::DropNewest,
    Policy::Random,
    Policy::Afr,
];

/// A random interleaving of pushes (true) and pops (false).
fn ops() -> impl Strategy<Value = Vec<bool>> {
    prop::collection::vec(prop::bool::weighted(0.7), 0..400)
}

fn queue(policy: Policy, len: usize, seed: u64) -> TopicQueue<u64> {
    let queue = if policy == Policy::Latest { 1 } else { len };
    TopicQueue::with_seed(
        &TopicQos {
            policy,
            queue,
            ..TopicQos::default()
        },
        seed,
    )
}

proptest! {
    #[test]
    fn queues_never_exceed_their_bound_and_account_for_every_item(
        p in 0..POLICIES.len(), len in 1usize..40, seed: u64, ops in ops()
    ) {
        let policy = POLICIES[p];
        let mut q = queue(policy, len, seed);
        let (mut next, mut popped, mut dropped, mut refused) = (0u64, Vec::new(), Vec::new(), Vec::new());
        for push in ops {
            if push {
                match q.push(next, Nanos(next)) {
                    Push::Queued => {}
                    Push::Dropped { item, .. } => dropped.push(item),
                    Push::Backpressure(item) => refused.push(item),
                }
                next += 1;
            } else if let Some(m) = q.pop(Nanos(next)) {
                popped.push(m);
            }
            prop_assert!(q.len() <= q.capacity());
        }
        let queued = q.len();
        popped.extend(std::iter::from_fn(|| q.pop(Nanos(next))));
        // Every pushed item is exactly one of: delivered, dropped, refused.
        let mut all: Vec<u64> = popped.iter().chain(&dropped).chain(&refused).copied().collect();
        all.sort_unstable();
        prop_assert_eq!(all, (0..next).collect::<Vec<_>>());
        // Delivery keeps arrival order for every policy.
        prop_assert!(popped.windows(2).all(|w| w[0] < w[1]));
        prop_assert!(queued <= len);
        if policy == Policy::Fifo {
            prop_assert!(dropped.is_empty(), "fifo never drops");
        } else {
            prop_assert!(refused.is_empty(), "only fifo pushes back");
        }
    }

    #[test]
    fn fifo_with_a_retrying_source_delivers_everything_in_order(len in 1usize..10, ops in ops()) {
        let mut q = queue(Policy::Fifo, len, 0);
        let (mut next, mut pending, mut out) = (0u64, None, Vec::new());
        for push in ops {
            if push {
                let item = pending.take().unwrap_or_else(|| { next += 1; next - 1 });
                if let Push::Backpressure(item) = q.push(item, Nanos::ZERO) {
                    pending = Some(item);
                }
            } else if let Some(m) = q.pop(Nanos::ZERO) {
                out.push(m);
            }
        }
        out.extend(std::iter::from_fn(|| q.pop(Nanos::ZERO)));
        out.extend(pending);
        prop_assert_eq!(out, (0..next).collect::<Vec<_>>());
    }

    #[test]
    fn afr_keeps_the_newest_accepted_and_thins_evenly_during_an_outage(len in 2usize..64, t in 1u64..3000) {
        let mut q = queue(Policy::Afr, len, 0);
        for m in 1..=t {
            let _ = q.push(m, Nanos::ZERO);
        }
        let kept: Vec<u64> = std::iter::from_fn(|| q.pop(Nanos::ZERO)).collect();
        prop_assert_eq!(kept.len() as u64, t.min(len as u64));
        // Gaps between kept messages differ by at most a factor of two.
        let gaps: Vec<u64> = kept.windows(2).map(|w| w[1] - w[0]).collect();
        if let (Some(min), Some(max)) = (gaps.iter().min(), gaps.iter().max()) {
            prop_assert!(*max <= 2 * *min, "{:?}", kept);
        }
    }
}

proptest! {
    /// A topic given a new QoS while it flows (a runtime configuration change) loses
    /// nothing unaccounted: every offered message is sent, dropped at its offer, or
    /// dropped by the change, once; what is sent keeps its order; and the queue holds
    /// its new bound.
    #[test]
    fn a_new_qos_accounts_for_every_message_a_topic_queued(
        p0 in 0..POLICIES.len(), len0 in 1usize..20, p1 in 0..POLICIES.len(), len1 in 1usize..20,
        prio in prop::sample::select(vec![0.5f32, 1.0, 5.0]), before in 0u64..60, after in 0u64..60
    ) {
        use fleetlink_qos::{Scheduler, SchedulerConfig, TopicId};
        let qos = |p: usize, len: usize, priority: f32| TopicQos {
            policy: POLICIES[p],
            queue: if POLICIES[p] == Policy::Latest { 1 } else { len },
            priority,
            ..TopicQos::default()
        };
        let mut s: Scheduler<crate::util::Msg> = Scheduler::new(SchedulerConfig {
            max_in_flight: 1 << 20,
            ..SchedulerConfig::default()
        });
        let (a, other) = (TopicId(1), TopicId(2));
        s.add_topic(a, qos(p0, len0, 1.0)).unwrap();
        s.add_topic(other, qos(2, 4, 1.0)).unwrap();
        let msg = |seq| crate::util::Msg { seq, len: 10, born: seq };
        let mut gone = Vec::new();
        let offer = |s: &mut Scheduler<crate::util::Msg>, gone: &mut Vec<u64>, seq: u64| {
            match s.offer(a, msg(seq), Nanos(seq)) {
                Push::Queued => {}
                Push::Dropped { item, .. } | Push::Backpressure(item) => gone.push(item.seq),
            }
        };
        for seq in 0..before {
            offer(&mut s, &mut gone, seq);
        }
        let _ = s.offer(other, msg(0), Nanos(0));
        let dropped = s.set_qos(a, qos(p1, len1, prio), Nanos(before)).unwrap();
        let bound = if POLICIES[p1] == Policy::Latest { 1 } else { len1 };
        prop_assert!(s.queued(a) <= bound);
        gone.extend(dropped.iter().map(|m| m.seq));
        for seq in before..before + after {
            offer(&mut s, &mut gone, seq);
        }
        let mut sent = Vec::new();
        while let Some((t, m)) = s.poll_next(Nanos(before + after)) {
            if t == a {
                sent.push(m.seq);
            }
        }
        prop_assert!(sent.windows(2).all(|w| w[0] < w[1]), "sent out of order: {:?}", sent);
        let mut all: Vec<u64> = sent.iter().chain(&gone).copied().collect();
        all.sort_unstable();
        prop_assert_eq!(all, (0..before + after).collect::<Vec<_>>());
    }
}
