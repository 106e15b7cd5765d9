//! The hub's parameters: served from memory, written through to the database so they
//! survive a restart.
//!
//! Memory is the truth; the database follows it. A change marks its names dirty, and one
//! writer thread brings each dirty name's row in line with memory (set, or deleted), so a
//! `set_param` never waits for the disk on the session's task. What waits is bounded by
//! the parameters themselves: a name changed again before it was written is written once,
//! with its newest value (counted in [`DurableParams::coalesced`]); nothing is lost, since
//! the newest value is what the database must hold. A failed write is logged. A stopping
//! hub waits for the writer ([`ParamStore::flush`]), so a change answered `true` just
//! before the stop is still there after the restart.

use std::collections::{BTreeMap, BTreeSet};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::mpsc::{SyncSender, sync_channel};
use std::sync::{Arc, Condvar, Mutex};

use fleetlink_relay::params::{MemoryParams, ParamStore};

use crate::store::{Store, StoreError};

/// What the writer thread has to do.
#[derive(Default)]
struct Dirty {
    names: BTreeSet<String>,
    /// Answered once every name dirty when they were asked is written.
    flushes: Vec<SyncSender<()>>,
    /// The store is gone: the writer ends after this round.
    closed: bool,
}

struct Shared {
    // std Mutex: marking names and taking them, never held across an await or a write.
    dirty: Mutex<Dirty>,
    wake: Condvar,
    coalesced: AtomicU64,
}

impl Shared {
    fn lock(&self) -> std::sync::MutexGuard<'_, Dirty> {
        self.dirty.lock().unwrap_or_else(|p| p.into_inner())
    }

    fn mark(&self, names: impl IntoIterator<Item = String>) {
        let mut d = self.lock();
        for n in names {
            if !d.names.insert(n) {
                self.coalesced.fetch_add(1, Relaxed);
            }
        }
        drop(d);
        self.wake.notify_one();
    }
}

pub struct DurableParams {
    mem: Arc<MemoryParams>,
    shared: Arc<Shared>,
}

impl DurableParams {
    /// Loads the stored parameters and starts the writer thread.
    pub fn open(store: Store) -> Result<DurableParams, StoreError> {
        let (params, start) = DurableParams::unstarted(store)?;
        start()?;
        Ok(params)
    }

    /// The store, and what starts its writer thread.
    fn unstarted(
        store: Store,
    ) -> Result<(DurableParams, impl FnOnce() -> Result<(), StoreError>), StoreError> {
        let mem = Arc::new(MemoryParams::with(store.params()?));
        let shared = Arc::new(Shared {
            dirty: Mutex::new(Dirty::default()),
            wake: Condvar::new(),
            coalesced: AtomicU64::new(0),
        });
        let (m, sh) = (mem.clone(), shared.clone());
        let start = move || {
            std::thread::Builder::new()
                .name("fleetlink-params".into())
                .spawn(move || write_loop(&store, &m, &sh))
                .map(|_| ())
                .map_err(StoreError::Thread)
        };
        Ok((DurableParams { mem, shared }, start))
    }

    /// Writes saved because a name changed again before it was written.
    pub fn coalesced(&self) -> u64 {
        self.shared.coalesced.load(Relaxed)
    }
}

impl Drop for DurableParams {
    fn drop(&mut self) {
        self.shared.lock().closed = true;
        self.shared.wake.notify_one();
    }
}

/// The writer thread: brings each dirty name's row in line with memory.
fn write_loop(store: &Store, mem: &MemoryParams, shared: &Shared) {
    loop {
        let (names, flushes, closed) = {
            let mut d = shared.lock();
            while d.names.is_empty() && d.flushes.is_empty() && !d.closed {
                d = shared.wake.wait(d).unwrap_or_else(|p| p.into_inner());
            }
            (
                std::mem::take(&mut d.names),
                std::mem::take(&mut d.flushes),
                d.closed,
            )
        };
        for name in names {
            let r = match mem.get(&name) {
                Some(v) => store.set_param(&name, &v),
                None => store.delete_param(&name),
            };
            if let Err(e) = r {
                tracing::error!("parameters: cannot write {name} to the database: {e}");
            }
        }
        for f in flushes {
            let _ = f.send(());
        }
        if closed {
            return;
        }
    }
}

impl ParamStore for DurableParams {
    fn snapshot(&self) -> BTreeMap<String, String> {
        self.mem.snapshot()
    }
    fn get(&self, name: &str) -> Option<String> {
        self.mem.get(name)
    }
    fn set(&self, name: &str, value_json: String) {
        self.mem.set(name, value_json);
        self.shared.mark([name.to_owned()]);
    }
    fn delete(&self, name: &str) -> bool {
        let gone = self.mem.remove_under(name);
        let any = !gone.is_empty();
        self.shared.mark(gone);
        any
    }
    fn flush(&self) {
        let (done_tx, done_rx) = sync_channel(1);
        self.shared.lock().flushes.push(done_tx);
        self.shared.wake.notify_one();
        let _ = done_rx.recv();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flush_returns_once_every_change_is_in_the_database() {
        let dir = std::env::temp_dir().join(format!(
            "fleetlink-params-{}-{:?}",
            std::process::id(),
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .unwrap_or_default()
                .as_nanos()
        ));
        let params = DurableParams::open(Store::open(&dir).unwrap()).unwrap();
        for i in 0..2000 {
            params.set(&format!("/p/{i:04}"), i.to_string());
        }
        assert!(params.delete("/p/0000"));
        params.flush();
        // A second connection, as a restarted hub would open.
        let stored = Store::open(&dir).unwrap().params().unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(stored.len(), 1999, "changes missing after flush");
        assert_eq!(stored.get("/p/1999").map(String::as_str), Some("1999"));
        assert!(!stored.contains_key("/p/0000"));
    }

    /// Issue 36: what waits for the database is one entry per parameter, however often it
    /// changes, and the database ends with the newest value; a subtree deleted and a name
    /// under it set again keeps that name.
    #[test]
    fn issue36_repeated_changes_wait_as_one_write_and_the_newest_value_wins() {
        let dir = std::env::temp_dir().join(format!(
            "fleetlink-params-coalesce-{}-{}",
            std::process::id(),
            fleetlink_relay::unix_nanos()
        ));
        // The changes come in before the writer runs, as they would while it is busy.
        let (params, start) = DurableParams::unstarted(Store::open(&dir).unwrap()).unwrap();
        for i in 0..10_000 {
            params.set("/speed", i.to_string());
        }
        params.set("/a/b", "1".into());
        params.set("/a/c", "2".into());
        assert!(params.delete("/a"));
        params.set("/a/c", "3".into());
        assert_eq!(
            params.shared.lock().names.len(),
            3,
            "one entry per name waits"
        );
        start().unwrap();
        params.flush();
        assert_eq!(params.coalesced(), 9_999 + 3);
        let stored = Store::open(&dir).unwrap().params().unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(stored.get("/speed").map(String::as_str), Some("9999"));
        assert_eq!(stored.get("/a/c").map(String::as_str), Some("3"));
        assert!(!stored.contains_key("/a/b"));
    }
}
