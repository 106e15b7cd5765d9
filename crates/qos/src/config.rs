//! Per-topic QoS configuration: [`TopicQos`], the partial form [`TopicQosSpec`] read from
//! agent YAML and hub subscription options, defaults by ROS message type, and validation.
//!
//! Design choice: a configuration is checked once, when it is loaded
//! ([`TopicQos::validate`]), and every error names the offending field, so the queues and
//! the scheduler can trust their inputs and never fail on the message path.

use serde::Deserialize;

use crate::error::QosError;

/// How a topic goes up the link (see `docs/qos.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Deserialize, serde::Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// Every message while someone wants the topic (or always, with `always: true`).
    #[default]
    Stream,
    /// Only on request: the agent keeps the latest message and sends exactly one each time
    /// a subscriber asks (`pull`).
    Pull,
}

/// How a topic's messages are compressed on the robot's link (see `docs/qos.md`). The
/// agent decides per message; the hub decompresses once, before fan-out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Deserialize, serde::Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Compression {
    /// Sent as published.
    None,
    /// LZ4: cheap on the robot's CPU, a smaller saving.
    Lz4,
    /// zstd at its default level; ROS Gateway's `zip` and `rawzip` mean this (the ROS
    /// bridges carry a robot's messages in their raw ROS serialization).
    #[serde(alias = "zip", alias = "rawzip")]
    Zstd,
    /// zstd at a fast level where it pays: a topic whose messages do not shrink (JPEG or
    /// PNG images, already-compressed clouds) is sent as it is and checked again now and
    /// then; small messages are never compressed.
    #[default]
    Auto,
}

impl Compression {
    /// Stable lower-case name, as written in configuration.
    pub fn as_str(self) -> &'static str {
        match self {
            Compression::None => "none",
            Compression::Lz4 => "lz4",
            Compression::Zstd => "zstd",
            Compression::Auto => "auto",
        }
    }
}

/// What a bounded per-topic queue does when it is full (see `docs/qos.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Deserialize, serde::Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Policy {
    /// No drop: when full, the item is handed back to the source (backpressure).
    Fifo,
    /// Keep only the newest message (queue length is 1).
    Latest,
    /// When full, evict the oldest queued message.
    #[default]
    DropOldest,
    /// When full, refuse the incoming message.
    DropNewest,
    /// When full, evict a uniformly chosen queued message (seeded, reproducible).
    Random,
    /// AFR buffering (adaptive frame rate): thin the queue evenly, halve the accepted rate.
    Afr,
}

impl Policy {
    /// Stable lower-case name, as written in configuration and used as a metrics label.
    pub fn as_str(self) -> &'static str {
        match self {
            Policy::Fifo => "fifo",
            Policy::Latest => "latest",
            Policy::DropOldest => "drop_oldest",
            Policy::DropNewest => "drop_newest",
            Policy::Random => "random",
            Policy::Afr => "afr",
        }
    }
}

/// Complete, validated QoS settings of one topic.
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct TopicQos {
    /// Scheduling weight, > 0; larger is served sooner.
    #[serde(default = "default_priority")]
    pub priority: f32,
    /// At most this many messages per second enter the queue; `None` means unlimited.
    #[serde(default)]
    pub rate_limit_hz: Option<f64>,
    #[serde(default)]
    pub policy: Policy,
    /// Queue length L, >= 1.
    #[serde(default = "default_queue")]
    pub queue: usize,
    /// Never drop: served first from one FIFO shared by all no-drop topics; requires
    /// `policy: fifo` and no rate limit.
    #[serde(default)]
    pub no_drop: bool,
    /// Sent whether or not anyone at the hub wants it (a demand-driven uplink holds a
    /// topic back while nobody does). No-drop topics always are.
    #[serde(default)]
    pub always: bool,
    /// A message older than this (milliseconds since it was received) when its turn on
    /// the link comes is dropped (`too_old`); `None`: no limit. No-drop topics take none.
    #[serde(default)]
    pub max_age_ms: Option<u64>,
    /// `pull`: sent only when a subscriber asks, one message per request.
    #[serde(default)]
    pub mode: Mode,
    /// On the robot's link.
    #[serde(default)]
    pub compression: Compression,
}

fn default_priority() -> f32 {
    DEFAULT_PRIORITY
}

