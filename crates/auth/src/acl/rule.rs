//! The rule model: who ([`Subject`]) may do what ([`OpSet`]) on which names ([`NamePattern`]).
//!
//! Design choice: a pattern is compiled when the rule is built — from YAML, from the
//! database or from an API body — so an invalid or oversized regex is refused at the door
//! with a message and never reaches the decision path. Patterns match the *whole* name
//! (`^(?:…)$` is added), because a rule for `/r1/cmd` must not also grant `/r1/cmd_x`.
//! The `regex` crate runs in linear time, so "catastrophic backtracking" cannot happen;
//! what remains is size, bounded by a length limit and the compiled-program size limits.

use std::fmt;
use std::sync::Arc;

use ipnet::IpNet;
use regex::{Regex, RegexBuilder};
use serde::{Deserialize, Serialize};

use crate::identity::{GroupName, HubName, Identity, IdentityKind, RobotName, UserName};

/// Something a client can do with a named topic, service or action.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Operation {
    /// Advertise and publish a topic.
    Publish,
    /// Subscribe to a topic, see it in listings, and keep receiving it (checked on delivery).
    Subscribe,
    /// Call a service (including the hub's own `/rosapi/*` services).
    CallService,
    /// Offer a service to others.
    AdvertiseService,
    /// Send a goal to an action, and cancel it.
    SendActionGoal,
    /// Offer an action server.
    AdvertiseAction,
    /// Administer the hub through its REST API/CLI; names are API resources (`/rules`, …).
    Admin,
}

impl Operation {
    pub const ALL: [Operation; 7] = [
        Operation::Publish,
        Operation::Subscribe,
        Operation::CallService,
        Operation::AdvertiseService,
        Operation::SendActionGoal,
        Operation::AdvertiseAction,
        Operation::Admin,
    ];

    pub(crate) fn index(self) -> usize {
        self as usize
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Operation::Publish => "publish",
            Operation::Subscribe => "subscribe",
            Operation::CallService => "call_service",
            Operation::AdvertiseService => "advertise_service",
            Operation::SendActionGoal => "send_action_goal",
            Operation::AdvertiseAction => "advertise_action",
            Operation::Admin => "admin",
        }
    }

    pub fn parse(s: &str) -> Option<Operation> {
        Operation::ALL.into_iter().find(|op| op.as_str() == s)
    }
}

impl fmt::Display for Operation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A set of operations. Serialized as a list of names; `all` stands for every operation.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct OpSet(u8);

impl OpSet {
    pub const EMPTY: OpSet = OpSet(0);
    pub const ALL: OpSet = OpSet((1 << Operation::ALL.len()) - 1);

    pub fn of(ops: &[Operation]) -> OpSet {
        OpSet(ops.iter().fold(0, |acc, op| acc | 1 << op.index()))
    }

    pub fn contains(self, op: Operation) -> bool {
        self.0 & (1 << op.index()) != 0
    }

    pub fn iter(self) -> impl Iterator<Item = Operation> {
        Operation::ALL
            .into_iter()
            .filter(move |op| self.contains(*op))
    }
}

impl fmt::Debug for OpSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_set().entries(self.iter()).finish()
    }
}

impl Serialize for OpSet {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if *self == OpSet::ALL {
            return ["all"].serialize(s);
        }
        let names: Vec<&str> = self.iter().map(Operation::as_str).collect();
        names.serialize(s)
    }
}

impl<'de> Deserialize<'de> for OpSet {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<OpSet, D::Error> {
        let names = Vec::<String>::deserialize(d)?;
        let mut set = OpSet::EMPTY;
        for name in &names {
            if name == "all" {
                set = OpSet::ALL;
                continue;
            }
            let op = Operation::parse(name).ok_or_else(|| {
                serde::de::Error::custom(format!(
                    "unknown operation {name:?} (expected one of: all, {})",
                    Operation::ALL.map(Operation::as_str).join(", ")
                ))
            })?;
            set.0 |= 1 << op.index();
        }
        Ok(set)
    }
}

/// Whether a matching rule grants or forbids. A matching `deny` wins over any `allow`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Effect {
    #[default]
    Allow,
    Deny,
}

/// Whom a rule applies to.
///
/// In YAML: `{user: alice}`, `{group: operators}`, `{robot: r1}`, `{cidr: 10.8.0.0/16}`,
/// `{hub: eu1}` (a federated hub: what it forwards itself and every call it forwards for
/// its clients), or one of the words `any_robot`, `any_user`, `any_hub`, `anonymous`,
/// `anyone` (every identity, anonymous included).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Subject {
    User(UserName),
    Group(GroupName),
    Robot(RobotName),
    /// Identities whose resolved client address lies in this network.
    Cidr(IpNet),
    /// A hub of the federation, named by its certificate: the hub itself, and every
    /// identity it vouches for.
    Hub(HubName),
    AnyRobot,
    AnyUser,
    AnyHub,
    Anonymous,
    Anyone,
}

