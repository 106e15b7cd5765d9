//! The robot's ring buffer: chosen local topics written to MCAP segments on disk, the
//! oldest segments deleted when the ring would pass its size.
//!
//! Like a hub recording, the ring is a subscriber of the (agent's) router with its own
//! bounded queue per topic, drained by a thread of its own; subscribing makes the ROS
//! adapters read those topics whether or not anything is sent. A segment is closed when it
//! reaches an eighth of the ring (so deleting one frees an eighth) or after a minute; its
//! chunks are closed every second, so a robot that loses power loses at most the last
//! second. Segments are named by the receive time of their first message
//! (`bb-<unix ns>.mcap`): the names sort in time order, and the segments of earlier runs
//! are found again at start.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_relay::outbox::Taken;
use fleetlink_relay::router::{ClientKind, SubOptions, Target};
use fleetlink_relay::{ClientId, Outbox, Router};
use tokio::sync::{Notify, oneshot};
use tokio_util::sync::CancellationToken;

use super::DATA_TOPIC;
use crate::file::{McapFile, RecordingNote};
use crate::spec::Compression;

/// A segment is closed after this long even when small.
const SEGMENT_AGE: Duration = Duration::from_secs(60);
/// The open chunk is written out this often.
const CHUNK_EVERY: Duration = Duration::from_secs(1);
/// Smallest and largest segment.
const MIN_SEGMENT: u64 = 1 << 20;
const MAX_SEGMENT: u64 = 64 << 20;
/// Smallest ring.
pub const MIN_RING_BYTES: u64 = 8 << 20;
/// Per-topic queue of the ring's subscription.
const QUEUE: u32 = 64;

/// What the ring keeps and where.
#[derive(Debug, Clone, PartialEq)]
pub struct RingOptions {
    /// The black box's directory: segments go to `ring/`, slices to `slices/`.
    pub dir: PathBuf,
    /// Most bytes of segments kept.
    pub max_bytes: u64,
    /// Whole-name patterns of local topics.
    pub topics: Vec<String>,
    pub compression: Compression,
}

/// One segment file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Segment {
    pub path: PathBuf,
    /// Receive time of its first message, Unix nanoseconds.
    pub start_ns: u64,
    pub bytes: u64,
}

/// The ring's figures (for diagnostics and tests).
#[derive(Debug, Default)]
pub struct RingStats {
    pub messages: AtomicU64,
    /// Messages its queue dropped because the disk was behind.
    pub dropped: AtomicU64,
    /// Segments deleted to keep the ring within its size.
    pub deleted: AtomicU64,
}

struct Shared {
    /// Finished segments, oldest first.
    segments: Mutex<Vec<Segment>>,
    /// Waiting for the open segment to be finished.
    rotations: Mutex<Vec<oneshot::Sender<()>>>,
    wake: Notify,
    stop: CancellationToken,
    stats: RingStats,
}

pub struct Ring {
    shared: Arc<Shared>,
    thread: Mutex<Option<std::thread::JoinHandle<()>>>,
    dir: PathBuf,
}

impl Ring {
    /// Subscribes the ring to `opts.topics` on `router` and starts its thread, which
    /// waits for its queue on `runtime`.
    pub fn start(
        router: Arc<Router>,
        opts: RingOptions,
        runtime: tokio::runtime::Handle,
    ) -> Result<Ring, String> {
        let pattern = super::SliceRange {
            topics: opts.topics.clone(),
            ..super::SliceRange::default()
        }
        .pattern()?
        .ok_or("topics: name at least one topic for the black box to keep")?;
        let ring_dir = opts.dir.join("ring");
        std::fs::create_dir_all(&ring_dir)
            .map_err(|e| format!("dir: cannot create {}: {e}", ring_dir.display()))?;
        let segments = existing(&ring_dir)
            .map_err(|e| format!("dir: cannot read {}: {e}", ring_dir.display()))?;
        let shared = Arc::new(Shared {
            segments: Mutex::new(segments),
            rotations: Mutex::new(Vec::new()),
            wake: Notify::new(),
            stop: CancellationToken::new(),
            stats: RingStats::default(),
        });
        prune(&shared, opts.max_bytes, 0);
        let (client, outbox) = router.connect(
            ClientKind::Internal {
                role: "blackbox".into(),
            },
            None,
        );
        let sub = SubOptions {
            queue_length: QUEUE,
            ..SubOptions::default()
        };
        if let Err(e) = router.subscribe(client, Target::Pattern(pattern), sub) {
            router.disconnect(client);
            return Err(format!("topics: {e}"));
        }
        let job = Job {
            router,
            client,
            outbox,
            dir: ring_dir,
            segment_bytes: (opts.max_bytes / 8).clamp(MIN_SEGMENT, MAX_SEGMENT),
            max_bytes: opts.max_bytes,
            compression: opts.compression,
            shared: shared.clone(),
            runtime,
        };
        let thread = std::thread::Builder::new()
            .name("blackbox".into())
            .spawn(move || job.run())
            .map_err(|e| format!("cannot start the black box's thread: {e}"))?;
        Ok(Ring {
            shared,
            thread: Mutex::new(Some(thread)),
            dir: opts.dir,
        })
    }

