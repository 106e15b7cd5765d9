//! ACL rule rows: list, add, remove, replace, and the revision counter.
//!
//! Rules are stored as JSON of [`Rule`], so a new rule field needs no migration; each is
//! re-validated (patterns compiled) when read back. Every change bumps the revision in its
//! transaction (and, on PostgreSQL, notifies the other hubs when it commits).

use fleetlink_postgres::changes::{Change, notify};
use rusqlite::{OptionalExtension, params};

use super::{Backend, Store, StoreError, corrupt, with};
use crate::UnixTime;
use crate::acl::{Rule, RuleId, StoredRule};

fn bump_revision(tx: &rusqlite::Transaction<'_>) -> rusqlite::Result<()> {
    tx.execute(
        "UPDATE auth_meta SET value = value + 1 WHERE key = 'rules_revision'",
        [],
    )?;
    Ok(())
}

/// The PostgreSQL twin of [`bump_revision`], with the notification.
async fn pg_bump_revision(
    tx: &fleetlink_postgres::Transaction<'_>,
) -> Result<(), fleetlink_postgres::DbError> {
    tx.execute(
        "UPDATE auth_meta SET value = value + 1 WHERE key = 'rules_revision'",
        &[],
    )
    .await?;
    notify(tx, Change::Rules).await
}

const PG_INSERT: &str =
    "INSERT INTO auth_rules (rule_json, created_at) VALUES ($1, $2) RETURNING id";

impl Store {
    pub fn list_rules(&self) -> Result<Vec<StoredRule>, StoreError> {
        let rows: Vec<(i64, String)> = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                let mut stmt = c.prepare("SELECT id, rule_json FROM auth_rules ORDER BY id")?;
                let rows = stmt.query_map([], |r| Ok((r.get(0)?, r.get(1)?)))?;
                Ok(rows.collect::<rusqlite::Result<_>>()?)
            })?,
            Backend::Postgres(db) => db
                .query("SELECT id, rule_json FROM auth_rules ORDER BY id", &[])?
                .iter()
                .map(|r| Ok((r.try_get(0)?, r.try_get(1)?)))
                .collect::<Result<_, fleetlink_postgres::PgError>>()?,
        };
        rows.into_iter()
            .map(|(id, json)| {
                let rule: Rule = serde_json::from_str(&json).map_err(corrupt("ACL rule"))?;
                Ok(StoredRule {
                    id: RuleId(id),
                    rule,
                })
            })
            .collect()
    }

    pub fn add_rule(&self, rule: &Rule, now: UnixTime) -> Result<RuleId, StoreError> {
        let json = serde_json::to_string(rule).map_err(corrupt("ACL rule"))?;
        let id = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                let tx = c.transaction()?;
                tx.execute(
                    "INSERT INTO auth_rules (rule_json, created_at) VALUES (?1, ?2)",
                    params![json, now.0],
                )?;
                let id = tx.last_insert_rowid();
                bump_revision(&tx)?;
                tx.commit()?;
                Ok(id)
            })?,
            Backend::Postgres(db) => db.transaction(async |tx| {
                let id: i64 = tx
                    .query_one(PG_INSERT, &[&json, &now.0])
                    .await?
                    .try_get(0)?;
                pg_bump_revision(tx).await?;
                Ok(id)
            })?,
        };
        Ok(RuleId(id))
    }

    /// Removes a rule; `false` if there was none with that id.
    pub fn remove_rule(&self, id: RuleId) -> Result<bool, StoreError> {
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                let tx = c.transaction()?;
                let n = tx.execute("DELETE FROM auth_rules WHERE id = ?1", [id.0])?;
                if n > 0 {
                    bump_revision(&tx)?;
                }
                tx.commit()?;
                Ok(n > 0)
            }),
            Backend::Postgres(db) => Ok(db.transaction(async |tx| {
                let n = tx
                    .execute("DELETE FROM auth_rules WHERE id = $1", &[&id.0])
                    .await?;
                if n > 0 {
                    pg_bump_revision(tx).await?;
                }
                Ok(n > 0)
            })?),
        }
    }

    /// Replaces all rules at once (a YAML import), atomically.
    pub fn replace_rules(
        &self,
        rules: &[Rule],
        now: UnixTime,
    ) -> Result<Vec<StoredRule>, StoreError> {
        let jsons = rules
            .iter()
            .map(serde_json::to_string)
            .collect::<Result<Vec<_>, _>>()
            .map_err(corrupt("ACL rule"))?;
        let ids: Vec<i64> = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                let tx = c.transaction()?;
                tx.execute("DELETE FROM auth_rules", [])?;
                let mut ids = Vec::with_capacity(rules.len());
                for json in &jsons {
                    tx.execute(
                        "INSERT INTO auth_rules (rule_json, created_at) VALUES (?1, ?2)",
                        params![json, now.0],
                    )?;
                    ids.push(tx.last_insert_rowid());
                }
                bump_revision(&tx)?;
                tx.commit()?;
                Ok(ids)
            })?,
            Backend::Postgres(db) => db.transaction(async |tx| {
                tx.execute("DELETE FROM auth_rules", &[]).await?;
                let insert = tx.prepare_cached(PG_INSERT).await?;
                let mut ids = Vec::with_capacity(rules.len());
                for json in &jsons {
                    ids.push(tx.query_one(&insert, &[json, &now.0]).await?.try_get(0)?);
                }
                pg_bump_revision(tx).await?;
                Ok(ids)
            })?,
        };
        Ok(rules
            .iter()
            .zip(ids)
            .map(|(rule, id)| StoredRule {
                id: RuleId(id),
                rule: rule.clone(),
            })
            .collect())
    }

    /// Increases on every rule change, by any process using this database.
    pub fn rules_revision(&self) -> Result<u64, StoreError> {
        const SQL: &str = "SELECT value FROM auth_meta WHERE key = 'rules_revision'";
        let v: Option<i64> = match self.backend() {
            Backend::Sqlite(c) => {
                with(c, |c| Ok(c.query_row(SQL, [], |r| r.get(0)).optional()?))?
            }
            Backend::Postgres(db) => db.query_opt(SQL, &[])?.map(|r| r.try_get(0)).transpose()?,
        };
        Ok(v.unwrap_or(0).max(0) as u64)
    }
}
