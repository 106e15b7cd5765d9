//! The durable outbox: no-drop messages on disk until the hub confirms them, so an agent
//! killed or powered off mid-outage resends them when it comes back.
//!
//! One append-only file, `outbox.log`, in the configured directory. Every record is
//!
//! ```text
//! +-------------+-------------+------------------------------+
//! | len u32le   | crc32 u32le | body (len bytes)             |
//! +-------------+-------------+------------------------------+
//! body: kind u8, then
//!   HEADER  0x01  magic "FLKOUTBX" | version u32le | epoch u64le          (first record)
//!   TOPIC   0x02  ref u32le | name | type | schema encoding | schema text  (str = u32le len + UTF-8)
//!   MESSAGE 0x03  ref u32le | seq u64le | stamp_ns u64le | encoding u8 | payload (rest)
//!   CONFIRM 0x04  ref u32le | seq u64le                                    (hub has ≤ seq)
//!   FLOOR   0x05  ref u32le | next_seq u64le                               (numbering goes on)
//! ```
//!
//! Design choices:
//!
//! - **Nothing on the agent's thread waits on the disk.** The agent runs its adapters, its
//!   link and its heartbeat on one thread, so one slow flash write would stall them all.
//!   [`FileJournal`] is the agent thread's side: it numbers topics, keeps the byte count
//!   that bounds the outbox, and hands each record to the journal's own thread over a
//!   bounded channel ([`JOURNAL_QUEUE`] records); that thread writes, syncs by the policy
//!   ([`Fsync`]) and compacts. A record holds the message's payload by reference (the
//!   buffer the outbox queues), so the channel costs no copies.
//! - **What a crash may take.** A message is handed to the journal thread before it is
//!   queued for the hub, and written by it in order, normally within microseconds. A
//!   `kill -9` loses what the thread had not written yet; a power cut also what was not
//!   yet synced (the fsync policy). When the thread falls [`JOURNAL_QUEUE`] records behind
//!   (a disk far slower than the no-drop traffic) the agent's thread waits for it: a no-drop
//!   message is never refused for a slow disk.
//! - Reading back stops at the first torn or corrupt record and cuts the file there: only
//!   the tail that was being written can be damaged by a crash.
//! - The unconfirmed messages are also held in memory (their payloads are the same shared
//!   buffers the outbox queues), so compaction rewrites the file from the journal thread's
//!   own copy of that list without reading the file: when the file has grown well past
//!   what is still unconfirmed, the live records are written to a new file that replaces
//!   the old one atomically (rename).

mod disk;

use std::collections::{HashMap, VecDeque};
use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{Receiver, RecvTimeoutError, SyncSender, TrySendError};
use std::time::Duration;

use fleetlink_proto::Payload;
use fleetlink_relay::TopicName;
use fleetlink_relay::message::TopicMeta;
use fleetlink_relay::reliable::{Journal, JournalError, Recovered};

use disk::{Disk, Live, Op};

/// `Fsync::Batch`: at most this long between a write and its sync while messages flow.
pub const BATCH_SYNC: Duration = Duration::from_millis(50);
/// Records the agent's thread may hand the journal thread ahead of the disk (the channel's
/// bound). Each holds its payload by reference; only past this does the agent wait.
pub const JOURNAL_QUEUE: usize = 65_536;

/// When written records are forced to the disk (`outbox.fsync`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Fsync {
    /// After every message the journal thread writes: a power cut loses at most what the
    /// thread had not reached; costs one disk flush per message (on that thread).
    Always,
    /// At most [`BATCH_SYNC`] after a write while messages flow, and within a second
    /// otherwise: a power cut may lose the last fraction of a second.
    #[default]
    Batch,
    /// Left to the operating system's writeback: survives process crashes, not power cuts.
    Never,
}

/// `outbox:` in the agent configuration.
#[derive(Debug, Clone, PartialEq)]
pub struct OutboxStoreConfig {
    pub dir: PathBuf,
    pub max_bytes: u64,
    pub fsync: Fsync,
}

#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("durable outbox {path}: {cause}")]
    Io { path: String, cause: std::io::Error },
    #[error(
        "durable outbox {path} is used by another running agent (locked); give each agent \
         its own outbox.dir"
    )]
    Locked { path: String },
    #[error("durable outbox {path} is not a fleetlink outbox file ({why}); move it away")]
    Foreign { path: String, why: String },
}

fn io_err(path: &Path, cause: std::io::Error) -> StoreError {
    StoreError::Io {
        path: path.display().to_string(),
        cause,
    }
}

/// An opened outbox: the journal to write to, and what a previous run left unconfirmed.
pub struct Opened {
    pub journal: FileJournal,
    pub epoch: u64,
    /// Per topic, the next sequence number to use.
    pub next_seq: HashMap<TopicName, u64>,
    /// Unconfirmed messages, in the order they were first written.
    pub recovered: Vec<Recovered>,
}

