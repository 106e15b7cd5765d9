//! Authentication: every credential kind in, an [`Identity`] (or an [`AuthError`]) out.
//!
//! Design choice: one entry point, [`Authenticator::authenticate`], for every transport —
//! the hub only extracts a [`Credential`] from wherever the client put it (rosbridge
//! `auth` op, `Authorization: Bearer`, `?token=`, fleetlink.v1 HELLO) and passes it here
//! with the peer's [`ConnInfo`] and `now`. The error says exactly why (for the audit log);
//! [`AuthError::public_message`] is the deliberately vague text to send back.

pub(crate) mod password;

use std::net::IpAddr;
use std::sync::Mutex;

use ipnet::IpNet;

use crate::UnixTime;
use crate::identity::{
    ConnInfo, Identity, IdentityKind, NameError, RobotName, TrustedProxies, UserName,
};
use crate::jwt::{JwksCache, JwtConfig, JwtError};
use crate::ratelimit::{LoginLimiter, RateLimitConfig};
use crate::store::{Store, StoreError, TokenRecord};
use crate::token::{Token, TokenFormatError, TokenKind};

pub use password::MAX_PASSWORD_LEN;

/// Longest bearer token accepted (JWTs with many groups can be a few KiB).
pub const MAX_TOKEN_LEN: usize = 8 * 1024;

/// What a client presented.
#[derive(Clone, PartialEq, Eq)]
pub enum Credential {
    /// A bearer token from a rosbridge client: a fleetlink token (`flk_…`) or an OIDC JWT,
    /// told apart by shape.
    Bearer(String),
    /// User name and password (rosbridge `auth` op with `user`/`password`, or the login
    /// endpoint). Subject to the login rate limit.
    Password { user: String, password: String },
    /// An agent's fleetlink.v1 HELLO: the robot name it claims (parsed from HELLO by the
    /// hub, which refuses a name breaking the rule before authenticating), and its token
    /// if any. With no token, the claim is accepted from a verified client certificate
    /// naming the same robot or from a configured robot network.
    Agent {
        robot: RobotName,
        token: Option<String>,
    },
    /// Nothing presented.
    None,
}

impl Credential {
    /// The credential in an HTTP `Authorization` header value: `Bearer <token>` (scheme
    /// case-insensitive). `None` for other schemes or an empty token.
    pub fn from_authorization_header(value: &str) -> Option<Credential> {
        let (scheme, token) = value.trim().split_once(' ')?;
        let token = token.trim();
        (scheme.eq_ignore_ascii_case("bearer") && !token.is_empty())
            .then(|| Credential::Bearer(token.to_owned()))
    }
}

impl std::fmt::Debug for Credential {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Credential::Bearer(_) => f.write_str("Bearer(…)"),
            Credential::Password { user, .. } => write!(f, "Password {{ user: {user:?}, … }}"),
            Credential::Agent { robot, token } => write!(
                f,
                "Agent {{ robot: {robot:?}, token: {} }}",
                if token.is_some() { "…" } else { "none" }
            ),
            Credential::None => f.write_str("None"),
        }
    }
}

/// Robots trusted by address (Robofleet-style, for robots on a VPN).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RobotNetwork {
    pub net: IpNet,
    /// The only robot that may connect from `net`; `None` trusts any claimed name.
    pub robot: Option<RobotName>,
}

/// Authentication policy knobs.
#[derive(Debug, Clone)]
pub struct AuthPolicy {
    /// Let clients without a credential in as [`IdentityKind::Anonymous`] — only when their
    /// resolved address is loopback (`fleetlink demo`). Off for `fleetlink hub`.
    pub allow_anonymous_read: bool,
    pub trusted_proxies: TrustedProxies,
    pub robot_networks: Vec<RobotNetwork>,
    /// Lifetime of a login session.
    pub session_ttl_secs: i64,
    pub login_limits: RateLimitConfig,
    /// OIDC bearer tokens; `None` rejects JWTs.
    pub jwt: Option<JwtConfig>,
}

