//! Audit log: records written through the non-blocking writer, filters and paging.

use fleetlink_auth::acl::{AclDefaults, NamePattern};
use fleetlink_auth::audit::{AuditAction, AuditLog, AuditQuery, AuditRecord};
use fleetlink_auth::{AuthPolicy, Credential};

use crate::util::*;

on_both_backends!(
    audit_query_filters_by_principal_action_name_allowed_and_time,
    audit_paging_with_cursor_visits_every_record_once,
    authentication_failures_are_audited_with_client_address,
    prune_audit_drops_only_older_records,
);

fn fill(log: &AuditLog) {
    let alice = user_id("alice", &["ops"], "203.0.113.5");
    let r1 = robot_id("r1", "198.51.100.1");
    for i in 0..30 {
        let (who, action, name, allowed) = match i % 3 {
            0 => (&alice, AuditAction::Publish, "/r1/cmd_vel", true),
            1 => (&alice, AuditAction::CallService, "/r2/reset", false),
            _ => (&r1, AuditAction::SendActionGoal, "/r1/navigate", true),
        };
        assert!(log.record(AuditRecord::operation(
            who,
            action,
            name,
            Some(64),
            allowed,
            T0.plus_secs(i)
        )));
    }
    log.flush();
}

fn audit_query_filters_by_principal_action_name_allowed_and_time(backend: Backend) {
    let store = store_on(backend);
    let log = AuditLog::start(store.clone(), 1024).unwrap();
    fill(&log);
    assert_eq!(log.written(), 30);
    assert_eq!(log.overflowed(), 0);

    let q = |q: AuditQuery| store.query_audit(&q).unwrap().records;
    assert_eq!(q(AuditQuery::default()).len(), 30);
    assert_eq!(
        q(AuditQuery {
            principal: Some("robot:r1".into()),
            ..Default::default()
        })
        .len(),
        10
    );
    let denied = q(AuditQuery {
        allowed: Some(false),
        ..Default::default()
    });
    assert_eq!(denied.len(), 10);
    assert!(denied.iter().all(|r| r.record.name == "/r2/reset"));
    assert_eq!(
        q(AuditQuery {
            name_prefix: Some("/r1/".into()),
            action: Some(AuditAction::Publish),
            ..Default::default()
        })
        .len(),
        10
    );
    assert_eq!(
        q(AuditQuery {
            name_regex: Some(NamePattern::new("/r[0-9]+/nav.*").unwrap()),
            ..Default::default()
        })
        .len(),
        10
    );
    let window = q(AuditQuery {
        since: Some(T0.plus_secs(10)),
        until: Some(T0.plus_secs(20)),
        ..Default::default()
    });
    assert_eq!(window.len(), 10);
    assert!(window.windows(2).all(|w| w[0].id > w[1].id), "newest first");
}

fn audit_paging_with_cursor_visits_every_record_once(backend: Backend) {
    let store = store_on(backend);
    let log = AuditLog::start(store.clone(), 1024).unwrap();
    fill(&log);
    let mut seen = Vec::new();
    let mut after = None;
    loop {
        let page = store
            .query_audit(&AuditQuery {
                limit: 7,
                after,
                ..Default::default()
            })
            .unwrap();
        seen.extend(page.records.iter().map(|r| r.id));
        match page.next {
            Some(c) => after = Some(c),
            None => break,
        }
    }
    let mut sorted = seen.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), 30);
    assert_eq!(seen.len(), 30);
}

fn authentication_failures_are_audited_with_client_address(backend: Backend) {
    let sec = security_on(backend, AuthPolicy::default(), AclDefaults::default());
    let _ = sec.authenticate(
        Credential::Agent {
            robot: robot("r9"),
            token: None,
        },
        peer("192.0.2.99"),
        T0,
    );
    let _ = sec.login("mallory", "guess", peer("192.0.2.98"), T0);
    sec.audit.flush();
    let page = sec
        .store
        .query_audit(&AuditQuery {
            action: Some(AuditAction::AuthFailure),
            ..Default::default()
        })
        .unwrap();
    let got: Vec<(String, String)> = page
        .records
        .iter()
        .map(|r| (r.record.principal.clone(), r.record.client_ip.to_string()))
        .collect();
    assert_eq!(
        got,
        vec![
            ("claimed-user:mallory".to_owned(), "192.0.2.98".to_owned()),
            ("claimed-robot:r9".to_owned(), "192.0.2.99".to_owned()),
        ]
    );
    assert!(
        page.records
            .iter()
            .all(|r| !r.record.allowed && r.record.detail.is_some())
    );
}

fn prune_audit_drops_only_older_records(backend: Backend) {
    let store = store_on(backend);
    let log = AuditLog::start(store.clone(), 1024).unwrap();
    fill(&log);
    assert_eq!(store.prune_audit(T0.plus_secs(10)).unwrap(), 10);
    let rest = store.query_audit(&AuditQuery::default()).unwrap().records;
    assert_eq!(rest.len(), 20);
    assert!(rest.iter().all(|r| r.record.at >= T0.plus_secs(10)));
}
