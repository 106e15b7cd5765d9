//! The audit log: who did what to which robot, from where, when, and whether it was
//! allowed; plus every authentication failure and every rule or credential change.
//!
//! Design choice: recording never blocks the caller. [`AuditLog::record`] is a `try_send`
//! on a bounded channel to one writer thread that inserts in batches (one transaction per
//! batch, up to [`BATCH_MAX`] records). When the channel is full the record is dropped and
//! counted ([`AuditLog::overflowed`]) — the relay must not slow down because the disk
//! did; the counter is exported as a metric so a gap in the log is visible. While a shared
//! database is unreachable, up to [`HOLD_MAX`] records wait in the writer and are written
//! when it answers again; beyond that they are counted as failed ([`AuditLog::failed`]).
//!
//! Layout: `record.rs` says what an entry is, `query.rs` what one asks of the log and gets
//! back; the store writes and reads them (`crate::store`, one SQL dialect per backend);
//! this file is the writer thread between the two.

pub(crate) mod query;
pub(crate) mod record;

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, SyncSender, TrySendError, sync_channel};

pub use query::{AuditCursor, AuditPage, AuditQuery, MAX_PAGE, StoredAudit};
pub use record::{AuditAction, AuditRecord};

use crate::store::Store;

/// Records written per transaction at most.
pub const BATCH_MAX: usize = 512;

enum Msg {
    Record(AuditRecord),
    Flush(SyncSender<()>),
}

#[derive(Default)]
struct Counters {
    overflowed: AtomicU64,
    written: AtomicU64,
    failed: AtomicU64,
}

/// The sending side of the audit log. Cheap to clone; the writer thread ends when the
/// last clone is dropped, after writing what was queued.
#[derive(Clone)]
pub struct AuditLog {
    // Overflow policy: a full channel drops the new record and counts it.
    tx: SyncSender<Msg>,
    counters: Arc<Counters>,
}

impl AuditLog {
    /// Starts the writer thread on `store` with a channel of `capacity` records.
    pub fn start(store: Store, capacity: usize) -> std::io::Result<AuditLog> {
        let (tx, rx) = sync_channel(capacity.max(1));
        let counters = Arc::new(Counters::default());
        let c = Arc::clone(&counters);
        std::thread::Builder::new()
            .name("fleetlink-audit".to_owned())
            .spawn(move || writer(store, rx, c))?;
        Ok(AuditLog { tx, counters })
    }

    /// Queues a record without blocking; `false` if it was dropped (channel full or
    /// writer gone).
    pub fn record(&self, record: AuditRecord) -> bool {
        match self.tx.try_send(Msg::Record(record)) {
            Ok(()) => true,
            Err(TrySendError::Full(_) | TrySendError::Disconnected(_)) => {
                self.counters.overflowed.fetch_add(1, Ordering::Relaxed);
                false
            }
        }
    }

    /// Blocks until everything queued before this call is written. For tests and
    /// shutdown only — never on an async worker thread.
    pub fn flush(&self) {
        let (done_tx, done_rx) = sync_channel(1);
        if self.tx.send(Msg::Flush(done_tx)).is_ok() {
            let _ = done_rx.recv();
        }
    }

    /// Records dropped because the channel was full.
    pub fn overflowed(&self) -> u64 {
        self.counters.overflowed.load(Ordering::Relaxed)
    }

    pub fn written(&self) -> u64 {
        self.counters.written.load(Ordering::Relaxed)
    }

    /// Records lost to database errors (each failed batch is logged with its cause).
    pub fn failed(&self) -> u64 {
        self.counters.failed.load(Ordering::Relaxed)
    }
}

/// Records kept for another try while the database is unreachable, at most; beyond
/// that they are counted as failed.
pub const HOLD_MAX: usize = 8 * BATCH_MAX;
/// How often held records are tried again when nothing new arrives.
const RETRY_EVERY: std::time::Duration = std::time::Duration::from_secs(1);

