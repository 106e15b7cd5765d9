//! Services and actions both ways, over ROS 2's request/reply topics (`rq/<name>Request`,
//! `rr/<name>Reply`) in the two mappings ROS 2's middlewares use ([`Mapping`]): Cyclone
//! DDS's (a 16-byte request header in each sample: the client's id and a sequence number,
//! copied into the reply) and Fast DDS's (the request's own sample identity, echoed as the
//! reply's related sample identity in the RTPS inline QoS).
//!
//! - **Exposed** ([`Remote`]): a local server (a foreign reader on `rq/…Request`) matching
//!   `services.expose` is advertised in the call table; a fleet call becomes a request
//!   with this bridge's client id and the answer is matched by sequence number. An action
//!   server (its `send_goal` service) matching `actions.expose` is advertised as an
//!   action: a goal is a `send_goal` request, then `get_result`; feedback samples with the
//!   goal's UUID become the goal's feedback; a cancel is a `cancel_goal` request.
//! - **Offered** ([`Offered`]): a fleet service matching `services.offer` gets a reader on
//!   its request topic and a writer on its reply topic, so local clients call it like any
//!   ROS 2 service.
//!
//! Bodies are never decoded except an action's result (its `get_result` answer puts the
//! result after a status byte, so its alignment differs from a result of its own; the
//! registry converts that one message).
//!
//! # Layout
//!
//! - [`endpoint`]: one service of a local server as the bridge calls it ([`Endpoint`]).
//! - [`exposed`]: local servers exposed to the fleet ([`Remote`]).
//! - [`offered`]: fleet services offered to local clients ([`Offered`]), and which fleet
//!   actions are ([`crate::offered_actions`] serves them).

mod endpoint;
mod exposed;
mod offered;

use std::sync::Arc;

use fleetlink_relay::calls::{CallStatus, PeerMsg, ServiceChange};
use fleetlink_relay::params;

use crate::bridge::Bridge;
use exposed::{cancel, serve};
use offered::{answer_local, offer, offer_action};

pub(crate) use endpoint::{Endpoint, Mapping};
pub use exposed::Remote;
pub(crate) use exposed::discover;
pub use offered::Offered;
pub(crate) use offered::{LocalCall, ReplyTo, follow_offers};

/// The call table's messages for this bridge.
pub(crate) fn on_peer(bridge: &Arc<Bridge>, m: PeerMsg) {
    match m {
        PeerMsg::Call(req)
            if bridge.opts.parameters && params::is_param_service(req.service.name.as_str()) =>
        {
            let bridge = bridge.clone();
            tokio::spawn(async move { crate::params::serve(&bridge, &req).await });
        }
        PeerMsg::Call(req) => {
            let remote = bridge
                .lock()
                .remotes
                .get(req.service.name.as_str())
                .cloned();
            let bridge = bridge.clone();
            tokio::spawn(async move {
                match remote {
                    Some(r) => serve(&bridge, &r, req).await,
                    None => {
                        let text =
                            format!("{} is not exposed by the ROS 2 bridge", req.service.name);
                        bridge.router.calls.respond(
                            bridge.client,
                            req.id,
                            CallStatus::NoProvider,
                            None,
                            text,
                        );
                    }
                }
            });
        }
        PeerMsg::Cancel(id) => {
            let goal = bridge.lock().goals.get(&id).cloned();
            if let Some((remote, uuid)) = goal {
                tokio::spawn(async move { cancel(&remote, uuid).await });
            }
        }
        PeerMsg::Event(ev) => {
            let action = bridge.lock().offered_goals.get(&ev.id()).cloned();
            match action {
                Some(a) => crate::offered_actions::on_event(bridge, &a, ev),
                None => answer_local(bridge, ev),
            }
        }
        PeerMsg::Changed(ServiceChange::Added(info)) => {
            let name = info.name.as_str();
            if info.provider == bridge.client {
                return;
            }
            let opts = bridge.live();
            if info.action && opts.offer_actions.matches(name) {
                offer_action(bridge, name, &info.schema.type_name);
            } else if !info.action && opts.offer.matches(name) {
                offer(bridge, name, &info.schema.type_name);
            }
        }
        PeerMsg::Changed(ServiceChange::Removed(info)) => {
            let name = info.name.as_str();
            let (service, action) = {
                let mut st = bridge.lock();
                (st.offered.remove(name), st.offered_actions.remove(name))
            };
            if let Some(o) = &service {
                o.task.abort();
            }
            if let Some(a) = &action {
                a.abort();
            }
            if service.is_some() || action.is_some() {
                tracing::info!("ros2: fleet {name} is gone: no longer offered to local nodes");
            }
        }
    }
}
