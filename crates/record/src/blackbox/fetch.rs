//! The hub's side of a black-box fetch: ask the robot for a slice, window by window,
//! append the pieces that arrive in order, ask again from where the file ends when they
//! stop, and keep the finished file (checked against the robot's SHA-256) as a
//! recording. Topics the requester may not read are cut out of the file before it is
//! kept.
//!
//! The task wakes only for what moves it: a call's answer, pieces in its outbox, a stop,
//! or the next of its deadlines (a retry, a stall, the give-up). Its disk work (the
//! slice's file, `recording.json`) runs on the blocking pool, so a slow disk holds this
//! fetch, not the hub's other tasks. Times are Tokio's, so tests can run it on a paused
//! clock.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use fleetlink_proto::Payload;
use fleetlink_relay::calls::{
    CallEvent, CallId, CallOptions, CallRefused, CallStatus, ChannelPeer, PeerMsg, PeerReceiver,
};
use fleetlink_relay::gate::{Gate, Op};
use fleetlink_relay::outbox::Taken;
use fleetlink_relay::router::{ClientKind, SubOptions, Target};
use fleetlink_relay::{ClientId, Outbox, Router, TopicName};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use tokio::time::Instant;

use super::{DATA_TOPIC, FETCH_SERVICE, FetchReply, FetchRequest, Piece, SliceRange};
use crate::file::FileFigures;
pub use crate::recorder::BlackBoxFetch;
use crate::recorder::{RecordingInfo, Shared, State};

/// Bytes asked for per call; the next window is asked for when half of this one is in.
pub const WINDOW: u64 = 1 << 20;
/// Pieces that stop coming for this long are asked for again from where the file ends.
pub const STALL: Duration = Duration::from_secs(8);
/// Wait between calls while the robot cannot be reached.
const RETRY: Duration = Duration::from_secs(1);
/// How long one call may take (the first one cuts the slice on the robot).
const CALL_TIMEOUT: Duration = Duration::from_secs(60);
/// A fetch that makes no progress for this long fails.
pub const GIVE_UP: Duration = Duration::from_secs(3600);
/// Figures are written to `recording.json` at most this often while bytes arrive.
const PERSIST_EVERY: Duration = Duration::from_secs(2);

/// A request for a slice of a robot's black box (`POST /api/v1/recordings/blackbox`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FetchSpec {
    /// The robot's name.
    pub robot: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub last_s: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from_ns: Option<u64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub to_ns: Option<u64>,
    /// Patterns of the robot's local topic names; empty: everything the ring keeps.
    #[serde(default)]
    pub topics: Vec<String>,
    /// A label for people; the file is named after it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
}

impl FetchSpec {
    pub fn range(&self) -> SliceRange {
        SliceRange {
            last_s: self.last_s,
            from_ns: self.from_ns,
            to_ns: self.to_ns,
            topics: self.topics.clone(),
        }
    }

    /// Checks the request; an error names the field.
    pub fn check(&self) -> Result<(), String> {
        check_robot(&self.robot)?;
        let range = self.range();
        range.resolve(fleetlink_relay::unix_nanos())?;
        range.pattern()?;
        if let Some(n) = &self.name {
            super::check_slice_id(n).map_err(|e| e.replacen("slice", "name", 1))?;
        }
        Ok(())
    }
}

/// A robot's name as it appears in topic names (`/robot1/...`).
fn check_robot(robot: &str) -> Result<(), String> {
    if robot.is_empty() || TopicName::parse(&format!("/{robot}")).is_err() || robot.contains('/') {
        return Err(format!(
            "robot: {:?} is not a robot's name (letters, digits and '_', as in /robot1/...)",
            robot.chars().take(80).collect::<String>()
        ));
    }
    Ok(())
}

/// Is this robot connected to the hub now?
pub type Online = Box<dyn Fn(&str) -> bool + Send + Sync>;

/// A robot that is online but offers no fetch service this long has no black box.
const NO_SERVICE: Duration = Duration::from_secs(10);

