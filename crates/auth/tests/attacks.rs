//! One test per attack that is decidable at the security core's API. The over-the-wire
//! versions (oversized frames on a socket, HTTP path traversal) live in the hub's tests.

use std::time::Instant;

use fleetlink_auth::acl::{AclDefaults, NamePattern, Operation, PatternError, import_yaml};
use fleetlink_auth::authn::{MAX_TOKEN_LEN, RobotNetwork};
use fleetlink_auth::{AuthError, AuthPolicy, ConnInfo, Credential, IdentityKind, TrustedProxies};

use crate::util::*;

fn bearer(t: &str) -> Credential {
    Credential::Bearer(t.to_owned())
}

#[test]
fn no_token_is_rejected_when_anonymous_access_is_off() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let err = sec
        .authenticate(Credential::None, peer("127.0.0.1"), T0)
        .unwrap_err();
    assert!(matches!(err, AuthError::Missing), "{err}");
    assert_eq!(err.public_message(), "authentication required");
}

#[test]
fn anonymous_access_is_refused_from_a_non_loopback_peer() {
    let sec = security(AuthPolicy::demo(), AclDefaults::demo());
    let err = sec
        .authenticate(Credential::None, peer("192.0.2.10"), T0)
        .unwrap_err();
    assert!(
        matches!(err, AuthError::AnonymousNotAllowed { .. }),
        "{err}"
    );
    let ok = sec.authenticate(Credential::None, peer("::1"), T0).unwrap();
    assert_eq!(ok.kind, IdentityKind::Anonymous);
}

#[test]
fn invalid_tokens_are_rejected() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let garbage = sec.authenticate(bearer("flk_robot_nope"), peer("192.0.2.1"), T0);
    assert!(matches!(garbage, Err(AuthError::MalformedToken(_))));
    // Well-formed but never issued.
    let forged = format!("flk_robot_{}", "A".repeat(43));
    let unknown = sec.authenticate(bearer(&forged), peer("192.0.2.1"), T0);
    assert!(matches!(unknown, Err(AuthError::UnknownToken)));
    // A JWT-shaped token with JWT disabled.
    let jwt = sec.authenticate(bearer("a.b.c"), peer("192.0.2.1"), T0);
    assert!(matches!(jwt, Err(AuthError::JwtNotConfigured)));
}

#[test]
fn expired_token_is_rejected() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let token = sec
        .add_robot_token(&admin(), &robot("r1"), Some(T0.plus_secs(60)), T0)
        .unwrap();
    let cred = || Credential::Agent {
        robot: robot("r1"),
        token: Some(token.expose().into()),
    };
    assert!(
        sec.authenticate(cred(), peer("192.0.2.1"), T0.plus_secs(59))
            .is_ok()
    );
    let err = sec
        .authenticate(cred(), peer("192.0.2.1"), T0.plus_secs(60))
        .unwrap_err();
    assert!(matches!(err, AuthError::Expired(_)), "{err}");
    assert_eq!(err.public_message(), "authentication failed");
}

#[test]
fn revoked_robot_token_is_rejected() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let token = sec
        .add_robot_token(&admin(), &robot("r1"), None, T0)
        .unwrap();
    assert!(
        sec.authenticate(bearer(token.expose()), peer("192.0.2.1"), T0)
            .is_ok()
    );
    let id = sec.store.list_tokens(None).unwrap()[0].id;
    assert!(sec.revoke_token(&admin(), id, T0).unwrap());
    let err = sec
        .authenticate(bearer(token.expose()), peer("192.0.2.1"), T0)
        .unwrap_err();
    assert!(matches!(err, AuthError::Revoked(_)), "{err}");
}

