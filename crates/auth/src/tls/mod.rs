//! TLS configuration: the hub's `rustls::ServerConfig` (reloaded when its files change),
//! the agent's `rustls::ClientConfig`, and robot names from client certificates.
//!
//! Design choice: the whole `ServerConfig` is rebuilt from the files and swapped behind an
//! `ArcSwap`, rather than only the certificate resolver, so a renewed client CA takes
//! effect the same way as a renewed certificate; connections already open keep the config
//! they started with. Reloading is driven by the caller ([`ReloadingServerConfig::reload_if_changed`]
//! on a timer) — no watcher thread, no inotify — and a broken file keeps the old config.
//! Only the `ring` provider is used, completed for RSA-PSS keys ([`provider`]); the agent
//! checks the hub with [`HubVerifier`] (webpki, plus certificates of `tls.ca` pinned, so a
//! self-signed `openssl req -x509` certificate works), the hub checks robots with
//! [`RobotVerifier`].

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::SystemTime;

use arc_swap::ArcSwap;
use rustls::RootCertStore;
use rustls::pki_types::pem::PemObject;
use rustls::pki_types::{CertificateDer, PrivateKeyDer};
use rustls::server::WebPkiClientVerifier;
use rustls::{ClientConfig, ServerConfig};

use crate::identity::RobotName;

/// A TLS set-up failure, naming the file involved.
#[derive(Debug, thiserror::Error)]
pub enum TlsError {
    #[error("cannot read {path}: {source}")]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("cannot parse PEM in {path}: {source}")]
    Pem {
        path: PathBuf,
        source: rustls::pki_types::pem::Error,
    },
    #[error("no certificate in {0}")]
    NoCertificate(PathBuf),
    #[error("CA file {path}: {reason}")]
    BadCa { path: PathBuf, reason: String },
    #[error("no system root certificates could be loaded: {0}")]
    NoSystemRoots(String),
    #[error("client certificate verifier: {0}")]
    Verifier(#[from] rustls::server::VerifierBuilderError),
    #[error("TLS configuration: {0}")]
    Rustls(#[from] rustls::Error),
}

mod crypto;
pub mod federation;
mod verify;

pub use crypto::provider;
pub use verify::{HubCertError, HubVerifier, RobotVerifier};

fn pem_err(path: &Path) -> impl FnOnce(rustls::pki_types::pem::Error) -> TlsError + '_ {
    move |source| match source {
        rustls::pki_types::pem::Error::Io(source) => TlsError::Read {
            path: path.to_owned(),
            source,
        },
        source => TlsError::Pem {
            path: path.to_owned(),
            source,
        },
    }
}

/// All certificates in a PEM file, in order (leaf first for a chain).
pub fn load_certs(path: &Path) -> Result<Vec<CertificateDer<'static>>, TlsError> {
    let certs = CertificateDer::pem_file_iter(path)
        .map_err(pem_err(path))?
        .collect::<Result<Vec<_>, _>>()
        .map_err(pem_err(path))?;
    if certs.is_empty() {
        return Err(TlsError::NoCertificate(path.to_owned()));
    }
    Ok(certs)
}

/// The first private key (PKCS#8, PKCS#1 or SEC1) in a PEM file.
pub fn load_key(path: &Path) -> Result<PrivateKeyDer<'static>, TlsError> {
    PrivateKeyDer::from_pem_file(path).map_err(pem_err(path))
}

fn load_roots(path: &Path) -> Result<RootCertStore, TlsError> {
    let mut roots = RootCertStore::empty();
    for cert in load_certs(path)? {
        roots.add(cert).map_err(|e| TlsError::BadCa {
            path: path.to_owned(),
            reason: e.to_string(),
        })?;
    }
    Ok(roots)
}

/// Whether the hub asks robots for a client certificate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ClientAuth {
    #[default]
    None,
    /// Verified if presented; clients without one fall back to tokens.
    Optional,
    /// The handshake fails without a certificate signed by the client CA.
    Required,
}

/// The files a hub's TLS listener is built from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ServerTlsFiles {
    /// Certificate chain, leaf first.
    pub cert: PathBuf,
    pub key: PathBuf,
    /// CA that signs robot client certificates; required unless `client_auth` is `None`.
    pub client_ca: Option<PathBuf>,
    pub client_auth: ClientAuth,
}

impl ServerTlsFiles {
    fn paths(&self) -> impl Iterator<Item = &Path> {
        [Some(&self.cert), Some(&self.key), self.client_ca.as_ref()]
            .into_iter()
            .flatten()
            .map(PathBuf::as_path)
    }
}

/// Builds a server config (ALPN `http/1.1`, as WebSocket upgrades need).
pub fn server_config(files: &ServerTlsFiles) -> Result<Arc<ServerConfig>, TlsError> {
    let builder =
        ServerConfig::builder_with_provider(provider()).with_safe_default_protocol_versions()?;
    let builder = match (&files.client_ca, files.client_auth) {
        (_, ClientAuth::None) => builder.with_no_client_auth(),
        (None, _) => {
            return Err(TlsError::BadCa {
                path: PathBuf::new(),
                reason: "client certificates requested but no client CA file configured".to_owned(),
            });
        }
        (Some(ca), mode) => {
            let verifier =
                WebPkiClientVerifier::builder_with_provider(Arc::new(load_roots(ca)?), provider());
            let verifier = if mode == ClientAuth::Optional {
                verifier.allow_unauthenticated()
            } else {
                verifier
            };
            builder.with_client_cert_verifier(Arc::new(RobotVerifier::new(verifier.build()?)))
        }
    };
    let mut config = builder.with_single_cert(load_certs(&files.cert)?, load_key(&files.key)?)?;
    config.alpn_protocols = vec![b"http/1.1".to_vec()];
    Ok(Arc::new(config))
}