/// What a fetch's task needs.
pub(crate) struct FetchJob {
    pub router: Arc<Router>,
    pub shared: Arc<Shared>,
    pub dir: PathBuf,
    pub gate: Box<dyn Gate>,
    pub online: Online,
    /// Writes `recording.json`; shared so that it can run on the blocking pool.
    pub persist: Arc<dyn Fn(&RecordingInfo) + Send + Sync>,
}

/// Leaves the router when the fetch ends, however it ends.
struct Member(Arc<Router>, ClientId);

impl Drop for Member {
    fn drop(&mut self) {
        self.0.disconnect(self.1);
    }
}

pub(crate) async fn run(job: FetchJob) {
    let outcome = fetch(&job).await;
    job.shared.update(|i| {
        i.stopped_at_ms = Some(fleetlink_relay::unix_nanos() / 1_000_000);
        match outcome {
            Ok(()) => i.state = State::Stopped,
            Err(e) => {
                tracing::warn!(recording = %i.id, "black-box fetch failed: {e}");
                i.state = State::Failed;
                i.error = Some(e);
            }
        }
    });
    persist(&job).await;
}

/// Writes the fetch's `recording.json` as it stands now, off the runtime, and waits
/// until it is written (a later write must not be overtaken by an earlier one).
async fn persist(job: &FetchJob) {
    let (write, info) = (job.persist.clone(), job.shared.info());
    let id = info.id.clone();
    if let Err(e) = tokio::task::spawn_blocking(move || write(&info)).await {
        tracing::warn!(recording = %id, "keeping recording.json: {e}");
    }
}

/// Runs disk work on the blocking pool; an error says `what` was being done.
async fn on_disk<T: Send + 'static>(
    what: String,
    work: impl FnOnce() -> std::io::Result<T> + Send + 'static,
) -> Result<T, String> {
    match tokio::task::spawn_blocking(work).await {
        Ok(done) => done.map_err(|e| format!("{what}: {e}")),
        Err(e) => Err(format!("{what}: {e}")),
    }
}

struct Progress {
    file: std::fs::File,
    hash: Sha256,
    received: u64,
    last: Instant,
}

async fn fetch(job: &FetchJob) -> Result<(), String> {
    let info = job.shared.info();
    let id = info.id.clone();
    let bb = info.blackbox.clone().ok_or("not a black-box fetch")?;
    let robot = bb.robot.clone();
    let service =
        TopicName::parse(&format!("/{robot}{FETCH_SERVICE}")).map_err(|e| format!("robot: {e}"))?;
    let data =
        TopicName::parse(&format!("/{robot}{DATA_TOPIC}")).map_err(|e| format!("robot: {e}"))?;
    let (client, outbox, calls, _member) = join(&job.router, data)?;
    let label = info.spec.name.clone().unwrap_or_else(|| id.clone());
    let final_name = format!("{label}.mcap");
    let part = job.dir.join(format!("{final_name}.part"));
    let file = on_disk(format!("creating {}", part.display()), {
        let part = part.clone();
        move || std::fs::File::create(part)
    })
    .await?;
    let mut got = Progress {
        file,
        hash: Sha256::new(),
        received: 0,
        last: Instant::now(),
    };
    let mut asking = Asking::new(Instant::now());
    let mut last_persist = Instant::now();
    let mut items: Vec<Taken> = Vec::new();
    let slice = Slice {
        job,
        id: &id,
        robot: &robot,
        range: &bb.range,
        service: &service,
        client,
    };
    loop {
        if asking
            .reply
            .as_ref()
            .is_some_and(|r| got.received >= r.size)
        {
            break;
        }
        if job.shared.stop.is_cancelled() {
            return Err("stopped before the whole slice arrived".into());
        }
        let now = Instant::now();
        if got.last.elapsed() >= GIVE_UP {
            return Err(format!(
                "no part of the slice arrived from {robot} for {} minutes; giving up",
                GIVE_UP.as_secs() / 60
            ));
        }
        asking.ask(&slice, &got, now)?;
        let wake = asking.wake(&got);
        tokio::select! {
            m = calls.recv() => match m {
                Some(PeerMsg::Event(CallEvent::Done { id: call, status, payload, text }))
                    if asking.pending.is_some_and(|(p, _)| p == call) =>
                {
                    asking.answered(&slice, got.received, status, payload, &text)?;
                }
                Some(_) => {}
                None => return Err("the hub is stopping".into()),
            },
            _ = outbox.ready() => {
                got = write_pieces(&slice, &outbox, &mut items, &part, got).await?;
                if last_persist.elapsed() >= PERSIST_EVERY {
                    last_persist = Instant::now();
                    persist(job).await;
                }
            }
            _ = tokio::time::sleep_until(wake) => {}
            _ = job.shared.stop.cancelled() => {}
        }
    }
    keep(&slice, got, asking, &part, &final_name).await
}

