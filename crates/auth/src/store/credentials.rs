//! Credential rows: robot and operator tokens, users, and login sessions.
//!
//! Design choice: all three token kinds share one table keyed by the token's SHA-256, so
//! authentication is one indexed lookup whatever the kind. Revocation and logout set
//! `revoked_at` instead of deleting, so a replayed token is recognised as *revoked*
//! (audited as such) rather than merely unknown.
//!
//! Nothing here is cached by a hub: every authentication reads the token (and a session's
//! user) from the database, so a revocation or a removed user applies on every hub sharing
//! the database with the next request. Changes still notify [`Change::Tokens`] /
//! [`Change::Users`] on PostgreSQL, for whatever a hub keeps in memory about them.

use fleetlink_postgres::changes::{Change, notify};
use rusqlite::{OptionalExtension, Row, params};
use serde::Serialize;

use super::{Backend, Store, StoreError, corrupt, with};
use crate::UnixTime;
use crate::authn::password;
use crate::identity::{GroupName, RobotName, UserName};
use crate::token::{Token, TokenHash, TokenKind};

/// A token's row id: how admins name a token they do not hold.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(transparent)]
pub struct TokenId(pub i64);

/// What the authenticator needs from a token row.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TokenRecord {
    pub id: TokenId,
    pub kind: TokenKind,
    /// Robot name for robot tokens, user name otherwise.
    pub subject: String,
    /// Groups carried by operator tokens (sessions take the user's current groups).
    pub groups: Vec<GroupName>,
    pub expires_at: Option<UnixTime>,
    pub revoked_at: Option<UnixTime>,
}

/// A token as listed to admins (never the secret).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct TokenInfo {
    pub id: TokenId,
    pub kind: &'static str,
    pub subject: String,
    pub groups: Vec<GroupName>,
    pub created_at: UnixTime,
    pub expires_at: Option<UnixTime>,
    pub revoked_at: Option<UnixTime>,
    pub last_used_at: Option<UnixTime>,
}

/// A user as the authenticator sees it.
#[derive(Debug, Clone)]
pub struct UserRecord {
    pub name: UserName,
    pub password_hash: String,
    pub groups: Vec<GroupName>,
}

/// A user as listed to admins.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct UserInfo {
    pub name: UserName,
    pub groups: Vec<GroupName>,
    pub created_at: UnixTime,
}

fn parse_groups(json: &str) -> Result<Vec<GroupName>, StoreError> {
    serde_json::from_str(json).map_err(corrupt("group list"))
}

fn groups_json(groups: &[GroupName]) -> Result<String, StoreError> {
    serde_json::to_string(groups).map_err(corrupt("group list"))
}

fn opt_time(v: Option<i64>) -> Option<UnixTime> {
    v.map(UnixTime)
}

const TOKEN_COLUMNS: &str =
    "id, kind, subject, groups_json, created_at, expires_at, revoked_at, last_used_at";

type RawToken = (
    i64,
    String,
    String,
    String,
    i64,
    Option<i64>,
    Option<i64>,
    Option<i64>,
);

