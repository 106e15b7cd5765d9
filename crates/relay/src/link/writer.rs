//! The writer task of a `fleetlink.v1` link: what the link's [`Outbound`] produces, onto
//! the socket. It decides nothing about what goes out; it writes, flushes and waits for
//! the session's next control frame, the outbox's next data or the outbound's next
//! deadline.

use std::sync::Arc;
use std::time::Duration;

use fleetlink_proto::Encoding;
use futures_util::{Sink, SinkExt};
use tokio::sync::mpsc::error::TryRecvError;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

use super::outbound::{Outbound, Transmit, ViaOut};
use super::{Control, ControlReceiver, LinkNamer};
use crate::message::TopicMeta;
use crate::outbox::Outbox;

/// How long a writer whose outbox was closed waits for its owner's close frame.
const CLOSE_REASON_WAIT: Duration = Duration::from_millis(500);

/// Writes `outbox` and `control` (the session's frames) onto the link until either side
/// closes: see [`Outbound`] for what goes out when. `announce_first` topics are advertised
/// before anything else; `gate`, if any, must allow each message's topic for it to be
/// sent; `via` marks messages between hubs.
pub async fn write_link<K>(
    mut sink: K,
    outbox: Arc<Outbox>,
    mut control: ControlReceiver,
    namer: LinkNamer,
    announce_first: Vec<(Arc<TopicMeta>, Encoding)>,
    gate: Option<Box<dyn crate::gate::Gate>>,
    via: Option<ViaOut>,
) where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    let mut out = Outbound::new(outbox.clone(), namer, announce_first, gate, via);
    // The wait for the outbox, made once and kept across rounds (made again after it
    // fires): a fresh one each round joined and left the outbox's waiters, under their
    // lock, at every heartbeat of every idle link.
    let mut ready = std::pin::pin!(outbox.ready());
    loop {
        loop {
            match control.try_recv() {
                Ok(c) => out.on_control(Some(*c)),
                Err(TryRecvError::Disconnected) => out.on_control(None),
                Err(TryRecvError::Empty) => break,
            }
            if out.is_closing() {
                break;
            }
        }
        let round = out.round();
        if !write_out(&mut sink, &mut out).await {
            return;
        }
        if round.again {
            continue;
        }
        if outbox.is_closed() {
            // The router let the client go; its owner ends the link with its reason
            // (`Control::Close`) right after. Wait a moment for it, so the peer learns the
            // close code (1007, 1001, ...) instead of a bare close.
            let until = tokio::time::Instant::now() + CLOSE_REASON_WAIT;
            while !out.is_closing() {
                match tokio::time::timeout_at(until, control.recv()).await {
                    Ok(Some(c)) if matches!(*c, Control::Close(_) | Control::Frame(_)) => {
                        out.on_control(Some(*c))
                    }
                    Ok(Some(_)) => {}
                    Ok(None) | Err(_) => out.on_control(None),
                }
            }
            write_out(&mut sink, &mut out).await;
            return;
        }
        tokio::select! {
            c = control.recv() => out.on_control(c.map(|c| *c)),
            _ = ready.as_mut() => ready.set(outbox.ready()),
            _ = super::drive::timer(round.wake) => {}
        }
    }
}

/// Writes everything `out` has ready and flushes; false once the link is done (closed
/// here, or the socket failed).
async fn write_out<K>(sink: &mut K, out: &mut Outbound) -> bool
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    while let Some(t) = out.poll_transmit() {
        let m = match t {
            Transmit::Binary(b) => WsMessage::Binary(b),
            Transmit::Pong(p) => WsMessage::Pong(p),
            Transmit::Close(frame) => {
                if frame.is_some() {
                    let _ = sink.send(WsMessage::Close(frame)).await;
                }
                let _ = sink.close().await;
                return false;
            }
        };
        if sink.feed(m).await.is_err() {
            return false;
        }
    }
    sink.flush().await.is_ok()
}