/// Joins the router for one fetch: subscribed to the robot's pieces, attached to the
/// call table. The member leaves when dropped, on an error here too.
fn join(
    router: &Arc<Router>,
    data: TopicName,
) -> Result<(ClientId, Arc<Outbox>, PeerReceiver, Member), String> {
    let (client, outbox) = router.connect(
        ClientKind::Internal {
            role: "blackbox fetch".into(),
        },
        None,
    );
    let member = Member(router.clone(), client);
    let sub = SubOptions {
        queue_length: 256,
        ..SubOptions::default()
    };
    router
        .subscribe(client, Target::Exact(data), sub)
        .map_err(|e| e.to_string())?;
    let (peer, calls) = ChannelPeer::new();
    router.calls.attach(client, peer);
    Ok((client, outbox, calls, member))
}

/// The slice one fetch asks for and of whom, the same for every call.
struct Slice<'a> {
    job: &'a FetchJob,
    /// The recording's id, which is the slice's id on the robot.
    id: &'a str,
    robot: &'a str,
    range: &'a SliceRange,
    service: &'a TopicName,
    /// The fetch's member of the router.
    client: ClientId,
}

impl Slice<'_> {
    /// Shows what the fetch waits for (`None`: nothing) and how far the asking is.
    fn show(&self, f: impl FnOnce(&mut BlackBoxFetch)) {
        self.job.shared.update(|i| {
            if let Some(b) = &mut i.blackbox {
                f(b);
            }
        });
    }
}

/// Where the asking stands: what the robot said of the slice, how far it was asked for,
/// the call in flight, and when the next may leave.
struct Asking {
    reply: Option<FetchReply>,
    /// The end of the bytes asked for so far, and when the last call left.
    asked_to: u64,
    asked_at: Instant,
    /// The call in flight and the offset it asked from.
    pending: Option<(CallId, u64)>,
    retry_at: Option<Instant>,
    calls_made: u64,
    resumed: u64,
    /// Since when the robot has been online without the service.
    no_service: Option<Instant>,
}

impl Asking {
    fn new(now: Instant) -> Asking {
        Asking {
            reply: None,
            asked_to: 0,
            asked_at: now,
            pending: None,
            retry_at: None,
            calls_made: 0,
            resumed: 0,
            no_service: None,
        }
    }

    /// Makes the next call if one is due: the first, the next window once half of the
    /// last is in, or from where the file ends once pieces stopped coming.
    fn ask(&mut self, s: &Slice<'_>, got: &Progress, now: Instant) -> Result<(), String> {
        if self.pending.is_some() || self.retry_at.is_some_and(|at| now < at) {
            return Ok(());
        }
        let stalled = self.reply.is_some()
            && got.received < self.asked_to
            && now >= self.asked_at + STALL
            && now >= got.last + STALL;
        if stalled {
            self.asked_to = got.received;
            self.resumed += 1;
            tracing::info!(recording = %s.id, "black-box pieces stopped at byte {}; asking again", got.received);
        }
        let more = match &self.reply {
            None => true,
            Some(r) => self.asked_to < r.size && got.received + WINDOW / 2 >= self.asked_to,
        };
        if !more {
            return Ok(());
        }
        let req = FetchRequest {
            slice: s.id.to_owned(),
            range: s.range.clone(),
            offset: self.asked_to,
            window: WINDOW,
        };
        let body = serde_json::to_vec(&req).map_err(|e| e.to_string())?;
        let opts = CallOptions {
            timeout: Some(CALL_TIMEOUT),
            ..CallOptions::default()
        };
        self.calls_made += 1;
        self.asked_at = now;
        self.retry_at = None;
        match s
            .job
            .router
            .calls
            .call(s.client, s.service, Payload::json(body), opts)
        {
            Ok(call) => self.pending = Some((call, self.asked_to)),
            Err(refused) => self.refused(s, refused, now)?,
        }
        Ok(())
    }

