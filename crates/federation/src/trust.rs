//! How hubs prove who they are before anything crosses between them.
//!
//! - **Transport.** Zenoh's own TLS transport with certificates on both ends: every hub
//!   holds a certificate of its fleet's CA whose common name is `HUB@FLEET`
//!   ([`fleetlink_auth::tls::federation`]), presents it on every link it makes and
//!   accepts, and accepts only certificates of that CA. A hub listens only on the
//!   endpoints it is given (never on Zenoh's default `tcp/[::]:0`), and every endpoint it
//!   listens on or connects to is `tls/…`. Plain TCP is an explicit, loudly logged
//!   opt-in ([`Trust::PlainTcp`]) for a private network.
//! - **Admission.** Zenoh tells which certificate name each link presented (its "auth
//!   identifier"). A hub is *admitted* — its offers listed, its wants served, its calls
//!   answered, its messages published here — only once a link to it has shown a name of
//!   this fleet; that name, not what the hub says of itself, is how rules and the audit
//!   log know it. A link showing another name is refused with a log line saying why, and
//!   nothing it offers is taken. ([`Admission`]; the loops ask it for every token, call
//!   and subscription.)
//!
//! Design choice: Zenoh's TLS client side also trusts the web's public roots, which a
//! fleet's private CA cannot switch off; admission by name closes that door, since no
//! public CA issues a `HUB@FLEET` name, and Zenoh's default server-name check on connect
//! stays on. Within a fleet, hubs trust each other to say which of their clients made a
//! call: each hub holds a certificate of the same CA, and the robot's hub still decides
//! every call with its own rules.

use std::collections::{HashMap, HashSet};
use std::net::{IpAddr, Ipv6Addr, SocketAddr};
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use fleetlink_auth::tls::federation::{FederationFiles, HubCertName, check_own};
use tokio::sync::watch;

use crate::{FederationError, TrustArgs};

/// How this hub authenticates the others.
#[derive(Debug, Clone)]
pub enum Trust {
    /// Mutual TLS with the fleet's CA; this hub's own certificate name.
    Tls {
        files: FederationFiles,
        me: HubCertName,
    },
    /// Plain TCP: any process that reaches an endpoint is taken for a hub of the fleet.
    PlainTcp,
}

/// A peer hub this hub admitted: the name its certificate holds (or, over plain TCP, the
/// name it gave itself), and the address its link comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Admitted {
    pub name: String,
    pub addr: IpAddr,
}

/// The TLS section of a Zenoh configuration.
const TLS: &str = "transport/link/tls";

/// How this hub authenticates the others, from the flags or the Zenoh file's TLS section
/// (the flags win), with this hub's own files checked ([`check_own`]); the TLS section
/// is completed for mutual TLS on both listening and connecting links.
pub fn resolve(
    cfg: &mut zenoh::Config,
    fleet: &str,
    args: &TrustArgs,
) -> Result<Trust, FederationError> {
    let from_file = |key: &str| -> Option<PathBuf> {
        cfg.get_json(&format!("{TLS}/{key}"))
            .ok()
            .and_then(|j| serde_json::from_str::<Option<String>>(&j).ok().flatten())
            .map(PathBuf::from)
    };
    let ca = args.ca.clone().or_else(|| from_file("root_ca_certificate"));
    let cert = args
        .cert
        .clone()
        .or_else(|| from_file("listen_certificate"));
    let key = args.key.clone().or_else(|| from_file("listen_private_key"));
    if args.insecure_tcp {
        if args.ca.is_some() || args.cert.is_some() || args.key.is_some() {
            return Err(FederationError::Config(
                "--zenoh-insecure-tcp and --zenoh-ca/--zenoh-cert/--zenoh-key: choose \
                 certificates (TLS) or plain TCP"
                    .into(),
            ));
        }
        return Ok(Trust::PlainTcp);
    }
    let (Some(ca), Some(cert), Some(key)) = (ca, cert, key) else {
        return Err(FederationError::Unauthenticated {
            fleet: fleet.to_owned(),
        });
    };
    let files = FederationFiles { ca, cert, key };
    let me = check_own(&files, fleet, fleetlink_auth::UnixTime::now())?;
    let path = |p: &PathBuf| serde_json::to_string(&p.to_string_lossy()).expect("a string");
    for (k, v) in [
        ("root_ca_certificate", path(&files.ca)),
        ("listen_certificate", path(&files.cert)),
        ("listen_private_key", path(&files.key)),
        ("connect_certificate", path(&files.cert)),
        ("connect_private_key", path(&files.key)),
        ("enable_mtls", "true".to_owned()),
    ] {
        cfg.insert_json5(&format!("{TLS}/{k}"), &v)
            .map_err(|e| FederationError::Config(format!("{TLS}/{k}: {e}")))?;
    }
    Ok(Trust::Tls { files, me })
}

