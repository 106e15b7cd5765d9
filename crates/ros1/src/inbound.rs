//! The node's TCPROS listener: local subscribers of the topics it publishes (hub →
//! robot) and local callers of the fleet services it serves.
//!
//! A connection's first header says which: `topic=` or `service=`. Type checks happen
//! here, against the md5sum the caller sent; a mismatch is refused with an `error=`
//! header (what rospy and roscpp print) and logged with both types.

use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::TopicName;
use fleetlink_relay::calls::CallStatus;
use fleetlink_relay::calls::{CallEvent, CallOptions};
use tokio::io::AsyncReadExt;
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::mpsc;
use tokio_util::sync::CancellationToken;

use crate::node::{Node, SUBSCRIBER_QUEUE, SubscriberTx};
use crate::tcpros::{Header, read_header, read_message, write_header, write_service_response};

/// How long a peer may take to send its connection header.
const HEADER_TIMEOUT: Duration = Duration::from_secs(5);

pub async fn serve(node: Arc<Node>, listener: TcpListener, shutdown: CancellationToken) {
    loop {
        let (stream, _) = tokio::select! {
            r = listener.accept() => match r {
                Ok(s) => s,
                Err(e) => {
                    tracing::warn!("ros1: TCPROS accept: {e}");
                    tokio::time::sleep(Duration::from_millis(100)).await;
                    continue;
                }
            },
            _ = shutdown.cancelled() => return,
        };
        let node = node.clone();
        let shutdown = shutdown.clone();
        tokio::spawn(async move {
            tokio::select! {
                _ = connection(&node, stream) => {}
                _ = shutdown.cancelled() => {}
            }
        });
    }
}

async fn refuse(stream: &mut TcpStream, text: String) {
    let _ = write_header(stream, &Header::new().with("error", text)).await;
}

async fn connection(node: &Node, mut stream: TcpStream) {
    let _ = stream.set_nodelay(true);
    let header = match tokio::time::timeout(HEADER_TIMEOUT, read_header(&mut stream)).await {
        Ok(Ok(h)) => h,
        Ok(Err(e)) => {
            tracing::debug!("ros1: inbound connection header: {e}");
            return;
        }
        Err(_) => return,
    };
    if let Some(topic) = header.get("topic") {
        let topic = topic.to_owned();
        subscriber(node, stream, &topic, &header).await;
    } else if let Some(service) = header.get("service") {
        let service = service.to_owned();
        service_client(node, stream, &service, &header).await;
    } else {
        refuse(&mut stream, "header has neither topic nor service".into()).await;
    }
}

/// A local subscriber of a topic this node publishes.
async fn subscriber(node: &Node, mut stream: TcpStream, topic: &str, header: &Header) {
    let Some(publication) = node.lock().pubs.get(topic).cloned() else {
        refuse(
            &mut stream,
            format!("{} does not publish {topic}", node.opts.node_name),
        )
        .await;
        return;
    };
    let id = &publication.identity;
    let md5 = header.text("md5sum");
    if md5 != "*" && md5 != id.md5sum {
        let text = format!(
            "type mismatch on {topic}: the hub's topic is {} (md5 {}), subscriber {} wants {} (md5 {md5})",
            id.type_name,
            id.md5sum,
            header.text("callerid"),
            header.text("type"),
        );
        tracing::warn!("ros1: {text}");
        node.stats.type_mismatches.fetch_add(1, Relaxed);
        node.stats.problems.note(&text);
        refuse(&mut stream, text).await;
        return;
    }
    let reply = Header::new()
        .with("callerid", node.opts.node_name.as_str())
        .with("topic", topic)
        .with("md5sum", id.md5sum.as_str())
        .with("type", id.type_name.as_str())
        .with("message_definition", id.definition.as_str())
        .with("latching", if publication.latched { "1" } else { "0" });
    if write_header(&mut stream, &reply).await.is_err() {
        return;
    }
    let (tx, mut rx) = mpsc::channel::<Bytes>(SUBSCRIBER_QUEUE);
    let conn = node.next_conn_id();
    let queued = Arc::new(std::sync::atomic::AtomicUsize::new(0));
    {
        let mut out = publication.out.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(last) = &out.last
            && tx.try_send(last.clone()).is_ok()
        {
            queued.fetch_add(last.len(), Relaxed);
        }
        out.conns.push(SubscriberTx {
            conn,
            tx,
            queued: queued.clone(),
        });
        publication.release_held(&mut out);
    }
    tracing::info!(
        "ros1: {} subscribed to {topic} ({})",
        header.text("callerid"),
        id.type_name
    );
    let (mut rd, mut wr) = stream.into_split();
    let mut probe = [0u8; 64];
    loop {
        tokio::select! {
            f = rx.recv() => match f {
                Some(frame) => {
                    let written = tokio::io::AsyncWriteExt::write_all(&mut wr, &frame).await;
                    queued.fetch_sub(frame.len(), Relaxed);
                    if written.is_err() {
                        break;
                    }
                }
                None => break,
            },
            // Subscribers send nothing after their header: a read ends when they leave.
            r = rd.read(&mut probe) => if matches!(r, Ok(0) | Err(_)) { break },
        }
    }
    publication
        .out
        .lock()
        .unwrap_or_else(|p| p.into_inner())
        .conns
        .retain(|s| s.conn != conn);
}