#[test]
fn session_token_replayed_after_logout_is_rejected() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    sec.add_user(
        &admin(),
        &user("alice"),
        "s3cret-pass",
        &[group("operators")],
        T0,
    )
    .unwrap();
    let session = sec
        .login("alice", "s3cret-pass", peer("192.0.2.1"), T0)
        .unwrap();
    let id = sec
        .authenticate(bearer(session.token.expose()), peer("192.0.2.1"), T0)
        .unwrap();
    assert_eq!(sec.store.list_sessions(T0).unwrap().len(), 1);
    sec.logout(&id, session.token.expose(), T0).unwrap();
    let err = sec
        .authenticate(bearer(session.token.expose()), peer("192.0.2.1"), T0)
        .unwrap_err();
    assert!(matches!(err, AuthError::Revoked(_)), "{err}");
    assert!(sec.store.list_sessions(T0).unwrap().is_empty());
}

#[test]
fn session_token_is_not_accepted_as_a_robot_credential() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    sec.add_user(&admin(), &user("alice"), "s3cret-pass", &[], T0)
        .unwrap();
    let session = sec
        .login("alice", "s3cret-pass", peer("192.0.2.1"), T0)
        .unwrap();
    let err = sec
        .authenticate(
            Credential::Agent {
                robot: robot("r1"),
                token: Some(session.token.expose().into()),
            },
            peer("192.0.2.1"),
            T0,
        )
        .unwrap_err();
    assert!(matches!(err, AuthError::WrongTokenKind { .. }), "{err}");
}

#[test]
fn spoofed_x_forwarded_for_is_ignored_from_untrusted_peers() {
    let policy = AuthPolicy {
        allow_anonymous_read: true,
        trusted_proxies: TrustedProxies::new(vec!["10.0.0.1/32".parse().unwrap()]),
        robot_networks: vec![RobotNetwork {
            net: "10.8.0.0/16".parse().unwrap(),
            robot: None,
        }],
        ..AuthPolicy::default()
    };
    let sec = security(policy, AclDefaults::demo());
    // A remote client claims to be loopback, and to be on the robot VPN.
    let spoofed = ConnInfo::new(ip("203.0.113.66")).with_forwarded_for("127.0.0.1");
    let err = sec.authenticate(Credential::None, spoofed, T0).unwrap_err();
    assert!(
        matches!(err, AuthError::AnonymousNotAllowed { .. }),
        "{err}"
    );
    let spoofed = ConnInfo::new(ip("203.0.113.66")).with_forwarded_for("10.8.0.5");
    let agent = Credential::Agent {
        robot: robot("r1"),
        token: None,
    };
    let err = sec.authenticate(agent.clone(), spoofed, T0).unwrap_err();
    assert!(
        matches!(err, AuthError::UntrustedRobotAddress { .. }),
        "{err}"
    );
    // The same header through the trusted proxy is believed.
    let proxied = ConnInfo::new(ip("10.0.0.1")).with_forwarded_for("10.8.0.5");
    let id = sec.authenticate(agent, proxied, T0).unwrap();
    assert_eq!(id.client_ip, ip("10.8.0.5"));
}

#[test]
fn robot_cannot_publish_into_another_robots_namespace() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let token = sec
        .add_robot_token(&admin(), &robot("r1"), None, T0)
        .unwrap();
    // Claiming another robot's name with one's own token fails at the handshake…
    let err = sec
        .authenticate(
            Credential::Agent {
                robot: robot("r2"),
                token: Some(token.expose().into()),
            },
            peer("192.0.2.1"),
            T0,
        )
        .unwrap_err();
    assert!(matches!(err, AuthError::RobotMismatch { .. }), "{err}");
    // …and as itself it may publish only under /r1.
    let id = sec
        .authenticate(
            Credential::Agent {
                robot: robot("r1"),
                token: Some(token.expose().into()),
            },
            peer("192.0.2.1"),
            T0,
        )
        .unwrap();
    let mut access = sec.access(id);
    assert!(access.allows("/r1/odom", Operation::Publish));
    for name in [
        "/r2/cmd_vel",
        "/r10/odom",
        "/r1_evil/odom",
        "/cmd_vel",
        "/r2/r1/odom",
    ] {
        assert!(!access.allows(name, Operation::Publish), "{name}");
    }
}

