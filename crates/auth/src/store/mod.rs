//! Durable security state: rules, credentials, sessions and the audit log, in SQLite (one
//! hub) or PostgreSQL (several hubs sharing it).
//!
//! Design choice: one [`Store`] API over two backends. With SQLite the tables live in the
//! hub's own database file (all prefixed `auth_` or `audit_`, created with `IF NOT
//! EXISTS`), behind one connection in a std `Mutex`. With PostgreSQL they live in the
//! shared database ([`fleetlink_postgres`]: a pool, versioned migrations, change
//! notifications). Either way every statement is short and synchronous; callers on an
//! async runtime run store calls on the blocking pool. Each method holds both dialects
//! side by side, so a change to one is seen next to the other.
//!
//! Rule edits bump a revision counter in the same transaction, so a hub notices edits made
//! by another process (`fleetlink admin`, another hub) by polling
//! [`Store::rules_revision`]; on PostgreSQL the same transaction also notifies every hub
//! ([`fleetlink_postgres::changes`]), which reloads at once.

mod credentials;
mod rules;

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use fleetlink_postgres::Database;
use rusqlite::Connection;

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

/// The PostgreSQL schema, one entry per version (never edit one that shipped; add one).
const PG_MIGRATIONS: &[&str] = &["
    CREATE TABLE auth_meta (
        key TEXT PRIMARY KEY,
        value BIGINT NOT NULL
    );
    INSERT INTO auth_meta (key, value) VALUES ('rules_revision', 0);
    CREATE TABLE auth_rules (
        id BIGSERIAL PRIMARY KEY,
        rule_json TEXT NOT NULL,
        created_at BIGINT NOT NULL
    );
    CREATE TABLE auth_tokens (
        id BIGSERIAL PRIMARY KEY,
        hash BYTEA NOT NULL UNIQUE,
        kind TEXT NOT NULL,
        subject TEXT NOT NULL,
        groups_json TEXT NOT NULL DEFAULT '[]',
        created_at BIGINT NOT NULL,
        expires_at BIGINT,
        revoked_at BIGINT,
        last_used_at BIGINT
    );
    CREATE INDEX auth_tokens_subject ON auth_tokens (kind, subject);
    CREATE TABLE auth_users (
        name TEXT PRIMARY KEY,
        password_hash TEXT NOT NULL,
        groups_json TEXT NOT NULL DEFAULT '[]',
        created_at BIGINT NOT NULL
    );
    CREATE TABLE audit_log (
        id BIGSERIAL PRIMARY KEY,
        at BIGINT NOT NULL,
        principal TEXT NOT NULL,
        client_ip TEXT NOT NULL,
        action TEXT NOT NULL,
        name TEXT NOT NULL,
        size BIGINT,
        allowed BOOLEAN NOT NULL,
        detail TEXT
    );
    CREATE INDEX audit_log_at ON audit_log (at);
    CREATE INDEX audit_log_principal ON audit_log (principal, id);
"];

/// Handle to the security tables. Cheap to clone.
#[derive(Clone)]
pub struct Store {
    backend: Backend,
}

#[derive(Clone)]
pub(crate) enum Backend {
    // std Mutex: every use is one short synchronous statement or transaction, never held
    // across an await; contention is low (logins, admin edits, audit batches).
    Sqlite(Arc<Mutex<Connection>>),
    Postgres(Database),
}

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

    /// The tables in a shared PostgreSQL database, created or brought up to date first
    /// (safe when several hubs start at once). Blocks: call it from a blocking thread.
    pub fn postgres(db: Database) -> Result<Store, StoreError> {
        db.migrate("auth", PG_MIGRATIONS)?;
        Ok(Store {
            backend: Backend::Postgres(db),
        })
    }

    fn from_conn(conn: Connection) -> Store {
        Store {
            backend: Backend::Sqlite(Arc::new(Mutex::new(conn))),
        }
    }

    /// The shared database, when the store is in PostgreSQL.
    pub fn database(&self) -> Option<&Database> {
        match &self.backend {
            Backend::Sqlite(_) => None,
            Backend::Postgres(db) => Some(db),
        }
    }

    pub(crate) fn backend(&self) -> &Backend {
        &self.backend
    }

    /// Holds the connection, stalling every writer: lets tests fill the audit channel.
    #[cfg(test)]
    pub(crate) fn lock_for_test(&self) -> std::sync::MutexGuard<'_, Connection> {
        match &self.backend {
            Backend::Sqlite(c) => c.lock().unwrap_or_else(|p| p.into_inner()),
            Backend::Postgres(_) => unreachable!("the audit stall test runs on SQLite"),
        }
    }
}

/// Runs `f` on the SQLite connection.
pub(crate) fn with<T>(
    conn: &Mutex<Connection>,
    f: impl FnOnce(&mut Connection) -> Result<T, StoreError>,
) -> Result<T, StoreError> {
    let mut conn = conn.lock().unwrap_or_else(|p| p.into_inner());
    f(&mut conn)
}

fn corrupt(what: &'static str) -> impl FnOnce(serde_json::Error) -> StoreError {
    move |e| StoreError::Corrupt {
        what,
        reason: e.to_string(),
    }
}
