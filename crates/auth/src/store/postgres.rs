//! The PostgreSQL backend of the security [`Store`]: the `auth_` and `audit_` tables in
//! the database several hubs share, and every rule, credential and audit statement the
//! store runs there.
//!
//! Design choice: each change notifies the other hubs in its own transaction
//! ([`fleetlink_postgres::changes`]): rules bump the revision and notify
//! [`Change::Rules`], credentials notify [`Change::Tokens`] / [`Change::Users`], so what a
//! hub keeps in memory follows at once.

use std::sync::Arc;

use fleetlink_postgres::Database;
use fleetlink_postgres::changes::{Change, notify};

use super::audit::{RawAudit, SCAN_BUDGET, page, size_column};
use super::credentials::{RawToken, TOKEN_COLUMNS};
use super::{Engine, Store, StoreError, TokenId};
use crate::UnixTime;
use crate::acl::RuleId;
use crate::audit::query::{AuditPage, AuditQuery};
use crate::audit::record::{AuditAction, AuditRecord};
use crate::identity::{RobotName, UserName};
use crate::token::{TokenHash, TokenKind};

/// The PostgreSQL schema, one entry per version (never edit one that shipped; add one).
const PG_MIGRATIONS: &[&str] = &["
    CREATE TABLE auth_meta (
        key TEXT PRIMARY KEY,
        value BIGINT NOT NULL
    );
    INSERT INTO auth_meta (key, value) VALUES ('rules_revision', 0);
    CREATE TABLE auth_rules (
        id BIGSERIAL PRIMARY KEY,
        rule_json TEXT NOT NULL,
        created_at BIGINT NOT NULL
    );
    CREATE TABLE auth_tokens (
        id BIGSERIAL PRIMARY KEY,
        hash BYTEA NOT NULL UNIQUE,
        kind TEXT NOT NULL,
        subject TEXT NOT NULL,
        groups_json TEXT NOT NULL DEFAULT '[]',
        created_at BIGINT NOT NULL,
        expires_at BIGINT,
        revoked_at BIGINT,
        last_used_at BIGINT
    );
    CREATE INDEX auth_tokens_subject ON auth_tokens (kind, subject);
    CREATE TABLE auth_users (
        name TEXT PRIMARY KEY,
        password_hash TEXT NOT NULL,
        groups_json TEXT NOT NULL DEFAULT '[]',
        created_at BIGINT NOT NULL
    );
    CREATE TABLE audit_log (
        id BIGSERIAL PRIMARY KEY,
        at BIGINT NOT NULL,
        principal TEXT NOT NULL,
        client_ip TEXT NOT NULL,
        action TEXT NOT NULL,
        name TEXT NOT NULL,
        size BIGINT,
        allowed BOOLEAN NOT NULL,
        detail TEXT
    );
    CREATE INDEX audit_log_at ON audit_log (at);
    CREATE INDEX audit_log_principal ON audit_log (principal, id);
"];

impl Store {
    /// The tables in a shared PostgreSQL database, created or brought up to date first
    /// (safe when several hubs start at once). Blocks: call it from a blocking thread.
    pub fn postgres(db: Database) -> Result<Store, StoreError> {
        db.migrate("auth", PG_MIGRATIONS)?;
        Ok(Store {
            engine: Arc::new(Postgres { db }),
        })
    }
}

struct Postgres {
    db: Database,
}

/// Bumps the rules revision, with the notification.
async fn bump_revision(
    tx: &fleetlink_postgres::Transaction<'_>,
) -> Result<(), fleetlink_postgres::DbError> {
    tx.execute(
        "UPDATE auth_meta SET value = value + 1 WHERE key = 'rules_revision'",
        &[],
    )
    .await?;
    notify(tx, Change::Rules).await
}

const INSERT_RULE: &str =
    "INSERT INTO auth_rules (rule_json, created_at) VALUES ($1, $2) RETURNING id";

fn raw_token(r: &fleetlink_postgres::Row) -> Result<RawToken, fleetlink_postgres::PgError> {
    Ok((
        r.try_get(0)?,
        r.try_get(1)?,
        r.try_get(2)?,
        r.try_get(3)?,
        r.try_get(4)?,
        r.try_get(5)?,
        r.try_get(6)?,
        r.try_get(7)?,
    ))
}

impl Postgres {
    /// One revoking `UPDATE` (`$1` the key, `$2` the time) that notifies the other hubs.
    fn revoke(
        &self,
        sql: &str,
        key: &(dyn fleetlink_postgres::ToSql + Sync),
        now: UnixTime,
    ) -> Result<u64, StoreError> {
        Ok(self.db.transaction(async |tx| {
            let n = tx.execute(sql, &[key, &now.0]).await?;
            if n > 0 {
                notify(tx, Change::Tokens).await?;
            }
            Ok(n)
        })?)
    }
}

impl Engine for Postgres {
    fn database(&self) -> Option<&Database> {
        Some(&self.db)
    }

    fn list_rules(&self) -> Result<Vec<(i64, String)>, StoreError> {
        Ok(self
            .db
            .query("SELECT id, rule_json FROM auth_rules ORDER BY id", &[])?
            .iter()
            .map(|r| Ok((r.try_get(0)?, r.try_get(1)?)))
            .collect::<Result<_, fleetlink_postgres::PgError>>()?)
    }

    fn add_rule(&self, json: &str, now: UnixTime) -> Result<i64, StoreError> {
        Ok(self.db.transaction(async |tx| {
            let id: i64 = tx
                .query_one(INSERT_RULE, &[&json, &now.0])
                .await?
                .try_get(0)?;
            bump_revision(tx).await?;
            Ok(id)
        })?)
    }

    fn remove_rule(&self, id: RuleId) -> Result<bool, StoreError> {
        Ok(self.db.transaction(async |tx| {
            let n = tx
                .execute("DELETE FROM auth_rules WHERE id = $1", &[&id.0])
                .await?;
            if n > 0 {
                bump_revision(tx).await?;
            }
            Ok(n > 0)
        })?)
    }

    fn replace_rules(&self, jsons: &[String], now: UnixTime) -> Result<Vec<i64>, StoreError> {
        Ok(self.db.transaction(async |tx| {
            tx.execute("DELETE FROM auth_rules", &[]).await?;
            let insert = tx.prepare_cached(INSERT_RULE).await?;
            let mut ids = Vec::with_capacity(jsons.len());
            for json in jsons {
                ids.push(tx.query_one(&insert, &[json, &now.0]).await?.try_get(0)?);
            }
            bump_revision(tx).await?;
            Ok(ids)
        })?)
    }

    fn rules_revision(&self) -> Result<Option<i64>, StoreError> {
        const SQL: &str = "SELECT value FROM auth_meta WHERE key = 'rules_revision'";
        Ok(self
            .db
            .query_opt(SQL, &[])?
            .map(|r| r.try_get(0))
            .transpose()?)
    }

    fn insert_token(
        &self,
        hash: &TokenHash,
        kind: TokenKind,
        subject: &str,
        groups: &str,
        expires_at: Option<i64>,
        now: UnixTime,
    ) -> Result<(), StoreError> {
        self.db.execute(
            "INSERT INTO auth_tokens (hash, kind, subject, groups_json, created_at, expires_at)
                     VALUES ($1, $2, $3, $4, $5, $6)",
            &[
                &hash.as_bytes(),
                &kind.as_str(),
                &subject,
                &groups,
                &now.0,
                &expires_at,
            ],
        )?;
        Ok(())
    }

    fn lookup_token(&self, hash: &TokenHash) -> Result<Option<RawToken>, StoreError> {
        Ok(self
            .db
            .query_opt(
                &format!("SELECT {TOKEN_COLUMNS} FROM auth_tokens WHERE hash = $1"),
                &[&hash.as_bytes()],
            )?
            .as_ref()
            .map(raw_token)
            .transpose()?)
    }

    fn touch_token(&self, id: TokenId, now: UnixTime) -> Result<(), StoreError> {
        // Written at every authentication, and only informative: the commit does
        // not wait for the server's disk (a crash of the database may lose the
        // newest `last_used_at`, never a credential). One round trip, as the
        // values are integers formatted here, not text from a client.
        let (id, now) = (id.0, now.0);
        self.db.run(async |c| {
            Ok(c.batch_execute(&format!(
                "BEGIN; SET LOCAL synchronous_commit = off;
                         UPDATE auth_tokens SET last_used_at = {now} WHERE id = {id}; COMMIT"
            ))
            .await?)
        })?;
        Ok(())
    }

    fn revoke_token(&self, id: TokenId, now: UnixTime) -> Result<u64, StoreError> {
        self.revoke(
            "UPDATE auth_tokens SET revoked_at = $2 WHERE id = $1 AND revoked_at IS NULL",
            &id.0,
            now,
        )
    }

    fn revoke_token_by_hash(&self, hash: &TokenHash, now: UnixTime) -> Result<u64, StoreError> {
        self.revoke(
            "UPDATE auth_tokens SET revoked_at = $2 WHERE hash = $1 AND revoked_at IS NULL",
            &hash.as_bytes(),
            now,
        )
    }

    fn revoke_robot_tokens(&self, robot: &RobotName, now: UnixTime) -> Result<usize, StoreError> {
        Ok(self.revoke(
            "UPDATE auth_tokens SET revoked_at = $2
                 WHERE kind = 'robot' AND subject = $1 AND revoked_at IS NULL",
            &robot.as_str(),
            now,
        )? as usize)
    }

    fn list_tokens(&self, kind: Option<&str>) -> Result<Vec<RawToken>, StoreError> {
        Ok(self
            .db
            .query(
                &format!(
                    "SELECT {TOKEN_COLUMNS} FROM auth_tokens
                         WHERE $1::TEXT IS NULL OR kind = $1 ORDER BY id DESC"
                ),
                &[&kind],
            )?
            .iter()
            .map(raw_token)
            .collect::<Result<Vec<_>, _>>()?)
    }

    fn add_user(
        &self,
        name: &UserName,
        hash: &str,
        groups: &str,
        now: UnixTime,
    ) -> Result<u64, StoreError> {
        Ok(self.db.transaction(async |tx| {
            let n = tx
                .execute(
                    "INSERT INTO auth_users (name, password_hash, groups_json, created_at)
                         VALUES ($1, $2, $3, $4) ON CONFLICT (name) DO NOTHING",
                    &[&name.as_str(), &hash, &groups, &now.0],
                )
                .await?;
            notify(tx, Change::Users).await?;
            Ok(n)
        })?)
    }

    fn set_password(&self, name: &UserName, hash: &str) -> Result<u64, StoreError> {
        Ok(self.db.transaction(async |tx| {
            let n = tx
                .execute(
                    "UPDATE auth_users SET password_hash = $2 WHERE name = $1",
                    &[&name.as_str(), &hash],
                )
                .await?;
            notify(tx, Change::Users).await?;
            Ok(n)
        })?)
    }

    fn remove_user(&self, name: &UserName, now: UnixTime) -> Result<bool, StoreError> {
        Ok(self.db.transaction(async |tx| {
            let n = tx
                .execute("DELETE FROM auth_users WHERE name = $1", &[&name.as_str()])
                .await?;
            tx.execute(
                "UPDATE auth_tokens SET revoked_at = $2
                     WHERE kind = 'session' AND subject = $1 AND revoked_at IS NULL",
                &[&name.as_str(), &now.0],
            )
            .await?;
            notify(tx, Change::Users).await?;
            notify(tx, Change::Tokens).await?;
            Ok(n > 0)
        })?)
    }

    fn user(&self, name: &UserName) -> Result<Option<(String, String)>, StoreError> {
        Ok(self
            .db
            .query_opt(
                "SELECT password_hash, groups_json FROM auth_users WHERE name = $1",
                &[&name.as_str()],
            )?
            .map(|r| Ok::<_, fleetlink_postgres::PgError>((r.try_get(0)?, r.try_get(1)?)))
            .transpose()?)
    }

    fn list_users(&self) -> Result<Vec<(String, String, i64)>, StoreError> {
        const SQL: &str = "SELECT name, groups_json, created_at FROM auth_users ORDER BY name";
        Ok(self
            .db
            .query(SQL, &[])?
            .iter()
            .map(|r| Ok((r.try_get(0)?, r.try_get(1)?, r.try_get(2)?)))
            .collect::<Result<_, fleetlink_postgres::PgError>>()?)
    }

    fn insert_audit_batch(&self, batch: &[AuditRecord]) -> Result<(), StoreError> {
        // One statement for the whole batch (columns as arrays), so a batch costs
        // one round trip to the server however many records it holds.
        let at: Vec<i64> = batch.iter().map(|r| r.at.0).collect();
        let principal: Vec<&str> = batch.iter().map(|r| r.principal.as_str()).collect();
        let ip: Vec<String> = batch.iter().map(|r| r.client_ip.to_string()).collect();
        let action: Vec<&str> = batch.iter().map(|r| r.action.as_str()).collect();
        let name: Vec<&str> = batch.iter().map(|r| r.name.as_str()).collect();
        let size: Vec<Option<i64>> = batch.iter().map(|r| r.size.map(size_column)).collect();
        let allowed: Vec<bool> = batch.iter().map(|r| r.allowed).collect();
        let detail: Vec<Option<&str>> = batch.iter().map(|r| r.detail.as_deref()).collect();
        self.db.execute(
            "INSERT INTO audit_log (at, principal, client_ip, action, name, size, allowed, detail)
                     SELECT * FROM UNNEST($1::BIGINT[], $2::TEXT[], $3::TEXT[], $4::TEXT[],
                                          $5::TEXT[], $6::BIGINT[], $7::BOOLEAN[], $8::TEXT[])",
            &[
                &at, &principal, &ip, &action, &name, &size, &allowed, &detail,
            ],
        )?;
        Ok(())
    }

    fn prune_audit(&self, before: UnixTime) -> Result<usize, StoreError> {
        Ok(self
            .db
            .execute("DELETE FROM audit_log WHERE at < $1", &[&before.0])? as usize)
    }

    fn query_audit(&self, q: &AuditQuery, limit: usize) -> Result<AuditPage, StoreError> {
        let fetch = if q.name_regex.is_some() {
            SCAN_BUDGET
        } else {
            limit + 1
        } as i64;
        let rows = self.db.query(
            "SELECT id, at, principal, client_ip, action, name, size, allowed, detail
                     FROM audit_log
                     WHERE ($1::BIGINT IS NULL OR id < $1)
                       AND ($2::TEXT IS NULL OR principal = $2)
                       AND ($3::TEXT IS NULL OR action = $3)
                       AND ($4::TEXT IS NULL OR starts_with(name, $4))
                       AND ($5::BOOLEAN IS NULL OR allowed = $5)
                       AND ($6::BIGINT IS NULL OR at >= $6)
                       AND ($7::BIGINT IS NULL OR at < $7)
                     ORDER BY id DESC
                     LIMIT $8",
            &[
                &q.after.map(|c| c.0),
                &q.principal,
                &q.action.map(AuditAction::as_str),
                &q.name_prefix,
                &q.allowed,
                &q.since.map(|t| t.0),
                &q.until.map(|t| t.0),
                &fetch,
            ],
        )?;
        let rows = rows.iter().map(|r| {
            Ok::<_, fleetlink_postgres::PgError>(RawAudit {
                id: r.try_get(0)?,
                at: r.try_get(1)?,
                principal: r.try_get(2)?,
                client_ip: r.try_get(3)?,
                action: r.try_get(4)?,
                name: r.try_get(5)?,
                size: r.try_get(6)?,
                allowed: r.try_get(7)?,
                detail: r.try_get(8)?,
            })
            .map_err(StoreError::from)
        });
        page(rows, q, limit)
    }

    #[cfg(test)]
    fn lock_for_test(&self) -> std::sync::MutexGuard<'_, rusqlite::Connection> {
        unreachable!("the audit stall test runs on SQLite")
    }
}