/// The address of a Zenoh locator (`tls/10.0.0.2:7447`, `tcp/[::1]:7447`).
fn locator_ip(locator: &str) -> IpAddr {
    locator
        .split_once('/')
        .and_then(|(_, addr)| addr.split(['?', '#']).next())
        .and_then(|a| a.parse::<SocketAddr>().ok())
        .map_or(IpAddr::V6(Ipv6Addr::UNSPECIFIED), |a| a.ip())
}

/// How many refused hubs the book remembers (the latest): a Zenoh id is its session's own
/// choice, so a peer reconnecting under fresh ids must not grow the book without end.
const REFUSED_KEPT: usize = 1024;

#[derive(Default)]
struct Book {
    /// Admitted hubs by Zenoh id, with how many of their links are up.
    admitted: HashMap<String, (Admitted, usize)>,
    /// Hubs refused, by Zenoh id, with why and when (the count of refusals before it);
    /// logged once each while remembered. At most [`REFUSED_KEPT`].
    refused: HashMap<String, (String, u64)>,
    /// Refusals so far.
    refusals: u64,
}

impl Book {
    /// Remembers that hub `zid` was refused for `why`; true if it was not remembered
    /// already. The earliest refusal is forgotten when the book is full.
    fn refuse(&mut self, zid: &str, why: &str) -> bool {
        if let Some((reason, _)) = self.refused.get_mut(zid) {
            why.clone_into(reason);
            return false;
        }
        if self.refused.len() >= REFUSED_KEPT {
            let oldest = self
                .refused
                .iter()
                .min_by_key(|(_, (_, at))| *at)
                .map(|(z, _)| z.clone());
            if let Some(z) = oldest {
                self.refused.remove(&z);
            }
        }
        self.refusals += 1;
        self.refused
            .insert(zid.to_owned(), (why.to_owned(), self.refusals));
        true
    }
}

/// Which hubs of the federation this hub admits, kept from Zenoh's link events.
pub struct Admission {
    trust: Trust,
    fleet: String,
    book: Mutex<Book>,
    /// Bumped whenever a hub is admitted, for the loops that park what came earlier.
    changed: watch::Sender<u64>,
}

impl Admission {
    pub fn new(trust: Trust, fleet: &str) -> Arc<Admission> {
        Arc::new(Admission {
            trust,
            fleet: fleet.to_owned(),
            book: Mutex::new(Book::default()),
            changed: watch::channel(0).0,
        })
    }

    pub fn is_plain_tcp(&self) -> bool {
        matches!(self.trust, Trust::PlainTcp)
    }

    /// The admitted hub with Zenoh id `zid`, if it is admitted. Over plain TCP every hub
    /// is, named by its own token (`None` here until then: callers fall back to the id).
    pub fn admitted(&self, zid: &str) -> Option<Admitted> {
        let book = self.book.lock().unwrap_or_else(|p| p.into_inner());
        book.admitted.get(zid).map(|(a, _)| a.clone())
    }

    /// Whether anything from hub `zid` may be taken.
    pub fn is_admitted(&self, zid: &str) -> bool {
        self.is_plain_tcp() || self.admitted(zid).is_some()
    }

    /// Why hub `zid` was refused, if it was.
    pub fn refusal(&self, zid: &str) -> Option<String> {
        let book = self.book.lock().unwrap_or_else(|p| p.into_inner());
        book.refused.get(zid).map(|(why, _)| why.clone())
    }

