//! Agent configuration: the YAML file `fleetlink agent --config robot.yaml` starts from.
//!
//! Every field is optional; [`AgentConfig::default`] is a working agent (hub on localhost,
//! local rosbridge listener on 127.0.0.1:9090, no simulator). The reference with every field
//! and default is `docs/config.md`; `examples/agent.yaml` is a commented example.
//!
//! Design: errors name the file, line, column and field, for all three kinds of mistakes:
//!
//! - YAML syntax (`name: [a`) — position from the parser (serde-saphyr), no field;
//! - wrong type or unknown key (`deny_unknown_fields` everywhere) — position from the parser,
//!   field path recovered by mapping the position back onto the document
//!   ([`locate::LocationTree::path_at`]);
//! - semantic checks on the typed value (`rate_hz: 0`, topic names, duplicates, `listen`
//!   that is not an `IP:PORT`; [`validate`]) — field path from the check, position by
//!   looking the path up in the document ([`locate::LocationTree::position_of`]).
//!
//! The typed structs stay span-free plain data; the location tree is a second parse of the
//! same text that only happens when there is an error to report.
//!
//! The `topics:` key holds per-topic QoS for the uplink (`priority`, `rate_limit_hz`,
//! `policy`, `queue`, `no_drop`; reference in docs/qos.md), checked here like every other
//! field.

mod locate;
pub mod origin;
mod ros1;
mod ros2;
mod rosbridge;
mod rosgw;
pub mod runtime;
mod sim;
mod source;
mod validate;
mod video;

use std::collections::BTreeMap;
use std::fmt;
use std::net::SocketAddr;
use std::path::PathBuf;
use std::time::Duration;

use fleetlink_auth::RobotName;
use serde::{Deserialize, Deserializer};
use serde_saphyr::MessageFormatter;

use locate::{FieldPath, LocationTree, Segment};
pub use ros1::{Ros1Config, Ros1Publish, Ros1Services};
pub use ros2::{Ros2Actions, Ros2Config};
pub use rosbridge::RosbridgeConfig;
pub use sim::{
    ImageSim, LaserScanSim, MarkersSim, OdometrySim, PointCloudSim, PoseSim, SimConfig, period_of,
};
pub use source::ConfigSource;
pub use video::VideoStreamConfig;