    /// A call the table refused: the robot is away, or offers no black box (yet). Tried
    /// again after [`RETRY`]; a robot online without the service for [`NO_SERVICE`]
    /// has none.
    fn refused(&mut self, s: &Slice<'_>, refused: CallRefused, now: Instant) -> Result<(), String> {
        let robot = s.robot;
        tracing::debug!(recording = %s.id, "fetch call refused: {}", refused.text);
        let online = (s.job.online)(robot);
        if online && refused.status == CallStatus::NoProvider {
            let since = *self.no_service.get_or_insert(now);
            if now >= since + NO_SERVICE {
                return Err(format!(
                    "{robot} is online but keeps no black box (its agent has no \
                     blackbox: section)"
                ));
            }
        } else {
            self.no_service = None;
        }
        let why = if online {
            format!("{robot} does not offer its black box yet")
        } else {
            format!("{robot} is offline; the fetch goes on when it is back")
        };
        s.show(|b| b.waiting = Some(why));
        self.retry_at = Some(now + RETRY);
        Ok(())
    }

    /// When to look again with nothing else happening: a retry, a stall's deadline, the
    /// give-up.
    fn wake(&self, got: &Progress) -> Instant {
        let mut wake = got.last + GIVE_UP;
        if self.pending.is_none() {
            match self.retry_at {
                Some(t) => wake = wake.min(t),
                None if self.reply.is_some() && got.received < self.asked_to => {
                    wake = wake.min(self.asked_at.max(got.last) + STALL);
                }
                None => {}
            }
        }
        wake
    }

    /// The robot answered the call in flight (`received`: the bytes at the hub now).
    fn answered(
        &mut self,
        s: &Slice<'_>,
        received: u64,
        status: CallStatus,
        payload: Option<Payload>,
        text: &str,
    ) -> Result<(), String> {
        let robot = s.robot;
        let (_, offset) = self.pending.take().expect("matched by the caller");
        match status {
            CallStatus::Ok => {
                let r: FetchReply = payload
                    .as_ref()
                    .and_then(|p| serde_json::from_slice(&p.bytes).ok())
                    .ok_or_else(|| format!("{robot} answered the fetch with something that is not a slice's description"))?;
                self.asked_to = self.asked_to.max(offset.saturating_add(WINDOW)).min(r.size);
                self.reply = Some(r);
                self.no_service = None;
            }
            CallStatus::NoProvider
            | CallStatus::Timeout
            | CallStatus::Busy
            | CallStatus::Aborted => {
                // The robot is away or its link is: ask again from where the file ends.
                self.asked_to = received;
                self.retry_at = Some(Instant::now() + RETRY);
            }
            _ => return Err(format!("{robot}: {text}")),
        }
        let waiting = (status != CallStatus::Ok).then(|| format!("{robot}: {text}"));
        s.show(|b| {
            b.waiting = waiting;
            b.size = self.reply.as_ref().map(|r| r.size);
            b.sha256 = self.reply.as_ref().map(|r| r.sha256.clone());
            b.calls = self.calls_made;
            b.resumed = self.resumed;
        });
        Ok(())
    }
}

/// Appends the pieces in the outbox to the file (on the blocking pool) and shows the
/// bytes at the hub.
async fn write_pieces(
    s: &Slice<'_>,
    outbox: &Outbox,
    items: &mut Vec<Taken>,
    part: &Path,
    got: Progress,
) -> Result<Progress, String> {
    outbox.take_into(items, 256, 16 << 20, Instant::now().into_std());
    let pieces: Vec<Arc<fleetlink_relay::Message>> = items.drain(..).map(|(_, _, m)| m).collect();
    let mut writing = got;
    let slice = s.id.to_owned();
    let got = on_disk(format!("writing {}", part.display()), move || {
        for m in &pieces {
            accept(&m.payload, &slice, &mut writing)?;
        }
        Ok(writing)
    })
    .await?;
    s.job.shared.update(|i| {
        if let Some(b) = &mut i.blackbox {
            b.received = got.received;
        }
        i.bytes = got.received;
    });
    Ok(got)
}