    /// The black box's directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    pub fn stats(&self) -> &RingStats {
        &self.shared.stats
    }

    /// Finishes the open segment, so that everything received until now is in finished
    /// segments; then returns them, oldest first.
    pub async fn rotate(&self) -> Vec<Segment> {
        let (tx, rx) = oneshot::channel();
        self.shared
            .rotations
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .push(tx);
        self.shared.wake.notify_one();
        // An error means the thread has ended, which finished the segment too.
        let _ = rx.await;
        self.segments()
    }

    /// The finished segments, oldest first.
    pub fn segments(&self) -> Vec<Segment> {
        self.shared
            .segments
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .clone()
    }

    /// Stops the ring and waits until its open segment is finished.
    pub async fn stop(&self) {
        self.shared.stop.cancel();
        let thread = self.thread.lock().unwrap_or_else(|p| p.into_inner()).take();
        if let Some(t) = thread {
            let _ = tokio::task::spawn_blocking(move || t.join()).await;
        }
    }
}

impl Drop for Ring {
    fn drop(&mut self) {
        self.shared.stop.cancel();
    }
}

/// Segments left by earlier runs, oldest first.
fn existing(dir: &Path) -> std::io::Result<Vec<Segment>> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir)? {
        let e = e?;
        let name = e.file_name();
        let Some(start_ns) = name
            .to_str()
            .and_then(|n| n.strip_prefix("bb-"))
            .and_then(|n| n.strip_suffix(".mcap"))
            .and_then(|n| n.parse::<u64>().ok())
        else {
            continue;
        };
        out.push(Segment {
            path: e.path(),
            start_ns,
            bytes: e.metadata()?.len(),
        });
    }
    out.sort_by_key(|s| s.start_ns);
    Ok(out)
}

/// Deletes the oldest segments while the ring (with `open` bytes of the open segment) is
/// over `max_bytes`.
fn prune(shared: &Shared, max_bytes: u64, open: u64) {
    let mut segs = shared.segments.lock().unwrap_or_else(|p| p.into_inner());
    let mut total: u64 = segs.iter().map(|s| s.bytes).sum::<u64>() + open;
    while total > max_bytes && !segs.is_empty() {
        let old = segs.remove(0);
        total -= old.bytes;
        match std::fs::remove_file(&old.path) {
            Ok(()) => {
                shared.stats.deleted.fetch_add(1, Relaxed);
            }
            Err(e) => tracing::warn!("black box: deleting {}: {e}", old.path.display()),
        }
    }
}

struct Job {
    router: Arc<Router>,
    client: ClientId,
    outbox: Arc<Outbox>,
    dir: PathBuf,
    segment_bytes: u64,
    max_bytes: u64,
    compression: Compression,
    shared: Arc<Shared>,
    runtime: tokio::runtime::Handle,
}

/// The segment being written.
struct Open {
    file: McapFile,
    start_ns: u64,
    opened: Instant,
    chunk_since: Option<Instant>,
}

