//! Errors of the QoS crate: configuration that cannot be used.
//!
//! Design choice: the message path never fails (a full queue is an outcome, not an error),
//! so the only errors are made at configuration time, and each names the field at fault.

use crate::topic::TopicId;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum QosError {
    #[error("invalid QoS field `{field}`: {reason}")]
    InvalidField { field: &'static str, reason: String },
    #[error("topic {0:?} is already registered with the scheduler")]
    DuplicateTopic(TopicId),
    #[error("topic {0:?} is not registered with the scheduler")]
    UnknownTopic(TopicId),
    /// A registered topic's `no_drop` cannot change: its messages are in the no-drop
    /// FIFO (or not), under the reliable layer's sequence numbers (or not).
    #[error("`no_drop` of a topic that is already flowing cannot change")]
    NoDropChange(TopicId),
    #[error("invalid {what}: {reason}")]
    InvalidParameter { what: &'static str, reason: String },
}

impl QosError {
    pub(crate) fn invalid(field: &'static str, reason: String) -> Self {
        QosError::InvalidField { field, reason }
    }

    /// The configuration field at fault, for `InvalidField`.
    pub fn field(&self) -> Option<&'static str> {
        match self {
            QosError::InvalidField { field, .. } => Some(field),
            _ => None,
        }
    }
}
