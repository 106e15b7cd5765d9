//! No-drop topics on a link, the sender's half: every message is numbered, kept until the
//! receiver confirms it (`DELIVERED`), and sent again on the next connection if the one
//! that carried it died first.
//!
//! Design choice: the sequence number of a no-drop message is the *stream's*, assigned
//! here per topic name — not the publisher's, which restarts with every local client and
//! interleaves when two processes publish one topic. The receiver needs a number that
//! only ever grows for a `(robot, topic)` to deliver each message exactly once across
//! reconnects and restarts of either side; `outbox_epoch` (sent in `HELLO`) names the
//! numbering, so a robot whose outbox starts afresh is not mistaken for a replay.
//!
//! A [`Journal`] (the agent's durable outbox) sees every message before it is queued and
//! every confirmation, so a restarted agent resumes where it stopped.

use std::collections::{HashMap, VecDeque};
use std::sync::Arc;

use fleetlink_proto::{Encoding, Payload, Schema};

use crate::message::{Message, TopicMeta};
use crate::names::TopicName;

/// Why a journal could not take a message.
#[derive(Debug, thiserror::Error)]
pub enum JournalError {
    #[error(
        "the durable outbox is full ({used} of {limit} bytes): the link has been down or \
         too slow for longer than it can hold; raise outbox.max_mb"
    )]
    Full { used: u64, limit: u64 },
    #[error("writing the durable outbox {path}: {cause}")]
    Io { path: String, cause: std::io::Error },
}

/// Durable storage of the no-drop messages not yet confirmed by the receiver.
pub trait Journal: Send {
    /// Records `msg` (numbered `seq`) before it is queued. An error refuses the message.
    fn append(
        &mut self,
        topic: &TopicMeta,
        seq: u64,
        stamp_ns: u64,
        payload: &Payload,
    ) -> Result<(), JournalError>;
    /// The receiver has every message of `topic` up to `seq`.
    fn confirm(&mut self, topic: &TopicName, seq: u64);
    /// Called about once a second: a chance to sync writes a policy left pending.
    fn tick(&mut self) {}
    /// The sender is stopping: write and sync what is pending, then let go of the storage.
    fn close(&mut self) {}
}

/// A message read back from a journal after a restart.
#[derive(Debug, Clone)]
pub struct Recovered {
    pub topic: TopicName,
    pub schema: Schema,
    pub seq: u64,
    pub stamp_ns: u64,
    pub encoding: Encoding,
    pub payload: bytes::Bytes,
}

/// The sender's state of its no-drop topics (see the module docs).
pub struct ReliableOut {
    epoch: u64,
    next_seq: HashMap<TopicName, u64>,
    /// Taken for sending and not yet confirmed, in send order: (topic alias, message).
    unconfirmed: VecDeque<(u32, Arc<Message>)>,
    journal: Option<Box<dyn Journal>>,
}

impl ReliableOut {
    /// `epoch` must be non-zero; `next_seq` continues the numbering of a recovered journal.
    pub fn new(
        epoch: u64,
        next_seq: HashMap<TopicName, u64>,
        journal: Option<Box<dyn Journal>>,
    ) -> ReliableOut {
        ReliableOut {
            epoch: epoch.max(1),
            next_seq,
            unconfirmed: VecDeque::new(),
            journal,
        }
    }

    /// An in-memory sender with a fresh random epoch (no durable outbox).
    pub fn in_memory() -> ReliableOut {
        ReliableOut::new(fastrand_epoch(), HashMap::new(), None)
    }

    pub fn epoch(&self) -> u64 {
        self.epoch
    }

    /// Whether messages are also kept on disk (then the journal, not the in-memory queue
    /// length, bounds how many may wait).
    pub fn is_durable(&self) -> bool {
        self.journal.is_some()
    }

    /// Numbers `msg` on its topic's stream and records it in the journal.
    pub fn admit(&mut self, msg: &Message) -> Result<Arc<Message>, JournalError> {
        let next = self.next_seq.entry(msg.topic.name.clone()).or_insert(1);
        let seq = *next;
        if let Some(j) = &mut self.journal {
            j.append(&msg.topic, seq, msg.stamp_ns, &msg.payload)?;
        }
        *next += 1;
        Ok(Arc::new(msg.resequenced(seq)))
    }

