//! Semantic checks on a parsed [`AgentConfig`]: what serde's types cannot say (rates > 0,
//! ROS topic name syntax, unique sim topics, every `hub` is a WebSocket URL).
//!
//! Checks run on the typed value and report a [`FieldPath`]; the caller turns the path into
//! a line and column with [`super::locate::LocationTree`]. The first problem in document
//! order of the fields is reported.

use std::collections::BTreeMap;

use super::locate::FieldPath;
use super::{AgentConfig, SimConfig};

/// One thing wrong with a config, and where.
#[derive(Debug)]
pub(crate) struct Problem {
    pub(crate) path: FieldPath,
    /// Point at the mapping key rather than its value (the key itself is wrong).
    pub(crate) at_key: bool,
    pub(crate) message: String,
}

fn problem(path: FieldPath, message: impl Into<String>) -> Problem {
    Problem {
        path,
        at_key: false,
        message: message.into(),
    }
}

pub(crate) fn validate(cfg: &AgentConfig) -> Result<(), Problem> {
    validate_hubs(cfg)?;
    validate_mirror(cfg)?;
    if let Some(tls) = &cfg.tls {
        for (field, path) in [
            ("tls.ca", &tls.ca),
            ("tls.cert", &tls.cert),
            ("tls.key", &tls.key),
        ] {
            if path.as_ref().is_some_and(|p| p.as_os_str().is_empty()) {
                return Err(problem(
                    field.into(),
                    "must be a file path, got an empty string",
                ));
            }
        }
        match (&tls.cert, &tls.key) {
            (Some(_), None) => {
                return Err(problem(
                    "tls.cert".into(),
                    "needs tls.key (the certificate's private key)",
                ));
            }
            (None, Some(_)) => {
                return Err(problem(
                    "tls.key".into(),
                    "needs tls.cert (the client certificate)",
                ));
            }
            _ => {}
        }
    }
    if let Some(o) = &cfg.outbox {
        if o.dir.as_os_str().is_empty() {
            return Err(problem(
                "outbox.dir".into(),
                "must be a directory path, got an empty string",
            ));
        }
        if o.max_mb == 0 {
            return Err(problem(
                "outbox.max_mb".into(),
                "must be > 0 (megabytes of unconfirmed no_drop messages to hold), got 0",
            ));
        }
    }
    if let Some(b) = &cfg.link.budget {
        for (field, v, unit) in [
            ("link.budget.max_kbps", b.max_kbps, "kilobits per second"),
            ("link.budget.mb_per_day", b.mb_per_day, "megabytes a day"),
        ] {
            if let Some(v) = v
                && !(v.is_finite() && v > 0.0)
            {
                return Err(problem(
                    field.into(),
                    format!("must be > 0 ({unit}), got {v}"),
                ));
            }
        }
        if b.max_kbps.is_none() && b.mb_per_day.is_none() {
            return Err(problem(
                "link.budget".into(),
                "sets no limit: give max_kbps (kilobits per second) and/or mb_per_day",
            ));
        }
        if !(b.protect_priority.is_finite() && b.protect_priority > 0.0) {
            return Err(problem(
                "link.budget.protect_priority".into(),
                format!("must be a number > 0, got {}", b.protect_priority),
            ));
        }
    }
    if cfg.heartbeat_ms == 0 {
        return Err(problem("heartbeat_ms".into(), "must be > 0, got 0"));
    }
    if cfg.reconnect.initial_ms == 0 {
        return Err(problem("reconnect.initial_ms".into(), "must be > 0, got 0"));
    }
    if cfg.reconnect.max_ms < cfg.reconnect.initial_ms {
        return Err(problem(
            "reconnect.max_ms".into(),
            format!(
                "must be >= reconnect.initial_ms ({}), got {}",
                cfg.reconnect.initial_ms, cfg.reconnect.max_ms
            ),
        ));
    }
    let remap = FieldPath::from("remap");
    for (local, hub) in &cfg.remap {
        check_topic(local).map_err(|m| Problem {
            path: remap.key(local.clone()),
            at_key: true,
            message: format!("local topic {m}"),
        })?;
        check_topic(hub).map_err(|m| problem(remap.key(local.clone()), m))?;
    }
    let subscribe = FieldPath::from("subscribe");
    for (i, sub) in cfg.subscribe.iter().enumerate() {
        check_topic(&sub.hub).map_err(|m| problem(subscribe.index(i).key("hub"), m))?;
        check_topic(&sub.local).map_err(|m| problem(subscribe.index(i).key("local"), m))?;
    }
    if let Some(sim) = &cfg.sim {
        validate_sim(sim)?;
    }
    if let Some(r) = &cfg.ros1 {
        validate_ros1(r)?;
    }
    if let Some(r) = &cfg.ros2 {
        validate_ros2(r)?;
    }
    if let Some(r) = &cfg.rosbridge {
        validate_rosbridge(r)?;
    }
    if let Some(b) = &cfg.blackbox {
        validate_blackbox(b)?;
    }
    validate_video(cfg)?;
    let topics = FieldPath::from("topics");
    for (name, spec) in &cfg.topics {
        check_topic(name).map_err(|m| Problem {
            path: topics.key(name.clone()),
            at_key: true,
            message: format!("topic {m}"),
        })?;
        let base = fleetlink_qos::TopicQos::default_for_topic(name, "");
        if let Err(e) = spec.resolve(&base) {
            let path = match e.field() {
                Some(f) => topics.key(name.clone()).key(f),
                None => topics.key(name.clone()),
            };
            return Err(problem(path, e.to_string()));
        }
    }
    Ok(())
}

