//! The SQLite backend of the security [`Store`]: the `auth_` and `audit_` tables in the
//! hub's own database file (or in memory), and every rule, credential and audit statement
//! the store runs there.
//!
//! Design choice: one connection behind a std `Mutex`, for every table; every use is one
//! short synchronous statement or transaction. Rule changes bump the
//! revision in their transaction, which is how other processes on the same file notice.

use std::path::Path;
use std::sync::{Arc, Mutex};

use fleetlink_postgres::Database;
use rusqlite::{Connection, OptionalExtension, Row, params};

use super::audit::{RawAudit, page, size_column};
use super::credentials::{RawToken, TOKEN_COLUMNS};
use super::{Engine, Store, StoreError, TokenId, init_schema};
use crate::UnixTime;
use crate::acl::RuleId;
use crate::audit::query::{AuditPage, AuditQuery};
use crate::audit::record::{AuditAction, AuditRecord};
use crate::identity::{RobotName, UserName};
use crate::token::{TokenHash, TokenKind};

const SCHEMA: &str = "
    CREATE TABLE IF NOT EXISTS auth_meta (
        key TEXT PRIMARY KEY,
        value INTEGER NOT NULL
    );
    INSERT OR IGNORE INTO auth_meta (key, value) VALUES ('rules_revision', 0);
    CREATE TABLE IF NOT EXISTS auth_rules (
        id INTEGER PRIMARY KEY AUTOINCREMENT,
        rule_json TEXT NOT NULL,
        created_at INTEGER NOT NULL
    );
    CREATE TABLE IF NOT EXISTS auth_tokens (
        id INTEGER PRIMARY KEY AUTOINCREMENT,
        hash BLOB NOT NULL UNIQUE,
        kind TEXT NOT NULL,
        subject TEXT NOT NULL,
        groups_json TEXT NOT NULL DEFAULT '[]',
        created_at INTEGER NOT NULL,
        expires_at INTEGER,
        revoked_at INTEGER,
        last_used_at INTEGER
    );
    CREATE INDEX IF NOT EXISTS auth_tokens_subject ON auth_tokens (kind, subject);
    CREATE TABLE IF NOT EXISTS auth_users (
        name TEXT PRIMARY KEY,
        password_hash TEXT NOT NULL,
        groups_json TEXT NOT NULL DEFAULT '[]',
        created_at INTEGER NOT NULL
    );
    CREATE TABLE IF NOT EXISTS audit_log (
        id INTEGER PRIMARY KEY AUTOINCREMENT,
        at INTEGER NOT NULL,
        principal TEXT NOT NULL,
        client_ip TEXT NOT NULL,
        action TEXT NOT NULL,
        name TEXT NOT NULL,
        size INTEGER,
        allowed INTEGER NOT NULL,
        detail TEXT
    );
    CREATE INDEX IF NOT EXISTS audit_log_at ON audit_log (at);
    CREATE INDEX IF NOT EXISTS audit_log_principal ON audit_log (principal, id);
";

impl Store {
    /// Opens (creating if needed) the tables in the database file at `path`.
    pub fn open(path: &Path) -> Result<Store, StoreError> {
        let open_err = |source| StoreError::Open {
            path: path.to_owned(),
            source,
        };
        let conn = Connection::open(path).map_err(open_err)?;
        init_schema(&conn, SCHEMA).map_err(open_err)?;
        Ok(Store::from_conn(conn))
    }

    /// A private in-memory database, for tests and `fleetlink demo`.
    pub fn open_in_memory() -> Result<Store, StoreError> {
        let conn = Connection::open_in_memory()?;
        init_schema(&conn, SCHEMA)?;
        Ok(Store::from_conn(conn))
    }

    fn from_conn(conn: Connection) -> Store {
        Store {
            engine: Arc::new(Sqlite {
                conn: Mutex::new(conn),
            }),
        }
    }
}

struct Sqlite {
    // std Mutex: every use is one short synchronous statement or transaction, never held
    // across an await; contention is low (logins, admin edits, audit batches).
    conn: Mutex<Connection>,
}

/// Runs `f` on the SQLite connection.
fn with<T>(
    conn: &Mutex<Connection>,
    f: impl FnOnce(&mut Connection) -> Result<T, StoreError>,
) -> Result<T, StoreError> {
    let mut conn = conn.lock().unwrap_or_else(|p| p.into_inner());
    f(&mut conn)
}