    /// Hubs refused (the latest [`REFUSED_KEPT`]): Zenoh id and reason.
    pub fn refused(&self) -> Vec<(String, String)> {
        let book = self.book.lock().unwrap_or_else(|p| p.into_inner());
        let mut v: Vec<_> = book
            .refused
            .iter()
            .map(|(z, (r, _))| (z.clone(), r.clone()))
            .collect();
        v.sort();
        v
    }

    /// A receiver that changes whenever a hub is admitted.
    pub fn subscribe(&self) -> watch::Receiver<u64> {
        self.changed.subscribe()
    }

    /// A link to hub `zid` came up, showing certificate name `auth` (`None`: no
    /// certificate, a plain TCP link). Returns the hub's admission, or why it is refused.
    pub fn link_up(&self, zid: &str, auth: Option<&str>, remote: &str) -> Result<Admitted, String> {
        let addr = locator_ip(remote);
        if self.is_plain_tcp() {
            // Named by its own token; its address kept for rules and the audit log.
            let mut book = self.book.lock().unwrap_or_else(|p| p.into_inner());
            let entry = book.admitted.entry(zid.to_owned()).or_insert((
                Admitted {
                    name: String::new(),
                    addr,
                },
                0,
            ));
            entry.1 += 1;
            return Ok(entry.0.clone());
        }
        let verdict = match auth {
            None => Err(format!(
                "its link from {remote} shows no certificate (only tls/ endpoints with \
                 certificates of the fleet's CA are accepted)"
            )),
            Some(cn) => match HubCertName::parse(cn) {
                Err(e) => Err(format!("its certificate: {e}")),
                Ok(name) if name.fleet != self.fleet => Err(format!(
                    "its certificate names fleet {:?}, this hub's fleet is {:?}",
                    name.fleet, self.fleet
                )),
                Ok(name) => Ok(Admitted {
                    name: name.hub,
                    addr,
                }),
            },
        };
        let mut book = self.book.lock().unwrap_or_else(|p| p.into_inner());
        match verdict {
            Ok(admitted) => {
                if let Some((known, links)) = book.admitted.get_mut(zid) {
                    if known.name != admitted.name {
                        let why = format!(
                            "a second link from {remote} shows {:?} where the first showed {:?}",
                            admitted.name, known.name
                        );
                        tracing::warn!("federation: link of hub {zid} refused: {why}");
                        return Err(why);
                    }
                    *links += 1;
                    return Ok(known.clone());
                }
                book.refused.remove(zid);
                book.admitted.insert(zid.to_owned(), (admitted.clone(), 1));
                drop(book);
                tracing::info!(
                    "federation: hub {} ({zid}) admitted: its certificate from {remote} is of fleet {}",
                    admitted.name,
                    self.fleet
                );
                self.changed.send_modify(|g| *g += 1);
                Ok(admitted)
            }
            Err(why) => {
                if book.refuse(zid, &why) {
                    tracing::warn!("federation: refused hub {zid} at {remote}: {why}");
                }
                Err(why)
            }
        }
    }

    /// A link to hub `zid` went down; the hub stays admitted while another link is up.
    pub fn link_down(&self, zid: &str) {
        let mut book = self.book.lock().unwrap_or_else(|p| p.into_inner());
        if let Some((_, links)) = book.admitted.get_mut(zid) {
            *links = links.saturating_sub(1);
            if *links == 0 {
                book.admitted.remove(zid);
            }
        }
    }

    /// The address hub `zid`'s link comes from (unspecified when not known).
    pub fn address(&self, zid: &str) -> IpAddr {
        self.admitted(zid)
            .map_or(IpAddr::V6(Ipv6Addr::UNSPECIFIED), |a| a.addr)
    }

