//! Hubs federated in one process: a router, its rules and a federation each, linked by
//! Zenoh over plain TCP on loopback; and the waits the tests share.

use std::future::Future;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_auth::{
    AclDefaults, AuthPolicy, ConnInfo, GroupName, Identity, IdentityKind, Security, Store,
    UnixTime, UserName,
};
use fleetlink_federation::{Federation, Settings, Trust, TrustArgs, zenoh_config};
use fleetlink_hub::registry::Registry;
use fleetlink_relay::Router;
use tokio_util::sync::CancellationToken;

/// The fleet every test hub joins.
pub const FLEET: &str = "test";

/// How long a test waits for something to cross between hubs.
const PATIENCE: Duration = Duration::from_secs(20);

/// A hub's router, rules and federation; the federation stops when it is dropped.
pub struct Hub {
    pub router: Arc<Router>,
    pub security: Arc<Security>,
    pub federation: Federation,
    stop: CancellationToken,
}

impl Drop for Hub {
    fn drop(&mut self) {
        self.stop.cancel();
    }
}

/// The Zenoh configuration of a peer of [`FLEET`] over plain TCP (every peer believed).
pub fn plain_tcp(connect: &[String], listen: &[String]) -> (zenoh::Config, Trust) {
    let trust = TrustArgs {
        insecure_tcp: true,
        ..TrustArgs::default()
    };
    zenoh_config(None, Some("peer"), connect, listen, FLEET, &trust)
        .expect("a plain TCP configuration")
}

/// A hub named `name` that connects to `connect` and listens on `listen`.
async fn start(name: &str, connect: &[String], listen: &[String]) -> Result<Hub, String> {
    let (cfg, trust) = plain_tcp(connect, listen);
    let router = Arc::new(Router::default());
    let store = Store::open_in_memory().expect("an in-memory store");
    let security = Arc::new(
        Security::new(store, AuthPolicy::default(), AclDefaults::default()).expect("rules"),
    );
    let stop = CancellationToken::new();
    let settings = Settings {
        fleet: FLEET.into(),
        hub_name: name.into(),
        zenoh: cfg,
        trust,
    };
    let federation = Federation::start(
        settings,
        router.clone(),
        Arc::new(Registry::default()),
        security.clone(),
        stop.clone(),
    )
    .await
    .map_err(|e| e.to_string())?;
    Ok(Hub {
        router,
        security,
        federation,
        stop,
    })
}

/// A hub that other hubs connect to, and its endpoint. The port is one the system just
/// gave out (port 0) and let go; taken meanwhile, another is tried.
pub async fn listening_hub(name: &str) -> (Hub, String) {
    let mut last = String::new();
    for _ in 0..5 {
        let port = std::net::TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .expect("a free port")
            .port();
        let endpoint = format!("tcp/127.0.0.1:{port}");
        match start(name, &[], std::slice::from_ref(&endpoint)).await {
            Ok(hub) => return (hub, endpoint),
            Err(e) => last = e,
        }
    }
    panic!("hub {name} could not listen: {last}");
}

/// A hub linked to the hub at `endpoint`.
pub async fn hub_linked_to(name: &str, endpoint: &str) -> Hub {
    start(name, &[endpoint.to_owned()], &[])
        .await
        .unwrap_or_else(|e| panic!("hub {name}: {e}"))
}

impl Hub {
    /// Replaces the hub's access rules with a YAML document, as an administrator.
    pub fn set_rules(&self, yaml: &str) {
        let ip = "127.0.0.1".parse().unwrap();
        let admin = Identity {
            kind: IdentityKind::User {
                name: UserName::new("root").unwrap(),
                groups: vec![GroupName::new("admin").unwrap()],
            },
            source: ConnInfo::new(ip),
            client_ip: ip,
        };
        self.security
            .import_rules_yaml(&admin, yaml, UnixTime::now())
            .expect("rules");
    }
}

/// Waits until `done` holds, looking every 20 ms; fails the test naming `what` after
/// [`PATIENCE`].
pub async fn eventually(what: &str, mut done: impl FnMut() -> bool) {
    within(what, async {
        while !done() {
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
}

/// `fut`'s outcome; fails the test naming `what` after [`PATIENCE`].
pub async fn within<T>(what: &str, fut: impl Future<Output = T>) -> T {
    tokio::time::timeout(PATIENCE, fut)
        .await
        .unwrap_or_else(|_| panic!("{what}: not within {PATIENCE:?}"))
}
