//! Discovery: once per period while connected, the server's rosapi is asked what it has
//! (topics, services, action servers), and what matches the options is bridged; what the
//! server no longer lists is let go. Definitions of types the agent does not know come
//! from `/rosapi/message_details`.

use std::collections::HashSet;
use std::sync::Arc;

use fleetlink_proto::Schema;
use fleetlink_relay::TopicName;
use serde_json::Value;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use crate::ops;
use crate::shared::{Exposed, Shared, Up};

/// Once per period while connected: what the server has now, bridged or let go.
pub(crate) async fn discovery(shared: Arc<Shared>) {
    let mut tick = tokio::time::interval(shared.opts.discovery_period);
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    loop {
        tick.tick().await;
        if shared.lock().ros_version.is_none() {
            let v = shared
                .request("/rosapi/get_ros_version", Value::Object(Default::default()))
                .await
                .ok()
                .and_then(|v| v.get("version").and_then(Value::as_u64));
            shared.lock().ros_version = Some(v.unwrap_or(2));
        }
        if !shared.opts.publish.is_empty() {
            follow_topics(&shared).await;
        }
        if !shared.opts.expose.is_empty() {
            follow_services(&shared, false).await;
        }
        if !shared.opts.expose_actions.is_empty() {
            follow_services(&shared, true).await;
        }
    }
}

async fn follow_topics(shared: &Arc<Shared>) {
    let listed = match shared
        .request("/rosapi/topics", Value::Object(Default::default()))
        .await
    {
        Ok(v) => v,
        Err(e) => {
            tracing::debug!("rosbridge: /rosapi/topics: {e}");
            return;
        }
    };
    let names = strings(&listed, "topics");
    let types = strings(&listed, "types");
    let own: HashSet<&str> = shared.opts.subscribe.iter().map(|t| t.as_str()).collect();
    let wanted: Vec<(String, String)> = names
        .iter()
        .enumerate()
        .filter(|(_, n)| shared.opts.publish.matches(n) && !own.contains(n.as_str()))
        .map(|(i, n)| (n.clone(), types.get(i).cloned().unwrap_or_default()))
        .collect();
    let (new, gone): (Vec<(String, String)>, Vec<String>) = {
        let st = shared.lock();
        (
            wanted
                .iter()
                .filter(|(n, _)| !st.up.contains_key(n))
                .cloned()
                .collect(),
            st.up
                .keys()
                .filter(|n| !wanted.iter().any(|(w, _)| w == *n))
                .cloned()
                .collect(),
        )
    };
    for (topic, type_name) in new {
        let Ok(name) = TopicName::parse(&topic) else {
            tracing::warn!("rosbridge: the server's topic {topic:?} is not a valid ROS name");
            continue;
        };
        if type_name.is_empty() {
            tracing::warn!("rosbridge: the server lists {topic} without a type; not bridged");
            continue;
        }
        let schema = schema_of(shared, &type_name).await;
        let topic_handle = match shared.router.advertise(shared.client, &name, schema, false) {
            Ok(t) => t,
            Err(e) => {
                tracing::warn!("rosbridge: cannot bridge {topic}: {e}");
                continue;
            }
        };
        tracing::info!("rosbridge: bridging the server's {topic} ({type_name}) to the fleet");
        let mut st = shared.lock();
        shared.send(&st, WsMessage::text(ops::subscribe(&topic, &type_name)));
        st.up.insert(
            topic,
            Up {
                type_name,
                topic: topic_handle,
                seq: 0,
            },
        );
    }
    for topic in gone {
        let mut st = shared.lock();
        st.up.remove(&topic);
        shared.send(&st, WsMessage::text(ops::unsubscribe(&topic)));
        drop(st);
        if let Ok(name) = TopicName::parse(&topic) {
            shared.router.unadvertise(shared.client, &name);
        }
        tracing::info!("rosbridge: the server no longer lists {topic}; no longer bridged");
    }
}

