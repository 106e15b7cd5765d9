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
//! Design choices: a message is written (one `write` call) before it is queued, so once the
//! agent has read it from a publisher a `kill -9` cannot lose it — the kernel holds it. The
//! fsync policy decides what a *power loss* may take ([`Fsync`]). Reading back stops at the
//! first torn or corrupt record and cuts the file there: only the tail that was being
//! written can be damaged by a crash. The unconfirmed messages are also held in memory
//! (their payloads are the same shared buffers the outbox queues), so compaction rewrites
//! the file from memory without reading it: when the file has grown well past what is
//! still unconfirmed, the live records are written to a new file that replaces the old one
//! atomically (rename).

use std::collections::{HashMap, VecDeque};
use std::fs::{File, OpenOptions};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::TopicName;
use fleetlink_relay::message::TopicMeta;
use fleetlink_relay::reliable::{Journal, JournalError, Recovered};

const FILE: &str = "outbox.log";
const MAGIC: &[u8; 8] = b"FLKOUTBX";
const VERSION: u32 = 1;
/// A record larger than this is corruption, not a message (the link carries ≤ 64 MiB).
const MAX_RECORD: u32 = 80 << 20;
/// Compact when the file exceeds this and is mostly confirmed records.
const COMPACT_MIN: u64 = 4 << 20;
/// `Fsync::Batch`: at most this long between a write and its sync while messages flow.
pub const BATCH_SYNC: Duration = Duration::from_millis(50);

const HEADER: u8 = 0x01;
const TOPIC: u8 = 0x02;
const MESSAGE: u8 = 0x03;
const CONFIRM: u8 = 0x04;
const FLOOR: u8 = 0x05;

/// When written records are forced to the disk (`outbox.fsync`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Fsync {
    /// After every message: nothing the agent has read is lost to a power cut; costs one
    /// disk flush per message.
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

/// An opened outbox: the journal to write to, and what a previous run left unconfirmed.
pub struct Opened {
    pub journal: FileJournal,
    pub epoch: u64,
    /// Per topic, the next sequence number to use.
    pub next_seq: HashMap<TopicName, u64>,
    /// Unconfirmed messages, in the order they were first written.
    pub recovered: Vec<Recovered>,
}

struct TopicEntry {
    name: TopicName,
    schema: Schema,
    next_seq: u64,
}

struct Live {
    topic: u32,
    seq: u64,
    stamp_ns: u64,
    encoding: Encoding,
    payload: Bytes,
}

/// The file-backed [`Journal`].
pub struct FileJournal {
    path: PathBuf,
    file: File,
    len: u64,
    epoch: u64,
    topics: Vec<TopicEntry>,
    refs: HashMap<TopicName, u32>,
    live: VecDeque<Live>,
    live_bytes: u64,
    max_bytes: u64,
    fsync: Fsync,
    synced_at: Instant,
    dirty: bool,
    /// The batch policy's syncs run here, off the agent's thread.
    syncer: Option<Syncer>,
}

