//! OIDC bearer tokens: a JWKS with an Ed25519 key generated at test time, tokens signed
//! with it, and the ways a token must fail.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use fleetlink_auth::acl::AclDefaults;
use fleetlink_auth::jwt::{JwtConfig, JwtError};
use fleetlink_auth::{AuthError, AuthPolicy, Credential, IdentityKind, Security};
use jsonwebtoken::{Algorithm, EncodingKey, Header};
use serde_json::json;

use crate::util::*;

struct Provider {
    key: rcgen::KeyPair,
    kid: &'static str,
}

impl Provider {
    fn new(kid: &'static str) -> Provider {
        Provider {
            key: rcgen::KeyPair::generate_for(&rcgen::PKCS_ED25519).unwrap(),
            kid,
        }
    }

    fn jwks(&self) -> String {
        json!({"keys": [{
            "kty": "OKP", "crv": "Ed25519", "use": "sig", "alg": "EdDSA",
            "kid": self.kid,
            "x": URL_SAFE_NO_PAD.encode(self.key.public_key_raw()),
        }]})
        .to_string()
    }

    fn sign(&self, claims: serde_json::Value) -> String {
        let mut header = Header::new(Algorithm::EdDSA);
        header.kid = Some(self.kid.to_owned());
        let key = EncodingKey::from_ed_der(&self.key.serialize_der());
        jsonwebtoken::encode(&header, &claims, &key).unwrap()
    }
}

fn config() -> JwtConfig {
    let mut c = JwtConfig::new("https://idp.example", "fleetlink");
    c.user_claim = "email".into();
    c.groups_claim = Some("groups".into());
    c
}

fn claims(exp: i64) -> serde_json::Value {
    json!({
        "iss": "https://idp.example", "aud": "fleetlink", "sub": "1234",
        "email": "alice@example.com", "groups": ["/operators", "bad group"],
        "exp": exp, "iat": T0.0,
    })
}

fn setup(p: &Provider) -> Security {
    let sec = security(
        AuthPolicy {
            jwt: Some(config()),
            ..AuthPolicy::default()
        },
        AclDefaults::default(),
    );
    assert!(sec.authn.jwks().needs_refresh(&config(), T0));
    assert_eq!(sec.authn.jwks().install(&p.jwks(), T0).unwrap(), 1);
    sec
}

fn auth(sec: &Security, token: String) -> Result<fleetlink_auth::Identity, AuthError> {
    sec.authenticate(Credential::Bearer(token), peer("192.0.2.1"), T0)
}

#[test]
fn valid_jwt_maps_claims_to_user_and_groups() {
    let p = Provider::new("k1");
    let sec = setup(&p);
    let id = auth(&sec, p.sign(claims(T0.0 + 300))).unwrap();
    assert_eq!(
        id.kind,
        IdentityKind::User {
            name: user("alice@example.com"),
            groups: vec![group("operators")],
        }
    );
}

#[test]
fn expired_jwt_is_rejected_against_the_given_now() {
    let p = Provider::new("k1");
    let sec = setup(&p);
    let err = auth(&sec, p.sign(claims(T0.0 - 61))).unwrap_err();
    assert!(matches!(err, AuthError::Jwt(JwtError::Expired(_))), "{err}");
    // Within the leeway is fine.
    assert!(auth(&sec, p.sign(claims(T0.0 - 30))).is_ok());
}

#[test]
fn jwt_with_wrong_audience_or_issuer_is_rejected() {
    let p = Provider::new("k1");
    let sec = setup(&p);
    let mut c = claims(T0.0 + 300);
    c["aud"] = json!("someone-else");
    assert!(matches!(
        auth(&sec, p.sign(c)),
        Err(AuthError::Jwt(JwtError::Invalid(_)))
    ));
    let mut c = claims(T0.0 + 300);
    c["iss"] = json!("https://evil.example");
    assert!(matches!(
        auth(&sec, p.sign(c)),
        Err(AuthError::Jwt(JwtError::Invalid(_)))
    ));
}

#[test]
fn jwt_signed_by_another_key_with_the_same_kid_is_rejected() {
    let p = Provider::new("k1");
    let sec = setup(&p);
    let forger = Provider::new("k1");
    let err = auth(&sec, forger.sign(claims(T0.0 + 300))).unwrap_err();
    assert!(matches!(err, AuthError::Jwt(JwtError::Invalid(_))), "{err}");
}

#[test]
fn unsigned_or_hmac_jwt_is_rejected() {
    let p = Provider::new("k1");
    let sec = setup(&p);
    let body = URL_SAFE_NO_PAD.encode(claims(T0.0 + 300).to_string());
    let none = format!(
        "{}.{body}.",
        URL_SAFE_NO_PAD.encode(r#"{"alg":"none","kid":"k1"}"#)
    );
    assert!(auth(&sec, none).is_err());
    // HS256 keyed with the public key bytes: the classic algorithm-confusion forgery.
    let mut header = Header::new(Algorithm::HS256);
    header.kid = Some("k1".into());
    let hs = jsonwebtoken::encode(
        &header,
        &claims(T0.0 + 300),
        &EncodingKey::from_secret(p.key.public_key_raw()),
    )
    .unwrap();
    let err = auth(&sec, hs).unwrap_err();
    assert!(
        matches!(err, AuthError::Jwt(JwtError::AlgorithmMismatch { .. })),
        "{err}"
    );
}

#[test]
fn unknown_kid_asks_for_a_rate_limited_refresh() {
    let p = Provider::new("k1");
    let sec = setup(&p);
    let rotated = Provider::new("k2");
    let token = rotated.sign(claims(T0.0 + 300));
    let err = auth(&sec, token.clone()).unwrap_err();
    assert!(
        matches!(err, AuthError::Jwt(JwtError::UnknownKey(_))),
        "{err}"
    );
    let jwks = sec.authn.jwks();
    assert!(
        !jwks.needs_refresh(&config(), T0.plus_secs(1)),
        "too soon after a fetch"
    );
    assert!(jwks.needs_refresh(&config(), T0.plus_secs(30)));
    jwks.install(&rotated.jwks(), T0.plus_secs(30)).unwrap();
    assert!(!jwks.needs_refresh(&config(), T0.plus_secs(31)));
    assert!(auth(&sec, token).is_ok());
    assert!(
        jwks.needs_refresh(&config(), T0.plus_secs(30 + 3600)),
        "TTL"
    );
}
