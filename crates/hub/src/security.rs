//! The hub's side of authentication and authorization: the `fleetlink-auth` core plugged
//! into the relay's [`Gate`] seam, and credentials read from where each transport carries
//! them.
//!
//! - rosbridge clients: `Authorization: Bearer` on the upgrade request, a `token` query
//!   parameter (browsers cannot set headers on WebSocket requests), or an `auth` operation
//!   (`token`, or rosbridge's `mac` field, or `user` + `password`);
//! - agents: the robot name and token in `HELLO` (or a verified client certificate);
//! - the HTTP API: the same header or query parameter.
//!
//! Checking a credential can mean an argon2 hash (passwords) or a database read (tokens),
//! so it never runs on a runtime worker: see [`authenticate`].

use std::collections::HashMap;
use std::net::SocketAddr;
use std::sync::Arc;

use fleetlink_auth::audit::AuditAction;
use fleetlink_auth::{
    Access, AuditRecord, ConnInfo, Credential, GroupName, HubName, Identity, IdentityKind,
    Operation, RobotName, Security, UnixTime, UserName,
};
use fleetlink_relay::gate::{Caller, Gate, Guard, Op};
use serde_json::{Map, Value};

use crate::registry::Registry;

fn operation(op: Op) -> Operation {
    match op {
        Op::Publish => Operation::Publish,
        Op::Subscribe => Operation::Subscribe,
        Op::CallService => Operation::CallService,
        Op::AdvertiseService => Operation::AdvertiseService,
        Op::SendActionGoal | Op::CancelActionGoal => Operation::SendActionGoal,
        Op::AdvertiseAction => Operation::AdvertiseAction,
    }
}

fn audit_action(op: Op) -> AuditAction {
    match op {
        Op::Publish => AuditAction::Publish,
        Op::Subscribe => AuditAction::Subscribe,
        Op::CallService => AuditAction::CallService,
        Op::AdvertiseService => AuditAction::AdvertiseService,
        Op::SendActionGoal => AuditAction::SendActionGoal,
        Op::CancelActionGoal => AuditAction::CancelActionGoal,
        Op::AdvertiseAction => AuditAction::AdvertiseAction,
    }
}

/// One connection's gate: its identity's cached decisions, plus the audit log.
pub struct HubGate {
    access: Access,
    security: Arc<Security>,
    registry: Arc<Registry>,
    /// Refusals already audited on this connection: a client retrying a refused publish
    /// 30 times a second is recorded once per name, not flooding the log.
    reported: std::collections::HashSet<(String, Op)>,
    /// The robot an agent link speaks for (its HELLO name): what it publishes under that
    /// namespace is the robot's own output, not an input to audit.
    acting_as: Option<String>,
    /// The last [`HubGate::robot_input`] answer: the topic asked about, the registry's
    /// generation then, and the answer. A client mostly publishes one topic after
    /// another, so this saves splitting the name and a registry lookup per message (the
    /// identity and `acting_as` never change for a gate).
    last_input: Option<(String, u64, bool)>,
    /// Calls of robots' configuration and black-box services are let through (the gate
    /// of a site hub's link upstream: the hub there answers its API through them).
    hub_calls: bool,
    /// Decisions by router topic id, with the rules' generation they were made in: the
    /// publish and delivery paths ask once per message, and an id is cheaper to look up
    /// than a name.
    by_topic: HashMap<(u32, Op), (u64, bool), foldhash::fast::RandomState>,
}

/// Topic decisions a gate keeps by id before it starts afresh.
const BY_TOPIC_CAPACITY: usize = 1 << 16;

impl HubGate {
    pub fn new(security: Arc<Security>, registry: Arc<Registry>, identity: Identity) -> HubGate {
        HubGate {
            access: security.access(identity),
            security,
            registry,
            reported: Default::default(),
            acting_as: None,
            last_input: None,
            hub_calls: false,
            by_topic: HashMap::default(),
        }
    }

    /// A gate for the link to a hub upstream (a site hub's): as [`HubGate::new`], and
    /// the hub there may call the robots' configuration and black-box services (its API
    /// checks who may change a robot's configuration or read its topics).
    pub fn for_upstream(
        security: Arc<Security>,
        registry: Arc<Registry>,
        identity: Identity,
    ) -> HubGate {
        HubGate {
            hub_calls: true,
            ..HubGate::new(security, registry, identity)
        }
    }

    /// A gate for an agent link that speaks for robot `robot`.
    pub fn for_agent(
        security: Arc<Security>,
        registry: Arc<Registry>,
        identity: Identity,
        robot: &str,
    ) -> HubGate {
        HubGate {
            acting_as: Some(robot.to_owned()),
            ..HubGate::new(security, registry, identity)
        }
    }

