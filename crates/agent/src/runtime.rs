//! Changing a running agent's configuration (docs/runtime-config.md).
//!
//! A change ([`crate::config::runtime`]) is checked like the YAML file, then applied to the
//! running parts without restarting them: the uplink's per-topic QoS at once (and its topic
//! names by reconnecting), what the ROS 1 and ROS 2 bridges carry through their change
//! channels (each bridge starts and stops only the topics and services that changed), the
//! video streams through theirs (each starts, restarts or ends only if its own settings
//! changed). The
//! changes in force are written to the robot's disk before they apply, with the file they
//! were made against, and merged again with the file, entry by entry, when the agent
//! starts ([`crate::config::runtime::kept`]). Every change is recorded in an audit log
//! next to the kept changes' file, and in the agent's log.
//!
//! Two ways in: the services [`GET_SERVICE`] and [`SET_SERVICE`], which the agent offers to
//! the fleet like any local service (the hub's `/api/v1/robots/<robot>/config` calls them,
//! and only the hub may: see the hub's gate), and the local listener's REST API
//! ([`crate::local`]).

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{CallStatus, ChannelPeer, PeerMsg};
use fleetlink_relay::{ClientKind, Router, TopicName};
use serde_json::{Value, json};
use tokio::sync::watch;
use tokio_util::sync::CancellationToken;

use crate::config::origin::annotated_yaml;
use crate::config::runtime::kept::{self, KeptEntry, Level, Record, SetAside};
use crate::config::runtime::{self, CHANGEABLE};
use crate::config::{AgentConfig, ConfigError, ConfigSource};
use crate::options::PartOptions;
use crate::uplink::UplinkControl;

pub use fleetlink_relay::names::{
    CONFIG_GET_SERVICE as GET_SERVICE, CONFIG_SERVICE_TYPE as SERVICE_TYPE,
    CONFIG_SET_SERVICE as SET_SERVICE,
};

/// Where the running parts take their changes from.
pub struct Parts {
    pub uplink: Arc<UplinkControl>,
    pub ros1: Option<watch::Sender<fleetlink_ros1::Ros1Options>>,
    pub ros2: Option<watch::Sender<fleetlink_ros2::Ros2Options>>,
    /// The video streams ([`crate::video::supervise`]).
    pub video: Option<watch::Sender<Vec<crate::video::VideoOptions>>>,
}

/// The configuration of a running agent and the changes made to it.
pub struct RuntimeConfig {
    /// Where the changes in force are kept on disk; `None`: in memory only.
    file: Option<PathBuf>,
    /// What the agent's configuration was read from (what kept changes are made against).
    source: ConfigSource,
    state: Mutex<State>,
    parts: Mutex<Option<Parts>>,
}

/// What a change, or changes kept elsewhere, make of the configuration in force.
struct Update {
    config: AgentConfig,
    kept: Vec<KeptEntry>,
    /// Kept changes that were not applied.
    set_aside: Vec<SetAside>,
}

struct State {
    /// The configuration the agent started with: its file and flags.
    started: AgentConfig,
    /// The configuration in force: `started` with the changes `kept`.
    current: AgentConfig,
    kept: Vec<KeptEntry>,
    /// Kept changes that were not applied (at start, or of the hub's), and why.
    set_aside: Vec<SetAside>,
    /// When the changes in force last changed (Unix ms), and by whom.
    changed: Option<(u64, String)>,
}

/// A change that was refused: the text (as the YAML's errors read) and its parts.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Refusal {
    pub error: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub field: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<u64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub column: Option<u64>,
}

impl Refusal {
    fn of(e: &ConfigError) -> Refusal {
        Refusal {
            error: e.to_string(),
            field: e.field().map(str::to_owned),
            line: e.position().map(|p| p.line),
            column: e.position().map(|p| p.column),
        }
    }

    fn text(error: String) -> Refusal {
        Refusal {
            error,
            field: None,
            line: None,
            column: None,
        }
    }
}

impl std::fmt::Debug for RuntimeConfig {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RuntimeConfig")
            .field("file", &self.file)
            .finish_non_exhaustive()
    }
}

