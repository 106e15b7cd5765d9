//! The pieces every driver of a [`LinkSession`] uses — the hub's per-robot task and the
//! agent's uplink — so that a driver is only its own select loop: what the socket read
//! goes in ([`feed`]), the session's deadline wakes it ([`timer`]), what the session has
//! to send goes to the link's writer task while that has room ([`pump`]), and the writer
//! is stopped without waiting on a dead socket ([`stop_writer`]).

use std::time::{Duration, Instant};

use bytes::Bytes;
use tokio_tungstenite::tungstenite::Error as WsError;
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;

use super::session::{CloseReason, LinkSession};
use super::{Control, ControlSender};
use crate::websocket::ClientMessage;

/// How long a closing link's writer may take to flush and close the WebSocket before it
/// is stopped. A link declared dead is not waited for at all.
pub const CLOSE_GRACE: Duration = Duration::from_secs(1);

/// Feeds the session what the socket read (`None`: the stream ended). Returns the payload
/// of a WebSocket ping, which the driver answers with [`Control::Pong`].
pub fn feed(
    session: &mut LinkSession,
    read: Option<Result<ClientMessage, WsError>>,
    now: Instant,
) -> Option<Bytes> {
    match read {
        Some(Ok(ClientMessage::Binary(b))) => session.handle_binary(&b, now),
        // A text message must be UTF-8 whatever the subprotocol (RFC 6455, 8.1).
        Some(Ok(ClientMessage::Text(t))) => match std::str::from_utf8(&t) {
            Ok(_) => session.handle_text(now),
            Err(e) => session.handle_invalid(1007, format!("a text message is not UTF-8: {e}")),
        },
        Some(Ok(ClientMessage::Ping(p))) => {
            session.handle_activity(now);
            return Some(p);
        }
        Some(Ok(ClientMessage::Pong(_))) => session.handle_activity(now),
        Some(Ok(ClientMessage::Close(c))) => {
            session.handle_close(c.map(|c| c.reason.to_string()).unwrap_or_default())
        }
        Some(Err(e)) => match &e {
            WsError::Protocol(p) => session.handle_invalid(1002, p.to_string()),
            WsError::Capacity(c) => session.handle_invalid(1009, c.to_string()),
            WsError::Utf8(u) => session.handle_invalid(1007, u.clone()),
            _ => session.handle_read_error(e.to_string()),
        },
        None => session.handle_close(String::new()),
    }
    None
}

/// The close frame a session that ended for `reason` sends, if the socket is worth
/// writing to (not after the link was declared dead or failed).
pub fn close_frame(reason: &CloseReason) -> Option<CloseFrame> {
    let frame = |code: CloseCode, text: &str| CloseFrame {
        code,
        reason: text.chars().take(120).collect::<String>().into(),
    };
    match reason {
        CloseReason::Silent { .. } | CloseReason::ReadError(_) => None,
        CloseReason::Local(text) => Some(frame(CloseCode::Away, text)),
        CloseReason::Invalid { code, text } => Some(frame(CloseCode::from(*code), text)),
        CloseReason::Refused(text) => Some(frame(CloseCode::Policy, text)),
        _ => Some(frame(CloseCode::Normal, "")),
    }
}

/// Sleeps until the session's next deadline (forever once it has none).
pub async fn timer(at: Option<Instant>) {
    match at {
        Some(at) => tokio::time::sleep_until(at.into()).await,
        None => std::future::pending().await,
    }
}

pub use fleetlink_websocket::timer::Timer;

/// Moves what the session has to send to the writer, as long as the writer's queue has
/// room; the rest stays in the session (the driver also waits for room in its select).
pub fn pump(session: &mut LinkSession, writer: &ControlSender) {
    while session.has_transmit() {
        let Ok(permit) = writer.try_reserve() else {
            return;
        };
        if let Some(c) = session.poll_transmit() {
            permit.send(Box::new(c));
        }
    }
}

/// Ends the link's writer after its session ended for `reason`: with a close frame after
/// what is queued when the link is alive ([`close_frame`]: 1001 with the reason when this
/// side ends it, the RFC 6455 code for a protocol error), at once when the link was
/// declared dead or failed (its socket may never drain).
pub async fn stop_writer(
    mut writer: tokio::task::JoinHandle<()>,
    queue: ControlSender,
    reason: &CloseReason,
) {
    let sent = close_frame(reason)
        .is_some_and(|f| queue.try_send(Box::new(Control::Close(Some(f)))).is_ok());
    drop(queue);
    if sent && tokio::time::timeout(CLOSE_GRACE, &mut writer).await.is_ok() {
        return;
    }
    writer.abort();
    let _ = writer.await;
}
