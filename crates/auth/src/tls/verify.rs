//! Certificate verifiers: the agent's check of the hub and the hub's check of robots.
//!
//! [`HubVerifier`] is webpki's verifier plus one rule: a hub certificate that is
//! byte-identical to a certificate in the agent's `tls.ca` file is trusted as pinned.
//! `openssl req -x509 …` makes a self-signed certificate with `CA:TRUE`; webpki refuses
//! such a certificate as a server's own (`CaUsedAsEndEntity`), although the user
//! said to trust exactly that certificate. For a pinned certificate the chain is the
//! certificate itself, so what is left to check is what webpki would check of the leaf:
//! the server name, the validity period and — what proves the hub holds the key — the
//! handshake signature. Every other certificate goes to webpki unchanged. Pinning adds
//! no trust beyond the file: a hub presenting a CA certificate from `tls.ca` and signing
//! with its key holds that CA's key, and could issue itself a leaf anyway.
//!
//! Both verifiers also accept `rsassaPss` keys in TLS 1.3 handshakes (see `crypto`).

use std::sync::Arc;

use rustls::client::danger::{HandshakeSignatureValid, ServerCertVerified, ServerCertVerifier};
use rustls::client::{WebPkiServerVerifier, verify_server_name};
use rustls::crypto::WebPkiSupportedAlgorithms;
use rustls::pki_types::{CertificateDer, ServerName, UnixTime};
use rustls::server::ParsedCertificate;
use rustls::server::danger::{ClientCertVerified, ClientCertVerifier};
use rustls::{CertificateError, DigitallySignedStruct, DistinguishedName, SignatureScheme};

use super::crypto::algorithms;

/// Why the agent does not trust a hub's certificate, when rustls' own errors do not
/// say it well enough to tell the user what to do. Carried in
/// `CertificateError::Other`; the agent matches on it.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HubCertError {
    /// The certificate signed itself and is not in `tls.ca`.
    #[error("the hub's certificate is self-signed and not the one given as tls.ca")]
    SelfSigned,
    /// A CA certificate (not self-signed) presented as the hub's own.
    #[error("the hub presents a CA certificate as its own")]
    CaAsServer,
}

impl HubCertError {
    /// The `HubCertError` inside a rustls error, if that is what it carries.
    pub fn of(e: &rustls::Error) -> Option<&HubCertError> {
        match e {
            rustls::Error::InvalidCertificate(CertificateError::Other(o)) => o.0.downcast_ref(),
            _ => None,
        }
    }
}

fn hub_cert_error(e: HubCertError) -> rustls::Error {
    rustls::Error::InvalidCertificate(CertificateError::Other(rustls::OtherError(Arc::new(e))))
}

/// The agent's verifier of the hub's certificate (see the module docs).
#[derive(Debug)]
pub struct HubVerifier {
    webpki: Arc<WebPkiServerVerifier>,
    pinned: Vec<CertificateDer<'static>>,
    algorithms: WebPkiSupportedAlgorithms,
}

impl HubVerifier {
    /// `pinned`: the certificates of the agent's `tls.ca` file (empty with system roots).
    pub fn new(webpki: Arc<WebPkiServerVerifier>, pinned: Vec<CertificateDer<'static>>) -> Self {
        HubVerifier {
            webpki,
            pinned,
            algorithms: algorithms(),
        }
    }

    fn verify_pinned(
        &self,
        end_entity: &CertificateDer<'_>,
        server_name: &ServerName<'_>,
        now: UnixTime,
    ) -> Result<ServerCertVerified, rustls::Error> {
        verify_server_name(&ParsedCertificate::try_from(end_entity)?, server_name)?;
        let (_, cert) = x509_parser::parse_x509_certificate(end_entity.as_ref())
            .map_err(|_| rustls::Error::InvalidCertificate(CertificateError::BadEncoding))?;
        let now = i64::try_from(now.as_secs()).unwrap_or(i64::MAX);
        let validity = cert.validity();
        if now < validity.not_before.timestamp() {
            return Err(CertificateError::NotValidYet.into());
        }
        if now > validity.not_after.timestamp() {
            return Err(CertificateError::Expired.into());
        }
        Ok(ServerCertVerified::assertion())
    }
}

/// Whether a certificate names itself as its issuer.
fn self_signed(cert: &CertificateDer<'_>) -> bool {
    x509_parser::parse_x509_certificate(cert.as_ref())
        .is_ok_and(|(_, c)| c.issuer().as_raw() == c.subject().as_raw())
}

