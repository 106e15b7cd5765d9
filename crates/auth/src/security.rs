//! [`Security`]: the one handle the hub keeps, holding store, authenticator, authorizer
//! and audit log in step.
//!
//! Design choice: every administrative change goes through here, so "persist, recompile
//! the rules, write the audit record" cannot be half done by a REST handler or CLI that
//! forgets a step. The parts stay public for the hot path (`authz` for [`Access`],
//! `audit` for operation records).
//!
//! With the store in PostgreSQL, changes made through another hub arrive as notifications
//! ([`fleetlink_postgres::changes`]); a thread of the security core (`fleetlink-auth-sync`)
//! reloads what they name, so a rule changed anywhere applies here within a second. What
//! the authorizer caches (each connection's [`Access`], the hub's per-topic decisions) is
//! keyed by the rules' generation, which a reload moves on, so no stale decision survives
//! it. Tokens and users are not cached: every authentication reads them.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, TrySendError, sync_channel};
use std::sync::{Arc, Mutex, Weak};

use fleetlink_postgres::Change;

use crate::UnixTime;
use crate::acl::{Access, AclDefaults, Authorizer, Rule, RuleId, import_yaml};
use crate::audit::{AuditAction, AuditLog, AuditRecord};
use crate::authn::{AuthError, AuthPolicy, Authenticator, Credential, Session};
use crate::identity::{ConnInfo, GroupName, Identity, RobotName, UserName};
use crate::store::{Store, StoreError, TokenId};
use crate::token::Token;