fn default_queue() -> usize {
    DEFAULT_QUEUE
}

const DEFAULT_PRIORITY: f32 = 5.0;
const DEFAULT_QUEUE: usize = 16;

impl Default for TopicQos {
    fn default() -> Self {
        TopicQos {
            priority: DEFAULT_PRIORITY,
            rate_limit_hz: None,
            policy: Policy::DropOldest,
            queue: DEFAULT_QUEUE,
            no_drop: false,
            always: false,
            max_age_ms: None,
            mode: Mode::Stream,
            compression: Compression::Auto,
        }
    }
}

impl TopicQos {
    fn new(priority: f32, policy: Policy, queue: usize) -> Self {
        TopicQos {
            priority,
            rate_limit_hz: None,
            policy,
            queue,
            no_drop: false,
            always: false,
            max_age_ms: None,
            mode: Mode::Stream,
            compression: Compression::Auto,
        }
    }

    fn no_drop(priority: f32, queue: usize) -> Self {
        TopicQos {
            no_drop: true,
            ..TopicQos::new(priority, Policy::Fifo, queue)
        }
    }

    /// Defaults for a ROS message type, given as `pkg/Type` or `pkg/msg/Type`.
    /// The table is documented in `docs/qos.md`; unknown types get [`TopicQos::default`].
    pub fn default_for_type(ros_type: &str) -> TopicQos {
        let name = normalize_type(ros_type);
        match name.as_str() {
            // Motion commands: only the newest command matters, and it matters now.
            "geometry_msgs/Twist" | "geometry_msgs/TwistStamped" => {
                TopicQos::new(10.0, Policy::Latest, 1)
            }
            "ackermann_msgs/AckermannDriveStamped" | "ackermann_msgs/AckermannDrive" => {
                TopicQos::new(10.0, Policy::Latest, 1)
            }
            // Where the robot is: small, frequent, newest wins.
            "nav_msgs/Odometry"
            | "geometry_msgs/PoseStamped"
            | "geometry_msgs/PoseWithCovarianceStamped"
            | "sensor_msgs/NavSatFix" => TopicQos::new(8.0, Policy::Latest, 1),
            "tf2_msgs/TFMessage" | "tf/tfMessage" => TopicQos::new(8.0, Policy::DropOldest, 64),
            // Maps are sent rarely and must arrive whole.
            "nav_msgs/OccupancyGrid" | "map_msgs/OccupancyGridUpdate" | "nav_msgs/MapMetaData" => {
                TopicQos::no_drop(5.0, 4)
            }
            "nav_msgs/Path" | "sensor_msgs/BatteryState" | "diagnostic_msgs/DiagnosticArray" => {
                TopicQos::new(3.0, Policy::Latest, 1)
            }
            "sensor_msgs/Imu" => TopicQos::new(4.0, Policy::DropOldest, 32),
            "sensor_msgs/LaserScan" => TopicQos::new(3.0, Policy::Afr, 16),
            // Bulk sensor data: lowest priority; AFR keeps evenly spaced frames through
            // outages, which is what mapping and tracking need.
            "sensor_msgs/Image" | "sensor_msgs/CompressedImage" => {
                TopicQos::new(2.0, Policy::Afr, 8)
            }
            // Video: each frame needs the ones before it back to a keyframe, so frames
            // are not thinned; room for four seconds at 15 fps, but a frame that waited
            // two (an outage) is stale for a live viewer: the hub asks for a keyframe
            // instead (docs/video.md).
            "foxglove_msgs/CompressedVideo" => TopicQos {
                max_age_ms: Some(2000),
                ..TopicQos::new(2.0, Policy::DropOldest, 64)
            },
            "sensor_msgs/PointCloud2" | "sensor_msgs/PointCloud" => {
                TopicQos::new(1.0, Policy::Afr, 8)
            }
            "rosgraph_msgs/Log" | "rcl_interfaces/Log" => {
                TopicQos::new(2.0, Policy::DropOldest, 100)
            }
            _ => TopicQos::default(),
        }
    }