/// A mirror (docs/mirror.md) has a name of its own and presents a real robot's topics.
fn validate_mirror(cfg: &AgentConfig) -> Result<(), Problem> {
    if let Some(m) = &cfg.mirror {
        if *m == cfg.name {
            return Err(problem(
                "name".into(),
                format!("a mirror needs a name of its own, not {m}'s (e.g. {m}_mirror)"),
            ));
        }
        if cfg.sim.is_some() {
            return Err(problem(
                "sim".into(),
                format!(
                    "a mirror of {m} presents the real robot's topics; a simulated robot \
                     belongs in an agent of its own (remove sim: or mirror:)"
                ),
            ));
        }
    }
    Ok(())
}

/// `hub`: at least one URL, each a `ws://` or `wss://` URL with a host, none twice; with
/// `tls:`, every one `wss://`. A single hub is named `hub`, one of several `hub[i]`.
fn validate_hubs(cfg: &AgentConfig) -> Result<(), Problem> {
    let hubs = &cfg.hub;
    if hubs.is_empty() {
        return Err(problem(
            "hub".into(),
            "lists no hub: give its URL (hub: ws://hub.example:8080) or several to fail over \
             between (hub: [wss://a.example:8443, wss://b.example:8443])",
        ));
    }
    let at = |i: usize| match hubs.len() {
        1 => FieldPath::from("hub"),
        _ => FieldPath::from("hub").index(i),
    };
    for (i, url) in hubs.iter().enumerate() {
        check_hub_url(url).map_err(|m| problem(at(i), m))?;
        if let Some(first) = hubs[..i].iter().position(|u| u == url) {
            return Err(problem(
                at(i),
                format!("{url:?} is already hub[{first}]; list each hub once"),
            ));
        }
    }
    // `tls:` applies to every hub: a plain ws:// one in the list would carry the robot's
    // data unencrypted after a failover, which whoever wrote `tls:` did not mean.
    if cfg.tls.is_some()
        && let Some((i, url)) = hubs
            .iter()
            .enumerate()
            .find(|(_, u)| !u.starts_with("wss://"))
    {
        let message = match hubs.len() {
            1 => format!("is only used with a wss:// hub, but hub is {url:?}"),
            _ => format!("applies to every hub, so each must be wss://, but hub[{i}] is {url:?}"),
        };
        return Err(problem("tls".into(), message));
    }
    Ok(())
}

/// A `ws://` or `wss://` URL that names a host.
pub(crate) fn check_hub_url(url: &str) -> Result<(), String> {
    if !(url.starts_with("ws://") || url.starts_with("wss://")) {
        return Err(format!(
            "must be a ws:// or wss:// URL such as ws://hub.example:8080, got {url:?}"
        ));
    }
    match url.parse::<tokio_tungstenite::tungstenite::http::Uri>() {
        Ok(uri) if uri.host().is_some_and(|h| !h.is_empty()) => Ok(()),
        Ok(_) => Err(format!("names no host: {url:?} (expected ws://HOST:PORT)")),
        Err(e) => Err(format!("is not a valid URL ({e}): {url:?}")),
    }
}

