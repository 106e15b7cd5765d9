//! The writer's wait between batches, shared by the rosbridge and Foxglove writers, which
//! differ only in how they frame a batch of messages; the replies it waits for are the
//! WebSocket layer's ([`Reply`]).

use std::time::Instant;

use futures_util::{Sink, SinkExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

use crate::outbox::Outbox;
pub use fleetlink_websocket::replies::{Reply, close_with};

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
