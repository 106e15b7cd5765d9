//! One running recording: a router subscriber with its own bounded queue, drained by a
//! thread of its own that writes MCAP.
//!
//! The recorder never slows the relay: the router gives it messages as it gives every
//! subscriber, into a queue per topic of `spec.queue` messages, and when the disk falls
//! behind the oldest are dropped and counted (the recording's `dropped`, also written into
//! each file's metadata). Writing and compressing happen on the recorder's thread, not on
//! the runtime the sessions run on. What it records is what its starter may read: the
//! access rules are asked for every message, as for a live subscriber.

use std::path::PathBuf;
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_relay::gate::{Gate, Op};
use fleetlink_relay::outbox::Taken;
use fleetlink_relay::router::{ClientKind, SubOptions, Target};
use fleetlink_relay::{ClientId, Outbox, Router};
use serde::{Deserialize, Serialize};
use tokio_util::sync::CancellationToken;

use crate::blackbox::SliceRange;
use crate::file::{FileFigures, McapFile, RecordingNote};
use crate::spec::RecordSpec;

/// Messages (and about this many bytes) the recorder takes from its queue at a time.
const BATCH: usize = 512;
const BATCH_BYTES: usize = 16 << 20;
/// How often a growing recording's figures are written to its `recording.json`.
const PERSIST_EVERY: Duration = Duration::from_secs(5);

/// Where a recording is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum State {
    Recording,
    Stopped,
    /// The hub stopped (or died) while it was recording: its last file may lack the
    /// summary (readers read it linearly up to its last chunk).
    Interrupted,
    /// Writing failed (a full disk, say); `error` says why.
    Failed,
    /// A slice of a robot's black box on its way (`blackbox` says how far).
    Fetching,
}

/// A recording as the API shows it and `recording.json` keeps it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordingInfo {
    pub id: String,
    pub spec: RecordSpec,
    pub state: State,
    /// Who started it (the principal of the API caller).
    pub started_by: String,
    pub started_at_ms: u64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stopped_at_ms: Option<u64>,
    /// Messages written.
    pub messages: u64,
    /// Bytes of all its files.
    pub bytes: u64,
    /// Messages its queue dropped because the disk was behind.
    pub dropped: u64,
    /// Messages of matching topics its starter may not read (not recorded).
    pub refused: u64,
    /// Messages that could not be given in their channel's encoding (not recorded).
    pub unconvertible: u64,
    /// Finished files, then the one being written.
    pub files: Vec<FileFigures>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// Set for a slice fetched from a robot's black box.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub blackbox: Option<BlackBoxFetch>,
}

impl RecordingInfo {
    /// A recording (or fetch) that starts now, with nothing in it yet.
    pub fn new(
        id: String,
        spec: RecordSpec,
        state: State,
        started_by: String,
        started_at_ms: u64,
    ) -> RecordingInfo {
        RecordingInfo {
            id,
            spec,
            state,
            started_by,
            started_at_ms,
            stopped_at_ms: None,
            messages: 0,
            bytes: 0,
            dropped: 0,
            refused: 0,
            unconvertible: 0,
            files: Vec::new(),
            error: None,
            blackbox: None,
        }
    }
}

/// A fetch as `recording.json` keeps it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BlackBoxFetch {
    pub robot: String,
    pub range: SliceRange,
    /// The slice's size once the robot has cut it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<u64>,
    /// Bytes of it at the hub.
    pub received: u64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sha256: Option<String>,
    /// Fetch calls made.
    pub calls: u64,
    /// Times pieces stopped coming and the rest was asked for again.
    pub resumed: u64,
    /// Messages of topics the requester may not read, cut out of the file.
    #[serde(default)]
    pub refused: u64,
    /// What the fetch waits for, while it waits (`robot1 is offline`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub waiting: Option<String>,
}

/// What the API and the recorder's thread share.
pub(crate) struct Shared {
    pub info: Mutex<RecordingInfo>,
    pub stop: CancellationToken,
}

impl Shared {
    pub fn info(&self) -> RecordingInfo {
        self.info.lock().unwrap_or_else(|p| p.into_inner()).clone()
    }

    pub(crate) fn update(&self, f: impl FnOnce(&mut RecordingInfo)) {
        f(&mut self.info.lock().unwrap_or_else(|p| p.into_inner()))
    }
}

/// What the recorder's thread needs.
pub(crate) struct Job {
    pub router: Arc<Router>,
    pub dir: PathBuf,
    pub hub_name: String,
    pub gate: Box<dyn Gate>,
    pub shared: Arc<Shared>,
    pub runtime: tokio::runtime::Handle,
    /// Called with the recording's figures whenever they should be kept.
    pub persist: Box<dyn Fn(&RecordingInfo) + Send>,
}

