//! Access decisions: the shared [`Authorizer`] and the per-connection [`Access`] cache.
//!
//! Design choice: the rule set is compiled once and swapped whole (`ArcSwap`) on every
//! change, together with a bump of an atomic generation counter. Each connection holds an
//! [`Access`]: the rules that can apply to its identity (filtered once per generation) and
//! a cache of decisions keyed by name, one slot per operation. A check on the hot path is
//! therefore one atomic load plus one hash lookup, with no lock shared between
//! connections; a rule change makes every `Access` drop its cache on its next check, so
//! it also takes effect on live subscriptions when the hub checks on delivery.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use arc_swap::ArcSwap;

use super::rule::{Effect, OpSet, Operation, RuleId, StoredRule};
use crate::identity::{GroupName, Identity, IdentityKind};

/// Built-in grants that hold whatever the rules say (explicit `deny` rules still win,
/// except over the admin group).
#[derive(Debug, Clone)]
pub struct AclDefaults {
    /// What a robot may do under its own namespace `/<robot>/...`.
    pub robot_own_namespace: OpSet,
    /// Members of this group may do everything (the demo's operator token is in it).
    pub admin_group: Option<GroupName>,
    /// Members of this group may scrape `/metrics` (`admin` on the resource
    /// [`METRICS`]) and nothing else: the group for a Prometheus token.
    pub metrics_group: Option<GroupName>,
    /// Anonymous identities may subscribe to anything, call `/rosapi/*` (listings) and
    /// read [`METRICS`]. Only meaningful if the authenticator lets anonymous clients in.
    pub anonymous_read: bool,
    /// What a federated hub may do acting for itself ([`IdentityKind::Hub`]): forward the
    /// topics its clients publish (their rights were checked there) and subscribe for
    /// them. `deny` rules naming the hub limit it. Calls it forwards are decided on the
    /// identity of the client who made them.
    pub federated_hub: OpSet,
}

/// The resource name of the hub's Prometheus metrics, checked with [`Operation::Admin`].
pub const METRICS: &str = "/metrics";

impl Default for AclDefaults {
    fn default() -> AclDefaults {
        AclDefaults {
            robot_own_namespace: OpSet::of(&[
                Operation::Publish,
                Operation::Subscribe,
                Operation::AdvertiseService,
                Operation::AdvertiseAction,
                Operation::CallService,
                Operation::SendActionGoal,
            ]),
            admin_group: GroupName::new("admin").ok(),
            metrics_group: GroupName::new("metrics").ok(),
            anonymous_read: false,
            federated_hub: OpSet::of(&[Operation::Publish, Operation::Subscribe]),
        }
    }
}

impl AclDefaults {
    /// `fleetlink demo`: the defaults plus read access for anonymous (loopback) clients.
    pub fn demo() -> AclDefaults {
        AclDefaults {
            anonymous_read: true,
            ..AclDefaults::default()
        }
    }
}

/// Why a decision came out the way it did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Reason {
    AdminGroup,
    MetricsGroup,
    OwnNamespace,
    AnonymousRead,
    /// A federated hub forwarding for its clients ([`AclDefaults::federated_hub`]).
    FederatedHub,
    Rule(RuleId),
    /// Nothing granted it: deny by default.
    NoRule,
}

/// An access decision.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Decision {
    pub allowed: bool,
    pub reason: Reason,
}

impl Decision {
    const fn allow(reason: Reason) -> Decision {
        Decision {
            allowed: true,
            reason,
        }
    }

    const fn deny(reason: Reason) -> Decision {
        Decision {
            allowed: false,
            reason,
        }
    }
}

/// The compiled rules of one generation.
struct RuleSet {
    generation: u64,
    rules: Arc<[StoredRule]>,
}

/// The shared decision point: rules, defaults and the generation counter.
pub struct Authorizer {
    rules: ArcSwap<RuleSet>,
    generation: AtomicU64,
    defaults: AclDefaults,
    /// The generation installed last, for sessions that act on a change (a viewer's
    /// channel list) instead of asking again on a timer.
    changed: tokio::sync::watch::Sender<u64>,
    // std Mutex: serialises the rare writers so generations are installed in order;
    // never held across an await (there is none) and never taken by readers.
    writer: Mutex<()>,
}