    pub fn identity(&self) -> &Identity {
        self.access.identity()
    }

    /// Whether this gate speaks for the namespace `ns` (`robot1`, or `site7/robot1` of a
    /// site hub's robot): the link of the agent (or site hub) that owns its first
    /// segment, or that robot's own credential.
    fn speaks_for(&self, ns: &str) -> bool {
        let owner = ns.split('/').next().unwrap_or(ns);
        self.acting_as.as_deref() == Some(owner)
            || matches!(&self.identity().kind, IdentityKind::Robot { name } if name.as_str() == owner)
    }

    /// Whether `name` is an input of some online robot: a topic in its namespace that the
    /// robot did not publish itself. Publishing there acts on a robot and is audited.
    fn robot_input(&mut self, name: &str) -> bool {
        let generation = self.registry.generation();
        if let Some((topic, g, answer)) = &self.last_input
            && *g == generation
            && topic == name
        {
            return *answer;
        }
        let answer = self.robot_input_now(name);
        match &mut self.last_input {
            // The same allocation for the next name, most of the time.
            Some((topic, g, a)) => {
                topic.clear();
                topic.push_str(name);
                (*g, *a) = (generation, answer);
            }
            None => self.last_input = Some((name.to_owned(), generation, answer)),
        }
        answer
    }

    /// [`HubGate::robot_input`] without the cache.
    fn robot_input_now(&self, name: &str) -> bool {
        let Some(first) = name.strip_prefix('/').and_then(|n| n.split('/').next()) else {
            return false;
        };
        if let IdentityKind::Robot { name: me } = &self.identity().kind
            && me.as_str() == first
        {
            return false;
        }
        if self.acting_as.as_deref() == Some(first) {
            return false;
        }
        self.registry.is_online(first)
    }
}

/// Whether `name` is one of a robot's configuration services (`/<robot>/fleetlink/config/
/// get` and `…/set`): only the hub calls them, for `/api/v1/robots/<robot>/config`.
pub fn is_config_service(name: &str) -> bool {
    use fleetlink_relay::names::{HubOnly, hub_only};
    matches!(hub_only(name), Some((HubOnly::ConfigService, _)))
}

/// Why `op` on the hub-only name `name` is refused to this gate, if it is
/// ([`fleetlink_relay::names::hub_only`]): the hub calls those services itself, and reads
/// the black box's answers itself, for its API. A site hub's link upstream may call a
/// robot's configuration and black-box services (the hub there answers for its API); a
/// robot's own link publishes its black box's data.
fn hub_only_refusal(gate: &HubGate, name: &str, op: Op) -> Option<&'static str> {
    use fleetlink_relay::names::{HubOnly, hub_only};
    let (kind, robot) = hub_only(name)?;
    match (kind, op) {
        (HubOnly::ConfigService, Op::CallService) if !gate.hub_calls => {
            Some("a robot's configuration changes through the hub's API only")
        }
        (HubOnly::BlackboxService, Op::CallService) if !gate.hub_calls => Some(
            "a robot's black box is fetched through the hub's API only \
             (POST /api/v1/recordings/blackbox)",
        ),
        (HubOnly::ConfigService | HubOnly::BlackboxService, Op::AdvertiseService) => (!gate
            .speaks_for(robot))
        .then_some("only the robot itself provides its fleetlink services"),
        (HubOnly::BlackboxData, Op::Subscribe) => Some(
            "a robot's black-box data is read by the hub only; fetch a slice through \
             the hub's API",
        ),
        (HubOnly::BlackboxData, Op::Publish) => (!gate.speaks_for(robot))
            .then_some("only the robot itself publishes its black-box data"),
        _ => None,
    }
}

impl HubGate {
    /// Audits a refusal of `op` on `name`, once per name and operation on this connection
    /// (a client retrying 30 times a second is one record), with `detail`'s reason.
    fn audit_refusal(&mut self, name: &str, op: Op, detail: impl FnOnce() -> String) {
        if self.reported.len() < 1024 && self.reported.insert((name.to_owned(), op)) {
            let rec = AuditRecord::operation(
                self.identity(),
                audit_action(op),
                name,
                None,
                false,
                UnixTime::now(),
            )
            .with_detail(detail());
            self.security.audit.record(rec);
        }
    }
}

