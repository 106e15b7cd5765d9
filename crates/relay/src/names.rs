//! Identifier newtypes, so a topic name, a client and a topic index cannot be mixed up.

use std::fmt;
use std::sync::Arc;

/// A validated, absolute topic name such as `/robot1/scan`. Cheap to clone.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TopicName(Arc<str>);

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("invalid topic name {name:?}: {reason}")]
pub struct NameError {
    pub name: String,
    pub reason: &'static str,
}

/// The one name rule every gate decides on: a ROS-style name with its leading `/` added
/// (rosbridge clients often omit it) and trailing `/` dropped, so `scan`, `/scan` and
/// `/scan/` are one name; empty names, empty segments (`//`), whitespace, control
/// characters and names over 1024 bytes are refused. A name already in that form is
/// borrowed as it is (the check on a per-message path allocates nothing).
pub fn normalize(raw: &str) -> Result<std::borrow::Cow<'_, str>, NameError> {
    let err = |reason| NameError {
        name: raw.chars().take(200).collect(),
        reason,
    };
    if raw.is_empty() || raw == "/" {
        return Err(err("empty"));
    }
    if raw.len() > 1024 {
        return Err(err("longer than 1024 bytes"));
    }
    if raw.chars().any(|c| c.is_whitespace() || c.is_control()) {
        return Err(err("contains whitespace or control characters"));
    }
    if raw.contains("//") {
        return Err(err("contains an empty segment"));
    }
    let trimmed = raw.trim_end_matches('/');
    if trimmed.is_empty() {
        return Err(err("empty"));
    }
    if raw.starts_with('/') {
        Ok(std::borrow::Cow::Borrowed(trimmed))
    } else {
        Ok(std::borrow::Cow::Owned(format!("/{trimmed}")))
    }
}

impl TopicName {
    /// Accepts ROS-style names by the one rule, [`normalize`]: `scan`, `/scan` and
    /// `/scan/` are the same topic.
    pub fn parse(raw: &str) -> Result<TopicName, NameError> {
        Ok(TopicName(normalize(raw)?.as_ref().into()))
    }

    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// `namespace` + `self`, e.g. `/robot1` + `/scan` = `/robot1/scan`.
    pub fn in_namespace(&self, namespace: &str) -> TopicName {
        let ns = namespace.trim_end_matches('/');
        if ns.is_empty() {
            return self.clone();
        }
        TopicName(format!("{ns}{}", self.0).into())
    }

    /// The name relative to `namespace` when it lies inside it.
    pub fn strip_namespace(&self, namespace: &str) -> Option<TopicName> {
        let ns = namespace.trim_end_matches('/');
        let rest = self.0.strip_prefix(ns)?;
        rest.starts_with('/').then(|| TopicName(rest.into()))
    }
}

/// Lets maps keyed by topic name be searched with the name as a client spelled it.
impl std::borrow::Borrow<str> for TopicName {
    fn borrow(&self) -> &str {
        &self.0
    }
}

impl fmt::Display for TopicName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl fmt::Debug for TopicName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", &*self.0)
    }
}

/// One connection (or in-process participant) attached to a router.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, PartialOrd, Ord)]
pub struct ClientId(pub u64);

impl fmt::Display for ClientId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "c{}", self.0)
    }
}

/// A topic's index in one router; used as the alias of the topic on every downstream
/// `fleetlink.v1` link, so a message's frame is the same bytes for every subscriber.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, PartialOrd, Ord)]
pub struct TopicId(pub u32);

/// Whole-name include/exclude patterns (a plain name is a pattern matching itself).
#[derive(Debug, Clone, Default)]
pub struct NameFilter {
    pub include: Vec<regex::Regex>,
    pub exclude: Vec<regex::Regex>,
}

impl NameFilter {
    /// Compiles patterns as whole-name regexes (`^(?:p)$`).
    pub fn new(include: &[String], exclude: &[String]) -> Result<NameFilter, regex::Error> {
        let compile = |ps: &[String]| {
            ps.iter()
                .map(|p| regex::Regex::new(&format!("^(?:{p})$")))
                .collect::<Result<Vec<_>, _>>()
        };
        Ok(NameFilter {
            include: compile(include)?,
            exclude: compile(exclude)?,
        })
    }

    pub fn matches(&self, name: &str) -> bool {
        self.include.iter().any(|r| r.is_match(name))
            && !self.exclude.iter().any(|r| r.is_match(name))
    }

    pub fn is_empty(&self) -> bool {
        self.include.is_empty()
    }
}