fn pg_raw_token(r: &fleetlink_postgres::Row) -> Result<RawToken, fleetlink_postgres::PgError> {
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

fn raw_token(r: &Row<'_>) -> rusqlite::Result<RawToken> {
    Ok((
        r.get(0)?,
        r.get(1)?,
        r.get(2)?,
        r.get(3)?,
        r.get(4)?,
        r.get(5)?,
        r.get(6)?,
        r.get(7)?,
    ))
}

fn token_info(raw: RawToken) -> Result<(TokenKind, TokenInfo), StoreError> {
    let (id, kind, subject, groups, created, expires, revoked, used) = raw;
    let kind = TokenKind::parse(&kind).ok_or_else(|| StoreError::Corrupt {
        what: "token kind",
        reason: format!("unknown kind {kind:?}"),
    })?;
    let info = TokenInfo {
        id: TokenId(id),
        kind: kind.as_str(),
        subject,
        groups: parse_groups(&groups)?,
        created_at: UnixTime(created),
        expires_at: opt_time(expires),
        revoked_at: opt_time(revoked),
        last_used_at: opt_time(used),
    };
    Ok((kind, info))
}

impl Store {
    fn insert_token(
        &self,
        kind: TokenKind,
        subject: &str,
        groups: &[GroupName],
        expires_at: Option<UnixTime>,
        now: UnixTime,
    ) -> Result<Token, StoreError> {
        let token = Token::generate(kind)?;
        let groups = groups_json(groups)?;
        let expires_at = expires_at.map(|t| t.0);
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                c.execute(
                    "INSERT INTO auth_tokens (hash, kind, subject, groups_json, created_at, expires_at)
                     VALUES (?1, ?2, ?3, ?4, ?5, ?6)",
                    params![
                        token.hash().as_bytes(),
                        kind.as_str(),
                        subject,
                        groups,
                        now.0,
                        expires_at
                    ],
                )?;
                Ok(())
            })?,
            Backend::Postgres(db) => {
                db.execute(
                    "INSERT INTO auth_tokens (hash, kind, subject, groups_json, created_at, expires_at)
                     VALUES ($1, $2, $3, $4, $5, $6)",
                    &[
                        &token.hash().as_bytes(),
                        &kind.as_str(),
                        &subject,
                        &groups,
                        &now.0,
                        &expires_at,
                    ],
                )?;
            }
        }
        Ok(token)
    }

    /// Mints a robot token. The plain token is returned once and not stored.
    pub fn add_robot_token(
        &self,
        robot: &RobotName,
        expires_at: Option<UnixTime>,
        now: UnixTime,
    ) -> Result<Token, StoreError> {
        self.insert_token(TokenKind::Robot, robot.as_str(), &[], expires_at, now)
    }

    /// Mints an operator (API) token for `user` with `groups`; it needs no user row, so
    /// `fleetlink demo` can print one for user `operator` in group `admin`.
    pub fn mint_operator_token(
        &self,
        user: &UserName,
        groups: &[GroupName],
        expires_at: Option<UnixTime>,
        now: UnixTime,
    ) -> Result<Token, StoreError> {
        self.insert_token(TokenKind::Operator, user.as_str(), groups, expires_at, now)
    }

    /// Starts a login session for `user` (called by the authenticator after a password
    /// check).
    pub(crate) fn create_session(
        &self,
        user: &UserName,
        expires_at: UnixTime,
        now: UnixTime,
    ) -> Result<Token, StoreError> {
        self.insert_token(
            TokenKind::Session,
            user.as_str(),
            &[],
            Some(expires_at),
            now,
        )
    }

    /// Finds a token by hash, revoked and expired ones included (the caller decides).
    pub fn lookup_token(&self, hash: &TokenHash) -> Result<Option<TokenRecord>, StoreError> {
        let raw = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.query_row(
                    &format!("SELECT {TOKEN_COLUMNS} FROM auth_tokens WHERE hash = ?1"),
                    [hash.as_bytes()],
                    raw_token,
                )
                .optional()?)
            })?,
            Backend::Postgres(db) => db
                .query_opt(
                    &format!("SELECT {TOKEN_COLUMNS} FROM auth_tokens WHERE hash = $1"),
                    &[&hash.as_bytes()],
                )?
                .as_ref()
                .map(pg_raw_token)
                .transpose()?,
        };
        let Some(raw) = raw else { return Ok(None) };
        let (kind, info) = token_info(raw)?;
        Ok(Some(TokenRecord {
            id: info.id,
            kind,
            subject: info.subject,
            groups: info.groups,
            expires_at: info.expires_at,
            revoked_at: info.revoked_at,
        }))
    }

    pub(crate) fn touch_token(&self, id: TokenId, now: UnixTime) -> Result<(), StoreError> {
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                c.execute(
                    "UPDATE auth_tokens SET last_used_at = ?2 WHERE id = ?1",
                    params![id.0, now.0],
                )?;
                Ok(())
            }),
            Backend::Postgres(db) => {
                // Written at every authentication, and only informative: the commit does
                // not wait for the server's disk (a crash of the database may lose the
                // newest `last_used_at`, never a credential). One round trip, as the
                // values are integers formatted here, not text from a client.
                let (id, now) = (id.0, now.0);
                db.run(async |c| {
                    Ok(c.batch_execute(&format!(
                        "BEGIN; SET LOCAL synchronous_commit = off;
                         UPDATE auth_tokens SET last_used_at = {now} WHERE id = {id}; COMMIT"
                    ))
                    .await?)
                })?;
                Ok(())
            }
        }
    }

    /// Revokes one token by id; `false` if it did not exist or was already revoked.
    pub fn revoke_token(&self, id: TokenId, now: UnixTime) -> Result<bool, StoreError> {
        let n = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.execute(
                    "UPDATE auth_tokens SET revoked_at = ?2 WHERE id = ?1 AND revoked_at IS NULL",
                    params![id.0, now.0],
                )? as u64)
            })?,
            Backend::Postgres(_) => self.pg_revoke(
                "UPDATE auth_tokens SET revoked_at = $2 WHERE id = $1 AND revoked_at IS NULL",
                &id.0,
                now,
            )?,
        };
        Ok(n > 0)
    }

    /// Revokes a token its holder presents (logout). `false` if unknown or already revoked.
    pub fn revoke_token_by_hash(
        &self,
        hash: &TokenHash,
        now: UnixTime,
    ) -> Result<bool, StoreError> {
        let n = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.execute(
                    "UPDATE auth_tokens SET revoked_at = ?2 WHERE hash = ?1 AND revoked_at IS NULL",
                    params![hash.as_bytes(), now.0],
                )? as u64)
            })?,
            Backend::Postgres(_) => self.pg_revoke(
                "UPDATE auth_tokens SET revoked_at = $2 WHERE hash = $1 AND revoked_at IS NULL",
                &hash.as_bytes(),
                now,
            )?,
        };
        Ok(n > 0)
    }

    /// Revokes every live token of one robot; returns how many.
    pub fn revoke_robot_tokens(
        &self,
        robot: &RobotName,
        now: UnixTime,
    ) -> Result<usize, StoreError> {
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.execute(
                    "UPDATE auth_tokens SET revoked_at = ?2
                     WHERE kind = 'robot' AND subject = ?1 AND revoked_at IS NULL",
                    params![robot.as_str(), now.0],
                )?)
            }),
            Backend::Postgres(_) => Ok(self.pg_revoke(
                "UPDATE auth_tokens SET revoked_at = $2
                 WHERE kind = 'robot' AND subject = $1 AND revoked_at IS NULL",
                &robot.as_str(),
                now,
            )? as usize),
        }
    }

    /// One revoking `UPDATE` (`$1` the key, `$2` the time) that notifies the other hubs.
    fn pg_revoke(
        &self,
        sql: &str,
        key: &(dyn fleetlink_postgres::ToSql + Sync),
        now: UnixTime,
    ) -> Result<u64, StoreError> {
        let Backend::Postgres(db) = self.backend() else {
            unreachable!("called on the PostgreSQL backend only")
        };
        Ok(db.transaction(async |tx| {
            let n = tx.execute(sql, &[key, &now.0]).await?;
            if n > 0 {
                notify(tx, Change::Tokens).await?;
            }
            Ok(n)
        })?)
    }

    /// Tokens of one kind (or all), newest first, secrets never included.
    pub fn list_tokens(&self, kind: Option<TokenKind>) -> Result<Vec<TokenInfo>, StoreError> {
        let kind = kind.map(TokenKind::as_str);
        let raws = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                let mut stmt = c.prepare(&format!(
                    "SELECT {TOKEN_COLUMNS} FROM auth_tokens
                     WHERE ?1 IS NULL OR kind = ?1 ORDER BY id DESC"
                ))?;
                let rows = stmt.query_map([kind], raw_token)?;
                Ok(rows.collect::<rusqlite::Result<Vec<_>>>()?)
            })?,
            Backend::Postgres(db) => db
                .query(
                    &format!(
                        "SELECT {TOKEN_COLUMNS} FROM auth_tokens
                         WHERE $1::TEXT IS NULL OR kind = $1 ORDER BY id DESC"
                    ),
                    &[&kind],
                )?
                .iter()
                .map(pg_raw_token)
                .collect::<Result<Vec<_>, _>>()?,
        };
        raws.into_iter()
            .map(|raw| token_info(raw).map(|(_, info)| info))
            .collect()
    }

    /// Login sessions that are neither revoked nor expired at `now`.
    pub fn list_sessions(&self, now: UnixTime) -> Result<Vec<TokenInfo>, StoreError> {
        Ok(self
            .list_tokens(Some(TokenKind::Session))?
            .into_iter()
            .filter(|t| t.revoked_at.is_none() && t.expires_at.is_none_or(|e| e > now))
            .collect())
    }

    /// Adds a user with an argon2id-hashed password. Hashing takes tens of milliseconds
    /// of CPU on purpose.
    pub fn add_user(
        &self,
        name: &UserName,
        password: &str,
        groups: &[GroupName],
        now: UnixTime,
    ) -> Result<(), StoreError> {
        let hash = password::hash(password).map_err(StoreError::PasswordHash)?;
        let groups = groups_json(groups)?;
        let n = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.execute(
                    "INSERT OR IGNORE INTO auth_users (name, password_hash, groups_json, created_at)
                     VALUES (?1, ?2, ?3, ?4)",
                    params![name.as_str(), hash, groups, now.0],
                )? as u64)
            })?,
            Backend::Postgres(db) => db.transaction(async |tx| {
                let n = tx
                    .execute(
                        "INSERT INTO auth_users (name, password_hash, groups_json, created_at)
                         VALUES ($1, $2, $3, $4) ON CONFLICT (name) DO NOTHING",
                        &[&name.as_str(), &hash, &groups, &now.0],
                    )
                    .await?;
                notify(tx, Change::Users).await?;
                Ok(n)
            })?,
        };
        if n == 0 {
            return Err(StoreError::UserExists(name.to_string()));
        }
        Ok(())
    }

    pub fn set_password(&self, name: &UserName, password: &str) -> Result<(), StoreError> {
        let hash = password::hash(password).map_err(StoreError::PasswordHash)?;
        let n = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.execute(
                    "UPDATE auth_users SET password_hash = ?2 WHERE name = ?1",
                    params![name.as_str(), hash],
                )? as u64)
            })?,
            Backend::Postgres(db) => db.transaction(async |tx| {
                let n = tx
                    .execute(
                        "UPDATE auth_users SET password_hash = $2 WHERE name = $1",
                        &[&name.as_str(), &hash],
                    )
                    .await?;
                notify(tx, Change::Users).await?;
                Ok(n)
            })?,
        };
        if n == 0 {
            return Err(StoreError::NoSuchUser(name.to_string()));
        }
        Ok(())
    }

    /// Removes a user and revokes their sessions; `false` if there was no such user.
    pub fn remove_user(&self, name: &UserName, now: UnixTime) -> Result<bool, StoreError> {
        match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                let tx = c.transaction()?;
                let n = tx.execute("DELETE FROM auth_users WHERE name = ?1", [name.as_str()])?;
                tx.execute(
                    "UPDATE auth_tokens SET revoked_at = ?2
                     WHERE kind = 'session' AND subject = ?1 AND revoked_at IS NULL",
                    params![name.as_str(), now.0],
                )?;
                tx.commit()?;
                Ok(n > 0)
            }),
            Backend::Postgres(db) => Ok(db.transaction(async |tx| {
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
            })?),
        }
    }

    pub fn user(&self, name: &UserName) -> Result<Option<UserRecord>, StoreError> {
        let row: Option<(String, String)> = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                Ok(c.query_row(
                    "SELECT password_hash, groups_json FROM auth_users WHERE name = ?1",
                    [name.as_str()],
                    |r| Ok((r.get(0)?, r.get(1)?)),
                )
                .optional()?)
            })?,
            Backend::Postgres(db) => db
                .query_opt(
                    "SELECT password_hash, groups_json FROM auth_users WHERE name = $1",
                    &[&name.as_str()],
                )?
                .map(|r| Ok::<_, fleetlink_postgres::PgError>((r.try_get(0)?, r.try_get(1)?)))
                .transpose()?,
        };
        row.map(|(password_hash, groups)| {
            Ok(UserRecord {
                name: name.clone(),
                password_hash,
                groups: parse_groups(&groups)?,
            })
        })
        .transpose()
    }

    pub fn list_users(&self) -> Result<Vec<UserInfo>, StoreError> {
        const SQL: &str = "SELECT name, groups_json, created_at FROM auth_users ORDER BY name";
        let rows: Vec<(String, String, i64)> = match self.backend() {
            Backend::Sqlite(c) => with(c, |c| {
                let mut stmt = c.prepare(SQL)?;
                let rows = stmt.query_map([], |r| Ok((r.get(0)?, r.get(1)?, r.get(2)?)))?;
                Ok(rows.collect::<rusqlite::Result<Vec<_>>>()?)
            })?,
            Backend::Postgres(db) => db
                .query(SQL, &[])?
                .iter()
                .map(|r| Ok((r.try_get(0)?, r.try_get(1)?, r.try_get(2)?)))
                .collect::<Result<_, fleetlink_postgres::PgError>>()?,
        };
        rows.into_iter()
            .map(|(name, groups, created)| {
                Ok(UserInfo {
                    name: UserName::new(&name).map_err(|e| StoreError::Corrupt {
                        what: "user name",
                        reason: e.to_string(),
                    })?,
                    groups: parse_groups(&groups)?,
                    created_at: UnixTime(created),
                })
            })
            .collect()
    }
}
