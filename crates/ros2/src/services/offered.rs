//! Fleet services and actions offered to local clients. A service ([`Offered`]) is a
//! request reader and a reply writer: each local request becomes a fleet call, and its
//! answer is written back in the caller's mapping ([`ReplyTo`]). Actions are served by
//! [`crate::offered_actions`].

use std::sync::Arc;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::TopicName;
use fleetlink_relay::calls::{CallEvent, CallOptions, CallStatus};
use futures::StreamExt;
use rustdds::{GUID, SampleIdentity, WriteOptionsBuilder};
use tokio::task::AbortHandle;

use super::endpoint::Mapping;
use crate::bridge::{Bridge, RawReader, RawWriter};
use crate::names;
use crate::qos;
use crate::raw::{RawCdr, RequestHeader};

/// A fleet service offered to local clients.
pub struct Offered {
    srv_type: String,
    replies: RawWriter,
    pub(crate) task: AbortHandle,
}

/// Where a local caller's answer goes.
pub(crate) struct LocalCall {
    service: String,
    reply: ReplyTo,
}

/// What ties a local caller's reply to its request, in the caller's mapping.
#[derive(Debug, Clone, Copy)]
pub(crate) enum ReplyTo {
    Cyclone(RequestHeader),
    FastDds(SampleIdentity),
}

impl ReplyTo {
    /// A local client's request sample (`raw`, described by `info`): where its reply
    /// goes, and the request message as a CDR sample of its own. `None`: a Cyclone-style
    /// sample too short for its header.
    pub(crate) fn of_request(info: &rustdds::SampleInfo, raw: Bytes) -> Option<(ReplyTo, Bytes)> {
        let (related, id) = (info.related_sample_identity(), info.sample_identity());
        if related.is_some() || Mapping::of(id.writer_guid) == Mapping::FastDds {
            // A Fast DDS client names its reply reader; else its writer gets the reply.
            let writer_guid = related
                .map(|r| r.writer_guid)
                .filter(|g| *g != GUID::GUID_UNKNOWN)
                .unwrap_or(id.writer_guid);
            let to = SampleIdentity {
                writer_guid,
                sequence_number: id.sequence_number,
            };
            return Some((ReplyTo::FastDds(to), raw));
        }
        let header = RequestHeader::read(&raw)?;
        Some((ReplyTo::Cyclone(header), RequestHeader::strip(&raw)?))
    }

    /// Writes `body` (a CDR message with its encapsulation header) as the reply.
    pub(crate) fn reply(&self, writer: &RawWriter, body: Bytes) -> Result<(), String> {
        match self {
            ReplyTo::Cyclone(header) => writer
                .write(RawCdr(header.prepend(&body)), None)
                .map_err(|e| format!("writing a reply: {e:?}")),
            ReplyTo::FastDds(to) => {
                let options = WriteOptionsBuilder::new()
                    .related_sample_identity(*to)
                    .build();
                writer
                    .write_with_options(RawCdr(body), options)
                    .map(|_| ())
                    .map_err(|e| format!("writing a reply: {e:?}"))
            }
        }
    }
}

/// Watches the fleet services and actions the options offer to local nodes, and stops
/// offering those they no longer do (after a runtime change).
pub(crate) fn follow_offers(bridge: &Arc<Bridge>) {
    let opts = bridge.live();
    let (services, actions) = {
        let mut st = bridge.lock();
        let services: Vec<_> = st
            .offered
            .keys()
            .filter(|n| !opts.offer.matches(n))
            .cloned()
            .collect();
        let actions: Vec<_> = st
            .offered_actions
            .keys()
            .filter(|n| !opts.offer_actions.matches(n))
            .cloned()
            .collect();
        (
            services
                .into_iter()
                .filter_map(|n| st.offered.remove(&n).map(|o| (n, o)))
                .collect::<Vec<_>>(),
            actions
                .into_iter()
                .filter_map(|n| st.offered_actions.remove(&n).map(|a| (n, a)))
                .collect::<Vec<_>>(),
        )
    };
    for (name, o) in services {
        o.task.abort();
        tracing::info!("ros2: fleet service {name} no longer offered to local nodes");
    }
    for (name, a) in actions {
        a.abort();
        tracing::info!("ros2: fleet action {name} no longer offered to local nodes");
    }
    // Watched anew: the services that match now are told at once (those offered already
    // stay as they are).
    bridge.router.calls.unwatch(bridge.client);
    for re in opts.offer.include.iter().chain(&opts.offer_actions.include) {
        bridge.router.calls.watch(bridge.client, re.clone());
    }
}