fn validate_ros1(r: &super::Ros1Config) -> Result<(), Problem> {
    let at = FieldPath::from("ros1");
    if let Some(uri) = &r.master_uri {
        let ok = uri
            .strip_prefix("http://")
            .and_then(|rest| rest.split('/').next())
            .and_then(|hp| hp.rsplit_once(':'))
            .is_some_and(|(h, p)| !h.is_empty() && p.parse::<u16>().is_ok());
        if !ok {
            return Err(problem(
                at.key("master_uri"),
                format!("must be http://HOST:PORT such as http://localhost:11311, got {uri:?}"),
            ));
        }
    }
    if let Some(name) = &r.node_name {
        let bare = name.strip_prefix('/').unwrap_or(name);
        let valid = !bare.is_empty()
            && bare.split('/').all(|part| {
                part.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
                    && part.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            });
        if !valid {
            return Err(problem(
                at.key("node_name"),
                format!("must be a ROS name such as /fleetlink_agent, got {name:?}"),
            ));
        }
    }
    if r.host.as_deref().is_some_and(|h| h.trim().is_empty()) {
        return Err(problem(at.key("host"), "must not be empty"));
    }
    let lists = [
        (at.key("publish").key("include"), &r.publish.include),
        (at.key("publish").key("exclude"), &r.publish.exclude),
        (at.key("services").key("expose"), &r.services.expose),
        (at.key("services").key("exclude"), &r.services.exclude),
        (at.key("services").key("offer"), &r.services.offer),
    ];
    check_patterns(lists)?;
    check_bridge_common(&at, &r.subscribe, r.discovery_ms, r.call_timeout_ms)
}

fn validate_ros2(r: &super::Ros2Config) -> Result<(), Problem> {
    let at = FieldPath::from("ros2");
    if let Some(d) = r.domain_id
        && d > 232
    {
        return Err(problem(
            at.key("domain_id"),
            format!("must be a DDS domain id 0..=232 (ROS 2's usable range), got {d}"),
        ));
    }
    if let Some(name) = &r.node_name
        && !is_ros2_node_name(name)
    {
        return Err(problem(
            at.key("node_name"),
            format!(
                "must be a ROS 2 node name such as fleetlink_agent or /robot/fleetlink_agent \
                 (letters, digits and _, not starting with a digit), got {name:?}"
            ),
        ));
    }
    if let Some(d) = &r.distro
        && fleetlink_ros2::node_info::gid_len(d).is_none()
    {
        return Err(problem(
            at.key("distro"),
            format!(
                "is not a ROS 2 distribution the agent knows, got {d:?} (humble, iron, jazzy, \
                 kilted, rolling, ...; leave it out to learn it from the graph)"
            ),
        ));
    }
    let lists = [
        (at.key("publish").key("include"), &r.publish.include),
        (at.key("publish").key("exclude"), &r.publish.exclude),
        (at.key("services").key("expose"), &r.services.expose),
        (at.key("services").key("exclude"), &r.services.exclude),
        (at.key("services").key("offer"), &r.services.offer),
        (at.key("actions").key("expose"), &r.actions.expose),
        (at.key("actions").key("exclude"), &r.actions.exclude),
        (at.key("actions").key("offer"), &r.actions.offer),
        (at.key("read"), &r.read),
    ];
    check_patterns(lists)?;
    check_bridge_common(&at, &r.subscribe, r.discovery_ms, r.call_timeout_ms)
}

fn validate_blackbox(b: &super::BlackBoxConfig) -> Result<(), Problem> {
    let at = FieldPath::from("blackbox");
    if b.dir.trim().is_empty() {
        return Err(problem(
            at.key("dir"),
            "is required: a directory on the robot for the ring, such as \
             /var/lib/fleetlink/blackbox",
        ));
    }
    let min_mb = fleetlink_record::blackbox::ring::MIN_RING_BYTES >> 20;
    if b.max_mb < min_mb {
        return Err(problem(
            at.key("max_mb"),
            format!("must be at least {min_mb} (MiB), got {}", b.max_mb),
        ));
    }
    if b.topics.is_empty() {
        return Err(problem(
            at.key("topics"),
            "is required: the local topics to keep, such as [/scan, /odom, /camera/.*]",
        ));
    }
    check_patterns([(at.key("topics"), &b.topics)])
}