impl RuntimeConfig {
    /// The configuration the agent starts with (`started`: its file and flags, read from
    /// `source`), with the changes kept in `file` merged in entry by entry
    /// ([`kept::open`]): what no longer merges is set aside and said in the log, which
    /// also shows the configuration in force with each field's origin.
    pub fn open(
        started: AgentConfig,
        source: ConfigSource,
        file: Option<PathBuf>,
    ) -> RuntimeConfig {
        let opened = file
            .as_deref()
            .map(|path| kept::open(&started, &source, path));
        let (settled, found) = match opened {
            Some(o) => {
                for n in &o.notes {
                    match n.level {
                        Level::Info => tracing::info!("runtime configuration: {}", n.text),
                        Level::Warn => tracing::warn!("runtime configuration: {}", n.text),
                        Level::Error => tracing::error!("runtime configuration: {}", n.text),
                    }
                }
                (o.settled, o.found)
            }
            None => (
                kept::Settled {
                    config: started.clone(),
                    in_force: Vec::new(),
                    set_aside: Vec::new(),
                },
                false,
            ),
        };
        tracing::info!(
            "configuration in force (from {}{}):\n{}",
            source.name(),
            match (&file, found) {
                (Some(f), true) => format!(" and the changes kept in {}", f.display()),
                _ => String::new(),
            },
            annotated_yaml(&settled.config, &source, &settled.in_force).trim_end()
        );
        RuntimeConfig {
            file,
            source,
            state: Mutex::new(State {
                started,
                current: settled.config,
                kept: settled.in_force,
                set_aside: settled.set_aside,
                changed: None,
            }),
            parts: Mutex::new(None),
        }
    }

    /// The configuration in force (what the agent's parts are built from).
    pub fn current(&self) -> AgentConfig {
        self.lock().current.clone()
    }

    /// Connects the running parts (once they exist).
    pub fn attach(&self, parts: Parts) {
        *self.parts.lock().unwrap_or_else(|p| p.into_inner()) = Some(parts);
    }

