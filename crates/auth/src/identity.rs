//! Who is on the other end of a connection: names, [`Identity`] and where it came from.
//!
//! Design choice: names are validated newtypes, parsed once where a name enters the system
//! (a HELLO, a config file, a command-line flag, a certificate, a REST path) and carried
//! typed from there. [`RobotName`] is the one robot name rule for the whole workspace
//! (hub, agent and CLI all use it; there is no second copy): one ROS name segment starting
//! with a letter (`[A-Za-z][A-Za-z0-9_]*`), at most 63 bytes. A segment, so a robot's own
//! namespace `/<name>/` can be checked with a plain prefix test and no robot name can
//! smuggle a `/` into another robot's namespace; 63 bytes, a DNS label's limit, because
//! `fleetlink admin cert robot NAME` writes the name into a certificate as a DNS name.
//! The client address is resolved here, once, from the socket peer and — only when that
//! peer is a configured trusted proxy — the `X-Forwarded-For` header.

use std::fmt;
use std::net::IpAddr;
use std::sync::Arc;

use ipnet::IpNet;

/// A name that failed validation, with the reason.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("invalid {what} {name:?}: {reason}")]
pub struct NameError {
    pub what: &'static str,
    pub name: String,
    pub reason: &'static str,
}

/// How much of a refused name an error message repeats.
const ECHOED_NAME_CHARS: usize = 128;

/// Longest robot name, in bytes: a DNS label's limit (RFC 1035), since robot certificates
/// carry the name as a DNS name.
pub const MAX_ROBOT_NAME_LEN: usize = 63;

/// The robot name rule as a literal, so each refusal's reason can quote it (`concat!`).
macro_rules! robot_name_rule {
    () => {
        "robot names are [A-Za-z][A-Za-z0-9_]*, at most 63 bytes"
    };
}

/// The robot name rule in words, as every refusal of a robot name quotes it.
pub const ROBOT_NAME_RULE: &str = robot_name_rule!();

/// A refusal reason followed by the rule, so the reader knows what to write instead.
macro_rules! robot_reason {
    ($reason:literal) => {
        concat!($reason, " (", robot_name_rule!(), ")")
    };
}

fn echoed(raw: &str) -> String {
    raw.chars().take(ECHOED_NAME_CHARS).collect()
}

fn check_robot_name(what: &'static str, raw: &str) -> Result<(), NameError> {
    let err = |reason| NameError {
        what,
        name: echoed(raw),
        reason,
    };
    if raw.is_empty() {
        return Err(err(robot_reason!("must not be empty")));
    }
    if raw.len() > MAX_ROBOT_NAME_LEN {
        return Err(err(robot_reason!("longer than 63 bytes")));
    }
    let mut chars = raw.chars();
    if !chars.next().is_some_and(|c| c.is_ascii_alphabetic()) {
        return Err(err(robot_reason!("must start with an ASCII letter")));
    }
    if !chars.all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(err(robot_reason!(
            "only ASCII letters, digits and '_' are allowed"
        )));
    }
    Ok(())
}

fn check_hub_name(what: &'static str, raw: &str) -> Result<(), NameError> {
    let err = |reason| NameError {
        what,
        name: echoed(raw),
        reason,
    };
    if raw.is_empty() {
        return Err(err("must not be empty (hub names are [A-Za-z0-9_.-]+)"));
    }
    if raw.len() > 128 {
        return Err(err("longer than 128 bytes"));
    }
    if !raw
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.'))
    {
        return Err(err(
            "only ASCII letters, digits, '_', '.' and '-' are allowed (hub names are [A-Za-z0-9_.-]+)",
        ));
    }
    Ok(())
}

fn check_principal(what: &'static str, raw: &str) -> Result<(), NameError> {
    let err = |reason| NameError {
        what,
        name: echoed(raw),
        reason,
    };
    if raw.is_empty() {
        return Err(err("empty"));
    }
    if raw.len() > 256 {
        return Err(err("longer than 256 bytes"));
    }
    if raw.chars().any(|c| c.is_control() || c.is_whitespace()) {
        return Err(err("contains whitespace or control characters"));
    }
    Ok(())
}

