//! Durable security state: rules, credentials, sessions and the audit log, in SQLite (one
//! hub) or PostgreSQL (several hubs sharing it).
//!
//! Design choice: one [`Store`] API over two backends, chosen once, when the store is
//! opened. Each backend is an `Engine` in its own file that holds all of its SQL
//! dialect. With SQLite (`sqlite.rs`, [`Store::open`]) the tables live in the hub's own
//! database file (all prefixed `auth_` or `audit_`, created with `IF NOT EXISTS`), behind
//! one connection in a std `Mutex`. With PostgreSQL (`postgres.rs`, [`Store::postgres`])
//! they live in the shared database ([`fleetlink_postgres`]: a pool, versioned
//! migrations, change notifications). Either way every statement is short and
//! synchronous; callers on an async runtime run store calls on the blocking pool. The
//! public methods (`rules.rs`, `credentials.rs`, `audit.rs`) turn values into columns and
//! rows back into values, and leave the statements to the engine.
//!
//! Rule edits bump a revision counter in the same transaction, so a hub notices edits made
//! by another process (`fleetlink admin`, another hub) by polling
//! [`Store::rules_revision`]; on PostgreSQL the same transaction also notifies every hub
//! ([`fleetlink_postgres::changes`]), which reloads at once.

mod audit;
mod credentials;
mod postgres;
mod rules;
mod sqlite;

use std::path::PathBuf;
use std::sync::Arc;

use fleetlink_postgres::Database;
use rusqlite::Connection;

use crate::UnixTime;
use crate::acl::RuleId;
use crate::audit::query::{AuditPage, AuditQuery};
use crate::audit::record::AuditRecord;
use crate::identity::{RobotName, UserName};
use crate::token::{TokenHash, TokenKind};
use credentials::RawToken;

pub use credentials::{TokenId, TokenInfo, TokenRecord, UserInfo, UserRecord};

