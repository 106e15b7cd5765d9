//! The audit log in the store: the public audit methods of [`Store`], and what both
//! engines share to serve them (the row as read, the page a scan of rows makes).
//!
//! Filters SQL can express run in SQL, in each engine's dialect (`sqlite.rs`,
//! `postgres.rs`); a name regex runs in Rust on the rows SQL returns, with a scan budget
//! so a regex that matches nothing cannot make one request read the whole table — the
//! page then ends early with a cursor to continue. SQLite hands rows over one at a time,
//! so the budget bounds the scan; PostgreSQL sends a query's rows at once, so there the
//! query itself is limited to the rows the page can use (the budget with a regex, one
//! more than the page without).

use std::net::IpAddr;

use super::{Store, StoreError};
use crate::UnixTime;
use crate::audit::query::{AuditCursor, AuditPage, AuditQuery, MAX_PAGE, StoredAudit};
use crate::audit::record::{AuditAction, AuditRecord};

/// Rows examined per query at most when a regex filter is set.
pub(super) const SCAN_BUDGET: usize = 100_000;

impl Store {
    /// Writes a batch of records: one transaction on SQLite, one statement on PostgreSQL.
    /// Blocks; the audit log's writer thread calls it.
    pub(crate) fn insert_audit_batch(&self, batch: &[AuditRecord]) -> Result<(), StoreError> {
        self.engine.insert_audit_batch(batch)
    }

    /// Deletes records older than `before` (retention); returns how many.
    pub fn prune_audit(&self, before: UnixTime) -> Result<usize, StoreError> {
        self.engine.prune_audit(before)
    }

    /// Audit records matching `q`, newest first.
    pub fn query_audit(&self, q: &AuditQuery) -> Result<AuditPage, StoreError> {
        let limit = match q.limit {
            0 => 100,
            n => n.min(MAX_PAGE),
        } as usize;
        self.engine.query_audit(q, limit)
    }
}

/// The `size` column of a payload size (sizes past `i64::MAX` saturate).
pub(super) fn size_column(size: u64) -> i64 {
    i64::try_from(size).unwrap_or(i64::MAX)
}

/// One `audit_log` row as either backend returns it.
pub(super) struct RawAudit {
    pub(super) id: i64,
    pub(super) at: i64,
    pub(super) principal: String,
    pub(super) client_ip: String,
    pub(super) action: String,
    pub(super) name: String,
    pub(super) size: Option<i64>,
    pub(super) allowed: bool,
    pub(super) detail: Option<String>,
}

/// The page `rows` (newest first, SQL filters applied) make under `q`'s regex, `limit`
/// and the scan budget.
pub(super) fn page(
    rows: impl Iterator<Item = Result<RawAudit, StoreError>>,
    q: &AuditQuery,
    limit: usize,
) -> Result<AuditPage, StoreError> {
    let mut records = Vec::new();
    let mut scanned = 0usize;
    for row in rows {
        let row = row?;
        let id = row.id;
        scanned += 1;
        if q.name_regex
            .as_ref()
            .is_none_or(|re| re.is_match(&row.name))
        {
            if records.len() == limit {
                // One more match exists: the page is full and there is a next one.
                let next = records.last().map(|r: &StoredAudit| AuditCursor(r.id));
                return Ok(AuditPage { records, next });
            }
            records.push(read_row(row)?);
        }
        if scanned >= SCAN_BUDGET {
            return Ok(AuditPage {
                records,
                next: Some(AuditCursor(id)),
            });
        }
    }
    Ok(AuditPage {
        records,
        next: None,
    })
}

fn read_row(row: RawAudit) -> Result<StoredAudit, StoreError> {
    let corrupt = |what: &'static str, reason: String| StoreError::Corrupt { what, reason };
    Ok(StoredAudit {
        id: row.id,
        record: AuditRecord {
            at: UnixTime(row.at),
            principal: row.principal,
            client_ip: row
                .client_ip
                .parse::<IpAddr>()
                .map_err(|e| corrupt("audit client address", e.to_string()))?,
            action: AuditAction::parse(&row.action).ok_or_else(|| {
                corrupt("audit action", format!("unknown action {:?}", row.action))
            })?,
            name: row.name,
            size: row.size.map(|s| s.max(0) as u64),
            allowed: row.allowed,
            detail: row.detail,
        },
    })
}