/// Serves fleet action `name` to local action clients.
pub(super) fn offer_action(bridge: &Arc<Bridge>, name: &str, type_name: &str) {
    if bridge.lock().offered_actions.contains_key(name) {
        return;
    }
    match crate::offered_actions::offer(bridge, name, type_name) {
        Ok(a) => {
            tracing::info!("ros2: offering fleet action {name} ({type_name}) to local nodes");
            bridge.lock().offered_actions.insert(name.to_owned(), a);
        }
        Err(e) => tracing::warn!("ros2: cannot offer fleet action {name} to local nodes: {e}"),
    }
}

/// Offers fleet service `name` to local clients.
pub(super) fn offer(bridge: &Arc<Bridge>, name: &str, type_name: &str) {
    if bridge.lock().offered.contains_key(name) {
        return;
    }
    let srv_type = type_name.trim_end_matches("_Request").to_owned();
    let made = (|| {
        let dds = |suffix: &str| {
            names::dds_type(&format!("{srv_type}{suffix}"))
                .ok_or_else(|| format!("{srv_type:?} is not a ROS service type name"))
        };
        let requests = bridge.reader(
            &names::request_topic(name),
            &dds("_Request")?,
            qos::service(),
        )?;
        let replies = bridge.writer(
            &names::reply_topic(name),
            &dds("_Response")?,
            qos::service(),
        )?;
        Ok::<_, String>((requests, replies))
    })();
    let (requests, replies) = match made {
        Ok(m) => m,
        Err(e) => {
            tracing::warn!("ros2: cannot offer fleet service {name} to local nodes: {e}");
            return;
        }
    };
    let task =
        tokio::spawn(pump_requests(bridge.clone(), name.to_owned(), requests)).abort_handle();
    tracing::info!("ros2: offering fleet service {name} ({srv_type}) to local nodes");
    bridge.lock().offered.insert(
        name.to_owned(),
        Arc::new(Offered {
            srv_type,
            replies,
            task,
        }),
    );
}

/// Local clients' requests of an offered fleet service → fleet calls.
async fn pump_requests(bridge: Arc<Bridge>, service: String, reader: RawReader) {
    let Ok(name) = TopicName::parse(&service) else {
        return;
    };
    let mut samples = reader.async_sample_stream();
    while let Some(r) = samples.next().await {
        let Ok(sample) = r else { continue };
        if bridge.is_own(sample.sample_info().writer_guid()) {
            continue;
        }
        let info = sample.sample_info().clone();
        let Some((reply, msg)) = ReplyTo::of_request(&info, sample.into_value().0) else {
            continue;
        };
        let opts = CallOptions {
            timeout: Some(bridge.opts.call_timeout),
            goal: false,
            goal_id: None,
            on_behalf_of: None,
        };
        match bridge
            .router
            .calls
            .call(bridge.client, &name, Payload::new(Encoding::Cdr, msg), opts)
        {
            Ok(id) => {
                bridge.lock().local_calls.insert(
                    id,
                    LocalCall {
                        service: service.clone(),
                        reply,
                    },
                );
            }
            Err(e) => tracing::warn!("ros2: a local call of {service} was refused: {}", e.text),
        }
    }
}

/// The end of a local caller's fleet call: the reply, written with the caller's header.
pub(super) fn answer_local(bridge: &Bridge, ev: CallEvent) {
    let CallEvent::Done {
        id,
        status,
        payload,
        text,
    } = ev
    else {
        return;
    };
    let (call, offered) = {
        let mut st = bridge.lock();
        let Some(call) = st.local_calls.remove(&id) else {
            return;
        };
        let offered = st.offered.get(&call.service).cloned();
        (call, offered)
    };
    let Some(offered) = offered else {
        return;
    };
    let Some(payload) = payload.filter(|_| status == CallStatus::Ok) else {
        // ROS 2 services have no error reply: the local client times out.
        tracing::warn!(
            "ros2: a local call of {} failed ({status:?}): {text}",
            call.service
        );
        return;
    };
    match bridge.to_cdr(&format!("{}_Response", offered.srv_type), &payload) {
        Ok(body) => {
            if let Err(e) = call.reply.reply(&offered.replies, body) {
                tracing::debug!("ros2: replying to a local call of {}: {e}", call.service);
            }
        }
        Err(e) => tracing::warn!(
            "ros2: the answer of {} cannot be sent to the local caller: {e}",
            call.service
        ),
    }
}