/// `video:`: each camera topic and video topic a valid name, the video topic neither the
/// camera's nor another stream's, the settings in range; `openh264_library` a file.
fn validate_video(cfg: &AgentConfig) -> Result<(), Problem> {
    let at = FieldPath::from("video");
    let mut seen: BTreeMap<&str, &str> = BTreeMap::new();
    for (camera, stream) in &cfg.video {
        check_topic(camera).map_err(|m| Problem {
            path: at.key(camera.clone()),
            at_key: true,
            message: format!("camera topic {m}"),
        })?;
        let here = at.key(camera.clone());
        check_topic(&stream.topic).map_err(|m| problem(here.key("topic"), m))?;
        if stream.topic == *camera {
            return Err(problem(
                here.key("topic"),
                format!(
                    "is the camera topic itself; name the video topic beside it, such as \
                     {}/video",
                    camera.rsplit_once('/').map_or("", |(dir, _)| dir)
                ),
            ));
        }
        if let Some(other) = seen.insert(&stream.topic, camera) {
            return Err(problem(
                here.key("topic"),
                format!(
                    "{} is already the video of {other}; give each camera its own",
                    stream.topic
                ),
            ));
        }
        if cfg.video.contains_key(&stream.topic) {
            return Err(problem(
                here.key("topic"),
                format!(
                    "{} is a camera topic of video: too; a video topic cannot be a camera",
                    stream.topic
                ),
            ));
        }
        if let Some((field, message)) = stream.problem() {
            return Err(problem(here.key(field), message));
        }
    }
    if let Some(path) = &cfg.openh264_library
        && !path.is_file()
    {
        return Err(problem(
            "openh264_library".into(),
            format!(
                "{} is not a file: give the path of Cisco's libopenh264.so (docs/video.md), \
                 or leave it out to use the built-in encoder",
                path.display()
            ),
        ));
    }
    Ok(())
}

fn validate_rosbridge(r: &super::RosbridgeConfig) -> Result<(), Problem> {
    let at = FieldPath::from("rosbridge");
    if r.url.is_empty() {
        return Err(problem(
            at.key("url"),
            "is required: the robot's rosbridge server, such as ws://192.168.1.10:9090",
        ));
    }
    if !(r.url.starts_with("ws://") || r.url.starts_with("wss://")) {
        return Err(problem(
            at.key("url"),
            format!(
                "must be a ws:// or wss:// URL such as ws://192.168.1.10:9090, got {:?}",
                r.url
            ),
        ));
    }
    check_hub_url(&r.url).map_err(|m| problem(at.key("url"), m))?;
    let lists = [
        (at.key("publish").key("include"), &r.publish.include),
        (at.key("publish").key("exclude"), &r.publish.exclude),
        (at.key("services").key("expose"), &r.services.expose),
        (at.key("services").key("exclude"), &r.services.exclude),
        (at.key("services").key("offer"), &r.services.offer),
        (at.key("actions").key("expose"), &r.actions.expose),
        (at.key("actions").key("exclude"), &r.actions.exclude),
    ];
    check_patterns(lists)?;
    if !r.actions.offer.is_empty() {
        return Err(problem(
            at.key("actions").key("offer"),
            "is not supported by the rosbridge client: fleet actions cannot be offered on \
             a rosbridge server yet (expose the server's actions with actions.expose)",
        ));
    }
    check_bridge_common(&at, &r.subscribe, r.discovery_ms, r.call_timeout_ms)?;
    // A topic both read from the server and written to it would come straight back
    // (a rosbridge server delivers a client's own publishes to its subscriptions).
    let publish = fleetlink_relay::names::NameFilter::new(&r.publish.include, &r.publish.exclude)
        .map_err(|e| problem(at.key("publish"), e.to_string()))?;
    if let Some((i, t)) = r
        .subscribe
        .iter()
        .enumerate()
        .find(|(_, t)| publish.matches(t))
    {
        return Err(problem(
            at.key("subscribe").index(i),
            format!(
                "{t:?} also matches rosbridge.publish: it would be sent to the server and \
                 read back from it in a loop; exclude it there (publish.exclude)"
            ),
        ));
    }
    if r.reconnect.initial_ms == 0 {
        return Err(problem(
            at.key("reconnect").key("initial_ms"),
            "must be > 0, got 0",
        ));
    }
    if r.reconnect.max_ms < r.reconnect.initial_ms {
        return Err(problem(
            at.key("reconnect").key("max_ms"),
            format!(
                "must be >= rosbridge.reconnect.initial_ms ({}), got {}",
                r.reconnect.initial_ms, r.reconnect.max_ms
            ),
        ));
    }
    Ok(())
}

/// A ROS 2 node name, maybe with its namespace: `/`-separated tokens of `[A-Za-z0-9_]`
/// that do not start with a digit.
fn is_ros2_node_name(name: &str) -> bool {
    let t = name.strip_prefix('/').unwrap_or(name);
    !t.is_empty()
        && t.split('/').all(|c| {
            !c.is_empty()
                && !c.starts_with(|ch: char| ch.is_ascii_digit())
                && c.chars().all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
        })
}

