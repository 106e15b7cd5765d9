//! Shared hub state in PostgreSQL: what lets several hubs keep one set of tokens, users,
//! rules, robot records, parameters and one audit log (`fleetlink hub --database URL`).
//!
//! Design choice: the stores above this crate (`fleetlink-auth`'s and the hub's) are
//! synchronous, and their callers already run them on tokio's blocking pool or on threads
//! of their own, because SQLite is synchronous. So a [`Database`] owns a small runtime of
//! its own (one worker thread, `fleetlink-db`) that drives the pooled connections, and each
//! store call waits for its statement with [`tokio::runtime::Handle::block_on`] on the
//! calling thread. That keeps one store API for both backends, works the same from the
//! hub, from `fleetlink admin` (no runtime) and from plain `#[test]`s, and fails loudly
//! (tokio panics) if a call ever comes from an async worker instead of blocking it.
//!
//! # Layout
//!
//! - this file: [`Database`] (URL, pool, the blocking bridge) and [`DbError`];
//! - [`migrate`]: versioned schemas per component, applied under an advisory lock;
//! - [`scratch_database`]: a database of its own for each test, on the server the test
//!   suite started;
//! - [`changes`]: `LISTEN`/`NOTIFY` on one channel, so a change made through one hub is
//!   applied by every other hub within a second; the listener reconnects by itself.
//!
//! Connections are plain TCP or Unix sockets (`NoTls`): run the database on the hubs'
//! private network or a local socket; TLS to the database is not supported yet.

pub mod changes;
pub mod migrate;
mod scratch;

use std::sync::Arc;
use std::time::Duration;

use deadpool_postgres::{Manager, ManagerConfig, Pool, RecyclingMethod};

pub use changes::Change;
pub use deadpool_postgres::{Client, Transaction};
pub use scratch::{TEST_URL_ENV, scratch_database, scratch_database_url};
pub use tokio_postgres::Error as PgError;
pub use tokio_postgres::Row;
pub use tokio_postgres::types::ToSql;

/// How long opening a connection may take before the attempt counts as failed.
pub const CONNECT_TIMEOUT: Duration = Duration::from_secs(5);
/// Connections kept open at most: more than the blocking calls a 2-core hub runs at once
/// (logins, audit batches, parameter and delivery writes), few enough for a database
/// shared by many hubs.
pub const POOL_SIZE: usize = 16;

/// A database failure, with its cause and, where it helps, what to do.
#[derive(Debug, thiserror::Error)]
pub enum DbError {
    #[error(
        "{url:?} is not a PostgreSQL URL: {reason} (expected \
         postgres://USER[:PASSWORD]@HOST[:PORT]/DATABASE or postgresql://...)"
    )]
    BadUrl { url: String, reason: String },
    #[error("cannot start the database runtime: {0}")]
    Runtime(std::io::Error),
    #[error(
        "cannot reach PostgreSQL at {url}: {cause}. Check that the server is running and \
         accepts this user from this host (pg_hba.conf), or leave out --database to keep \
         the hub's state in SQLite under --data-dir"
    )]
    Unreachable { url: String, cause: String },
    /// No connection could be had for a statement while running (database down, pool
    /// exhausted); the pool tries again on the next call.
    #[error("PostgreSQL at {url} is unavailable: {cause}")]
    Unavailable { url: String, cause: String },
    #[error("PostgreSQL: {0}")]
    Sql(#[from] tokio_postgres::Error),
    #[error(
        "the database's {component} schema is at version {found}, newer than this fleetlink \
         knows ({known}): upgrade fleetlink on this host"
    )]
    SchemaTooNew {
        component: String,
        found: i32,
        known: usize,
    },
}

impl DbError {
    /// Whether the database could not be reached (as opposed to a statement failing).
    pub fn is_unavailable(&self) -> bool {
        match self {
            DbError::Unreachable { .. } | DbError::Unavailable { .. } => true,
            DbError::Sql(e) => e.is_closed(),
            _ => false,
        }
    }
}

/// A pooled connection to one PostgreSQL database. Cheap to clone; share one per process.
#[derive(Clone)]
pub struct Database {
    inner: Arc<Inner>,
}

struct Inner {
    /// Dropped with `shutdown_background` (see `Drop`), so a `Database` may be dropped
    /// anywhere, an async task included.
    runtime: Option<tokio::runtime::Runtime>,
    handle: tokio::runtime::Handle,
    pool: Pool,
    config: tokio_postgres::Config,
    /// The URL without its password, for messages.
    shown: String,
    changes: Arc<changes::Subscribers>,
}