/// Start-up or an administrative change failed.
#[derive(Debug, thiserror::Error)]
pub enum SecurityError {
    #[error("cannot start the audit writer thread: {0}")]
    AuditWriter(std::io::Error),
    #[error("cannot start the thread applying changes from other hubs: {0}")]
    SyncThread(std::io::Error),
    #[error(transparent)]
    Store(#[from] StoreError),
    #[error(transparent)]
    Import(#[from] crate::acl::AclImportError),
}

/// Store, authenticator, authorizer and audit log, wired together.
pub struct Security {
    pub store: Store,
    pub authn: Arc<Authenticator>,
    pub authz: Arc<Authorizer>,
    pub audit: AuditLog,
    rules: Arc<RuleLoader>,
}

/// Loads the authorizer's rules from the store, one load at a time.
struct RuleLoader {
    store: Store,
    authz: Arc<Authorizer>,
    /// The store's rule revision the authorizer was last loaded from.
    loaded_revision: AtomicU64,
    /// Counted per change kind received from other processes: rules, tokens, users,
    /// everything (after the listener reconnected).
    received: [AtomicU64; 4],
    // std Mutex: serialises loads (admin edits, the notification thread, the hub's
    // periodic check) so an older read never replaces a newer one; held across two short
    // blocking store reads on a blocking thread, never across an await.
    loading: Mutex<()>,
}

impl RuleLoader {
    /// Recompiles the rules from the store and remembers the revision.
    fn reload(&self) -> Result<(), StoreError> {
        let _one = self.loading.lock().unwrap_or_else(|p| p.into_inner());
        let revision = self.store.rules_revision()?;
        self.authz.replace_rules(self.store.list_rules()?);
        self.loaded_revision.store(revision, Ordering::Release);
        Ok(())
    }

    fn reload_if_changed(&self) -> Result<bool, StoreError> {
        if self.store.rules_revision()? == self.loaded_revision.load(Ordering::Acquire) {
            return Ok(false);
        }
        self.reload()?;
        Ok(true)
    }
}

/// Notifications waiting for the sync thread at most; more are dropped, since one reload
/// covers any number of them.
const CHANGES_QUEUED: usize = 64;

/// Subscribes to the shared database's changes and starts the thread that applies them.
fn follow_changes(
    db: &fleetlink_postgres::Database,
    rules: &Arc<RuleLoader>,
) -> std::io::Result<()> {
    let (tx, rx) = sync_channel::<Change>(CHANGES_QUEUED);
    let weak = Arc::downgrade(rules);
    std::thread::Builder::new()
        .name("fleetlink-auth-sync".to_owned())
        .spawn(move || apply_changes(rx, weak))?;
    db.on_change(move |change| match tx.try_send(change) {
        Ok(()) | Err(TrySendError::Full(_)) => true,
        // The security core is gone: unsubscribe.
        Err(TrySendError::Disconnected(_)) => false,
    });
    Ok(())
}

fn apply_changes(rx: Receiver<Change>, rules: Weak<RuleLoader>) {
    while let Ok(change) = rx.recv() {
        let Some(rules) = rules.upgrade() else { return };
        let slot = match change {
            Change::Rules => 0,
            Change::Tokens => 1,
            Change::Users => 2,
            Change::Everything => 3,
            Change::Params => continue,
        };
        rules.received[slot].fetch_add(1, Ordering::Relaxed);
        let result = match change {
            // Notifications may have been missed: load whatever the revision says.
            Change::Everything => rules.reload(),
            Change::Rules => rules.reload_if_changed().map(|_| ()),
            // Read at every authentication, nothing to reload.
            _ => Ok(()),
        };
        if let Err(e) = result {
            tracing::warn!("cannot reload access rules after a change elsewhere: {e}");
        }
    }
}

/// Audit channel size: a few seconds of commands at fleet scale.
pub const AUDIT_CAPACITY: usize = 65_536;

impl Security {
    /// Loads the rules from `store` and starts the audit writer.
    pub fn new(
        store: Store,
        policy: AuthPolicy,
        defaults: AclDefaults,
    ) -> Result<Security, SecurityError> {
        let revision = store.rules_revision()?;
        let authz = Arc::new(Authorizer::new(store.list_rules()?, defaults));
        let audit =
            AuditLog::start(store.clone(), AUDIT_CAPACITY).map_err(SecurityError::AuditWriter)?;
        let rules = Arc::new(RuleLoader {
            store: store.clone(),
            authz: authz.clone(),
            loaded_revision: AtomicU64::new(revision),
            received: Default::default(),
            loading: Mutex::new(()),
        });
        if let Some(db) = store.database() {
            follow_changes(db, &rules).map_err(SecurityError::SyncThread)?;
        }
        Ok(Security {
            authn: Arc::new(Authenticator::new(store.clone(), policy)),
            store,
            authz,
            audit,
            rules,
        })
    }

    /// Change notifications received from the shared database, by kind: `rules`,
    /// `tokens`, `users`, `everything` (the listener reconnected). All zero with SQLite.
    pub fn changes_received(&self) -> [(&'static str, u64); 4] {
        let n = |i: usize| self.rules.received[i].load(Ordering::Relaxed);
        [
            ("rules", n(0)),
            ("tokens", n(1)),
            ("users", n(2)),
            ("everything", n(3)),
        ]
    }

    /// Authenticates and, on failure, records an `auth_failure` audit entry.
    pub fn authenticate(
        &self,
        credential: Credential,
        peer: ConnInfo,
        now: UnixTime,
    ) -> Result<Identity, AuthError> {
        let claimed = match &credential {
            Credential::Password { user, .. } => Some(format!("claimed-user:{user}")),
            Credential::Agent { robot, .. } => Some(format!("claimed-robot:{robot}")),
            Credential::Bearer(_) | Credential::None => None,
        };
        let client_ip = self.authn.policy().trusted_proxies.client_ip(&peer);
        self.authn
            .authenticate(credential, peer, now)
            .inspect_err(|e| {
                self.audit.record(AuditRecord::auth_failure(
                    client_ip,
                    claimed.as_deref(),
                    e,
                    now,
                ));
            })
    }

    /// A decision cache for a freshly authenticated connection.
    pub fn access(&self, identity: Identity) -> Access {
        self.authz.access(identity)
    }

    pub fn login(
        &self,
        user: &str,
        password: &str,
        peer: ConnInfo,
        now: UnixTime,
    ) -> Result<Session, AuthError> {
        let client_ip = self.authn.policy().trusted_proxies.client_ip(&peer);
        match self.authn.login(user, password, peer, now) {
            Ok(session) => {
                self.audit.record(AuditRecord::operation(
                    &session.identity,
                    AuditAction::Login,
                    "",
                    None,
                    true,
                    now,
                ));
                Ok(session)
            }
            Err(e) => {
                let claimed = format!("claimed-user:{user}");
                self.audit.record(AuditRecord::auth_failure(
                    client_ip,
                    Some(&claimed),
                    &e,
                    now,
                ));
                Err(e)
            }
        }
    }

    pub fn logout(&self, identity: &Identity, token: &str, now: UnixTime) -> Result<(), AuthError> {
        let result = self.authn.logout(token, now);
        self.audit.record(AuditRecord::operation(
            identity,
            AuditAction::Logout,
            "",
            None,
            result.is_ok(),
            now,
        ));
        result
    }

    fn audit_change(
        &self,
        actor: &Identity,
        action: AuditAction,
        name: String,
        detail: String,
        now: UnixTime,
    ) {
        self.audit.record(
            AuditRecord::operation(actor, action, &name, None, true, now).with_detail(detail),
        );
    }

    fn reload(&self) -> Result<(), StoreError> {
        self.rules.reload()
    }

    /// Picks up rule edits made by another process on the same database (the CLI, or
    /// another hub when notifications are lost). Cheap: one indexed read when nothing
    /// changed; call it every second or so.
    pub fn reload_rules_if_changed(&self) -> Result<bool, StoreError> {
        self.rules.reload_if_changed()
    }

    pub fn add_rule(
        &self,
        actor: &Identity,
        rule: Rule,
        now: UnixTime,
    ) -> Result<RuleId, SecurityError> {
        let id = self.store.add_rule(&rule, now)?;
        self.reload()?;
        let detail = serde_json::to_string(&rule).unwrap_or_default();
        self.audit_change(
            actor,
            AuditAction::RuleChange,
            format!("add rule {id}"),
            detail,
            now,
        );
        Ok(id)
    }

    pub fn remove_rule(
        &self,
        actor: &Identity,
        id: RuleId,
        now: UnixTime,
    ) -> Result<bool, SecurityError> {
        let removed = self.store.remove_rule(id)?;
        if removed {
            self.reload()?;
            self.audit_change(
                actor,
                AuditAction::RuleChange,
                format!("remove rule {id}"),
                String::new(),
                now,
            );
        }
        Ok(removed)
    }

    /// Replaces every rule with those of a YAML document (see [`crate::acl`]).
    pub fn import_rules_yaml(
        &self,
        actor: &Identity,
        yaml: &str,
        now: UnixTime,
    ) -> Result<usize, SecurityError> {
        let rules = import_yaml(yaml)?;
        self.replace_rules(actor, rules, now)
    }

    pub fn replace_rules(
        &self,
        actor: &Identity,
        rules: Vec<Rule>,
        now: UnixTime,
    ) -> Result<usize, SecurityError> {
        let stored = self.store.replace_rules(&rules, now)?;
        self.reload()?;
        self.audit_change(
            actor,
            AuditAction::RuleChange,
            "replace rules".to_owned(),
            format!("{} rules", stored.len()),
            now,
        );
        Ok(stored.len())
    }

    pub fn add_robot_token(
        &self,
        actor: &Identity,
        robot: &RobotName,
        expires_at: Option<UnixTime>,
        now: UnixTime,
    ) -> Result<Token, SecurityError> {
        let token = self.store.add_robot_token(robot, expires_at, now)?;
        self.audit_change(
            actor,
            AuditAction::CredentialChange,
            format!("robot token for {robot}"),
            token.hash().label(),
            now,
        );
        Ok(token)
    }

    pub fn mint_operator_token(
        &self,
        actor: &Identity,
        user: &UserName,
        groups: &[GroupName],
        expires_at: Option<UnixTime>,
        now: UnixTime,
    ) -> Result<Token, SecurityError> {
        let token = self
            .store
            .mint_operator_token(user, groups, expires_at, now)?;
        self.audit_change(
            actor,
            AuditAction::CredentialChange,
            format!("operator token for {user}"),
            token.hash().label(),
            now,
        );
        Ok(token)
    }

    pub fn revoke_token(
        &self,
        actor: &Identity,
        id: TokenId,
        now: UnixTime,
    ) -> Result<bool, SecurityError> {
        let revoked = self.store.revoke_token(id, now)?;
        if revoked {
            self.audit_change(
                actor,
                AuditAction::CredentialChange,
                format!("revoke token #{}", id.0),
                String::new(),
                now,
            );
        }
        Ok(revoked)
    }

    pub fn add_user(
        &self,
        actor: &Identity,
        user: &UserName,
        password: &str,
        groups: &[GroupName],
        now: UnixTime,
    ) -> Result<(), SecurityError> {
        self.store.add_user(user, password, groups, now)?;
        self.audit_change(
            actor,
            AuditAction::CredentialChange,
            format!("add user {user}"),
            String::new(),
            now,
        );
        Ok(())
    }

    pub fn remove_user(
        &self,
        actor: &Identity,
        user: &UserName,
        now: UnixTime,
    ) -> Result<bool, SecurityError> {
        let removed = self.store.remove_user(user, now)?;
        if removed {
            self.audit_change(
                actor,
                AuditAction::CredentialChange,
                format!("remove user {user}"),
                String::new(),
                now,
            );
        }
        Ok(removed)
    }
}