/// The agent's configuration. See `docs/config.md` for every field.
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct AgentConfig {
    /// Hub URLs, `ws://` or `wss://`, in the order to try them: YAML `hub:` takes one URL
    /// or a list. The agent stays on the hub it is connected to and moves on to the next
    /// only when that one fails (`uplink::failover`). Default `[ws://127.0.0.1:8080]`.
    /// CLI `--hub` (repeatable) replaces the list.
    #[serde(deserialize_with = "one_or_more_urls")]
    pub hub: Vec<String>,
    /// Robot name (the rule is [`fleetlink_auth::RobotName`]'s; a name breaking it is
    /// refused while parsing, at its line); its topics appear on the hub under `/<name>`.
    /// Default `robot1`. CLI `--name` overrides.
    pub name: RobotName,
    /// The robot this agent mirrors, if it is a mirror (docs/mirror.md): it runs beside
    /// offloaded nodes (in the cloud), which see the robot's topics, services and actions
    /// under the robot's own local names, and their outputs go to the robot. `name` is
    /// then the mirror's own (default `<robot>_mirror`). CLI `--mirror` overrides.
    pub mirror: Option<RobotName>,
    /// Credential presented to the hub. Default empty (no credential).
    pub token: String,
    /// TLS for a `wss://` hub: a private CA and, for mutual TLS, the robot's certificate.
    /// Default `None`: a `wss://` hub is checked against the system's roots.
    pub tls: Option<TlsConfig>,
    /// Ping interval in milliseconds; the link is declared dead after two intervals of
    /// silence. Default 1000.
    pub heartbeat_ms: u64,
    /// Reconnect backoff.
    pub reconnect: ReconnectConfig,
    /// Local rosbridge v2 listener; `None` (`local_rosbridge: null`) disables it.
    pub local_rosbridge: Option<LocalRosbridgeConfig>,
    /// Local topic → hub topic. Topics not listed go to `/<name><local topic>`.
    pub remap: BTreeMap<String, String>,
    /// Hub topics delivered to local subscribers.
    pub subscribe: Vec<Subscription>,
    /// Simulated robot; `None` (the default) runs no simulator.
    pub sim: Option<SimConfig>,
    /// The native ROS 1 bridge; `None` (the default) runs none. See docs/ros1.md.
    pub ros1: Option<Ros1Config>,
    /// The native ROS 2 bridge; `None` (the default) runs none. See docs/ros2.md.
    pub ros2: Option<Ros2Config>,
    /// The rosbridge client of the robot's own rosbridge server; `None` (the default)
    /// runs none. See docs/rosbridge-client.md.
    pub rosbridge: Option<RosbridgeConfig>,
    /// Per-topic QoS of the uplink, by local topic name (see docs/qos.md); topics not
    /// listed get the defaults for their type.
    pub topics: BTreeMap<String, fleetlink_qos::TopicQosSpec>,
    /// The durable outbox for `no_drop` topics; `None` (the default) keeps them in memory,
    /// which survives link outages but not an agent restart.
    pub outbox: Option<OutboxConfig>,
    /// Most megabytes of topics' latest messages kept for the hub (sent at once when
    /// someone starts watching a topic, or asks for a pull topic). A topic whose latest
    /// message does not fit has none kept. Default 64; 0 keeps none.
    pub latest_cache_mb: u64,
    /// The robot's link: its data budget.
    pub link: LinkSettings,
    /// The black box: chosen local topics kept on disk in MCAP, from which the hub can
    /// fetch a slice; `None` (the default) keeps none. See docs/recording.md.
    pub blackbox: Option<BlackBoxConfig>,
    /// Where the changes made while the agent runs are kept, restored at its next start
    /// (docs/runtime-config.md). Default: `<name>/runtime.json` in the state directory
    /// ([`AgentConfig::runtime_file_path`]).
    pub runtime_file: Option<PathBuf>,
    /// Camera topics offered as H.264 video, keyed by the camera topic (docs/video.md).
    pub video: BTreeMap<String, VideoStreamConfig>,
    /// Cisco's prebuilt OpenH264 library (`libopenh264.so.7`) to encode video with, instead
    /// of the one built into fleetlink (docs/video.md says when one would).
    pub openh264_library: Option<PathBuf>,
}

/// `blackbox:` — a ring buffer of local topics on the robot's disk, in MCAP segments, the
/// oldest deleted past `max_mb`. It keeps its topics whether or not they are sent.
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct BlackBoxConfig {
    /// Directory of the ring (`ring/`) and of slices cut for the hub (`slices/`). Required.
    pub dir: String,
    /// Most megabytes (MiB) of segments kept. Default 512; at least 8.
    pub max_mb: u64,
    /// Whole-name patterns of the local topics to keep. Required.
    pub topics: Vec<String>,
    /// `zstd` (the default) or `none`.
    pub compression: fleetlink_record::Compression,
}

impl Default for BlackBoxConfig {
    fn default() -> Self {
        BlackBoxConfig {
            dir: String::new(),
            max_mb: 512,
            topics: Vec::new(),
            compression: fleetlink_record::Compression::Zstd,
        }
    }
}

/// `link:` — what the robot's link may carry.
#[derive(Debug, Clone, Default, PartialEq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct LinkSettings {
    /// A data budget; `None` (the default): none.
    pub budget: Option<BudgetSettings>,
}