    /// [`TopicQos::default_for_type`] refined by well-known topic names: emergency stops
    /// (`e_stop`, `estop`, `emergency_stop`) get the highest priority, `/tf_static` and
    /// `/map` are no-drop.
    pub fn default_for_topic(topic: &str, ros_type: &str) -> TopicQos {
        let last = topic
            .rsplit('/')
            .next()
            .unwrap_or(topic)
            .to_ascii_lowercase();
        match last.as_str() {
            "e_stop" | "estop" | "emergency_stop" => TopicQos::new(100.0, Policy::Latest, 1),
            "tf_static" => TopicQos::no_drop(8.0, 16),
            "map" => TopicQos::no_drop(5.0, 4),
            _ => TopicQos::default_for_type(ros_type),
        }
    }

    /// Checks every field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), QosError> {
        if !(self.priority.is_finite() && self.priority > 0.0) {
            return Err(QosError::invalid(
                "priority",
                format!("must be a finite number > 0, got {}", self.priority),
            ));
        }
        if let Some(hz) = self.rate_limit_hz
            && !(hz.is_finite() && hz > 0.0)
        {
            return Err(QosError::invalid(
                "rate_limit_hz",
                format!("must be a finite number > 0, got {hz}"),
            ));
        }
        if self.queue == 0 {
            return Err(QosError::invalid("queue", "must be at least 1".to_string()));
        }
        if self.max_age_ms == Some(0) {
            return Err(QosError::invalid(
                "max_age",
                "must be longer than 0 (leave it out for no limit)".to_string(),
            ));
        }
        if self.mode == Mode::Pull && (self.no_drop || self.always) {
            return Err(QosError::invalid(
                "mode",
                format!(
                    "a pull topic is sent only when asked, which `{}: true` contradicts; \
                     remove one of the two",
                    if self.no_drop { "no_drop" } else { "always" }
                ),
            ));
        }
        if self.no_drop && self.max_age_ms.is_some() {
            return Err(QosError::invalid(
                "max_age",
                "a no_drop topic never drops a message, however old; remove one of the two"
                    .to_string(),
            ));
        }
        if self.policy == Policy::Latest && self.queue != 1 {
            return Err(QosError::invalid(
                "queue",
                format!(
                    "policy `latest` keeps exactly one message, got queue {}",
                    self.queue
                ),
            ));
        }
        if self.no_drop && self.policy != Policy::Fifo {
            return Err(QosError::invalid(
                "policy",
                format!(
                    "no_drop topics must use `fifo`, got `{}`",
                    self.policy.as_str()
                ),
            ));
        }
        if self.no_drop && self.rate_limit_hz.is_some() {
            return Err(QosError::invalid(
                "rate_limit_hz",
                "a no_drop topic cannot be rate limited (rate limiting drops)".to_string(),
            ));
        }
        Ok(())
    }
}

/// `pkg/msg/Type` (ROS 2) and `pkg/Type` (ROS 1) name the same thing here.
fn normalize_type(ros_type: &str) -> String {
    let t = ros_type.trim();
    match t.split('/').collect::<Vec<_>>().as_slice() {
        [pkg, "msg", name] => format!("{pkg}/{name}"),
        _ => t.to_string(),
    }
}

/// Topic QoS as written by an operator: every field optional, missing ones taken from the
/// defaults of the topic's type ([`TopicQosSpec::resolve`]).
#[derive(Debug, Clone, Default, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct TopicQosSpec {
    pub priority: Option<f32>,
    pub rate_limit_hz: Option<f64>,
    pub policy: Option<Policy>,
    pub queue: Option<usize>,
    pub no_drop: Option<bool>,
    pub always: Option<bool>,
    /// `500ms`, `2s`, `1m` (or a number of milliseconds).
    #[serde(default, deserialize_with = "age", serialize_with = "age_text")]
    pub max_age: Option<std::time::Duration>,
    pub mode: Option<Mode>,
    pub compression: Option<Compression>,
}

/// An age limit written back as it is read: `500ms`, `2s`.
fn age_text<S: serde::Serializer>(
    age: &Option<std::time::Duration>,
    s: S,
) -> Result<S::Ok, S::Error> {
    match age {
        Some(d) => s.serialize_str(&humantime::format_duration(*d).to_string()),
        None => s.serialize_none(),
    }
}