/// Opens (or creates) the outbox in `cfg.dir`, reads back what it holds, and starts its
/// journal thread.
pub fn open(cfg: &OutboxStoreConfig) -> Result<Opened, StoreError> {
    std::fs::create_dir_all(&cfg.dir).map_err(|e| io_err(&cfg.dir, e))?;
    let path = disk::file_in(&cfg.dir);
    let file = OpenOptions::new()
        .read(true)
        .append(true)
        .create(true)
        .open(&path)
        .map_err(|e| io_err(&path, e))?;
    match file.try_lock() {
        Ok(()) => {}
        Err(std::fs::TryLockError::WouldBlock) => {
            return Err(StoreError::Locked {
                path: path.display().to_string(),
            });
        }
        Err(std::fs::TryLockError::Error(e)) => return Err(io_err(&path, e)),
    }
    let disk = Disk::open(path.clone(), file, cfg.fsync)?;
    let recovered = disk
        .live
        .iter()
        .map(|l| {
            let t = &disk.topics[l.topic as usize];
            Recovered {
                topic: t.name.clone(),
                schema: t.schema.clone(),
                seq: l.seq,
                stamp_ns: l.stamp_ns,
                encoding: l.encoding,
                payload: l.payload.clone(),
            }
        })
        .collect();
    let next_seq = disk
        .topics
        .iter()
        .map(|t| (t.name.clone(), t.next_seq))
        .collect();
    let refs = disk
        .topics
        .iter()
        .enumerate()
        .map(|(i, t)| (t.name.clone(), i as u32))
        .collect();
    let live = disk
        .live
        .iter()
        .map(|l| (l.topic, l.seq, l.payload.len() as u64))
        .collect();
    let epoch = disk.epoch;
    let journal = FileJournal {
        path,
        refs,
        live,
        live_bytes: disk.live_bytes(),
        max_bytes: cfg.max_bytes,
        writer: JournalThread::start(disk).map_err(|e| io_err(&cfg.dir, e))?,
        waited_logged: false,
    };
    Ok(Opened {
        epoch,
        next_seq,
        recovered,
        journal,
    })
}

/// The journal thread and the channel to it.
struct JournalThread {
    tx: Option<SyncSender<Op>>,
    thread: Option<std::thread::JoinHandle<()>>,
    /// The last write error, taken by the agent's side to refuse the next message.
    failed: std::sync::Arc<std::sync::Mutex<Option<std::io::Error>>>,
}

impl JournalThread {
    fn start(mut disk: Disk) -> std::io::Result<JournalThread> {
        let (tx, rx) = std::sync::mpsc::sync_channel::<Op>(JOURNAL_QUEUE);
        let failed = std::sync::Arc::new(std::sync::Mutex::new(None));
        let report = failed.clone();
        let thread = std::thread::Builder::new()
            .name("outbox-journal".into())
            .spawn(move || run(&mut disk, &rx, &report))?;
        Ok(JournalThread {
            tx: Some(tx),
            thread: Some(thread),
            failed,
        })
    }
}

/// The journal thread: applies what the agent's thread hands it, in order, until the
/// agent's side is dropped; a batch policy's pending writes are synced when the records
/// pause.
fn run(disk: &mut Disk, rx: &Receiver<Op>, failed: &std::sync::Mutex<Option<std::io::Error>>) {
    loop {
        let op = if disk.sync_pending() {
            match rx.recv_timeout(BATCH_SYNC) {
                Ok(op) => op,
                Err(RecvTimeoutError::Timeout) => Op::Tick,
                Err(RecvTimeoutError::Disconnected) => break,
            }
        } else {
            match rx.recv() {
                Ok(op) => op,
                Err(_) => break,
            }
        };
        if let Err(e) = disk.apply(op) {
            tracing::warn!("durable outbox {}: {e}", disk.path.display());
            *failed.lock().unwrap_or_else(|p| p.into_inner()) = Some(e);
        }
    }
    // The agent is stopping: what was written is made durable before the file is let go.
    disk.sync(true);
}

