//! Errors of the crate, one enum per concern.
//!
//! Design choice: definition problems ([`ParseError`], [`RegistryError`]) are separate
//! from message problems ([`CodecError`]) because callers react differently: a bad
//! definition is a configuration or peer bug reported once, a bad message is counted and
//! dropped. Codec errors keep *incomplete* (more bytes would have helped) apart from
//! *invalid* (no amount of bytes would), as the style guide asks of every decoder.

use std::path::PathBuf;

/// A `.msg`/`.srv`/`.action` text could not be parsed. Names the source, line and column.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{source_name}:{line}:{column}: {message}")]
pub struct ParseError {
    /// Type name or file the text came from.
    pub source_name: String,
    /// 1-based line number.
    pub line: usize,
    /// 1-based column number (in characters).
    pub column: usize,
    /// What is wrong.
    pub message: String,
}

/// A definition could not be registered or resolved.
#[derive(Debug, thiserror::Error)]
pub enum RegistryError {
    #[error(transparent)]
    Parse(#[from] ParseError),
    #[error("invalid type name {name:?}: {reason}")]
    BadName { name: String, reason: &'static str },
    #[error(
        "unknown type {name}: not bundled, not in a --msg-path package, not received at run time"
    )]
    NotFound { name: String },
    #[error("unknown type {name} (referenced from {from})")]
    UnknownType { name: String, from: String },
    #[error("recursive definition: {chain}")]
    Recursive { chain: String },
    #[error("invalid default value for {type_name}.{field}: {reason}")]
    BadDefault {
        type_name: String,
        field: String,
        reason: String,
    },
    #[error("reading {path}: {cause}")]
    Io {
        path: PathBuf,
        cause: std::io::Error,
    },
    #[error("{0} is a service or action, not a message; name one of its parts")]
    NotAMessage(String),
}

/// A message could not be decoded or encoded.
#[derive(Debug, thiserror::Error)]
pub enum CodecError {
    /// The input ended early: more bytes would have been needed.
    #[error("truncated input at {path}: need {needed} bytes at offset {offset}, have {available}")]
    Incomplete {
        path: String,
        offset: usize,
        needed: usize,
        available: usize,
    },
    /// The input can never be valid for this type.
    #[error("invalid input at {path} (offset {offset}): {reason}")]
    Invalid {
        path: String,
        offset: usize,
        reason: String,
    },
    /// A value (JSON, CBOR or [`crate::Value`]) does not fit the type.
    #[error("value does not fit {path}: {reason}")]
    Mismatch { path: String, reason: String },
    #[error(transparent)]
    Registry(#[from] RegistryError),
    #[error("invalid JSON text at byte {offset}: {reason}")]
    JsonSyntax { offset: usize, reason: String },
    #[error("invalid CBOR: {0}")]
    Cbor(String),
}

impl CodecError {
    /// True when the input was cut short (a longer buffer might decode).
    pub fn is_incomplete(&self) -> bool {
        matches!(self, CodecError::Incomplete { .. })
    }
}
