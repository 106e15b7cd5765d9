//! The ACL matrix: identities × names × operations over the decision API, and rule
//! changes reaching live (cached) decisions.

use fleetlink_auth::acl::{AclDefaults, Operation, Reason, import_yaml};
use fleetlink_auth::{AuthPolicy, Identity};

use crate::util::*;

const RULES: &str = r#"
rules:
  - subject: {group: operators}
    names: "/.*"
    ops: [subscribe, call_service]
  - subject: {group: operators}
    names: "/r[0-9]+/cmd_vel"
    ops: [publish, send_action_goal]
  - subject: any_robot
    names: "/fleet/.*"
    ops: [subscribe]
  - subject: {user: intern}
    names: "/r1/.*"
    ops: [publish]
    effect: deny
    comment: intern may watch r1 but not drive it
  - subject: {user: bob}
    names: "/r2/camera/.*"
    ops: [subscribe]
  - subject: {cidr: 10.8.0.0/16}
    names: "/vpn/.*"
    ops: [subscribe]
  - subject: {robot: r2}
    names: "/r1/status"
    ops: [subscribe]
"#;

use Operation::*;

#[test]
fn acl_matrix_allows_and_denies_each_case() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    sec.import_rules_yaml(&admin(), RULES, T0).unwrap();

    let r1 = robot_id("r1", "198.51.100.1");
    let r2 = robot_id("r2", "10.8.0.7");
    let alice = user_id("alice", &["operators"], "203.0.113.5");
    let intern = user_id("intern", &["operators"], "203.0.113.6");
    let bob = user_id("bob", &[], "203.0.113.7");
    let root = admin();
    let anon = anonymous("127.0.0.1");

    #[rustfmt::skip]
    let cases: &[(&Identity, &str, Operation, bool)] = &[
        // robots: own namespace yes, others' no, fleet topics by rule
        (&r1, "/r1/scan", Publish, true),
        (&r1, "/r1/cmd_vel", Subscribe, true),
        (&r1, "/r1/nav", AdvertiseAction, true),
        (&r1, "/r2/cmd_vel", Publish, false),
        (&r1, "/r10/scan", Publish, false),
        (&r1, "/fleet/map", Subscribe, true),
        (&r1, "/fleet/map", Publish, false),
        (&r1, "/r2/scan", Subscribe, false),
        (&r1, "/vpn/status", Subscribe, false),
        (&r1, "/r1/anything", Admin, false),
        (&r2, "/vpn/status", Subscribe, true), // by CIDR
        (&r2, "/r1/status", Subscribe, true),
        (&r2, "/r1/scan", Subscribe, false),
        // operators: read everything, drive by cmd_vel only
        (&alice, "/r1/scan", Subscribe, true),
        (&alice, "/rosapi/topics", CallService, true),
        (&alice, "/r1/cmd_vel", Publish, true),
        (&alice, "/r1/cmd_vel_raw", Publish, false),
        (&alice, "/r1/cmd_vel", SendActionGoal, true),
        (&alice, "/r1/scan", Publish, false),
        (&alice, "/r1/map_server", AdvertiseService, false),
        (&alice, "/rules", Admin, false),
        // a deny rule beats the group's allow
        (&intern, "/r1/cmd_vel", Publish, false),
        (&intern, "/r2/cmd_vel", Publish, true),
        (&intern, "/r1/scan", Subscribe, true),
        // bob: one camera subtree
        (&bob, "/r2/camera/image", Subscribe, true),
        (&bob, "/r2/camera", Subscribe, false),
        (&bob, "/r2/scan", Subscribe, false),
        (&bob, "/r2/camera/image", Publish, false),
        // admin group: everything
        (&root, "/r1/cmd_vel", Publish, true),
        (&root, "/rules", Admin, true),
        // anonymous without anonymous_read: nothing
        (&anon, "/r1/scan", Subscribe, false),
        (&anon, "/rosapi/topics", CallService, false),
    ];

    let mut failures = Vec::new();
    for &(id, name, op, want) in cases {
        let uncached = sec.authz.decide(id, name, op).allowed;
        let mut access = sec.access(id.clone());
        let cold = access.allows(name, op);
        let warm = access.allows(name, op);
        if uncached != want || cold != want || warm != want {
            failures.push(format!(
                "{} {op} {name}: want {want}, got uncached {uncached} cold {cold} warm {warm}",
                id.principal()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn anonymous_read_grants_subscribe_and_rosapi_only() {
    let sec = security(AuthPolicy::demo(), AclDefaults::demo());
    let mut anon = sec.access(anonymous("127.0.0.1"));
    assert!(anon.allows("/r1/scan", Subscribe));
    assert!(anon.allows("/rosapi/topics", CallService));
    assert!(!anon.allows("/r1/reset", CallService));
    assert!(!anon.allows("/r1/cmd_vel", Publish));
    assert!(!anon.allows("/r1/nav", SendActionGoal));
}

#[test]
fn cached_decision_flips_when_a_rule_is_added_and_removed() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let mut bob = sec.access(user_id("bob", &[], "203.0.113.7"));
    assert!(!bob.allows("/r1/scan", Subscribe));
    assert_eq!(bob.cached_names(), 1);

    let rule = import_yaml("rules: [{subject: {user: bob}, names: \"/r1/.*\", ops: [subscribe]}]")
        .unwrap()
        .remove(0);
    let id = sec.add_rule(&admin(), rule, T0).unwrap();
    let d = bob.decide("/r1/scan", Subscribe);
    assert!(d.allowed, "live subscription must see the new rule");
    assert_eq!(d.reason, Reason::Rule(id));

    assert!(sec.remove_rule(&admin(), id, T0).unwrap());
    assert!(
        !bob.allows("/r1/scan", Subscribe),
        "revocation must reach the live subscription"
    );
}

#[test]
fn rule_edit_by_another_process_is_picked_up_by_polling() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("hub.sqlite3");
    let hub = fleetlink_auth::Security::new(
        fleetlink_auth::Store::open(&path).unwrap(),
        AuthPolicy::default(),
        AclDefaults::default(),
    )
    .unwrap();
    let mut alice = hub.access(user_id("alice", &[], "203.0.113.5"));
    assert!(!alice.allows("/r1/scan", Subscribe));
    let mut told = alice.watch_rules();
    assert!(!told.has_changed().unwrap());

    // `fleetlink admin` writes the same file through its own connection.
    let cli = fleetlink_auth::Store::open(&path).unwrap();
    let rules =
        import_yaml("rules: [{subject: {user: alice}, names: \"/.*\", ops: [subscribe]}]").unwrap();
    cli.add_rule(&rules[0], T0).unwrap();

    assert!(hub.reload_rules_if_changed().unwrap());
    // Sessions that show what is allowed are told (a viewer's channel list).
    assert!(
        told.has_changed().unwrap(),
        "a reload wakes the rules' watchers"
    );
    told.mark_unchanged();
    assert!(!hub.reload_rules_if_changed().unwrap());
    assert!(
        !told.has_changed().unwrap(),
        "nothing changed, nobody woken"
    );
    assert!(alice.allows("/r1/scan", Subscribe));
}

#[test]
fn visible_filters_listings_to_permitted_names() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    sec.import_rules_yaml(&admin(), RULES, T0).unwrap();
    let mut bob = sec.access(user_id("bob", &[], "203.0.113.7"));
    let topics = [
        "/r1/scan",
        "/r2/camera/image",
        "/r2/camera/info",
        "/r2/scan",
    ];
    assert_eq!(
        bob.visible(topics, Subscribe),
        vec!["/r2/camera/image", "/r2/camera/info"]
    );
}
