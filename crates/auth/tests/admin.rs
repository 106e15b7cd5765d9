//! The store operations the REST API and `fleetlink admin` use, through [`Security`].

use fleetlink_auth::acl::{AclDefaults, Operation, export_yaml, import_yaml};
use fleetlink_auth::audit::{AuditAction, AuditQuery};
use fleetlink_auth::{AuthPolicy, Credential, IdentityKind, TokenKind};

use crate::util::*;

on_both_backends!(
    demo_operator_token_has_full_rights,
    rules_add_list_remove_replace_and_yaml_round_trip,
    tokens_are_stored_hashed_and_listed_without_secrets,
    users_add_list_remove_and_group_changes_reach_sessions,
    robot_authenticates_by_client_certificate_name_without_token,
);

fn demo_operator_token_has_full_rights(backend: Backend) {
    let sec = security_on(backend, AuthPolicy::demo(), AclDefaults::demo());
    let token = sec
        .store
        .mint_operator_token(&user("operator"), &[group("admin")], None, T0)
        .unwrap();
    assert!(token.expose().starts_with("flk_operator_"));
    let id = sec
        .authenticate(
            Credential::Bearer(token.expose().into()),
            peer("127.0.0.1"),
            T0,
        )
        .unwrap();
    let mut access = sec.access(id);
    assert!(access.allows("/r1/cmd_vel", Operation::Publish));
    assert!(access.allows("/r1/nav", Operation::SendActionGoal));
    assert!(access.allows("/rules", Operation::Admin));
}

fn rules_add_list_remove_replace_and_yaml_round_trip(backend: Backend) {
    let sec = security_on(backend, AuthPolicy::default(), AclDefaults::default());
    let yaml = "rules:
  - subject: {group: ops}
    names: /.*
    ops: [subscribe]
  - subject: {cidr: 10.8.0.0/16}
    names: /vpn/.*
    ops: [all]
    effect: deny
    comment: no VPN writes
";
    assert_eq!(sec.import_rules_yaml(&admin(), yaml, T0).unwrap(), 2);
    let stored = sec.store.list_rules().unwrap();
    assert_eq!(stored.len(), 2);
    let rules: Vec<_> = stored.iter().map(|s| s.rule.clone()).collect();
    assert_eq!(import_yaml(&export_yaml(&rules).unwrap()).unwrap(), rules);

    let extra = import_yaml("rules: [{subject: any_robot, names: /fleet/.*, ops: [subscribe]}]")
        .unwrap()
        .remove(0);
    let id = sec.add_rule(&admin(), extra, T0).unwrap();
    assert_eq!(sec.authz.rules().len(), 3);
    assert!(sec.remove_rule(&admin(), id, T0).unwrap());
    assert!(!sec.remove_rule(&admin(), id, T0).unwrap());
    assert_eq!(sec.authz.rules().len(), 2);

    sec.audit.flush();
    let changes = sec
        .store
        .query_audit(&AuditQuery {
            action: Some(AuditAction::RuleChange),
            ..AuditQuery::default()
        })
        .unwrap();
    assert_eq!(changes.records.len(), 3, "replace, add, remove are audited");
    assert!(
        changes
            .records
            .iter()
            .all(|r| r.record.principal == "user:root")
    );
}

#[test]
fn invalid_yaml_names_the_problem() {
    let err = import_yaml("rules: [{subject: {robot: 'r/1'}, names: /x, ops: [publish]}]")
        .unwrap_err()
        .to_string();
    assert!(err.contains("robot name"), "{err}");
    let err = import_yaml("rules: [{subject: anyone, names: /x, ops: [fly]}]")
        .unwrap_err()
        .to_string();
    assert!(err.contains("unknown operation"), "{err}");
}

