//! The agent's status topic, `/fleetlink/diagnostics` (at the hub
//! `/<robot>/fleetlink/diagnostics`): a `diagnostic_msgs/msg/DiagnosticArray` every
//! [`PERIOD`], latched, with one `DiagnosticStatus` per ROS adapter and one for the uplink
//! (which hub it is connected to, or trying, and the round trip).
//! An adapter that found problems a user must act on (type mismatches, unknown types) is
//! at level WARN, its message says the newest of them and its values list every one, so
//! the problem shows wherever ROS diagnostics are read (Foxglove's and Lichtblick's
//! diagnostics panels, `rostopic echo`, a rosbridge client) and not only in the robot's log.
//! Published only when a ROS adapter is configured: a simulated robot has nothing to say.

use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::stats::AdapterReport;
use fleetlink_relay::{ClientKind, Router, TopicName};
use serde_json::{Value, json};
use tokio_util::sync::CancellationToken;

use crate::uplink::{LinkState, UplinkStats};

pub const TOPIC: &str = "/fleetlink/diagnostics";
pub const TYPE: &str = "diagnostic_msgs/msg/DiagnosticArray";
pub const PERIOD: Duration = Duration::from_secs(5);

/// `DiagnosticStatus.level`.
const OK: u8 = 0;
const WARN: u8 = 1;

/// One adapter on the status topic: `name` is `ros1` or `ros2`.
pub struct Part {
    pub name: &'static str,
    pub report: Arc<dyn AdapterReport>,
}

/// The status message of `robot` now (JSON of a `DiagnosticArray`).
pub fn message(
    robot: &str,
    parts: &[Part],
    uplink: &UplinkStats,
    link: &LinkState,
    stamp_ns: u64,
) -> Value {
    let kv = |k: &str, v: String| json!({"key": k, "value": v});
    let mut status = Vec::with_capacity(parts.len() + 1);
    for p in parts {
        let problems = p.report.problems();
        let mut values: Vec<Value> = p
            .report
            .counters()
            .into_iter()
            .map(|(k, v)| kv(k, v.to_string()))
            .collect();
        values.extend(problems.iter().map(|t| kv("problem", t.clone())));
        let (level, text) = match problems.last() {
            Some(newest) if problems.len() == 1 => (WARN, newest.clone()),
            Some(newest) => (
                WARN,
                format!("{} problems; the newest: {newest}", problems.len()),
            ),
            None => (OK, "ok".to_owned()),
        };
        status.push(json!({
            "level": level,
            "name": format!("fleetlink agent: {}", p.name),
            "message": text,
            "hardware_id": robot,
            "values": values,
        }));
    }
    let rtt_ms = uplink.rtt_ns.load(Relaxed) as f64 / 1e6;
    let (text, hub) = match link {
        LinkState::Connected { hub, .. } => (
            format!("connected to {hub}; round trip {rtt_ms:.1} ms"),
            hub.as_str(),
        ),
        LinkState::Connecting { hub, attempt } => (
            format!("connecting to {hub} (attempt {attempt})"),
            hub.as_str(),
        ),
        LinkState::Disconnected { reason } => (format!("disconnected: {reason}"), ""),
    };
    status.push(json!({
        "level": OK,
        "name": "fleetlink agent: uplink",
        "message": text,
        "hardware_id": robot,
        "values": [
            kv("hub", hub.to_owned()),
            kv("connects", uplink.connects.load(Relaxed).to_string()),
            kv("rtt_ms", format!("{rtt_ms:.1}")),
            kv("share_bytes_per_s", uplink.share_bps.load(Relaxed).to_string()),
        ],
    }));
    json!({
        "header": {
            "stamp": {"sec": stamp_ns / 1_000_000_000, "nanosec": stamp_ns % 1_000_000_000},
            "frame_id": "",
        },
        "status": status,
    })
}

