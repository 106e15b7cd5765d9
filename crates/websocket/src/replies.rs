//! The direct replies a session's reader hands its writer (`status`, answers, pings, the
//! close frame), and how the writer sends its last one.

use futures_util::{Sink, SinkExt};
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

/// What the reader asks the writer to send besides the outbox.
#[derive(Debug)]
pub enum Reply {
    Frame(WsMessage),
    /// Sent last: the writer then closes the connection.
    Close(Option<CloseFrame>),
}

/// Sends `c` as the last frame and closes the connection.
pub async fn close_with<K>(sink: &mut K, c: Option<CloseFrame>)
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    let _ = sink.send(WsMessage::Close(c)).await;
    let _ = sink.close().await;
}