/// An age limit as written: a duration with its unit (`500ms`, `2s`), or milliseconds.
fn age<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<std::time::Duration>, D::Error> {
    #[derive(Deserialize, serde::Serialize)]
    #[serde(untagged)]
    enum Written {
        Millis(u64),
        Text(String),
    }
    match Written::deserialize(d)? {
        Written::Millis(ms) => Ok(Some(std::time::Duration::from_millis(ms))),
        Written::Text(t) => humantime::parse_duration(t.trim()).map(Some).map_err(|e| {
            serde::de::Error::custom(format!(
                "max_age {t:?}: {e}; write a duration with its unit, e.g. 500ms or 2s"
            ))
        }),
    }
}

impl TopicQosSpec {
    /// Whether a topic with this spec is no-drop, when the defaults of its name and type
    /// (`base_no_drop`) say so or not: `no_drop` when written; otherwise a dropping policy,
    /// a pull topic or an age limit ends a no-drop default (`/map`, `/tf_static`,
    /// `nav_msgs/OccupancyGrid`). [`TopicQosSpec::resolve`] decides it with this, so a
    /// configuration can tell whether two specs agree on no-drop for a topic of any type.
    pub fn no_drop_with(&self, base_no_drop: bool) -> bool {
        if let Some(nd) = self.no_drop {
            return nd;
        }
        let drops = self.policy.is_some_and(|p| p != Policy::Fifo)
            || self.mode == Some(Mode::Pull)
            || self.max_age.is_some();
        base_no_drop && !drops
    }