impl Job {
    fn run(self) {
        let mut items: Vec<Taken> = Vec::new();
        let mut open: Option<Open> = None;
        loop {
            if self.shared.stop.is_cancelled() {
                break;
            }
            let waiting: Vec<_> = std::mem::take(
                &mut *self
                    .shared
                    .rotations
                    .lock()
                    .unwrap_or_else(|p| p.into_inner()),
            );
            if !waiting.is_empty() {
                // What was queued before the request belongs in the segment too.
                self.write(&mut items, &mut open, Instant::now());
                self.finish(open.take());
                for w in waiting {
                    let _ = w.send(());
                }
            }
            let now = Instant::now();
            if let Some(o) = &mut open {
                if o.opened.elapsed() >= SEGMENT_AGE {
                    self.finish(open.take());
                } else if o.chunk_since.is_some_and(|t| now >= t + CHUNK_EVERY) {
                    o.chunk_since = None;
                    if let Err(e) = o.file.close_chunk() {
                        tracing::warn!("black box: writing {}: {e}", o.file.path().display());
                        open = None;
                    }
                }
            }
            if !self.write(&mut items, &mut open, now) {
                let deadline = open.as_ref().map(|o| {
                    let age = o.opened + SEGMENT_AGE;
                    o.chunk_since.map_or(age, |c| age.min(c + CHUNK_EVERY))
                });
                crate::recorder::wait(
                    &self.runtime,
                    &self.outbox,
                    &self.shared.stop,
                    Some(&self.shared.wake),
                    deadline,
                );
            }
            if let Some(o) = &open
                && o.file.writer_len() >= self.segment_bytes
            {
                self.finish(open.take());
            }
        }
        self.router.disconnect(self.client);
        self.write(&mut items, &mut open, Instant::now());
        self.finish(open.take());
        for w in std::mem::take(
            &mut *self
                .shared
                .rotations
                .lock()
                .unwrap_or_else(|p| p.into_inner()),
        ) {
            let _ = w.send(());
        }
    }

    /// Writes what the queue holds; false if it held nothing.
    fn write(&self, items: &mut Vec<Taken>, open: &mut Option<Open>, now: Instant) -> bool {
        self.outbox.take_into(items, 512, 16 << 20, now);
        if items.is_empty() {
            return false;
        }
        let tc = self.router.transcoder();
        for (_, _, msg) in items.drain(..) {
            if msg.topic.name.as_str() == DATA_TOPIC {
                continue;
            }
            if open.is_none() {
                let start_ns = msg.received_unix_ns();
                let name = format!("bb-{start_ns:020}.mcap");
                match McapFile::create(
                    &self.dir,
                    &name,
                    McapFile::profile_for(&msg, tc),
                    self.compression,
                ) {
                    Ok(file) => {
                        *open = Some(Open {
                            file,
                            start_ns,
                            opened: Instant::now(),
                            chunk_since: None,
                        })
                    }
                    Err(e) => {
                        tracing::warn!(
                            "black box: creating {}: {e}",
                            self.dir.join(&name).display()
                        );
                        continue;
                    }
                }
            }
            let o = open.as_mut().expect("opened above");
            match o.file.write(&msg, tc) {
                Ok(_) => {
                    self.shared.stats.messages.fetch_add(1, Relaxed);
                    o.chunk_since.get_or_insert(now);
                }
                Err(e) => {
                    tracing::warn!("black box: writing {}: {e}", o.file.path().display());
                    *open = None;
                }
            }
        }
        self.shared
            .stats
            .dropped
            .store(self.outbox.dropped.load(Relaxed), Relaxed);
        true
    }

    /// Finishes a segment, keeps it, and deletes the oldest ones past the ring's size.
    fn finish(&self, open: Option<Open>) {
        let Some(o) = open else { return };
        let path = o.file.path().to_owned();
        let mut note = RecordingNote::default();
        note.fields
            .insert("kind".into(), "fleetlink black box segment".into());
        match o.file.finish(&note) {
            Ok(fig) => {
                self.shared
                    .segments
                    .lock()
                    .unwrap_or_else(|p| p.into_inner())
                    .push(Segment {
                        path,
                        start_ns: o.start_ns,
                        bytes: fig.bytes,
                    });
                // Room for the next open segment.
                prune(
                    &self.shared,
                    self.max_bytes.saturating_sub(self.segment_bytes),
                    0,
                );
            }
            Err(e) => tracing::warn!("black box: finishing {}: {e}", path.display()),
        }
    }
}
