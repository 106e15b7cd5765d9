//! Cost of an authorization check on the publish path, with 100 rules.
//!
//! - `decide_100_rules/cache_hit`: `Access::decide` on a name already decided — the
//!   steady state of a publisher or subscriber (atomic load + hash lookup).
//! - `decide_100_rules/cache_miss`: `Access::decide` on a name never seen (evaluates the
//!   rules that apply to the identity, then caches).
//! - `decide_100_rules/uncached_allow` / `uncached_deny`: `Authorizer::decide`, which
//!   filters all 100 rules by subject and runs the matching regexes each time; the deny
//!   case matches nothing, so every applicable regex runs.

use std::hint::black_box;
use std::sync::Arc;

use criterion::{Criterion, criterion_group, criterion_main};
use fleetlink_auth::acl::{
    AclDefaults, Authorizer, Operation, Rule, RuleId, StoredRule, import_yaml,
};
use fleetlink_auth::{ConnInfo, GroupName, Identity, IdentityKind, UserName};

fn rules() -> Vec<StoredRule> {
    let mut yaml = String::from("rules:\n");
    for i in 0..100 {
        let (subject, names, ops) = match i % 4 {
            0 => (
                format!("{{group: team{}}}", i % 10),
                format!("/r{i}/.*"),
                "[subscribe, publish]",
            ),
            1 => (
                format!("{{robot: r{i}}}"),
                format!("/fleet/topic{i}"),
                "[subscribe]",
            ),
            2 => (
                format!("{{user: u{i}}}"),
                format!("/r[0-9]+/cam{i}/.*"),
                "[subscribe]",
            ),
            _ => (
                "any_user".to_owned(),
                format!("/shared/(a|b)/t{i}"),
                "[subscribe]",
            ),
        };
        yaml.push_str(&format!(
            "  - {{subject: {subject}, names: \"{names}\", ops: {ops}}}\n"
        ));
    }
    import_yaml(&yaml)
        .expect("bench rules parse")
        .into_iter()
        .enumerate()
        .map(|(i, rule): (usize, Rule)| StoredRule {
            id: RuleId(i as i64),
            rule,
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let authz = Arc::new(Authorizer::new(rules(), AclDefaults::default()));
    let identity = Identity {
        kind: IdentityKind::User {
            name: UserName::new("alice").expect("name"),
            groups: vec![
                GroupName::new("team0").expect("group"),
                GroupName::new("team4").expect("group"),
            ],
        },
        source: ConnInfo::new([203, 0, 113, 5].into()),
        client_ip: [203, 0, 113, 5].into(),
    };
    let allowed = "/r40/cmd_vel";
    let denied = "/r41/cmd_vel";
    assert!(authz.decide(&identity, allowed, Operation::Publish).allowed);
    assert!(!authz.decide(&identity, denied, Operation::Publish).allowed);

    let mut g = c.benchmark_group("decide_100_rules");
    let mut access = authz.access(identity.clone());
    access.decide(allowed, Operation::Publish);
    g.bench_function("cache_hit", |b| {
        b.iter(|| access.decide(black_box(allowed), Operation::Publish))
    });

    let names: Vec<String> = (0..1_000_000)
        .map(|i| format!("/r{}/topic{i}", i % 200))
        .collect();
    let mut fresh = authz.access(identity.clone());
    let mut i = 0;
    g.bench_function("cache_miss", |b| {
        b.iter(|| {
            i = (i + 1) % names.len();
            fresh.decide(black_box(&names[i]), Operation::Publish)
        })
    });
    g.bench_function("uncached_allow", |b| {
        b.iter(|| authz.decide(&identity, black_box(allowed), Operation::Publish))
    });
    g.bench_function("uncached_deny", |b| {
        b.iter(|| authz.decide(&identity, black_box(denied), Operation::Publish))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
