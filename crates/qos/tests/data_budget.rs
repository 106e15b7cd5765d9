//! A robot's data budget in the scheduler, on virtual time: the link holds the budget's
//! rate over a minute, protected topics keep theirs, and the lowest priorities give way
//! first (thinned, then paused).

use fleetlink_qos::{
    BudgetConfig, DataBudget, Nanos, Policy, Scheduler, SchedulerConfig, TopicId, TopicQos,
};

use crate::util::Msg;

struct Source {
    id: TopicId,
    priority: f32,
    hz: u64,
    len: usize,
}

/// Publishes every source at its rate for `secs`, sending whatever the scheduler lets go
/// every millisecond (acknowledged at once, bytes taken from the budget as they leave).
/// Returns, per source, the messages published and sent.
fn run(
    budget: Option<BudgetConfig>,
    sources: &[Source],
    secs: u64,
) -> (Vec<(u64, u64)>, u64, Scheduler<Msg>) {
    let mut s: Scheduler<Msg> = Scheduler::new(SchedulerConfig::default());
    for src in sources {
        let qos = TopicQos {
            priority: src.priority,
            policy: Policy::DropOldest,
            queue: 4,
            ..TopicQos::default()
        };
        s.add_topic(src.id, qos).unwrap();
    }
    s.set_data_budget(budget.map(|b| DataBudget::new(b, Nanos::ZERO)));
    let mut counts = vec![(0u64, 0u64); sources.len()];
    let mut bytes = 0u64;
    for ms in 0..secs * 1000 {
        let now = Nanos::from_millis(ms);
        for (i, src) in sources.iter().enumerate() {
            if ms % (1000 / src.hz) == 0 {
                counts[i].0 += 1;
                let _ = s.offer(
                    src.id,
                    Msg {
                        seq: ms,
                        len: src.len,
                        born: ms,
                    },
                    now,
                );
            }
        }
        while let Some((topic, m)) = s.poll_next(now) {
            s.on_acked(1, now);
            // Counted as the agent counts it: with its headers on the wire.
            let cost = fleetlink_qos::budget::wire_cost(m.len);
            s.debit_data(cost, now);
            bytes += cost as u64;
            let i = sources.iter().position(|x| x.id == topic).unwrap();
            counts[i].1 += 1;
        }
    }
    (counts, bytes, s)
}

fn fleet() -> Vec<Source> {
    vec![
        Source {
            id: TopicId(1),
            priority: 10.0,
            hz: 50,
            len: 120,
        }, // cmd_vel echo
        Source {
            id: TopicId(2),
            priority: 8.0,
            hz: 20,
            len: 700,
        }, // odometry
        Source {
            id: TopicId(3),
            priority: 3.0,
            hz: 10,
            len: 6_000,
        }, // scan
        Source {
            id: TopicId(4),
            priority: 1.0,
            hz: 10,
            len: 150_000,
        }, // point cloud
    ]
}

#[test]
fn a_rate_budget_holds_within_ten_percent_and_protected_topics_keep_their_rate() {
    let limit = 60_000.0;
    let budget = BudgetConfig {
        max_bytes_per_sec: Some(limit),
        bytes_per_day: None,
        protect_priority: 10.0,
    };
    let (unlimited, free_bytes, _) = run(None, &fleet(), 60);
    assert!(
        free_bytes as f64 / 60.0 > 10.0 * limit,
        "the fleet wants far more than the budget"
    );
    let (counts, bytes, s) = run(Some(budget), &fleet(), 60);
    let rate = bytes as f64 / 60.0;
    assert!(
        (rate - limit).abs() <= 0.10 * limit,
        "held {rate:.0} B/s for a {limit} B/s budget"
    );
    // The protected topic keeps every message; so does odometry (priority 8), which the
    // budget covers: the budget goes to the highest priorities first.
    assert_eq!(counts[0].1, counts[0].0, "cmd_vel: {:?}", counts[0]);
    assert!(
        counts[1].1 as f64 >= 0.99 * counts[1].0 as f64,
        "odometry: {:?}",
        counts[1]
    );
    // The lowest priority gives way most: its share of what it published is the smallest.
    let share = |i: usize| counts[i].1 as f64 / counts[i].0 as f64;
    assert!(
        share(3) < share(2) && share(2) < share(1),
        "shares {:?}",
        (0..4).map(share).collect::<Vec<_>>()
    );
    assert!(
        unlimited[3].1 > 10 * counts[3].1,
        "the cloud is thinned: {:?} vs {:?}",
        counts[3],
        unlimited[3]
    );
    // The thinned topics are the unprotected ones that waited.
    let thinned: Vec<TopicId> = s.thinned_since(Nanos::from_secs(59)).collect();
    assert!(
        thinned.contains(&TopicId(4)) && !thinned.contains(&TopicId(1)),
        "{thinned:?}"
    );
}

#[test]
fn protected_traffic_alone_over_the_budget_still_flows() {
    let budget = BudgetConfig {
        max_bytes_per_sec: Some(2_000.0),
        bytes_per_day: None,
        protect_priority: 8.0,
    };
    let (counts, bytes, _) = run(Some(budget), &fleet(), 20);
    // cmd_vel and odometry (6 kB/s + 14 kB/s) are both protected here: all sent, though
    // that is ten times the budget; the rest is paused.
    assert_eq!(counts[0].1, counts[0].0);
    assert_eq!(counts[1].1, counts[1].0);
    assert!(counts[3].1 <= 1, "the cloud is paused: {:?}", counts[3]);
    assert!(bytes as f64 / 20.0 > 2_000.0);
}