fn writer(store: Store, rx: Receiver<Msg>, counters: Arc<Counters>) {
    use std::sync::mpsc::RecvTimeoutError;
    // Records a write failed for because the database was unreachable (a shared
    // PostgreSQL restarting): written with the next batch once it answers again.
    let mut held: Vec<AuditRecord> = Vec::new();
    let mut batch = Vec::with_capacity(BATCH_MAX);
    let mut flushes = Vec::new();
    loop {
        let first = if held.is_empty() {
            match rx.recv() {
                Ok(m) => Some(m),
                // Every sender is gone and nothing is held: done.
                Err(_) => return,
            }
        } else {
            match rx.recv_timeout(RETRY_EVERY) {
                Ok(m) => Some(m),
                Err(RecvTimeoutError::Timeout) => None,
                Err(RecvTimeoutError::Disconnected) => {
                    write(&store, &mut held, &mut Vec::new(), &counters, false);
                    return;
                }
            }
        };
        let mut next = first;
        while let Some(msg) = next {
            match msg {
                Msg::Record(r) => batch.push(r),
                Msg::Flush(done) => flushes.push(done),
            }
            next = if batch.len() < BATCH_MAX {
                rx.try_recv().ok()
            } else {
                None
            };
        }
        write(&store, &mut held, &mut batch, &counters, true);
        for done in flushes.drain(..) {
            let _ = done.send(());
        }
    }
}

/// Writes `held` then `batch` in one go. When the database is unreachable and `may_hold`,
/// keeps up to [`HOLD_MAX`] of them in `held` for the next try; what does not fit, or
/// fails for another reason, is counted as failed.
fn write(
    store: &Store,
    held: &mut Vec<AuditRecord>,
    batch: &mut Vec<AuditRecord>,
    counters: &Counters,
    may_hold: bool,
) {
    if held.is_empty() && batch.is_empty() {
        return;
    }
    let retrying = held.len();
    held.append(batch);
    let n = held.len() as u64;
    match store.insert_audit_batch(held) {
        Ok(()) => {
            if retrying > 0 {
                tracing::info!(
                    "audit log: wrote {retrying} records held while the database was away"
                );
            }
            counters.written.fetch_add(n, Ordering::Relaxed);
            held.clear();
        }
        Err(e) if may_hold && e.is_unavailable() => {
            if held.len() > HOLD_MAX {
                let lost = held.len() - HOLD_MAX;
                held.drain(..lost);
                counters.failed.fetch_add(lost as u64, Ordering::Relaxed);
            }
            if retrying == 0 {
                tracing::error!(
                    "audit log: {e}; holding up to {HOLD_MAX} records until it answers"
                );
            }
        }
        Err(e) => {
            tracing::error!("audit log: cannot write {n} records: {e}");
            counters.failed.fetch_add(n, Ordering::Relaxed);
            held.clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use std::net::IpAddr;

    use super::*;
    use crate::UnixTime;

    fn record(i: i64) -> AuditRecord {
        AuditRecord {
            at: UnixTime(i),
            principal: "robot:r1".to_owned(),
            client_ip: IpAddr::from([192, 0, 2, 1]),
            action: AuditAction::Publish,
            name: "/r1/cmd_vel".to_owned(),
            size: Some(64),
            allowed: true,
            detail: None,
        }
    }

    #[test]
    fn full_channel_drops_and_counts_instead_of_blocking() {
        let store = Store::open_in_memory().unwrap();
        let log = AuditLog::start(store.clone(), 1).unwrap();
        let accepted = {
            let _stalled = store.lock_for_test();
            // The writer can hold at most one record while stalled, the channel one more.
            (0..10).filter(|i| log.record(record(*i))).count() as u64
        };
        assert!(accepted <= 2, "accepted {accepted}");
        assert_eq!(log.overflowed(), 10 - accepted);
        log.flush();
        assert_eq!(log.written(), accepted);
    }

    #[test]
    fn writer_batches_everything_queued() {
        let store = Store::open_in_memory().unwrap();
        let log = AuditLog::start(store.clone(), 4096).unwrap();
        for i in 0..2000 {
            assert!(log.record(record(i)));
        }
        log.flush();
        assert_eq!(log.written(), 2000);
        assert_eq!(log.failed(), 0);
    }
}
