//! Shared fixtures: identities, a fresh [`Security`], clock values, a test PKI.

use std::net::IpAddr;
use std::path::{Path, PathBuf};

use fleetlink_auth::acl::AclDefaults;
use fleetlink_auth::{
    AuthPolicy, ConnInfo, GroupName, Identity, IdentityKind, RobotName, Security, Store, UnixTime,
    UserName,
};

pub const T0: UnixTime = UnixTime(1_800_000_000);

pub fn ip(s: &str) -> IpAddr {
    s.parse().unwrap()
}

pub fn peer(s: &str) -> ConnInfo {
    ConnInfo::new(ip(s))
}

pub fn robot(name: &str) -> RobotName {
    RobotName::new(name).unwrap()
}

pub fn user(name: &str) -> UserName {
    UserName::new(name).unwrap()
}

pub fn group(name: &str) -> GroupName {
    GroupName::new(name).unwrap()
}

fn identity(kind: IdentityKind, from: &str) -> Identity {
    Identity {
        kind,
        source: peer(from),
        client_ip: ip(from),
    }
}

pub fn robot_id(name: &str, from: &str) -> Identity {
    identity(IdentityKind::Robot { name: robot(name) }, from)
}

pub fn user_id(name: &str, groups: &[&str], from: &str) -> Identity {
    identity(
        IdentityKind::User {
            name: user(name),
            groups: groups.iter().map(|g| group(g)).collect(),
        },
        from,
    )
}

pub fn anonymous(from: &str) -> Identity {
    identity(IdentityKind::Anonymous, from)
}

pub fn admin() -> Identity {
    user_id("root", &["admin"], "127.0.0.1")
}

pub fn security(policy: AuthPolicy, defaults: AclDefaults) -> Security {
    Security::new(Store::open_in_memory().unwrap(), policy, defaults).unwrap()
}

/// Where a test's store lives: the tests written for both run once on each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Backend {
    /// A private in-memory SQLite database.
    Sqlite,
    /// A new database of its own on the server named by `FLEETLINK_TEST_POSTGRES`.
    Postgres,
}

pub fn store_on(backend: Backend) -> Store {
    match backend {
        Backend::Sqlite => Store::open_in_memory().unwrap(),
        Backend::Postgres => Store::postgres(fleetlink_postgres::scratch_database()).unwrap(),
    }
}

pub fn security_on(backend: Backend, policy: AuthPolicy, defaults: AclDefaults) -> Security {
    Security::new(store_on(backend), policy, defaults).unwrap()
}

/// Runs each named test body (a `fn(Backend)` of the calling module) on both backends:
/// `<module>::sqlite::<name>` always, `<module>::postgres::<name>` when ignored tests are
/// run with a server (tests/interop/postgres/run.sh does), so a plain test run reports
/// the PostgreSQL variants as skipped instead of passing them without a database.
macro_rules! on_both_backends {
    ($($name:ident),* $(,)?) => {
        mod sqlite {
            $(#[test]
            fn $name() {
                super::$name($crate::util::Backend::Sqlite)
            })*
        }
        mod postgres {
            $(#[test]
            #[ignore = "needs PostgreSQL: tests/interop/postgres/run.sh runs it with a server"]
            fn $name() {
                super::$name($crate::util::Backend::Postgres)
            })*
        }
    };
}
pub(crate) use on_both_backends;

/// A CA, a hub certificate for `localhost`, a client certificate for robot `r1`, and a
/// client certificate for `r1` from an unrelated CA, as PEM files in a temp dir.
pub struct Pki {
    pub dir: tempfile::TempDir,
}

impl Pki {
    pub fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }

    pub fn generate() -> Pki {
        let dir = tempfile::tempdir().unwrap();
        let ca = make_ca("fleet CA");
        let rogue = make_ca("rogue CA");
        write(dir.path(), "ca.pem", &ca.pem());
        leaf(dir.path(), "server", &["localhost"], "localhost", &ca);
        leaf(dir.path(), "r1", &[], "r1", &ca);
        leaf(dir.path(), "rogue", &[], "r1", &rogue);
        Pki { dir }
    }

    /// Reissues the hub certificate (same name, new key) in place.
    pub fn reissue_server(&self) {
        let ca = make_ca("another CA");
        leaf(self.dir.path(), "server", &["localhost"], "localhost", &ca);
    }
}

fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).unwrap();
}

type Ca = rcgen::CertifiedIssuer<'static, rcgen::KeyPair>;

fn make_ca(cn: &str) -> Ca {
    let key = rcgen::KeyPair::generate().unwrap();
    let mut params = rcgen::CertificateParams::new(Vec::<String>::new()).unwrap();
    params.is_ca = rcgen::IsCa::Ca(rcgen::BasicConstraints::Unconstrained);
    params
        .distinguished_name
        .push(rcgen::DnType::CommonName, cn);
    params.key_usages = vec![
        rcgen::KeyUsagePurpose::KeyCertSign,
        rcgen::KeyUsagePurpose::DigitalSignature,
    ];
    rcgen::CertifiedIssuer::self_signed(params, key).unwrap()
}

fn leaf(dir: &Path, name: &str, sans: &[&str], cn: &str, ca: &Ca) {
    let key = rcgen::KeyPair::generate().unwrap();
    let sans: Vec<String> = sans.iter().map(|s| s.to_string()).collect();
    let mut params = rcgen::CertificateParams::new(sans).unwrap();
    params
        .distinguished_name
        .push(rcgen::DnType::CommonName, cn);
    let cert = params.signed_by(&key, ca).unwrap();
    write(dir, &format!("{name}.pem"), &cert.pem());
    write(dir, &format!("{name}.key"), &key.serialize_pem());
}