/// `link.budget:` — at most `max_kbps` and/or `mb_per_day` on the link; as the budget is
/// spent, topics below `protect_priority` are thinned, lowest priority first
/// (docs/qos.md, "A data budget").
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct BudgetSettings {
    /// Kilobits per second (1 kbit = 1,000 bits), bytes on the wire.
    #[serde(default)]
    pub max_kbps: Option<f64>,
    /// Megabytes (10^6 bytes) a day, at an even pace (an hour of it may go in a burst).
    #[serde(default)]
    pub mb_per_day: Option<f64>,
    /// Topics of this priority or more are never held back. Default 10 (motion commands
    /// and emergency stops; no-drop topics are never held back either).
    #[serde(default = "default_protect_priority")]
    pub protect_priority: f32,
}

fn default_protect_priority() -> f32 {
    fleetlink_qos::budget::DEFAULT_PROTECT_PRIORITY
}

impl BudgetSettings {
    /// The scheduler's form.
    pub fn to_config(&self) -> fleetlink_qos::BudgetConfig {
        fleetlink_qos::BudgetConfig {
            max_bytes_per_sec: self.max_kbps.map(|k| k * 1000.0 / 8.0),
            bytes_per_day: self.mb_per_day.map(|m| m * 1e6),
            protect_priority: self.protect_priority,
        }
    }
}

impl Default for AgentConfig {
    fn default() -> Self {
        Self {
            hub: vec!["ws://127.0.0.1:8080".to_owned()],
            name: RobotName::new("robot1").expect("robot1 is a valid robot name"),
            mirror: None,
            token: String::new(),
            tls: None,
            heartbeat_ms: 1000,
            reconnect: ReconnectConfig::default(),
            local_rosbridge: Some(LocalRosbridgeConfig::default()),
            remap: BTreeMap::new(),
            subscribe: Vec::new(),
            sim: None,
            ros1: None,
            ros2: None,
            rosbridge: None,
            topics: BTreeMap::new(),
            outbox: None,
            latest_cache_mb: 64,
            link: LinkSettings::default(),
            blackbox: None,
            runtime_file: None,
            video: BTreeMap::new(),
            openh264_library: None,
        }
    }
}

/// Exponential reconnect backoff with jitter, from `initial_ms` doubling up to `max_ms`.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct ReconnectConfig {
    /// First retry delay. Default 250.
    pub initial_ms: u64,
    /// Largest retry delay. Default 10000.
    pub max_ms: u64,
}

impl Default for ReconnectConfig {
    fn default() -> Self {
        Self {
            initial_ms: 250,
            max_ms: 10_000,
        }
    }
}

impl ReconnectConfig {
    pub fn initial(&self) -> Duration {
        Duration::from_millis(self.initial_ms)
    }

    pub fn max(&self) -> Duration {
        Duration::from_millis(self.max_ms)
    }
}

/// `outbox:` — where `no_drop` messages wait on disk until the hub confirms them.
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct OutboxConfig {
    /// Directory of the outbox file (created if missing). One agent per directory.
    pub dir: PathBuf,
    /// Largest total of unconfirmed message bytes held; beyond it new `no_drop` messages
    /// are refused (counted, logged). Default 256.
    #[serde(default = "default_outbox_mb")]
    pub max_mb: u64,
    /// `always`, `batch` (default) or `never`; see docs/config.md.
    #[serde(default)]
    pub fsync: crate::outbox_store::Fsync,
}

fn default_outbox_mb() -> u64 {
    256
}

impl OutboxConfig {
    pub fn store(&self) -> crate::outbox_store::OutboxStoreConfig {
        crate::outbox_store::OutboxStoreConfig {
            dir: self.dir.clone(),
            max_bytes: self.max_mb.saturating_mul(1 << 20),
            fsync: self.fsync,
        }
    }
}

/// The rosbridge v2 server local programs connect to.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct LocalRosbridgeConfig {
    /// `false` disables the listener (same as `local_rosbridge: null`). Default `true`.
    pub enabled: bool,
    /// `IP:PORT` to listen on (an IP literal, not a host name). Default `127.0.0.1:9090`.
    #[serde(deserialize_with = "socket_addr")]
    pub listen: SocketAddr,
    /// The bearer token of the listener's configuration API (`GET`/`PUT /api/v1/config`,
    /// docs/runtime-config.md). Default empty: the API is closed.
    pub config_token: String,
}