#[test]
fn regex_subscription_reveals_only_permitted_topics() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let mut r1 = sec.access(robot_id("r1", "192.0.2.1"));
    // The client subscribes with ".*"; the hub expands it over existing topics and keeps
    // only those the caller may subscribe to.
    let all = ["/r1/cmd_vel", "/r2/camera/image", "/r3/secrets", "/r1/map"];
    assert_eq!(
        r1.visible(all, Operation::Subscribe),
        vec!["/r1/cmd_vel", "/r1/map"]
    );
}

#[test]
fn catastrophic_backtracking_pattern_matches_in_linear_time() {
    let p = NamePattern::new("(a+)+b").unwrap();
    let evil = "a".repeat(50_000);
    let started = Instant::now();
    assert!(!p.is_match(&evil));
    // Not a speed assertion: a backtracking engine would not return in our lifetime.
    let _ = started.elapsed();
}

#[test]
fn gigantic_regex_is_rejected() {
    let long = "a".repeat(10_000);
    assert!(matches!(
        NamePattern::new(&long),
        Err(PatternError::TooLong { .. })
    ));
    // Short source, huge program.
    let blowup = NamePattern::new("(?:[a-z]{50}){50}{50}");
    assert!(
        matches!(blowup, Err(PatternError::Invalid { .. })),
        "{blowup:?}"
    );
    let deep = format!("{}a{}", "(".repeat(100), ")".repeat(100));
    assert!(matches!(
        NamePattern::new(&deep),
        Err(PatternError::Invalid { .. })
    ));
    // Rejected rules never reach the store.
    let yaml = format!("rules: [{{subject: anyone, names: \"{long}\", ops: [subscribe]}}]");
    assert!(import_yaml(&yaml).is_err());
}

#[test]
fn oversized_auth_frame_is_rejected_before_any_work() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    let huge = "x".repeat(MAX_TOKEN_LEN + 1);
    let err = sec
        .authenticate(bearer(&huge), peer("192.0.2.1"), T0)
        .unwrap_err();
    assert!(matches!(err, AuthError::Oversized { .. }), "{err}");
    let err = sec
        .authenticate(
            Credential::Password {
                user: "alice".into(),
                password: "p".repeat(1 << 20),
            },
            peer("192.0.2.1"),
            T0,
        )
        .unwrap_err();
    assert!(matches!(err, AuthError::Oversized { .. }), "{err}");
}

#[test]
fn login_brute_force_engages_the_rate_limit() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    sec.add_user(&admin(), &user("alice"), "right-password", &[], T0)
        .unwrap();
    let from = || peer("198.51.100.20");
    for i in 0..5 {
        let err = sec
            .login("alice", &format!("guess{i}"), from(), T0)
            .unwrap_err();
        assert!(matches!(err, AuthError::BadPassword), "{err}");
    }
    // Locked: even the right password is refused, without revealing it was right.
    let err = sec
        .login("alice", "right-password", from(), T0)
        .unwrap_err();
    let AuthError::RateLimited { retry_after_secs } = err else {
        panic!("expected rate limit, got {err}");
    };
    assert!(retry_after_secs > 0);
    let later = T0.plus_secs(retry_after_secs);
    assert!(sec.login("alice", "right-password", from(), later).is_ok());
}

#[test]
fn unknown_user_gets_the_same_answer_as_a_wrong_password() {
    let sec = security(AuthPolicy::default(), AclDefaults::default());
    sec.add_user(&admin(), &user("alice"), "right-password", &[], T0)
        .unwrap();
    let a = sec
        .login("alice", "wrong", peer("192.0.2.1"), T0)
        .unwrap_err();
    let b = sec
        .login("mallory", "wrong", peer("192.0.2.2"), T0)
        .unwrap_err();
    assert!(matches!(a, AuthError::BadPassword) && matches!(b, AuthError::BadPassword));
    assert_eq!(a.public_message(), b.public_message());
}