fn bump_revision(tx: &rusqlite::Transaction<'_>) -> rusqlite::Result<()> {
    tx.execute(
        "UPDATE auth_meta SET value = value + 1 WHERE key = 'rules_revision'",
        [],
    )?;
    Ok(())
}

fn raw_token(r: &Row<'_>) -> rusqlite::Result<RawToken> {
    Ok((
        r.get(0)?,
        r.get(1)?,
        r.get(2)?,
        r.get(3)?,
        r.get(4)?,
        r.get(5)?,
        r.get(6)?,
        r.get(7)?,
    ))
}

impl Engine for Sqlite {
    fn database(&self) -> Option<&Database> {
        None
    }

    fn list_rules(&self) -> Result<Vec<(i64, String)>, StoreError> {
        with(&self.conn, |c| {
            let mut stmt = c.prepare("SELECT id, rule_json FROM auth_rules ORDER BY id")?;
            let rows = stmt.query_map([], |r| Ok((r.get(0)?, r.get(1)?)))?;
            Ok(rows.collect::<rusqlite::Result<_>>()?)
        })
    }

    fn add_rule(&self, json: &str, now: UnixTime) -> Result<i64, StoreError> {
        with(&self.conn, |c| {
            let tx = c.transaction()?;
            tx.execute(
                "INSERT INTO auth_rules (rule_json, created_at) VALUES (?1, ?2)",
                params![json, now.0],
            )?;
            let id = tx.last_insert_rowid();
            bump_revision(&tx)?;
            tx.commit()?;
            Ok(id)
        })
    }

    fn remove_rule(&self, id: RuleId) -> Result<bool, StoreError> {
        with(&self.conn, |c| {
            let tx = c.transaction()?;
            let n = tx.execute("DELETE FROM auth_rules WHERE id = ?1", [id.0])?;
            if n > 0 {
                bump_revision(&tx)?;
            }
            tx.commit()?;
            Ok(n > 0)
        })
    }

    fn replace_rules(&self, jsons: &[String], now: UnixTime) -> Result<Vec<i64>, StoreError> {
        with(&self.conn, |c| {
            let tx = c.transaction()?;
            tx.execute("DELETE FROM auth_rules", [])?;
            let mut ids = Vec::with_capacity(jsons.len());
            for json in jsons {
                tx.execute(
                    "INSERT INTO auth_rules (rule_json, created_at) VALUES (?1, ?2)",
                    params![json, now.0],
                )?;
                ids.push(tx.last_insert_rowid());
            }
            bump_revision(&tx)?;
            tx.commit()?;
            Ok(ids)
        })
    }

    fn rules_revision(&self) -> Result<Option<i64>, StoreError> {
        const SQL: &str = "SELECT value FROM auth_meta WHERE key = 'rules_revision'";
        with(&self.conn, |c| {
            Ok(c.query_row(SQL, [], |r| r.get(0)).optional()?)
        })
    }

    fn insert_token(
        &self,
        hash: &TokenHash,
        kind: TokenKind,
        subject: &str,
        groups: &str,
        expires_at: Option<i64>,
        now: UnixTime,
    ) -> Result<(), StoreError> {
        with(&self.conn, |c| {
            c.execute(
                "INSERT INTO auth_tokens (hash, kind, subject, groups_json, created_at, expires_at)
                     VALUES (?1, ?2, ?3, ?4, ?5, ?6)",
                params![
                    hash.as_bytes(),
                    kind.as_str(),
                    subject,
                    groups,
                    now.0,
                    expires_at
                ],
            )?;
            Ok(())
        })
    }

    fn lookup_token(&self, hash: &TokenHash) -> Result<Option<RawToken>, StoreError> {
        with(&self.conn, |c| {
            Ok(c.query_row(
                &format!("SELECT {TOKEN_COLUMNS} FROM auth_tokens WHERE hash = ?1"),
                [hash.as_bytes()],
                raw_token,
            )
            .optional()?)
        })
    }

    fn touch_token(&self, id: TokenId, now: UnixTime) -> Result<(), StoreError> {
        with(&self.conn, |c| {
            c.execute(
                "UPDATE auth_tokens SET last_used_at = ?2 WHERE id = ?1",
                params![id.0, now.0],
            )?;
            Ok(())
        })
    }

    fn revoke_token(&self, id: TokenId, now: UnixTime) -> Result<u64, StoreError> {
        with(&self.conn, |c| {
            Ok(c.execute(
                "UPDATE auth_tokens SET revoked_at = ?2 WHERE id = ?1 AND revoked_at IS NULL",
                params![id.0, now.0],
            )? as u64)
        })
    }