impl Default for LocalRosbridgeConfig {
    fn default() -> Self {
        Self {
            enabled: true,
            listen: SocketAddr::from(([127, 0, 0, 1], 9090)),
            config_token: String::new(),
        }
    }
}

/// Files for the TLS link to the hub (PEM). Relative paths are relative to the agent's
/// working directory.
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct TlsConfig {
    /// CA certificate(s) the hub's certificate must chain to; `None` = system roots.
    pub ca: Option<PathBuf>,
    /// Client certificate chain for hubs that require one (with `key`).
    pub cert: Option<PathBuf>,
    /// Private key of `cert`.
    pub key: Option<PathBuf>,
}

/// A hub topic delivered to local subscribers under a local name.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Subscription {
    /// Topic name on the hub.
    pub hub: String,
    /// Topic name local programs subscribe to.
    pub local: String,
}

/// Command-line values that replace the file's (`fleetlink agent --hub … --name …`). They
/// are applied before the checks, so what is checked is the configuration the agent will
/// run with — a `tls:` section is right for a `--hub wss://…`, and a `--hub http://x` is
/// refused like a bad `hub:` line would be.
#[derive(Debug, Clone, Default)]
pub struct Overrides {
    /// `--hub`, given once per hub: replaces the file's whole list.
    pub hub: Option<Vec<String>>,
    pub name: Option<RobotName>,
    /// `--mirror ROBOT`.
    pub mirror: Option<RobotName>,
}

impl Overrides {
    /// `name_written`: the file has a `name:` of its own.
    fn apply(&self, cfg: &mut AgentConfig, name_written: bool) {
        if let Some(h) = &self.hub {
            cfg.hub = h.clone();
        }
        if let Some(n) = &self.name {
            cfg.name = n.clone();
        }
        if let Some(m) = &self.mirror {
            cfg.mirror = Some(m.clone());
        }
        let name_given = name_written || self.name.is_some();
        cfg.name_the_mirror(name_given);
    }

    /// The command-line flag that set the field at `path` (`hub[1]` was set by `--hub`
    /// too), if one did.
    fn flag_for(&self, path: &FieldPath) -> Option<&'static str> {
        match path.0.first() {
            Some(Segment::Key(k)) if k == "hub" && self.hub.is_some() => Some("--hub"),
            Some(Segment::Key(k)) if k == "name" && self.name.is_some() => Some("--name"),
            Some(Segment::Key(k)) if k == "mirror" && self.mirror.is_some() => Some("--mirror"),
            _ => None,
        }
    }
}

impl AgentConfig {
    /// The configuration as it runs, defaults filled in, as YAML. The tokens are not
    /// shown, only whether there are some. ([`origin::annotated_yaml`] marks where each
    /// field came from.)
    pub fn effective_yaml(&self) -> String {
        match self.effective_value() {
            Ok(value) => serde_saphyr::to_string(&value)
                .unwrap_or_else(|e| format!("# cannot show the configuration: {e}\n")),
            Err(e) => format!("# cannot show the configuration: {e}\n"),
        }
    }

    /// The configuration as JSON, the tokens replaced by whether there are some.
    pub(crate) fn effective_value(&self) -> Result<serde_json::Value, serde_json::Error> {
        let mut value = serde_json::to_value(self)?;
        if let Some(t) = value.get_mut("token") {
            *t = serde_json::Value::String(if self.token.is_empty() {
                "(none)".to_owned()
            } else {
                format!("(set, {} characters)", self.token.chars().count())
            });
        }
        if let Some(t) = value.pointer_mut("/rosbridge/token")
            && let Some(rb) = &self.rosbridge
        {
            *t = serde_json::Value::String(if rb.token.is_empty() {
                "(none)".to_owned()
            } else {
                format!("(set, {} characters)", rb.token.chars().count())
            });
        }
        if let Some(t) = value.pointer_mut("/local_rosbridge/config_token")
            && let Some(l) = &self.local_rosbridge
        {
            *t = serde_json::Value::String(if l.config_token.is_empty() {
                "(none)".to_owned()
            } else {
                format!("(set, {} characters)", l.config_token.chars().count())
            });
        }
        Ok(value)
    }

