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
    ///
    /// The marks are read from the store on the robot's first connection, and on every
    /// connection when the store is shared with other hubs: the robot may have been
    /// connected to another hub since, which delivered (and marked) more.
    pub async fn open(&self, robot: &str, epoch: u64) -> Arc<Mutex<RobotBook>> {
        let cached = self
            .robots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(robot)
            .cloned();
        let rows = if cached.is_none() || self.store.is_shared() {
            let (store, r) = (self.store.clone(), robot.to_owned());
            tokio::task::spawn_blocking(move || store.delivered(&r))
                .await
                .map_err(|e| e.to_string())
                .and_then(|r| r.map_err(|e| e.to_string()))
                .unwrap_or_else(|e| {
                    tracing::error!("reading delivery marks of {robot}: {e}");
                    Vec::new()
                })
        } else {
            Vec::new()
        };
        let book = match cached {
            Some(b) => b,
            None => self
                .robots
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .entry(robot.to_owned())
                .or_insert_with(|| {
                    Arc::new(Mutex::new(RobotBook {
                        epoch,
                        ..RobotBook::default()
                    }))
                })
                .clone(),
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
            // Rows of another epoch are from an outbox the robot no longer has.
            for (topic, e, seq) in rows {
                if e == epoch {
                    let last = b.last.entry(topic).or_insert(seq);
                    *last = (*last).max(seq);
                }
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
    use crate::store::testing::{Backend, Place, on_both_backends};

    on_both_backends!(
        resends_are_recognised_across_a_hub_restart,
        a_new_epoch_starts_the_numbering_again,
        sessions_of_one_robot_share_one_book,
    );

    fn run(f: impl std::future::Future<Output = ()>) {
        tokio::runtime::Runtime::new().unwrap().block_on(f)
    }

    fn resends_are_recognised_across_a_hub_restart(backend: Backend) {
        let place = Place::new(backend, "ledger");
        // Opened outside the runtime: opening blocks on the database.
        let (first, restarted) = (place.open(), place.open());
        run(async {
            let ledger = DeliveryLedger::new(first);
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
            let ledger = DeliveryLedger::new(restarted);
            let book = ledger.open("r1", 7).await;
            let mut b = book.lock().unwrap();
            assert!(!b.admit("/r1/a", 1));
            assert!(!b.admit("/r1/a", 2));
            assert!(b.admit("/r1/a", 3));
            assert!(!b.admit("/r1/b", 1));
        });
    }

    fn a_new_epoch_starts_the_numbering_again(backend: Backend) {
        let place = Place::new(backend, "ledger-epoch");
        let store = place.open();
        run(async {
            let ledger = DeliveryLedger::new(store);
            let book = ledger.open("r1", 7).await;
            assert!(book.lock().unwrap().admit("/r1/a", 50));
            ledger.record("r1", &book).await;
            let book = ledger.open("r1", 8).await;
            assert!(book.lock().unwrap().admit("/r1/a", 1));
        });
    }

    fn sessions_of_one_robot_share_one_book(backend: Backend) {
        let place = Place::new(backend, "ledger-share");
        let store = place.open();
        run(async {
            let ledger = DeliveryLedger::new(store);
            let old = ledger.open("r1", 7).await;
            let new = ledger.open("r1", 7).await;
            assert!(old.lock().unwrap().admit("/r1/a", 1));
            assert!(!new.lock().unwrap().admit("/r1/a", 1));
        });
    }

    /// A robot fails over from hub A to hub B and back: A knows what B delivered meanwhile
    /// (its cached book is brought up to date from the shared database).
    #[test]
    #[ignore = "needs PostgreSQL: tests/interop/postgres/run.sh runs it with a server"]
    fn a_robot_back_from_another_hub_is_not_delivered_twice() {
        let place = Place::new(Backend::Postgres, "ledger-failover");
        let (a, b) = (
            DeliveryLedger::new(place.open()),
            DeliveryLedger::new(place.open()),
        );
        run(async {
            let on_a = a.open("r1", 7).await;
            assert!(on_a.lock().unwrap().admit("/r1/a", 1));
            a.record("r1", &on_a).await;
            let on_b = b.open("r1", 7).await;
            assert!(!on_b.lock().unwrap().admit("/r1/a", 1));
            assert!(on_b.lock().unwrap().admit("/r1/a", 2));
            b.record("r1", &on_b).await;
            let back = a.open("r1", 7).await;
            assert!(!back.lock().unwrap().admit("/r1/a", 2), "delivered by B");
            assert!(back.lock().unwrap().admit("/r1/a", 3));
        });
    }
}
