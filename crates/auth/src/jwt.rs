//! OIDC/JWT bearer tokens validated against a cached JWKS (Google, Keycloak, any OIDC
//! provider).
//!
//! Design choice: sans-IO. The crate never fetches the JWKS itself; the hub runs a small
//! refresher that asks [`JwksCache::needs_refresh`] and hands the fetched document to
//! [`JwksCache::install`] (from a file with [`read_jwks_file`], or from the provider's
//! `jwks_uri` with any HTTP client). Validation therefore never blocks on the network and
//! is testable with `now` passed in. A token whose `kid` is unknown asks for an early
//! refresh (key rotation), rate-limited by `min_refresh_secs` so a flood of made-up `kid`s
//! cannot turn into a flood of fetches.
//!
//! The algorithm comes from the key (the JWK's `alg`, else its key type and curve), never
//! from the token header alone, and symmetric (`oct`) keys are ignored: a public JWKS
//! must not be usable as an HMAC secret.

use std::collections::HashMap;
use std::path::Path;
use std::sync::Mutex;

use jsonwebtoken::jwk::{AlgorithmParameters, EllipticCurve, Jwk, JwkSet};
use jsonwebtoken::{Algorithm, DecodingKey, Validation};
use serde_json::Value;

use crate::UnixTime;
use crate::identity::{GroupName, UserName};

/// Why a JWT was refused or a JWKS could not be used.
#[derive(Debug, thiserror::Error)]
pub enum JwtError {
    #[error("malformed JWT: {0}")]
    Malformed(jsonwebtoken::errors::Error),
    #[error("JWT has no `kid` header")]
    NoKeyId,
    #[error("no JWKS key with kid {0:?} (yet)")]
    UnknownKey(String),
    #[error("JWT header alg {header:?} does not match its key's {key:?}")]
    AlgorithmMismatch { header: Algorithm, key: Algorithm },
    #[error("JWT rejected: {0}")]
    Invalid(jsonwebtoken::errors::Error),
    #[error("JWT expired at {0}")]
    Expired(i64),
    #[error("JWT not valid before {0}")]
    NotYetValid(i64),
    #[error("JWT claim {claim:?} missing or invalid: {reason}")]
    Claim { claim: String, reason: String },
    #[error("invalid JWKS document: {0}")]
    BadJwks(serde_json::Error),
    #[error("cannot read JWKS file {path}: {source}")]
    ReadJwks {
        path: String,
        source: std::io::Error,
    },
}

/// Which tokens to accept and how to map their claims to a user.
#[derive(Debug, Clone)]
pub struct JwtConfig {
    /// Accepted `iss` values (e.g. `https://accounts.google.com`).
    pub issuers: Vec<String>,
    /// Accepted `aud` values (the client id registered with the provider).
    pub audiences: Vec<String>,
    /// Claim holding the user name: `sub` (stable) or `email` / `preferred_username`.
    pub user_claim: String,
    /// Claim holding a list of groups (Keycloak: `groups`), if any.
    pub groups_claim: Option<String>,
    /// Clock skew tolerated on `exp`/`nbf`, in seconds.
    pub leeway_secs: i64,
    /// How long a fetched JWKS is used before a refresh is due.
    pub jwks_ttl_secs: i64,
    /// Minimum time between refreshes asked for by unknown `kid`s.
    pub min_refresh_secs: i64,
}

impl JwtConfig {
    pub fn new(issuer: impl Into<String>, audience: impl Into<String>) -> JwtConfig {
        JwtConfig {
            issuers: vec![issuer.into()],
            audiences: vec![audience.into()],
            user_claim: "sub".to_owned(),
            groups_claim: None,
            leeway_secs: 60,
            jwks_ttl_secs: 3600,
            min_refresh_secs: 30,
        }
    }
}

/// Reads a JWKS document from a file (the "file" JWKS source).
pub fn read_jwks_file(path: &Path) -> Result<String, JwtError> {
    std::fs::read_to_string(path).map_err(|source| JwtError::ReadJwks {
        path: path.display().to_string(),
        source,
    })
}

struct Key {
    key: DecodingKey,
    alg: Algorithm,
}

#[derive(Default)]
struct CacheState {
    keys: HashMap<String, Key>,
    fetched_at: Option<UnixTime>,
    refresh_wanted: bool,
}

/// Keys by `kid`, with the time they were installed.
#[derive(Default)]
pub struct JwksCache {
    // std Mutex: held only to look up or swap keys, never across I/O or an await.
    state: Mutex<CacheState>,
}

fn key_algorithm(jwk: &Jwk) -> Option<Algorithm> {
    if let Some(alg) = jwk.common.key_algorithm {
        return Algorithm::try_from(alg).ok();
    }
    match &jwk.algorithm {
        AlgorithmParameters::RSA(_) => Some(Algorithm::RS256),
        AlgorithmParameters::EllipticCurve(p) => match p.curve {
            EllipticCurve::P256 => Some(Algorithm::ES256),
            EllipticCurve::P384 => Some(Algorithm::ES384),
            _ => None,
        },
        AlgorithmParameters::OctetKeyPair(p) => {
            (p.curve == EllipticCurve::Ed25519).then_some(Algorithm::EdDSA)
        }
        _ => None,
    }
}

