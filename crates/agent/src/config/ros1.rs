//! `ros1:` — the native ROS 1 bridge (crates/ros1): which master, which node, and what
//! crosses between the robot's ROS graph and the fleet. Reference in docs/config.md.

use std::time::Duration;

use serde::{Deserialize, Deserializer};

/// The agent as a node of the robot's ROS 1 graph.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros1Config {
    /// `http://host:port` of the master. Default: `ROS_MASTER_URI`, else
    /// `http://localhost:11311`.
    pub master_uri: Option<String>,
    /// The node's name in the graph. Default `/fleetlink_<robot name>`.
    pub node_name: Option<String>,
    /// Host name or IP other nodes reach this one at. Default: `ROS_HOSTNAME`, else
    /// `ROS_IP`, else the machine's host name.
    pub host: Option<String>,
    /// Local topics sent up to the hub. A list is short for its `include`.
    #[serde(deserialize_with = "list_or_mapping")]
    pub publish: Ros1Publish,
    /// Topics of the agent's router (hub topics brought down, e.g. `/cmd_vel` for the
    /// hub's `/<robot>/cmd_vel`) published into the graph.
    pub subscribe: Vec<String>,
    /// Services both ways. A list is short for its `expose`.
    #[serde(deserialize_with = "list_or_mapping")]
    pub services: Ros1Services,
    /// Master polling period for new publishers/services and master restarts. Default
    /// 1000.
    pub discovery_ms: u64,
    /// How long a local caller of a fleet service waits. Default 10000.
    pub call_timeout_ms: u64,
    /// Offer the master's parameters to the fleet (rosapi's parameter services under
    /// `/<robot>/rosapi/`, which the hub's `/rosapi/get_param` of `/<robot>/...` reaches).
    /// Default true.
    pub parameters: bool,
}

impl Default for Ros1Config {
    fn default() -> Self {
        Self {
            master_uri: None,
            node_name: None,
            host: None,
            publish: Ros1Publish::default(),
            subscribe: Vec::new(),
            services: Ros1Services::default(),
            discovery_ms: 1000,
            call_timeout_ms: 10_000,
            parameters: true,
        }
    }
}

/// Whole-name regular expressions; a plain topic name matches itself.
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros1Publish {
    /// Topics (names or patterns) bridged when a local node publishes them.
    pub include: Vec<String>,
    /// Topics never bridged, even when `include` matches.
    pub exclude: Vec<String>,
}

#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros1Services {
    /// Local ROS services (names or patterns) offered to the fleet, under the robot's
    /// namespace on the hub.
    pub expose: Vec<String>,
    /// Local services never exposed.
    pub exclude: Vec<String>,
    /// Fleet services (as the agent names them: `/cloud/plan`, `/robot2/set_mode`)
    /// offered to local nodes as ROS services.
    pub offer: Vec<String>,
}

/// A section that may be written as the list its main key takes: `publish: [/chatter]`
/// for `publish: { include: [/chatter] }`.
pub(super) trait Shorthand: Default + for<'de> Deserialize<'de> {
    /// The shapes accepted, each with an example (the text of a shape error).
    const EXPECTING: &'static str;
    fn from_list(names: Vec<String>) -> Self;
}

impl Shorthand for Ros1Publish {
    const EXPECTING: &'static str = "a list of topics (`publish: [/chatter, /tf]`) or a \
        mapping (`publish: { include: ['/sensors/.*'], exclude: [/camera/raw] }`)";
    fn from_list(include: Vec<String>) -> Self {
        Self {
            include,
            ..Self::default()
        }
    }
}

impl Shorthand for Ros1Services {
    const EXPECTING: &'static str = "a list of local services to expose (`services: \
        [/set_mode]`) or a mapping (`services: { expose: [/set_mode], offer: [/cloud/plan] }`)";
    fn from_list(expose: Vec<String>) -> Self {
        Self {
            expose,
            ..Self::default()
        }
    }
}

/// Reads a [`Shorthand`] section: a mapping, a list, one name, or nothing (the default).
pub(super) fn list_or_mapping<'de, D: Deserializer<'de>, T: Shorthand>(
    deserializer: D,
) -> Result<T, D::Error> {
    struct Shape<T>(std::marker::PhantomData<T>);
    impl<'de, T: Shorthand> serde::de::Visitor<'de> for Shape<T> {
        type Value = T;

        fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str(T::EXPECTING)
        }

        fn visit_unit<E: serde::de::Error>(self) -> Result<T, E> {
            Ok(T::default())
        }

        fn visit_none<E: serde::de::Error>(self) -> Result<T, E> {
            Ok(T::default())
        }

        fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<T, E> {
            Ok(T::from_list(vec![name.to_owned()]))
        }

        fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<T, A::Error> {
            let mut names = Vec::new();
            while let Some(name) = seq.next_element::<String>()? {
                names.push(name);
            }
            Ok(T::from_list(names))
        }

        fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<T, A::Error> {
            T::deserialize(serde::de::value::MapAccessDeserializer::new(map))
        }
    }
    deserializer.deserialize_any(Shape(std::marker::PhantomData))
}

impl Ros1Config {
    pub fn discovery(&self) -> Duration {
        Duration::from_millis(self.discovery_ms)
    }

    pub fn call_timeout(&self) -> Duration {
        Duration::from_millis(self.call_timeout_ms)
    }
}
