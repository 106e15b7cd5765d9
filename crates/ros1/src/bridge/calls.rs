//! Service calls both ways through the router's call table: fleet calls of local
//! services, and fleet services offered to local nodes (registered with the master).

use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Instant;

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{CallRequest, CallStatus, PeerMsg, ServiceChange};

use crate::node::{Node, Offered, srv_type_of};
use crate::outbound::call_service;

/// Watches the fleet services the options offer to local nodes, and withdraws from the
/// master those they no longer do (after a runtime change).
pub(super) async fn follow_offers(node: &Arc<Node>) {
    let opts = node.live();
    let gone: Vec<String> = {
        let mut st = node.lock();
        let names: Vec<String> = st
            .offered
            .keys()
            .filter(|n| !opts.offer.matches(n))
            .cloned()
            .collect();
        for n in &names {
            st.offered.remove(n);
            st.registered_services.remove(n);
        }
        names
    };
    for name in gone {
        let _ = node
            .master
            .unregister_service(&name, &node.service_api)
            .await;
        tracing::info!("ros1: fleet service {name} no longer offered to local nodes");
    }
    // Watched anew: the services that match now are told at once.
    node.router.calls.unwatch(node.client);
    for re in &opts.offer.include {
        node.router.calls.watch(node.client, re.clone());
    }
}

pub(super) fn on_peer(node: &Arc<Node>, m: PeerMsg) {
    match m {
        PeerMsg::Call(req) => {
            let node = node.clone();
            tokio::spawn(async move { serve_call(&node, req).await });
        }
        PeerMsg::Event(ev) => node.answer(ev),
        PeerMsg::Cancel(_) => {}
        PeerMsg::Changed(ServiceChange::Added(info)) => {
            let name = info.name.as_str();
            if info.action || info.provider == node.client || !node.live().offer.matches(name) {
                return;
            }
            let srv_type = srv_type_of(&info.schema.type_name);
            let Some(identity) = node.router.transcoder().ros1_identity(&srv_type) else {
                tracing::warn!(
                    "ros1: cannot offer fleet service {name} to local nodes: type {:?} is unknown to the registry",
                    info.schema.type_name
                );
                return;
            };
            tracing::info!(
                "ros1: offering fleet service {name} ({}) to local nodes",
                identity.type_name
            );
            node.lock()
                .offered
                .insert(name.to_owned(), Offered { srv_type, identity });
            let node = node.clone();
            let name = name.to_owned();
            tokio::spawn(async move { register_service(&node, &name).await });
        }
        PeerMsg::Changed(ServiceChange::Removed(info)) => {
            let name = info.name.as_str().to_owned();
            let removed = {
                let mut st = node.lock();
                st.registered_services.remove(&name);
                st.offered.remove(&name).is_some()
            };
            if removed {
                let node = node.clone();
                tokio::spawn(async move {
                    let _ = node
                        .master
                        .unregister_service(&name, &node.service_api)
                        .await;
                });
            }
        }
    }
}

pub(super) async fn register_service(node: &Node, name: &str) {
    match node.master.register_service(name, &node.service_api).await {
        Ok(()) => {
            node.lock().registered_services.insert(name.to_owned());
            node.stats.master_registrations.fetch_add(1, Relaxed);
        }
        Err(e) => tracing::debug!("ros1: registering service {name}: {e}"),
    }
}

/// A fleet caller's call of a local ROS service.
async fn serve_call(node: &Node, req: CallRequest) {
    let name = req.service.name.as_str();
    if node.opts.parameters && fleetlink_relay::params::is_param_service(name) {
        return crate::params::serve(node, &req).await;
    }
    let found = node
        .lock()
        .exposed
        .get(name)
        .map(|e| (e.srv_type.clone(), e.md5sum.clone()));
    let respond = |status, payload, text: String| {
        node.router
            .calls
            .respond(node.client, req.id, status, payload, text);
    };
    let Some((srv_type, md5sum)) = found else {
        respond(
            CallStatus::NoProvider,
            None,
            format!("{name} is not exposed by the ROS 1 bridge"),
        );
        return;
    };
    let schema = Schema {
        type_name: format!("{srv_type}_Request"),
        encoding: "ros1msg".into(),
        text: String::new(),
    };
    let request = match node
        .router
        .transcoder()
        .convert(&schema, &req.payload, Encoding::Ros1)
    {
        Ok(b) => b,
        Err(e) => {
            respond(CallStatus::Failed, None, e.to_string());
            return;
        }
    };
    // A provider that never answers must not hold this task past the caller's deadline.
    let limit = req.deadline.map_or(node.opts.call_timeout, |d| {
        d.saturating_duration_since(Instant::now())
    });
    match tokio::time::timeout(limit, call_service(node, name, &md5sum, &request)).await {
        Ok(Ok(body)) => respond(
            CallStatus::Ok,
            Some(Payload::new(Encoding::Ros1, body)),
            String::new(),
        ),
        Ok(Err(text)) => respond(CallStatus::Failed, None, text),
        Err(_) => respond(
            CallStatus::Timeout,
            None,
            format!("{name} did not answer within {limit:?}"),
        ),
    }
}
