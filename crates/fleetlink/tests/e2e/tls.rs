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
    up.hub_url = format!("wss://localhost:{port}");
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
