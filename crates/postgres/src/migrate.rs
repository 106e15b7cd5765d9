//! Versioned schemas: each component (`auth`, `hub`) lists its migrations in order, and
//! [`Database::migrate`] applies those the database has not seen yet.
//!
//! Design choice: one table, `fleetlink_schema (component, version)`, records what was
//! applied; everything happens in one transaction that first takes a transaction-level
//! advisory lock, so two hubs starting together against a new database do not both
//! create the tables (PostgreSQL's `CREATE TABLE IF NOT EXISTS` is not safe against a
//! concurrent twin: the loser fails on a unique index of the catalog). The second hub
//! waits for the lock, then finds every version applied and does nothing.

use crate::{Database, DbError};

/// The advisory lock key: "fleetlnk" in ASCII, unlikely to meet another application's.
pub const MIGRATION_LOCK: i64 = 0x666c_6565_746c_6e6b;

impl Database {
    /// Applies `steps[v..]` of `component` where `v` is the version the database has
    /// (0 for none); step `i` brings the schema to version `i + 1`. Idempotent, and safe
    /// when several processes run it at once.
    pub fn migrate(&self, component: &str, steps: &[&str]) -> Result<(), DbError> {
        let applied = self.transaction(async |tx| {
            tx.execute("SELECT pg_advisory_xact_lock($1)", &[&MIGRATION_LOCK])
                .await?;
            // Checked first rather than `IF NOT EXISTS`, whose "already exists" notice
            // would be logged at every start.
            let exists: bool = tx
                .query_one("SELECT to_regclass('fleetlink_schema') IS NOT NULL", &[])
                .await?
                .try_get(0)?;
            if !exists {
                tx.batch_execute(
                    "CREATE TABLE fleetlink_schema (
                         component TEXT NOT NULL,
                         version INTEGER NOT NULL,
                         applied_at TIMESTAMPTZ NOT NULL DEFAULT now(),
                         PRIMARY KEY (component, version)
                     )",
                )
                .await?;
            }
            let found: i32 = tx
                .query_one(
                    "SELECT COALESCE(MAX(version), 0) FROM fleetlink_schema WHERE component = $1",
                    &[&component],
                )
                .await?
                .try_get(0)?;
            let done = usize::try_from(found).unwrap_or(0);
            if done > steps.len() {
                return Err(DbError::SchemaTooNew {
                    component: component.to_owned(),
                    found,
                    known: steps.len(),
                });
            }
            for (i, step) in steps.iter().enumerate().skip(done) {
                tx.batch_execute(step).await?;
                let version = i32::try_from(i + 1).unwrap_or(i32::MAX);
                tx.execute(
                    "INSERT INTO fleetlink_schema (component, version) VALUES ($1, $2)",
                    &[&component, &version],
                )
                .await?;
            }
            Ok(steps.len() - done)
        })?;
        if applied > 0 {
            tracing::info!(
                "database {}: {component} schema brought to version {} ({applied} step(s))",
                self.url(),
                steps.len()
            );
        }
        Ok(())
    }
}