    /// A message already numbered (recovered from the journal): later ones continue after it.
    pub fn restored(&mut self, topic: &TopicName, seq: u64) {
        let next = self.next_seq.entry(topic.clone()).or_insert(1);
        *next = (*next).max(seq + 1);
    }

    /// The writer took `msg` (of link alias `alias`) for sending.
    pub fn sent(&mut self, alias: u32, msg: Arc<Message>) {
        self.unconfirmed.push_back((alias, msg));
    }

    /// The receiver confirmed `alias` up to `seq`.
    pub fn confirm(&mut self, alias: u32, seq: u64) {
        let mut name = None;
        self.unconfirmed.retain(|(a, m)| {
            let done = *a == alias && m.seq <= seq;
            if done && name.is_none() {
                name = Some(m.topic.name.clone());
            }
            !done
        });
        if let (Some(j), Some(name)) = (&mut self.journal, name) {
            j.confirm(&name, seq);
        }
    }

    /// Everything sent but not confirmed, oldest first: the connection that carried it is
    /// gone, so it must be sent again.
    pub fn take_unconfirmed(&mut self) -> VecDeque<(u32, Arc<Message>)> {
        std::mem::take(&mut self.unconfirmed)
    }

    /// The sender is stopping (see [`Journal::close`]).
    pub fn close_journal(&mut self) {
        if let Some(j) = &mut self.journal {
            j.close();
        }
    }

    /// Periodic journal housekeeping (see [`Journal::tick`]).
    pub fn tick(&mut self) {
        if let Some(j) = &mut self.journal {
            j.tick();
        }
    }

    pub fn unconfirmed_len(&self) -> usize {
        self.unconfirmed.len()
    }
}

/// A non-zero epoch that two restarts of one robot will not share.
fn fastrand_epoch() -> u64 {
    let t = crate::unix_nanos();
    (t ^ u64::from(std::process::id()).rotate_left(32)).max(1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::names::{ClientId, TopicId};

    fn meta(name: &str, id: u32) -> Arc<TopicMeta> {
        Arc::new(TopicMeta::new(
            TopicId(id),
            TopicName::parse(name).unwrap(),
            Schema::default(),
            false,
        ))
    }

    fn msg(m: &Arc<TopicMeta>, publisher_seq: u64) -> Message {
        Message::new(
            m.clone(),
            publisher_seq,
            7,
            ClientId(1),
            Payload::new(Encoding::Json, bytes::Bytes::from_static(b"{}")),
        )
    }

    #[test]
    fn stream_numbers_ignore_the_publishers_own() {
        let mut r = ReliableOut::in_memory();
        let a = meta("/a", 1);
        let seqs: Vec<u64> = [40, 3, 3, 900]
            .iter()
            .map(|&p| r.admit(&msg(&a, p)).unwrap().seq)
            .collect();
        assert_eq!(seqs, [1, 2, 3, 4]);
        let b = meta("/b", 2);
        assert_eq!(r.admit(&msg(&b, 5)).unwrap().seq, 1);
    }

    #[test]
    fn confirmed_messages_are_forgotten_and_the_rest_resent_in_order() {
        let mut r = ReliableOut::in_memory();
        let (a, b) = (meta("/a", 1), meta("/b", 2));
        for i in 0..3 {
            let m = r.admit(&msg(&a, i)).unwrap();
            r.sent(1, m);
            let m = r.admit(&msg(&b, i)).unwrap();
            r.sent(2, m);
        }
        r.confirm(1, 2);
        let left: Vec<(u32, u64)> = r
            .take_unconfirmed()
            .iter()
            .map(|(a, m)| (*a, m.seq))
            .collect();
        assert_eq!(left, [(2, 1), (2, 2), (1, 3), (2, 3)]);
        assert_eq!(r.unconfirmed_len(), 0);
    }

    #[test]
    fn restored_numbering_continues_after_the_journal() {
        let mut r = ReliableOut::new(9, HashMap::new(), None);
        let a = meta("/a", 1);
        r.restored(&a.name, 41);
        assert_eq!(r.admit(&msg(&a, 0)).unwrap().seq, 42);
        assert_eq!(r.epoch(), 9);
    }
}
