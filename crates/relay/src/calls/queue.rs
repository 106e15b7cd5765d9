//! A participant of the call table that queues what the table tells it for its own task
//! ([`ChannelPeer`] for the table, [`PeerReceiver`] for the task), bounded.
//!
//! What can queue is bounded by the table itself, except for two kinds of news that a
//! fast source can repeat faster than a slow reader takes them: an action's feedback
//! (paced by its provider, not by the reader) and services coming and going (paced by
//! whoever advertises). For both only the latest state matters, so they are coalesced in
//! place: a goal's feedback replaces its older feedback still queued, and a service's
//! change replaces its older change still queued (each change says the whole state: added
//! with its provider, or removed). Each keeps the place in line of the first one it
//! replaced, so feedback still comes before its goal's end. Everything else — calls,
//! cancels, call endings — is bounded by the table's pending limits (per caller and per
//! provider) and is never dropped. The coalesced count is kept per queue.

use std::collections::{HashMap, VecDeque};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};

use fleetlink_proto::Payload;
use tokio::sync::Notify;

use super::{CallEvent, CallId, CallPeer, CallRequest, PeerMsg, ServiceChange};
use crate::names::TopicName;

/// A place in line: a message, or the newest feedback of a goal or change of a service,
/// kept beside the line.
enum Slot {
    Msg(PeerMsg),
    Feedback(CallId),
    Changed(TopicName),
}

#[derive(Default)]
struct Line {
    order: VecDeque<Slot>,
    feedback: HashMap<CallId, Payload>,
    changes: HashMap<TopicName, ServiceChange>,
    /// The table let go of the peer: nothing more will come.
    closed: bool,
}

struct Shared {
    // std Mutex: a push or a pop, never held across an await.
    line: Mutex<Line>,
    ready: Notify,
    /// Feedback and service changes replaced by newer ones before they were read.
    coalesced: AtomicU64,
}

impl Shared {
    fn line(&self) -> std::sync::MutexGuard<'_, Line> {
        self.line.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn push(&self, msg: PeerMsg) {
        let mut line = self.line();
        match msg {
            PeerMsg::Event(CallEvent::Feedback { id, payload }) => {
                if line.feedback.insert(id, payload).is_some() {
                    self.coalesced.fetch_add(1, Relaxed);
                } else {
                    line.order.push_back(Slot::Feedback(id));
                }
            }
            PeerMsg::Changed(change) => {
                let name = match &change {
                    ServiceChange::Added(i) | ServiceChange::Removed(i) => i.name.clone(),
                };
                if line.changes.insert(name.clone(), change).is_some() {
                    self.coalesced.fetch_add(1, Relaxed);
                } else {
                    line.order.push_back(Slot::Changed(name));
                }
            }
            other => line.order.push_back(Slot::Msg(other)),
        }
        drop(line);
        self.ready.notify_one();
    }
}

/// The table's side: what it delivers is queued for the task holding the
/// [`PeerReceiver`]. When the table lets go of it (the participant is detached), the
/// receiver ends once it has taken what was queued.
pub struct ChannelPeer(Arc<Shared>);

/// The task's side of a [`ChannelPeer`].
pub struct PeerReceiver(Arc<Shared>);

impl ChannelPeer {
    pub fn new() -> (Arc<ChannelPeer>, PeerReceiver) {
        let shared = Arc::new(Shared {
            line: Mutex::new(Line::default()),
            ready: Notify::new(),
            coalesced: AtomicU64::new(0),
        });
        (Arc::new(ChannelPeer(shared.clone())), PeerReceiver(shared))
    }
}

impl Drop for ChannelPeer {
    fn drop(&mut self) {
        self.0.line().closed = true;
        self.0.ready.notify_one();
    }
}

impl CallPeer for ChannelPeer {
    fn deliver_call(&self, call: CallRequest) {
        self.0.push(PeerMsg::Call(call));
    }
    fn deliver_cancel(&self, id: CallId) {
        self.0.push(PeerMsg::Cancel(id));
    }
    fn deliver_event(&self, event: CallEvent) {
        self.0.push(PeerMsg::Event(event));
    }
    fn service_changed(&self, change: ServiceChange) {
        self.0.push(PeerMsg::Changed(change));
    }
}

impl PeerReceiver {
    /// The next message, if one is queued; `Err(Closed)` once the table let go and the
    /// queue is empty.
    pub fn try_recv(&self) -> Result<Option<PeerMsg>, Closed> {
        let mut line = self.0.line();
        loop {
            let Some(slot) = line.order.pop_front() else {
                return if line.closed { Err(Closed) } else { Ok(None) };
            };
            let msg = match slot {
                Slot::Msg(m) => Some(m),
                Slot::Feedback(id) => line
                    .feedback
                    .remove(&id)
                    .map(|payload| PeerMsg::Event(CallEvent::Feedback { id, payload })),
                Slot::Changed(name) => line.changes.remove(&name).map(PeerMsg::Changed),
            };
            if msg.is_some() {
                return Ok(msg);
            }
        }
    }

