//! TLS: configs built from PEM files generated at test time, handshakes driven in memory
//! (rustls is sans-IO), client-certificate names, and reloading.

use std::sync::Arc;
use std::time::{Duration, SystemTime};

use fleetlink_auth::tls::{
    ClientAuth, ClientTlsFiles, HubRoots, ReloadingServerConfig, ServerTlsFiles, TlsError,
    client_cert_name, client_config, server_config,
};
use rustls::pki_types::ServerName;
use rustls::{ClientConnection, ServerConnection};

use crate::util::*;

fn server_files(pki: &Pki, auth: ClientAuth) -> ServerTlsFiles {
    ServerTlsFiles {
        cert: pki.path("server.pem"),
        key: pki.path("server.key"),
        client_ca: Some(pki.path("ca.pem")),
        client_auth: auth,
    }
}

fn client_files(pki: &Pki, cert: Option<&str>) -> ClientTlsFiles {
    ClientTlsFiles {
        roots: HubRoots::CaFile(pki.path("ca.pem")),
        client_cert: cert.map(|c| (pki.path(&format!("{c}.pem")), pki.path(&format!("{c}.key")))),
    }
}

/// Runs a handshake to completion (or the first error) by moving bytes in memory.
fn handshake(
    client: &mut ClientConnection,
    server: &mut ServerConnection,
) -> Result<(), rustls::Error> {
    for _ in 0..20 {
        let mut buf = Vec::new();
        while client.wants_write() {
            client.write_tls(&mut buf).unwrap();
        }
        let mut rd = &buf[..];
        while !rd.is_empty() {
            server.read_tls(&mut rd).unwrap();
            server.process_new_packets()?;
        }
        let mut buf = Vec::new();
        while server.wants_write() {
            server.write_tls(&mut buf).unwrap();
        }
        let mut rd = &buf[..];
        while !rd.is_empty() {
            client.read_tls(&mut rd).unwrap();
            client.process_new_packets()?;
        }
        if !client.is_handshaking() && !server.is_handshaking() {
            return Ok(());
        }
    }
    panic!("handshake did not finish");
}

fn connect(
    pki: &Pki,
    auth: ClientAuth,
    cert: Option<&str>,
) -> Result<ServerConnection, rustls::Error> {
    let server_cfg = server_config(&server_files(pki, auth)).unwrap();
    let client_cfg = client_config(&client_files(pki, cert)).unwrap();
    let mut client =
        ClientConnection::new(client_cfg, ServerName::try_from("localhost").unwrap()).unwrap();
    let mut server = ServerConnection::new(server_cfg).unwrap();
    handshake(&mut client, &mut server)?;
    Ok(server)
}

#[test]
fn mtls_handshake_yields_the_robot_name_from_the_certificate() {
    let pki = Pki::generate();
    let server = connect(&pki, ClientAuth::Required, Some("r1")).unwrap();
    assert_eq!(
        client_cert_name(server.peer_certificates()),
        Some(robot("r1"))
    );
    assert_eq!(server.alpn_protocol(), None, "client offered no ALPN");
}

/// Issue 36, item 6: a certificate names a robot only with a name that follows the one
/// robot name rule (`RobotName`): a DNS SAN that breaks it is passed over for the next,
/// then for the CN; a CN that breaks it names nobody.
#[test]
fn issue36_certificate_names_follow_the_robot_name_rule() {
    let name_of = |sans: &[&str], cn: &str| {
        let key = rcgen::KeyPair::generate().unwrap();
        let sans: Vec<String> = sans.iter().map(|s| s.to_string()).collect();
        let mut params = rcgen::CertificateParams::new(sans).unwrap();
        params
            .distinguished_name
            .push(rcgen::DnType::CommonName, cn);
        let cert = params.self_signed(&key).unwrap();
        client_cert_name(Some(&[cert.der().clone()])).map(|r| r.to_string())
    };
    let longest = format!("r{}", "0".repeat(62));
    let too_long = format!("{longest}0");
    assert_eq!(name_of(&["1robot", "r2"], "r3").as_deref(), Some("r2"));
    assert_eq!(name_of(&["_bot"], "r3").as_deref(), Some("r3"));
    assert_eq!(name_of(&[&longest], "r3"), Some(longest.clone()));
    assert_eq!(name_of(&[&too_long], "_bot"), None);
    assert_eq!(name_of(&[], &too_long), None);
}

#[test]
fn tls_client_without_certificate_fails_when_one_is_required() {
    let pki = Pki::generate();
    let err = connect(&pki, ClientAuth::Required, None).unwrap_err();
    assert!(
        matches!(err, rustls::Error::NoCertificatesPresented),
        "{err:?}"
    );
}

#[test]
fn tls_client_certificate_from_another_ca_is_rejected() {
    let pki = Pki::generate();
    let err = connect(&pki, ClientAuth::Required, Some("rogue")).unwrap_err();
    assert!(
        matches!(err, rustls::Error::InvalidCertificate(_)),
        "{err:?}"
    );
}

#[test]
fn optional_client_auth_lets_tokens_only_clients_in() {
    let pki = Pki::generate();
    let server = connect(&pki, ClientAuth::Optional, None).unwrap();
    assert_eq!(client_cert_name(server.peer_certificates()), None);
}

#[test]
fn agent_refuses_a_hub_not_signed_by_its_ca() {
    let pki = Pki::generate();
    let other = Pki::generate();
    let server_cfg = server_config(&server_files(&other, ClientAuth::None)).unwrap();
    let client_cfg = client_config(&client_files(&pki, None)).unwrap();
    let mut client =
        ClientConnection::new(client_cfg, ServerName::try_from("localhost").unwrap()).unwrap();
    let mut server = ServerConnection::new(server_cfg).unwrap();
    let err = handshake(&mut client, &mut server).unwrap_err();
    assert!(
        matches!(err, rustls::Error::InvalidCertificate(_)),
        "{err:?}"
    );
}

#[test]
fn server_config_reloads_when_files_change_and_keeps_old_on_error() {
    let pki = Pki::generate();
    let reloader = ReloadingServerConfig::load(server_files(&pki, ClientAuth::None)).unwrap();
    let first = reloader.current();
    assert!(!reloader.reload_if_changed().unwrap());

    pki.reissue_server();
    bump_mtime(&pki.path("server.pem"));
    assert!(reloader.reload_if_changed().unwrap());
    let second = reloader.current();
    assert!(!Arc::ptr_eq(&first, &second));

    std::fs::write(pki.path("server.key"), "not a key").unwrap();
    bump_mtime(&pki.path("server.key"));
    let err = reloader.reload_if_changed().unwrap_err();
    assert!(
        matches!(err, TlsError::Pem { .. } | TlsError::Rustls(_)),
        "{err}"
    );
    assert!(
        Arc::ptr_eq(&second, &reloader.current()),
        "old config stays"
    );
}

#[test]
fn missing_files_are_named_in_the_error() {
    let pki = Pki::generate();
    let mut files = server_files(&pki, ClientAuth::None);
    files.cert = pki.path("nope.pem");
    let err = server_config(&files).unwrap_err().to_string();
    assert!(err.contains("nope.pem"), "{err}");
}

/// Filesystems with coarse timestamps may not see a same-second rewrite; set one.
fn bump_mtime(path: &std::path::Path) {
    let f = std::fs::File::options().write(true).open(path).unwrap();
    let later = SystemTime::now() + Duration::from_secs(5);
    f.set_modified(later).unwrap();
}
