//! TLS end to end: certificates made at test time (a CA, the hub's for 127.0.0.1 and
//! localhost, a robot's client certificate), an agent uplink over `wss://` named by its
//! certificate, and a rosbridge client over `wss://` receiving the robot's messages.

use std::path::Path;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_auth::tls::{ClientAuth, ClientTlsFiles, HubRoots, ServerTlsFiles};
use serde_json::json;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use crate::util::*;

type Ca = rcgen::CertifiedIssuer<'static, rcgen::KeyPair>;

fn make_ca() -> Ca {
    let key = rcgen::KeyPair::generate().unwrap();
    let mut params = rcgen::CertificateParams::new(Vec::<String>::new()).unwrap();
    params.is_ca = rcgen::IsCa::Ca(rcgen::BasicConstraints::Unconstrained);
    params
        .distinguished_name
        .push(rcgen::DnType::CommonName, "fleetlink e2e CA");
    params.key_usages = vec![
        rcgen::KeyUsagePurpose::KeyCertSign,
        rcgen::KeyUsagePurpose::DigitalSignature,
    ];
    rcgen::CertifiedIssuer::self_signed(params, key).unwrap()
}

/// Writes `<name>.pem` and `<name>.key` signed by `ca`.
fn leaf(dir: &Path, name: &str, sans: &[&str], ca: &Ca) {
    let key = rcgen::KeyPair::generate().unwrap();
    let sans: Vec<String> = sans.iter().map(|s| s.to_string()).collect();
    let mut params = rcgen::CertificateParams::new(sans).unwrap();
    params
        .distinguished_name
        .push(rcgen::DnType::CommonName, name);
    let cert = params.signed_by(&key, ca).unwrap();
    std::fs::write(dir.join(format!("{name}.pem")), cert.pem()).unwrap();
    std::fs::write(dir.join(format!("{name}.key")), key.serialize_pem()).unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn robot_to_browser_over_wss_with_a_client_certificate() {
    let dir = temp_dir("tls");
    let ca = make_ca();
    std::fs::write(dir.join("ca.pem"), ca.pem()).unwrap();
    leaf(&dir, "hub", &["localhost", "127.0.0.1"], &ca);
    leaf(&dir, "r1", &["r1"], &ca);
    let files = ServerTlsFiles {
        cert: dir.join("hub.pem"),
        key: dir.join("hub.key"),
        client_ca: Some(dir.join("ca.pem")),
        client_auth: ClientAuth::Optional,
    };
    let hub = start_hub_with(|cfg| cfg.tls = Some(files)).await;
    let port = hub.addr.port();

    // The agent: no token; its certificate says it is r1.
    let mut up = uplink_config(&hub, "r1");
    up.hub_urls = vec![format!("wss://localhost:{port}")];
    up.token = String::new();
    up.tls = Some(
        fleetlink_auth::tls::client_config(&ClientTlsFiles {
            roots: HubRoots::CaFile(dir.join("ca.pem")),
            client_cert: Some((dir.join("r1.pem"), dir.join("r1.key"))),
        })
        .unwrap(),
    );
    let agent = start_agent_with(up, false).await;
    agent.wait_connected().await;

    // An operator's rosbridge client over wss://, trusting only the test CA.
    let roots = fleetlink_auth::tls::client_config(&ClientTlsFiles {
        roots: HubRoots::CaFile(dir.join("ca.pem")),
        client_cert: None,
    })
    .unwrap();
    let url = format!("wss://127.0.0.1:{port}/?token={}", hub.operator_token);
    let (mut op, _) = within(
        "wss rosbridge connect",
        tokio_tungstenite::connect_async_tls_with_config(
            url,
            None,
            false,
            Some(tokio_tungstenite::Connector::Rustls(Arc::clone(&roots))),
        ),
    )
    .await
    .expect("rosbridge over wss connects");
    use futures_util::{SinkExt, StreamExt};
    op.send(WsMessage::text(
        json!({"op": "subscribe", "topic": "/r1/odom", "id": "s"}).to_string(),
    ))
    .await
    .unwrap();
    let mut pubr = LocalPublisher::new(&agent.router, "/odom", "std_msgs/msg/String");
    // Publish until the subscription is live end to end; bounded in count and time.
    let got = within("a robot message over wss", async {
        for i in 0..2000 {
            pubr.publish_json(&json!({"data": format!("pose {i}")}));
            if let Ok(Some(Ok(WsMessage::Text(t)))) =
                tokio::time::timeout(Duration::from_millis(50), op.next()).await
            {
                let v: serde_json::Value = serde_json::from_str(t.as_str()).unwrap();
                if v["op"] == "publish" {
                    return v;
                }
            }
        }
        panic!("no message after 2000 publishes");
    })
    .await;
    assert_eq!(got["topic"], "/r1/odom");
    assert!(got["msg"]["data"].as_str().unwrap().starts_with("pose "));

    // Plain ws:// to a TLS port gets nowhere.
    let plain = tokio_tungstenite::connect_async(format!("ws://127.0.0.1:{port}/")).await;
    assert!(plain.is_err(), "plain WebSocket accepted on a TLS port");

    agent.shutdown().await;
    hub.shutdown().await;
}

// --- Issue 14, finding 3: the certificates people make, in real agent→hub handshakes.

const BIN: &str = env!("CARGO_BIN_EXE_fleetlink");

/// Runs a command in `dir`; panics with its stderr on failure. Returns stdout.
fn run_in(dir: &Path, program: &str, args: &[&str]) -> String {
    let out = std::process::Command::new(program)
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("{program} (the openssl CLI makes the test certificates): {e}"));
    assert!(
        out.status.success(),
        "{program} {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// `openssl genpkey` arguments of every key type.
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

/// A self-signed certificate the `openssl req -x509` way (CA:TRUE), key of `kind`.
fn openssl_self_signed(dir: &Path, name: &str, kind: &[&str], san: &str) {
    let key = format!("{name}.key");
    let mut genpkey = vec!["genpkey"];
    genpkey.extend_from_slice(kind);
    genpkey.extend_from_slice(&["-out", &key]);
    run_in(dir, "openssl", &genpkey);
    run_in(
        dir,
        "openssl",
        &[
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
        ],
    );
}

fn tls_hub_files(cert: std::path::PathBuf, key: std::path::PathBuf) -> ServerTlsFiles {
    ServerTlsFiles {
        cert,
        key,
        client_ca: None,
        client_auth: ClientAuth::None,
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue14_every_openssl_key_type_connects_an_agent_over_wss() {
    let dir = temp_dir("tls-keys");
    for (name, kind) in KEY_TYPES {
        openssl_self_signed(&dir, name, kind, "DNS:localhost,IP:127.0.0.1");
        let crt = dir.join(format!("{name}.crt"));
        let files = tls_hub_files(crt.clone(), dir.join(format!("{name}.key")));
        let hub = start_hub_with(|cfg| cfg.tls = Some(files)).await;
        let mut up = uplink_config(&hub, "r1");
        up.hub_urls = vec![format!("wss://localhost:{}", hub.addr.port())];
        up.tls = Some(
            fleetlink_auth::tls::client_config(&ClientTlsFiles {
                roots: HubRoots::CaFile(crt),
                client_cert: None,
            })
            .unwrap(),
        );
        let agent = start_agent_with(up, false).await;
        within(
            &format!("agent over wss with a {name} key"),
            agent.wait_connected(),
        )
        .await;
        agent.shutdown().await;
        hub.shutdown().await;
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue14_admin_cert_makes_hub_and_robot_certificates_for_mutual_tls() {
    let dir = temp_dir("admin-cert");
    let hub_out = run_in(
        &dir,
        BIN,
        &[
            "admin",
            "cert",
            "--dir",
            "pki",
            "hub",
            "--name",
            "localhost",
            "--ip",
            "127.0.0.1",
        ],
    );
    assert!(
        hub_out.contains("--tls-cert pki/hub.pem --tls-key pki/hub.key"),
        "{hub_out}"
    );
    assert!(hub_out.contains("ca: pki/ca.pem"), "{hub_out}");
    let robot_out = run_in(&dir, BIN, &["admin", "cert", "--dir", "pki", "robot", "r7"]);
    assert!(
        robot_out.contains("--tls-client-ca pki/ca.pem"),
        "{robot_out}"
    );
    assert!(robot_out.contains("cert: pki/r7.pem"), "{robot_out}");
    assert!(
        !robot_out.contains("a new CA"),
        "the CA is reused: {robot_out}"
    );

    let pki = dir.join("pki");
    let files = ServerTlsFiles {
        cert: pki.join("hub.pem"),
        key: pki.join("hub.key"),
        client_ca: Some(pki.join("ca.pem")),
        client_auth: ClientAuth::Required,
    };
    let hub = start_hub_with(|cfg| cfg.tls = Some(files)).await;
    // No token: the robot certificate names the robot.
    let mut up = uplink_config(&hub, "r7");
    up.hub_urls = vec![format!("wss://127.0.0.1:{}", hub.addr.port())];
    up.token = String::new();
    up.tls = Some(
        fleetlink_auth::tls::client_config(&ClientTlsFiles {
            roots: HubRoots::CaFile(pki.join("ca.pem")),
            client_cert: Some((pki.join("r7.pem"), pki.join("r7.key"))),
        })
        .unwrap(),
    );
    let agent = start_agent_with(up, false).await;
    agent.wait_connected().await;
    agent.shutdown().await;
    hub.shutdown().await;
}

/// Starts the agent binary with `yaml` and returns its first log line containing
/// `needle` (bounded by `WAIT`); the agent is killed afterwards.
async fn agent_says(dir: &Path, yaml: &str, needle: &str) -> String {
    use tokio::io::AsyncBufReadExt;
    let cfg = dir.join("robot.yaml");
    std::fs::write(&cfg, yaml).unwrap();
    let mut child = tokio::process::Command::from(fleetlink_in(dir))
        .arg("agent")
        .arg("--config")
        .arg(&cfg)
        .env("NO_COLOR", "1")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .kill_on_drop(true)
        .spawn()
        .unwrap();
    let mut lines = tokio::io::BufReader::new(child.stderr.take().unwrap()).lines();
    let line = within(&format!("the agent to say {needle:?}"), async {
        while let Some(l) = lines.next_line().await.unwrap() {
            if l.contains(needle) {
                return l;
            }
        }
        panic!("the agent exited without saying {needle:?}");
    })
    .await;
    let _ = child.kill().await;
    line
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue14_untrusted_self_signed_hub_gets_one_clear_message() {
    let dir = temp_dir("tls-selfsigned");
    openssl_self_signed(&dir, "hub", KEY_TYPES[0].1, "DNS:localhost,IP:127.0.0.1");
    let files = tls_hub_files(dir.join("hub.crt"), dir.join("hub.key"));
    let hub = start_hub_with(|cfg| cfg.tls = Some(files)).await;
    let yaml = format!(
        "hub: wss://localhost:{}\nname: r1\ntoken: {}\nlocal_rosbridge: null\n",
        hub.addr.port(),
        hub.robot_token("r1")
    );
    let line = agent_says(&dir, &yaml, "hub link down").await;
    assert!(line.contains("is self-signed"), "{line}");
    assert!(line.contains("as `tls.ca`"), "{line}");
    assert!(
        !line.contains("OtherError") && !line.contains("Some("),
        "{line}"
    );
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue14_hub_certificate_for_another_name_gets_one_clear_message() {
    let dir = temp_dir("tls-name");
    openssl_self_signed(&dir, "hub", KEY_TYPES[2].1, "DNS:localhost");
    let files = tls_hub_files(dir.join("hub.crt"), dir.join("hub.key"));
    let hub = start_hub_with(|cfg| cfg.tls = Some(files)).await;
    let yaml = format!(
        "hub: wss://127.0.0.1:{}\nname: r1\ntoken: {}\ntls: {{ ca: {} }}\nlocal_rosbridge: null\n",
        hub.addr.port(),
        hub.robot_token("r1"),
        dir.join("hub.crt").display()
    );
    let line = agent_says(&dir, &yaml, "hub link down").await;
    assert!(line.contains("not issued for the name 127.0.0.1"), "{line}");
    hub.shutdown().await;
}
