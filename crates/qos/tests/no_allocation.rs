//! The steady-state message path allocates nothing: queue push/pop for every policy, the
//! scheduler's offer/pick/ack, and the link estimator's per-frame work. (A counting
//! global allocator from `allocation-counter` measures each closure; it counts this
//! thread's allocations only.)

use std::sync::Arc;

use fleetlink_qos::{
    LinkConfig, LinkEstimator, Nanos, Policy, Scheduler, SchedulerConfig, TopicId, TopicQos,
    TopicQueue,
};

const POLICIES: [Policy; 6] = [
    Policy::Fifo,
    Policy::Latest,
    Policy::DropOldest,
    Policy::DropNewest,
    Policy::Random,
    Policy::Afr,
];

#[test]
fn queue_push_and_pop_do_not_allocate_once_warm() {
    let payload = Arc::new(vec![0u8; 100]);
    for policy in POLICIES {
        let queue = if policy == Policy::Latest { 1 } else { 32 };
        let mut q = TopicQueue::new(&TopicQos {
            policy,
            queue,
            ..TopicQos::default()
        });
        let mut t = 0;
        let mut run = |n: u64| {
            for _ in 0..n {
                t += 1;
                drop(q.push(Arc::clone(&payload), Nanos(t)));
                if t % 3 == 0 {
                    drop(q.pop(Nanos(t)));
                }
            }
        };
        run(1000);
        let info = allocation_counter::measure(|| run(10_000));
        assert_eq!(info.count_total, 0, "{policy:?}");
    }
}

#[test]
fn scheduler_offer_pick_ack_does_not_allocate_once_warm() {
    let payload = Arc::new(vec![0u8; 100]);
    let mut s = Scheduler::new(SchedulerConfig {
        max_in_flight: 8,
        ..SchedulerConfig::default()
    });
    for i in 0..100u32 {
        let qos = if i % 10 == 0 {
            TopicQos {
                no_drop: true,
                policy: Policy::Fifo,
                queue: 8,
                ..TopicQos::default()
            }
        } else {
            let policy = POLICIES[(i % 5 + 1) as usize];
            let queue = if policy == Policy::Latest { 1 } else { 16 };
            TopicQos {
                priority: 1.0 + (i % 4) as f32,
                policy,
                queue,
                ..TopicQos::default()
            }
        };
        s.add_topic(TopicId(i), qos).unwrap();
    }
    s.set_rate_budget(Some(1e9), Nanos::ZERO);
    let mut now = 0u64;
    let mut run = |n: u32| {
        for k in 0..n {
            now += 10_000;
            drop(s.offer(TopicId(k % 100), Arc::clone(&payload), Nanos(now)));
            if let Some((_, item)) = s.poll_next(Nanos(now)) {
                drop(item);
                s.on_acked(1, Nanos(now));
            }
        }
    };
    run(10_000);
    let info = allocation_counter::measure(|| run(10_000));
    assert_eq!(info.count_total, 0);
}

#[test]
fn link_estimator_per_frame_work_does_not_allocate_once_warm() {
    let mut est = LinkEstimator::new(LinkConfig::default());
    let mut now = Nanos::ZERO;
    let mut run = |ms: u64| {
        for _ in 0..ms {
            now += Nanos::from_millis(1);
            if let Some(p) = est.poll_probe(now, true) {
                est.handle_echo(p.id, now, now + Nanos::from_millis(1));
            }
            est.handle_ack(1000, now.saturating_sub(Nanos::from_millis(30)), now);
        }
    };
    run(5_000);
    let info = allocation_counter::measure(|| run(5_000));
    assert_eq!(info.count_total, 0);
}