/// Subscribes the recorder and starts its thread. The subscription exists when this
/// returns: a message published after it is recorded.
pub(crate) fn start(job: Job) -> Result<std::thread::JoinHandle<()>, String> {
    let spec = job.shared.info().spec;
    let pattern = spec.check()?;
    let (client, outbox) = job.router.connect(
        ClientKind::Internal {
            role: "recorder".into(),
        },
        None,
    );
    let opts = SubOptions {
        queue_length: spec.queue as u32,
        ..SubOptions::default()
    };
    if let Err(e) = job.router.subscribe(client, Target::Pattern(pattern), opts) {
        job.router.disconnect(client);
        return Err(format!("topics: {e}"));
    }
    let id = job.shared.info().id;
    std::thread::Builder::new()
        .name(format!("recorder {id}"))
        .spawn(move || run(job, client, outbox))
        .map_err(|e| format!("cannot start the recorder's thread: {e}"))
}

fn run(mut job: Job, client: ClientId, outbox: Arc<Outbox>) {
    let router = job.router.clone();
    let info = job.shared.info();
    let spec = info.spec.clone();
    let label = spec.name.clone().unwrap_or_else(|| info.id.clone());
    let started = Instant::now();
    let end_at = spec.duration_s.map(|s| started + Duration::from_secs(s));
    let split_every = spec.split_duration_s.map(Duration::from_secs);
    let mut items: Vec<Taken> = Vec::new();
    let mut file: Option<(McapFile, Instant, u64)> = None;
    let mut index = info.files.len();
    let mut last_persist = Instant::now();
    let mut failure: Option<String> = None;
    let mut refused_total = 0u64;
    let mut unconvertible_done = 0u64;

    'outer: loop {
        let now = Instant::now();
        if job.shared.stop.is_cancelled() || end_at.is_some_and(|e| now >= e) {
            break;
        }
        // A file whose time is up is closed even when nothing arrives.
        if let (Some(every), Some((_, opened, _))) = (split_every, &file)
            && now >= *opened + every
        {
            let (f, _, d0) = file.take().expect("open");
            if let Err(e) = close(&job, f, d0, &outbox, &mut unconvertible_done) {
                failure = Some(e);
                break;
            }
        }
        let wake_at = outbox.take_into(&mut items, BATCH, BATCH_BYTES, now);
        if items.is_empty() {
            let deadline = [
                wake_at,
                end_at,
                split_every.zip(file.as_ref()).map(|(e, f)| f.1 + e),
                Some(last_persist + PERSIST_EVERY),
            ]
            .into_iter()
            .flatten()
            .min();
            wait(&job.runtime, &outbox, &job.shared.stop, None, deadline);
        }
        let tc = router.transcoder();
        for (_, _, msg) in items.drain(..) {
            if !job
                .gate
                .allows_topic(msg.topic.id.0, msg.topic.name.as_str(), Op::Subscribe)
            {
                refused_total += 1;
                continue;
            }
            if file.is_none() {
                index += 1;
                let name = format!("{label}_{index:03}.mcap");
                match McapFile::create(
                    &job.dir,
                    &name,
                    McapFile::profile_for(&msg, tc),
                    spec.compression,
                ) {
                    Ok(f) => {
                        job.shared.update(|i| i.files.push(f.figures.clone()));
                        file = Some((f, Instant::now(), outbox.dropped.load(Relaxed)));
                    }
                    Err(e) => {
                        failure = Some(format!("creating {}: {e}", job.dir.join(name).display()));
                        break 'outer;
                    }
                }
            }
            let (f, _, _) = file.as_mut().expect("open");
            if let Err(e) = f.write(&msg, tc) {
                failure = Some(format!("writing {}: {e}", f.path().display()));
                break 'outer;
            }
        }
        let dropped = outbox.dropped.load(Relaxed);
        job.shared.update(|i| {
            i.dropped = dropped;
            i.refused = refused_total;
            if let Some((f, _, _)) = &file {
                i.unconvertible = unconvertible_done + f.unconvertible;
                if let Some(last) = i.files.last_mut() {
                    *last = f.figures.clone();
                }
            }
            i.messages = i.files.iter().map(|f| f.messages).sum();
            i.bytes = i.files.iter().map(|f| f.bytes).sum();
        });
        if let Some(limit) = spec.split_size_bytes
            && file
                .as_ref()
                .is_some_and(|(f, _, _)| f.writer_len() >= limit)
        {
            let (f, _, d0) = file.take().expect("open");
            if let Err(e) = close(&job, f, d0, &outbox, &mut unconvertible_done) {
                failure = Some(e);
                break;
            }
        }
        if last_persist.elapsed() >= PERSIST_EVERY {
            last_persist = Instant::now();
            (job.persist)(&job.shared.info());
        }
    }
    // Nothing more enters the queue; what is in it is the recording's tail.
    router.disconnect(client);
    if failure.is_none()
        && let Err(e) = write_tail(&mut job, &outbox, &mut items, &mut file, &mut refused_total)
    {
        failure = Some(e);
    }
    if let Some((f, _, d0)) = file.take()
        && let Err(e) = close(&job, f, d0, &outbox, &mut unconvertible_done)
    {
        failure.get_or_insert(e);
    }
    conclude(&job, &outbox, refused_total, unconvertible_done, failure);
}

