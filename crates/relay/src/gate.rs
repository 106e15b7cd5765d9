//! Authorization as the relay sees it: a [`Gate`] answers "may this connection do this
//! to that name?" and hears about what it did, for the audit log.
//!
//! The relay knows nothing of tokens, rules or databases; the hub implements `Gate` on
//! top of its security layer and the agent's local listener uses [`AllowAll`]. A session
//! asks at advertise/publish/subscribe time and again for every message it delivers, so a
//! rule change reaches live subscriptions; implementations cache decisions so the
//! per-message question is a hash lookup.

use serde_json::{Map, Value};

/// What a connection wants to do to a name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Op {
    /// Advertise or publish a topic.
    Publish,
    /// Subscribe to a topic, see it listed, and keep receiving it.
    Subscribe,
    /// Call a service (the hub's own `/rosapi` services included).
    CallService,
    /// Provide a service (`advertise_service`, a robot's services on its link).
    AdvertiseService,
    /// Send a goal to an action.
    SendActionGoal,
    /// Cancel one's own goal (allowed where sending the goal is).
    CancelActionGoal,
    /// Provide an action.
    AdvertiseAction,
}

/// Leaves in `items` (a batch a writer took from its client's outbox) the messages `gate`
/// lets the client receive; none without a gate (a client not yet authenticated). Asked
/// at take time, so a rule change reaches live subscriptions; a batch mostly holds runs of
/// one topic, so the gate is asked once per run.
pub fn retain_allowed(gate: Option<&mut dyn Gate>, items: &mut Vec<crate::outbox::Taken>) {
    let Some(g) = gate else {
        items.clear();
        return;
    };
    let mut last = None;
    items.retain(|(_, _, m)| match last {
        Some((id, ok)) if id == m.topic.id => ok,
        _ => {
            let ok = g.allows_topic(m.topic.id.0, m.topic.name.as_str(), Op::Subscribe);
            last = Some((m.topic.id, ok));
            ok
        }
    });
}

pub trait Gate: Send + Sync + 'static {
    /// May this connection do `op` on `name`? Refusals are recorded by the gate.
    fn allows(&mut self, name: &str, op: Op) -> bool;

    /// [`Gate::allows`] for a router topic, by its id (which never names another topic
    /// while the router lives): a gate may cache by id, which on the per-message paths
    /// costs less than looking the name up.
    fn allows_topic(&mut self, _topic: u32, name: &str, op: Op) -> bool {
        self.allows(name, op)
    }

    /// `op` on `name` was done (`size` payload bytes); a gate records the operations that
    /// act on robots.
    fn done(&mut self, _name: &str, _op: Op, _size: usize) {}

    /// A call or goal (`op`) to `name` with a `size`-byte request ended with `outcome`
    /// (`ok`, `timeout: ...`); a gate records calls that act on robots.
    fn finished(&mut self, _name: &str, _op: Op, _size: usize, _outcome: &str) {}

    /// A second gate for the same identity (the session's writer task gets one).
    fn fork(&self) -> Box<dyn Gate>;
    /// Wakes when the rules behind this gate's answers may have changed, for sessions
    /// that show what is allowed (a viewer's channel list). `None`: they never change.
    fn rules_changed(&self) -> Option<tokio::sync::watch::Receiver<u64>> {
        None
    }

    /// Who this is, for messages (`user:alice`, `robot:r1`, `anonymous`).
    fn principal(&self) -> String;

    /// Who this is, for a call this connection makes that another hub may serve: that
    /// hub decides and audits the call on it. `None`: nobody a hub can vouch for (the
    /// robot's local listener).
    fn caller(&self) -> Option<Caller> {
        None
    }
}

/// The maker of a call, as the gate that let it through knows them: what a hub tells the
/// hub it forwards the call to ([`Gate::caller`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Caller {
    Robot { name: String },
    User { name: String, groups: Vec<String> },
    Anonymous,
}

/// No authorization: every operation is allowed (a robot's own local listener).
#[derive(Debug, Clone, Copy, Default)]
pub struct AllowAll;

impl Gate for AllowAll {
    fn allows(&mut self, _name: &str, _op: Op) -> bool {
        true
    }

    fn fork(&self) -> Box<dyn Gate> {
        Box::new(AllowAll)
    }

    fn principal(&self) -> String {
        "local".into()
    }
}

/// Turns the fields of a rosbridge `auth` operation into a gate for the authenticated
/// identity; the error text is sent back in a `status` message.
pub trait Guard: Send + Sync + 'static {
    fn authenticate(&self, fields: &Map<String, Value>) -> Result<Box<dyn Gate>, String>;
}

/// How a session starts out.
pub struct SessionAuth {
    /// Already authenticated (from the upgrade request, or anonymous access); `None`
    /// means every operation but `auth` is refused until the client authenticates.
    pub gate: Option<Box<dyn Gate>>,
    /// Accepts the `auth` operation; `None` = the operation is not needed here.
    pub guard: Option<std::sync::Arc<dyn Guard>>,
}

impl SessionAuth {
    /// No authentication, everything allowed.
    pub fn open() -> SessionAuth {
        SessionAuth {
            gate: Some(Box::new(AllowAll)),
            guard: None,
        }
    }
}
