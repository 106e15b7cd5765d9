//! The SQLite backend of the hub [`Store`]: the tables in `<data-dir>/hub.sqlite3`, one
//! hub's own file, and every statement the store runs there.
//!
//! Design choice: one connection behind a std `Mutex`, since every use is one short
//! synchronous statement or transaction on the blocking pool. This hub is the only
//! writer, so nothing here notifies anyone.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Mutex;

use rusqlite::{Connection, params};

use super::{Engine, KeptConfig, RobotRecord, Store, StoreError};

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
             );
             CREATE TABLE IF NOT EXISTS robot_configs (
                 robot TEXT PRIMARY KEY,
                 overlay TEXT NOT NULL,
                 by_whom TEXT NOT NULL,
                 at_ms INTEGER NOT NULL
             );",
        )
        .map_err(|source| StoreError::Open { path, source })?;
        Ok(Store::new(Sqlite {
            conn: Mutex::new(conn),
        }))
    }
}

struct Sqlite {
    // std Mutex: every use is one short synchronous statement on the blocking pool.
    conn: Mutex<Connection>,
}

impl Sqlite {
    fn with<T>(&self, f: impl FnOnce(&Connection) -> rusqlite::Result<T>) -> Result<T, StoreError> {
        let conn = self.conn.lock().unwrap_or_else(|p| p.into_inner());
        Ok(f(&conn)?)
    }
}

impl Engine for Sqlite {
    fn is_shared(&self) -> bool {
        false
    }

    fn on_params_changed(&self, _: Box<dyn Fn() -> bool + Send + Sync>) {}

    fn robot_seen(
        &self,
        name: &str,
        addr: &str,
        now: i64,
        connected: i64,
    ) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "INSERT INTO robots (name, first_seen_ms, last_seen_ms, last_addr, connects)
                     VALUES (?1, ?2, ?2, ?3, ?4)
                     ON CONFLICT(name) DO UPDATE SET last_seen_ms = ?2, last_addr = ?3,
                         connects = connects + ?4",
                params![name, now, addr, connected],
            )
            .map(|_| ())
        })
    }

    fn robot_config(&self, robot: &str) -> Result<Option<KeptConfig>, StoreError> {
        const SQL: &str = "SELECT overlay, by_whom, at_ms FROM robot_configs WHERE robot = ?1";
        self.with(|c| {
            let mut st = c.prepare(SQL)?;
            let mut rows = st.query_map(params![robot], |r| {
                Ok(KeptConfig {
                    overlay: r.get(0)?,
                    by: r.get(1)?,
                    at_ms: r.get(2)?,
                })
            })?;
            rows.next().transpose()
        })
    }

    fn set_robot_config(
        &self,
        robot: &str,
        overlay: &str,
        by: &str,
        now: i64,
    ) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "INSERT INTO robot_configs (robot, overlay, by_whom, at_ms) VALUES (?1, ?2, ?3, ?4)
                     ON CONFLICT(robot) DO UPDATE SET overlay = ?2, by_whom = ?3, at_ms = ?4",
                params![robot, overlay, by, now],
            )
            .map(|_| ())
        })
    }

    fn delivered(&self, robot: &str) -> Result<Vec<(String, u64, u64)>, StoreError> {
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

    fn record_delivered(
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

    fn params(&self) -> Result<BTreeMap<String, String>, StoreError> {
        self.with(|c| {
            let mut st = c.prepare("SELECT name, value FROM params")?;
            let rows = st.query_map([], |r| Ok((r.get(0)?, r.get(1)?)))?;
            rows.collect()
        })
    }

    fn write_params(&self, changes: &[(String, Option<String>)]) -> Result<(), StoreError> {
        let mut conn = self.conn.lock().unwrap_or_else(|p| p.into_inner());
        let tx = conn.transaction()?;
        {
            let mut set = tx.prepare_cached(
                "INSERT INTO params (name, value) VALUES (?1, ?2)
                         ON CONFLICT(name) DO UPDATE SET value = excluded.value",
            )?;
            let mut delete = tx.prepare_cached("DELETE FROM params WHERE name = ?1")?;
            for (name, value) in changes {
                match value {
                    Some(v) => set.execute(params![name, v])?,
                    None => delete.execute(params![name])?,
                };
            }
        }
        tx.commit()?;
        Ok(())
    }

    fn delete_params(&self, name: &str, below: &str) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "DELETE FROM params WHERE name = ?1 OR name LIKE ?2",
                params![name, below],
            )
            .map(|_| ())
        })
    }

    fn robots(&self) -> Result<Vec<RobotRecord>, StoreError> {
        const SQL: &str = "SELECT name, first_seen_ms, last_seen_ms, last_addr, connects \
                           FROM robots ORDER BY name";
        self.with(|c| {
            let mut st = c.prepare(SQL)?;
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
