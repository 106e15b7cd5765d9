//! Attacks on the transport: path traversal in HTTP request targets, and a TLS client
//! without a certificate on a hub that requires one.

use std::path::Path;
use std::sync::Arc;

use fleetlink_auth::audit::AuditAction;
use fleetlink_auth::tls::{ClientAuth, ClientTlsFiles, HubRoots, ServerTlsFiles};
use tokio::net::TcpStream;
use tokio_rustls::rustls::pki_types::ServerName;

use crate::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn path_traversal_never_serves_files() {
    let fx = hub().await;
    let auth = format!("Bearer {}", fx.operator);
    let targets = [
        "/../../etc/passwd",
        "/%2e%2e/%2e%2e/etc/passwd",
        "/%2e%2e%2f%2e%2e%2fetc%2fpasswd",
        "/api/v1/../../x",
        "/api/v1/../../../etc/passwd",
        "/api/v1/%2e%2e/%2e%2e/etc/passwd",
        "/..%5c..%5cetc%5cpasswd",
        "//etc/passwd",
    ];
    for target in targets {
        for headers in [vec![], vec![("Authorization", auth.as_str())]] {
            let r = http(fx.addr, "GET", target, &headers, "").await;
            assert!(
                r.status == 404 || r.status == 400,
                "{target}: got {} {:?}",
                r.status,
                r.body
            );
            assert!(
                !r.body.contains("root:"),
                "{target} leaked a file: {:?}",
                r.body
            );
        }
    }
    fx.still_serving().await;
}

type Ca = rcgen::CertifiedIssuer<'static, rcgen::KeyPair>;

fn make_ca() -> Ca {
    let key = rcgen::KeyPair::generate().unwrap();
    let mut params = rcgen::CertificateParams::new(Vec::<String>::new()).unwrap();
    params.is_ca = rcgen::IsCa::Ca(rcgen::BasicConstraints::Unconstrained);
    params
        .distinguished_name
        .push(rcgen::DnType::CommonName, "attacks test CA");
    params.key_usages = vec![
        rcgen::KeyUsagePurpose::KeyCertSign,
        rcgen::KeyUsagePurpose::DigitalSignature,
    ];
    rcgen::CertifiedIssuer::self_signed(params, key).unwrap()
}

/// Writes `<name>.pem` and `<name>.key`, signed by `ca`.
fn leaf(dir: &Path, name: &str, sans: &[&str], cn: &str, ca: &Ca) {
    let key = rcgen::KeyPair::generate().unwrap();
    let sans: Vec<String> = sans.iter().map(|s| s.to_string()).collect();
    let mut params = rcgen::CertificateParams::new(sans).unwrap();
    params
        .distinguished_name
        .push(rcgen::DnType::CommonName, cn);
    let cert = params.signed_by(&key, ca).unwrap();
    std::fs::write(dir.join(format!("{name}.pem")), cert.pem()).unwrap();
    std::fs::write(dir.join(format!("{name}.key")), key.serialize_pem()).unwrap();
}

type TlsWs = tokio_tungstenite::WebSocketStream<tokio_rustls::client::TlsStream<TcpStream>>;

/// TLS, then a `fleetlink.v1` upgrade; the error text if either fails.
async fn tls_agent(
    addr: std::net::SocketAddr,
    config: Arc<tokio_rustls::rustls::ClientConfig>,
) -> Result<TlsWs, String> {
    let tcp = TcpStream::connect(addr).await.map_err(|e| e.to_string())?;
    let tls = tokio_rustls::TlsConnector::from(config)
        .connect(ServerName::try_from("localhost").unwrap(), tcp)
        .await
        .map_err(|e| format!("TLS: {e}"))?;
    let mut req = format!("wss://localhost:{}/", addr.port())
        .into_client_request()
        .unwrap();
    req.headers_mut().insert(
        "sec-websocket-protocol",
        fleetlink_proto::SUBPROTOCOL.parse().unwrap(),
    );
    // With TLS 1.3 the server checks the client's certificate after the client thinks
    // the handshake is done, so a refusal shows up here, on the first exchange.
    tokio_tungstenite::client_async(req, tls)
        .await
        .map(|(ws, _)| ws)
        .map_err(|e| format!("upgrade: {e}"))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tls_client_without_certificate_fails_the_handshake() {
    let dir = temp_dir("tls");
    let ca = make_ca();
    std::fs::write(dir.join("ca.pem"), ca.pem()).unwrap();
    leaf(&dir, "hub", &["localhost", "127.0.0.1"], "hub", &ca);
    leaf(&dir, "r7", &["r7"], "r7", &ca);
    let files = ServerTlsFiles {
        cert: dir.join("hub.pem"),
        key: dir.join("hub.key"),
        client_ca: Some(dir.join("ca.pem")),
        client_auth: ClientAuth::Required,
    };
    let fx = hub_with(|cfg| cfg.tls = Some(files)).await;
    // A connection closed before its ClientHello (an agent's abandoned staggered connect,
    // a port probe) is no refused login: it must not be audited as one.
    drop(tokio::net::TcpStream::connect(fx.addr).await.unwrap());
    let anonymous = fleetlink_auth::tls::client_config(&ClientTlsFiles {
        roots: HubRoots::CaFile(dir.join("ca.pem")),
        client_cert: None,
    })
    .unwrap();
    let err = within("TLS refusal", tls_agent(fx.addr, anonymous))
        .await
        .map(|_| ())
        .expect_err("a client without a certificate must not get in");
    assert!(
        err.contains("TLS") || err.contains("upgrade"),
        "unexpected error: {err}"
    );
    fx.assert_audited(AuditAction::AuthFailure, "TLS handshake")
        .await;
    let failures = fx.audited(AuditAction::AuthFailure).await;
    assert_eq!(
        failures.len(),
        1,
        "only the client without a certificate was refused: {failures:#?}"
    );

    // A robot with a valid certificate gets in without a token: the certificate names it.
    let r7 = fleetlink_auth::tls::client_config(&ClientTlsFiles {
        roots: HubRoots::CaFile(dir.join("ca.pem")),
        client_cert: Some((dir.join("r7.pem"), dir.join("r7.key"))),
    })
    .unwrap();
    let mut ws = within("TLS agent", tls_agent(fx.addr, r7.clone()))
        .await
        .expect("certificate accepted");
    hello(&mut ws, "r7", "").await;
    match next_frame(&mut ws).await {
        Some(Frame::Welcome { namespace, .. }) => assert_eq!(namespace, "/r7"),
        other => panic!("expected WELCOME, got {other:?}"),
    }
    // The same certificate cannot claim another robot.
    let mut ws = within("TLS agent", tls_agent(fx.addr, r7))
        .await
        .expect("certificate accepted");
    hello(&mut ws, "r8", "").await;
    refused(&mut ws, 401, "authentication failed").await;
    fx.assert_audited(AuditAction::AuthFailure, "claimed-robot:r8")
        .await;
}
