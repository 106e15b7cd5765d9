//! Databases for tests: one per test, on the server the suite started.

use crate::Database;

/// The variable naming the server the PostgreSQL variants of the tests use, e.g.
/// `postgres://fleetlink@127.0.0.1:5433/fleetlink` (tests/interop/postgres/run.sh sets it).
pub const TEST_URL_ENV: &str = "FLEETLINK_TEST_POSTGRES";

/// For tests: a new, empty database of its own on the server named by [`TEST_URL_ENV`],
/// so tests running in parallel never see each other's rows. Panics, saying how to run
/// these tests, when the variable is not set or the server cannot be reached.
pub fn scratch_database() -> Database {
    Database::connect(&scratch_database_url()).unwrap_or_else(|e| panic!("{e}"))
}

/// Like [`scratch_database`], but only creates the database and returns its URL, for
/// tests that connect to it more than once (two "hubs").
pub fn scratch_database_url() -> String {
    use std::sync::atomic::{AtomicU64, Ordering};
    static N: AtomicU64 = AtomicU64::new(0);
    let base = std::env::var(TEST_URL_ENV).unwrap_or_else(|_| {
        panic!(
            "{TEST_URL_ENV} is not set: the PostgreSQL variants of the tests need a server; \
             run tests/interop/postgres/run.sh, which starts one and runs them"
        )
    });
    let server = Database::connect(&base).unwrap_or_else(|e| panic!("{e}"));
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    let name = format!(
        "fleetlink_t{}_{nanos}_{}",
        std::process::id(),
        N.fetch_add(1, Ordering::Relaxed)
    );
    server
        .run(async |c| Ok(c.batch_execute(&format!("CREATE DATABASE {name}")).await?))
        .unwrap_or_else(|e| panic!("creating database {name}: {e}"));
    with_database(&base, &name)
}

/// `url` naming database `name` instead of its own.
fn with_database(url: &str, name: &str) -> String {
    let (base, query) = match url.split_once('?') {
        Some((b, q)) => (b, format!("?{q}")),
        None => (url, String::new()),
    };
    let start = base.find("://").map_or(0, |i| i + 3);
    let host_end = base[start..].find('/').map_or(base.len(), |i| start + i);
    format!("{}/{name}{query}", &base[..host_end])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scratch_url_names_the_new_database() {
        assert_eq!(
            with_database("postgres://u@h:5/fleet?sslmode=disable", "t1"),
            "postgres://u@h:5/t1?sslmode=disable"
        );
        assert_eq!(
            with_database("postgresql://u@h", "t2"),
            "postgresql://u@h/t2"
        );
    }
}