/// A local caller of a fleet service this node serves.
async fn service_client(node: &Node, mut stream: TcpStream, service: &str, header: &Header) {
    let found = node
        .lock()
        .offered
        .get(service)
        .map(|o| (o.srv_type.clone(), o.identity.clone()));
    let Some((srv_type, id)) = found else {
        refuse(
            &mut stream,
            format!("{} does not serve {service}", node.opts.node_name),
        )
        .await;
        return;
    };
    let md5 = header.text("md5sum");
    if md5 != "*" && md5 != id.md5sum {
        let text = format!(
            "type mismatch on service {service}: the fleet's is {} (md5 {}), caller wants md5 {md5}",
            id.type_name, id.md5sum
        );
        tracing::warn!("ros1: {text}");
        node.stats.type_mismatches.fetch_add(1, Relaxed);
        node.stats.problems.note(&text);
        refuse(&mut stream, text).await;
        return;
    }
    let reply = Header::new()
        .with("callerid", node.opts.node_name.as_str())
        .with("md5sum", id.md5sum.as_str())
        .with("type", id.type_name.as_str())
        .with("request_type", format!("{}Request", id.type_name))
        .with("response_type", format!("{}Response", id.type_name));
    if write_header(&mut stream, &reply).await.is_err() || header.flag("probe") {
        return;
    }
    let Ok(name) = TopicName::parse(service) else {
        return;
    };
    let response_schema = Schema {
        type_name: format!("{srv_type}_Response"),
        encoding: "ros1msg".into(),
        text: String::new(),
    };
    // One request per message; a `persistent=1` caller sends more on the same socket.
    loop {
        let request = match read_message(&mut stream).await {
            Ok(b) => b,
            Err(_) => return,
        };
        let answer = call_fleet(node, &name, &response_schema, request).await;
        let sent = match &answer {
            Ok(b) => write_service_response(&mut stream, Ok(&b[..])).await,
            Err(text) => write_service_response(&mut stream, Err(text.as_str())).await,
        };
        if sent.is_err() || !header.flag("persistent") {
            return;
        }
    }
}

/// Calls a fleet service with a ROS 1 request; its response as ROS 1 bytes.
async fn call_fleet(
    node: &Node,
    name: &TopicName,
    response_schema: &Schema,
    request: bytes::Bytes,
) -> Result<bytes::Bytes, String> {
    let opts = CallOptions {
        timeout: Some(node.opts.call_timeout),
        ..CallOptions::default()
    };
    let calls = &node.router.calls;
    let id = calls
        .call(
            node.client,
            name,
            Payload::new(Encoding::Ros1, request),
            opts,
        )
        .map_err(|e| e.to_string())?;
    let rx = node.wait_for(id);
    // The table's own deadline answers first; this only guards a lost answer.
    let ev = match tokio::time::timeout(node.opts.call_timeout + Duration::from_secs(1), rx).await {
        Ok(Ok(ev)) => ev,
        _ => {
            node.forget(id);
            return Err(format!("{name}: no answer from the fleet"));
        }
    };
    match ev {
        CallEvent::Done {
            status: CallStatus::Ok,
            payload: Some(p),
            ..
        } => node
            .router
            .transcoder()
            .convert(response_schema, &p, Encoding::Ros1)
            .map_err(|e| format!("{name}: {e}")),
        CallEvent::Done { status, text, .. } => Err(format!("{name}: {status:?}: {text}")),
        CallEvent::Feedback { .. } => Err(format!("{name}: unexpected feedback")),
    }
}