fn tokens_are_stored_hashed_and_listed_without_secrets(backend: Backend) {
    let sec = security_on(backend, AuthPolicy::default(), AclDefaults::default());
    let t = sec
        .add_robot_token(&admin(), &robot("r7"), None, T0)
        .unwrap();
    let listed = sec.store.list_tokens(Some(TokenKind::Robot)).unwrap();
    assert_eq!(listed.len(), 1);
    assert_eq!(listed[0].subject, "r7");
    let json = serde_json::to_string(&listed).unwrap();
    assert!(!json.contains(&t.expose()[10..]));
    let id = sec
        .authenticate(
            Credential::Bearer(t.expose().into()),
            peer("192.0.2.1"),
            T0.plus_secs(5),
        )
        .unwrap();
    assert_eq!(id.kind, IdentityKind::Robot { name: robot("r7") });
    let listed = sec.store.list_tokens(Some(TokenKind::Robot)).unwrap();
    assert_eq!(listed[0].last_used_at, Some(T0.plus_secs(5)));
    assert_eq!(sec.store.revoke_robot_tokens(&robot("r7"), T0).unwrap(), 1);
}

fn users_add_list_remove_and_group_changes_reach_sessions(backend: Backend) {
    let sec = security_on(backend, AuthPolicy::default(), AclDefaults::default());
    sec.add_user(&admin(), &user("alice"), "pw-alice-1", &[group("ops")], T0)
        .unwrap();
    assert!(
        sec.add_user(&admin(), &user("alice"), "x", &[], T0)
            .is_err()
    );
    let users = sec.store.list_users().unwrap();
    assert_eq!(users.len(), 1);
    assert_eq!(users[0].groups, vec![group("ops")]);

    let session = sec
        .login("alice", "pw-alice-1", peer("192.0.2.1"), T0)
        .unwrap();
    sec.store
        .set_password(&user("alice"), "pw-alice-2")
        .unwrap();
    assert!(
        sec.login("alice", "pw-alice-1", peer("192.0.2.1"), T0)
            .is_err()
    );
    assert!(
        sec.login("alice", "pw-alice-2", peer("192.0.2.1"), T0)
            .is_ok()
    );

    assert!(sec.remove_user(&admin(), &user("alice"), T0).unwrap());
    let replay = sec.authenticate(
        Credential::Bearer(session.token.expose().into()),
        peer("192.0.2.1"),
        T0,
    );
    assert!(replay.is_err(), "removing a user ends their sessions");
}

fn robot_authenticates_by_client_certificate_name_without_token(backend: Backend) {
    let sec = security_on(backend, AuthPolicy::default(), AclDefaults::default());
    let conn = peer("192.0.2.1").with_tls_client_name(robot("r1"));
    let cred = |name: &str| Credential::Agent {
        robot: robot(name),
        token: None,
    };
    let id = sec.authenticate(cred("r1"), conn.clone(), T0).unwrap();
    assert_eq!(id.robot(), Some(&robot("r1")));
    assert!(sec.authenticate(cred("r2"), conn.clone(), T0).is_err());
    // HELLO's empty token string means "no token", not a malformed one.
    let empty = Credential::Agent {
        robot: robot("r1"),
        token: Some(String::new()),
    };
    assert!(sec.authenticate(empty, conn, T0).is_ok());
}

/// Issue 14 (found by the docs suite): a hub creating its database while `fleetlink admin`
/// mints a token in the same file must not fail with "database is locked"; both wait for
/// the other's lock.
#[test]
fn issue14_two_processes_opening_a_new_database_at_once_both_succeed() {
    for round in 0..20 {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("hub.sqlite3");
        let openers: Vec<_> = (0..4)
            .map(|i| {
                let path = path.clone();
                std::thread::spawn(move || {
                    let store = fleetlink_auth::store::Store::open(&path)
                        .unwrap_or_else(|e| panic!("round {round}, opener {i}: {e}"));
                    store
                        .mint_operator_token(&user(&format!("op{i}")), &[group("admin")], None, T0)
                        .unwrap_or_else(|e| panic!("round {round}, opener {i} minting: {e}"));
                })
            })
            .collect();
        for o in openers {
            o.join().unwrap();
        }
    }
}
