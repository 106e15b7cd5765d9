//! The direct replies a session's reader hands its writer (`status`, answers, the close
//! frame), and the writer's wait between batches — shared by the rosbridge and Foxglove
//! writers, which differ only in how they frame a batch of messages.

use std::time::Instant;

use futures_util::{Sink, SinkExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

use crate::outbox::Outbox;

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

/// A writer with nothing to send waits here for a reply, the outbox or `wake_at` (when
/// a held-back message is due). False: the session is over and the connection closed,
/// the writer returns.
///
/// When the outbox is closed the session has ended; its last word — a close frame with
/// its code, queued before the router let go of the outbox — may still wait in
/// `replies` and is sent as it is, not replaced by a close without a code.
pub async fn wait_for_work<K>(
    sink: &mut K,
    replies: &mut mpsc::Receiver<Reply>,
    outbox: &Outbox,
    wake_at: Option<Instant>,
) -> bool
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    if outbox.is_closed() {
        while let Ok(r) = replies.try_recv() {
            match r {
                Reply::Frame(m) => {
                    if sink.feed(m).await.is_err() {
                        return false;
                    }
                }
                Reply::Close(c) => {
                    close_with(sink, c).await;
                    return false;
                }
            }
        }
        let _ = sink.close().await;
        return false;
    }
    let wake = wake_at.map(tokio::time::Instant::from_std);
    tokio::select! {
        r = replies.recv() => match r {
            Some(Reply::Frame(m)) => sink.send(m).await.is_ok(),
            Some(Reply::Close(c)) => {
                close_with(sink, c).await;
                false
            }
            None => {
                // The reader is gone: flush what is queued and stop.
                let _ = sink.close().await;
                false
            }
        },
        _ = outbox.ready() => true,
        _ = async {
            match wake {
                Some(w) => tokio::time::sleep_until(w).await,
                None => std::future::pending().await,
            }
        } => true,
    }
}