impl Gate for HubGate {
    /// Decides on the name by the one name rule ([`fleetlink_relay::names::normalize`]):
    /// `/r1/secret/` and `r1/secret` are `/r1/secret`, so no spelling gets round a rule;
    /// a name that is no name is refused. Callers forward the normalized name.
    fn allows(&mut self, name: &str, op: Op) -> bool {
        let name = match fleetlink_relay::names::normalize(name) {
            Ok(n) => n,
            Err(e) => {
                self.audit_refusal(name, op, || e.to_string());
                return false;
            }
        };
        if let Some(why) = hub_only_refusal(self, &name, op) {
            self.audit_refusal(&name, op, || why.into());
            return false;
        }
        let d = self.access.decide(&name, operation(op));
        if !d.allowed {
            self.audit_refusal(&name, op, || format!("{:?}", d.reason));
        }
        d.allowed
    }

    fn allows_topic(&mut self, topic: u32, name: &str, op: Op) -> bool {
        let generation = self.access.current_generation();
        if let Some(&(g, ok)) = self.by_topic.get(&(topic, op))
            && g == generation
        {
            return ok;
        }
        let ok = self.allows(name, op);
        if self.by_topic.len() >= BY_TOPIC_CAPACITY {
            self.by_topic.clear();
        }
        self.by_topic.insert((topic, op), (generation, ok));
        ok
    }

    fn done(&mut self, name: &str, op: Op, size: usize) {
        let audited = match op {
            Op::Publish => self.robot_input(name),
            Op::AdvertiseService | Op::AdvertiseAction => true,
            // Calls and goals are recorded when they end, with their outcome.
            _ => false,
        };
        if audited {
            let rec = AuditRecord::operation(
                self.identity(),
                audit_action(op),
                name,
                Some(size as u64),
                true,
                UnixTime::now(),
            );
            self.security.audit.record(rec);
        }
    }

    fn finished(&mut self, name: &str, op: Op, size: usize, outcome: &str) {
        let rec = AuditRecord::operation(
            self.identity(),
            audit_action(op),
            name,
            Some(size as u64),
            true,
            UnixTime::now(),
        )
        .with_detail(outcome.chars().take(500).collect::<String>());
        self.security.audit.record(rec);
    }

    fn rules_changed(&self) -> Option<tokio::sync::watch::Receiver<u64>> {
        Some(self.access.watch_rules())
    }

    fn fork(&self) -> Box<dyn Gate> {
        Box::new(HubGate {
            access: self.access.clone(),
            security: self.security.clone(),
            registry: self.registry.clone(),
            reported: Default::default(),
            acting_as: self.acting_as.clone(),
            last_input: None,
            hub_calls: self.hub_calls,
            by_topic: HashMap::default(),
        })
    }

    fn principal(&self) -> String {
        self.identity().principal()
    }

    fn caller(&self) -> Option<Caller> {
        let id = self.identity();
        if id.source.hub.is_some() {
            // Vouched for by another hub already: not forwarded a second time.
            return None;
        }
        Some(match &id.kind {
            IdentityKind::Robot { name } => Caller::Robot {
                name: name.as_str().to_owned(),
            },
            IdentityKind::User { name, groups } => Caller::User {
                name: name.as_str().to_owned(),
                groups: groups.iter().map(|g| g.as_str().to_owned()).collect(),
            },
            IdentityKind::Anonymous => Caller::Anonymous,
            IdentityKind::Hub { .. } => return None,
        })
    }
}

/// The identity a hub vouches for when it forwards a call `caller` made there: that
/// caller, marked as coming through hub `hub` (rules naming the hub apply, and the audit
/// log says so). `None` when a name in it breaks the rules for names.
pub fn vouched_identity(
    caller: &Caller,
    hub: &HubName,
    peer: std::net::IpAddr,
) -> Option<Identity> {
    let kind = match caller {
        Caller::Robot { name } => IdentityKind::Robot {
            name: RobotName::new(name).ok()?,
        },
        Caller::User { name, groups } => IdentityKind::User {
            name: UserName::new(name).ok()?,
            groups: groups
                .iter()
                .map(|g| GroupName::new(g).ok())
                .collect::<Option<Vec<_>>>()?,
        },
        Caller::Anonymous => IdentityKind::Anonymous,
    };
    Some(Identity {
        kind,
        source: ConnInfo::new(peer).with_hub(hub.clone()),
        client_ip: peer,
    })
}

/// A federated hub acting for itself (the topics it forwards), as rules see it.
pub fn hub_identity(hub: &HubName, peer: std::net::IpAddr) -> Identity {
    Identity {
        kind: IdentityKind::Hub { name: hub.clone() },
        source: ConnInfo::new(peer).with_hub(hub.clone()),
        client_ip: peer,
    }
}

