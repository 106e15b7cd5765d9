//! The hub's gate: one name rule for every decision, hub-only names, and identities other
//! hubs vouch for.

use std::sync::Arc;

use fleetlink_auth::store::Store;
use fleetlink_auth::{AclDefaults, AuthPolicy, Identity, IdentityKind, Security};
use fleetlink_relay::gate::{Caller, Gate, Op};
use proptest::prelude::*;

use super::*;
use crate::registry::Registry;

const RULES: &str = r#"
rules:
  - subject: {user: alice}
    names: "/r1/.*"
    ops: [subscribe, call_service, publish]
  - subject: {user: alice}
    names: "/r1/secret"
    ops: [subscribe, call_service, publish]
    effect: deny
  - subject: {hub: site7}
    names: "/r1/cmd_vel"
    ops: [publish, call_service]
    effect: deny
"#;

fn security() -> Arc<Security> {
    let security = Arc::new(
        Security::new(
            Store::open_in_memory().expect("an in-memory store"),
            AuthPolicy::default(),
            AclDefaults::default(),
        )
        .expect("security"),
    );
    let admin = Identity {
        kind: IdentityKind::User {
            name: UserName::new("root").unwrap(),
            groups: vec![GroupName::new("admin").unwrap()],
        },
        source: ConnInfo::new("127.0.0.1".parse().unwrap()),
        client_ip: "127.0.0.1".parse().unwrap(),
    };
    security
        .import_rules_yaml(&admin, RULES, UnixTime::now())
        .expect("rules");
    security
}

fn user(name: &str, groups: &[&str]) -> Identity {
    Identity {
        kind: IdentityKind::User {
            name: UserName::new(name).unwrap(),
            groups: groups.iter().map(|g| GroupName::new(g).unwrap()).collect(),
        },
        source: ConnInfo::new("10.0.0.9".parse().unwrap()),
        client_ip: "10.0.0.9".parse().unwrap(),
    }
}

fn gate(security: &Arc<Security>, identity: Identity) -> HubGate {
    HubGate::new(security.clone(), Arc::new(Registry::default()), identity)
}

#[test]
fn a_name_spelled_another_way_meets_the_same_rule() {
    let s = security();
    let mut alice = gate(&s, user("alice", &[]));
    for spelling in ["/r1/secret", "/r1/secret/", "r1/secret", "r1/secret/"] {
        assert!(!alice.allows(spelling, Op::Subscribe), "{spelling:?}");
        assert!(!alice.allows(spelling, Op::CallService), "{spelling:?}");
    }
    for spelling in ["/r1/odom", "/r1/odom/", "r1/odom"] {
        assert!(alice.allows(spelling, Op::Subscribe), "{spelling:?}");
    }
    for not_a_name in ["", "/", "/r1//secret", "/r1/se cret", "/r1/\u{7}"] {
        assert!(!alice.allows(not_a_name, Op::Subscribe), "{not_a_name:?}");
    }
}

#[test]
fn hub_only_names_are_refused_to_every_client_admins_included() {
    let s = security();
    let mut admin = gate(&s, user("root", &["admin"]));
    for (name, op) in [
        ("/r1/fleetlink/config/set", Op::CallService),
        ("/r1/fleetlink/config/get/", Op::CallService),
        ("/r1/fleetlink/blackbox/fetch", Op::CallService),
        ("/site7/r1/fleetlink/blackbox/fetch", Op::CallService),
        ("/r1/fleetlink/blackbox/data", Op::Subscribe),
        ("r1/fleetlink/blackbox/data/", Op::Subscribe),
        ("/r1/fleetlink/blackbox/data", Op::Publish),
        ("/r1/fleetlink/blackbox/fetch", Op::AdvertiseService),
    ] {
        assert!(!admin.allows(name, op), "{name} {op:?}");
    }
    assert!(admin.allows("/r1/odom", Op::Subscribe));
    // The robot's own link provides its services and publishes its black box's data.
    let robot = Identity {
        kind: IdentityKind::Robot {
            name: RobotName::new("r1").unwrap(),
        },
        ..user("x", &[])
    };
    let mut link = HubGate::for_agent(s.clone(), Arc::new(Registry::default()), robot, "r1");
    assert!(link.allows("/r1/fleetlink/blackbox/data", Op::Publish));
    assert!(link.allows("/r1/fleetlink/blackbox/fetch", Op::AdvertiseService));
    assert!(!link.allows("/r1/fleetlink/blackbox/data", Op::Subscribe));
    assert!(!link.allows("/r2/fleetlink/blackbox/data", Op::Publish));
    // A site hub's link upstream: the hub there answers its API through them.
    let mut upstream = HubGate::for_upstream(
        s.clone(),
        Arc::new(Registry::default()),
        user("cloud", &["admin"]),
    );
    assert!(upstream.allows("/r1/fleetlink/blackbox/fetch", Op::CallService));
    assert!(upstream.allows("/r1/fleetlink/config/set", Op::CallService));
}

