//! Audit storage: batch inserts and filtered, paged queries (newest first).
//!
//! Paging uses a cursor (the last row id seen), not an offset, so pages stay stable while
//! new records arrive. Filters SQL can express run in SQL; a name regex runs in Rust on the
//! rows SQL returns, with a scan budget so a regex that matches nothing cannot make one
//! request read the whole table — the page then ends early with a cursor to continue.
//! SQLite hands rows over one at a time, so the budget bounds the scan; PostgreSQL sends
//! a query's rows at once, so there the query itself is limited to the rows the page can
//! use (the budget with a regex, one more than the page without).

use std::net::IpAddr;

use fleetlink_postgres::PgError;
use rusqlite::params;
use serde::Serialize;

use super::{AuditAction, AuditRecord};
use crate::UnixTime;
use crate::acl::NamePattern;
use crate::store::{Backend, Store, StoreError, with};

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
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
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
                            r.size.map(size_column),
                            r.allowed,
                            r.detail,
                        ])?;
                    }
                }
                tx.commit()?;
                Ok(())
            }),
            Backend::Postgres(db) => {
                // One statement for the whole batch (columns as arrays), so a batch costs
                // one round trip to the server however many records it holds.
                let at: Vec<i64> = batch.iter().map(|r| r.at.0).collect();
                let principal: Vec<&str> = batch.iter().map(|r| r.principal.as_str()).collect();
                let ip: Vec<String> = batch.iter().map(|r| r.client_ip.to_string()).collect();
                let action: Vec<&str> = batch.iter().map(|r| r.action.as_str()).collect();
                let name: Vec<&str> = batch.iter().map(|r| r.name.as_str()).collect();
                let size: Vec<Option<i64>> =
                    batch.iter().map(|r| r.size.map(size_column)).collect();
                let allowed: Vec<bool> = batch.iter().map(|r| r.allowed).collect();
                let detail: Vec<Option<&str>> = batch.iter().map(|r| r.detail.as_deref()).collect();
                db.execute(
                    "INSERT INTO audit_log (at, principal, client_ip, action, name, size, allowed, detail)
                     SELECT * FROM UNNEST($1::BIGINT[], $2::TEXT[], $3::TEXT[], $4::TEXT[],
                                          $5::TEXT[], $6::BIGINT[], $7::BOOLEAN[], $8::TEXT[])",
                    &[&at, &principal, &ip, &action, &name, &size, &allowed, &detail],
                )?;
                Ok(())
            }
        }
    }

    /// Deletes records older than `before` (retention); returns how many.
    pub fn prune_audit(&self, before: UnixTime) -> Result<usize, StoreError> {
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.execute("DELETE FROM audit_log WHERE at < ?1", [before.0])?)
            }),
            Backend::Postgres(db) => {
                Ok(db.execute("DELETE FROM audit_log WHERE at < $1", &[&before.0])? as usize)
            }
        }
    }

    /// Audit records matching `q`, newest first.
    pub fn query_audit(&self, q: &AuditQuery) -> Result<AuditPage, StoreError> {
        let limit = match q.limit {
            0 => 100,
            n => n.min(MAX_PAGE),
        } as usize;
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
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
                let rows = stmt.query_map(
                    params![
                        q.after.map(|c| c.0),
                        q.principal,
                        q.action.map(AuditAction::as_str),
                        q.name_prefix,
                        q.allowed,
                        q.since.map(|t| t.0),
                        q.until.map(|t| t.0),
                    ],
                    |r| {
                        Ok(RawAudit {
                            id: r.get(0)?,
                            at: r.get(1)?,
                            principal: r.get(2)?,
                            client_ip: r.get(3)?,
                            action: r.get(4)?,
                            name: r.get(5)?,
                            size: r.get(6)?,
                            allowed: r.get(7)?,
                            detail: r.get(8)?,
                        })
                    },
                )?;
                page(rows.map(|r| r.map_err(StoreError::from)), q, limit)
            }),
            Backend::Postgres(db) => {
                let fetch = if q.name_regex.is_some() {
                    SCAN_BUDGET
                } else {
                    limit + 1
                } as i64;
                let rows = db.query(
                    "SELECT id, at, principal, client_ip, action, name, size, allowed, detail
                     FROM audit_log
                     WHERE ($1::BIGINT IS NULL OR id < $1)
                       AND ($2::TEXT IS NULL OR principal = $2)
                       AND ($3::TEXT IS NULL OR action = $3)
                       AND ($4::TEXT IS NULL OR starts_with(name, $4))
                       AND ($5::BOOLEAN IS NULL OR allowed = $5)
                       AND ($6::BIGINT IS NULL OR at >= $6)
                       AND ($7::BIGINT IS NULL OR at < $7)
                     ORDER BY id DESC
                     LIMIT $8",
                    &[
                        &q.after.map(|c| c.0),
                        &q.principal,
                        &q.action.map(AuditAction::as_str),
                        &q.name_prefix,
                        &q.allowed,
                        &q.since.map(|t| t.0),
                        &q.until.map(|t| t.0),
                        &fetch,
                    ],
                )?;
                let rows = rows.iter().map(|r| {
                    Ok::<_, PgError>(RawAudit {
                        id: r.try_get(0)?,
                        at: r.try_get(1)?,
                        principal: r.try_get(2)?,
                        client_ip: r.try_get(3)?,
                        action: r.try_get(4)?,
                        name: r.try_get(5)?,
                        size: r.try_get(6)?,
                        allowed: r.try_get(7)?,
                        detail: r.try_get(8)?,
                    })
                    .map_err(StoreError::from)
                });
                page(rows, q, limit)
            }
        }
    }
}

fn size_column(size: u64) -> i64 {
    i64::try_from(size).unwrap_or(i64::MAX)
}

/// One `audit_log` row as either backend returns it.
struct RawAudit {
    id: i64,
    at: i64,
    principal: String,
    client_ip: String,
    action: String,
    name: String,
    size: Option<i64>,
    allowed: bool,
    detail: Option<String>,
}

/// The page `rows` (newest first, SQL filters applied) make under `q`'s regex, `limit`
/// and the scan budget.
fn page(
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