/// Publishes the status of `parts` and the uplink (`link`: its state) every [`PERIOD`]
/// until `shutdown`.
pub async fn publish(
    router: Arc<Router>,
    robot: String,
    parts: Vec<Part>,
    uplink: Arc<UplinkStats>,
    link: tokio::sync::watch::Receiver<LinkState>,
    shutdown: CancellationToken,
) {
    let (client, _) = router.connect(
        ClientKind::Internal {
            role: "status".into(),
        },
        None,
    );
    let schema = router
        .transcoder()
        .schema_for(TYPE)
        .unwrap_or_else(|| Schema::named(TYPE));
    let topic = TopicName::parse(TOPIC)
        .map_err(|e| e.to_string())
        .and_then(|n| {
            router
                .advertise(client, &n, schema, true)
                .map_err(|e| e.to_string())
        });
    let topic = match topic {
        Ok(t) => t,
        Err(e) => {
            tracing::warn!("the agent's status topic {TOPIC} cannot be published: {e}");
            return;
        }
    };
    let mut tick = tokio::time::interval(PERIOD);
    let mut seq = 0;
    loop {
        tokio::select! {
            _ = tick.tick() => {}
            _ = shutdown.cancelled() => break,
        }
        seq += 1;
        let now = fleetlink_relay::unix_nanos();
        let json = Payload::json(
            message(&robot, &parts, &uplink, &link.borrow(), now)
                .to_string()
                .into_bytes(),
        );
        // CDR when the registry knows the type, as a ROS 2 robot would publish it.
        let payload = router
            .transcoder()
            .convert(&topic.meta().schema, &json, Encoding::Cdr)
            .map(|b| Payload::new(Encoding::Cdr, b))
            .unwrap_or(json);
        topic.publish(client, seq, now, payload);
    }
    router.disconnect(client);
}

#[cfg(test)]
mod tests {
    use super::*;
    use fleetlink_relay::stats::Problems;

    struct Fake(Problems);
    impl AdapterReport for Fake {
        fn counters(&self) -> Vec<(&'static str, u64)> {
            vec![("type_mismatches", self.0.list().len() as u64)]
        }
        fn problems(&self) -> Vec<String> {
            self.0.list()
        }
    }

    #[test]
    fn an_adapter_with_problems_warns_and_names_them() {
        let fake = Arc::new(Fake(Problems::default()));
        let parts = [Part {
            name: "ros1",
            report: fake.clone(),
        }];
        let uplink = UplinkStats::default();
        let link = LinkState::Connected {
            session: "s1".into(),
            namespace: "/robot1".into(),
            hub: "wss://b.example:8443".into(),
        };
        let m = message("robot1", &parts, &uplink, &link, 1_500_000_000);
        assert_eq!(m["status"][0]["level"], OK);
        assert_eq!(m["status"][0]["message"], "ok");
        assert_eq!(m["header"]["stamp"]["sec"], 1);
        assert_eq!(m["header"]["stamp"]["nanosec"], 500_000_000);

        fake.0.note("type mismatch on /cmd_vel: a vs b");
        fake.0.note("type mismatch on /odom: c vs d");
        let m = message("robot1", &parts, &uplink, &link, 0);
        let s = &m["status"][0];
        assert_eq!(s["level"], WARN);
        assert_eq!(s["name"], "fleetlink agent: ros1");
        assert_eq!(s["hardware_id"], "robot1");
        assert_eq!(
            s["message"],
            "2 problems; the newest: type mismatch on /odom: c vs d"
        );
        let problems: Vec<&str> = s["values"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|kv| kv["key"] == "problem")
            .map(|kv| kv["value"].as_str().unwrap())
            .collect();
        assert_eq!(
            problems,
            [
                "type mismatch on /cmd_vel: a vs b",
                "type mismatch on /odom: c vs d"
            ]
        );
        assert_eq!(m["status"][1]["name"], "fleetlink agent: uplink");
    }

    /// Issue 38: the uplink's status names the hub it is connected to, or trying.
    #[test]
    fn the_uplink_status_names_its_hub() {
        let uplink = UplinkStats::default();
        let hub = |m: &Value| m["status"][0]["values"][0].clone();
        let link = LinkState::Connected {
            session: "s1".into(),
            namespace: "/robot1".into(),
            hub: "wss://b.example:8443".into(),
        };
        let m = message("robot1", &[], &uplink, &link, 0);
        assert_eq!(m["status"][0]["name"], "fleetlink agent: uplink");
        assert_eq!(
            hub(&m),
            json!({"key": "hub", "value": "wss://b.example:8443"})
        );
        assert!(
            m["status"][0]["message"]
                .as_str()
                .unwrap()
                .starts_with("connected to wss://b.example:8443; round trip"),
            "{m}"
        );
        let link = LinkState::Connecting {
            attempt: 2,
            hub: "wss://a.example:8443".into(),
        };
        let m = message("robot1", &[], &uplink, &link, 0);
        assert_eq!(
            m["status"][0]["message"],
            "connecting to wss://a.example:8443 (attempt 2)"
        );
    }
}