impl Subject {
    /// Whether the subject names hubs: a `deny` for one binds even the admins another hub
    /// vouches for.
    pub fn is_hub(&self) -> bool {
        matches!(self, Subject::Hub(_) | Subject::AnyHub)
    }

    pub fn matches(&self, id: &Identity) -> bool {
        match (self, &id.kind) {
            (Subject::User(u), IdentityKind::User { name, .. }) => u == name,
            (Subject::Group(g), IdentityKind::User { groups, .. }) => groups.contains(g),
            (Subject::Robot(r), IdentityKind::Robot { name }) => r == name,
            (Subject::Cidr(net), _) => net.contains(&id.client_ip),
            (Subject::Hub(h), _) => id.hub() == Some(h),
            (Subject::AnyHub, _) => id.hub().is_some(),
            (Subject::AnyRobot, IdentityKind::Robot { .. }) => true,
            (Subject::AnyUser, IdentityKind::User { .. }) => true,
            (Subject::Anonymous, IdentityKind::Anonymous) => true,
            (Subject::Anyone, _) => true,
            _ => false,
        }
    }
}

/// Longest pattern source accepted, in bytes.
pub const MAX_PATTERN_LEN: usize = 512;
/// Compiled-program and lazy-DFA budgets per pattern, in bytes.
const REGEX_SIZE_LIMIT: usize = 256 * 1024;
const REGEX_DFA_LIMIT: usize = 1024 * 1024;
const REGEX_NEST_LIMIT: u32 = 32;

/// Why a pattern was refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PatternError {
    #[error("pattern is {len} bytes, longer than the limit of {MAX_PATTERN_LEN}")]
    TooLong { len: usize },
    #[error("invalid or too complex pattern {pattern:?}: {reason}")]
    Invalid { pattern: String, reason: String },
}

/// A regex over whole topic/service/action names, compiled within size limits.
#[derive(Clone)]
pub struct NamePattern {
    source: Arc<str>,
    regex: Regex,
}

impl NamePattern {
    pub fn new(source: &str) -> Result<NamePattern, PatternError> {
        if source.len() > MAX_PATTERN_LEN {
            return Err(PatternError::TooLong { len: source.len() });
        }
        let regex = RegexBuilder::new(&format!("^(?:{source})$"))
            .size_limit(REGEX_SIZE_LIMIT)
            .dfa_size_limit(REGEX_DFA_LIMIT)
            .nest_limit(REGEX_NEST_LIMIT)
            .build()
            .map_err(|e| PatternError::Invalid {
                pattern: source.to_owned(),
                reason: e.to_string(),
            })?;
        Ok(NamePattern {
            source: source.into(),
            regex,
        })
    }

    pub fn as_str(&self) -> &str {
        &self.source
    }

    pub fn is_match(&self, name: &str) -> bool {
        self.regex.is_match(name)
    }
}

impl fmt::Debug for NamePattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&*self.source, f)
    }
}

impl PartialEq for NamePattern {
    fn eq(&self, other: &NamePattern) -> bool {
        self.source == other.source
    }
}

impl Eq for NamePattern {}

impl Serialize for NamePattern {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.source)
    }
}

impl<'de> Deserialize<'de> for NamePattern {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<NamePattern, D::Error> {
        let s = <std::borrow::Cow<'de, str>>::deserialize(d)?;
        NamePattern::new(&s).map_err(serde::de::Error::custom)
    }
}

/// One access rule.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rule {
    pub subject: Subject,
    /// Whole-name regex, e.g. `/r[0-9]+/cmd_vel` or `/fleet/.*`.
    pub names: NamePattern,
    pub ops: OpSet,
    #[serde(default)]
    pub effect: Effect,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub comment: Option<String>,
}

/// A rule's row id in the database; stable across edits of other rules.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(transparent)]
pub struct RuleId(pub i64);

impl fmt::Display for RuleId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{}", self.0)
    }
}

/// A rule as stored, with its id.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct StoredRule {
    pub id: RuleId,
    #[serde(flatten)]
    pub rule: Rule,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn patterns_match_whole_names_only() {
        let p = NamePattern::new("/r1/cmd").unwrap();
        assert!(p.is_match("/r1/cmd"));
        assert!(!p.is_match("/r1/cmd_x"));
        assert!(!p.is_match("/x/r1/cmd"));
        let alt = NamePattern::new("/a|/b").unwrap();
        assert!(
            !alt.is_match("/a/x"),
            "alternation must stay inside the anchors"
        );
    }

    #[test]
    fn opset_round_trips_names_and_all() {
        let set: OpSet = serde_json::from_str(r#"["publish","call_service"]"#).unwrap();
        assert!(set.contains(Operation::Publish) && set.contains(Operation::CallService));
        assert!(!set.contains(Operation::Subscribe));
        let all: OpSet = serde_json::from_str(r#"["all"]"#).unwrap();
        assert_eq!(all, OpSet::ALL);
        assert_eq!(serde_json::to_string(&all).unwrap(), r#"["all"]"#);
        assert!(serde_json::from_str::<OpSet>(r#"["fly"]"#).is_err());
    }
}