/// The schema of a server topic's type: the registry's definition when the agent knows
/// the type, else the definition the server's rosapi gives (`message_details`), else
/// the name alone (messages then travel as JSON, unconverted).
async fn schema_of(shared: &Arc<Shared>, type_name: &str) -> Schema {
    if let Some(s) = shared.router.transcoder().schema_for(type_name) {
        return s;
    }
    let details = shared
        .request(
            "/rosapi/message_details",
            serde_json::json!({ "type": type_name }),
        )
        .await;
    let encoding = match shared.lock().ros_version {
        Some(1) => "ros1msg",
        _ => "ros2msg",
    };
    match details.and_then(|d| {
        let defs = d.get("typedefs").cloned().unwrap_or(Value::Null);
        crate::typedefs::full_text(type_name, &defs).map_err(|e| e.to_string())
    }) {
        Ok(text) => Schema {
            type_name: type_name.to_owned(),
            encoding: encoding.into(),
            text,
        },
        Err(e) => {
            tracing::warn!(
                "rosbridge: no definition of {type_name} from the server ({e}); its messages \
                 go to the fleet as JSON only"
            );
            Schema::named(type_name)
        }
    }
}

/// The server's services (or action servers) matching `expose` in the call table.
async fn follow_services(shared: &Arc<Shared>, actions: bool) {
    let (service, key, filter) = if actions {
        (
            "/rosapi/action_servers",
            "action_servers",
            &shared.opts.expose_actions,
        )
    } else {
        ("/rosapi/services", "services", &shared.opts.expose)
    };
    let listed = match shared
        .request(service, Value::Object(Default::default()))
        .await
    {
        Ok(v) => strings(&v, key),
        Err(e) => {
            tracing::debug!("rosbridge: {service}: {e}");
            return;
        }
    };
    let wanted: Vec<String> = {
        let st = shared.lock();
        listed
            .into_iter()
            .filter(|s| filter.matches(s) && !st.offered.contains_key(s))
            .collect()
    };
    let (new, gone): (Vec<String>, Vec<String>) = {
        let st = shared.lock();
        (
            wanted
                .iter()
                .filter(|s| !st.exposed.contains_key(*s))
                .cloned()
                .collect(),
            st.exposed
                .iter()
                .filter(|(s, e)| e.action == actions && !wanted.contains(s))
                .map(|(s, _)| s.clone())
                .collect(),
        )
    };
    for s in new {
        let Ok(name) = TopicName::parse(&s) else {
            continue;
        };
        let type_name = match shared
            .request("/rosapi/service_type", serde_json::json!({ "service": s }))
            .await
        {
            Ok(v) => v
                .get("type")
                .and_then(Value::as_str)
                .unwrap_or_default()
                .to_owned(),
            Err(e) => {
                tracing::debug!("rosbridge: type of {s}: {e}");
                continue;
            }
        };
        if type_name.is_empty() {
            tracing::warn!("rosbridge: the server gives no type for {s}; not exposed");
            continue;
        }
        let schema = shared
            .router
            .transcoder()
            .schema_for(&type_name)
            .unwrap_or_else(|| Schema::named(type_name.clone()));
        let what = if actions { "action" } else { "service" };
        tracing::info!("rosbridge: exposing the server's {what} {s} ({type_name}) to the fleet");
        shared.lock().exposed.insert(
            s.clone(),
            Exposed {
                type_name,
                action: actions,
            },
        );
        shared
            .router
            .calls
            .advertise(shared.client, name, schema, actions);
    }
    for s in gone {
        shared.lock().exposed.remove(&s);
        if let Ok(name) = TopicName::parse(&s) {
            shared.router.calls.unadvertise(shared.client, &name);
        }
        tracing::info!("rosbridge: the server no longer lists {s}; no longer exposed");
    }
}

fn strings(v: &Value, key: &str) -> Vec<String> {
    v.get(key)
        .and_then(Value::as_array)
        .map(|a| {
            a.iter()
                .filter_map(|s| s.as_str().map(str::to_owned))
                .collect()
        })
        .unwrap_or_default()
}