impl ServerCertVerifier for HubVerifier {
    fn verify_server_cert(
        &self,
        end_entity: &CertificateDer<'_>,
        intermediates: &[CertificateDer<'_>],
        server_name: &ServerName<'_>,
        ocsp_response: &[u8],
        now: UnixTime,
    ) -> Result<ServerCertVerified, rustls::Error> {
        if self
            .pinned
            .iter()
            .any(|p| p.as_ref() == end_entity.as_ref())
        {
            return self.verify_pinned(end_entity, server_name, now);
        }
        self.webpki
            .verify_server_cert(end_entity, intermediates, server_name, ocsp_response, now)
            .map_err(|e| {
                if self_signed(end_entity) {
                    // Only a pin could make it trusted, and it is not pinned.
                    hub_cert_error(HubCertError::SelfSigned)
                } else if matches!(
                    &e,
                    rustls::Error::InvalidCertificate(CertificateError::Other(o))
                        if o.0.downcast_ref::<webpki::Error>() == Some(&webpki::Error::CaUsedAsEndEntity)
                ) {
                    hub_cert_error(HubCertError::CaAsServer)
                } else {
                    e
                }
            })
    }

    fn verify_tls12_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        rustls::crypto::verify_tls12_signature(message, cert, dss, &self.algorithms)
    }

    fn verify_tls13_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        tls13_signature(message, cert, dss, &self.algorithms)
    }

    fn supported_verify_schemes(&self) -> Vec<SignatureScheme> {
        self.algorithms.supported_schemes()
    }
}

/// A TLS 1.3 handshake signature. rustls tries only the first algorithm mapped to the
/// scheme (the `rsaEncryption` one for RSA-PSS); an `rsassaPss` key needs the next, so
/// on a key-type mismatch of an RSA-PSS scheme the remaining candidates are tried the TLS 1.2 way — same
/// scheme, same hash, same salt length.
fn tls13_signature(
    message: &[u8],
    cert: &CertificateDer<'_>,
    dss: &DigitallySignedStruct,
    algorithms: &WebPkiSupportedAlgorithms,
) -> Result<HandshakeSignatureValid, rustls::Error> {
    match rustls::crypto::verify_tls13_signature(message, cert, dss, algorithms) {
        Err(rustls::Error::InvalidCertificate(
            CertificateError::UnsupportedSignatureAlgorithmForPublicKeyContext { .. },
        )) if matches!(
            dss.scheme,
            SignatureScheme::RSA_PSS_SHA256
                | SignatureScheme::RSA_PSS_SHA384
                | SignatureScheme::RSA_PSS_SHA512
        ) =>
        {
            rustls::crypto::verify_tls12_signature(message, cert, dss, algorithms)
        }
        other => other,
    }
}

/// The hub's verifier of robots' client certificates: webpki's, with `rsassaPss` keys
/// accepted in TLS 1.3 handshakes.
#[derive(Debug)]
pub struct RobotVerifier {
    webpki: Arc<dyn ClientCertVerifier>,
    algorithms: WebPkiSupportedAlgorithms,
}

impl RobotVerifier {
    pub fn new(webpki: Arc<dyn ClientCertVerifier>) -> Self {
        RobotVerifier {
            webpki,
            algorithms: algorithms(),
        }
    }
}

impl ClientCertVerifier for RobotVerifier {
    fn offer_client_auth(&self) -> bool {
        self.webpki.offer_client_auth()
    }

    fn client_auth_mandatory(&self) -> bool {
        self.webpki.client_auth_mandatory()
    }

    fn root_hint_subjects(&self) -> &[DistinguishedName] {
        self.webpki.root_hint_subjects()
    }

    fn verify_client_cert(
        &self,
        end_entity: &CertificateDer<'_>,
        intermediates: &[CertificateDer<'_>],
        now: UnixTime,
    ) -> Result<ClientCertVerified, rustls::Error> {
        self.webpki
            .verify_client_cert(end_entity, intermediates, now)
    }

    fn verify_tls12_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        rustls::crypto::verify_tls12_signature(message, cert, dss, &self.algorithms)
    }

    fn verify_tls13_signature(
        &self,
        message: &[u8],
        cert: &CertificateDer<'_>,
        dss: &DigitallySignedStruct,
    ) -> Result<HandshakeSignatureValid, rustls::Error> {
        tls13_signature(message, cert, dss, &self.algorithms)
    }

    fn supported_verify_schemes(&self) -> Vec<SignatureScheme> {
        self.algorithms.supported_schemes()
    }
}