/// Runs a batch policy's disk syncs on a thread of its own, so the agent (one thread)
/// never waits for the disk. At most one request waits behind the sync in progress, and
/// it covers every write made before it starts.
struct Syncer {
    tx: Option<std::sync::mpsc::SyncSender<()>>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Syncer {
    fn start(file: &File, path: &Path) -> std::io::Result<Syncer> {
        let file = file.try_clone()?;
        let path = path.display().to_string();
        let (tx, rx) = std::sync::mpsc::sync_channel::<()>(1);
        let thread = std::thread::Builder::new()
            .name("outbox-sync".into())
            .spawn(move || {
                // Ends when the journal drops its sender (closed, or its file replaced).
                while rx.recv().is_ok() {
                    if let Err(e) = file.sync_data() {
                        tracing::warn!("durable outbox {path}: sync failed: {e}");
                    }
                }
            })?;
        Ok(Syncer {
            tx: Some(tx),
            thread: Some(thread),
        })
    }

    fn request(&self) {
        // Full: a sync is already waiting to start, and it covers this write too.
        if let Some(tx) = &self.tx {
            let _ = tx.try_send(());
        }
    }
}

impl Drop for Syncer {
    /// Waits for the thread: its copy of the file descriptor holds the outbox's lock, which
    /// must be free when the journal is gone (an agent restarting in the same process).
    fn drop(&mut self) {
        drop(self.tx.take());
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

fn io_err(path: &Path, cause: std::io::Error) -> StoreError {
    StoreError::Io {
        path: path.display().to_string(),
        cause,
    }
}

/// Opens (or creates) the outbox in `cfg.dir` and reads back what it holds.
pub fn open(cfg: &OutboxStoreConfig) -> Result<Opened, StoreError> {
    std::fs::create_dir_all(&cfg.dir).map_err(|e| io_err(&cfg.dir, e))?;
    let path = cfg.dir.join(FILE);
    let mut file = OpenOptions::new()
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
    let mut data = Vec::new();
    file.read_to_end(&mut data).map_err(|e| io_err(&path, e))?;
    let mut j = FileJournal {
        path: path.clone(),
        file,
        len: 0,
        epoch: 0,
        topics: Vec::new(),
        refs: HashMap::new(),
        live: VecDeque::new(),
        live_bytes: 0,
        max_bytes: cfg.max_bytes,
        fsync: cfg.fsync,
        synced_at: Instant::now(),
        dirty: false,
        syncer: None,
    };
    let good = j.replay(&data)?;
    if good < data.len() as u64 {
        tracing::warn!(
            "durable outbox {}: dropped a torn record at byte {good} of {} (the agent stopped \
             while writing it; it was never queued)",
            path.display(),
            data.len()
        );
        j.file.set_len(good).map_err(|e| io_err(&path, e))?;
    }
    j.len = good;
    if j.epoch == 0 {
        // A new outbox: a new numbering the hub has not seen.
        j.epoch = fastrand::u64(1..);
        j.rewrite()?;
    }
    let recovered = j
        .live
        .iter()
        .map(|l| {
            let t = &j.topics[l.topic as usize];
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
    let next_seq = j
        .topics
        .iter()
        .map(|t| (t.name.clone(), t.next_seq))
        .collect();
    Ok(Opened {
        epoch: j.epoch,
        next_seq,
        recovered,
        journal: j,
    })
}

impl FileJournal {
    /// Applies the records in `data`; returns the length of its intact prefix.
    fn replay(&mut self, data: &[u8]) -> Result<u64, StoreError> {
        let foreign = |why: &str| StoreError::Foreign {
            path: self.path.display().to_string(),
            why: why.to_owned(),
        };
        let mut pos = 0usize;
        let mut confirmed: HashMap<u32, u64> = HashMap::new();
        while let Some((body, next)) = record_at(data, pos) {
            let mut r = Cursor(body);
            let Some(kind) = r.u8() else { break };
            let ok = match kind {
                HEADER => {
                    if r.take(8) != Some(&MAGIC[..]) || r.u32() != Some(VERSION) {
                        return Err(foreign("bad header"));
                    }
                    r.u64().map(|e| self.epoch = e).is_some()
                }
                TOPIC => (|| {
                    let (id, name) = (r.u32()?, r.str()?);
                    let schema = Schema {
                        type_name: r.str()?,
                        encoding: r.str()?,
                        text: r.str()?,
                    };
                    let name = TopicName::parse(&name).ok()?;
                    if id as usize != self.topics.len() {
                        return None;
                    }
                    self.refs.insert(name.clone(), id);
                    self.topics.push(TopicEntry {
                        name,
                        schema,
                        next_seq: 1,
                    });
                    Some(())
                })()
                .is_some(),
                MESSAGE => (|| {
                    let (topic, seq, stamp_ns) = (r.u32()?, r.u64()?, r.u64()?);
                    let encoding = Encoding::from_u8(r.u8()?)?;
                    let t = self.topics.get_mut(topic as usize)?;
                    t.next_seq = t.next_seq.max(seq + 1);
                    let payload = Bytes::copy_from_slice(r.0);
                    self.live_bytes += payload.len() as u64;
                    self.live.push_back(Live {
                        topic,
                        seq,
                        stamp_ns,
                        encoding,
                        payload,
                    });
                    Some(())
                })()
                .is_some(),
                CONFIRM => (|| {
                    let (topic, seq) = (r.u32()?, r.u64()?);
                    let c = confirmed.entry(topic).or_default();
                    *c = (*c).max(seq);
                    Some(())
                })()
                .is_some(),
                FLOOR => (|| {
                    let (topic, next) = (r.u32()?, r.u64()?);
                    let t = self.topics.get_mut(topic as usize)?;
                    t.next_seq = t.next_seq.max(next);
                    Some(())
                })()
                .is_some(),
                _ => false,
            };
            if !ok || (pos == 0 && kind != HEADER) {
                if pos == 0 {
                    return Err(foreign("no header"));
                }
                break;
            }
            pos = next;
        }
        let before = self.live.len();
        self.live
            .retain(|l| confirmed.get(&l.topic).is_none_or(|&c| l.seq > c));
        if self.live.len() != before {
            self.live_bytes = self.live.iter().map(|l| l.payload.len() as u64).sum();
        }
        Ok(pos as u64)
    }

    fn topic_ref(&mut self, topic: &TopicMeta) -> Result<u32, JournalError> {
        if let Some(&r) = self.refs.get(&topic.name) {
            return Ok(r);
        }
        let id = self.topics.len() as u32;
        self.write(&topic_body(id, &topic.name, &topic.schema))?;
        self.refs.insert(topic.name.clone(), id);
        self.topics.push(TopicEntry {
            name: topic.name.clone(),
            schema: topic.schema.clone(),
            next_seq: 1,
        });
        Ok(id)
    }

    fn write(&mut self, body: &[u8]) -> Result<(), JournalError> {
        let rec = frame(body);
        self.file
            .write_all(&rec)
            .map_err(|cause| JournalError::Io {
                path: self.path.display().to_string(),
                cause,
            })?;
        self.len += rec.len() as u64;
        self.dirty = true;
        Ok(())
    }

    /// Syncs by the fsync policy; `idle` syncs a batch policy's pending writes now.
    pub fn sync(&mut self, idle: bool) {
        let due = match self.fsync {
            Fsync::Always => true,
            Fsync::Batch => idle || self.synced_at.elapsed() >= BATCH_SYNC,
            Fsync::Never => false,
        };
        if due && self.dirty {
            if self.fsync == Fsync::Batch && self.syncer.is_none() {
                self.syncer = Syncer::start(&self.file, &self.path)
                    .map_err(|e| {
                        tracing::warn!(
                            "durable outbox {}: no sync thread ({e}); syncing inline",
                            self.path.display()
                        )
                    })
                    .ok();
            }
            match &self.syncer {
                Some(s) => s.request(),
                None => {
                    if let Err(e) = self.file.sync_data() {
                        tracing::warn!("durable outbox {}: sync failed: {e}", self.path.display());
                    }
                }
            }
            self.dirty = false;
            self.synced_at = Instant::now();
        }
    }

    /// Writes the live state to a new file and swaps it in.
    fn rewrite(&mut self) -> Result<(), StoreError> {
        let tmp = self.path.with_extension("log.tmp");
        let mut out = Vec::new();
        let mut h = vec![HEADER];
        h.extend_from_slice(MAGIC);
        h.extend_from_slice(&VERSION.to_le_bytes());
        h.extend_from_slice(&self.epoch.to_le_bytes());
        out.extend_from_slice(&frame(&h));
        for (id, t) in self.topics.iter().enumerate() {
            out.extend_from_slice(&frame(&topic_body(id as u32, &t.name, &t.schema)));
            let mut f = vec![FLOOR];
            f.extend_from_slice(&(id as u32).to_le_bytes());
            f.extend_from_slice(&t.next_seq.to_le_bytes());
            out.extend_from_slice(&frame(&f));
        }
        for l in &self.live {
            out.extend_from_slice(&frame(&message_body(l)));
        }
        let write = || -> std::io::Result<File> {
            let mut f = File::create(&tmp)?;
            f.write_all(&out)?;
            f.sync_all()?;
            std::fs::rename(&tmp, &self.path)?;
            if let Some(dir) = self.path.parent() {
                File::open(dir)?.sync_all()?;
            }
            let f = OpenOptions::new()
                .read(true)
                .append(true)
                .open(&self.path)?;
            f.try_lock().map_err(std::io::Error::other)?;
            Ok(f)
        };
        self.file = write().map_err(|e| io_err(&self.path, e))?;
        // The sync thread holds the old file: the next sync starts one for the new file.
        self.syncer = None;
        self.len = out.len() as u64;
        self.dirty = false;
        Ok(())
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
        let topic_ref = self.topic_ref(topic)?;
        let live = Live {
            topic: topic_ref,
            seq,
            stamp_ns,
            encoding: payload.encoding,
            payload: payload.bytes.clone(),
        };
        self.write(&message_body(&live))?;
        self.sync(false);
        let t = &mut self.topics[topic_ref as usize];
        t.next_seq = t.next_seq.max(seq + 1);
        self.live_bytes += size;
        self.live.push_back(live);
        Ok(())
    }

    fn confirm(&mut self, topic: &TopicName, seq: u64) {
        let Some(&r) = self.refs.get(topic) else {
            return;
        };
        let mut freed = 0;
        self.live.retain(|l| {
            let done = l.topic == r && l.seq <= seq;
            if done {
                freed += l.payload.len() as u64;
            }
            !done
        });
        self.live_bytes -= freed;
        let mut b = vec![CONFIRM];
        b.extend_from_slice(&r.to_le_bytes());
        b.extend_from_slice(&seq.to_le_bytes());
        if let Err(e) = self.write(&b) {
            // Not fatal: without the record, a restart resends what the hub already has
            // and the hub recognises it by its sequence number.
            tracing::warn!("{e}");
        }
        if self.len > COMPACT_MIN
            && self.len > 4 * self.live_bytes.max(1 << 20)
            && let Err(e) = self.rewrite()
        {
            tracing::warn!("compacting the durable outbox: {e}");
        }
    }

    fn tick(&mut self) {
        self.sync(true);
    }
}

fn topic_body(id: u32, name: &TopicName, schema: &Schema) -> Vec<u8> {
    let mut b = vec![TOPIC];
    b.extend_from_slice(&id.to_le_bytes());
    for s in [
        name.as_str(),
        &schema.type_name,
        &schema.encoding,
        &schema.text,
    ] {
        put_str(&mut b, s);
    }
    b
}

fn message_body(l: &Live) -> Vec<u8> {
    let mut b = Vec::with_capacity(30 + l.payload.len());
    b.push(MESSAGE);
    b.extend_from_slice(&l.topic.to_le_bytes());
    b.extend_from_slice(&l.seq.to_le_bytes());
    b.extend_from_slice(&l.stamp_ns.to_le_bytes());
    b.push(l.encoding as u8);
    b.extend_from_slice(&l.payload);
    b
}

fn put_str(b: &mut Vec<u8>, s: &str) {
    b.extend_from_slice(&(s.len() as u32).to_le_bytes());
    b.extend_from_slice(s.as_bytes());
}

fn frame(body: &[u8]) -> Vec<u8> {
    let mut rec = Vec::with_capacity(8 + body.len());
    rec.extend_from_slice(&(body.len() as u32).to_le_bytes());
    rec.extend_from_slice(&crc32fast::hash(body).to_le_bytes());
    rec.extend_from_slice(body);
    rec
}

/// The intact record at `pos`: its body and where the next starts.
fn record_at(data: &[u8], pos: usize) -> Option<(&[u8], usize)> {
    let head = data.get(pos..pos + 8)?;
    let len = u32::from_le_bytes(head[..4].try_into().ok()?);
    let crc = u32::from_le_bytes(head[4..].try_into().ok()?);
    if len > MAX_RECORD {
        return None;
    }
    let body = data.get(pos + 8..pos + 8 + len as usize)?;
    (crc32fast::hash(body) == crc).then_some((body, pos + 8 + len as usize))
}

struct Cursor<'a>(&'a [u8]);

impl<'a> Cursor<'a> {
    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        if self.0.len() < n {
            return None;
        }
        let (a, b) = self.0.split_at(n);
        self.0 = b;
        Some(a)
    }
    fn u8(&mut self) -> Option<u8> {
        self.take(1).map(|b| b[0])
    }
    fn u32(&mut self) -> Option<u32> {
        self.take(4)
            .map(|b| u32::from_le_bytes(b.try_into().unwrap_or([0; 4])))
    }
    fn u64(&mut self) -> Option<u64> {
        self.take(8)
            .map(|b| u64::from_le_bytes(b.try_into().unwrap_or([0; 8])))
    }
    fn str(&mut self) -> Option<String> {
        let n = self.u32()? as usize;
        String::from_utf8(self.take(n)?.to_vec()).ok()
    }
}

#[cfg(test)]
#[path = "outbox_store_tests.rs"]
mod tests;
