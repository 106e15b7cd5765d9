//! How a hub's Zenoh configuration is made from its flags: authentication required, TLS
//! endpoints only, no default listener.

use std::path::{Path, PathBuf};

use rcgen::{
    BasicConstraints, CertificateParams, DnType, ExtendedKeyUsagePurpose, IsCa, Issuer, KeyPair,
    SanType,
};

use super::*;

/// A fleet CA and a hub certificate named `cn`, written to `dir`.
fn pki(dir: &Path, cn: &str) -> TrustArgs {
    let ca_key = KeyPair::generate().unwrap();
    let mut ca = CertificateParams::default();
    ca.is_ca = IsCa::Ca(BasicConstraints::Constrained(0));
    ca.distinguished_name
        .push(DnType::CommonName, "test federation CA");
    let ca_cert = ca.self_signed(&ca_key).unwrap();
    let issuer = Issuer::new(ca, ca_key);
    let key = KeyPair::generate().unwrap();
    let mut leaf = CertificateParams::default();
    leaf.distinguished_name.push(DnType::CommonName, cn);
    leaf.subject_alt_names
        .push(SanType::IpAddress("127.0.0.1".parse().unwrap()));
    leaf.extended_key_usages = vec![
        ExtendedKeyUsagePurpose::ServerAuth,
        ExtendedKeyUsagePurpose::ClientAuth,
    ];
    let cert = leaf.signed_by(&key, &issuer).unwrap();
    let write = |name: &str, pem: String| {
        let p = dir.join(name);
        std::fs::write(&p, pem).unwrap();
        p
    };
    TrustArgs {
        ca: Some(write("ca.pem", ca_cert.pem())),
        cert: Some(write("hub.pem", cert.pem())),
        key: Some(write("hub.key", key.serialize_pem())),
        insecure_tcp: false,
    }
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("fleetlink-fed-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn list(cfg: &zenoh::Config, key: &str) -> Vec<String> {
    endpoints(cfg, key)
}

#[test]
fn without_certificates_the_federation_refuses_and_says_how() {
    let e = zenoh_config(
        None,
        None,
        &[],
        &["tls/127.0.0.1:7447".into()],
        "acme",
        &TrustArgs::default(),
    )
    .unwrap_err();
    let text = e.to_string();
    assert!(text.contains("--zenoh-ca"), "{text}");
    assert!(
        text.contains("fleetlink admin cert federation --fleet acme"),
        "{text}"
    );
    assert!(text.contains("--zenoh-insecure-tcp"), "{text}");
}

#[test]
fn plain_tcp_is_an_explicit_opt_in_and_listens_only_where_told() {
    let insecure = TrustArgs {
        insecure_tcp: true,
        ..TrustArgs::default()
    };
    let (cfg, trust) = zenoh_config(
        None,
        None,
        &["tcp/10.0.0.2:7447".into()],
        &[],
        "acme",
        &insecure,
    )
    .unwrap();
    assert!(matches!(trust, Trust::PlainTcp));
    assert_eq!(
        list(&cfg, "listen/endpoints"),
        Vec::<String>::new(),
        "no default listener"
    );
    assert_eq!(list(&cfg, "connect/endpoints"), vec!["tcp/10.0.0.2:7447"]);
    let both = TrustArgs {
        ca: Some("ca.pem".into()),
        ..insecure
    };
    let e = zenoh_config(None, None, &[], &[], "acme", &both).unwrap_err();
    assert!(e.to_string().contains("choose"), "{e}");
}

#[test]
fn with_certificates_every_endpoint_is_tls_and_links_are_mutual() {
    let dir = tmp("tls");
    let args = pki(&dir, "hub-a@acme");
    let (cfg, trust) = zenoh_config(
        None,
        None,
        &["tls/127.0.0.1:7448".into()],
        &["tls/127.0.0.1:7447".into()],
        "acme",
        &args,
    )
    .unwrap();
    let Trust::Tls { me, .. } = trust else {
        panic!("TLS expected")
    };
    assert_eq!(me.hub, "hub-a");
    assert_eq!(list(&cfg, "listen/endpoints"), vec!["tls/127.0.0.1:7447"]);
    assert_eq!(
        cfg.get_json("transport/link/tls/enable_mtls").unwrap(),
        "true"
    );
    for ep in ["tcp/127.0.0.1:7447", "udp/127.0.0.1:7447"] {
        let e = zenoh_config(None, None, &[ep.into()], &[], "acme", &args).unwrap_err();
        assert!(e.to_string().contains(ep), "{e}");
    }
    // A certificate of another fleet, or not named HUB@FLEET, stops the hub at start.
    let e = zenoh_config(None, None, &[], &[], "globex", &args).unwrap_err();
    assert!(e.to_string().contains("fleet \"acme\""), "{e}");
    let web = pki(&tmp("web"), "hub.example.com");
    let e = zenoh_config(None, None, &[], &[], "acme", &web).unwrap_err();
    assert!(e.to_string().contains("HUB@FLEET"), "{e}");
}

#[test]
fn a_hub_certificate_from_another_ca_is_refused_at_start() {
    let ours = pki(&tmp("ours"), "hub-a@acme");
    let theirs = pki(&tmp("theirs"), "hub-a@acme");
    let mixed = TrustArgs {
        ca: ours.ca,
        ..theirs
    };
    let e = zenoh_config(None, None, &[], &[], "acme", &mixed).unwrap_err();
    assert!(
        e.to_string().contains("not signed by the federation CA"),
        "{e}"
    );
}
