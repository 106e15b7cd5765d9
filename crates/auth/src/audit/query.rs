//! What one asks of the audit log and gets back: the filters ([`AuditQuery`]), and a page
//! of records, newest first ([`AuditPage`]).
//!
//! Paging uses a cursor (the last row id seen), not an offset, so pages stay stable while
//! new records arrive. The store runs the query (`crate::store`, where each backend holds
//! its SQL and a scan budget bounds a name regex's work).

use serde::Serialize;

use super::record::{AuditAction, AuditRecord};
use crate::UnixTime;
use crate::acl::NamePattern;

/// Largest page.
pub const MAX_PAGE: u32 = 1000;

/// Continue after this record (exclusive), going back in time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(transparent)]
pub struct AuditCursor(pub i64);

/// Filters; all optional and combined with AND.
#[derive(Debug, Clone, Default)]
pub struct AuditQuery {
    /// Exact principal, e.g. `user:alice`.
    pub principal: Option<String>,
    pub action: Option<AuditAction>,
    pub name_prefix: Option<String>,
    /// Whole-name regex, same limits as ACL patterns.
    pub name_regex: Option<NamePattern>,
    pub allowed: Option<bool>,
    /// Inclusive lower bound.
    pub since: Option<UnixTime>,
    /// Exclusive upper bound.
    pub until: Option<UnixTime>,
    /// Page size (capped at [`MAX_PAGE`]; 0 means 100).
    pub limit: u32,
    pub after: Option<AuditCursor>,
}

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct StoredAudit {
    pub id: i64,
    #[serde(flatten)]
    pub record: AuditRecord,
}

/// One page of results; `next` is set when there may be more.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct AuditPage {
    pub records: Vec<StoredAudit>,
    pub next: Option<AuditCursor>,
}