    fn revoke_token_by_hash(&self, hash: &TokenHash, now: UnixTime) -> Result<u64, StoreError> {
        with(&self.conn, |c| {
            Ok(c.execute(
                "UPDATE auth_tokens SET revoked_at = ?2 WHERE hash = ?1 AND revoked_at IS NULL",
                params![hash.as_bytes(), now.0],
            )? as u64)
        })
    }

    fn revoke_robot_tokens(&self, robot: &RobotName, now: UnixTime) -> Result<usize, StoreError> {
        with(&self.conn, |c| {
            Ok(c.execute(
                "UPDATE auth_tokens SET revoked_at = ?2
                     WHERE kind = 'robot' AND subject = ?1 AND revoked_at IS NULL",
                params![robot.as_str(), now.0],
            )?)
        })
    }

    fn list_tokens(&self, kind: Option<&str>) -> Result<Vec<RawToken>, StoreError> {
        with(&self.conn, |c| {
            let mut stmt = c.prepare(&format!(
                "SELECT {TOKEN_COLUMNS} FROM auth_tokens
                     WHERE ?1 IS NULL OR kind = ?1 ORDER BY id DESC"
            ))?;
            let rows = stmt.query_map([kind], raw_token)?;
            Ok(rows.collect::<rusqlite::Result<Vec<_>>>()?)
        })
    }

    fn add_user(
        &self,
        name: &UserName,
        hash: &str,
        groups: &str,
        now: UnixTime,
    ) -> Result<u64, StoreError> {
        with(&self.conn, |c| {
            Ok(c.execute(
                "INSERT OR IGNORE INTO auth_users (name, password_hash, groups_json, created_at)
                     VALUES (?1, ?2, ?3, ?4)",
                params![name.as_str(), hash, groups, now.0],
            )? as u64)
        })
    }

    fn set_password(&self, name: &UserName, hash: &str) -> Result<u64, StoreError> {
        with(&self.conn, |c| {
            Ok(c.execute(
                "UPDATE auth_users SET password_hash = ?2 WHERE name = ?1",
                params![name.as_str(), hash],
            )? as u64)
        })
    }

    fn remove_user(&self, name: &UserName, now: UnixTime) -> Result<bool, StoreError> {
        with(&self.conn, |c| {
            let tx = c.transaction()?;
            let n = tx.execute("DELETE FROM auth_users WHERE name = ?1", [name.as_str()])?;
            tx.execute(
                "UPDATE auth_tokens SET revoked_at = ?2
                     WHERE kind = 'session' AND subject = ?1 AND revoked_at IS NULL",
                params![name.as_str(), now.0],
            )?;
            tx.commit()?;
            Ok(n > 0)
        })
    }

    fn user(&self, name: &UserName) -> Result<Option<(String, String)>, StoreError> {
        with(&self.conn, |c| {
            Ok(c.query_row(
                "SELECT password_hash, groups_json FROM auth_users WHERE name = ?1",
                [name.as_str()],
                |r| Ok((r.get(0)?, r.get(1)?)),
            )
            .optional()?)
        })
    }

    fn list_users(&self) -> Result<Vec<(String, String, i64)>, StoreError> {
        const SQL: &str = "SELECT name, groups_json, created_at FROM auth_users ORDER BY name";
        with(&self.conn, |c| {
            let mut stmt = c.prepare(SQL)?;
            let rows = stmt.query_map([], |r| Ok((r.get(0)?, r.get(1)?, r.get(2)?)))?;
            Ok(rows.collect::<rusqlite::Result<Vec<_>>>()?)
        })
    }

    fn insert_audit_batch(&self, batch: &[AuditRecord]) -> Result<(), StoreError> {
        with(&self.conn, |c| {
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
        })
    }

    fn prune_audit(&self, before: UnixTime) -> Result<usize, StoreError> {
        with(&self.conn, |c| {
            Ok(c.execute("DELETE FROM audit_log WHERE at < ?1", [before.0])?)
        })
    }

    fn query_audit(&self, q: &AuditQuery, limit: usize) -> Result<AuditPage, StoreError> {
        with(&self.conn, |c| {
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
        })
    }

    #[cfg(test)]
    fn lock_for_test(&self) -> std::sync::MutexGuard<'_, Connection> {
        self.conn.lock().unwrap_or_else(|p| p.into_inner())
    }
}