    /// Waits for the next message; `None` once the table let go and the queue is empty.
    pub async fn recv(&self) -> Option<PeerMsg> {
        loop {
            // Registered before looking, so a push between the look and the wait wakes it.
            let ready = self.0.ready.notified();
            match self.try_recv() {
                Ok(Some(m)) => return Some(m),
                Err(Closed) => return None,
                Ok(None) => ready.await,
            }
        }
    }

    /// Messages waiting (a coalesced feedback or change counts once).
    pub fn len(&self) -> usize {
        self.0.line().order.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Feedback and service changes replaced by newer ones before they were read.
    pub fn coalesced(&self) -> u64 {
        self.0.coalesced.load(Relaxed)
    }
}

/// The table let go of the participant and everything queued was taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Closed;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calls::ServiceInfo;
    use crate::names::ClientId;
    use bytes::Bytes;
    use fleetlink_proto::{Encoding, Schema};

    fn feedback(id: CallId, n: u8) -> CallEvent {
        CallEvent::Feedback {
            id,
            payload: Payload::new(Encoding::Json, Bytes::from(vec![n])),
        }
    }

    fn info(name: &str, provider: u64) -> Arc<ServiceInfo> {
        Arc::new(ServiceInfo {
            name: TopicName::parse(name).unwrap(),
            schema: Schema::default(),
            action: false,
            provider: ClientId(provider),
        })
    }

    #[test]
    fn a_goals_feedback_is_coalesced_and_stays_before_its_end() {
        let (peer, rx) = ChannelPeer::new();
        for n in 0..1000u16 {
            peer.deliver_event(feedback(7, (n % 250) as u8));
        }
        peer.deliver_event(feedback(8, 1));
        peer.deliver_event(CallEvent::Done {
            id: 7,
            status: super::super::CallStatus::Ok,
            payload: None,
            text: String::new(),
        });
        assert_eq!(rx.len(), 3, "one feedback per goal, then the end");
        assert_eq!(rx.coalesced(), 999);
        match rx.try_recv() {
            Ok(Some(PeerMsg::Event(CallEvent::Feedback { id: 7, payload }))) => {
                assert_eq!(&payload.bytes[..], &[(999 % 250) as u8], "the newest");
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            rx.try_recv(),
            Ok(Some(PeerMsg::Event(CallEvent::Feedback { id: 8, .. })))
        ));
        assert!(matches!(
            rx.try_recv(),
            Ok(Some(PeerMsg::Event(CallEvent::Done { id: 7, .. })))
        ));
        assert!(matches!(rx.try_recv(), Ok(None)));
    }

    #[test]
    fn a_services_changes_keep_only_the_latest_state() {
        let (peer, rx) = ChannelPeer::new();
        for _ in 0..100 {
            peer.service_changed(ServiceChange::Added(info("/a", 1)));
            peer.service_changed(ServiceChange::Removed(info("/a", 1)));
        }
        peer.service_changed(ServiceChange::Added(info("/a", 2)));
        peer.service_changed(ServiceChange::Added(info("/b", 3)));
        assert_eq!(rx.len(), 2);
        match rx.try_recv() {
            Ok(Some(PeerMsg::Changed(ServiceChange::Added(i)))) => {
                assert_eq!((i.name.as_str(), i.provider), ("/a", ClientId(2)));
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            rx.try_recv(),
            Ok(Some(PeerMsg::Changed(ServiceChange::Added(_))))
        ));
        assert_eq!(rx.coalesced(), 200);
    }

    #[test]
    fn calls_and_cancels_are_never_coalesced() {
        let (peer, rx) = ChannelPeer::new();
        for id in 0..10 {
            peer.deliver_cancel(id);
            peer.deliver_cancel(id);
        }
        assert_eq!(rx.len(), 20);
        assert_eq!(rx.coalesced(), 0);
        let mut n = 0;
        while let Ok(Some(PeerMsg::Cancel(_))) = rx.try_recv() {
            n += 1;
        }
        assert_eq!(n, 20);
    }

    #[tokio::test]
    async fn the_receiver_ends_after_the_table_lets_go_and_the_queue_is_drained() {
        let (peer, rx) = ChannelPeer::new();
        peer.deliver_cancel(1);
        drop(peer);
        assert!(matches!(rx.recv().await, Some(PeerMsg::Cancel(1))));
        assert!(rx.recv().await.is_none());
    }

    #[tokio::test]
    async fn a_waiting_receiver_is_woken() {
        let (peer, rx) = ChannelPeer::new();
        let waiter = tokio::spawn(async move { rx.recv().await });
        tokio::task::yield_now().await;
        peer.deliver_cancel(5);
        let got = tokio::time::timeout(std::time::Duration::from_secs(5), waiter)
            .await
            .expect("woken")
            .unwrap();
        assert!(matches!(got, Some(PeerMsg::Cancel(5))));
    }
}
