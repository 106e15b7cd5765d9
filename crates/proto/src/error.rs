//! Decode errors. A caller reading from a stream needs to know whether to wait for more
//! bytes ([`ErrorKind::Incomplete`]) or to reject the input ([`ErrorKind::Invalid`]).

use std::fmt;

/// Whether the input was cut short or is wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// The buffer ends before the value does; more bytes could complete it.
    Incomplete,
    /// The bytes can never form a valid value.
    Invalid,
}

/// A decode failure with the field it happened in and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub struct DecodeError {
    pub kind: ErrorKind,
    /// What was being read, e.g. `"ADVERTISE.topic"`.
    pub context: &'static str,
    pub reason: String,
}

impl DecodeError {
    pub fn incomplete(context: &'static str, needed: usize, have: usize) -> Self {
        DecodeError {
            kind: ErrorKind::Incomplete,
            context,
            reason: format!("need {needed} more bytes, have {have}"),
        }
    }

    pub fn invalid(context: &'static str, reason: impl Into<String>) -> Self {
        DecodeError {
            kind: ErrorKind::Invalid,
            context,
            reason: reason.into(),
        }
    }

    pub fn is_incomplete(&self) -> bool {
        self.kind == ErrorKind::Incomplete
    }
}

impl fmt::Display for DecodeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self.kind {
            ErrorKind::Incomplete => "truncated",
            ErrorKind::Invalid => "invalid",
        };
        write!(f, "{kind} {}: {}", self.context, self.reason)
    }
}
