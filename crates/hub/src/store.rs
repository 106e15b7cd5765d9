//! Durable hub state: in an embedded SQLite database (`<data-dir>/hub.sqlite3`), or in a
//! PostgreSQL database several hubs share (`--database`).
//!
//! It remembers every robot that ever connected, so the API can list robots that are
//! offline, how far each robot's no-drop topics have been delivered (see
//! [`crate::delivery`]), so a restarted hub — or the hub a robot fails over to — still
//! delivers each message once, and the parameters. Writes run on the blocking pool.
//!
//! Design choice: one [`Store`] API over two backends, chosen once, when the store is
//! opened. Each backend is an `Engine` in its own file that holds all of its SQL
//! dialect: `store/sqlite.rs` ([`Store::open`]) and `store/postgres.rs`
//! ([`Store::postgres`]). The methods here only prepare values and hand them to the
//! engine. A parameter change on PostgreSQL notifies the other hubs
//! ([`Store::on_params_changed`]).

mod postgres;
mod sqlite;

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;

use fleetlink_postgres::{DbError, PgError};

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

/// Handle to the hub's tables. Cheap to clone.
#[derive(Clone)]
pub struct Store {
    engine: Arc<dyn Engine>,
}

/// One backend's statements: every [`Store`] method, in that backend's SQL dialect.
/// Values (times, counters) are prepared by the caller, so both engines write the same.
trait Engine: Send + Sync {
    /// Whether other hubs may change this state too.
    fn is_shared(&self) -> bool;
    /// See [`Store::on_params_changed`].
    fn on_params_changed(&self, f: Box<dyn Fn() -> bool + Send + Sync>);
    fn robot_seen(
        &self,
        name: &str,
        addr: &str,
        now: i64,
        connected: i64,
    ) -> Result<(), StoreError>;
    fn robot_config(&self, robot: &str) -> Result<Option<KeptConfig>, StoreError>;
    fn set_robot_config(
        &self,
        robot: &str,
        overlay: &str,
        by: &str,
        now: i64,
    ) -> Result<(), StoreError>;
    fn delivered(&self, robot: &str) -> Result<Vec<(String, u64, u64)>, StoreError>;
    fn record_delivered(&self, robot: &str, marks: &[(String, u64, u64)])
    -> Result<(), StoreError>;
    fn params(&self) -> Result<BTreeMap<String, String>, StoreError>;
    /// `changes` is never empty.
    fn write_params(&self, changes: &[(String, Option<String>)]) -> Result<(), StoreError>;
    /// `below` is the `LIKE` pattern of the names under `name`.
    fn delete_params(&self, name: &str, below: &str) -> Result<(), StoreError>;
    fn robots(&self) -> Result<Vec<RobotRecord>, StoreError>;
}

impl Store {
    fn new(engine: impl Engine + 'static) -> Store {
        Store {
            engine: Arc::new(engine),
        }
    }

    /// Whether other hubs may change this state too (a shared PostgreSQL database).
    pub fn is_shared(&self) -> bool {
        self.engine.is_shared()
    }

    /// Calls `f` whenever any hub on the shared database changed a parameter, and when
    /// the notifications may have been missed (the listener reconnected). Never with
    /// SQLite, where this hub is the only writer. `f` must return at once (see
    /// [`fleetlink_postgres::Database::on_change`]); returning `false` unsubscribes it.
    pub fn on_params_changed(&self, f: impl Fn() -> bool + Send + Sync + 'static) {
        self.engine.on_params_changed(Box::new(f));
    }

    pub fn robot_seen(&self, name: &str, addr: &str, connected: bool) -> Result<(), StoreError> {
        let now = now_ms();
        let connected = i64::from(connected);
        self.engine.robot_seen(name, addr, now, connected)
    }

    /// The configuration changes kept for `robot`, if the hub applied any.
    pub fn robot_config(&self, robot: &str) -> Result<Option<KeptConfig>, StoreError> {
        self.engine.robot_config(robot)
    }

    /// Keeps `overlay` as `robot`'s configuration changes, applied by `by` now.
    pub fn set_robot_config(&self, robot: &str, overlay: &str, by: &str) -> Result<(), StoreError> {
        let now = now_ms();
        self.engine.set_robot_config(robot, overlay, by, now)
    }

    /// How far `robot`'s no-drop topics were delivered: (topic, epoch, last seq).
    pub fn delivered(&self, robot: &str) -> Result<Vec<(String, u64, u64)>, StoreError> {
        self.engine.delivered(robot)
    }

    /// Records delivery marks of `robot` (topic, epoch, seq) in one transaction.
    pub fn record_delivered(
        &self,
        robot: &str,
        marks: &[(String, u64, u64)],
    ) -> Result<(), StoreError> {
        self.engine.record_delivered(robot, marks)
    }

    /// Every parameter (name → JSON text).
    pub fn params(&self) -> Result<BTreeMap<String, String>, StoreError> {
        self.engine.params()
    }

    /// Brings the named parameters in line in one transaction: each set to its value, or
    /// deleted when it has none. On PostgreSQL the other hubs are notified once.
    pub fn write_params(&self, changes: &[(String, Option<String>)]) -> Result<(), StoreError> {
        if changes.is_empty() {
            return Ok(());
        }
        self.engine.write_params(changes)
    }

    /// Deletes `name` and every parameter under it.
    pub fn delete_params(&self, name: &str) -> Result<(), StoreError> {
        let below = format!("{name}/%");
        self.engine.delete_params(name, &below)
    }

    pub fn robots(&self) -> Result<Vec<RobotRecord>, StoreError> {
        self.engine.robots()
    }
}

fn now_ms() -> i64 {
    (fleetlink_relay::unix_nanos() / 1_000_000) as i64
}

/// Stores for the tests of this crate's modules, on either backend.
#[cfg(test)]
pub(crate) mod testing {
    use std::path::PathBuf;

    use fleetlink_postgres::Database;

    use super::Store;

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
