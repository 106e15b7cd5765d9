//! Criterion benches of the per-message hot paths: AFR enqueue, scheduler pick-next, and
//! the queue policies. Results and the exact command are in docs/benchmarks/qos.md.

use std::hint::black_box;
use std::sync::Arc;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fleetlink_qos::afr::Afr;
use fleetlink_qos::{Nanos, Policy, Scheduler, SchedulerConfig, TopicId, TopicQos, TopicQueue};

/// A payload shared like the hub's `Arc<Message>`; never cloned by the queues.
fn payload() -> Arc<Vec<u8>> {
    Arc::new(vec![0u8; 1024])
}

fn afr_enqueue(c: &mut Criterion) {
    let mut group = c.benchmark_group("afr_enqueue");
    for l in [64usize, 4096] {
        group.bench_with_input(BenchmarkId::from_parameter(l), &l, |b, &l| {
            // Steady state of an outage: the queue is full and thinning; items dropped by
            // the policy are handed back and released, as the caller would.
            let mut afr = Afr::new(l);
            let p = payload();
            for _ in 0..l * 4 {
                drop(afr.push(p.clone()));
            }
            b.iter_batched_ref(
                || p.clone(),
                |item| drop(black_box(afr.push(std::mem::replace(item, Arc::clone(&p))))),
                criterion::BatchSize::SmallInput,
            );
        });
    }
    group.finish();
}

fn queue_push_pop(c: &mut Criterion) {
    let mut group = c.benchmark_group("queue_push_pop");
    for policy in [
        Policy::DropOldest,
        Policy::Latest,
        Policy::Random,
        Policy::Afr,
    ] {
        let queue = if policy == Policy::Latest { 1 } else { 64 };
        let qos = TopicQos {
            policy,
            queue,
            ..TopicQos::default()
        };
        group.bench_function(policy.as_str(), |b| {
            let mut q = TopicQueue::new(&qos);
            let p = payload();
            for _ in 0..queue {
                let _ = q.push(p.clone(), Nanos::ZERO);
            }
            let mut t = 0u64;
            b.iter(|| {
                t += 1;
                drop(black_box(q.push(Arc::clone(&p), Nanos(t))));
                if t.is_multiple_of(2) {
                    drop(black_box(q.pop(Nanos(t))));
                }
            });
        });
    }
    group.finish();
}

/// 1,000 topics, all with a message waiting; each iteration offers one message and picks
/// the next one to send (the steady state of a saturated uplink).
fn scheduler_pick_next(c: &mut Criterion) {
    let mut group = c.benchmark_group("scheduler_pick_next_1000_topics");
    for levels in [8u32, 1000] {
        group.bench_with_input(
            BenchmarkId::new("priority_levels", levels),
            &levels,
            |b, &levels| {
                let mut s = Scheduler::new(SchedulerConfig {
                    max_in_flight: usize::MAX,
                    ..SchedulerConfig::default()
                });
                let p = payload();
                for i in 0..1000u32 {
                    let qos = TopicQos {
                        priority: 1.0 + (i % levels) as f32,
                        policy: Policy::Latest,
                        queue: 1,
                        ..TopicQos::default()
                    };
                    s.add_topic(TopicId(i), qos).unwrap();
                    let _ = s.offer(TopicId(i), p.clone(), Nanos(u64::from(i)));
                }
                let mut now = 1_000_000u64;
                b.iter(|| {
                    now += 1_000;
                    let (topic, item) = s.poll_next(Nanos(now)).expect("a topic is ready");
                    s.on_acked(1, Nanos(now));
                    drop(black_box(s.offer(topic, item, Nanos(now))));
                });
            },
        );
    }
    group.finish();
}

criterion_group!(benches, afr_enqueue, queue_push_pop, scheduler_pick_next);
criterion_main!(benches);