    /// Runs the semantic checks on a config built or changed in code (for example after
    /// command-line overrides). Errors carry the field but no position.
    pub fn validate(&self) -> Result<(), ConfigError> {
        validate::validate(self).map_err(|problem| ConfigError::Invalid {
            field: problem.path.to_string(),
            message: problem.message,
        })
    }

    /// A mirror given no name of its own (`name_given` false) is `<robot>_mirror`: not
    /// the default `robot1`, which may well be a robot's.
    fn name_the_mirror(&mut self, name_given: bool) {
        if let Some(m) = &self.mirror
            && !name_given
        {
            let own = format!("{m}_mirror");
            if let Ok(n) = RobotName::new(&own) {
                self.name = n;
            }
        }
    }

    /// The robot whose namespace the agent's topics live in on the hub: its own, or the
    /// one it mirrors.
    pub fn namespace_robot(&self) -> &RobotName {
        self.mirror.as_ref().unwrap_or(&self.name)
    }

    /// Ping interval.
    pub fn heartbeat(&self) -> Duration {
        Duration::from_millis(self.heartbeat_ms)
    }

    /// Silence after which the hub link is declared dead: two heartbeats.
    pub fn link_timeout(&self) -> Duration {
        self.heartbeat() * 2
    }

    /// The local listener's configuration API token (empty: the API is closed).
    pub fn local_config_token(&self) -> &str {
        self.local_rosbridge
            .as_ref()
            .map_or("", |l| l.config_token.as_str())
    }

    /// Address of the local rosbridge listener, `None` when disabled.
    pub fn local_rosbridge_listen(&self) -> Option<SocketAddr> {
        self.local_rosbridge
            .as_ref()
            .filter(|l| l.enabled)
            .map(|l| l.listen)
    }

    /// Hub topic for a local topic: the `remap` entry, else `/<name><local>`.
    pub fn hub_topic(&self, local: &str) -> String {
        match self.remap.get(local) {
            Some(hub) => hub.clone(),
            None => format!("/{}{}", self.namespace_robot(), local),
        }
    }
}

/// Checks a fully qualified ROS topic name (`/a/b_c`).
pub fn check_topic_name(topic: &str) -> Result<(), String> {
    validate::check_topic(topic)
}

/// Where in which file: `robot.yaml:12:5`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SourcePos {
    pub file: String,
    /// 1-based.
    pub line: u64,
    /// 1-based, in characters.
    pub column: u64,
}

impl fmt::Display for SourcePos {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.column)
    }
}

/// Why a configuration was rejected.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    #[error("{}: cannot read config: {source}", path.display())]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    /// Not valid YAML; `message` is the parser's.
    #[error("{at}: invalid YAML: {message}")]
    Syntax { at: SourcePos, message: String },
    /// A field has the wrong type, is unknown, or fails a check; `message` is the parser's
    /// or the check's text.
    #[error("{at}: {field}: {message}")]
    Field {
        at: SourcePos,
        field: String,
        message: String,
    },
    /// From [`AgentConfig::validate`] on a config that did not come from a file.
    #[error("config field {field}: {message}")]
    Invalid { field: String, message: String },
    /// A value given on the command line (`flag`, e.g. `--hub`) fails a check.
    #[error("{flag}: {message}")]
    Flag { flag: &'static str, message: String },
}

