//! Connections this node opens: to local publishers (robot → hub) and to local service
//! providers (fleet → local service).
//!
//! A publisher connection asks for `*` type and md5sum, so any type is accepted, and takes
//! the publisher's `type`, `md5sum`, `message_definition` and `latching` from its header.
//! The router learns the definition with the topic; each message goes on as the bytes
//! that arrived (`Encoding::Ros1`), never decoded here.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Duration;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::TopicName;
use fleetlink_relay::router::RouteError;
use tokio::net::TcpStream;

use crate::master::request_topic;
use crate::node::Node;
use crate::tcpros::{
    FrameError, Header, read_header, read_message, read_service_response, write_header,
};

const CONNECT_TIMEOUT: Duration = Duration::from_secs(3);

/// How a publisher connection ended.
#[derive(Debug)]
pub enum PullEnd {
    /// The publisher went away or the connection broke: forget it (a restarted publisher
    /// comes back through `publisherUpdate`).
    Gone(String),
    /// The publisher is this node, or its type conflicts: keep it marked so it is not
    /// retried until its publisher list changes.
    Refused(String),
}

/// Receives `topic` from the publisher at `api` until the connection ends.
pub async fn pull(node: Arc<Node>, topic: String, api: String, seq: Arc<AtomicU64>) -> PullEnd {
    let gone = |e: String| PullEnd::Gone(e);
    let (host, port) = match request_topic(&node.opts.node_name, &api, &topic).await {
        Ok(ep) => ep,
        Err(e) => return gone(e.to_string()),
    };
    let mut stream = match tokio::time::timeout(
        CONNECT_TIMEOUT,
        TcpStream::connect((host.as_str(), port)),
    )
    .await
    {
        Ok(Ok(s)) => s,
        Ok(Err(e)) => return gone(format!("connect {host}:{port}: {e}")),
        Err(_) => return gone(format!("connect {host}:{port}: timed out")),
    };
    let _ = stream.set_nodelay(true);
    let hello = Header::new()
        .with("callerid", node.opts.node_name.as_str())
        .with("topic", topic.as_str())
        .with("md5sum", "*")
        .with("type", "*")
        .with("message_definition", "")
        .with("tcp_nodelay", "1");
    if let Err(e) = write_header(&mut stream, &hello).await {
        return gone(e.to_string());
    }
    let header = match read_header(&mut stream).await {
        Ok(h) => h,
        Err(e) => return gone(e.to_string()),
    };
    if let Some(err) = header.get("error") {
        return PullEnd::Refused(format!("{api} refused {topic}: {err}"));
    }
    if header.text("callerid") == node.opts.node_name {
        return PullEnd::Refused(format!("{topic} at {api} is this node's own publication"));
    }
    let ros_type = header.text("type").to_owned();
    let schema = Schema {
        type_name: ros_type.clone(),
        encoding: "ros1msg".into(),
        text: header.text("message_definition").to_owned(),
    };
    let Ok(name) = TopicName::parse(&topic) else {
        return PullEnd::Refused(format!("{topic} is not a valid topic name"));
    };
    let router_topic =
        match node
            .router
            .advertise(node.client, &name, schema, header.flag("latching"))
        {
            Ok(t) => t,
            Err(RouteError::TypeConflict { existing, .. }) => {
                report_mismatch(&node, &topic, &existing, &ros_type, header.text("callerid"));
                return PullEnd::Refused(format!("type mismatch on {topic}"));
            }
            Err(e) => return PullEnd::Refused(e.to_string()),
        };
    tracing::info!(
        "ros1: receiving {topic} ({ros_type}) from {}{}",
        header.text("callerid"),
        if header.flag("latching") {
            ", latched"
        } else {
            ""
        }
    );
    loop {
        match read_message(&mut stream).await {
            Ok(body) => {
                let n = seq.fetch_add(1, Relaxed) + 1;
                router_topic.publish(
                    node.client,
                    n,
                    fleetlink_relay::unix_nanos(),
                    Payload::new(Encoding::Ros1, body),
                );
                node.stats.messages_up.fetch_add(1, Relaxed);
            }
            Err(FrameError::Closed) => return gone(format!("{api} closed {topic}")),
            Err(e) => return gone(format!("{topic} from {api}: {e}")),
        }
    }
}

/// Logs (once per topic) and counts a type conflict between the robot and the hub.
pub fn report_mismatch(node: &Node, topic: &str, hub_type: &str, local_type: &str, who: &str) {
    node.stats.type_mismatches.fetch_add(1, Relaxed);
    if node.lock().mismatched.insert(topic.to_owned()) {
        let text = format!(
            "type mismatch on {topic}: the agent's topic is {hub_type}, local publisher {who} sends {local_type}; \
             {topic} is not bridged, other topics are unaffected"
        );
        tracing::warn!("ros1: {text}");
        node.stats.problems.note(&text);
    }
}

/// What a service's provider says about it when probed.
#[derive(Debug, Clone)]
pub struct ServiceProbe {
    pub uri: String,
    pub ros_type: String,
    pub md5sum: String,
}

fn rosrpc_addr(uri: &str) -> Option<&str> {
    uri.strip_prefix("rosrpc://")
        .map(|s| s.trim_end_matches('/'))
}

async fn connect_service(
    node: &Node,
    service: &str,
    md5sum: &str,
    probe: bool,
) -> Result<(TcpStream, Header, String), String> {
    let uri = node
        .master
        .lookup_service(service)
        .await
        .map_err(|e| e.to_string())?;
    let addr = rosrpc_addr(&uri).ok_or_else(|| format!("{service}: bad service URI {uri}"))?;
    let mut stream = tokio::time::timeout(CONNECT_TIMEOUT, TcpStream::connect(addr))
        .await
        .map_err(|_| format!("{service}: connect {addr}: timed out"))?
        .map_err(|e| format!("{service}: connect {addr}: {e}"))?;
    let _ = stream.set_nodelay(true);
    let mut hello = Header::new()
        .with("callerid", node.opts.node_name.as_str())
        .with("service", service)
        .with("md5sum", md5sum);
    if probe {
        hello = hello.with("probe", "1");
    }
    write_header(&mut stream, &hello)
        .await
        .map_err(|e| format!("{service}: {e}"))?;
    let header = read_header(&mut stream)
        .await
        .map_err(|e| format!("{service}: {e}"))?;
    if let Some(err) = header.get("error") {
        return Err(format!("{service}: {err}"));
    }
    Ok((stream, header, uri))
}

/// Asks a local service's provider for its type and md5sum.
pub async fn probe_service(node: &Node, service: &str) -> Result<ServiceProbe, String> {
    let (_, header, uri) = connect_service(node, service, "*", true).await?;
    Ok(ServiceProbe {
        uri,
        ros_type: header.text("type").to_owned(),
        md5sum: header.text("md5sum").to_owned(),
    })
}

/// Calls a local service with a ROS 1 request; the ROS 1 response, or the provider's error.
pub async fn call_service(
    node: &Node,
    service: &str,
    md5sum: &str,
    request: &[u8],
) -> Result<Bytes, String> {
    let (mut stream, _, _) = connect_service(node, service, md5sum, false).await?;
    tokio::io::AsyncWriteExt::write_all(&mut stream, &crate::tcpros::frame(request))
        .await
        .map_err(|e| format!("{service}: {e}"))?;
    read_service_response(&mut stream)
        .await
        .map_err(|e| format!("{service}: {e}"))?
        .map_err(|text| format!("{service} failed: {text}"))
}
