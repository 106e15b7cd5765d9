//! What the connection loop ([`crate::bridge`]) and discovery ([`crate::discovery`])
//! share: the bridge's counters, the state that outlives a connection (what is bridged,
//! which requests and calls are in flight) behind one std mutex, and the rosapi requests
//! to the server that discovery makes and the connection loop answers by id.

use std::collections::{HashMap, HashSet};
use std::sync::atomic::AtomicU64;
use std::sync::{Arc, Mutex};

use fleetlink_relay::calls::{CallId, CallStatus};
use fleetlink_relay::router::Topic;
use fleetlink_relay::{ClientId, Router};
use serde_json::Value;
use tokio::sync::{mpsc, oneshot};
use tokio_tungstenite::tungstenite::Message as WsMessage;

use crate::ops;
use crate::options::RosbridgeClientOptions;

/// Counters of the bridge (for tests, logs and the agent's status).
#[derive(Debug, Default)]
pub struct RosbridgeClientStats {
    /// Connections made to the server (1 plus the reconnects).
    pub connects: AtomicU64,
    /// Server messages published into the router.
    pub messages_up: AtomicU64,
    /// Router messages published on the server.
    pub messages_down: AtomicU64,
    /// Router messages dropped while the server was not connected or could not take
    /// them (no type, no JSON form).
    pub dropped_down: AtomicU64,
    /// Fleet calls and goals forwarded to the server.
    pub calls_forwarded: AtomicU64,
    /// Server programs' calls of fleet services.
    pub calls_served: AtomicU64,
    /// Operations the server refused (`status` errors and warnings).
    pub refusals: AtomicU64,
}

/// A rosapi answer: the values, or the server's reason.
pub(crate) type Reply = Result<Box<serde_json::value::RawValue>, String>;

#[derive(Default)]
pub(crate) struct State {
    /// Connected: where frames for the server go.
    out: Option<mpsc::Sender<WsMessage>>,
    /// The server's topics published into the router, by name.
    pub(crate) up: HashMap<String, Up>,
    /// Router topics advertised on the server in this connection.
    pub(crate) advertised: HashSet<String>,
    /// Router topics that cannot be advertised (no type), reported once.
    pub(crate) unadvertisable: HashSet<String>,
    /// The server's services and action servers in the call table, by name.
    pub(crate) exposed: HashMap<String, Exposed>,
    /// Fleet services advertised on the server: name → type.
    pub(crate) offered: HashMap<String, String>,
    /// Requests of this client to the server waiting for their answer, by id.
    pub(crate) waiting: HashMap<String, oneshot::Sender<Reply>>,
    /// Fleet calls forwarded to the server: rosbridge id → the call.
    pub(crate) forwarded: HashMap<String, Forwarded>,
    /// The same by call id (to cancel).
    pub(crate) forwarded_ids: HashMap<CallId, String>,
    /// Server programs' calls of offered fleet services: the call → its rosbridge id and
    /// service.
    pub(crate) serving: HashMap<CallId, Serving>,
    next_id: u64,
    /// The server's ROS version (rosapi `get_ros_version`): 1 names types `pkg/T`.
    pub(crate) ros_version: Option<u64>,
}

pub(crate) struct Up {
    pub(crate) type_name: String,
    pub(crate) topic: Arc<Topic>,
    pub(crate) seq: u64,
}

pub(crate) struct Exposed {
    pub(crate) type_name: String,
    pub(crate) action: bool,
}

pub(crate) struct Serving {
    pub(crate) id: Option<Value>,
    pub(crate) service: String,
    /// The service's type as the call table knows it (`pkg/srv/T`).
    pub(crate) type_name: String,
}

pub(crate) struct Forwarded {
    pub(crate) call: CallId,
    pub(crate) name: String,
    pub(crate) action: bool,
}

pub(crate) struct Shared {
    pub(crate) opts: RosbridgeClientOptions,
    pub(crate) router: Arc<Router>,
    pub(crate) client: ClientId,
    pub(crate) stats: Arc<RosbridgeClientStats>,
    // std Mutex: short critical sections, never held across an await.
    state: Mutex<State>,
}

impl Shared {
    pub(crate) fn new(
        opts: RosbridgeClientOptions,
        router: Arc<Router>,
        client: ClientId,
        stats: Arc<RosbridgeClientStats>,
    ) -> Shared {
        Shared {
            opts,
            router,
            client,
            stats,
            state: Mutex::new(State::default()),
        }
    }

    pub(crate) fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Queues a frame for the server; false when not connected or the queue is full.
    pub(crate) fn send(&self, st: &State, frame: WsMessage) -> bool {
        match &st.out {
            Some(tx) => tx.try_send(frame).is_ok(),
            None => false,
        }
    }

    /// A new connection: subscribe to the bridged topics and advertise the offered
    /// services again (the server forgot them with the old connection).
    pub(crate) fn connected(&self, tx: mpsc::Sender<WsMessage>) {
        let mut st = self.lock();
        st.out = Some(tx);
        st.advertised.clear();
        let mut frames = Vec::new();
        for (name, up) in &st.up {
            frames.push(ops::subscribe(name, &up.type_name));
        }
        for (name, ty) in &st.offered {
            frames.push(ops::advertise_service(name, ty));
        }
        for f in frames {
            self.send(&st, WsMessage::text(f));
        }
    }

    /// The connection is gone: its requests and the calls forwarded on it fail, and the
    /// server programs' calls of fleet services are cancelled.
    pub(crate) fn connection_ended(&self) {
        let (forwarded, serving) = {
            let mut st = self.lock();
            st.out = None;
            st.waiting.clear();
            st.forwarded_ids.clear();
            (
                std::mem::take(&mut st.forwarded),
                std::mem::take(&mut st.serving),
            )
        };
        for (_, f) in forwarded {
            self.router.calls.respond(
                self.client,
                f.call,
                CallStatus::Failed,
                None,
                format!(
                    "{}: the link to the robot's rosbridge server dropped before it answered",
                    f.name
                ),
            );
        }
        for call in serving.into_keys() {
            self.router.calls.cancel(self.client, call);
        }
    }

    pub(crate) fn next_id(&self, st: &mut State, kind: &str) -> String {
        st.next_id += 1;
        format!("{kind}:{}", st.next_id)
    }

    /// Calls `service` on the server (a rosapi service) and waits for its values.
    pub(crate) async fn request(&self, service: &str, args: Value) -> Result<Value, String> {
        let (tx, rx) = oneshot::channel();
        {
            let mut st = self.lock();
            let id = self.next_id(&mut st, "rosapi");
            let frame = ops::call_service(&id, service, None, args.to_string().as_bytes());
            if st.out.is_none() {
                return Err("not connected".into());
            }
            st.waiting.insert(id.clone(), tx);
            let text = String::from_utf8(frame).unwrap_or_default();
            if !self.send(&st, WsMessage::text(text)) {
                st.waiting.remove(&id);
                return Err("the server is not taking requests".into());
            }
        }
        match tokio::time::timeout(self.opts.call_timeout, rx).await {
            Ok(Ok(Ok(raw))) => serde_json::from_str(raw.get()).map_err(|e| e.to_string()),
            Ok(Ok(Err(why))) => Err(why),
            Ok(Err(_)) => Err("the connection ended".into()),
            Err(_) => Err(format!("no answer within {:?}", self.opts.call_timeout)),
        }
    }
}