impl Default for AuthPolicy {
    fn default() -> AuthPolicy {
        AuthPolicy {
            allow_anonymous_read: false,
            trusted_proxies: TrustedProxies::none(),
            robot_networks: Vec::new(),
            session_ttl_secs: 12 * 3600,
            login_limits: RateLimitConfig::default(),
            jwt: None,
        }
    }
}

impl AuthPolicy {
    /// `fleetlink demo`: anonymous read-only access for loopback clients.
    pub fn demo() -> AuthPolicy {
        AuthPolicy {
            allow_anonymous_read: true,
            ..AuthPolicy::default()
        }
    }
}

/// Why authentication failed. Match on it for the audit log; send
/// [`AuthError::public_message`] to the client.
#[derive(Debug, thiserror::Error)]
pub enum AuthError {
    #[error("no credential presented")]
    Missing,
    #[error("anonymous access is only allowed from loopback (client {client})")]
    AnonymousNotAllowed { client: IpAddr },
    #[error("{what} is {len} bytes, over the limit of {max}")]
    Oversized {
        what: &'static str,
        len: usize,
        max: usize,
    },
    #[error("malformed token: {0}")]
    MalformedToken(#[from] TokenFormatError),
    #[error("unknown token")]
    UnknownToken,
    #[error("token expired at {0:?}")]
    Expired(UnixTime),
    #[error("token revoked at {0:?}")]
    Revoked(UnixTime),
    #[error("a {found} token cannot be used here (expected {expected})")]
    WrongTokenKind {
        expected: &'static str,
        found: &'static str,
    },
    #[error("token belongs to robot {token_robot}, but the agent claims to be {claimed}")]
    RobotMismatch {
        claimed: RobotName,
        token_robot: String,
    },
    #[error("invalid name: {0}")]
    BadName(#[from] NameError),
    #[error("robot {robot} presented no token and {client} is not a trusted robot address")]
    UntrustedRobotAddress { robot: RobotName, client: IpAddr },
    #[error("wrong user name or password")]
    BadPassword,
    #[error("too many failed logins; retry in {retry_after_secs} s")]
    RateLimited { retry_after_secs: i64 },
    #[error("JWT bearer tokens are not configured")]
    JwtNotConfigured,
    #[error("JWT: {0}")]
    Jwt(#[from] JwtError),
    #[error("credential store: {0}")]
    Store(#[from] StoreError),
}

impl AuthError {
    /// What to tell the client: no hint whether a token exists, was revoked or expired.
    pub fn public_message(&self) -> String {
        match self {
            AuthError::RateLimited { retry_after_secs } => {
                format!("too many failed logins; retry in {retry_after_secs} s")
            }
            AuthError::Oversized { what, max, .. } => format!("{what} too large (max {max})"),
            AuthError::Missing | AuthError::AnonymousNotAllowed { .. } => {
                "authentication required".to_owned()
            }
            AuthError::Store(e) if e.is_unavailable() => {
                "authentication unavailable: the hub cannot reach its database; retry later"
                    .to_owned()
            }
            AuthError::Store(_) => "authentication unavailable".to_owned(),
            _ => "authentication failed".to_owned(),
        }
    }
}

/// A login session just started.
#[derive(Debug, Clone)]
pub struct Session {
    /// Give this to the client once; it authenticates later connections as `Bearer`.
    pub token: Token,
    pub identity: Identity,
    pub expires_at: UnixTime,
}

/// Turns credentials into identities. Share it as `Arc<Authenticator>`.
pub struct Authenticator {
    store: Store,
    policy: AuthPolicy,
    jwks: JwksCache,
    // std Mutex: held for a map lookup/update, never across hashing, I/O or an await.
    limiter: Mutex<LoginLimiter>,
}

fn check_len(what: &'static str, s: &str, max: usize) -> Result<(), AuthError> {
    if s.len() > max {
        return Err(AuthError::Oversized {
            what,
            len: s.len(),
            max,
        });
    }
    Ok(())
}

impl Authenticator {
    pub fn new(store: Store, policy: AuthPolicy) -> Authenticator {
        Authenticator {
            store,
            limiter: Mutex::new(LoginLimiter::new(policy.login_limits)),
            policy,
            jwks: JwksCache::new(),
        }
    }

    pub fn policy(&self) -> &AuthPolicy {
        &self.policy
    }

    /// The JWKS cache, for the refresher (see [`crate::jwt`]).
    pub fn jwks(&self) -> &JwksCache {
        &self.jwks
    }

    fn identity(&self, kind: IdentityKind, peer: ConnInfo) -> Identity {
        let client_ip = self.policy.trusted_proxies.client_ip(&peer);
        Identity {
            kind,
            source: peer,
            client_ip,
        }
    }

    /// Authenticates one connection. Cost: a token is one indexed SQLite lookup; a
    /// password is an argon2 verification (tens of ms of CPU) — run it on the blocking
    /// pool.
    pub fn authenticate(
        &self,
        credential: Credential,
        peer: ConnInfo,
        now: UnixTime,
    ) -> Result<Identity, AuthError> {
        let client_ip = self.policy.trusted_proxies.client_ip(&peer);
        match credential {
            Credential::None => {
                if !self.policy.allow_anonymous_read {
                    return Err(AuthError::Missing);
                }
                if !client_ip.is_loopback() {
                    return Err(AuthError::AnonymousNotAllowed { client: client_ip });
                }
                Ok(self.identity(IdentityKind::Anonymous, peer))
            }
            Credential::Bearer(text) => {
                check_len("token", &text, MAX_TOKEN_LEN)?;
                let kind = if text.starts_with("flk_") {
                    let record = self.token_record(&text, now)?;
                    self.token_identity(record)?
                } else {
                    let config = self
                        .policy
                        .jwt
                        .as_ref()
                        .ok_or(AuthError::JwtNotConfigured)?;
                    let (name, groups) = self.jwks.validate(config, &text, now)?;
                    IdentityKind::User { name, groups }
                };
                Ok(self.identity(kind, peer))
            }
            Credential::Password { user, password } => {
                let (kind, _) = self.check_password(&user, &password, client_ip, now)?;
                Ok(self.identity(kind, peer))
            }
            Credential::Agent {
                robot: claimed,
                token,
            } => {
                // HELLO carries an empty string for "no token".
                if let Some(token) = token.filter(|t| !t.is_empty()) {
                    check_len("token", &token, MAX_TOKEN_LEN)?;
                    let record = self.token_record(&token, now)?;
                    if record.kind != TokenKind::Robot {
                        return Err(AuthError::WrongTokenKind {
                            expected: "robot",
                            found: record.kind.as_str(),
                        });
                    }
                    if record.subject != claimed.as_str() {
                        return Err(AuthError::RobotMismatch {
                            claimed,
                            token_robot: record.subject,
                        });
                    }
                } else if peer.tls_client_name.as_ref() != Some(&claimed)
                    && !self.robot_network_allows(&claimed, client_ip)
                {
                    return Err(AuthError::UntrustedRobotAddress {
                        robot: claimed,
                        client: client_ip,
                    });
                }
                Ok(self.identity(IdentityKind::Robot { name: claimed }, peer))
            }
        }
    }

    fn robot_network_allows(&self, robot: &RobotName, ip: IpAddr) -> bool {
        self.policy
            .robot_networks
            .iter()
            .any(|n| n.net.contains(&ip) && n.robot.as_ref().is_none_or(|r| r == robot))
    }

    /// A live token's record: parsed, found, not revoked, not expired.
    fn token_record(&self, text: &str, now: UnixTime) -> Result<TokenRecord, AuthError> {
        let token = Token::parse(text)?;
        let record = self
            .store
            .lookup_token(&token.hash())?
            .ok_or(AuthError::UnknownToken)?;
        if let Some(at) = record.revoked_at {
            return Err(AuthError::Revoked(at));
        }
        if let Some(at) = record.expires_at
            && now >= at
        {
            return Err(AuthError::Expired(at));
        }
        self.store.touch_token(record.id, now)?;
        Ok(record)
    }

    fn token_identity(&self, record: TokenRecord) -> Result<IdentityKind, AuthError> {
        let corrupt = |e: NameError| {
            AuthError::Store(StoreError::Corrupt {
                what: "token subject",
                reason: e.to_string(),
            })
        };
        Ok(match record.kind {
            TokenKind::Robot => IdentityKind::Robot {
                name: RobotName::new(&record.subject).map_err(corrupt)?,
            },
            TokenKind::Operator => IdentityKind::User {
                name: UserName::new(&record.subject).map_err(corrupt)?,
                groups: record.groups,
            },
            TokenKind::Session => {
                let name = UserName::new(&record.subject).map_err(corrupt)?;
                // Groups are read now, so a group change applies to existing sessions.
                let user = self.store.user(&name)?.ok_or(AuthError::UnknownToken)?;
                IdentityKind::User {
                    name,
                    groups: user.groups,
                }
            }
        })
    }

    fn check_password(
        &self,
        user: &str,
        password: &str,
        client_ip: IpAddr,
        now: UnixTime,
    ) -> Result<(IdentityKind, UserName), AuthError> {
        check_len("user name", user, 256)?;
        check_len("password", password, MAX_PASSWORD_LEN)?;
        let lock = || self.limiter.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(retry_after_secs) = lock().check(user, client_ip, now) {
            return Err(AuthError::RateLimited { retry_after_secs });
        }
        let record = match UserName::new(user) {
            Ok(name) => self.store.user(&name)?,
            Err(_) => None,
        };
        let ok = match &record {
            Some(r) => password::verify(password, &r.password_hash),
            None => {
                password::verify_dummy(password);
                false
            }
        };
        match record {
            Some(r) if ok => {
                lock().record_success(user);
                let name = r.name.clone();
                Ok((
                    IdentityKind::User {
                        name: r.name,
                        groups: r.groups,
                    },
                    name,
                ))
            }
            _ => {
                lock().record_failure(user, client_ip, now);
                Err(AuthError::BadPassword)
            }
        }
    }

    /// Password login: checks the password (rate-limited) and starts a session whose
    /// token the client then presents as `Bearer`.
    pub fn login(
        &self,
        user: &str,
        password: &str,
        peer: ConnInfo,
        now: UnixTime,
    ) -> Result<Session, AuthError> {
        let client_ip = self.policy.trusted_proxies.client_ip(&peer);
        let (kind, name) = self.check_password(user, password, client_ip, now)?;
        let expires_at = now.plus_secs(self.policy.session_ttl_secs);
        let token = self.store.create_session(&name, expires_at, now)?;
        Ok(Session {
            token,
            identity: self.identity(kind, peer),
            expires_at,
        })
    }

    /// Ends the session of `token`; replaying it afterwards fails with
    /// [`AuthError::Revoked`]. Only session tokens can be logged out.
    pub fn logout(&self, token: &str, now: UnixTime) -> Result<(), AuthError> {
        check_len("token", token, MAX_TOKEN_LEN)?;
        let token = Token::parse(token)?;
        if token.kind() != TokenKind::Session {
            return Err(AuthError::WrongTokenKind {
                expected: "session",
                found: token.kind().as_str(),
            });
        }
        if !self.store.revoke_token_by_hash(&token.hash(), now)? {
            return Err(AuthError::UnknownToken);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn authorization_header_accepts_bearer_only() {
        assert_eq!(
            Credential::from_authorization_header("bearer flk_robot_x"),
            Some(Credential::Bearer("flk_robot_x".to_owned()))
        );
        assert_eq!(
            Credential::from_authorization_header("Basic dXNlcjpwdw=="),
            None
        );
        assert_eq!(Credential::from_authorization_header("Bearer   "), None);
    }
}