impl Drop for Inner {
    fn drop(&mut self) {
        if let Some(rt) = self.runtime.take() {
            rt.shutdown_background();
        }
    }
}

impl Database {
    /// Connects to `url` (`postgres://` or `postgresql://`) and checks that the database
    /// answers, so a hub with a wrong URL stops at start with the reason instead of
    /// failing every login later. Blocks; call it from a blocking thread.
    pub fn connect(url: &str) -> Result<Database, DbError> {
        let shown = redact(url);
        let mut config = parse_url(url)?;
        config
            .connect_timeout(CONNECT_TIMEOUT)
            // A database host that vanishes without closing the socket is noticed in
            // about 25 s instead of the kernel's two hours.
            .keepalives(true)
            .keepalives_idle(Duration::from_secs(10))
            .keepalives_interval(Duration::from_secs(5))
            .keepalives_retries(3);
        if config.get_application_name().is_none() {
            config.application_name("fleetlink");
        }
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(1)
            .thread_name("fleetlink-db")
            .enable_all()
            .build()
            .map_err(DbError::Runtime)?;
        let manager = Manager::from_config(
            config.clone(),
            tokio_postgres::NoTls,
            ManagerConfig {
                // A connection whose socket closed (database restarted) is replaced at
                // checkout; one that is merely idle is reused without a round trip.
                recycling_method: RecyclingMethod::Fast,
            },
        );
        let pool = Pool::builder(manager)
            .max_size(POOL_SIZE)
            .runtime(deadpool_postgres::Runtime::Tokio1)
            .wait_timeout(Some(CONNECT_TIMEOUT))
            .create_timeout(Some(CONNECT_TIMEOUT))
            .recycle_timeout(Some(CONNECT_TIMEOUT))
            .build()
            .map_err(|e| DbError::BadUrl {
                url: shown.clone(),
                reason: e.to_string(),
            })?;
        let db = Database {
            inner: Arc::new(Inner {
                handle: runtime.handle().clone(),
                runtime: Some(runtime),
                pool,
                config,
                shown: shown.clone(),
                changes: Arc::default(),
            }),
        };
        db.run(async |c| Ok(c.simple_query("SELECT 1").await.map(|_| ())?))
            .map_err(|e| DbError::Unreachable {
                url: shown,
                cause: cause(&e),
            })?;
        Ok(db)
    }

    /// The URL without its password: safe to log and show.
    pub fn url(&self) -> &str {
        &self.inner.shown
    }

    /// Runs `f` with a pooled connection and waits for it on this thread.
    ///
    /// Must be called from a thread where blocking is allowed (a `spawn_blocking` task,
    /// inside `block_in_place`, or a thread of one's own); tokio panics when it is called
    /// from an async task, which is a bug in the caller.
    pub fn run<T>(&self, f: impl AsyncFnOnce(&Client) -> Result<T, DbError>) -> Result<T, DbError> {
        self.inner.handle.block_on(async {
            let client = self.checkout().await?;
            f(&client).await
        })
    }

