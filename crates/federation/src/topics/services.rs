//! The services and actions other hubs offer: which hub provides each one that this hub
//! routes calls to ([`Providers`], read by [`crate::calls`]), and the federation's
//! advertisement of it on this hub's call table.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use fleetlink_proto::Schema;
use fleetlink_relay::{ClientId, Router, TopicName};

/// Which hub provides each remote service or action this hub routes calls to.
pub type Providers = Arc<Mutex<HashMap<TopicName, String>>>;

/// A remote service or action: the hubs offering it, with type and kind.
#[derive(Default)]
struct RemoteService {
    from: HashMap<String, (String, bool)>,
}

/// The remote services and actions, one per name an admitted hub offers (let go when no
/// hub offers it any more), and the provider hub chosen for each.
pub(super) struct Services {
    router: Arc<Router>,
    /// The federation's client on this hub's router, the provider it advertises.
    me: ClientId,
    by_name: HashMap<TopicName, RemoteService>,
    providers: Providers,
}

impl Services {
    pub(super) fn new(router: Arc<Router>, me: ClientId) -> Services {
        Services {
            router,
            me,
            by_name: HashMap::new(),
            providers: Providers::default(),
        }
    }

    pub(super) fn providers(&self) -> Providers {
        self.providers.clone()
    }

    /// A remote hub offers (or withdrew) a service or action: this hub provides it
    /// through the federation while no client here provides it itself.
    pub(super) fn offer(
        &mut self,
        hub: String,
        name: String,
        type_name: String,
        action: bool,
        put: bool,
    ) {
        let Ok(name) = TopicName::parse(&name) else {
            return;
        };
        let me = self.me;
        let calls = &self.router.calls;
        let entry = self.by_name.entry(name.clone()).or_default();
        if put {
            entry.from.insert(hub, (type_name, action));
        } else if entry
            .from
            .get(&hub)
            .is_some_and(|(t, a)| *t == type_name && *a == action)
        {
            entry.from.remove(&hub);
        } else {
            return;
        }
        let mut providers = self.providers.lock().unwrap_or_else(|p| p.into_inner());
        // Keep the current provider hub while it offers; otherwise take any other.
        let next = match providers.get(&name) {
            Some(h) if entry.from.contains_key(h) => Some(h.clone()),
            _ => entry.from.keys().next().cloned(),
        };
        match next {
            Some(h) => {
                if calls.service(&name).is_some_and(|s| s.provider != me) {
                    return; // a client here provides it: calls stay on this hub
                }
                let (type_name, action) = entry.from[&h].clone();
                providers.insert(name.clone(), h);
                drop(providers);
                calls.advertise(me, name, Schema::named(type_name), action);
            }
            None => {
                providers.remove(&name);
                drop(providers);
                self.by_name.remove(&name);
                calls.unadvertise(me, &name);
            }
        }
    }
}
