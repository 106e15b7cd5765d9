//! Durable hub state in an embedded SQLite database (`<data-dir>/hub.sqlite3`).
//!
//! For now it remembers every robot that ever connected, so the API can list robots that
//! are offline. Writes are rare (connect/disconnect) and run on the blocking pool.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use rusqlite::{Connection, params};

#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error("cannot create data directory {path}: {source}")]
    CreateDir {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("cannot open database {path}: {source}")]
    Open {
        path: PathBuf,
        source: rusqlite::Error,
    },
    #[error("database error: {0}")]
    Sql(#[from] rusqlite::Error),
}

/// A robot as remembered by the database.
#[derive(Debug, Clone, serde::Serialize)]
pub struct RobotRecord {
    pub name: String,
    pub first_seen_ms: i64,
    pub last_seen_ms: i64,
    pub last_addr: String,
    pub connects: i64,
}

#[derive(Clone)]
pub struct Store {
    // std Mutex: every use is one short synchronous statement on the blocking pool.
    conn: Arc<Mutex<Connection>>,
}

impl Store {
    pub fn open(dir: &Path) -> Result<Store, StoreError> {
        std::fs::create_dir_all(dir).map_err(|source| StoreError::CreateDir {
            path: dir.to_owned(),
            source,
        })?;
        let path = dir.join("hub.sqlite3");
        let conn = Connection::open(&path).map_err(|source| StoreError::Open {
            path: path.clone(),
            source,
        })?;
        conn.execute_batch(
            "PRAGMA journal_mode = WAL;
             PRAGMA synchronous = NORMAL;
             CREATE TABLE IF NOT EXISTS robots (
                 name TEXT PRIMARY KEY,
                 first_seen_ms INTEGER NOT NULL,
                 last_seen_ms INTEGER NOT NULL,
                 last_addr TEXT NOT NULL,
                 connects INTEGER NOT NULL DEFAULT 0
             );",
        )
        .map_err(|source| StoreError::Open { path, source })?;
        Ok(Store {
            conn: Arc::new(Mutex::new(conn)),
        })
    }

    fn with<T>(&self, f: impl FnOnce(&Connection) -> rusqlite::Result<T>) -> Result<T, StoreError> {
        let conn = self.conn.lock().unwrap_or_else(|p| p.into_inner());
        Ok(f(&conn)?)
    }

    pub fn robot_seen(&self, name: &str, addr: &str, connected: bool) -> Result<(), StoreError> {
        let now = now_ms();
        self.with(|c| {
            c.execute(
                "INSERT INTO robots (name, first_seen_ms, last_seen_ms, last_addr, connects)
                 VALUES (?1, ?2, ?2, ?3, ?4)
                 ON CONFLICT(name) DO UPDATE SET last_seen_ms = ?2, last_addr = ?3,
                     connects = connects + ?4",
                params![name, now, addr, i64::from(connected)],
            )
            .map(|_| ())
        })
    }

    pub fn robots(&self) -> Result<Vec<RobotRecord>, StoreError> {
        self.with(|c| {
            let mut st = c.prepare("SELECT name, first_seen_ms, last_seen_ms, last_addr, connects FROM robots ORDER BY name")?;
            let rows = st.query_map([], |r| {
                Ok(RobotRecord {
                    name: r.get(0)?,
                    first_seen_ms: r.get(1)?,
                    last_seen_ms: r.get(2)?,
                    last_addr: r.get(3)?,
                    connects: r.get(4)?,
                })
            })?;
            rows.collect()
        })
    }
}

fn now_ms() -> i64 {
    (fleetlink_relay::unix_nanos() / 1_000_000) as i64
}