/// Writes what is left in the queue once the recorder has left the router (the
/// recording's tail) into the open file, if there is one; stops at the first failure.
fn write_tail(
    job: &mut Job,
    outbox: &Outbox,
    items: &mut Vec<Taken>,
    file: &mut Option<(McapFile, Instant, u64)>,
    refused_total: &mut u64,
) -> Result<(), String> {
    let router = job.router.clone();
    let tc = router.transcoder();
    outbox.take_into(items, usize::MAX, usize::MAX, Instant::now());
    for (_, _, msg) in items.drain(..) {
        if !job
            .gate
            .allows_topic(msg.topic.id.0, msg.topic.name.as_str(), Op::Subscribe)
        {
            *refused_total += 1;
            continue;
        }
        if let Some((f, _, _)) = file.as_mut()
            && let Err(e) = f.write(&msg, tc)
        {
            return Err(format!("writing {}: {e}", f.path().display()));
        }
    }
    Ok(())
}

/// The recording's final figures and state (`failure`: why it failed), kept.
fn conclude(
    job: &Job,
    outbox: &Outbox,
    refused_total: u64,
    unconvertible_done: u64,
    failure: Option<String>,
) {
    let dropped = outbox.dropped.load(Relaxed);
    job.shared.update(|i| {
        i.dropped = dropped;
        i.refused = refused_total;
        i.unconvertible = unconvertible_done;
        i.messages = i.files.iter().map(|f| f.messages).sum();
        i.bytes = i.files.iter().map(|f| f.bytes).sum();
        i.stopped_at_ms = Some(fleetlink_relay::unix_nanos() / 1_000_000);
        match failure {
            Some(e) => {
                tracing::error!(recording = %i.id, "recording failed: {e}");
                i.state = State::Failed;
                i.error = Some(e);
            }
            None => i.state = State::Stopped,
        }
    });
    (job.persist)(&job.shared.info());
}

/// Waits on `runtime`, from a thread of its own, until the outbox may have something,
/// `stop` or `wake` fires, or `deadline` passes.
pub(crate) fn wait(
    runtime: &tokio::runtime::Handle,
    outbox: &Outbox,
    stop: &CancellationToken,
    wake: Option<&tokio::sync::Notify>,
    deadline: Option<Instant>,
) {
    runtime.block_on(async {
        let sleep = async {
            match deadline {
                Some(d) => tokio::time::sleep_until(d.into()).await,
                None => std::future::pending().await,
            }
        };
        let woken = async {
            match wake {
                Some(w) => w.notified().await,
                None => std::future::pending().await,
            }
        };
        tokio::select! {
            _ = outbox.ready() => {}
            _ = stop.cancelled() => {}
            _ = woken => {}
            _ = sleep => {}
        }
    });
}

/// Finishes a file with the recording's figures in its metadata.
fn close(
    job: &Job,
    f: McapFile,
    dropped_before: u64,
    outbox: &Outbox,
    unconvertible_done: &mut u64,
) -> Result<(), String> {
    let info = job.shared.info();
    let dropped_total = outbox.dropped.load(Relaxed);
    let mut note = RecordingNote::default();
    let mut put = |k: &str, v: String| {
        note.fields.insert(k.to_owned(), v);
    };
    put("recording_id", info.id.clone());
    put("hub", job.hub_name.clone());
    put("topics", info.spec.topics.join(" "));
    put("started_by", info.started_by.clone());
    put("started_at_ms", info.started_at_ms.to_string());
    put("file_index", info.files.len().to_string());
    put("dropped", (dropped_total - dropped_before).to_string());
    put("dropped_total", dropped_total.to_string());
    put("refused_total", info.refused.to_string());
    put("unconvertible", f.unconvertible.to_string());
    put("queue_per_topic", info.spec.queue.to_string());
    let path = f.path().to_owned();
    *unconvertible_done += f.unconvertible;
    let mut figures = f
        .finish(&note)
        .map_err(|e| format!("finishing {}: {e}", path.display()))?;
    figures.dropped = dropped_total - dropped_before;
    job.shared.update(|i| {
        if let Some(last) = i.files.last_mut() {
            *last = figures;
        }
        i.bytes = i.files.iter().map(|f| f.bytes).sum();
    });
    (job.persist)(&job.shared.info());
    Ok(())
}