/// A storage failure, with its cause.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("cannot open database {path}: {source}")]
    Open {
        path: PathBuf,
        source: rusqlite::Error,
    },
    #[error("database error: {0}")]
    Sql(#[from] rusqlite::Error),
    #[error(transparent)]
    Postgres(#[from] fleetlink_postgres::DbError),
    #[error("stored {what} is unreadable: {reason}")]
    Corrupt { what: &'static str, reason: String },
    #[error("cannot generate a token: {0}")]
    Random(#[from] getrandom::Error),
    #[error("cannot hash password: {0}")]
    PasswordHash(String),
    #[error("user {0} already exists")]
    UserExists(String),
    #[error("no such user {0}")]
    NoSuchUser(String),
}

impl StoreError {
    /// Whether the database could not be reached at all (a shared PostgreSQL that is down
    /// or restarting), as opposed to a statement failing.
    pub fn is_unavailable(&self) -> bool {
        matches!(self, StoreError::Postgres(e) if e.is_unavailable())
    }
}

impl From<fleetlink_postgres::PgError> for StoreError {
    fn from(e: fleetlink_postgres::PgError) -> StoreError {
        StoreError::Postgres(e.into())
    }
}

/// How long a statement waits for another process's lock on the database.
pub const BUSY_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(10);

/// Prepares a database file the hub and `fleetlink admin` share: WAL mode, then `schema`
/// in one write transaction, waiting up to [`BUSY_TIMEOUT`] for the other process's
/// locks. SQLite answers "database is locked" at once, without waiting, when two
/// connections create the same new file together (the journal-mode switch, or a read
/// that must become a write); those attempts are repeated.
pub fn init_schema(conn: &Connection, schema: &str) -> rusqlite::Result<()> {
    use rusqlite::ErrorCode::{DatabaseBusy, DatabaseLocked};
    conn.busy_timeout(BUSY_TIMEOUT)?;
    let deadline = std::time::Instant::now() + BUSY_TIMEOUT;
    loop {
        let attempt = conn
            .query_row("PRAGMA journal_mode = WAL", [], |_| Ok(()))
            .and_then(|()| conn.execute_batch("PRAGMA synchronous = NORMAL;"))
            .and_then(|()| conn.execute_batch(&format!("BEGIN IMMEDIATE; {schema}; COMMIT;")));
        match attempt {
            Err(rusqlite::Error::SqliteFailure(e, _))
                if matches!(e.code, DatabaseBusy | DatabaseLocked)
                    && std::time::Instant::now() < deadline =>
            {
                if !conn.is_autocommit() {
                    let _ = conn.execute_batch("ROLLBACK;");
                }
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
            other => return other,
        }
    }
}

/// Handle to the security tables. Cheap to clone.
#[derive(Clone)]
pub struct Store {
    engine: Arc<dyn Engine>,
}

/// One backend's statements for the rule, credential and audit methods of [`Store`], in
/// that backend's SQL dialect. Rows come back as plain columns; the callers parse them,
/// so both engines read the same.
trait Engine: Send + Sync {
    /// The shared database, for the PostgreSQL engine.
    fn database(&self) -> Option<&Database>;

    /// Every rule row (id, JSON), oldest first.
    fn list_rules(&self) -> Result<Vec<(i64, String)>, StoreError>;
    /// Inserts one rule and bumps the revision; returns its id.
    fn add_rule(&self, json: &str, now: UnixTime) -> Result<i64, StoreError>;
    /// Deletes one rule (bumping the revision if it existed); whether it existed.
    fn remove_rule(&self, id: RuleId) -> Result<bool, StoreError>;
    /// Replaces every rule and bumps the revision; returns the new ids in order.
    fn replace_rules(&self, jsons: &[String], now: UnixTime) -> Result<Vec<i64>, StoreError>;
    fn rules_revision(&self) -> Result<Option<i64>, StoreError>;

    fn insert_token(
        &self,
        hash: &TokenHash,
        kind: TokenKind,
        subject: &str,
        groups: &str,
        expires_at: Option<i64>,
        now: UnixTime,
    ) -> Result<(), StoreError>;
    fn lookup_token(&self, hash: &TokenHash) -> Result<Option<RawToken>, StoreError>;
    fn touch_token(&self, id: TokenId, now: UnixTime) -> Result<(), StoreError>;
    /// The revoking methods return how many tokens they revoked.
    fn revoke_token(&self, id: TokenId, now: UnixTime) -> Result<u64, StoreError>;
    fn revoke_token_by_hash(&self, hash: &TokenHash, now: UnixTime) -> Result<u64, StoreError>;
    fn revoke_robot_tokens(&self, robot: &RobotName, now: UnixTime) -> Result<usize, StoreError>;
    /// Tokens of one kind (`None`: all), newest first.
    fn list_tokens(&self, kind: Option<&str>) -> Result<Vec<RawToken>, StoreError>;

    /// Inserts a user unless one has the name; how many rows it inserted.
    fn add_user(
        &self,
        name: &UserName,
        hash: &str,
        groups: &str,
        now: UnixTime,
    ) -> Result<u64, StoreError>;
    /// How many users it updated.
    fn set_password(&self, name: &UserName, hash: &str) -> Result<u64, StoreError>;
    fn remove_user(&self, name: &UserName, now: UnixTime) -> Result<bool, StoreError>;
    /// The user's (password hash, groups JSON).
    fn user(&self, name: &UserName) -> Result<Option<(String, String)>, StoreError>;
    /// Every user's (name, groups JSON, created at), by name.
    fn list_users(&self) -> Result<Vec<(String, String, i64)>, StoreError>;

    /// Writes a batch of audit records in one go.
    fn insert_audit_batch(&self, batch: &[AuditRecord]) -> Result<(), StoreError>;
    /// Deletes audit records older than `before`; how many.
    fn prune_audit(&self, before: UnixTime) -> Result<usize, StoreError>;
    /// The page of at most `limit` audit records matching `q`, newest first, made by
    /// `audit::page` from the rows the filters SQL can express select.
    fn query_audit(&self, q: &AuditQuery, limit: usize) -> Result<AuditPage, StoreError>;

    /// Holds the SQLite connection, stalling every writer.
    #[cfg(test)]
    fn lock_for_test(&self) -> std::sync::MutexGuard<'_, Connection>;
}

impl Store {
    /// The shared database, when the store is in PostgreSQL.
    pub fn database(&self) -> Option<&Database> {
        self.engine.database()
    }

    /// Holds the connection, stalling every writer: lets tests fill the audit channel.
    #[cfg(test)]
    pub(crate) fn lock_for_test(&self) -> std::sync::MutexGuard<'_, Connection> {
        self.engine.lock_for_test()
    }
}

fn corrupt(what: &'static str) -> impl FnOnce(serde_json::Error) -> StoreError {
    move |e| StoreError::Corrupt {
        what,
        reason: e.to_string(),
    }
}