/// The whole slice is in: checks it against the robot's SHA-256 and keeps what the
/// requester may read as the recording's file.
async fn keep(
    s: &Slice<'_>,
    got: Progress,
    asking: Asking,
    part: &Path,
    final_name: &str,
) -> Result<(), String> {
    let (job, id, robot) = (s.job, s.id, s.robot);
    let r = asking.reply.expect("the loop ends with a reply");
    let mut file = got.file;
    on_disk(format!("syncing {}", part.display()), move || {
        file.flush()?;
        file.sync_data()
    })
    .await?;
    let sha = super::hex(&got.hash.finalize());
    if sha != r.sha256 {
        return Err(format!(
            "the slice arrived whole ({} bytes) but its SHA-256 is {sha}, not the robot's {}",
            r.size, r.sha256
        ));
    }
    // Keep only what the requester may read (the robot's topics under /<robot>).
    let dest = job.dir.join(final_name);
    let gate = job.gate.fork();
    let prefix = format!("/{robot}");
    let (kept, refused) = tokio::task::spawn_blocking({
        let (part, r) = (part.to_owned(), r.clone());
        move || cut_readable(gate, &prefix, &part, &dest, &r)
    })
    .await
    .map_err(|e| e.to_string())??;
    let (calls_made, resumed) = (asking.calls_made, asking.resumed);
    job.shared.update(|i| {
        i.messages = kept.messages;
        i.bytes = kept.size;
        i.files = vec![FileFigures {
            name: final_name.to_owned(),
            bytes: kept.size,
            messages: kept.messages,
            start_ns: Some(kept.start_ns),
            end_ns: Some(kept.end_ns),
            dropped: 0,
        }];
        i.refused = refused;
        if let Some(b) = &mut i.blackbox {
            b.received = r.size;
            b.refused = refused;
            b.calls = calls_made;
            b.resumed = resumed;
        }
    });
    tracing::info!(recording = %id, robot = %robot, bytes = r.size, resumed, "black-box slice fetched");
    Ok(())
}

/// Writes to `dest` the messages of the slice in `part` whose topics (under `prefix`,
/// the robot's) `gate` lets the requester read, and removes `part`. With nothing left
/// out, `part` is kept as it came. Returns the kept file's figures and the messages cut.
fn cut_readable(
    mut gate: Box<dyn Gate>,
    prefix: &str,
    part: &Path,
    dest: &Path,
    r: &FetchReply,
) -> Result<(FetchReply, u64), String> {
    let mut refused_topics = false;
    let mut keep = |topic: &str| {
        let ok = gate.allows(&format!("{prefix}{topic}"), Op::Subscribe);
        refused_topics |= !ok;
        ok
    };
    let cut = super::slice::cut(&[part], 0, u64::MAX, &mut keep, dest);
    match cut {
        Ok(k) if !refused_topics => {
            // Nothing was left out: keep the robot's bytes as they came.
            std::fs::rename(part, dest).map_err(|e| e.to_string())?;
            Ok((
                FetchReply {
                    size: r.size,
                    sha256: r.sha256.clone(),
                    ..k
                },
                0,
            ))
        }
        Ok(k) => {
            let _ = std::fs::remove_file(part);
            let refused = r.messages.saturating_sub(k.messages);
            Ok((k, refused))
        }
        Err(e) => {
            let _ = std::fs::remove_file(part);
            Err(format!(
                "none of the slice's topics may be read by its requester ({e})"
            ))
        }
    }
}

/// Appends a piece that starts where the file ends; others are ignored (a piece of
/// another slice, or a repeat after asking again).
fn accept(payload: &Payload, id: &str, got: &mut Progress) -> std::io::Result<()> {
    let Some(p) = Piece::decode(&payload.bytes) else {
        return Ok(());
    };
    if p.slice != id || p.offset != got.received || p.data.is_empty() {
        return Ok(());
    }
    got.file.write_all(p.data)?;
    got.hash.update(p.data);
    got.received += p.data.len() as u64;
    got.last = Instant::now();
    Ok(())
}