/// A check's problem as an error at the field's line and column in `text`.
fn field_error(problem: validate::Problem, text: &str, file_name: &str) -> ConfigError {
    let (line, column) = LocationTree::parse(text).map_or((1, 1), |tree| {
        tree.position_of(&problem.path, problem.at_key)
    });
    ConfigError::Field {
        at: SourcePos {
            file: file_name.to_owned(),
            line,
            column,
        },
        field: problem.path.to_string(),
        message: problem.message,
    }
}

/// A check's problem as an error naming the command-line flag that set the field, or the
/// field alone.
fn flag_or_field(problem: validate::Problem, overrides: &Overrides) -> ConfigError {
    match overrides.flag_for(&problem.path) {
        Some(flag) => ConfigError::Flag {
            flag,
            message: problem.message,
        },
        None => ConfigError::Invalid {
            field: problem.path.to_string(),
            message: problem.message,
        },
    }
}

impl ConfigError {
    /// The field path (`sim.point_cloud.rate_hz`), when a field is to blame.
    pub fn field(&self) -> Option<&str> {
        match self {
            Self::Field { field, .. } | Self::Invalid { field, .. } => Some(field),
            Self::Flag { flag, .. } => Some(flag),
            Self::Read { .. } | Self::Syntax { .. } => None,
        }
    }

    /// Line and column, when the error came from a file's text.
    pub fn position(&self) -> Option<&SourcePos> {
        match self {
            Self::Syntax { at, .. } | Self::Field { at, .. } => Some(at),
            Self::Read { .. } | Self::Invalid { .. } | Self::Flag { .. } => None,
        }
    }
}

/// The parser's message without snippet or position (we print those ourselves), with
/// control characters neutralised as the formatter's docs ask.
fn yaml_message(err: &serde_saphyr::Error) -> String {
    serde_saphyr::UserMessageFormatter
        .format_message(err.without_snippet())
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

fn yaml_position(err: &serde_saphyr::Error, file: &str) -> SourcePos {
    let (line, column) = err
        .location()
        .map_or((1, 1), |l| (l.line().max(1), l.column().max(1)));
    SourcePos {
        file: file.to_owned(),
        line,
        column,
    }
}

fn parse_error(err: &serde_saphyr::Error, text: &str, file: &str) -> ConfigError {
    // The location tree accepts any YAML, so if it fails the text itself is broken, and
    // its error is the syntax error proper.
    let tree = match LocationTree::parse(text) {
        Ok(tree) => tree,
        Err(syntax) => {
            return ConfigError::Syntax {
                at: yaml_position(&syntax, file),
                message: yaml_message(&syntax),
            };
        }
    };
    let at = yaml_position(err, file);
    let message = match err.without_snippet() {
        // The parser names only the type it wanted ("invalid u64"); say what it got.
        serde_saphyr::Error::InvalidScalar { ty, .. } => {
            let wanted = match *ty {
                "u8" | "u16" | "u32" | "u64" | "u128" | "usize" => {
                    format!("a whole number, 0 or more ({ty})")
                }
                "i8" | "i16" | "i32" | "i64" | "i128" | "isize" => {
                    format!("a whole number ({ty})")
                }
                "floating point" | "f32" | "f64" => "a number".to_owned(),
                "boolean" | "bool" => "true or false".to_owned(),
                other => other.to_owned(),
            };
            match scalar_at(text, at.line, at.column) {
                Some(got) => format!("expected {wanted}, got {got}"),
                None => format!("expected {wanted}"),
            }
        }
        _ => yaml_message(err),
    };
    let path = tree.path_at((at.line, at.column)).to_string();
    let message = match shape_example(&path) {
        // At the section itself (not a field inside it), an error is about its shape.
        Some(example) if !message.contains("unknown field") && !message.contains(example) => {
            format!("{message}; write it as, for example, `{example}`")
        }
        _ => message,
    };
    ConfigError::Field {
        at,
        field: path,
        message,
    }
}

/// The right spelling of a section, for an error about its shape (a list where a mapping
/// goes, a number where a list goes, ...).
fn shape_example(path: &str) -> Option<&'static str> {
    Some(match path {
        "ros1" => "ros1: { publish: [/chatter], subscribe: [/cmd_vel] }",
        "ros2" => "ros2: { domain_id: 0, publish: [/scan], subscribe: [/cmd_vel] }",
        "rosbridge" => "rosbridge: { url: ws://192.168.1.10:9090, publish: [/odom] }",
        "ros1.subscribe" | "ros2.subscribe" | "rosbridge.subscribe" => "subscribe: [/cmd_vel]",
        "sim" => "sim: { laser_scan: { rate_hz: 10 } }",
        "blackbox" => "blackbox: { dir: /var/lib/fleetlink/blackbox, topics: [/scan, /odom] }",
        "remap" => "remap: { /map: /fleet/map }",
        "subscribe" => "subscribe: [{ hub: /fleet/announcements, local: /announcements }]",
        "topics" => "topics: { /scan: { priority: 5 } }",
        "reconnect" => "reconnect: { initial_ms: 500, max_ms: 30000 }",
        "local_rosbridge" => "local_rosbridge: { listen: 127.0.0.1:9090 }",
        "tls" => "tls: { ca: /etc/fleetlink/ca.pem }",
        "outbox" => "outbox: { dir: /var/lib/fleetlink/outbox, max_mb: 64 }",
        "link" => "link: { budget: { max_kbps: 500 } }",
        "link.budget" => "budget: { max_kbps: 500, mb_per_day: 200 }",
        "remove" => "remove: { topics: [/scan], ros2: { publish: [/scan] } }",
        _ => return None,
    })
}