    /// Zenoh ids of the hubs admitted now.
    pub fn admitted_ids(&self) -> HashSet<String> {
        let book = self.book.lock().unwrap_or_else(|p| p.into_inner());
        book.admitted.keys().cloned().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tls() -> Trust {
        Trust::Tls {
            files: FederationFiles {
                ca: "ca.pem".into(),
                cert: "a.pem".into(),
                key: "a.key".into(),
            },
            me: HubCertName::parse("a@acme").unwrap(),
        }
    }

    #[test]
    fn the_refused_book_keeps_the_latest_refusals_only() {
        let adm = Admission::new(tls(), "acme");
        // A stranger reconnecting under ever new Zenoh ids.
        for i in 0..REFUSED_KEPT + 10 {
            assert!(adm.link_up(&format!("z{i}"), None, "10.0.0.9:1").is_err());
        }
        let refused = adm.refused();
        assert_eq!(refused.len(), REFUSED_KEPT);
        // The first ten went, the latest stayed.
        assert!(adm.refusal("z0").is_none() && adm.refusal("z9").is_none());
        assert!(adm.refusal("z10").is_some());
        assert!(adm.refusal(&format!("z{}", REFUSED_KEPT + 9)).is_some());
        // Refused again: remembered once, with the latest reason, and not counted twice.
        let again = adm
            .link_up("z10", Some("x@globex"), "10.0.0.9:1")
            .unwrap_err();
        assert_eq!(adm.refusal("z10").as_deref(), Some(again.as_str()));
        assert_eq!(adm.refused().len(), REFUSED_KEPT);
        // An id admitted later leaves the book.
        adm.link_up("z11", Some("eu1@acme"), "10.0.0.1:1").unwrap();
        assert!(adm.refusal("z11").is_none());
    }

    #[test]
    fn a_hub_is_admitted_by_its_certificate_name_and_fleet_only() {
        let adm = Admission::new(tls(), "acme");
        assert_eq!(
            adm.link_up("z1", Some("eu1@acme"), "10.0.0.1:1")
                .unwrap()
                .name,
            "eu1"
        );
        assert!(adm.is_admitted("z1"));
        let other = adm
            .link_up("z2", Some("eu2@globex"), "10.0.0.2:1")
            .unwrap_err();
        assert!(other.contains("globex"), "{other}");
        assert!(!adm.is_admitted("z2"));
        assert_eq!(adm.refusal("z2").as_deref(), Some(other.as_str()));
        let none = adm.link_up("z3", None, "10.0.0.3:1").unwrap_err();
        assert!(none.contains("no certificate"), "{none}");
        let web = adm
            .link_up("z4", Some("hub.example.com"), "10.0.0.4:1")
            .unwrap_err();
        assert!(web.contains("HUB@FLEET"), "{web}");
        assert!(!adm.is_admitted("z4"));
    }

    #[test]
    fn a_hub_stays_admitted_while_one_of_its_links_is_up() {
        let adm = Admission::new(tls(), "acme");
        let mut changes = adm.subscribe();
        adm.link_up("z1", Some("eu1@acme"), "r1").unwrap();
        assert!(changes.has_changed().unwrap());
        changes.mark_unchanged();
        adm.link_up("z1", Some("eu1@acme"), "r2").unwrap();
        assert!(
            !changes.has_changed().unwrap(),
            "a second link admits nobody new"
        );
        assert!(adm.link_up("z1", Some("eu9@acme"), "r3").is_err());
        adm.link_down("z1");
        assert!(adm.is_admitted("z1"));
        adm.link_down("z1");
        assert!(!adm.is_admitted("z1"));
    }

    #[test]
    fn a_link_address_is_read_from_its_locator() {
        assert_eq!(
            locator_ip("tls/10.0.0.2:7447"),
            "10.0.0.2".parse::<IpAddr>().unwrap()
        );
        assert_eq!(
            locator_ip("tcp/[::1]:7447"),
            "::1".parse::<IpAddr>().unwrap()
        );
        assert_eq!(locator_ip("nonsense"), IpAddr::V6(Ipv6Addr::UNSPECIFIED));
    }

    #[test]
    fn over_plain_tcp_every_hub_is_taken() {
        let adm = Admission::new(Trust::PlainTcp, "acme");
        assert!(adm.is_admitted("anything"));
        assert!(adm.link_up("z1", None, "r").is_ok());
    }
}
