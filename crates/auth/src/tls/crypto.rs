//! The `ring` crypto provider, completed for RSA-PSS keys.
//!
//! `openssl genpkey -algorithm RSA-PSS` makes a key whose PKCS#8 and certificate name the
//! algorithm `rsassaPss` instead of `rsaEncryption`. The key material is an ordinary RSA
//! key, but `ring` loads only `rsaEncryption` keys and webpki verifies signatures only
//! with `rsaEncryption` public keys. Two additions close that gap, nothing else changes:
//!
//! - [`PssKeys`] (the provider's key loader) unwraps an `rsassaPss` PKCS#8 to its RSA key
//!   and signs only with RSA-PSS schemes, as such a key demands (RFC 4055, RFC 8446 4.2.3).
//! - [`algorithms`] adds verifiers for `rsassaPss` public keys to ring's set: used for
//!   handshake signatures and for certificates such a key signed with a salt as long as
//!   the hash (what TLS and `-sigopt rsa_pss_saltlen:digest` use; `ring` verifies
//!   no other salt length).

use std::sync::{Arc, LazyLock};

use rustls::SignatureScheme;
use rustls::crypto::{CryptoProvider, KeyProvider, WebPkiSupportedAlgorithms};
use rustls::pki_types::{
    AlgorithmIdentifier, InvalidSignature, PrivateKeyDer, PrivatePkcs1KeyDer,
    SignatureVerificationAlgorithm, alg_id,
};
use rustls::sign::{Signer, SigningKey};

/// `rsassaPss` (1.2.840.113549.1.1.10) without parameters, as an AlgorithmIdentifier's
/// contents: what `openssl genpkey -algorithm RSA-PSS` puts in keys and certificates.
const RSASSA_PSS: AlgorithmIdentifier = AlgorithmIdentifier::from_slice(&[
    0x06, 0x09, 0x2a, 0x86, 0x48, 0x86, 0xf7, 0x0d, 0x01, 0x01, 0x0a,
]);
/// The same OID in dotted form, to recognise it in a PKCS#8 PrivateKeyInfo.
pub(crate) const RSASSA_PSS_OID: &str = "1.2.840.113549.1.1.10";

/// The provider every TLS config of fleetlink uses: ring, with `PssKeys` (RSA-PSS key
/// loading) and `algorithms` (RSA-PSS public keys).
pub fn provider() -> Arc<CryptoProvider> {
    Arc::new(CryptoProvider {
        key_provider: &PssKeys,
        signature_verification_algorithms: algorithms(),
        ..rustls::crypto::ring::default_provider()
    })
}

/// A signature by an `rsassaPss` public key, the salt as long as the hash.
#[derive(Debug)]
struct PssPublicKey {
    signature_alg_id: AlgorithmIdentifier,
    ring: &'static ring::signature::RsaParameters,
}

impl SignatureVerificationAlgorithm for PssPublicKey {
    fn verify_signature(
        &self,
        public_key: &[u8],
        message: &[u8],
        signature: &[u8],
    ) -> Result<(), InvalidSignature> {
        // The subjectPublicKey of an rsassaPss key is an RSAPublicKey, as for rsaEncryption.
        ring::signature::UnparsedPublicKey::new(self.ring, public_key)
            .verify(message, signature)
            .map_err(|_| InvalidSignature)
    }

    fn public_key_alg_id(&self) -> AlgorithmIdentifier {
        RSASSA_PSS
    }

    fn signature_alg_id(&self) -> AlgorithmIdentifier {
        self.signature_alg_id
    }
}

static PSS_SHA256: PssPublicKey = PssPublicKey {
    signature_alg_id: alg_id::RSA_PSS_SHA256,
    ring: &ring::signature::RSA_PSS_2048_8192_SHA256,
};
static PSS_SHA384: PssPublicKey = PssPublicKey {
    signature_alg_id: alg_id::RSA_PSS_SHA384,
    ring: &ring::signature::RSA_PSS_2048_8192_SHA384,
};
static PSS_SHA512: PssPublicKey = PssPublicKey {
    signature_alg_id: alg_id::RSA_PSS_SHA512,
    ring: &ring::signature::RSA_PSS_2048_8192_SHA512,
};

type Algs = &'static [&'static dyn SignatureVerificationAlgorithm];