impl JwksCache {
    pub fn new() -> JwksCache {
        JwksCache::default()
    }

    /// Replaces the keys with those of a JWKS document. Keys without a `kid`, symmetric
    /// keys and keys of unsupported types are skipped; returns how many were installed.
    pub fn install(&self, document: &str, now: UnixTime) -> Result<usize, JwtError> {
        let set: JwkSet = serde_json::from_str(document).map_err(JwtError::BadJwks)?;
        let mut keys = HashMap::new();
        for jwk in &set.keys {
            if matches!(jwk.algorithm, AlgorithmParameters::OctetKey(_)) {
                continue;
            }
            let (Some(kid), Some(alg)) = (jwk.common.key_id.clone(), key_algorithm(jwk)) else {
                continue;
            };
            if matches!(alg, Algorithm::HS256 | Algorithm::HS384 | Algorithm::HS512) {
                continue;
            }
            if let Ok(key) = DecodingKey::from_jwk(jwk) {
                keys.insert(kid, Key { key, alg });
            }
        }
        let n = keys.len();
        let mut st = self.state.lock().unwrap_or_else(|p| p.into_inner());
        *st = CacheState {
            keys,
            fetched_at: Some(now),
            refresh_wanted: false,
        };
        Ok(n)
    }

    /// Whether the refresher should fetch now: never fetched, older than the TTL, or an
    /// unknown `kid` was seen and the last fetch is at least `min_refresh_secs` old.
    pub fn needs_refresh(&self, config: &JwtConfig, now: UnixTime) -> bool {
        let st = self.state.lock().unwrap_or_else(|p| p.into_inner());
        match st.fetched_at {
            None => true,
            Some(at) => {
                let age = now.0 - at.0;
                age >= config.jwks_ttl_secs || (st.refresh_wanted && age >= config.min_refresh_secs)
            }
        }
    }

    /// Validates `token` and returns the user name and groups from its claims.
    pub fn validate(
        &self,
        config: &JwtConfig,
        token: &str,
        now: UnixTime,
    ) -> Result<(UserName, Vec<GroupName>), JwtError> {
        let header = jsonwebtoken::decode_header(token).map_err(JwtError::Malformed)?;
        let kid = header.kid.ok_or(JwtError::NoKeyId)?;
        let claims: Value = {
            let mut st = self.state.lock().unwrap_or_else(|p| p.into_inner());
            let Some(key) = st.keys.get(&kid) else {
                st.refresh_wanted = true;
                return Err(JwtError::UnknownKey(kid.chars().take(64).collect()));
            };
            if header.alg != key.alg {
                return Err(JwtError::AlgorithmMismatch {
                    header: header.alg,
                    key: key.alg,
                });
            }
            let mut v = Validation::new(key.alg);
            v.set_issuer(&config.issuers);
            v.set_audience(&config.audiences);
            // Time is checked below against the `now` we were given, not the wall clock.
            v.validate_exp = false;
            v.validate_nbf = false;
            v.set_required_spec_claims(&["iss", "aud"]);
            jsonwebtoken::decode::<Value>(token, &key.key, &v)
                .map_err(JwtError::Invalid)?
                .claims
        };
        check_time(&claims, config.leeway_secs, now)?;
        user_from_claims(config, &claims)
    }
}

fn check_time(claims: &Value, leeway: i64, now: UnixTime) -> Result<(), JwtError> {
    let exp = claims
        .get("exp")
        .and_then(Value::as_i64)
        .ok_or_else(|| JwtError::Claim {
            claim: "exp".to_owned(),
            reason: "required integer".to_owned(),
        })?;
    if now.0 > exp.saturating_add(leeway) {
        return Err(JwtError::Expired(exp));
    }
    if let Some(nbf) = claims.get("nbf").and_then(Value::as_i64)
        && now.0 < nbf.saturating_sub(leeway)
    {
        return Err(JwtError::NotYetValid(nbf));
    }
    Ok(())
}

fn user_from_claims(
    config: &JwtConfig,
    claims: &Value,
) -> Result<(UserName, Vec<GroupName>), JwtError> {
    let claim_err = |claim: &str, reason: String| JwtError::Claim {
        claim: claim.to_owned(),
        reason,
    };
    let user = claims
        .get(&config.user_claim)
        .and_then(Value::as_str)
        .ok_or_else(|| claim_err(&config.user_claim, "missing or not a string".to_owned()))?;
    let user = UserName::new(user).map_err(|e| claim_err(&config.user_claim, e.to_string()))?;
    let mut groups = Vec::new();
    if let Some(gc) = &config.groups_claim
        && let Some(list) = claims.get(gc).and_then(Value::as_array)
    {
        // Keycloak prefixes groups with '/'; a group we cannot represent is skipped
        // rather than failing the login.
        for g in list.iter().filter_map(Value::as_str).take(256) {
            if let Ok(g) = GroupName::new(g.trim_start_matches('/')) {
                groups.push(g);
            }
        }
    }
    Ok((user, groups))
}