impl Authorizer {
    pub fn new(rules: Vec<StoredRule>, defaults: AclDefaults) -> Authorizer {
        Authorizer {
            rules: ArcSwap::from_pointee(RuleSet {
                generation: 0,
                rules: rules.into(),
            }),
            generation: AtomicU64::new(0),
            defaults,
            changed: tokio::sync::watch::Sender::new(0),
            writer: Mutex::new(()),
        }
    }

    /// Installs a new rule set; every [`Access`] sees it on its next check.
    pub fn replace_rules(&self, rules: Vec<StoredRule>) {
        let _writer = self.writer.lock().unwrap_or_else(|p| p.into_inner());
        // Publish the rules before the generation, so a reader that sees the new
        // generation also loads the new rules.
        let generation = self.rules.load().generation + 1;
        self.rules.store(Arc::new(RuleSet {
            generation,
            rules: rules.into(),
        }));
        self.generation.store(generation, Ordering::Release);
        self.changed.send_replace(generation);
    }

    /// Wakes its holder whenever a new rule set is installed.
    pub fn watch(&self) -> tokio::sync::watch::Receiver<u64> {
        self.changed.subscribe()
    }

    pub fn generation(&self) -> u64 {
        self.generation.load(Ordering::Acquire)
    }

    pub fn rules(&self) -> Vec<StoredRule> {
        self.rules.load().rules.to_vec()
    }

    pub fn defaults(&self) -> &AclDefaults {
        &self.defaults
    }

    /// An uncached decision, for one-off checks (REST handlers, `explain`).
    pub fn decide(&self, identity: &Identity, name: &str, op: Operation) -> Decision {
        let set = self.rules.load();
        let applicable = set
            .rules
            .iter()
            .filter(|r| r.rule.subject.matches(identity));
        evaluate(&self.defaults, identity, applicable, name, op)
    }

    /// A per-connection decision cache for `identity`.
    pub fn access(self: &Arc<Self>, identity: Identity) -> Access {
        let mut access = Access {
            authz: Arc::clone(self),
            identity: Arc::new(identity),
            generation: u64::MAX,
            applicable: Vec::new(),
            cache: HashMap::default(),
        };
        access.refresh();
        access
    }
}

fn evaluate<'a>(
    defaults: &AclDefaults,
    identity: &Identity,
    applicable: impl Iterator<Item = &'a StoredRule>,
    name: &str,
    op: Operation,
) -> Decision {
    // A hub named in a deny rule is limited whoever it vouches for, admins included.
    if identity.hub().is_some() {
        let rules: Vec<&StoredRule> = applicable.collect();
        if let Some(denied) = rules.iter().find(|s| {
            s.rule.effect == Effect::Deny
                && s.rule.subject.is_hub()
                && s.rule.ops.contains(op)
                && s.rule.names.is_match(name)
        }) {
            return Decision::deny(Reason::Rule(denied.id));
        }
        return evaluate_rules(defaults, identity, rules.into_iter(), name, op);
    }
    evaluate_rules(defaults, identity, applicable, name, op)
}

fn evaluate_rules<'a>(
    defaults: &AclDefaults,
    identity: &Identity,
    applicable: impl Iterator<Item = &'a StoredRule>,
    name: &str,
    op: Operation,
) -> Decision {
    if let Some(admin) = &defaults.admin_group
        && identity.in_group(admin)
    {
        return Decision::allow(Reason::AdminGroup);
    }
    let mut granted = None;
    for stored in applicable {
        let rule = &stored.rule;
        if !rule.ops.contains(op) || !rule.names.is_match(name) {
            continue;
        }
        match rule.effect {
            Effect::Deny => return Decision::deny(Reason::Rule(stored.id)),
            Effect::Allow => {
                granted.get_or_insert(Decision::allow(Reason::Rule(stored.id)));
            }
        }
    }
    if let Some(d) = granted {
        return d;
    }
    match &identity.kind {
        IdentityKind::Robot { name: robot }
            if defaults.robot_own_namespace.contains(op) && robot.owns(name) =>
        {
            Decision::allow(Reason::OwnNamespace)
        }
        IdentityKind::Hub { .. } if defaults.federated_hub.contains(op) => {
            Decision::allow(Reason::FederatedHub)
        }
        IdentityKind::Anonymous
            if defaults.anonymous_read
                && (op == Operation::Subscribe
                    || (op == Operation::CallService && name.starts_with("/rosapi/"))
                    || (op == Operation::Admin && name == METRICS)) =>
        {
            Decision::allow(Reason::AnonymousRead)
        }
        _ if op == Operation::Admin
            && name == METRICS
            && defaults
                .metrics_group
                .as_ref()
                .is_some_and(|g| identity.in_group(g)) =>
        {
            Decision::allow(Reason::MetricsGroup)
        }
        _ => Decision::deny(Reason::NoRule),
    }
}

