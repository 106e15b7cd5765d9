//! Runs a [`Sim`] in real time: publishes its messages into the agent's local router at
//! their due times, as an in-process participant. The simulator itself stays sans-IO;
//! this is the only part that looks at a clock.

use std::sync::Arc;
use std::time::{Duration, Instant};

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{CallStatus, ChannelPeer, PeerMsg};
use fleetlink_relay::{ClientKind, Router, TopicName};
use serde_json::Value;
use tokio_util::sync::CancellationToken;

use super::Sim;
use super::services::{Answer, FEEDBACK_EVERY, SimCalls, offered};
use crate::config::SimConfig;

pub async fn drive(
    cfg: SimConfig,
    robot: String,
    router: Arc<Router>,
    shutdown: CancellationToken,
) {
    let mut sim = Sim::new(&cfg, &robot, fleetlink_relay::unix_nanos());
    let (client, _) = router.connect(ClientKind::Internal { role: "sim".into() }, None);
    let mut topics = Vec::new();
    for t in sim.topics() {
        let topic = TopicName::parse(&t.name)
            .map_err(|e| e.to_string())
            .and_then(|n| {
                router
                    .advertise(client, &n, Schema::named(t.type_name), false)
                    .map_err(|e| e.to_string())
            });
        match topic {
            Ok(topic) => topics.push(Some((topic, 0u64))),
            Err(e) => {
                tracing::warn!("simulator cannot publish {}: {e}", t.name);
                topics.push(None);
            }
        }
    }
    // Services and the navigation action, on the robot's local call table.
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    for (name, schema, action) in offered() {
        let name = TopicName::parse(name).expect("a constant name");
        router.calls.advertise(client, name, schema, action);
    }
    let mut state = SimCalls::default();
    let reply = |id, status, values: Option<Value>, text: String| {
        let payload = values.map(|v| Payload::json(v.to_string().into_bytes()));
        router.calls.respond(client, id, status, payload, text);
    };
    // The camera is rendered only while someone wants its pictures (the hub, a local
    // subscriber, a video stream): drawing and encoding 640x480 JPEGs at 15 Hz is most of
    // the demo's CPU otherwise.
    let costly: Vec<bool> = (0..topics.len()).map(|i| sim.is_costly(i)).collect();
    let start = Instant::now();
    let mut next_feedback = start;
    let mut due = Vec::new();
    loop {
        let mut wait = sim.next_due().saturating_sub(start.elapsed());
        if state.goal.is_some() {
            wait = wait.min(next_feedback.saturating_duration_since(Instant::now()));
        }
        tokio::select! {
            _ = tokio::time::sleep(wait.max(Duration::from_micros(100))) => {}
            m = peer_rx.recv() => {
                let now = start.elapsed();
                match m {
                    Some(PeerMsg::Call(req)) => {
                        let local = req.service.name.to_string();
                        let mut replaced = None;
                        let answer = state.on_call(&mut sim, now, &local, &req, &mut replaced);
                        if let Some((id, values)) = replaced {
                            reply(id, CallStatus::Cancelled, Some(values),
                                  "replaced by a newer goal".into());
                        }
                        match answer {
                            Answer::Reply { status, values, text } => reply(req.id, status, values, text),
                            Answer::Accepted => next_feedback = Instant::now(),
                        }
                    }
                    Some(PeerMsg::Cancel(id)) => {
                        if let Some(values) = state.on_cancel(&mut sim, now, id) {
                            reply(id, CallStatus::Cancelled, Some(values), "cancelled".into());
                        }
                    }
                    Some(_) => {}
                    None => break,
                }
                continue;
            }
            _ = shutdown.cancelled() => break,
        }
        if state.goal.is_some() && Instant::now() >= next_feedback {
            next_feedback = Instant::now() + FEEDBACK_EVERY;
            match state.progress(&mut sim, start.elapsed()) {
                Some((id, Ok(fb))) => {
                    router
                        .calls
                        .feedback(client, id, Payload::json(fb.to_string().into_bytes()));
                }
                Some((id, Err(result))) => reply(id, CallStatus::Ok, Some(result), String::new()),
                None => {}
            }
        }
        due.clear();
        sim.set_goal_marker(state.goal.as_ref().map(|g| g.to));
        let wanted = |i: usize| {
            !costly[i]
                || topics
                    .get(i)
                    .and_then(Option::as_ref)
                    .is_some_and(|(t, _)| t.wanted_by_others(client))
        };
        sim.poll_wanted_into(start.elapsed(), &mut due, wanted);
        for m in due.drain(..) {
            if let Some(Some((topic, seq))) = topics.get_mut(m.topic_index) {
                *seq += 1;
                // A ROS 2 robot publishes CDR; do the same when the type is known, so the
                // hub converts once per subscriber encoding and `cbor-raw` has raw bytes.
                let json = Payload::json(m.json);
                let payload = router
                    .transcoder()
                    .convert(&topic.meta().schema, &json, Encoding::Cdr)
                    .map(|b| Payload::new(Encoding::Cdr, b))
                    .unwrap_or(json);
                topic.publish(client, *seq, m.stamp_ns, payload);
            }
        }
    }
    router.disconnect(client);
}
