//! Audit storage: batch inserts and filtered, paged queries (newest first).
//!
//! Paging uses a cursor (the last row id seen), not an offset, so pages stay stable while
//! new records arrive. Filters SQL can express run in SQL; a name regex runs in Rust on the
//! rows SQL returns, with a scan budget so a regex that matches nothing cannot make one
//! request read the whole table — the page then ends early with a cursor to continue.

use std::net::IpAddr;

use rusqlite::params;
use serde::Serialize;

use super::{AuditAction, AuditRecord};
use crate::UnixTime;
use crate::acl::NamePattern;
use crate::store::{Store, StoreError};

/// Rows examined per query at most when a regex filter is set.
const SCAN_BUDGET: usize = 100_000;
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

impl Store {
    pub(crate) fn insert_audit_batch(&self, batch: &[AuditRecord]) -> Result<(), StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            {
                let mut stmt = tx.prepare_cached(
                    "INSERT INTO audit_log (at, principal, client_ip, action, name, size, allowed, detail)
                     VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)",
                )?;
                for r in batch {
                    stmt.execute(params![
                        r.at.0,
                        r.principal,
                        r.client_ip.to_string(),
                        r.action.as_str(),
                        r.name,
                        r.size.map(|s| i64::try_from(s).unwrap_or(i64::MAX)),
                        r.allowed,
                        r.detail,
                    ])?;
                }
            }
            tx.commit()?;
            Ok(())
        })
    }

    /// Deletes records older than `before` (retention); returns how many.
    pub fn prune_audit(&self, before: UnixTime) -> Result<usize, StoreError> {
        self.with(|c| Ok(c.execute("DELETE FROM audit_log WHERE at < ?1", [before.0])?))
    }

    /// Audit records matching `q`, newest first.
    pub fn query_audit(&self, q: &AuditQuery) -> Result<AuditPage, StoreError> {
        let limit = match q.limit {
            0 => 100,
            n => n.min(MAX_PAGE),
        } as usize;
        self.with(|c| {
            let mut stmt = c.prepare(
                "SELECT id, at, principal, client_ip, action, name, size, allowed, detail
                 FROM audit_log
                 WHERE (?1 IS NULL OR id < ?1)
                   AND (?2 IS NULL OR principal = ?2)
                   AND (?3 IS NULL OR action = ?3)
                   AND (?4 IS NULL OR substr(name, 1, length(?4)) = ?4)
                   AND (?5 IS NULL OR allowed = ?5)
                   AND (?6 IS NULL OR at >= ?6)
                   AND (?7 IS NULL OR at < ?7)
                 ORDER BY id DESC",
            )?;
            let mut rows = stmt.query(params![
                q.after.map(|c| c.0),
                q.principal,
                q.action.map(AuditAction::as_str),
                q.name_prefix,
                q.allowed,
                q.since.map(|t| t.0),
                q.until.map(|t| t.0),
            ])?;
            let mut records = Vec::new();
            let mut scanned = 0usize;
            while let Some(row) = rows.next()? {
                let id: i64 = row.get(0)?;
                scanned += 1;
                let name: String = row.get(5)?;
                if q.name_regex.as_ref().is_none_or(|re| re.is_match(&name)) {
                    if records.len() == limit {
                        // One more match exists: the page is full and there is a next one.
                        let next = records.last().map(|r: &StoredAudit| AuditCursor(r.id));
                        return Ok(AuditPage { records, next });
                    }
                    records.push(read_row(id, name, row)?);
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
        })
    }
}

fn read_row(id: i64, name: String, row: &rusqlite::Row<'_>) -> Result<StoredAudit, StoreError> {
    let corrupt = |what: &'static str, reason: String| StoreError::Corrupt { what, reason };
    let ip: String = row.get(3)?;
    let action: String = row.get(4)?;
    Ok(StoredAudit {
        id,
        record: AuditRecord {
            at: UnixTime(row.get(1)?),
            principal: row.get(2)?,
            client_ip: ip
                .parse::<IpAddr>()
                .map_err(|e| corrupt("audit client address", e.to_string()))?,
            action: AuditAction::parse(&action)
                .ok_or_else(|| corrupt("audit action", format!("unknown action {action:?}")))?,
            name,
            size: row.get::<_, Option<i64>>(6)?.map(|s| s.max(0) as u64),
            allowed: row.get(7)?,
            detail: row.get(8)?,
        },
    })
}