#[test]
fn a_call_another_hub_vouches_for_meets_the_callers_rules_and_the_hubs() {
    let s = security();
    let site7 = HubName::new("site7").unwrap();
    let alice = Caller::User {
        name: "alice".into(),
        groups: vec![],
    };
    let id = vouched_identity(&alice, &site7, "10.1.0.2".parse().unwrap()).unwrap();
    assert_eq!(id.principal(), "hub:site7/user:alice");
    let mut g = gate(&s, id);
    assert!(g.allows("/r1/set_mode", Op::CallService));
    assert!(
        !g.allows("/r1/secret/", Op::CallService),
        "alice's own deny"
    );
    assert!(!g.allows("/r1/cmd_vel", Op::CallService), "the hub's deny");
    // The hub's deny binds the admins it vouches for too; another hub's do not meet it.
    let root = Caller::User {
        name: "root".into(),
        groups: vec!["admin".into()],
    };
    let mut via_site7 = gate(
        &s,
        vouched_identity(&root, &site7, "10.1.0.2".parse().unwrap()).unwrap(),
    );
    assert!(!via_site7.allows("/r1/cmd_vel", Op::CallService));
    assert!(via_site7.allows("/r1/odom", Op::CallService));
    let eu1 = HubName::new("eu1").unwrap();
    let mut via_eu1 = gate(
        &s,
        vouched_identity(&root, &eu1, "10.1.0.3".parse().unwrap()).unwrap(),
    );
    assert!(via_eu1.allows("/r1/cmd_vel", Op::CallService));
    // Hub-only services stay the hub's, whoever vouches.
    assert!(!via_eu1.allows("/r1/fleetlink/config/set", Op::CallService));
    // A forwarded identity is not forwarded again.
    assert_eq!(via_eu1.caller(), None);
    // A name that breaks the rules for names is no identity.
    let bad = Caller::User {
        name: "al ice".into(),
        groups: vec![],
    };
    assert!(vouched_identity(&bad, &eu1, "10.1.0.3".parse().unwrap()).is_none());
}

#[test]
fn a_hub_forwarding_topics_is_limited_by_the_rules_that_name_it() {
    let s = security();
    let ip = "10.1.0.2".parse().unwrap();
    let mut site7 = gate(&s, hub_identity(&HubName::new("site7").unwrap(), ip));
    assert_eq!(site7.principal(), "hub:site7");
    assert!(site7.allows("/r1/pose", Op::Publish));
    assert!(site7.allows("/r1/pose", Op::Subscribe));
    assert!(!site7.allows("/r1/cmd_vel", Op::Publish));
    assert!(
        !site7.allows("/r1/pose", Op::AdvertiseService),
        "not a hub's default"
    );
    let mut eu1 = gate(&s, hub_identity(&HubName::new("eu1").unwrap(), ip));
    assert!(eu1.allows("/r1/cmd_vel", Op::Publish));
    assert_eq!(eu1.caller(), None);
}

/// Names drawn from the characters that make spellings differ.
fn raw_name() -> impl Strategy<Value = String> {
    proptest::collection::vec(
        prop_oneof![
            Just("/"),
            Just("r1"),
            Just("secret"),
            Just("odom"),
            Just("fleetlink"),
            Just("config"),
            Just("set"),
            Just(" "),
            Just("x"),
        ],
        0..7,
    )
    .prop_map(|parts| parts.concat())
}

proptest! {
    /// For any spelling, the gate's decision is the decision on the normalized name (and
    /// a spelling that is no name is refused), for every identity kind and operation.
    #[test]
    fn the_decision_on_a_raw_name_is_the_decision_on_its_normal_form(
        raw in raw_name(),
        who in 0usize..3,
        op in prop_oneof![Just(Op::Subscribe), Just(Op::Publish), Just(Op::CallService)],
    ) {
        let s = security();
        let identity = match who {
            0 => user("alice", &[]),
            1 => user("root", &["admin"]),
            _ => hub_identity(&HubName::new("site7").unwrap(), "10.1.0.2".parse().unwrap()),
        };
        let mut g = gate(&s, identity);
        let on_raw = g.allows(&raw, op);
        match fleetlink_relay::names::normalize(&raw) {
            Ok(normal) => prop_assert_eq!(on_raw, g.allows(&normal, op)),
            Err(_) => prop_assert!(!on_raw),
        }
    }
}
