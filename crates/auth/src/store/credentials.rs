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
//! [`Change::Users`] on PostgreSQL, for whatever a hub keeps in memory about them. The
//! statements are in each backend's file (`sqlite.rs`, `postgres.rs`); here values become
//! columns and rows become values.
//!
//! [`Change::Tokens`]: fleetlink_postgres::changes::Change::Tokens
//! [`Change::Users`]: fleetlink_postgres::changes::Change::Users

use serde::Serialize;

use super::{Store, StoreError, corrupt};
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

/// The columns of a token row, in the order of [`RawToken`].
pub(super) const TOKEN_COLUMNS: &str =
    "id, kind, subject, groups_json, created_at, expires_at, revoked_at, last_used_at";

/// A token row as read, before [`token_info`] checks it.
pub(super) type RawToken = (
    i64,
    String,
    String,
    String,
    i64,
    Option<i64>,
    Option<i64>,
    Option<i64>,
);

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
        self.engine
            .insert_token(&token.hash(), kind, subject, &groups, expires_at, now)?;
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
        let raw = self.engine.lookup_token(hash)?;
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
        self.engine.touch_token(id, now)
    }

    /// Revokes one token by id; `false` if it did not exist or was already revoked.
    pub fn revoke_token(&self, id: TokenId, now: UnixTime) -> Result<bool, StoreError> {
        let n = self.engine.revoke_token(id, now)?;
        Ok(n > 0)
    }

    /// Revokes a token its holder presents (logout). `false` if unknown or already revoked.
    pub fn revoke_token_by_hash(
        &self,
        hash: &TokenHash,
        now: UnixTime,
    ) -> Result<bool, StoreError> {
        let n = self.engine.revoke_token_by_hash(hash, now)?;
        Ok(n > 0)
    }

    /// Revokes every live token of one robot; returns how many.
    pub fn revoke_robot_tokens(
        &self,
        robot: &RobotName,
        now: UnixTime,
    ) -> Result<usize, StoreError> {
        self.engine.revoke_robot_tokens(robot, now)
    }

    /// Tokens of one kind (or all), newest first, secrets never included.
    pub fn list_tokens(&self, kind: Option<TokenKind>) -> Result<Vec<TokenInfo>, StoreError> {
        let kind = kind.map(TokenKind::as_str);
        let raws = self.engine.list_tokens(kind)?;
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
        let n = self.engine.add_user(name, &hash, &groups, now)?;
        if n == 0 {
            return Err(StoreError::UserExists(name.to_string()));
        }
        Ok(())
    }

    pub fn set_password(&self, name: &UserName, password: &str) -> Result<(), StoreError> {
        let hash = password::hash(password).map_err(StoreError::PasswordHash)?;
        let n = self.engine.set_password(name, &hash)?;
        if n == 0 {
            return Err(StoreError::NoSuchUser(name.to_string()));
        }
        Ok(())
    }

    /// Removes a user and revokes their sessions; `false` if there was no such user.
    pub fn remove_user(&self, name: &UserName, now: UnixTime) -> Result<bool, StoreError> {
        self.engine.remove_user(name, now)
    }

    pub fn user(&self, name: &UserName) -> Result<Option<UserRecord>, StoreError> {
        let row = self.engine.user(name)?;
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
        let rows = self.engine.list_users()?;
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
