//! Issue 14, finding 3 ("TLS with the certificates people actually make"): certificates
//! and keys made the ordinary way with the openssl CLI, every key type, in handshakes
//! driven in memory between the hub's and the agent's configs.

use std::path::{Path, PathBuf};
use std::process::Command;

use fleetlink_auth::tls::{
    ClientAuth, ClientTlsFiles, HubCertError, HubRoots, ServerTlsFiles, client_cert_name,
    client_config, server_config,
};
use rustls::pki_types::ServerName;
use rustls::{CertificateError, ClientConnection, ServerConnection};

/// The key types `openssl genpkey` makes, as its arguments.
const KEY_TYPES: &[(&str, &[&str])] = &[
    (
        "rsa",
        &["-algorithm", "RSA", "-pkeyopt", "rsa_keygen_bits:2048"],
    ),
    ("rsa_pss", &["-algorithm", "RSA-PSS"]),
    (
        "p256",
        &["-algorithm", "EC", "-pkeyopt", "ec_paramgen_curve:P-256"],
    ),
    (
        "p384",
        &["-algorithm", "EC", "-pkeyopt", "ec_paramgen_curve:P-384"],
    ),
    ("ed25519", &["-algorithm", "ED25519"]),
];

struct Dir(PathBuf);

impl Dir {
    fn new() -> Dir {
        let d = std::env::temp_dir().join(format!(
            "fleetlink-openssl-{}-{}",
            std::process::id(),
            rand_suffix()
        ));
        std::fs::create_dir_all(&d).unwrap();
        Dir(d)
    }

