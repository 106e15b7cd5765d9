//! Bearer tokens minted by the hub: `flk_<kind>_<43 base64url chars>`.
//!
//! Design choice: tokens carry 256 random bits, so storing their SHA-256 is enough (no
//! salt or slow hash needed — there is nothing to brute-force) and lets a lookup be an
//! indexed equality match on the hash (its timing can reveal at most how much of a
//! guessed *hash* matched, which does not help find a token that produces it). The plain token exists only in the value returned
//! to whoever minted it. The `flk_<kind>_` prefix makes leaked tokens recognisable by
//! secret scanners and lets the authenticator reject a robot token offered as a session.

use std::fmt;

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use sha2::{Digest, Sha256};

/// Which kind of principal a token stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TokenKind {
    /// A robot's long-lived credential.
    Robot,
    /// Issued by a password login; ends at logout or expiry.
    Session,
    /// A user-level API token for tools and the demo's operator, minted by an admin.
    Operator,
}

impl TokenKind {
    pub fn as_str(self) -> &'static str {
        match self {
            TokenKind::Robot => "robot",
            TokenKind::Session => "session",
            TokenKind::Operator => "operator",
        }
    }

    pub fn parse(s: &str) -> Option<TokenKind> {
        match s {
            "robot" => Some(TokenKind::Robot),
            "session" => Some(TokenKind::Session),
            "operator" => Some(TokenKind::Operator),
            _ => None,
        }
    }
}

const RANDOM_BYTES: usize = 32;
const RANDOM_CHARS: usize = 43; // base64url of 32 bytes, unpadded

/// Why a string is not a fleetlink token.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TokenFormatError {
    #[error("not a fleetlink token (expected flk_<kind>_<secret>)")]
    NotAToken,
    #[error("unknown token kind {0:?}")]
    UnknownKind(String),
    #[error("malformed token secret: {0}")]
    BadSecret(&'static str),
}

/// A plain token. Its `Debug` hides the secret so it never ends up in a log by accident.
#[derive(Clone, PartialEq, Eq)]
pub struct Token {
    kind: TokenKind,
    text: String,
}

impl Token {
    /// A fresh random token from the operating system's CSPRNG.
    pub fn generate(kind: TokenKind) -> Result<Token, getrandom::Error> {
        let mut bytes = [0u8; RANDOM_BYTES];
        getrandom::fill(&mut bytes)?;
        let text = format!("flk_{}_{}", kind.as_str(), URL_SAFE_NO_PAD.encode(bytes));
        Ok(Token { kind, text })
    }

    /// Parses a presented token. Only the shape is checked; validity is the store's call.
    pub fn parse(text: &str) -> Result<Token, TokenFormatError> {
        let rest = text
            .strip_prefix("flk_")
            .ok_or(TokenFormatError::NotAToken)?;
        let (kind, secret) = rest.split_once('_').ok_or(TokenFormatError::NotAToken)?;
        let kind = TokenKind::parse(kind)
            .ok_or_else(|| TokenFormatError::UnknownKind(kind.chars().take(16).collect()))?;
        if secret.len() != RANDOM_CHARS {
            return Err(TokenFormatError::BadSecret("wrong length"));
        }
        if !secret
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_')
        {
            return Err(TokenFormatError::BadSecret("not base64url"));
        }
        Ok(Token {
            kind,
            text: text.to_owned(),
        })
    }

    pub fn kind(&self) -> TokenKind {
        self.kind
    }

    /// The full token text, to hand to its owner once.
    pub fn expose(&self) -> &str {
        &self.text
    }

    pub fn hash(&self) -> TokenHash {
        TokenHash(Sha256::digest(self.text.as_bytes()).into())
    }
}

impl fmt::Debug for Token {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Token(flk_{}_…)", self.kind.as_str())
    }
}

/// SHA-256 of a token's full text: what the database stores and looks up.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct TokenHash(pub [u8; 32]);

impl TokenHash {
    pub fn as_bytes(&self) -> &[u8] {
        &self.0
    }

    /// A short, non-secret label (first 8 hex digits) for listings and audit.
    pub fn label(&self) -> String {
        self.0[..4].iter().map(|b| format!("{b:02x}")).collect()
    }
}

impl fmt::Debug for TokenHash {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "TokenHash({}…)", self.label())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_tokens_parse_back_with_their_kind() {
        for kind in [TokenKind::Robot, TokenKind::Session, TokenKind::Operator] {
            let t = Token::generate(kind).unwrap();
            assert!(t.expose().starts_with(&format!("flk_{}_", kind.as_str())));
            let back = Token::parse(t.expose()).unwrap();
            assert_eq!(back.kind(), kind);
            assert_eq!(back.hash(), t.hash());
        }
    }

    #[test]
    fn malformed_tokens_are_rejected() {
        assert_eq!(Token::parse("hello"), Err(TokenFormatError::NotAToken));
        assert!(matches!(
            Token::parse("flk_admin_AAAA"),
            Err(TokenFormatError::UnknownKind(_))
        ));
        assert!(matches!(
            Token::parse("flk_robot_short"),
            Err(TokenFormatError::BadSecret(_))
        ));
        let bad = format!("flk_robot_{}", "!".repeat(43));
        assert!(matches!(
            Token::parse(&bad),
            Err(TokenFormatError::BadSecret(_))
        ));
    }

    #[test]
    fn debug_never_prints_the_secret() {
        let t = Token::generate(TokenKind::Robot).unwrap();
        let shown = format!("{t:?}");
        assert!(!shown.contains(&t.expose()[10..]));
    }
}
