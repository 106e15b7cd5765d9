//! Durable hub state: in an embedded SQLite database (`<data-dir>/hub.sqlite3`), or in a
//! PostgreSQL database several hubs share (`--database`).
//!
//! It remembers every robot that ever connected, so the API can list robots that are
//! offline, how far each robot's no-drop topics have been delivered (see
//! [`crate::delivery`]), so a restarted hub — or the hub a robot fails over to — still
//! delivers each message once, and the parameters. Writes run on the blocking pool. Each
//! method holds both SQL dialects side by side; a parameter change on PostgreSQL notifies
//! the other hubs ([`Store::on_params_changed`]).

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use fleetlink_postgres::changes::{Change, notify};
use fleetlink_postgres::{Database, DbError, PgError};
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
    #[error(transparent)]
    Postgres(#[from] DbError),
    #[error("cannot start the database writer thread: {0}")]
    Thread(std::io::Error),
}

impl From<PgError> for StoreError {
    fn from(e: PgError) -> StoreError {
        StoreError::Postgres(e.into())
    }
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

/// The configuration changes the hub applied to a robot while it ran, as kept to apply
/// again when it reconnects (`crate::http::robot_config`).
#[derive(Debug, Clone, serde::Serialize)]
pub struct KeptConfig {
    /// The changes in force, as the agent answered them (JSON text).
    pub overlay: String,
    pub by: String,
    pub at_ms: i64,
}

/// The PostgreSQL schema, one entry per version (never edit one that shipped; add one).
const PG_MIGRATIONS: &[&str] = &[
    "
    CREATE TABLE robots (
        name TEXT PRIMARY KEY,
        first_seen_ms BIGINT NOT NULL,
        last_seen_ms BIGINT NOT NULL,
        last_addr TEXT NOT NULL,
        connects BIGINT NOT NULL DEFAULT 0
    );
    CREATE TABLE params (
        name TEXT PRIMARY KEY,
        value TEXT NOT NULL
    );
    CREATE TABLE delivered (
        robot TEXT NOT NULL,
        topic TEXT NOT NULL,
        epoch BIGINT NOT NULL,
        seq BIGINT NOT NULL,
        PRIMARY KEY (robot, topic)
    );
",
    "
    CREATE TABLE robot_configs (
        robot TEXT PRIMARY KEY,
        overlay TEXT NOT NULL,
        by_whom TEXT NOT NULL,
        at_ms BIGINT NOT NULL
    );
",
];

#[derive(Clone)]
pub struct Store {
    backend: Backend,
}

#[derive(Clone)]
enum Backend {
    // std Mutex: every use is one short synchronous statement on the blocking pool.
    Sqlite(Arc<Mutex<Connection>>),
    Postgres(Database),
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
             );
             CREATE TABLE IF NOT EXISTS robot_configs (
                 robot TEXT PRIMARY KEY,
                 overlay TEXT NOT NULL,
                 by_whom TEXT NOT NULL,
                 at_ms INTEGER NOT NULL
             );",
        )
        .map_err(|source| StoreError::Open { path, source })?;
        Ok(Store {
            backend: Backend::Sqlite(Arc::new(Mutex::new(conn))),
        })
    }

    /// The hub's tables in a shared PostgreSQL database, created or brought up to date
    /// first (safe when several hubs start at once). Blocks: call it from a blocking
    /// thread.
    pub fn postgres(db: Database) -> Result<Store, StoreError> {
        db.migrate("hub", PG_MIGRATIONS)?;
        Ok(Store {
            backend: Backend::Postgres(db),
        })
    }

    /// Whether other hubs may change this state too (a shared PostgreSQL database).
    pub fn is_shared(&self) -> bool {
        matches!(self.backend, Backend::Postgres(_))
    }

    /// Calls `f` whenever any hub on the shared database changed a parameter, and when
    /// the notifications may have been missed (the listener reconnected). Never with
    /// SQLite, where this hub is the only writer. `f` must return at once (see
    /// [`Database::on_change`]); returning `false` unsubscribes it.
    pub fn on_params_changed(&self, f: impl Fn() -> bool + Send + Sync + 'static) {
        if let Backend::Postgres(db) = &self.backend {
            db.on_change(move |c| match c {
                Change::Params | Change::Everything => f(),
                _ => true,
            });
        }
    }

    fn with<T>(
        conn: &Mutex<Connection>,
        f: impl FnOnce(&Connection) -> rusqlite::Result<T>,
    ) -> Result<T, StoreError> {
        let conn = conn.lock().unwrap_or_else(|p| p.into_inner());
        Ok(f(&conn)?)
    }

    pub fn robot_seen(&self, name: &str, addr: &str, connected: bool) -> Result<(), StoreError> {
        let now = now_ms();
        let connected = i64::from(connected);
        match &self.backend {
            Backend::Sqlite(c) => Self::with(c, |c| {
                c.execute(
                    "INSERT INTO robots (name, first_seen_ms, last_seen_ms, last_addr, connects)
                     VALUES (?1, ?2, ?2, ?3, ?4)
                     ON CONFLICT(name) DO UPDATE SET last_seen_ms = ?2, last_addr = ?3,
                         connects = connects + ?4",
                    params![name, now, addr, connected],
                )
                .map(|_| ())
            }),
            Backend::Postgres(db) => {
                db.execute(
                    "INSERT INTO robots (name, first_seen_ms, last_seen_ms, last_addr, connects)
                     VALUES ($1, $2, $2, $3, $4)
                     ON CONFLICT (name) DO UPDATE SET last_seen_ms = $2, last_addr = $3,
                         connects = robots.connects + $4",
                    &[&name, &now, &addr, &connected],
                )?;
                Ok(())
            }
        }
    }

    /// The configuration changes kept for `robot`, if the hub applied any.
    pub fn robot_config(&self, robot: &str) -> Result<Option<KeptConfig>, StoreError> {
        let sql_lite = "SELECT overlay, by_whom, at_ms FROM robot_configs WHERE robot = ?1";
        let sql_pg = "SELECT overlay, by_whom, at_ms FROM robot_configs WHERE robot = $1";
        match &self.backend {
            Backend::Sqlite(c) => Self::with(c, |c| {
                let mut st = c.prepare(sql_lite)?;
                let mut rows = st.query_map(params![robot], |r| {
                    Ok(KeptConfig {
                        overlay: r.get(0)?,
                        by: r.get(1)?,
                        at_ms: r.get(2)?,
                    })
                })?;
                rows.next().transpose()
            }),
            Backend::Postgres(db) => Ok(db
                .query(sql_pg, &[&robot])?
                .first()
                .map(|r| -> Result<KeptConfig, StoreError> {
                    Ok(KeptConfig {
                        overlay: r.try_get(0)?,
                        by: r.try_get(1)?,
                        at_ms: r.try_get(2)?,
                    })
                })
                .transpose()?),
        }
    }

    /// Keeps `overlay` as `robot`'s configuration changes, applied by `by` now.
    pub fn set_robot_config(&self, robot: &str, overlay: &str, by: &str) -> Result<(), StoreError> {
        let now = now_ms();
        match &self.backend {
            Backend::Sqlite(c) => Self::with(c, |c| {
                c.execute(
                    "INSERT INTO robot_configs (robot, overlay, by_whom, at_ms) VALUES (?1, ?2, ?3, ?4)
                     ON CONFLICT(robot) DO UPDATE SET overlay = ?2, by_whom = ?3, at_ms = ?4",
                    params![robot, overlay, by, now],
                )
                .map(|_| ())
            }),
            Backend::Postgres(db) => {
                db.execute(
                    "INSERT INTO robot_configs (robot, overlay, by_whom, at_ms) VALUES ($1, $2, $3, $4)
                     ON CONFLICT (robot) DO UPDATE SET overlay = $2, by_whom = $3, at_ms = $4",
                    &[&robot, &overlay, &by, &now],
                )?;
                Ok(())
            }
        }
    }

    /// How far `robot`'s no-drop topics were delivered: (topic, epoch, last seq).
    pub fn delivered(&self, robot: &str) -> Result<Vec<(String, u64, u64)>, StoreError> {
        match &self.backend {
            Backend::Sqlite(c) => Self::with(c, |c| {
                let mut st =
                    c.prepare("SELECT topic, epoch, seq FROM delivered WHERE robot = ?1")?;
                let rows = st.query_map(params![robot], |r| {
                    Ok((
                        r.get::<_, String>(0)?,
                        r.get::<_, i64>(1)? as u64,
                        r.get::<_, i64>(2)? as u64,
                    ))
                })?;
                rows.collect()
            }),
            Backend::Postgres(db) => db
                .query(
                    "SELECT topic, epoch, seq FROM delivered WHERE robot = $1",
                    &[&robot],
                )?
                .iter()
                .map(|r| {
                    Ok((
                        r.try_get(0)?,
                        r.try_get::<_, i64>(1)? as u64,
                        r.try_get::<_, i64>(2)? as u64,
                    ))
                })
                .collect(),
        }
    }

    /// Records delivery marks of `robot` (topic, epoch, seq) in one transaction.
    pub fn record_delivered(
        &self,
        robot: &str,
        marks: &[(String, u64, u64)],
    ) -> Result<(), StoreError> {
        match &self.backend {
            Backend::Sqlite(c) => {
                let mut conn = c.lock().unwrap_or_else(|p| p.into_inner());
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
            Backend::Postgres(db) => {
                let topics: Vec<&str> = marks.iter().map(|(t, _, _)| t.as_str()).collect();
                let epochs: Vec<i64> = marks.iter().map(|(_, e, _)| *e as i64).collect();
                let seqs: Vec<i64> = marks.iter().map(|(_, _, s)| *s as i64).collect();
                db.transaction(async |tx| {
                    // One statement for all marks: one round trip however many topics.
                    tx.execute(
                        "INSERT INTO delivered (robot, topic, epoch, seq)
                         SELECT $1, * FROM UNNEST($2::TEXT[], $3::BIGINT[], $4::BIGINT[])
                         ON CONFLICT (robot, topic)
                         DO UPDATE SET epoch = excluded.epoch, seq = excluded.seq",
                        &[&robot, &topics, &epochs, &seqs],
                    )
                    .await?;
                    if let Some(epoch) = epochs.first() {
                        tx.execute(
                            "DELETE FROM delivered WHERE robot = $1 AND epoch != $2",
                            &[&robot, epoch],
                        )
                        .await?;
                    }
                    Ok(())
                })?;
                Ok(())
            }
        }
    }

    /// Every parameter (name → JSON text).
    pub fn params(&self) -> Result<std::collections::BTreeMap<String, String>, StoreError> {
        match &self.backend {
            Backend::Sqlite(c) => Self::with(c, |c| {
                let mut st = c.prepare("SELECT name, value FROM params")?;
                let rows = st.query_map([], |r| Ok((r.get(0)?, r.get(1)?)))?;
                rows.collect()
            }),
            Backend::Postgres(db) => db
                .query("SELECT name, value FROM params", &[])?
                .iter()
                .map(|r| Ok((r.try_get(0)?, r.try_get(1)?)))
                .collect(),
        }
    }

    /// Brings the named parameters in line in one transaction: each set to its value, or
    /// deleted when it has none. On PostgreSQL the other hubs are notified once.
    pub fn write_params(&self, changes: &[(String, Option<String>)]) -> Result<(), StoreError> {
        if changes.is_empty() {
            return Ok(());
        }
        match &self.backend {
            Backend::Sqlite(c) => {
                let mut conn = c.lock().unwrap_or_else(|p| p.into_inner());
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
            Backend::Postgres(db) => {
                let (mut names, mut values, mut gone) = (Vec::new(), Vec::new(), Vec::new());
                for (name, value) in changes {
                    match value {
                        Some(v) => {
                            names.push(name.as_str());
                            values.push(v.as_str());
                        }
                        None => gone.push(name.as_str()),
                    }
                }
                Ok(db.transaction(async |tx| {
                    if !names.is_empty() {
                        tx.execute(
                            "INSERT INTO params (name, value)
                             SELECT * FROM UNNEST($1::TEXT[], $2::TEXT[])
                             ON CONFLICT (name) DO UPDATE SET value = excluded.value",
                            &[&names, &values],
                        )
                        .await?;
                    }
                    if !gone.is_empty() {
                        tx.execute("DELETE FROM params WHERE name = ANY($1)", &[&gone])
                            .await?;
                    }
                    notify(tx, Change::Params).await
                })?)
            }
        }
    }

    /// Deletes `name` and every parameter under it.
    pub fn delete_params(&self, name: &str) -> Result<(), StoreError> {
        let below = format!("{name}/%");
        match &self.backend {
            Backend::Sqlite(c) => Self::with(c, |c| {
                c.execute(
                    "DELETE FROM params WHERE name = ?1 OR name LIKE ?2",
                    params![name, below],
                )
                .map(|_| ())
            }),
            Backend::Postgres(db) => Ok(db.transaction(async |tx| {
                tx.execute(
                    "DELETE FROM params WHERE name = $1 OR name LIKE $2",
                    &[&name, &below],
                )
                .await?;
                notify(tx, Change::Params).await
            })?),
        }
    }

    pub fn robots(&self) -> Result<Vec<RobotRecord>, StoreError> {
        const SQL: &str = "SELECT name, first_seen_ms, last_seen_ms, last_addr, connects \
                           FROM robots ORDER BY name";
        match &self.backend {
            Backend::Sqlite(c) => Self::with(c, |c| {
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
            }),
            Backend::Postgres(db) => db
                .query(SQL, &[])?
                .iter()
                .map(|r| {
                    Ok(RobotRecord {
                        name: r.try_get(0)?,
                        first_seen_ms: r.try_get(1)?,
                        last_seen_ms: r.try_get(2)?,
                        last_addr: r.try_get(3)?,
                        connects: r.try_get(4)?,
                    })
                })
                .collect(),
        }
    }
}

fn now_ms() -> i64 {
    (fleetlink_relay::unix_nanos() / 1_000_000) as i64
}

/// Stores for the tests of this crate's modules, on either backend.
#[cfg(test)]
pub(crate) mod testing {
    use super::*;

    #[derive(Debug, Clone, Copy)]
    pub enum Backend {
        Sqlite,
        Postgres,
    }

    /// Where a fresh store lives; [`Place::open`] opens it again, as a second hub or a
    /// restarted one would.
    pub enum Place {
        Dir(PathBuf),
        Url(String),
    }

    impl Place {
        pub fn new(backend: Backend, what: &str) -> Place {
            match backend {
                Backend::Sqlite => Place::Dir(std::env::temp_dir().join(format!(
                    "fleetlink-{what}-{}-{}",
                    std::process::id(),
                    fleetlink_relay::unix_nanos()
                ))),
                Backend::Postgres => Place::Url(fleetlink_postgres::scratch_database_url()),
            }
        }

        pub fn open(&self) -> Store {
            match self {
                Place::Dir(d) => Store::open(d).unwrap(),
                Place::Url(u) => Store::postgres(Database::connect(u).unwrap()).unwrap(),
            }
        }
    }

    impl Drop for Place {
        fn drop(&mut self) {
            if let Place::Dir(d) = self {
                let _ = std::fs::remove_dir_all(d);
            }
        }
    }

    /// Runs each named test body (a `fn(Backend)` of the calling module) on both backends;
    /// the PostgreSQL variants are ignored unless run with a server (see
    /// tests/interop/postgres/run.sh), so a plain run reports them skipped.
    macro_rules! on_both_backends {
        ($($name:ident),* $(,)?) => {
            mod sqlite {
                $(#[test]
                fn $name() {
                    super::$name($crate::store::testing::Backend::Sqlite)
                })*
            }
            mod postgres {
                $(#[test]
                #[ignore = "needs PostgreSQL: tests/interop/postgres/run.sh runs it with a server"]
                fn $name() {
                    super::$name($crate::store::testing::Backend::Postgres)
                })*
            }
        };
    }
    pub(crate) use on_both_backends;
}

#[cfg(test)]
mod tests {
    use super::testing::{Backend, Place, on_both_backends};

    on_both_backends!(
        robots_are_remembered_with_their_connections,
        delivery_marks_of_a_new_epoch_replace_the_old_ones,
        params_set_delete_and_delete_a_subtree,
    );

    fn robots_are_remembered_with_their_connections(backend: Backend) {
        let place = Place::new(backend, "robots");
        let s = place.open();
        s.robot_seen("r2", "192.0.2.2:1", true).unwrap();
        s.robot_seen("r1", "192.0.2.1:1", true).unwrap();
        s.robot_seen("r1", "192.0.2.1:2", false).unwrap();
        s.robot_seen("r1", "192.0.2.1:3", true).unwrap();
        let robots = place.open().robots().unwrap();
        let names: Vec<_> = robots.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(names, ["r1", "r2"]);
        assert_eq!(robots[0].connects, 2);
        assert_eq!(robots[0].last_addr, "192.0.2.1:3");
        assert!(robots[0].first_seen_ms <= robots[0].last_seen_ms);
    }

    fn delivery_marks_of_a_new_epoch_replace_the_old_ones(backend: Backend) {
        let place = Place::new(backend, "marks");
        let s = place.open();
        let mark = |t: &str, e, q| (t.to_owned(), e, q);
        s.record_delivered("r1", &[mark("/a", 7, 1), mark("/b", 7, 5)])
            .unwrap();
        s.record_delivered("r1", &[mark("/a", 7, 3)]).unwrap();
        s.record_delivered("r2", &[mark("/a", 1, 9)]).unwrap();
        let mut got = place.open().delivered("r1").unwrap();
        got.sort();
        assert_eq!(got, vec![mark("/a", 7, 3), mark("/b", 7, 5)]);
        s.record_delivered("r1", &[mark("/c", 8, 1)]).unwrap();
        assert_eq!(s.delivered("r1").unwrap(), vec![mark("/c", 8, 1)]);
        assert_eq!(s.delivered("r2").unwrap(), vec![mark("/a", 1, 9)]);
    }

    fn params_set_delete_and_delete_a_subtree(backend: Backend) {
        let place = Place::new(backend, "params");
        let s = place.open();
        let change = |n: &str, v: Option<&str>| (n.to_owned(), v.map(str::to_owned));
        let set = |n: &str, v: &str| change(n, Some(v));
        s.write_params(&[
            set("/a", "1"),
            set("/a/b", "2"),
            set("/a/c/d", "3"),
            set("/ab", "4"),
        ])
        .unwrap();
        s.write_params(&[set("/a", "10")]).unwrap();
        assert_eq!(
            s.params().unwrap().get("/a").map(String::as_str),
            Some("10")
        );
        s.write_params(&[change("/ab", None)]).unwrap();
        s.delete_params("/a/c").unwrap();
        let left: Vec<_> = place.open().params().unwrap().into_keys().collect();
        assert_eq!(left, ["/a", "/a/b"]);
        s.delete_params("/a").unwrap();
        assert!(s.params().unwrap().is_empty());

        s.write_params(&[change("/x", Some("1")), change("/y", Some("2"))])
            .unwrap();
        s.write_params(&[
            change("/x", None),
            change("/y", Some("3")),
            change("/z", None),
        ])
        .unwrap();
        let left: Vec<_> = place.open().params().unwrap().into_iter().collect();
        assert_eq!(left, [("/y".to_owned(), "3".to_owned())]);
    }
}