/// Authenticates `auth` operations of one rosbridge connection.
pub struct HubGuard {
    pub security: Arc<Security>,
    pub registry: Arc<Registry>,
    pub conn: ConnInfo,
}

/// The longest credential field accepted in an `auth` operation.
const MAX_AUTH_FIELD: usize = 8 * 1024;

impl Guard for HubGuard {
    fn authenticate(&self, fields: &Map<String, Value>) -> Result<Box<dyn Gate>, String> {
        let text = |k: &str| fields.get(k).and_then(Value::as_str);
        for (k, v) in fields {
            if let Value::String(s) = v
                && s.len() > MAX_AUTH_FIELD
            {
                // Refused before the core sees it, so audited here.
                let err = fleetlink_auth::AuthError::Oversized {
                    what: "auth field",
                    len: s.len(),
                    max: MAX_AUTH_FIELD,
                };
                let ip = self
                    .security
                    .authn
                    .policy()
                    .trusted_proxies
                    .client_ip(&self.conn);
                self.security.audit.record(AuditRecord::auth_failure(
                    ip,
                    None,
                    &err,
                    UnixTime::now(),
                ));
                return Err(format!(
                    "field '{k}' is {} bytes, over the {MAX_AUTH_FIELD}-byte limit",
                    s.len()
                ));
            }
        }
        let credential = if let Some(t) = text("token").or_else(|| text("mac")) {
            Credential::Bearer(t.to_owned())
        } else if let (Some(u), Some(p)) = (text("user"), text("password")) {
            Credential::Password {
                user: u.to_owned(),
                password: p.to_owned(),
            }
        } else {
            return Err(
                "send 'token' (or 'mac') with a fleetlink or OIDC token, or 'user' and 'password'"
                    .into(),
            );
        };
        let security = self.security.clone();
        let conn = self.conn.clone();
        let identity = blocking(move || security.authenticate(credential, conn, UnixTime::now()))
            .map_err(|e| e.public_message())?;
        Ok(Box::new(HubGate::new(
            self.security.clone(),
            self.registry.clone(),
            identity,
        )))
    }
}

/// Runs a credential check off the async workers when the runtime allows it.
fn blocking<T>(f: impl FnOnce() -> T) -> T {
    match tokio::runtime::Handle::try_current().map(|h| h.runtime_flavor()) {
        Ok(tokio::runtime::RuntimeFlavor::MultiThread) => tokio::task::block_in_place(f),
        _ => f(),
    }
}

/// Checks a credential on the blocking pool.
pub async fn authenticate(
    security: &Arc<Security>,
    credential: Credential,
    conn: ConnInfo,
) -> Result<Identity, fleetlink_auth::AuthError> {
    let security = security.clone();
    match tokio::task::spawn_blocking(move || {
        security.authenticate(credential, conn, UnixTime::now())
    })
    .await
    {
        Ok(r) => r,
        Err(_) => Err(fleetlink_auth::AuthError::Missing),
    }
}

/// Where a connection comes from, for the security layer.
pub fn conn_info(
    peer: SocketAddr,
    headers: &axum::http::HeaderMap,
    tls_name: Option<fleetlink_auth::RobotName>,
) -> ConnInfo {
    let mut c = ConnInfo::new(peer.ip());
    if let Some(xff) = headers.get("x-forwarded-for").and_then(|v| v.to_str().ok()) {
        c = c.with_forwarded_for(xff);
    }
    if let Some(n) = tls_name {
        c = c.with_tls_client_name(n);
    }
    c
}

/// The credential an HTTP request carries: `Authorization: Bearer`, else `?token=`.
pub fn request_credential(headers: &axum::http::HeaderMap, query: Option<&str>) -> Credential {
    if let Some(c) = headers
        .get(axum::http::header::AUTHORIZATION)
        .and_then(|v| v.to_str().ok())
        .and_then(Credential::from_authorization_header)
    {
        return c;
    }
    if let Some(q) = query {
        for pair in q.split('&') {
            if let Some(t) = pair.strip_prefix("token=")
                && !t.is_empty()
            {
                return Credential::Bearer(percent_decode(t));
            }
        }
    }
    Credential::None
}

/// Tokens are base64url; only `%XX` escapes a browser may add need undoing.
fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%'
            && i + 2 < b.len()
            && let Ok(v) = u8::from_str_radix(&s[i + 1..i + 3], 16)
        {
            out.push(v);
            i += 3;
            continue;
        }
        out.push(b[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[cfg(test)]
#[path = "security_tests.rs"]
mod tests;