/// A robot's configuration service answering with the configuration in force (the
/// agent's local name; on the hub `/<robot>/fleetlink/config/get`).
pub const CONFIG_GET_SERVICE: &str = "/fleetlink/config/get";
/// A robot's configuration service applying a change (JSON `{"change": TEXT, "by": WHO}`).
pub const CONFIG_SET_SERVICE: &str = "/fleetlink/config/set";
/// The configuration services' type name (their requests and answers are JSON).
pub const CONFIG_SERVICE_TYPE: &str = "fleetlink/RuntimeConfig";
/// A robot's black-box service cutting a slice of its ring (the agent's local name).
pub const BLACKBOX_FETCH_SERVICE: &str = "/fleetlink/blackbox/fetch";
/// The topic a robot sends black-box slices on (the agent's local name).
pub const BLACKBOX_DATA_TOPIC: &str = "/fleetlink/blackbox/data";

/// A name of a robot's that only the hub itself uses: the services it calls for its API
/// (configuration, black box) and the topic the black box answers on. No client calls,
/// reads or lists them, whatever its rights; the hub's API decides who may ask for what
/// they carry and filters it by the asker's rights.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HubOnly {
    /// `/<robot>/fleetlink/config/get|set`.
    ConfigService,
    /// `/<robot>/fleetlink/blackbox/fetch`.
    BlackboxService,
    /// `/<robot>/fleetlink/blackbox/data`: only the robot publishes it.
    BlackboxData,
}

/// Whether `name` (normalized, as the hub names it: `/<robot>/...`, or
/// `/<site>/<robot>/...` for a site hub's robots) is one of a robot's hub-only names, and
/// the namespace it lies in (`robot1`, `site7/robot1`).
pub fn hub_only(name: &str) -> Option<(HubOnly, &str)> {
    [
        (CONFIG_GET_SERVICE, HubOnly::ConfigService),
        (CONFIG_SET_SERVICE, HubOnly::ConfigService),
        (BLACKBOX_FETCH_SERVICE, HubOnly::BlackboxService),
        (BLACKBOX_DATA_TOPIC, HubOnly::BlackboxData),
    ]
    .into_iter()
    .find_map(|(local, kind)| {
        let ns = name.strip_suffix(local)?.strip_prefix('/')?;
        (!ns.is_empty()).then_some((kind, ns))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hub_only_names_are_a_robots_fleetlink_services_and_black_box_topic() {
        assert_eq!(
            hub_only("/r1/fleetlink/config/set"),
            Some((HubOnly::ConfigService, "r1"))
        );
        assert_eq!(
            hub_only("/r1/fleetlink/blackbox/fetch"),
            Some((HubOnly::BlackboxService, "r1"))
        );
        assert_eq!(
            hub_only("/r1/fleetlink/blackbox/data"),
            Some((HubOnly::BlackboxData, "r1"))
        );
        assert_eq!(
            hub_only("/site7/r1/fleetlink/config/get"),
            Some((HubOnly::ConfigService, "site7/r1"))
        );
        for other in [
            "/fleetlink/blackbox/data",
            "/r1/fleetlink/blackbox",
            "/r1/odom",
            "/r1/fleetlink/config/set/x",
        ] {
            assert_eq!(hub_only(other), None, "{other}");
        }
    }

    #[test]
    fn normalize_borrows_what_is_already_normal() {
        assert!(matches!(
            normalize("/a/b").unwrap(),
            std::borrow::Cow::Borrowed("/a/b")
        ));
        assert!(matches!(
            normalize("/a/b/").unwrap(),
            std::borrow::Cow::Borrowed("/a/b")
        ));
        assert_eq!(normalize("a/b").unwrap(), "/a/b");
        for bad in ["", "/", "//", "a//b", "/a b", "/a\n", "///"] {
            assert!(normalize(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn leading_slash_is_added_and_trailing_removed() {
        assert_eq!(TopicName::parse("scan").unwrap().as_str(), "/scan");
        assert_eq!(TopicName::parse("/a/b/").unwrap().as_str(), "/a/b");
    }

    #[test]
    fn bad_names_are_refused_with_a_reason() {
        for bad in ["", "/", "a b", "/a//b", "x\u{0}"] {
            assert!(TopicName::parse(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn namespaces_compose_and_strip() {
        let scan = TopicName::parse("/scan").unwrap();
        let full = scan.in_namespace("/robot1");
        assert_eq!(full.as_str(), "/robot1/scan");
        assert_eq!(full.strip_namespace("/robot1").unwrap(), scan);
        assert!(full.strip_namespace("/robot").is_none());
    }

    #[test]
    fn filter_includes_then_excludes_whole_names() {
        let f = NameFilter::new(&[".*".into()], &["/camera/raw".into()]).unwrap();
        assert!(f.matches("/scan"));
        assert!(!f.matches("/camera/raw"));
        assert!(f.matches("/camera/raw/compressed"));
        let f = NameFilter::new(&["/scan".into()], &[]).unwrap();
        assert!(!f.matches("/scan2"));
        assert!(NameFilter::default().is_empty());
        assert!(!NameFilter::default().matches("/x"));
    }
}