/// Every entry of each list is a whole-name regular expression.
fn check_patterns<'a>(
    lists: impl IntoIterator<Item = (FieldPath, &'a Vec<String>)>,
) -> Result<(), Problem> {
    for (path, list) in lists {
        for (i, p) in list.iter().enumerate() {
            if let Err(e) = regex::Regex::new(&format!("^(?:{p})$")) {
                // The regex error draws a caret diagram over several lines; its last line
                // says what is wrong.
                let text = e.to_string();
                let reason = text.lines().last().unwrap_or(&text).trim();
                return Err(problem(
                    path.index(i),
                    format!("is not a valid pattern ({reason}): {p:?}"),
                ));
            }
        }
    }
    Ok(())
}

/// What the ROS 1 and ROS 2 sections share: topics to subscribe, periods > 0.
fn check_bridge_common(
    at: &FieldPath,
    subscribe: &[String],
    discovery_ms: u64,
    call_timeout_ms: u64,
) -> Result<(), Problem> {
    for (i, t) in subscribe.iter().enumerate() {
        check_topic(t).map_err(|m| problem(at.key("subscribe").index(i), m))?;
    }
    if discovery_ms == 0 {
        return Err(problem(at.key("discovery_ms"), "must be > 0, got 0"));
    }
    if call_timeout_ms == 0 {
        return Err(problem(at.key("call_timeout_ms"), "must be > 0, got 0"));
    }
    Ok(())
}

fn validate_sim(sim: &SimConfig) -> Result<(), Problem> {
    let mut seen: BTreeMap<&str, &str> = BTreeMap::new();
    for (key, topic, rate_hz) in sim.enabled_topics() {
        let at = FieldPath::from("sim").key(key);
        check_topic(topic).map_err(|m| problem(at.key("topic"), m))?;
        if let Some(first) = seen.insert(topic, key) {
            return Err(problem(
                at.key("topic"),
                format!("{topic:?} is already used by sim.{first}; sim topics must be unique"),
            ));
        }
        if !(rate_hz > 0.0 && rate_hz.is_finite()) {
            return Err(problem(
                at.key("rate_hz"),
                format!("must be > 0, got {rate_hz}"),
            ));
        }
        if rate_hz > 1000.0 {
            return Err(problem(
                at.key("rate_hz"),
                format!("must be <= 1000, got {rate_hz}"),
            ));
        }
    }
    let counts = [
        sim.laser_scan
            .as_ref()
            .map(|s| ("laser_scan", "ranges", s.ranges, 1, 100_000)),
        sim.point_cloud
            .as_ref()
            .map(|s| ("point_cloud", "points", s.points, 1, 5_000_000)),
        sim.image
            .as_ref()
            .map(|s| ("image", "width", s.width, 16, 4096)),
        sim.image
            .as_ref()
            .map(|s| ("image", "height", s.height, 16, 4096)),
        sim.image
            .as_ref()
            .map(|s| ("image", "quality", s.quality, 1, 100)),
    ];
    if let Some(image) = &sim.image
        && image.removed_bytes.is_some()
    {
        return Err(Problem {
            path: "sim.image.bytes".into(),
            at_key: true,
            message: "is no longer read: the camera now renders a JPEG picture of the room; \
                      set its size with `width` and `height` (pixels, default 320 and 240) \
                      and `quality` (1-100, default 75) instead, and remove `bytes`"
                .into(),
        });
    }
    for (sensor, field, value, min, max) in counts.into_iter().flatten() {
        if !(min..=max).contains(&value) {
            return Err(problem(
                FieldPath::from("sim").key(sensor).key(field),
                format!("must be in {min}..={max}, got {value}"),
            ));
        }
    }
    Ok(())
}

/// A fully qualified ROS topic name: `/` then `/`-separated tokens of `[A-Za-z0-9_]`,
/// no empty token, no trailing `/`.
pub(crate) fn check_topic(topic: &str) -> Result<(), String> {
    if topic.is_empty() {
        return Err("must not be empty".into());
    }
    let Some(rest) = topic.strip_prefix('/') else {
        return Err(format!("must start with '/', got {topic:?}"));
    };
    if rest.is_empty() || rest.split('/').any(str::is_empty) {
        return Err(format!(
            "must be '/'-separated non-empty names, got {topic:?}"
        ));
    }
    if let Some(c) = rest
        .chars()
        .find(|c| !(c.is_ascii_alphanumeric() || *c == '_' || *c == '/'))
    {
        return Err(format!(
            "may only contain A-Z, a-z, 0-9, _ and /, got {c:?} in {topic:?}"
        ));
    }
    Ok(())
}