    /// Like [`Database::run`] in one transaction, committed when `f` returns `Ok` and
    /// rolled back otherwise.
    pub fn transaction<T>(
        &self,
        f: impl AsyncFnOnce(&Transaction<'_>) -> Result<T, DbError>,
    ) -> Result<T, DbError> {
        self.inner.handle.block_on(async {
            let mut client = self.checkout().await?;
            let tx = client.transaction().await?;
            let out = f(&tx).await?;
            tx.commit().await?;
            Ok(out)
        })
    }

    /// One statement; the rows it changed.
    pub fn execute(&self, sql: &str, params: &[&(dyn ToSql + Sync)]) -> Result<u64, DbError> {
        self.run(async |c| {
            let st = c.prepare_cached(sql).await?;
            Ok(c.execute(&st, params).await?)
        })
    }

    /// One query; all its rows.
    pub fn query(&self, sql: &str, params: &[&(dyn ToSql + Sync)]) -> Result<Vec<Row>, DbError> {
        self.run(async |c| {
            let st = c.prepare_cached(sql).await?;
            Ok(c.query(&st, params).await?)
        })
    }

    /// One query expecting at most one row.
    pub fn query_opt(
        &self,
        sql: &str,
        params: &[&(dyn ToSql + Sync)],
    ) -> Result<Option<Row>, DbError> {
        self.run(async |c| {
            let st = c.prepare_cached(sql).await?;
            Ok(c.query_opt(&st, params).await?)
        })
    }

    async fn checkout(&self) -> Result<Client, DbError> {
        self.inner
            .pool
            .get()
            .await
            .map_err(|e| DbError::Unavailable {
                url: self.inner.shown.clone(),
                cause: pool_cause(e),
            })
    }
}

/// The text of `e` without the hint an `Unreachable` adds.
fn cause(e: &DbError) -> String {
    match e {
        DbError::Unavailable { cause, .. } => cause.clone(),
        other => other.to_string(),
    }
}

fn pool_cause(e: deadpool_postgres::PoolError) -> String {
    use deadpool_postgres::PoolError;
    match e {
        PoolError::Timeout(_) => format!(
            "no connection within {} s (the server is slow to accept, or all {POOL_SIZE} \
             connections are busy)",
            CONNECT_TIMEOUT.as_secs()
        ),
        PoolError::Backend(e) => {
            // tokio-postgres says "error connecting to server" and keeps the reason (the
            // refused connection, the failed password) in its source.
            match std::error::Error::source(&e) {
                Some(src) => format!("{e}: {src}"),
                None => e.to_string(),
            }
        }
        other => other.to_string(),
    }
}

/// Reads a database URL without connecting: `postgres://` or `postgresql://`, in the form
/// libpq accepts.
pub fn parse_url(url: &str) -> Result<tokio_postgres::Config, DbError> {
    let shown = redact(url);
    if !(url.starts_with("postgres://") || url.starts_with("postgresql://")) {
        return Err(DbError::BadUrl {
            url: shown,
            reason: "it does not start with postgres:// or postgresql://".to_owned(),
        });
    }
    url.parse().map_err(|e| DbError::BadUrl {
        url: shown,
        reason: format!("{e}"),
    })
}

/// `url` without the password (in the user part or a `password=` parameter).
pub fn redact(url: &str) -> String {
    let (base, query) = match url.split_once('?') {
        Some((b, q)) => (b, Some(q)),
        None => (url, None),
    };
    let mut out = match base.split_once("://") {
        Some((scheme, rest)) => {
            let (authority, path) = match rest.find('/') {
                Some(i) => rest.split_at(i),
                None => (rest, ""),
            };
            let authority = match authority.rsplit_once('@') {
                Some((userinfo, host)) => {
                    let user = userinfo.split_once(':').map_or(userinfo, |(u, _)| u);
                    format!("{user}@{host}")
                }
                None => authority.to_owned(),
            };
            format!("{scheme}://{authority}{path}")
        }
        None => base.to_owned(),
    };
    if let Some(q) = query {
        let kept: Vec<&str> = q
            .split('&')
            .filter(|kv| !kv.to_ascii_lowercase().starts_with("password="))
            .collect();
        if !kept.is_empty() {
            out.push('?');
            out.push_str(&kept.join("&"));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn redact_drops_every_password() {
        assert_eq!(
            redact("postgres://fleet:s3cr3t@db.example:5432/fleet"),
            "postgres://fleet@db.example:5432/fleet"
        );
        assert_eq!(
            redact("postgresql://fleet@db/fleet?password=x&sslmode=disable"),
            "postgresql://fleet@db/fleet?sslmode=disable"
        );
        assert_eq!(redact("postgres://db/fleet"), "postgres://db/fleet");
        assert_eq!(
            redact("postgres://u:p@h:1/d?PASSWORD=y"),
            "postgres://u@h:1/d"
        );
    }

    #[test]
    fn a_url_of_another_scheme_is_refused_with_the_expected_form() {
        let e = Database::connect("mysql://root:pw@localhost/x")
            .err()
            .expect("refused");
        let text = e.to_string();
        assert!(text.contains("postgres://USER"), "{text}");
        assert!(!text.contains("pw"), "password shown: {text}");
    }

    #[test]
    fn an_unreachable_server_is_named_without_its_password() {
        // Port 1 on loopback: nothing listens there, the connection is refused at once.
        let e = Database::connect("postgres://fleet:hunter2@127.0.0.1:1/fleet")
            .err()
            .expect("refused");
        assert!(matches!(e, DbError::Unreachable { .. }), "{e:?}");
        let text = e.to_string();
        assert!(
            text.contains("postgres://fleet@127.0.0.1:1/fleet"),
            "{text}"
        );
        assert!(!text.contains("hunter2"), "{text}");
        assert!(text.contains("--data-dir"), "says what to do: {text}");
    }
}
