//! Each message of a robot's no-drop topics delivered once, across reconnects and hub
//! restarts: the receiving half of [`fleetlink_relay::reliable`].
//!
//! An agent numbers a no-drop topic's messages itself (a stream per topic, named by the
//! `outbox_epoch` of its `HELLO`) and resends whatever the hub has not confirmed with
//! `DELIVERED`. The hub remembers, per robot and topic, the highest number it delivered:
//! anything at or below it is a resend of a message already delivered and is only
//! confirmed again. A new epoch means the robot's outbox started afresh, so the marks are
//! forgotten.
//!
//! The marks are written to the database before `DELIVERED` is sent, so a hub killed and
//! restarted still recognises what it delivered. Order of the two steps: deliver, record,
//! confirm. A hub killed between delivering and recording delivers that message again
//! after its restart (at-least-once in that window of a few milliseconds); recording first
//! would instead lose it, which no-drop must never do.
//!
//! One robot's book is shared by all its sessions (the old one may still be finishing while
//! the new one starts), so the check-and-advance is one step under its lock.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use crate::store::Store;

/// Per-robot delivery marks, loaded from the store on a robot's first connection.
pub struct DeliveryLedger {
    store: Store,
    // std Mutex: map lookups only, never held across an await.
    robots: Mutex<HashMap<String, Arc<Mutex<RobotBook>>>>,
}

/// One robot's marks.
#[derive(Debug, Default)]
pub struct RobotBook {
    epoch: u64,
    last: HashMap<String, u64>,
    /// Marks advanced since they were last written.
    dirty: HashMap<String, u64>,
}

impl RobotBook {
    /// Whether message `seq` of `topic` is new (and so to be delivered); advances the mark.
    pub fn admit(&mut self, topic: &str, seq: u64) -> bool {
        match self.last.get_mut(topic) {
            Some(last) if seq <= *last => false,
            Some(last) => {
                *last = seq;
                self.dirty.insert(topic.to_owned(), seq);
                true
            }
            None => {
                self.last.insert(topic.to_owned(), seq);
                self.dirty.insert(topic.to_owned(), seq);
                true
            }
        }
    }

    /// The epoch of the robot's outbox these marks belong to.
    pub fn epoch(&self) -> u64 {
        self.epoch
    }

    /// The marks to write: (topic, epoch, seq).
    fn take_dirty(&mut self) -> Vec<(String, u64, u64)> {
        let epoch = self.epoch;
        self.dirty.drain().map(|(t, s)| (t, epoch, s)).collect()
    }
}

impl DeliveryLedger {
    pub fn new(store: Store) -> DeliveryLedger {
        DeliveryLedger {
            store,
            robots: Mutex::new(HashMap::new()),
        }
    }

    /// The book of `robot` for a session whose `HELLO` carried `epoch`.
    pub async fn open(&self, robot: &str, epoch: u64) -> Arc<Mutex<RobotBook>> {
        let cached = self
            .robots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(robot)
            .cloned();
        let book = match cached {
            Some(b) => b,
            None => {
                let (store, r) = (self.store.clone(), robot.to_owned());
                let rows = tokio::task::spawn_blocking(move || store.delivered(&r))
                    .await
                    .map_err(|e| e.to_string())
                    .and_then(|r| r.map_err(|e| e.to_string()))
                    .unwrap_or_else(|e| {
                        tracing::error!("reading delivery marks of {robot}: {e}");
                        Vec::new()
                    });
                // Rows of another epoch are from an outbox the robot no longer has.
                let mut book = RobotBook {
                    epoch,
                    ..RobotBook::default()
                };
                for (topic, e, seq) in rows {
                    if e == epoch {
                        book.last.insert(topic, seq);
                    }
                }
                self.robots
                    .lock()
                    .unwrap_or_else(|p| p.into_inner())
                    .entry(robot.to_owned())
                    .or_insert_with(|| Arc::new(Mutex::new(book)))
                    .clone()
            }
        };
        {
            let mut b = book.lock().unwrap_or_else(|p| p.into_inner());
            if b.epoch != epoch {
                if b.epoch != 0 {
                    tracing::info!(
                        robot,
                        "robot's outbox started afresh (epoch {} → {epoch}); its no-drop \
                         numbering restarts",
                        b.epoch
                    );
                }
                b.epoch = epoch;
                b.last.clear();
                b.dirty.clear();
            }
        }
        book
    }

    /// Writes what `book` advanced since the last call; returns once it is on disk.
    pub async fn record(&self, robot: &str, book: &Mutex<RobotBook>) {
        let marks = book.lock().unwrap_or_else(|p| p.into_inner()).take_dirty();
        if marks.is_empty() {
            return;
        }
        let (store, r) = (self.store.clone(), robot.to_owned());
        let done = tokio::task::spawn_blocking(move || store.record_delivered(&r, &marks)).await;
        match done {
            Ok(Ok(())) => {}
            Ok(Err(e)) => tracing::error!("recording delivery marks of {robot}: {e}"),
            Err(e) => tracing::error!("recording delivery marks of {robot}: {e}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn store() -> (Store, std::path::PathBuf) {
        let dir = std::env::temp_dir().join(format!(
            "fleetlink-ledger-{}-{}",
            std::process::id(),
            fleetlink_relay::unix_nanos()
        ));
        (Store::open(&dir).unwrap(), dir)
    }

    #[tokio::test]
    async fn resends_are_recognised_across_a_hub_restart() {
        let (s, dir) = store();
        let ledger = DeliveryLedger::new(s.clone());
        let book = ledger.open("r1", 7).await;
        {
            let mut b = book.lock().unwrap();
            assert!(b.admit("/r1/a", 1));
            assert!(b.admit("/r1/a", 2));
            assert!(!b.admit("/r1/a", 2), "a resend is not delivered twice");
            assert!(b.admit("/r1/b", 1));
        }
        ledger.record("r1", &book).await;
        // A new hub process on the same database.
        let ledger = DeliveryLedger::new(Store::open(&dir).unwrap());
        let book = ledger.open("r1", 7).await;
        let mut b = book.lock().unwrap();
        assert!(!b.admit("/r1/a", 1));
        assert!(!b.admit("/r1/a", 2));
        assert!(b.admit("/r1/a", 3));
        assert!(!b.admit("/r1/b", 1));
        drop(b);
        let _ = std::fs::remove_dir_all(dir);
    }

    #[tokio::test]
    async fn a_new_epoch_starts_the_numbering_again() {
        let (s, dir) = store();
        let ledger = DeliveryLedger::new(s);
        let book = ledger.open("r1", 7).await;
        assert!(book.lock().unwrap().admit("/r1/a", 50));
        ledger.record("r1", &book).await;
        let book = ledger.open("r1", 8).await;
        assert!(book.lock().unwrap().admit("/r1/a", 1));
        let _ = std::fs::remove_dir_all(dir);
    }

    #[tokio::test]
    async fn sessions_of_one_robot_share_one_book() {
        let (s, dir) = store();
        let ledger = DeliveryLedger::new(s);
        let old = ledger.open("r1", 7).await;
        let new = ledger.open("r1", 7).await;
        assert!(old.lock().unwrap().admit("/r1/a", 1));
        assert!(!new.lock().unwrap().admit("/r1/a", 1));
        let _ = std::fs::remove_dir_all(dir);
    }
}