    /// The client whose calls are the hub's (the uplink's), once the parts are attached.
    fn hub_client(&self) -> Option<fleetlink_relay::ClientId> {
        self.parts
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .as_ref()
            .map(|p| p.uplink.client())
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// The changes in force as they are kept (on disk, and by the hub).
    fn record(&self, kept: &[KeptEntry]) -> Record {
        Record {
            made_against: Some(self.source.made_against()),
            entries: kept.to_vec(),
        }
    }

    /// What the API shows: the configuration in force (as YAML, each field with its
    /// origin, the tokens hidden), the changes in force (as a change, and as kept), those
    /// set aside, what may change, and where the changes are kept.
    pub fn view(&self) -> Value {
        let st = self.lock();
        let set_aside: Vec<Value> = st
            .set_aside
            .iter()
            .map(|a| {
                json!({
                    "entry": a.kept.entry.to_string(),
                    "value": a.kept.value,
                    "kept": a.kept.when_and_who(),
                    "why": a.why,
                })
            })
            .collect();
        json!({
            "effective": annotated_yaml(&st.current, &self.source, &st.kept),
            "overlay": kept::change_doc(&st.kept),
            "record": self.record(&st.kept).to_json(),
            "set_aside": set_aside,
            "changeable": CHANGEABLE,
            "persisted": self.file.as_ref().map(|p| p.display().to_string()),
            "changed_at_ms": st.changed.as_ref().map(|c| c.0),
            "changed_by": st.changed.as_ref().map(|c| c.1.clone()),
        })
    }

    /// Checks the change `text` and, if it is good, keeps it on disk and applies it. `by`
    /// names who asked (for the audit log). `Ok` tells which fields it wrote and whether
    /// anything changed.
    pub fn apply(&self, text: &str, by: &str) -> Result<Value, Refusal> {
        let st = self.lock();
        let at = now_ms();
        let changed = runtime::change(&st.started, &st.current, &st.kept, text, "change", by, at)
            .map_err(|e| Refusal::of(&e))?;
        let update = Update {
            config: changed.config,
            kept: changed.kept,
            set_aside: Vec::new(),
        };
        self.commit(st, update, &changed.fields, text, by, at)
    }

    /// Applies changes kept elsewhere (the hub's, `record` as [`Record::to_json`] writes
    /// it) as the agent applies its own at start: each entry that still merges with the
    /// file; the others are set aside and said. `by` names who sent them.
    pub fn apply_kept(&self, record: &Value, by: &str) -> Result<Value, Refusal> {
        let record =
            Record::read(record, "the changes kept for the robot").map_err(|e| Refusal::of(&e))?;
        let st = self.lock();
        let mut candidates = st.kept.clone();
        for k in &record.entries {
            match candidates.iter_mut().find(|c| c.entry == k.entry) {
                Some(c) => *c = k.clone(),
                None => candidates.push(k.clone()),
            }
        }
        let settled = kept::settle(&st.started, candidates);
        for a in &settled.set_aside {
            tracing::warn!(
                "runtime configuration: {by}: the kept change {} = {} ({}) is set aside: {}",
                a.kept.entry,
                kept::show(&a.kept.entry, &a.kept.value),
                a.kept.when_and_who(),
                a.why
            );
        }
        let mut fields: Vec<&'static str> =
            record.entries.iter().map(|k| k.entry.field()).collect();
        fields.sort_by_key(|f| CHANGEABLE.iter().position(|c| c == f));
        fields.dedup();
        let text = runtime::kept::change_doc(&record.entries);
        let text = serde_json::to_string(&text).unwrap_or_default();
        let set_aside_now: Vec<Value> = settled
            .set_aside
            .iter()
            .map(|a| json!({"entry": a.kept.entry.to_string(), "why": a.why}))
            .collect();
        let update = Update {
            config: settled.config,
            kept: settled.in_force,
            set_aside: settled.set_aside,
        };
        let mut view = self.commit(st, update, &fields, &text, by, now_ms())?;
        view["set_aside_now"] = json!(set_aside_now);
        Ok(view)
    }

    /// Keeps the update's changes on disk and applies its configuration to the running
    /// parts, unless nothing changes; answers with the view, `changed` (`fields`) and
    /// `unchanged`.
    fn commit(
        &self,
        mut st: std::sync::MutexGuard<'_, State>,
        update: Update,
        fields: &[&'static str],
        text: &str,
        by: &str,
        at: u64,
    ) -> Result<Value, Refusal> {
        let Update {
            config,
            kept,
            set_aside,
        } = update;
        let opts = PartOptions::from_config(&config).map_err(|e| Refusal::text(e.to_string()))?;
        let parts = self.parts.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(p) = parts.as_ref() {
            p.uplink
                .check_topic_qos(&opts.uplink.topic_qos)
                .map_err(Refusal::text)?;
        }
        let unchanged = config == st.current && kept == st.kept;
        if !unchanged {
            if let Some(path) = &self.file {
                persist(path, &self.record(&kept)).map_err(|e| {
                    Refusal::text(format!(
                        "the change was not applied: it cannot be kept in {} ({e}); fix the \
                         directory's permissions or set runtime_file",
                        path.display()
                    ))
                })?;
            }
            if let Some(p) = parts.as_ref() {
                p.uplink.set_topic_qos(opts.uplink.topic_qos.clone());
                p.uplink.set_names(opts.uplink.names.clone());
                if let (Some(tx), Some(o)) = (&p.ros1, opts.ros1.clone()) {
                    tx.send_replace(o);
                }
                if let (Some(tx), Some(o)) = (&p.ros2, opts.ros2.clone()) {
                    tx.send_replace(o);
                }
                if let Some(tx) = &p.video {
                    tx.send_if_modified(|now| {
                        let changed = *now != opts.video;
                        *now = opts.video.clone();
                        changed
                    });
                }
            }
            // Kept changes set aside at start were kept on disk until now; the file now
            // holds the changes in force only.
            let dropped: Vec<String> = std::mem::take(&mut st.set_aside)
                .iter()
                .filter(|a| !set_aside.iter().any(|n| n.kept.entry == a.kept.entry))
                .map(|a| {
                    let value = kept::show(&a.kept.entry, &a.kept.value);
                    format!("{} = {value}", a.kept.entry)
                })
                .collect();
            self.audit(at, by, fields, text, &dropped);
            st.current = config;
            st.kept = kept;
            st.changed = Some((at, by.to_owned()));
        }
        for a in set_aside {
            match st
                .set_aside
                .iter_mut()
                .find(|o| o.kept.entry == a.kept.entry)
            {
                Some(old) => *old = a,
                None => st.set_aside.push(a),
            }
        }
        drop(parts);
        drop(st);
        let mut view = self.view();
        view["changed"] = json!(fields);
        view["unchanged"] = json!(unchanged);
        Ok(view)
    }

    /// Records a change: a line in the agent's log, and one in the audit log beside the
    /// kept changes' file (JSON lines). `dropped`: kept changes set aside at start that
    /// the file no longer holds after it.
    fn audit(&self, at_ms: u64, by: &str, fields: &[&str], text: &str, dropped: &[String]) {
        tracing::info!(
            target: "fleetlink::audit",
            "runtime configuration changed by {by}: {}",
            fields.join(", ")
        );
        if !dropped.is_empty() {
            tracing::warn!(
                "runtime configuration: the kept changes set aside at start are dropped with \
                 this change: {}",
                dropped.join("; ")
            );
        }
        let Some(path) = &self.file else {
            return;
        };
        let log = audit_path(path);
        let mut line = json!({"at_ms": at_ms, "by": by, "fields": fields, "change": text});
        if !dropped.is_empty() {
            line["dropped"] = json!(dropped);
        }
        let written = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(&log)
            .and_then(|mut f| {
                use std::io::Write;
                writeln!(f, "{line}")
            });
        if let Err(e) = written {
            tracing::warn!(
                "runtime configuration: cannot append to {}: {e}",
                log.display()
            );
        }
    }
}

fn now_ms() -> u64 {
    fleetlink_relay::unix_nanos() / 1_000_000
}

/// The audit log of the changes kept in `file`: `<file>.audit.jsonl`.
pub fn audit_path(file: &std::path::Path) -> PathBuf {
    let mut name = file.as_os_str().to_owned();
    name.push(".audit.jsonl");
    PathBuf::from(name)
}

/// Writes the kept changes to `path` whole or not at all (a temporary file renamed over
/// it), synced, so a crash leaves the old or the new changes, never half of them.
fn persist(path: &std::path::Path, record: &Record) -> std::io::Result<()> {
    use std::io::Write;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    let mut f = std::fs::File::create(&tmp)?;
    let text = serde_json::to_string_pretty(&record.to_json()).unwrap_or_default();
    f.write_all(text.as_bytes())?;
    f.sync_all()?;
    std::fs::rename(&tmp, path)
}

/// Offers [`GET_SERVICE`] and [`SET_SERVICE`] on `router` until `shutdown`.
pub async fn serve(config: Arc<RuntimeConfig>, router: Arc<Router>, shutdown: CancellationToken) {
    let (client, _) = router.connect(
        ClientKind::Internal {
            role: "runtime config".into(),
        },
        None,
    );
    let (peer, calls) = ChannelPeer::new();
    router.calls.attach(client, peer);
    for name in [GET_SERVICE, SET_SERVICE] {
        router.calls.advertise(
            client,
            TopicName::parse(name).expect("a constant name"),
            Schema::named(SERVICE_TYPE),
            false,
        );
    }
    loop {
        tokio::select! {
            m = calls.recv() => match m {
                Some(PeerMsg::Call(req)) => {
                    // Only the hub, whose calls come through the uplink: a local program
                    // (a rosbridge client, a ROS node) changes the configuration through
                    // the local API, with its token.
                    if config.hub_client() != Some(req.caller) {
                        router.calls.respond(
                            client,
                            req.id,
                            CallStatus::Failed,
                            None,
                            format!(
                                "{} is the hub's: on the robot, use the local listener's \
                                 /api/v1/config with local_rosbridge.config_token",
                                req.service.name
                            ),
                        );
                        continue;
                    }
                    let answer = match req.service.name.as_str() {
                        GET_SERVICE => config.view(),
                        // Kept on disk (written and synced, the audit line appended) off
                        // the runtime's thread; calls are still taken one at a time.
                        _ => {
                            let (config, payload) = (config.clone(), req.payload.clone());
                            tokio::task::spawn_blocking(move || set_call(&config, &payload))
                                .await
                                .unwrap_or_else(|e| {
                                    json!({"ok": false, "error": Refusal::text(format!("the change failed: {e}"))})
                                })
                        }
                    };
                    let body = serde_json::to_vec(&answer).unwrap_or_default();
                    router.calls.respond(
                        client,
                        req.id,
                        CallStatus::Ok,
                        Some(Payload::json(body)),
                        String::new(),
                    );
                }
                Some(_) => {}
                None => break,
            },
            _ = shutdown.cancelled() => break,
        }
    }
    router.disconnect(client);
}

/// A call of [`SET_SERVICE`]: `{"change": TEXT, "by": WHO}`; answered `{"ok": true, ...}`
/// with the view, or `{"ok": false, "error": ...}` naming what is wrong.
fn set_call(config: &RuntimeConfig, payload: &Payload) -> Value {
    #[derive(serde::Deserialize)]
    struct Request {
        #[serde(default)]
        change: Option<String>,
        /// Changes kept elsewhere (the hub's), applied as the agent applies its own.
        #[serde(default)]
        kept: Option<Value>,
        #[serde(default)]
        by: Option<String>,
    }
    let request = match payload.encoding {
        Encoding::Json => serde_json::from_slice::<Request>(&payload.bytes).map_err(|e| {
            format!("a change is asked for as JSON {{\"change\": TEXT, \"by\": WHO}}: {e}")
        }),
        other => Err(format!(
            "a change is asked for as JSON {{\"change\": TEXT}}, not {other:?}"
        )),
    };
    let request = match request {
        Ok(r) => r,
        Err(e) => return json!({"ok": false, "error": Refusal::text(e)}),
    };
    let by = request.by.unwrap_or_else(|| "a fleet caller".to_owned());
    let outcome = match (&request.change, &request.kept) {
        (_, Some(record)) => config.apply_kept(record, &by),
        (Some(text), None) => config.apply(text, &by),
        (None, None) => Err(Refusal::text(
            "a change is asked for as JSON {\"change\": TEXT, \"by\": WHO}".to_owned(),
        )),
    };
    match outcome {
        Ok(mut view) => {
            view["ok"] = json!(true);
            view
        }
        Err(refusal) => json!({"ok": false, "error": refusal}),
    }
}