macro_rules! name_type {
    ($(#[$doc:meta])* $ty:ident, $what:literal, $check:ident) => {
        $(#[$doc])*
        #[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub struct $ty(Arc<str>);

        impl $ty {
            pub fn new(raw: &str) -> Result<$ty, NameError> {
                $check($what, raw)?;
                Ok($ty(raw.into()))
            }

            pub fn as_str(&self) -> &str {
                &self.0
            }
        }

        impl fmt::Display for $ty {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&self.0)
            }
        }

        impl fmt::Debug for $ty {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                fmt::Debug::fmt(&*self.0, f)
            }
        }

        impl std::str::FromStr for $ty {
            type Err = NameError;
            fn from_str(s: &str) -> Result<$ty, NameError> {
                $ty::new(s)
            }
        }

        impl<'de> serde::Deserialize<'de> for $ty {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<$ty, D::Error> {
                let s = <std::borrow::Cow<'de, str>>::deserialize(d)?;
                $ty::new(&s).map_err(serde::de::Error::custom)
            }
        }

        impl serde::Serialize for $ty {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(&self.0)
            }
        }
    };
}

name_type!(
    /// A robot's name, which is also its namespace: robot `r1` owns `/r1/...`. The rule
    /// is [`ROBOT_NAME_RULE`]; `docs/config.md` (the agent's `name:`) documents it.
    RobotName,
    "robot name",
    check_robot_name
);
name_type!(
    /// A user (person or tool) name: a login name or an OIDC subject/e-mail.
    UserName,
    "user name",
    check_principal
);
name_type!(
    /// A group of users, from the user table, an operator token or a JWT claim.
    GroupName,
    "group name",
    check_principal
);

name_type!(
    /// A hub's name in its federation: the `HUB` of its certificate's `HUB@FLEET`
    /// ([`crate::tls::federation`]), which rules name as `{hub: NAME}`.
    HubName,
    "hub name",
    check_hub_name
);

impl RobotName {
    /// `/<robot>`: the robot's own namespace.
    pub fn namespace(&self) -> String {
        format!("/{}", self.0)
    }

    /// Whether `name` is the namespace itself or lies inside it (`/r1` or `/r1/...`).
    pub fn owns(&self, name: &str) -> bool {
        name.strip_prefix('/')
            .and_then(|rest| rest.strip_prefix(&*self.0))
            .is_some_and(|rest| rest.is_empty() || rest.starts_with('/'))
    }
}

/// Where a connection comes from, as the transport saw it.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ConnInfo {
    /// The TCP peer address.
    pub peer_ip: IpAddr,
    /// The `X-Forwarded-For` header as received (untrusted until resolved).
    pub forwarded_for: Option<String>,
    /// The robot name from a verified TLS client certificate, if any
    /// (see [`crate::tls::client_cert_name`]).
    pub tls_client_name: Option<RobotName>,
    /// The federated hub a request came through (a call another hub forwards for one of
    /// its clients), named by that hub's certificate; `None` for this hub's own clients.
    pub hub: Option<HubName>,
}

impl ConnInfo {
    pub fn new(peer_ip: IpAddr) -> ConnInfo {
        ConnInfo {
            peer_ip,
            forwarded_for: None,
            tls_client_name: None,
            hub: None,
        }
    }

    pub fn with_forwarded_for(mut self, header: impl Into<String>) -> ConnInfo {
        self.forwarded_for = Some(header.into());
        self
    }

    pub fn with_tls_client_name(mut self, name: RobotName) -> ConnInfo {
        self.tls_client_name = Some(name);
        self
    }

    pub fn with_hub(mut self, hub: HubName) -> ConnInfo {
        self.hub = Some(hub);
        self
    }
}

