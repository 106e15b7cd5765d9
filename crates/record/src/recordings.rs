//! A hub's recordings: started, listed, stopped and removed through its API, each in its
//! own directory under the recordings directory with its files and a `recording.json`
//! that keeps its figures across hub restarts.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use fleetlink_relay::Router;
use fleetlink_relay::gate::Gate;
use tokio_util::sync::CancellationToken;

use crate::blackbox::fetch::{self, BlackBoxFetch, FetchSpec};
use crate::recorder::{self, Job, RecordingInfo, Shared, State};
use crate::spec::RecordSpec;

/// Recordings that may run at once: each is a thread and a subscriber of its own.
pub const MAX_ACTIVE: usize = 16;

const INFO_FILE: &str = "recording.json";

/// Why a request about recordings was refused.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum RecordError {
    /// The request is wrong; the text names the field.
    #[error("{0}")]
    Invalid(String),
    #[error("no recording {0}")]
    NotFound(String),
    #[error("{MAX_ACTIVE} recordings and fetches are running already; stop one first")]
    TooMany,
    /// The disk or the system refused.
    #[error("{0}")]
    Io(String),
}

struct Entry {
    shared: Arc<Shared>,
    /// A recording's writer.
    thread: Option<std::thread::JoinHandle<()>>,
    /// A black-box fetch's task.
    task: Option<tokio::task::JoinHandle<()>>,
}

pub struct Recordings {
    dir: PathBuf,
    hub_name: String,
    router: Arc<Router>,
    entries: Mutex<BTreeMap<String, Entry>>,
}

