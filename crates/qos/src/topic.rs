//! The caller-chosen identifier of a topic on one link ([`TopicId`]). It has a file of
//! its own because both the scheduler and the errors that name a topic use it.

/// Caller-chosen identifier of a topic on one link.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TopicId(pub u32);