    fn p(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    /// Runs openssl in this directory; panics with its stderr on failure.
    fn openssl(&self, args: &[&str]) {
        let out = Command::new("openssl")
            .args(args)
            .current_dir(&self.0)
            .output()
            .expect("the openssl CLI is needed to make test certificates");
        assert!(
            out.status.success(),
            "openssl {args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }

    fn genpkey(&self, key: &str, kind: &[&str]) {
        let mut args = vec!["genpkey"];
        args.extend_from_slice(kind);
        args.extend_from_slice(&["-out", key]);
        self.openssl(&args);
    }

    /// A self-signed certificate as `openssl req -x509` makes it (CA:TRUE).
    fn self_signed(&self, name: &str, kind: &[&str], san: &str) {
        let key = format!("{name}.key");
        self.genpkey(&key, kind);
        self.openssl(&[
            "req",
            "-x509",
            "-key",
            &key,
            "-out",
            &format!("{name}.crt"),
            "-days",
            "2",
            "-subj",
            "/CN=localhost",
            "-addext",
            &format!("subjectAltName={san}"),
        ]);
    }

    /// A CA the usual way (P-256), and `sign` for leaves of any key type.
    fn ca(&self) {
        self.openssl(&[
            "req",
            "-x509",
            "-newkey",
            "ec",
            "-pkeyopt",
            "ec_paramgen_curve:P-256",
            "-nodes",
            "-days",
            "2",
            "-subj",
            "/CN=test CA",
            "-keyout",
            "ca.key",
            "-out",
            "ca.crt",
        ]);
    }

    fn leaf(&self, name: &str, kind: &[&str], ext: &str) {
        let key = format!("{name}.key");
        self.genpkey(&key, kind);
        self.openssl(&[
            "req",
            "-new",
            "-key",
            &key,
            "-subj",
            &format!("/CN={name}"),
            "-out",
            &format!("{name}.csr"),
        ]);
        std::fs::write(self.p(&format!("{name}.ext")), ext).unwrap();
        self.openssl(&[
            "x509",
            "-req",
            "-in",
            &format!("{name}.csr"),
            "-CA",
            "ca.crt",
            "-CAkey",
            "ca.key",
            "-CAcreateserial",
            "-days",
            "2",
            "-extfile",
            &format!("{name}.ext"),
            "-out",
            &format!("{name}.crt"),
        ]);
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn rand_suffix() -> u64 {
    use std::hash::{BuildHasher, RandomState};
    RandomState::new().hash_one(std::time::Instant::now())
}

const HUB_EXT: &str = "basicConstraints=CA:FALSE\nkeyUsage=critical,digitalSignature\n\
    extendedKeyUsage=serverAuth\nsubjectAltName=DNS:localhost,IP:127.0.0.1\n";

fn hub_files(cert: &Path, key: &Path, client_ca: Option<&Path>) -> ServerTlsFiles {
    ServerTlsFiles {
        cert: cert.to_owned(),
        key: key.to_owned(),
        client_ca: client_ca.map(Path::to_owned),
        client_auth: if client_ca.is_some() {
            ClientAuth::Required
        } else {
            ClientAuth::None
        },
    }
}

/// A handshake between a hub config and an agent config connecting as `name`.
fn handshake(
    server: &ServerTlsFiles,
    client: &ClientTlsFiles,
    name: &str,
) -> Result<ServerConnection, rustls::Error> {
    let server_cfg = server_config(server).unwrap_or_else(|e| panic!("hub config: {e}"));
    let client_cfg = client_config(client).unwrap_or_else(|e| panic!("agent config: {e}"));
    let mut c =
        ClientConnection::new(client_cfg, ServerName::try_from(name.to_owned()).unwrap()).unwrap();
    let mut s = ServerConnection::new(server_cfg).unwrap();
    for _ in 0..20 {
        let mut buf = Vec::new();
        while c.wants_write() {
            c.write_tls(&mut buf).unwrap();
        }
        let mut rd = &buf[..];
        while !rd.is_empty() {
            s.read_tls(&mut rd).unwrap();
            s.process_new_packets()?;
        }
        let mut buf = Vec::new();
        while s.wants_write() {
            s.write_tls(&mut buf).unwrap();
        }
        let mut rd = &buf[..];
        while !rd.is_empty() {
            c.read_tls(&mut rd).unwrap();
            c.process_new_packets()?;
        }
        if !c.is_handshaking() && !s.is_handshaking() {
            return Ok(s);
        }
    }
    panic!("handshake did not finish");
}

fn pinned(cert: &Path) -> ClientTlsFiles {
    ClientTlsFiles {
        roots: HubRoots::CaFile(cert.to_owned()),
        client_cert: None,
    }
}

#[test]
fn issue14_openssl_req_x509_self_signed_cert_works_as_tls_ca() {
    // The exact command of the issue: a CA certificate (CA:TRUE) used as the hub's own.
    let d = Dir::new();
    d.openssl(&[
        "req",
        "-x509",
        "-newkey",
        "rsa:2048",
        "-nodes",
        "-keyout",
        "hub.key",
        "-out",
        "hub.crt",
        "-subj",
        "/CN=localhost",
        "-addext",
        "subjectAltName=DNS:localhost,IP:127.0.0.1",
    ]);
    let hub = hub_files(&d.p("hub.crt"), &d.p("hub.key"), None);
    for name in ["localhost", "127.0.0.1"] {
        handshake(&hub, &pinned(&d.p("hub.crt")), name)
            .unwrap_or_else(|e| panic!("pinned self-signed certificate as {name}: {e}"));
    }
}

#[test]
fn issue14_every_key_type_works_self_signed_and_pinned() {
    let d = Dir::new();
    for (name, kind) in KEY_TYPES {
        d.self_signed(name, kind, "DNS:localhost,IP:127.0.0.1");
        let crt = d.p(&format!("{name}.crt"));
        let hub = hub_files(&crt, &d.p(&format!("{name}.key")), None);
        handshake(&hub, &pinned(&crt), "localhost")
            .unwrap_or_else(|e| panic!("{name} self-signed: {e}"));
    }
}

#[test]
fn issue14_every_key_type_works_for_hub_and_robot_certificates_from_a_ca() {
    let d = Dir::new();
    d.ca();
    for (name, kind) in KEY_TYPES {
        let hub = format!("hub_{name}");
        let robot = format!("r_{name}");
        d.leaf(&hub, kind, HUB_EXT);
        d.leaf(
            &robot,
            kind,
            &format!(
                "basicConstraints=CA:FALSE\nkeyUsage=critical,digitalSignature\n\
                 extendedKeyUsage=clientAuth\nsubjectAltName=DNS:{robot}\n"
            ),
        );
        let server = hub_files(
            &d.p(&format!("{hub}.crt")),
            &d.p(&format!("{hub}.key")),
            Some(&d.p("ca.crt")),
        );
        let client = ClientTlsFiles {
            roots: HubRoots::CaFile(d.p("ca.crt")),
            client_cert: Some((d.p(&format!("{robot}.crt")), d.p(&format!("{robot}.key")))),
        };
        let s = handshake(&server, &client, "127.0.0.1")
            .unwrap_or_else(|e| panic!("{name} from a CA, mutual TLS: {e}"));
        assert_eq!(
            client_cert_name(s.peer_certificates()).map(|r| r.to_string()),
            Some(robot.clone()),
            "{name}"
        );
    }
}

#[test]
fn issue14_traditional_key_files_load() {
    // PKCS#1 "RSA PRIVATE KEY" and SEC1 "EC PRIVATE KEY", as older recipes write them.
    let d = Dir::new();
    d.ca();
    d.leaf("hub_rsa", KEY_TYPES[0].1, HUB_EXT);
    d.leaf("hub_ec", KEY_TYPES[2].1, HUB_EXT);
    d.openssl(&[
        "rsa",
        "-in",
        "hub_rsa.key",
        "-traditional",
        "-out",
        "hub_rsa.pkcs1",
    ]);
    d.openssl(&["ec", "-in", "hub_ec.key", "-out", "hub_ec.sec1"]);
    for (crt, key, header) in [
        ("hub_rsa.crt", "hub_rsa.pkcs1", "RSA PRIVATE KEY"),
        ("hub_ec.crt", "hub_ec.sec1", "EC PRIVATE KEY"),
    ] {
        let text = std::fs::read_to_string(d.p(key)).unwrap();
        assert!(text.contains(header), "{key} is not {header}");
        let server = hub_files(&d.p(crt), &d.p(key), None);
        handshake(&server, &pinned(&d.p("ca.crt")), "localhost")
            .unwrap_or_else(|e| panic!("{header}: {e}"));
    }
}

#[test]
fn issue14_self_signed_hub_not_in_tls_ca_is_reported_as_self_signed() {
    let d = Dir::new();
    d.ca();
    d.self_signed("hub", KEY_TYPES[0].1, "DNS:localhost");
    let server = hub_files(&d.p("hub.crt"), &d.p("hub.key"), None);
    let err = handshake(&server, &pinned(&d.p("ca.crt")), "localhost").unwrap_err();
    assert_eq!(
        HubCertError::of(&err),
        Some(&HubCertError::SelfSigned),
        "{err:?}"
    );
}

#[test]
fn issue14_pinned_certificate_still_checks_the_name() {
    let d = Dir::new();
    d.self_signed("hub", KEY_TYPES[2].1, "DNS:localhost");
    let server = hub_files(&d.p("hub.crt"), &d.p("hub.key"), None);
    let err = handshake(&server, &pinned(&d.p("hub.crt")), "hub.example").unwrap_err();
    assert!(
        matches!(
            err,
            rustls::Error::InvalidCertificate(
                CertificateError::NotValidForName | CertificateError::NotValidForNameContext { .. }
            )
        ),
        "{err:?}"
    );
}

#[test]
fn issue14_pinned_certificate_needs_the_matching_key() {
    // A hub that presents the pinned certificate without its key fails the handshake
    // signature: pinning trusts the key, not the bytes alone.
    let d = Dir::new();
    d.self_signed("hub", KEY_TYPES[2].1, "DNS:localhost");
    d.genpkey("other.key", KEY_TYPES[2].1);
    let server = ServerTlsFiles {
        key: d.p("other.key"),
        ..hub_files(&d.p("hub.crt"), &d.p("hub.key"), None)
    };
    // rustls refuses a key that does not match its certificate when it can tell.
    match server_config(&server) {
        Err(_) => {}
        Ok(_) => {
            let err = handshake(&server, &pinned(&d.p("hub.crt")), "localhost").unwrap_err();
            assert!(
                matches!(
                    err,
                    rustls::Error::InvalidCertificate(CertificateError::BadSignature)
                ),
                "{err:?}"
            );
        }
    }
}

#[test]
fn issue14_rsa_pss_ca_signing_with_digest_salt_is_accepted() {
    // A CA whose own key is RSA-PSS; webpki alone cannot verify rsassaPss public keys.
    let d = Dir::new();
    d.genpkey("ca.key", KEY_TYPES[1].1);
    d.openssl(&[
        "req",
        "-x509",
        "-key",
        "ca.key",
        "-out",
        "ca.crt",
        "-days",
        "2",
        "-subj",
        "/CN=pss CA",
        "-sigopt",
        "rsa_pss_saltlen:digest",
    ]);
    d.genpkey("hub.key", KEY_TYPES[2].1);
    d.openssl(&[
        "req", "-new", "-key", "hub.key", "-subj", "/CN=hub", "-out", "hub.csr",
    ]);
    std::fs::write(d.p("hub.ext"), HUB_EXT).unwrap();
    d.openssl(&[
        "x509",
        "-req",
        "-in",
        "hub.csr",
        "-CA",
        "ca.crt",
        "-CAkey",
        "ca.key",
        "-CAcreateserial",
        "-days",
        "2",
        "-extfile",
        "hub.ext",
        "-sigopt",
        "rsa_pss_saltlen:digest",
        "-out",
        "hub.crt",
    ]);
    let server = hub_files(&d.p("hub.crt"), &d.p("hub.key"), None);
    handshake(&server, &pinned(&d.p("ca.crt")), "localhost")
        .unwrap_or_else(|e| panic!("hub signed by an RSA-PSS CA: {e}"));
}