/// A server config that follows its files.
pub struct ReloadingServerConfig {
    files: ServerTlsFiles,
    current: ArcSwap<ServerConfig>,
    // std Mutex: only the reload timer takes it; never held across an await.
    stamps: Mutex<Vec<Option<SystemTime>>>,
}

fn stamps(files: &ServerTlsFiles) -> Vec<Option<SystemTime>> {
    files
        .paths()
        .map(|p| std::fs::metadata(p).and_then(|m| m.modified()).ok())
        .collect()
}

impl ReloadingServerConfig {
    pub fn load(files: ServerTlsFiles) -> Result<ReloadingServerConfig, TlsError> {
        let before = stamps(&files);
        let config = server_config(&files)?;
        Ok(ReloadingServerConfig {
            files,
            current: ArcSwap::new(config),
            stamps: Mutex::new(before),
        })
    }

    /// The config to accept the next connection with.
    pub fn current(&self) -> Arc<ServerConfig> {
        self.current.load_full()
    }

    /// Rebuilds the config if any file's modification time changed. `Ok(true)` when a new
    /// config is in place; on error the previous config stays and the next call retries.
    pub fn reload_if_changed(&self) -> Result<bool, TlsError> {
        let mut seen = self.stamps.lock().unwrap_or_else(|p| p.into_inner());
        let now = stamps(&self.files);
        if now == *seen {
            return Ok(false);
        }
        let config = server_config(&self.files)?;
        self.current.store(config);
        *seen = now;
        Ok(true)
    }
}

/// Which roots an agent trusts for the hub's certificate.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum HubRoots {
    /// The operating system's store (`rustls-native-certs`).
    System,
    /// Only this CA file (a private hub CA).
    CaFile(PathBuf),
}

/// What an agent needs to connect to a `wss://` hub.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ClientTlsFiles {
    pub roots: HubRoots,
    /// Client certificate chain and key, for hubs that require mutual TLS.
    pub client_cert: Option<(PathBuf, PathBuf)>,
}

/// The agent's config: the hub's certificate checked by [`HubVerifier`] (webpki, and
/// certificates of the `tls.ca` file pinned).
pub fn client_config(files: &ClientTlsFiles) -> Result<Arc<ClientConfig>, TlsError> {
    let mut pinned = Vec::new();
    let roots = match &files.roots {
        HubRoots::CaFile(path) => {
            pinned = load_certs(path)?;
            load_roots(path)?
        }
        HubRoots::System => {
            let found = rustls_native_certs::load_native_certs();
            let mut roots = RootCertStore::empty();
            let (added, _) = roots.add_parsable_certificates(found.certs);
            if added == 0 {
                let why = found
                    .errors
                    .first()
                    .map_or_else(|| "none found".to_owned(), ToString::to_string);
                return Err(TlsError::NoSystemRoots(why));
            }
            roots
        }
    };
    let webpki =
        rustls::client::WebPkiServerVerifier::builder_with_provider(Arc::new(roots), provider())
            .build()
            .map_err(|e| TlsError::BadCa {
                path: match &files.roots {
                    HubRoots::CaFile(p) => p.clone(),
                    HubRoots::System => PathBuf::from("<system roots>"),
                },
                reason: e.to_string(),
            })?;
    let builder = ClientConfig::builder_with_provider(provider())
        .with_safe_default_protocol_versions()?
        .dangerous()
        .with_custom_certificate_verifier(Arc::new(HubVerifier::new(webpki, pinned)));
    let config = match &files.client_cert {
        None => builder.with_no_client_auth(),
        Some((cert, key)) => builder.with_client_auth_cert(load_certs(cert)?, load_key(key)?)?,
    };
    Ok(Arc::new(config))
}

/// The robot named by a client certificate the handshake has already verified
/// (`ServerConnection::peer_certificates()`): the first DNS SAN that is a valid robot
/// name, else the subject CN. Both are parsed as [`RobotName`], the one robot name rule,
/// so a certificate can never name a robot HELLO would refuse. `None` if there is no
/// certificate or no usable name (the connection may still authenticate with a token).
pub fn client_cert_name(peer_certificates: Option<&[CertificateDer<'_>]>) -> Option<RobotName> {
    let leaf = peer_certificates?.first()?;
    let (_, cert) = x509_parser::parse_x509_certificate(leaf.as_ref()).ok()?;
    if let Ok(Some(san)) = cert.subject_alternative_name() {
        for name in &san.value.general_names {
            if let x509_parser::extensions::GeneralName::DNSName(dns) = name
                && let Ok(robot) = RobotName::new(dns)
            {
                return Some(robot);
            }
        }
    }
    let cn = cert.subject().iter_common_name().next()?.as_str().ok()?;
    RobotName::new(cn).ok()
}
