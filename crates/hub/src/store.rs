//! Durable hub state in an embedded SQLite database (`<data-dir>/hub.sqlite3`).
//!
//! It remembers every robot that ever connected, so the API can list robots that are
//! offline, and how far each robot's no-drop topics have been delivered (see
//! [`crate::delivery`]), so a restarted hub still delivers each message once. Writes run on
//! the blocking pool.

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
    #[error("cannot start the database writer thread: {0}")]
    Thread(std::io::Error),
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
        // Shared with `fleetlink admin` and the auth store: wait for their locks.
        fleetlink_auth::store::init_schema(
            &conn,
            "CREATE TABLE IF NOT EXISTS robots (
                 name TEXT PRIMARY KEY,
                 first_seen_ms INTEGER NOT NULL,
                 last_seen_ms INTEGER NOT NULL,
                 last_addr TEXT NOT NULL,
                 connects INTEGER NOT NULL DEFAULT 0
             );
             CREATE TABLE IF NOT EXISTS params (
                 name TEXT PRIMARY KEY,
                 value TEXT NOT NULL
             );
             CREATE TABLE IF NOT EXISTS delivered (
                 robot TEXT NOT NULL,
                 topic TEXT NOT NULL,
                 epoch INTEGER NOT NULL,
                 seq INTEGER NOT NULL,
                 PRIMARY KEY (robot, topic)
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

    /// How far `robot`'s no-drop topics were delivered: (topic, epoch, last seq).
    pub fn delivered(&self, robot: &str) -> Result<Vec<(String, u64, u64)>, StoreError> {
        self.with(|c| {
            let mut st = c.prepare("SELECT topic, epoch, seq FROM delivered WHERE robot = ?1")?;
            let rows = st.query_map(params![robot], |r| {
                Ok((
                    r.get::<_, String>(0)?,
                    r.get::<_, i64>(1)? as u64,
                    r.get::<_, i64>(2)? as u64,
                ))
            })?;
            rows.collect()
        })
    }

    /// Records delivery marks of `robot` (topic, epoch, seq) in one transaction.
    pub fn record_delivered(
        &self,
        robot: &str,
        marks: &[(String, u64, u64)],
    ) -> Result<(), StoreError> {
        let mut conn = self.conn.lock().unwrap_or_else(|p| p.into_inner());
        let tx = conn.transaction()?;
        {
            let mut st = tx.prepare_cached(
                "INSERT INTO delivered (robot, topic, epoch, seq) VALUES (?1, ?2, ?3, ?4)
                 ON CONFLICT(robot, topic) DO UPDATE SET epoch = ?3, seq = ?4",
            )?;
            for (topic, epoch, seq) in marks {
                st.execute(params![robot, topic, *epoch as i64, *seq as i64])?;
            }
            // Marks of an earlier epoch belong to an outbox the robot no longer has.
            if let Some((_, epoch, _)) = marks.first() {
                tx.execute(
                    "DELETE FROM delivered WHERE robot = ?1 AND epoch != ?2",
                    params![robot, *epoch as i64],
                )?;
            }
        }
        tx.commit()?;
        Ok(())
    }

    /// Every parameter (name → JSON text).
    pub fn params(&self) -> Result<std::collections::BTreeMap<String, String>, StoreError> {
        self.with(|c| {
            let mut st = c.prepare("SELECT name, value FROM params")?;
            let rows = st.query_map([], |r| Ok((r.get(0)?, r.get(1)?)))?;
            rows.collect()
        })
    }

    pub fn set_param(&self, name: &str, value: &str) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "INSERT INTO params (name, value) VALUES (?1, ?2)
                 ON CONFLICT(name) DO UPDATE SET value = excluded.value",
                params![name, value],
            )
            .map(|_| ())
        })
    }

    /// Deletes the parameter `name` alone.
    pub fn delete_param(&self, name: &str) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute("DELETE FROM params WHERE name = ?1", params![name])
                .map(|_| ())
        })
    }

    /// Deletes `name` and every parameter under it.
    pub fn delete_params(&self, name: &str) -> Result<(), StoreError> {
        let below = format!("{name}/%");
        self.with(|c| {
            c.execute(
                "DELETE FROM params WHERE name = ?1 OR name LIKE ?2",
                params![name, below],
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
