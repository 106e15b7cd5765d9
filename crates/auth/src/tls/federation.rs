//! Hub certificates of a federation: the name a hub goes by among its fleet's hubs, read
//! from its certificate, and the checks a hub makes of its own files before it joins.
//!
//! A federation certificate's subject common name is `HUB@FLEET` (`eu1@acme`): the hub's
//! name in the other hubs' listings, rules and audit records, and the fleet it belongs
//! to. Both parts are what a Zenoh key chunk may hold (`[A-Za-z0-9_.-]`). The common name
//! is what Zenoh reports for a TLS link (its "auth identifier"), which is why the fleet
//! travels there rather than in an extension: each hub checks every link's name against
//! its own fleet. A public CA never issues such a name, so a web certificate cannot pass
//! for a hub even where Zenoh's client side also trusts the web's roots.
//!
//! The certificate must chain to the fleet's CA (the file every hub of the fleet is
//! given) for both server and client use: a hub accepts links and makes them.

use std::fmt;
use std::path::{Path, PathBuf};

use rustls::pki_types::CertificateDer;

use super::{TlsError, load_certs, load_key};

/// The two names a federation certificate's common name holds.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct HubCertName {
    pub hub: String,
    pub fleet: String,
}

impl fmt::Display for HubCertName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}@{}", self.hub, self.fleet)
    }
}

/// Why a federation certificate (a hub's own, or a peer's name) is not acceptable.
#[derive(Debug, thiserror::Error)]
pub enum FederationCertError {
    #[error(
        "the common name {0:?} is not HUB@FLEET (e.g. eu1@acme, each part of letters, \
         digits, '_', '.', '-'); make the certificate with `fleetlink admin cert federation`"
    )]
    BadName(String),
    #[error("the certificate has no subject common name (it must be HUB@FLEET)")]
    NoName,
    #[error("cannot read the certificate: {0}")]
    Parse(String),
    #[error("{path}: {source}")]
    File { path: PathBuf, source: TlsError },
    #[error(
        "the certificate {cert} names fleet {found:?}, but this hub federates fleet \
         {expected:?} (--fleet): use a certificate made for this fleet"
    )]
    OtherFleet {
        cert: PathBuf,
        found: String,
        expected: String,
    },
    #[error(
        "the certificate {cert} is not signed by the federation CA {ca} ({reason}): every \
         hub's certificate must come from the fleet's CA"
    )]
    NotFromCa {
        cert: PathBuf,
        ca: PathBuf,
        reason: String,
    },
    #[error("the key {key} does not belong to the certificate {cert}")]
    KeyMismatch { cert: PathBuf, key: PathBuf },
    #[error("the key {key}: {reason}")]
    BadKey { key: PathBuf, reason: String },
}

fn is_chunk(s: &str) -> bool {
    !s.is_empty()
        && s.len() <= 128
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.'))
}

impl HubCertName {
    /// Reads `HUB@FLEET`.
    pub fn parse(cn: &str) -> Result<HubCertName, FederationCertError> {
        let bad = || FederationCertError::BadName(cn.chars().take(200).collect());
        let (hub, fleet) = cn.rsplit_once('@').ok_or_else(bad)?;
        if !is_chunk(hub) || !is_chunk(fleet) {
            return Err(bad());
        }
        Ok(HubCertName {
            hub: hub.to_owned(),
            fleet: fleet.to_owned(),
        })
    }

    /// The name in a certificate (DER).
    pub fn of_cert(der: &CertificateDer<'_>) -> Result<HubCertName, FederationCertError> {
        let (_, cert) = x509_parser::parse_x509_certificate(der.as_ref())
            .map_err(|e| FederationCertError::Parse(e.to_string()))?;
        let cn = cert
            .subject()
            .iter_common_name()
            .next()
            .ok_or(FederationCertError::NoName)?
            .as_str()
            .map_err(|e| FederationCertError::Parse(e.to_string()))?;
        HubCertName::parse(cn)
    }
}

/// The files a hub joins its federation with.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FederationFiles {
    /// The fleet's CA: every peer's certificate must chain to it.
    pub ca: PathBuf,
    /// This hub's certificate chain, leaf first, and its key.
    pub cert: PathBuf,
    pub key: PathBuf,
}

/// Checks a hub's own federation files before it joins, so that a mistake is an error at
/// start that names the file, not a handshake every peer refuses: the certificate chains
/// to the CA for server and client use, the key is its key, and its name is `HUB@FLEET`
/// of `fleet`. Returns the name.
pub fn check_own(
    files: &FederationFiles,
    fleet: &str,
    now: crate::UnixTime,
) -> Result<HubCertName, FederationCertError> {
    let now = rustls::pki_types::UnixTime::since_unix_epoch(std::time::Duration::from_secs(
        now.0.max(0) as u64,
    ));
    let file_err = |path: &Path| {
        let path = path.to_owned();
        move |source| FederationCertError::File { path, source }
    };
    let chain = load_certs(&files.cert).map_err(file_err(&files.cert))?;
    let anchors_der = load_certs(&files.ca).map_err(file_err(&files.ca))?;
    let key = load_key(&files.key).map_err(file_err(&files.key))?;
    let name = HubCertName::of_cert(&chain[0])?;
    if name.fleet != fleet {
        return Err(FederationCertError::OtherFleet {
            cert: files.cert.clone(),
            found: name.fleet,
            expected: fleet.to_owned(),
        });
    }
    let not_from_ca = |reason: String| FederationCertError::NotFromCa {
        cert: files.cert.clone(),
        ca: files.ca.clone(),
        reason,
    };
    let anchors = anchors_der
        .iter()
        .map(|c| {
            webpki::anchor_from_trusted_cert(c)
                .map(|a| a.to_owned())
                .map_err(|e| not_from_ca(format!("the CA file: {e}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let leaf = webpki::EndEntityCert::try_from(&chain[0])
        .map_err(|e| not_from_ca(format!("the certificate: {e}")))?;
    let algs = super::crypto::algorithms();
    for usage in [
        webpki::KeyUsage::server_auth(),
        webpki::KeyUsage::client_auth(),
    ] {
        leaf.verify_for_usage(algs.all, &anchors, &chain[1..], now, usage, None, None)
            .map_err(|e| not_from_ca(e.to_string()))?;
    }
    let provider = super::provider();
    let signing =
        provider
            .key_provider
            .load_private_key(key)
            .map_err(|e| FederationCertError::BadKey {
                key: files.key.clone(),
                reason: e.to_string(),
            })?;
    let certified = rustls::sign::CertifiedKey::new(chain, signing);
    match certified.keys_match() {
        Ok(()) | Err(rustls::Error::InconsistentKeys(rustls::InconsistentKeys::Unknown)) => {}
        Err(_) => {
            return Err(FederationCertError::KeyMismatch {
                cert: files.cert.clone(),
                key: files.key.clone(),
            });
        }
    }
    Ok(name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_hub_at_fleet() {
        let n = HubCertName::parse("eu-1.cloud@acme_2").unwrap();
        assert_eq!((n.hub.as_str(), n.fleet.as_str()), ("eu-1.cloud", "acme_2"));
        assert_eq!(n.to_string(), "eu-1.cloud@acme_2");
        for bad in [
            "eu1",
            "@acme",
            "eu1@",
            "eu 1@acme",
            "eu1@ac/me",
            "hub.example.com",
            "a@b@c",
        ] {
            assert!(
                matches!(
                    HubCertName::parse(bad),
                    Err(FederationCertError::BadName(_))
                ),
                "{bad:?} must be refused"
            );
        }
    }
}
