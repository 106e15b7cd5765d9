//! Durable security state in SQLite: rules, credentials, sessions and the audit log.
//!
//! Design choice: these tables live in the hub's own database file (all prefixed `auth_`
//! or `audit_`, created with `IF NOT EXISTS`), behind one connection in a std `Mutex`.
//! Every statement is short and synchronous; callers on an async runtime run store calls
//! on the blocking pool. Rule edits bump a revision counter in the same transaction, so a
//! hub can notice edits made by another process (`fleetlink admin` on the same file) by
//! polling [`Store::rules_revision`].

mod credentials;
mod rules;

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

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

/// Handle to the security tables. Cheap to clone.
#[derive(Clone)]
pub struct Store {
    // std Mutex: every use is one short synchronous statement or transaction, never held
    // across an await; contention is low (logins, admin edits, audit batches).
    conn: Arc<Mutex<Connection>>,
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

    fn from_conn(conn: Connection) -> Store {
        Store {
            conn: Arc::new(Mutex::new(conn)),
        }
    }

    pub(crate) fn with<T>(
        &self,
        f: impl FnOnce(&mut Connection) -> Result<T, StoreError>,
    ) -> Result<T, StoreError> {
        let mut conn = self.conn.lock().unwrap_or_else(|p| p.into_inner());
        f(&mut conn)
    }

    /// Holds the connection, stalling every writer: lets tests fill the audit channel.
    #[cfg(test)]
    pub(crate) fn lock_for_test(&self) -> std::sync::MutexGuard<'_, Connection> {
        self.conn.lock().unwrap_or_else(|p| p.into_inner())
    }
}

fn corrupt(what: &'static str) -> impl FnOnce(serde_json::Error) -> StoreError {
    move |e| StoreError::Corrupt {
        what,
        reason: e.to_string(),
    }
}
