//! fleetlink's security core: who a peer is, what it may do, and what it did.
//!
//! Independent of the hub: no sockets, no tasks, no clocks. Every time-dependent call
//! takes `now` ([`UnixTime`]), and the hub's connection layer drives it (see
//! `docs/security.md` for the wiring).
//!
//! # Layout
//!
//! - [`identity`]: name newtypes, [`Identity`], [`ConnInfo`], and [`TrustedProxies`]
//!   (the only place `X-Forwarded-For` is believed).
//! - [`token`]: `flk_<kind>_<secret>` tokens and their SHA-256 hashes.
//! - [`acl`]: rules, YAML import, the shared [`Authorizer`] and per-connection [`Access`]
//!   decision cache.
//! - [`store`]: the tables (rules, robot/operator tokens, users, sessions, audit), in
//!   SQLite or a shared PostgreSQL, and the operations the REST API and CLI need.
//! - [`authn`]: [`Authenticator`]: every [`Credential`] kind to an [`Identity`], login,
//!   logout, anonymous policy.
//! - [`ratelimit`]: sans-IO login throttling per user name and per client address.
//! - [`jwt`]: OIDC/JWT bearer validation against a cached JWKS.
//! - [`audit`]: audit records, the non-blocking batching writer and queries.
//! - [`security`]: [`Security`], the facade that keeps store, rules and audit in step for
//!   every administrative change.
//! - [`tls`]: rustls server config with file reload, client config, client-cert names;
//!   the certificate verifiers (pinned `tls.ca` certificates) and RSA-PSS key support.

pub mod acl;
pub mod audit;
pub mod authn;
pub mod identity;
pub mod jwt;
pub mod ratelimit;
pub mod security;
pub mod store;
pub mod tls;
pub mod token;

pub use acl::{Access, AclDefaults, Authorizer, Decision, Operation, Rule, RuleId, Subject};
pub use audit::{AuditLog, AuditRecord};
pub use authn::{AuthError, AuthPolicy, Authenticator, Credential, Session};
pub use identity::{
    ConnInfo, GroupName, HubName, Identity, IdentityKind, RobotName, TrustedProxies, UserName,
};
pub use security::{Security, SecurityError};
pub use store::{Store, StoreError};
pub use token::{Token, TokenKind};

/// Seconds since the Unix epoch: the crate's notion of `now`.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(transparent)]
pub struct UnixTime(pub i64);

impl UnixTime {
    /// The wall clock, for callers at the edge (the hub); the core never calls this.
    pub fn now() -> UnixTime {
        UnixTime::from(std::time::SystemTime::now())
    }

    pub fn plus_secs(self, secs: i64) -> UnixTime {
        UnixTime(self.0.saturating_add(secs))
    }
}

impl From<std::time::SystemTime> for UnixTime {
    fn from(t: std::time::SystemTime) -> UnixTime {
        match t.duration_since(std::time::UNIX_EPOCH) {
            Ok(d) => UnixTime(i64::try_from(d.as_secs()).unwrap_or(i64::MAX)),
            Err(e) => UnixTime(-i64::try_from(e.duration().as_secs()).unwrap_or(i64::MAX)),
        }
    }
}

#[cfg(test)]
mod tests {
    fn shared<T: Send + Sync>() {}
    fn owned<T: Send>() {}

    #[test]
    fn handles_can_cross_tasks() {
        shared::<crate::Security>();
        shared::<crate::Authorizer>();
        shared::<crate::Authenticator>();
        shared::<crate::AuditLog>();
        shared::<crate::tls::ReloadingServerConfig>();
        owned::<crate::Access>();
        owned::<crate::Identity>();
    }
}