/// Proxies whose `X-Forwarded-For` header is believed.
///
/// The header is a list `client, proxy1, proxy2` that every hop appends to, so anyone can
/// put anything at its start. We walk it from the right, skipping hops that are themselves
/// trusted proxies, and take the first untrusted address: the client as seen by our own
/// outermost proxy. With no trusted proxies the header is ignored entirely.
#[derive(Debug, Clone, Default)]
pub struct TrustedProxies {
    nets: Vec<IpNet>,
}

impl TrustedProxies {
    pub fn new(nets: Vec<IpNet>) -> TrustedProxies {
        TrustedProxies { nets }
    }

    pub fn none() -> TrustedProxies {
        TrustedProxies::default()
    }

    fn trusts(&self, ip: IpAddr) -> bool {
        self.nets.iter().any(|n| n.contains(&ip))
    }

    /// The address to attribute a request to.
    pub fn client_ip(&self, conn: &ConnInfo) -> IpAddr {
        if !self.trusts(conn.peer_ip) {
            return conn.peer_ip;
        }
        let Some(header) = conn.forwarded_for.as_deref() else {
            return conn.peer_ip;
        };
        let mut client = conn.peer_ip;
        for hop in header.rsplit(',') {
            match hop.trim().parse::<IpAddr>() {
                Ok(ip) => {
                    client = ip;
                    if !self.trusts(ip) {
                        break;
                    }
                }
                // A garbled entry ends the trustworthy part; what we have so far stands.
                Err(_) => break,
            }
        }
        client
    }
}

/// What kind of principal an identity is.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum IdentityKind {
    Robot {
        name: RobotName,
    },
    User {
        name: UserName,
        groups: Vec<GroupName>,
    },
    /// No credential; only possible when anonymous read access is enabled.
    Anonymous,
    /// Another hub of the federation, acting for itself: the topics it forwards from its
    /// clients, the subscriptions it holds for them.
    Hub {
        name: HubName,
    },
}

/// An authenticated principal together with where it connected from.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Identity {
    pub kind: IdentityKind,
    pub source: ConnInfo,
    /// The client address after applying [`TrustedProxies`]; ACL CIDR rules and the audit
    /// log use this one.
    pub client_ip: IpAddr,
}

impl Identity {
    /// A short principal label for logs and audit: `robot:r1`, `user:alice`, `anonymous`,
    /// `hub:eu1`; a principal another hub vouches for carries that hub in front
    /// (`hub:eu1/user:alice`).
    pub fn principal(&self) -> String {
        let own = match &self.kind {
            IdentityKind::Robot { name } => format!("robot:{name}"),
            IdentityKind::User { name, .. } => format!("user:{name}"),
            IdentityKind::Anonymous => "anonymous".to_owned(),
            IdentityKind::Hub { name } => return format!("hub:{name}"),
        };
        match &self.source.hub {
            Some(hub) => format!("hub:{hub}/{own}"),
            None => own,
        }
    }

    /// The federated hub this identity is or came through.
    pub fn hub(&self) -> Option<&HubName> {
        match &self.kind {
            IdentityKind::Hub { name } => Some(name),
            _ => self.source.hub.as_ref(),
        }
    }

    pub fn robot(&self) -> Option<&RobotName> {
        match &self.kind {
            IdentityKind::Robot { name } => Some(name),
            _ => None,
        }
    }