/// The scalar that starts at 1-based `line`:`column` of `text`, as written (quoted if it
/// was), shortened to a readable length; `None` if there is nothing there.
fn scalar_at(text: &str, line: u64, column: u64) -> Option<String> {
    let line = text
        .lines()
        .nth(usize::try_from(line).ok()?.checked_sub(1)?)?;
    let rest: String = line
        .chars()
        .skip(usize::try_from(column).ok()?.saturating_sub(1))
        .collect();
    let value = match rest.chars().next()? {
        q @ ('"' | '\'') => match rest[1..].find(q) {
            Some(end) => rest[..end + 2].to_owned(),
            None => rest.clone(),
        },
        _ => rest
            .split(" #")
            .next()
            .unwrap_or_default()
            .split([',', '}', ']'])
            .next()
            .unwrap_or_default()
            .trim()
            .to_owned(),
    };
    if value.is_empty() {
        return None;
    }
    let short: String = value.chars().take(40).collect();
    Some(if short.len() < value.len() {
        format!("`{short}…`")
    } else {
        format!("`{short}`")
    })
}

/// `hub:` as one URL (`hub: ws://hub.example:8080`) or a list of them. Each URL is checked
/// later, with the other fields ([`validate`]), so a bad one is named by its index.
fn one_or_more_urls<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Vec<String>, D::Error> {
    struct Urls;
    impl<'de> serde::de::Visitor<'de> for Urls {
        type Value = Vec<String>;

        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("a hub URL such as ws://hub.example:8080, or a list of them")
        }

        fn visit_str<E: serde::de::Error>(self, url: &str) -> Result<Vec<String>, E> {
            Ok(vec![url.to_owned()])
        }

        fn visit_seq<A: serde::de::SeqAccess<'de>>(
            self,
            mut seq: A,
        ) -> Result<Vec<String>, A::Error> {
            let mut urls = Vec::new();
            while let Some(url) = seq.next_element::<String>()? {
                urls.push(url);
            }
            Ok(urls)
        }
    }
    deserializer.deserialize_any(Urls)
}

fn socket_addr<'de, D: Deserializer<'de>>(deserializer: D) -> Result<SocketAddr, D::Error> {
    let text = String::deserialize(deserializer)?;
    text.parse().map_err(|e| {
        serde::de::Error::custom(format!(
            "expected IP:PORT like 127.0.0.1:9090, got {text:?} ({e})"
        ))
    })
}

#[cfg(test)]
mod tests;
