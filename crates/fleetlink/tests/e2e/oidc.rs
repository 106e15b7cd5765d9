//! Credentials beyond tokens. OIDC: a hub configured with an issuer, an audience and a JWKS URL accepts bearer JWTs
//! signed by the provider's key, maps their groups onto access rules, and refuses tokens
//! for another audience. The provider here is a key generated in the test and its JWKS
//! served over HTTP on loopback.

use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use serde_json::json;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

use crate::util::*;

/// Serves `body` as JSON to every request on a fresh loopback port; returns the URL.
async fn serve_jwks(body: String) -> String {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let addr = listener.local_addr().unwrap();
    tokio::spawn(async move {
        while let Ok((mut s, _)) = listener.accept().await {
            let body = body.clone();
            tokio::spawn(async move {
                let mut buf = [0u8; 4096];
                let _ = s.read(&mut buf).await;
                let resp = format!(
                    "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
                    body.len()
                );
                let _ = s.write_all(resp.as_bytes()).await;
            });
        }
    });
    format!("http://{addr}/.well-known/jwks.json")
}

fn sign(key: &rcgen::KeyPair, claims: serde_json::Value) -> String {
    let mut header = jsonwebtoken::Header::new(jsonwebtoken::Algorithm::EdDSA);
    header.kid = Some("k1".into());
    let enc = jsonwebtoken::EncodingKey::from_ed_der(&key.serialize_der());
    jsonwebtoken::encode(&header, &claims, &enc).unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn oidc_bearer_tokens_from_a_jwks_url_authenticate_and_carry_groups() {
    let key = rcgen::KeyPair::generate_for(&rcgen::PKCS_ED25519).unwrap();
    let jwks = json!({"keys": [{
        "kty": "OKP", "crv": "Ed25519", "use": "sig", "alg": "EdDSA", "kid": "k1",
        "x": URL_SAFE_NO_PAD.encode(key.public_key_raw()),
    }]})
    .to_string();
    let url = serve_jwks(jwks).await;
    let hub = start_hub_with(|cfg| {
        let mut jwt = fleetlink_auth::jwt::JwtConfig::new("https://idp.test", "fleetlink");
        jwt.user_claim = "email".into();
        jwt.groups_claim = Some("groups".into());
        cfg.auth.jwt = Some(jwt);
        cfg.jwks = Some(url.parse().unwrap());
    })
    .await;
    hub.set_rules("rules:\n  - subject: {group: viewers}\n    names: \"/(cam|rosapi)/.*\"\n    ops: [subscribe, call_service]\n");
    let now = fleetlink_auth::UnixTime::now().0;
    let claims = |aud: &str| {
        json!({"iss": "https://idp.test", "aud": aud, "email": "alice@example.com",
               "groups": ["viewers"], "iat": now, "exp": now + 600})
    };

    // A token for this hub: the viewer sees /cam/* and nothing else.
    let token = sign(&key, claims("fleetlink"));
    let mut viewer = Rosbridge::connect(&format!("ws://{}/?token={token}", hub.addr)).await;
    viewer
        .send(json!({"op": "subscribe", "topic": "/cam/front", "id": "ok"}))
        .await;
    viewer
        .send(json!({"op": "subscribe", "topic": "/secret", "id": "no"}))
        .await;
    let refusal = viewer.recv_op("status").await;
    assert_eq!(refusal["id"], "no");
    assert!(
        refusal["msg"].as_str().unwrap().contains("not allowed"),
        "{refusal}"
    );
    let mut cam = hub_publisher(&hub, "/cam/front", "sensor_msgs/msg/CompressedImage");
    let got = within("a frame for the OIDC viewer", async {
        loop {
            cam.publish_json(&json!({"format": "jpeg", "data": ""}));
            if let Ok(Some(v)) =
                tokio::time::timeout(std::time::Duration::from_millis(25), viewer.try_recv()).await
                && v["op"] == "publish"
            {
                return v;
            }
        }
    })
    .await;
    assert_eq!(got["topic"], "/cam/front");

    // A token minted for another application is refused before the WebSocket opens.
    let other = sign(&key, claims("someone-else"));
    let refused =
        tokio_tungstenite::connect_async(format!("ws://{}/?token={other}", hub.addr)).await;
    match refused {
        Err(tokio_tungstenite::tungstenite::Error::Http(resp)) => assert_eq!(resp.status(), 401),
        other => panic!("expected HTTP 401, got {other:?}"),
    }
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn robot_on_a_trusted_network_connects_without_a_token_and_only_as_itself() {
    let hub = start_hub_with(|cfg| {
        cfg.auth.robot_networks = vec![fleetlink_auth::authn::RobotNetwork {
            net: "127.0.0.0/8".parse().unwrap(),
            robot: Some(fleetlink_auth::RobotName::new("vpn_bot").unwrap()),
        }];
    })
    .await;
    let mut cfg = uplink_config(&hub, "vpn_bot");
    cfg.token = String::new();
    let ok = start_agent_with(cfg, false).await;
    ok.wait_connected().await;

    // The network vouches for vpn_bot only; another name from it still needs a token.
    let mut cfg = uplink_config(&hub, "intruder");
    cfg.token = String::new();
    let refused = start_agent_with(cfg, false).await;
    let reason = refused.wait_disconnected().await;
    assert!(
        reason.contains("refused") || reason.contains("closed"),
        "{reason}"
    );
    assert!(
        !hub.state
            .registry
            .list()
            .iter()
            .any(|r| r.name == "intruder")
    );
    ok.shutdown().await;
    refused.shutdown().await;
    hub.shutdown().await;
}
