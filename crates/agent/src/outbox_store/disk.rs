//! The outbox file as the journal thread keeps it: the record format, reading it back,
//! appending, syncing by the policy, and compaction.
//!
//! Everything here runs on the journal's own thread (or at start, before the agent runs):
//! it is the part of the durable outbox that waits on the disk.

use std::collections::{HashMap, VecDeque};
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Schema};
use fleetlink_relay::TopicName;

use super::{BATCH_SYNC, Fsync, StoreError, io_err, slow_disk};

pub(super) const FILE: &str = "outbox.log";
const MAGIC: &[u8; 8] = b"FLKOUTBX";
const VERSION: u32 = 1;
/// A record larger than this is corruption, not a message (the link carries ≤ 64 MiB).
const MAX_RECORD: u32 = 80 << 20;
/// Compact when the file exceeds this and is mostly confirmed records.
pub(super) const COMPACT_MIN: u64 = 4 << 20;

const HEADER: u8 = 0x01;
const TOPIC: u8 = 0x02;
const MESSAGE: u8 = 0x03;
const CONFIRM: u8 = 0x04;
const FLOOR: u8 = 0x05;

pub(super) struct TopicEntry {
    pub name: TopicName,
    pub schema: Schema,
    pub next_seq: u64,
}

/// An unconfirmed message. Its payload is the buffer the outbox queues, not a copy.
pub(super) struct Live {
    pub topic: u32,
    pub seq: u64,
    pub stamp_ns: u64,
    pub encoding: Encoding,
    pub payload: Bytes,
}

/// What the agent's thread hands the journal thread, in the order it happened.
pub(super) enum Op {
    Topic {
        id: u32,
        name: TopicName,
        schema: Schema,
    },
    Message(Live),
    Confirm {
        topic: u32,
        seq: u64,
    },
    /// About once a second: sync what a batch policy left pending.
    Tick,
    /// Answer once everything before it is written.
    Barrier(std::sync::mpsc::SyncSender<()>),
}

/// The file and what is live in it.
pub(super) struct Disk {
    pub path: PathBuf,
    file: File,
    len: u64,
    pub epoch: u64,
    pub topics: Vec<TopicEntry>,
    pub live: VecDeque<Live>,
    live_bytes: u64,
    fsync: Fsync,
    synced_at: Instant,
    dirty: bool,
}

impl Disk {
    /// The opened (and locked) file at `path`, with what it holds read back.
    pub fn open(path: PathBuf, mut file: File, fsync: Fsync) -> Result<Disk, StoreError> {
        use std::io::Read;
        let mut data = Vec::new();
        file.read_to_end(&mut data).map_err(|e| io_err(&path, e))?;
        let mut d = Disk {
            path,
            file,
            len: 0,
            epoch: 0,
            topics: Vec::new(),
            live: VecDeque::new(),
            live_bytes: 0,
            fsync,
            synced_at: Instant::now(),
            dirty: false,
        };
        let good = d.replay(&data)?;
        if good < data.len() as u64 {
            tracing::warn!(
                "durable outbox {}: dropped a torn record at byte {good} of {} (the agent \
                 stopped while writing it)",
                d.path.display(),
                data.len()
            );
            d.file.set_len(good).map_err(|e| io_err(&d.path, e))?;
        }
        d.len = good;
        if d.epoch == 0 {
            // A new outbox: a new numbering the hub has not seen.
            d.epoch = fastrand::u64(1..);
            d.rewrite()?;
        }
        Ok(d)
    }

    pub fn live_bytes(&self) -> u64 {
        self.live_bytes
    }

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

    /// Applies one operation of the agent's thread to the file.
    pub fn apply(&mut self, op: Op) -> std::io::Result<()> {
        match op {
            Op::Topic { id, name, schema } => {
                self.write(&topic_body(id, &name, &schema))?;
                self.topics.push(TopicEntry {
                    name,
                    schema,
                    next_seq: 1,
                });
            }
            Op::Message(live) => {
                self.write(&message_body(&live))?;
                if let Some(t) = self.topics.get_mut(live.topic as usize) {
                    t.next_seq = t.next_seq.max(live.seq + 1);
                }
                self.live_bytes += live.payload.len() as u64;
                self.live.push_back(live);
                self.sync(false);
            }
            Op::Confirm { topic, seq } => {
                let mut freed = 0;
                self.live.retain(|l| {
                    let done = l.topic == topic && l.seq <= seq;
                    if done {
                        freed += l.payload.len() as u64;
                    }
                    !done
                });
                self.live_bytes -= freed;
                let mut b = vec![CONFIRM];
                b.extend_from_slice(&topic.to_le_bytes());
                b.extend_from_slice(&seq.to_le_bytes());
                // Not fatal if it fails: without the record, a restart resends what the hub
                // already has and the hub recognises it by its sequence number.
                self.write(&b)?;
                if self.len > COMPACT_MIN && self.len > 4 * self.live_bytes.max(1 << 20) {
                    self.rewrite().map_err(std::io::Error::other)?;
                }
            }
            Op::Tick => self.sync(true),
            Op::Barrier(done) => {
                let _ = done.send(());
            }
        }
        Ok(())
    }

    fn write(&mut self, body: &[u8]) -> std::io::Result<()> {
        let rec = frame(body);
        slow_disk::wait(rec.len());
        self.file.write_all(&rec)?;
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
            if let Err(e) = self.file.sync_data() {
                tracing::warn!("durable outbox {}: sync failed: {e}", self.path.display());
            }
            self.dirty = false;
            self.synced_at = Instant::now();
        }
    }

    /// Whether a batch policy has writes waiting for their sync.
    pub fn sync_pending(&self) -> bool {
        self.dirty && self.fsync == Fsync::Batch
    }

    /// Writes the live state to a new file and swaps it in.
    fn rewrite(&mut self) -> Result<(), StoreError> {
        let tmp = self.path.with_extension("log.tmp");
        let write = || -> std::io::Result<(File, u64)> {
            let mut out = std::io::BufWriter::with_capacity(1 << 20, File::create(&tmp)?);
            let mut len = 0u64;
            let mut put = |body: &[u8], out: &mut std::io::BufWriter<File>| {
                let rec = frame(body);
                slow_disk::wait(rec.len());
                len += rec.len() as u64;
                out.write_all(&rec)
            };
            let mut h = vec![HEADER];
            h.extend_from_slice(MAGIC);
            h.extend_from_slice(&VERSION.to_le_bytes());
            h.extend_from_slice(&self.epoch.to_le_bytes());
            put(&h, &mut out)?;
            for (id, t) in self.topics.iter().enumerate() {
                put(&topic_body(id as u32, &t.name, &t.schema), &mut out)?;
                let mut f = vec![FLOOR];
                f.extend_from_slice(&(id as u32).to_le_bytes());
                f.extend_from_slice(&t.next_seq.to_le_bytes());
                put(&f, &mut out)?;
            }
            for l in &self.live {
                put(&message_body(l), &mut out)?;
            }
            let f = out.into_inner().map_err(|e| e.into_error())?;
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
            Ok((f, len))
        };
        let (file, len) = write().map_err(|e| io_err(&self.path, e))?;
        self.file = file;
        self.len = len;
        self.dirty = false;
        Ok(())
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

pub(super) fn frame(body: &[u8]) -> Vec<u8> {
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

/// The path of the outbox file in `dir`.
pub(super) fn file_in(dir: &Path) -> PathBuf {
    dir.join(FILE)
}
