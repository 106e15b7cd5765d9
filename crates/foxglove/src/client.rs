//! The client as a Foxglove session's reader acts toward it: who it is to the router,
//! what its gate lets it do, and the queue its replies go to the writer by.
//!
//! The reader's own operations ([`crate::session`]) and its service calls and parameter
//! reads (`crate::services`) both work through this, so neither needs the other's state.

use std::sync::Arc;

use bytes::Bytes;
use fleetlink_relay::gate::{Gate, Op as GateOp};
use fleetlink_relay::{ClientId, Router};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use crate::protocol::{self, Level};
use crate::writer::Reply;

pub(crate) struct Client {
    pub(crate) router: Arc<Router>,
    /// The client's id in the router and the call table.
    pub(crate) id: ClientId,
    /// What this client may do; `None`: nothing (no credential, no anonymous access).
    pub(crate) gate: Option<Box<dyn Gate>>,
    /// Replies for the writer to send (bounded: a client that does not read them slows
    /// its own reader down).
    pub(crate) replies: mpsc::Sender<Reply>,
}

impl Client {
    pub(crate) async fn send_text(&self, text: String) {
        let _ = self.replies.send(Reply::Frame(WsMessage::text(text))).await;
    }

    pub(crate) async fn send_binary(&self, b: Bytes) {
        let _ = self.replies.send(Reply::Frame(WsMessage::Binary(b))).await;
    }

    pub(crate) async fn error(&self, message: &str) {
        self.send_text(protocol::status(Level::Error, message))
            .await;
    }

    /// May the client do `op` on `name`? The refusal text names both.
    pub(crate) fn check(&mut self, verb: &str, name: &str, op: GateOp) -> Result<(), String> {
        let Some(gate) = self.gate.as_mut() else {
            return Err(format!("{verb} {name}: not authenticated"));
        };
        if gate.allows(name, op) {
            Ok(())
        } else {
            Err(format!(
                "{verb} {name}: not allowed for {}",
                gate.principal()
            ))
        }
    }
}