impl Drop for JournalThread {
    /// Waits for the thread to write what it was handed: its file holds the outbox's lock,
    /// which must be free when the journal is gone (an agent restarting in one process).
    fn drop(&mut self) {
        drop(self.tx.take());
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// The agent thread's side of the durable outbox (see the module docs).
pub struct FileJournal {
    path: PathBuf,
    refs: HashMap<TopicName, u32>,
    /// Unconfirmed messages: (topic ref, seq, payload bytes), for the byte bound.
    live: VecDeque<(u32, u64, u64)>,
    live_bytes: u64,
    max_bytes: u64,
    writer: JournalThread,
    /// Whether "the disk is behind" was logged (once per journal).
    waited_logged: bool,
}

impl FileJournal {
    /// Hands `op` to the journal thread; waits only when it is [`JOURNAL_QUEUE`] behind.
    fn hand(&mut self, op: Op) {
        let Some(tx) = &self.writer.tx else { return };
        match tx.try_send(op) {
            Ok(()) => {}
            Err(TrySendError::Full(op)) => {
                if !self.waited_logged {
                    self.waited_logged = true;
                    tracing::warn!(
                        "durable outbox {}: the disk is {JOURNAL_QUEUE} records behind the \
                         no-drop traffic; the agent waits for it",
                        self.path.display()
                    );
                }
                let _ = tx.send(op);
            }
            Err(TrySendError::Disconnected(_)) => {}
        }
    }

    /// Returns once the journal thread has written everything handed to it so far.
    pub fn wait_written(&mut self) {
        let (done, wait) = std::sync::mpsc::sync_channel(1);
        self.hand(Op::Barrier(done));
        let _ = wait.recv();
    }

    /// Stops the journal thread once it has written and synced everything handed to it
    /// (the agent is stopping). Messages appended afterwards are refused.
    pub fn close(&mut self) {
        let (tx, thread) = (self.writer.tx.take(), self.writer.thread.take());
        drop(tx);
        if let Some(t) = thread {
            let _ = t.join();
        }
    }

    fn topic_ref(&mut self, topic: &TopicMeta) -> u32 {
        if let Some(&r) = self.refs.get(&topic.name) {
            return r;
        }
        let id = self.refs.len() as u32;
        self.refs.insert(topic.name.clone(), id);
        self.hand(Op::Topic {
            id,
            name: topic.name.clone(),
            schema: topic.schema.clone(),
        });
        id
    }
}

impl Journal for FileJournal {
    fn append(
        &mut self,
        topic: &TopicMeta,
        seq: u64,
        stamp_ns: u64,
        payload: &Payload,
    ) -> Result<(), JournalError> {
        let size = payload.len() as u64;
        if self.live_bytes + size > self.max_bytes {
            return Err(JournalError::Full {
                used: self.live_bytes,
                limit: self.max_bytes,
            });
        }
        if self.writer.tx.is_none() {
            return Err(JournalError::Io {
                path: self.path.display().to_string(),
                cause: std::io::Error::other(
                    "the durable outbox is closed (the agent is stopping)",
                ),
            });
        }
        if let Some(cause) = self
            .writer
            .failed
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .take()
        {
            return Err(JournalError::Io {
                path: self.path.display().to_string(),
                cause,
            });
        }
        let topic_ref = self.topic_ref(topic);
        self.hand(Op::Message(Live {
            topic: topic_ref,
            seq,
            stamp_ns,
            encoding: payload.encoding,
            payload: payload.bytes.clone(),
        }));
        self.live_bytes += size;
        self.live.push_back((topic_ref, seq, size));
        Ok(())
    }

    fn confirm(&mut self, topic: &TopicName, seq: u64) {
        let Some(&r) = self.refs.get(topic) else {
            return;
        };
        let mut freed = 0;
        self.live.retain(|&(t, s, size)| {
            let done = t == r && s <= seq;
            if done {
                freed += size;
            }
            !done
        });
        self.live_bytes -= freed;
        self.hand(Op::Confirm { topic: r, seq });
    }

    fn tick(&mut self) {
        // A full channel has work queued anyway: the tick is not needed then.
        if let Some(tx) = &self.writer.tx {
            let _ = tx.try_send(Op::Tick);
        }
    }

    fn close(&mut self) {
        FileJournal::close(self);
    }
}

/// A slow disk for test builds: every write to the outbox file first waits as long as
/// writing it at the set rate would take, so that what waits on the disk can be measured
/// (`fleetlink bench journal`). Compiled out of release builds, where [`available`] is
/// false and [`set`] does nothing.
pub mod slow_disk {
    use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

    static RATE: AtomicU64 = AtomicU64::new(0);

    /// Whether this build can slow its disk (a build with debug assertions).
    pub fn available() -> bool {
        cfg!(debug_assertions)
    }

    /// Writes go at `bytes_per_sec` from now on; 0 for full speed.
    pub fn set(bytes_per_sec: u64) {
        if available() {
            RATE.store(bytes_per_sec, Relaxed);
        }
    }

    pub(crate) fn wait(bytes: usize) {
        let rate = RATE.load(Relaxed);
        if available() && rate > 0 {
            std::thread::sleep(std::time::Duration::from_secs_f64(
                bytes as f64 / rate as f64,
            ));
        }
    }
}

#[cfg(test)]
#[path = "tests.rs"]
mod tests;
