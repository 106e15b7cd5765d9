//! Password hashing: argon2id with the crate's default (OWASP-recommended) parameters.
//!
//! Design choice: verification against an unknown user still runs one argon2 hash (of a
//! fixed dummy), so response time does not reveal which user names exist.

use std::sync::OnceLock;

use argon2::Argon2;
use argon2::password_hash::phc::PasswordHash;
use argon2::password_hash::{PasswordHasher, PasswordVerifier};

/// Longest password accepted, in bytes; longer input is refused before hashing so a
/// megabyte "password" cannot be used to burn CPU.
pub const MAX_PASSWORD_LEN: usize = 1024;

/// A PHC string (`$argon2id$v=19$…`) for `password`, with a fresh random salt.
pub(crate) fn hash(password: &str) -> Result<String, String> {
    if password.len() > MAX_PASSWORD_LEN {
        return Err(format!("password longer than {MAX_PASSWORD_LEN} bytes"));
    }
    Argon2::default()
        .hash_password(password.as_bytes())
        .map(|h| h.to_string())
        .map_err(|e| e.to_string())
}

/// Whether `password` matches the stored PHC string. A malformed stored hash never
/// matches.
pub(crate) fn verify(password: &str, phc: &str) -> bool {
    match PasswordHash::new(phc) {
        Ok(parsed) => Argon2::default()
            .verify_password(password.as_bytes(), &parsed)
            .is_ok(),
        Err(_) => false,
    }
}

/// Burns the same work as a real verification, for unknown users.
pub(crate) fn verify_dummy(password: &str) {
    static DUMMY: OnceLock<String> = OnceLock::new();
    let phc = DUMMY.get_or_init(|| hash("fleetlink-dummy-password").unwrap_or_default());
    let _ = verify(password, phc);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hash_verifies_only_the_right_password() {
        let phc = hash("correct horse").unwrap();
        assert!(phc.starts_with("$argon2id$"));
        assert!(verify("correct horse", &phc));
        assert!(!verify("battery staple", &phc));
        assert!(!verify("correct horse", "not-a-phc-string"));
    }
}