impl Recordings {
    /// The recordings kept in `dir` (created if missing). One that was running when the
    /// hub stopped is `interrupted`.
    pub fn open(dir: &Path, router: Arc<Router>, hub_name: &str) -> std::io::Result<Recordings> {
        std::fs::create_dir_all(dir)?;
        let mut entries = BTreeMap::new();
        for e in std::fs::read_dir(dir)? {
            let path = e?.path().join(INFO_FILE);
            let Ok(text) = std::fs::read(&path) else {
                continue;
            };
            let mut info: RecordingInfo = match serde_json::from_slice(&text) {
                Ok(i) => i,
                Err(err) => {
                    tracing::warn!(
                        "{}: not a recording's description ({err}); left alone",
                        path.display()
                    );
                    continue;
                }
            };
            if info.state == State::Fetching {
                info.state = State::Interrupted;
                info.error =
                    Some("the hub stopped while the slice was on its way; fetch it again".into());
                write_info(&dir.join(&info.id), &info);
            }
            if info.state == State::Recording {
                info.state = State::Interrupted;
                // What the last file holds is what a reader finds up to its last chunk.
                if let Some(last) = info.files.last_mut()
                    && let Ok(m) = std::fs::metadata(dir.join(&info.id).join(&last.name))
                {
                    last.bytes = m.len();
                }
                info.bytes = info.files.iter().map(|f| f.bytes).sum();
                write_info(&dir.join(&info.id), &info);
            }
            entries.insert(
                info.id.clone(),
                Entry {
                    shared: Arc::new(Shared {
                        info: Mutex::new(info),
                        stop: CancellationToken::new(),
                    }),
                    thread: None,
                    task: None,
                },
            );
        }
        Ok(Recordings {
            dir: dir.to_owned(),
            hub_name: hub_name.to_owned(),
            router,
            entries: Mutex::new(entries),
        })
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Starts recording `spec` as `started_by`, reading what `gate` allows. Must be called
    /// within a Tokio runtime (the recorder waits for its queue on it).
    pub fn start(
        &self,
        spec: RecordSpec,
        started_by: String,
        gate: Box<dyn Gate>,
    ) -> Result<RecordingInfo, RecordError> {
        spec.check().map_err(RecordError::Invalid)?;
        let mut entries = self.lock();
        check_active(&entries)?;
        let now_ms = fleetlink_relay::unix_nanos() / 1_000_000;
        let (id, dir) = self.new_dir(&entries, "rec", now_ms)?;
        let info = RecordingInfo::new(id.clone(), spec, State::Recording, started_by, now_ms);
        let shared = begin(&dir, &info);
        let keep_dir = dir.clone();
        let job = Job {
            router: self.router.clone(),
            dir,
            hub_name: self.hub_name.clone(),
            gate,
            shared: shared.clone(),
            runtime: tokio::runtime::Handle::current(),
            persist: Box::new(move |i| write_info(&keep_dir, i)),
        };
        let thread = recorder::start(job).map_err(RecordError::Invalid)?;
        tracing::info!(recording = %id, topics = ?info.spec.topics, "recording started");
        entries.insert(
            id,
            Entry {
                shared,
                thread: Some(thread),
                task: None,
            },
        );
        Ok(info)
    }

    /// Asks robot `spec.robot` for a slice of its black box as `started_by`, keeping what
    /// `gate` allows; the slice arrives in the background (state `fetching`). `online`
    /// tells a robot that is away (waited for) from one without a black box (an error).
    /// Must be called within a Tokio runtime.
    pub fn fetch(
        &self,
        spec: FetchSpec,
        started_by: String,
        gate: Box<dyn Gate>,
        online: fetch::Online,
    ) -> Result<RecordingInfo, RecordError> {
        spec.check().map_err(RecordError::Invalid)?;
        let mut entries = self.lock();
        check_active(&entries)?;
        let now_ms = fleetlink_relay::unix_nanos() / 1_000_000;
        let (id, dir) = self.new_dir(&entries, &format!("bb-{}", spec.robot), now_ms)?;
        let mut record = RecordSpec::topics(spec.topics.clone());
        record.name = spec.name.clone();
        let mut info = RecordingInfo::new(id.clone(), record, State::Fetching, started_by, now_ms);
        info.blackbox = Some(BlackBoxFetch {
            robot: spec.robot.clone(),
            range: spec.range(),
            size: None,
            received: 0,
            sha256: None,
            calls: 0,
            resumed: 0,
            refused: 0,
            waiting: None,
        });
        let shared = begin(&dir, &info);
        let keep_dir = dir.clone();
        let job = fetch::FetchJob {
            router: self.router.clone(),
            shared: shared.clone(),
            dir,
            gate,
            online,
            persist: Arc::new(move |i| write_info(&keep_dir, i)),
        };
        let task = tokio::spawn(fetch::run(job));
        tracing::info!(recording = %id, robot = %spec.robot, "black-box fetch started");
        entries.insert(
            id,
            Entry {
                shared,
                thread: None,
                task: Some(task),
            },
        );
        Ok(info)
    }

    /// A new recording's id (`{prefix}-YYYYMMDD-HHMMSS`, numbered if taken) and its
    /// directory, created.
    fn new_dir(
        &self,
        entries: &BTreeMap<String, Entry>,
        prefix: &str,
        now_ms: u64,
    ) -> Result<(String, PathBuf), RecordError> {
        let base = format!("{prefix}-{}", id_at(now_ms));
        let mut id = base.clone();
        let mut n = 1;
        while entries.contains_key(&id) || self.dir.join(&id).exists() {
            n += 1;
            id = format!("{base}-{n}");
        }
        let dir = self.dir.join(&id);
        std::fs::create_dir_all(&dir)
            .map_err(|e| RecordError::Io(format!("creating {}: {e}", dir.display())))?;
        Ok((id, dir))
    }

    /// Every recording, newest first.
    pub fn list(&self) -> Vec<RecordingInfo> {
        let mut all: Vec<RecordingInfo> = self.lock().values().map(|e| e.shared.info()).collect();
        all.sort_by(|a, b| b.started_at_ms.cmp(&a.started_at_ms).then(b.id.cmp(&a.id)));
        all
    }

    pub fn get(&self, id: &str) -> Result<RecordingInfo, RecordError> {
        self.lock()
            .get(id)
            .map(|e| e.shared.info())
            .ok_or_else(|| RecordError::NotFound(clip(id)))
    }

    /// Stops a recording and waits until its files are finished; stopping a stopped one
    /// changes nothing.
    pub async fn stop(&self, id: &str) -> Result<RecordingInfo, RecordError> {
        let (thread, task) = {
            let mut entries = self.lock();
            let e = entries
                .get_mut(id)
                .ok_or_else(|| RecordError::NotFound(clip(id)))?;
            e.shared.stop.cancel();
            (e.thread.take(), e.task.take())
        };
        if let Some(t) = thread {
            let _ = tokio::task::spawn_blocking(move || t.join()).await;
            tracing::info!(recording = %id, "recording stopped");
        }
        if let Some(t) = task {
            let _ = t.await;
        }
        self.get(id)
    }

    /// Stops (if need be) and deletes a recording with its files.
    pub async fn remove(&self, id: &str) -> Result<(), RecordError> {
        self.stop(id).await?;
        self.lock().remove(id);
        let dir = self.dir.join(id);
        tokio::task::spawn_blocking(move || std::fs::remove_dir_all(&dir))
            .await
            .map_err(|e| RecordError::Io(e.to_string()))?
            .map_err(|e| RecordError::Io(format!("removing recording {id}: {e}")))
    }

    /// Stops every running recording (the hub is shutting down).
    pub async fn stop_all(&self) {
        let running: Vec<String> = self
            .lock()
            .iter()
            .filter(|(_, e)| e.thread.is_some() || e.task.is_some())
            .map(|(id, _)| id.clone())
            .collect();
        for id in running {
            let _ = self.stop(&id).await;
        }
    }

    /// The path of file `name` of recording `id`, if it is one of its files.
    pub fn file(&self, id: &str, name: &str) -> Result<PathBuf, RecordError> {
        let info = self.get(id)?;
        if !info.files.iter().any(|f| f.name == name) {
            return Err(RecordError::NotFound(format!(
                "{}/{}",
                clip(id),
                clip(name)
            )));
        }
        Ok(self.dir.join(&info.id).join(name))
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, BTreeMap<String, Entry>> {
        self.entries.lock().unwrap_or_else(|p| p.into_inner())
    }
}

/// A new recording's shared state, its `recording.json` written first.
fn begin(dir: &Path, info: &RecordingInfo) -> Arc<Shared> {
    write_info(dir, info);
    Arc::new(Shared {
        info: Mutex::new(info.clone()),
        stop: CancellationToken::new(),
    })
}

fn check_active(entries: &BTreeMap<String, Entry>) -> Result<(), RecordError> {
    let active = entries
        .values()
        .filter(|e| matches!(e.shared.info().state, State::Recording | State::Fetching))
        .count();
    if active >= MAX_ACTIVE {
        return Err(RecordError::TooMany);
    }
    Ok(())
}

/// A time for ids: `20261128-193005` (UTC).
fn id_at(unix_ms: u64) -> String {
    let t = time::OffsetDateTime::from_unix_timestamp((unix_ms / 1000) as i64)
        .unwrap_or(time::OffsetDateTime::UNIX_EPOCH);
    format!(
        "{:04}{:02}{:02}-{:02}{:02}{:02}",
        t.year(),
        u8::from(t.month()),
        t.day(),
        t.hour(),
        t.minute(),
        t.second()
    )
}

fn clip(s: &str) -> String {
    s.chars().take(100).collect()
}

/// Writes `recording.json` whole or not at all (a temporary file renamed over it).
fn write_info(dir: &Path, info: &RecordingInfo) {
    let tmp = dir.join(".recording.json.tmp");
    let done = serde_json::to_vec_pretty(info)
        .map_err(std::io::Error::other)
        .and_then(|b| std::fs::write(&tmp, b))
        .and_then(|()| std::fs::rename(&tmp, dir.join(INFO_FILE)));
    if let Err(e) = done {
        tracing::warn!("keeping {}: {e}", dir.join(INFO_FILE).display());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_read_as_the_utc_start() {
        assert_eq!(id_at(1_795_895_405_000), "20261128-195005");
    }
}