/// Distinct names cached per connection before the cache is cleared, so a client that
/// probes millions of names cannot grow it without bound. Large enough for a fleet-wide
/// subscription: its writer checks every delivered message, and a subscriber to all of
/// 1,000 robots' ten topics would otherwise clear and refill a smaller cache endlessly
/// (at 4,096 names that was the hub's costliest function, measured with `bench fleet`).
/// An entry is about 100 bytes; only connections that see that many names fill it.
const CACHE_CAPACITY: usize = 1 << 16;

type Slots = [Option<Decision>; Operation::ALL.len()];

/// One connection's view of the rules, with its decision cache.
///
/// Owned by the connection (checks take `&mut self`); clone it to give another task of
/// the same connection its own cache.
#[derive(Clone)]
pub struct Access {
    authz: Arc<Authorizer>,
    identity: Arc<Identity>,
    generation: u64,
    /// Rules whose subject matches this identity, in this generation.
    applicable: Vec<StoredRule>,
    cache: HashMap<Box<str>, Slots, foldhash::fast::RandomState>,
}

impl Access {
    pub fn identity(&self) -> &Identity {
        &self.identity
    }

    /// Wakes its holder whenever the rules change ([`Authorizer::watch`]).
    pub fn watch_rules(&self) -> tokio::sync::watch::Receiver<u64> {
        self.authz.watch()
    }

    /// The rules' generation now: a decision cached by a caller stays true while this
    /// does not change.
    pub fn current_generation(&self) -> u64 {
        self.authz.generation.load(Ordering::Acquire)
    }

    fn refresh(&mut self) {
        let set = self.authz.rules.load();
        self.applicable = set
            .rules
            .iter()
            .filter(|r| r.rule.subject.matches(&self.identity))
            .cloned()
            .collect();
        self.generation = set.generation;
        self.cache.clear();
    }

    /// The decision for `op` on `name`; cached until the rules change.
    pub fn decide(&mut self, name: &str, op: Operation) -> Decision {
        if self.authz.generation.load(Ordering::Acquire) != self.generation {
            self.refresh();
        }
        if let Some(slots) = self.cache.get(name)
            && let Some(d) = slots[op.index()]
        {
            return d;
        }
        let d = evaluate(
            &self.authz.defaults,
            &self.identity,
            self.applicable.iter(),
            name,
            op,
        );
        if self.cache.len() >= CACHE_CAPACITY && !self.cache.contains_key(name) {
            self.cache.clear();
        }
        self.cache
            .entry(name.into())
            .or_insert([None; Operation::ALL.len()])[op.index()] = Some(d);
        d
    }

    pub fn allows(&mut self, name: &str, op: Operation) -> bool {
        self.decide(name, op).allowed
    }

    /// The names among `names` this identity may `op` — for `/rosapi` listings and for
    /// expanding regex subscriptions.
    pub fn visible<'n, I>(&mut self, names: I, op: Operation) -> Vec<&'n str>
    where
        I: IntoIterator<Item = &'n str>,
    {
        names.into_iter().filter(|n| self.allows(n, op)).collect()
    }

    /// Number of cached names (for tests and metrics).
    pub fn cached_names(&self) -> usize {
        self.cache.len()
    }
}