    /// Fills the gaps from `base` (usually [`TopicQos::default_for_topic`]) and validates.
    ///
    /// Two fields follow from others when left out: `no_drop: true` implies `policy: fifo`,
    /// and `policy: latest` implies `queue: 1`; switching a no-drop default to a dropping
    /// policy clears `no_drop`.
    pub fn resolve(&self, base: &TopicQos) -> Result<TopicQos, QosError> {
        let mut qos = base.clone();
        if let Some(p) = self.priority {
            qos.priority = p;
        }
        if self.rate_limit_hz.is_some() {
            qos.rate_limit_hz = self.rate_limit_hz;
        }
        if let Some(policy) = self.policy {
            qos.policy = policy;
            if self.queue.is_none() {
                qos.queue = match policy {
                    Policy::Latest => 1,
                    _ if base.policy == Policy::Latest => DEFAULT_QUEUE,
                    _ => base.queue,
                };
            }
        }
        if let Some(q) = self.queue {
            qos.queue = q;
        }
        if let Some(a) = self.always {
            qos.always = a;
        }
        if let Some(m) = self.mode {
            qos.mode = m;
        }
        if let Some(c) = self.compression {
            qos.compression = c;
        }
        if let Some(age) = self.max_age {
            qos.max_age_ms = Some(age.as_millis().min(u128::from(u64::MAX)) as u64);
        }
        qos.no_drop = self.no_drop_with(base.no_drop);
        if self.no_drop == Some(true) && self.policy.is_none() {
            qos.policy = Policy::Fifo;
            if self.queue.is_none() && base.policy == Policy::Latest {
                qos.queue = DEFAULT_QUEUE;
            }
        }
        qos.validate()?;
        Ok(qos)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_by_type_are_valid_and_match_the_documented_table() {
        for t in [
            "geometry_msgs/Twist",
            "geometry_msgs/msg/Twist",
            "sensor_msgs/msg/PointCloud2",
            "nav_msgs/OccupancyGrid",
            "sensor_msgs/Image",
            "unknown_pkg/Thing",
        ] {
            TopicQos::default_for_type(t).validate().unwrap();
        }
        let twist = TopicQos::default_for_type("geometry_msgs/msg/Twist");
        assert_eq!((twist.policy, twist.priority), (Policy::Latest, 10.0));
        let cloud = TopicQos::default_for_type("sensor_msgs/PointCloud2");
        assert!(cloud.priority < twist.priority);
        assert!(TopicQos::default_for_type("nav_msgs/msg/OccupancyGrid").no_drop);
        let estop = TopicQos::default_for_topic("/robot1/e_stop", "std_msgs/Bool");
        assert!(estop.priority > twist.priority);
    }

    #[test]
    fn no_drop_with_is_what_resolve_decides() {
        let specs = [
            TopicQosSpec::default(),
            TopicQosSpec {
                no_drop: Some(true),
                ..TopicQosSpec::default()
            },
            TopicQosSpec {
                no_drop: Some(false),
                ..TopicQosSpec::default()
            },
            TopicQosSpec {
                policy: Some(Policy::Latest),
                ..TopicQosSpec::default()
            },
            TopicQosSpec {
                policy: Some(Policy::Fifo),
                ..TopicQosSpec::default()
            },
            TopicQosSpec {
                mode: Some(Mode::Pull),
                ..TopicQosSpec::default()
            },
            TopicQosSpec {
                max_age: Some(std::time::Duration::from_millis(500)),
                ..TopicQosSpec::default()
            },
            TopicQosSpec {
                priority: Some(3.0),
                ..TopicQosSpec::default()
            },
        ];
        for base in [
            TopicQos::default_for_type("nav_msgs/OccupancyGrid"),
            TopicQos::default_for_type("std_msgs/String"),
        ] {
            for spec in &specs {
                if let Ok(q) = spec.resolve(&base) {
                    assert_eq!(q.no_drop, spec.no_drop_with(base.no_drop), "{spec:?}");
                }
            }
        }
    }

    #[test]
    fn validation_names_the_bad_field() {
        let field = |q: TopicQos| q.validate().unwrap_err().field();
        assert_eq!(
            field(TopicQos {
                priority: 0.0,
                ..TopicQos::default()
            }),
            Some("priority")
        );
        assert_eq!(
            field(TopicQos {
                priority: f32::NAN,
                ..TopicQos::default()
            }),
            Some("priority")
        );
        assert_eq!(
            field(TopicQos {
                queue: 0,
                ..TopicQos::default()
            }),
            Some("queue")
        );
        assert_eq!(
            field(TopicQos {
                rate_limit_hz: Some(-1.0),
                ..TopicQos::default()
            }),
            Some("rate_limit_hz")
        );
        assert_eq!(
            field(TopicQos {
                no_drop: true,
                ..TopicQos::default()
            }),
            Some("policy")
        );
        assert_eq!(
            field(TopicQos {
                policy: Policy::Latest,
                queue: 4,
                ..TopicQos::default()
            }),
            Some("queue")
        );
    }

    #[test]
    fn yaml_field_names_and_policy_names_deserialize() {
        let q: TopicQos = serde_saphyr::from_str(
            "priority: 2.5\nrate_limit_hz: 10\npolicy: afr\nqueue: 8\nno_drop: false\n",
        )
        .unwrap();
        assert_eq!(q.policy, Policy::Afr);
        assert_eq!(q.rate_limit_hz, Some(10.0));
        for name in [
            "fifo",
            "latest",
            "drop_oldest",
            "drop_newest",
            "random",
            "afr",
        ] {
            let p: Policy = serde_saphyr::from_str(name).unwrap();
            assert_eq!(p.as_str(), name);
        }
        assert!(serde_saphyr::from_str::<TopicQos>("priorty: 1").is_err());
    }

    #[test]
    fn spec_fills_missing_fields_from_the_type_defaults() {
        let base = TopicQos::default_for_type("geometry_msgs/Twist");
        let spec: TopicQosSpec = serde_saphyr::from_str("priority: 20").unwrap();
        let q = spec.resolve(&base).unwrap();
        assert_eq!((q.priority, q.policy, q.queue), (20.0, Policy::Latest, 1));

        let spec: TopicQosSpec = serde_saphyr::from_str("policy: afr").unwrap();
        assert_eq!(spec.resolve(&base).unwrap().queue, DEFAULT_QUEUE);

        let spec: TopicQosSpec = serde_saphyr::from_str("no_drop: true").unwrap();
        let q = spec.resolve(&base).unwrap();
        assert_eq!((q.policy, q.no_drop), (Policy::Fifo, true));

        let map = TopicQos::default_for_type("nav_msgs/OccupancyGrid");
        let spec: TopicQosSpec = serde_saphyr::from_str("policy: latest").unwrap();
        let q = spec.resolve(&map).unwrap();
        assert_eq!((q.no_drop, q.queue), (false, 1));

        let spec: TopicQosSpec = serde_saphyr::from_str("priority: -3").unwrap();
        assert_eq!(spec.resolve(&base).unwrap_err().field(), Some("priority"));
    }
}
