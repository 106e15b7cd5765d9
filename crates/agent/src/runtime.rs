//! Changing a running agent's configuration (docs/runtime-config.md).
//!
//! A change ([`crate::config::runtime`]) is checked like the YAML file, then applied to the
//! running parts without restarting them: the uplink's per-topic QoS at once (and its topic
//! names by reconnecting), what the ROS 1 and ROS 2 bridges carry through their change
//! channels (each bridge starts and stops only the topics and services that changed). The
//! changes in force (the overlay) are written to the robot's disk before they apply, and
//! applied again when the agent starts. Every change is recorded in an audit log next to
//! the overlay's file, and in the agent's log.
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
use serde_json::{Map, Value, json};
use tokio::sync::watch;
use tokio_util::sync::CancellationToken;

use crate::agent::AgentOptions;
use crate::config::runtime::{self, CHANGEABLE};
use crate::config::{AgentConfig, ConfigError};
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
}

/// The configuration of a running agent and the changes made to it.
pub struct RuntimeConfig {
    /// Where the overlay is kept on disk; `None`: in memory only.
    file: Option<PathBuf>,
    state: Mutex<State>,
    parts: Mutex<Option<Parts>>,
}

struct State {
    current: AgentConfig,
    overlay: Map<String, Value>,
    /// When the overlay last changed (Unix ms), and by whom.
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
    /// The configuration the agent starts with (`started`: its file and flags), with the
    /// overlay kept in `file` applied. An overlay that no longer fits the file (its ROS
    /// section was removed, say) is set aside, said in the log, and the file's
    /// configuration runs.
    pub fn open(started: AgentConfig, file: Option<PathBuf>) -> RuntimeConfig {
        let mut state = State {
            current: started.clone(),
            overlay: Map::new(),
            changed: None,
        };
        if let Some(path) = &file {
            match std::fs::read_to_string(path) {
                Ok(text) => {
                    let source = path.display().to_string();
                    match runtime::change(&started, &Map::new(), &text, &source) {
                        Ok(c) => {
                            tracing::info!(
                                "runtime configuration: the changes kept in {source} are in force ({})",
                                c.fields.join(", ")
                            );
                            state.current = c.config;
                            state.overlay = c.overlay;
                        }
                        Err(e) => tracing::error!(
                            "runtime configuration: the changes kept in {source} no longer apply \
                             to this configuration ({e}); running without them"
                        ),
                    }
                }
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
                Err(e) => tracing::error!(
                    "runtime configuration: cannot read {}: {e}; running without the changes kept there",
                    path.display()
                ),
            }
        }
        RuntimeConfig {
            file,
            state: Mutex::new(state),
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

    /// What the API shows: the configuration in force (as YAML, the token hidden), the
    /// changes in force, what may change, and where the changes are kept.
    pub fn view(&self) -> Value {
        let st = self.lock();
        json!({
            "effective": st.current.effective_yaml(),
            "overlay": st.overlay,
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
        let mut st = self.lock();
        let changed = runtime::change(&st.current, &st.overlay, text, "change")
            .map_err(|e| Refusal::of(&e))?;
        let opts =
            AgentOptions::from_config(&changed.config).map_err(|e| Refusal::text(e.to_string()))?;
        let parts = self.parts.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(p) = parts.as_ref() {
            p.uplink
                .check_topic_qos(&opts.uplink.topic_qos)
                .map_err(Refusal::text)?;
        }
        let unchanged = changed.config == st.current && changed.overlay == st.overlay;
        if !unchanged {
            if let Some(path) = &self.file {
                persist(path, &changed.overlay).map_err(|e| {
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
            }
            let at = fleetlink_relay::unix_nanos() / 1_000_000;
            self.audit(at, by, &changed.fields, text);
            st.current = changed.config;
            st.overlay = changed.overlay;
            st.changed = Some((at, by.to_owned()));
        }
        drop(parts);
        drop(st);
        let mut view = self.view();
        view["changed"] = json!(changed.fields);
        view["unchanged"] = json!(unchanged);
        Ok(view)
    }

    /// Records a change: a line in the agent's log, and one in the audit log beside the
    /// overlay's file (JSON lines).
    fn audit(&self, at_ms: u64, by: &str, fields: &[&str], text: &str) {
        tracing::info!(
            target: "fleetlink::audit",
            "runtime configuration changed by {by}: {}",
            fields.join(", ")
        );
        let Some(path) = &self.file else {
            return;
        };
        let log = audit_path(path);
        let line = json!({"at_ms": at_ms, "by": by, "fields": fields, "change": text});
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

/// The audit log of the overlay kept in `file`: `<file>.audit.jsonl`.
pub fn audit_path(file: &std::path::Path) -> PathBuf {
    let mut name = file.as_os_str().to_owned();
    name.push(".audit.jsonl");
    PathBuf::from(name)
}

/// Writes the overlay to `path` whole or not at all (a temporary file renamed over it),
/// synced, so a crash leaves the old or the new changes, never half of them.
fn persist(path: &std::path::Path, overlay: &Map<String, Value>) -> std::io::Result<()> {
    use std::io::Write;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    let mut f = std::fs::File::create(&tmp)?;
    f.write_all(runtime::overlay_text(overlay).as_bytes())?;
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
                        _ => set_call(&config, &req.payload),
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
        change: String,
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
    match config.apply(&request.change, &by) {
        Ok(mut view) => {
            view["ok"] = json!(true);
            view
        }
        Err(refusal) => json!({"ok": false, "error": refusal}),
    }
}