    pub fn in_group(&self, group: &GroupName) -> bool {
        matches!(&self.kind, IdentityKind::User { groups, .. } if groups.contains(group))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn conn(peer: &str, xff: Option<&str>) -> ConnInfo {
        let mut c = ConnInfo::new(peer.parse().unwrap());
        c.forwarded_for = xff.map(str::to_owned);
        c
    }

    #[test]
    fn robot_names_are_single_ros_segments() {
        assert!(RobotName::new("r1").is_ok());
        assert!(RobotName::new("robot_7").is_ok());
        for bad in ["", "1r", "r/1", "r1/../r2", "r 1", "_r", "ä"] {
            assert!(RobotName::new(bad).is_err(), "{bad:?} accepted");
        }
    }

    fn refusal(name: &str) -> String {
        RobotName::new(name)
            .expect_err(&format!("{name:?} accepted"))
            .to_string()
    }

    /// Issue 36, item 6: the rule the hub, the agent and the CLI all apply.
    #[test]
    fn issue36_robot_name_must_start_with_a_letter() {
        assert_eq!(
            refusal("1robot"),
            "invalid robot name \"1robot\": must start with an ASCII letter \
             (robot names are [A-Za-z][A-Za-z0-9_]*, at most 63 bytes)"
        );
        assert!(
            refusal("_bot").contains("must start with an ASCII letter"),
            "{}",
            refusal("_bot")
        );
        assert!(RobotName::new("bot_1").is_ok());
        assert!(RobotName::new("B").is_ok());
    }

    #[test]
    fn issue36_robot_name_is_at_most_63_bytes() {
        let longest = format!("r{}", "0".repeat(62));
        assert_eq!(longest.len(), 63);
        assert_eq!(RobotName::new(&longest).unwrap().as_str(), longest);
        let too_long = format!("{longest}0");
        let err = refusal(&too_long);
        assert!(err.contains("longer than 63 bytes"), "{err}");
        assert!(err.contains(&too_long), "names the refused name: {err}");
        // The rule text and the limit the check applies agree.
        assert!(ROBOT_NAME_RULE.contains(&format!("at most {MAX_ROBOT_NAME_LEN} bytes")));
        // A huge name is refused on its length, and echoed only in part.
        let huge = "r".repeat(100_000);
        assert!(refusal(&huge).len() < 400);
    }

    #[test]
    fn issue36_robot_name_refusals_name_the_problem_and_the_rule() {
        for (bad, problem) in [
            ("", "must not be empty"),
            ("r/1", "only ASCII letters, digits and '_' are allowed"),
            ("/r1", "must start with an ASCII letter"),
            ("r1/../r2", "only ASCII letters, digits and '_' are allowed"),
            ("r 1", "only ASCII letters, digits and '_' are allowed"),
            ("robot-1", "only ASCII letters, digits and '_' are allowed"),
            ("ä", "must start with an ASCII letter"),
            ("rö", "only ASCII letters, digits and '_' are allowed"),
            // Unicode letters and digits that look ASCII are still refused.
            ("ｒ1", "must start with an ASCII letter"),
            ("r١", "only ASCII letters, digits and '_' are allowed"),
        ] {
            let err = refusal(bad);
            assert!(err.contains(problem), "{bad:?}: {err}");
            assert!(err.contains(ROBOT_NAME_RULE), "{bad:?}: {err}");
            assert!(err.contains(&format!("{bad:?}")), "{bad:?}: {err}");
        }
    }

    #[test]
    fn robot_owns_only_its_namespace() {
        let r = RobotName::new("r1").unwrap();
        assert!(r.owns("/r1"));
        assert!(r.owns("/r1/cmd_vel"));
        assert!(!r.owns("/r10/cmd_vel"));
        assert!(!r.owns("/r2/r1/x"));
        assert!(!r.owns("r1/x"));
    }

    #[test]
    fn forwarded_for_ignored_from_untrusted_peer() {
        let proxies = TrustedProxies::new(vec!["10.0.0.1/32".parse().unwrap()]);
        let c = conn("203.0.113.9", Some("127.0.0.1"));
        assert_eq!(
            proxies.client_ip(&c),
            "203.0.113.9".parse::<IpAddr>().unwrap()
        );
    }

    #[test]
    fn forwarded_for_walks_from_the_right_through_trusted_hops() {
        let proxies = TrustedProxies::new(vec!["10.0.0.0/24".parse().unwrap()]);
        // The client forged "127.0.0.1" at the start; the real client is 198.51.100.7.
        let c = conn("10.0.0.1", Some("127.0.0.1, 198.51.100.7, 10.0.0.2"));
        assert_eq!(
            proxies.client_ip(&c),
            "198.51.100.7".parse::<IpAddr>().unwrap()
        );
        let garbled = conn("10.0.0.1", Some("nonsense"));
        assert_eq!(
            proxies.client_ip(&garbled),
            "10.0.0.1".parse::<IpAddr>().unwrap()
        );
    }
}