/// ring's algorithms, plus [`PssPublicKey`] for each RSA-PSS hash. In the TLS scheme
/// mapping the `rsassaPss` key comes second: TLS 1.2 tries every candidate; for TLS 1.3,
/// where rustls tries only the first, the verifiers in `verify` fall back to the rest.
pub fn algorithms() -> WebPkiSupportedAlgorithms {
    static ALL: LazyLock<Vec<&'static dyn SignatureVerificationAlgorithm>> = LazyLock::new(|| {
        let ring = rustls::crypto::ring::default_provider().signature_verification_algorithms;
        let mut all = ring.all.to_vec();
        all.extend([
            &PSS_SHA256 as &dyn SignatureVerificationAlgorithm,
            &PSS_SHA384,
            &PSS_SHA512,
        ]);
        all
    });
    static MAPPING: LazyLock<Vec<(SignatureScheme, Algs)>> = LazyLock::new(|| {
        let ring = rustls::crypto::ring::default_provider().signature_verification_algorithms;
        ring.mapping
            .iter()
            .map(|&(scheme, algs)| {
                let extra: &'static dyn SignatureVerificationAlgorithm = match scheme {
                    SignatureScheme::RSA_PSS_SHA256 => &PSS_SHA256,
                    SignatureScheme::RSA_PSS_SHA384 => &PSS_SHA384,
                    SignatureScheme::RSA_PSS_SHA512 => &PSS_SHA512,
                    _ => return (scheme, algs),
                };
                let mut with = algs.to_vec();
                with.push(extra);
                // Built once for the process's life; the mapping must be 'static.
                (scheme, &*Box::leak(with.into_boxed_slice()))
            })
            .collect()
    });
    WebPkiSupportedAlgorithms {
        all: ALL.as_slice(),
        mapping: MAPPING.as_slice(),
    }
}

/// ring's key loader, plus PKCS#8 keys of algorithm `rsassaPss`.
#[derive(Debug)]
pub struct PssKeys;

impl KeyProvider for PssKeys {
    fn load_private_key(
        &self,
        key_der: PrivateKeyDer<'static>,
    ) -> Result<Arc<dyn SigningKey>, rustls::Error> {
        if let PrivateKeyDer::Pkcs8(pkcs8) = &key_der
            && let Some(rsa) = pss_pkcs8_inner(pkcs8.secret_pkcs8_der())
        {
            let inner = rustls::crypto::ring::sign::any_supported_type(&PrivateKeyDer::Pkcs1(
                PrivatePkcs1KeyDer::from(rsa),
            ))?;
            return Ok(Arc::new(PssOnly(inner)));
        }
        rustls::crypto::ring::default_provider()
            .key_provider
            .load_private_key(key_der)
    }
}

/// The RSAPrivateKey inside a PKCS#8 PrivateKeyInfo whose algorithm is `rsassaPss`;
/// `None` for any other key (those go to ring as they are).
fn pss_pkcs8_inner(der: &[u8]) -> Option<Vec<u8>> {
    use x509_parser::der_parser::parse_der;
    let (_, info) = parse_der(der).ok()?;
    let fields = info.as_sequence().ok()?;
    let alg = fields.get(1)?.as_sequence().ok()?;
    if alg.first()?.as_oid().ok()?.to_id_string() != RSASSA_PSS_OID {
        return None;
    }
    Some(fields.get(2)?.as_slice().ok()?.to_vec())
}

/// An RSA key that may sign only with RSA-PSS (its certificate says `rsassaPss`).
#[derive(Debug)]
struct PssOnly(Arc<dyn SigningKey>);

impl SigningKey for PssOnly {
    fn choose_scheme(&self, offered: &[SignatureScheme]) -> Option<Box<dyn Signer>> {
        let pss: Vec<SignatureScheme> = offered
            .iter()
            .copied()
            .filter(|s| {
                matches!(
                    s,
                    SignatureScheme::RSA_PSS_SHA256
                        | SignatureScheme::RSA_PSS_SHA384
                        | SignatureScheme::RSA_PSS_SHA512
                )
            })
            .collect();
        self.0.choose_scheme(&pss)
    }

    fn algorithm(&self) -> rustls::SignatureAlgorithm {
        self.0.algorithm()
    }
}
