//! What one audit entry holds: the action ([`AuditAction`]) and the record
//! ([`AuditRecord`]) the hub files for it.
//!
//! A leaf of the audit module: the store writes and reads these, and the log's writer
//! thread carries them, so neither has to import the other to name them.

use std::net::IpAddr;

use serde::{Deserialize, Serialize};

use crate::UnixTime;
use crate::identity::Identity;

/// What was done.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum AuditAction {
    /// Publishing to a robot's input topic (and every refused publish or advertise).
    Publish,
    /// A refused subscription.
    Subscribe,
    CallService,
    SendActionGoal,
    CancelActionGoal,
    /// Offering a service (and every refused offer).
    AdvertiseService,
    /// Offering an action (and every refused offer).
    AdvertiseAction,
    AuthFailure,
    Login,
    Logout,
    RuleChange,
    CredentialChange,
    /// A refused read of something only some may see: an admin listing (`/rules`,
    /// `/audit`, `/clients`, ...) or `/metrics`.
    AccessDenied,
    /// A recording started, stopped or removed (and every refused attempt).
    Recording,
    /// A robot's configuration changed while it runs (and every refused attempt).
    ConfigChange,
}

impl AuditAction {
    pub fn as_str(self) -> &'static str {
        match self {
            AuditAction::Publish => "publish",
            AuditAction::Subscribe => "subscribe",
            AuditAction::CallService => "call_service",
            AuditAction::SendActionGoal => "send_action_goal",
            AuditAction::CancelActionGoal => "cancel_action_goal",
            AuditAction::AdvertiseService => "advertise_service",
            AuditAction::AdvertiseAction => "advertise_action",
            AuditAction::AuthFailure => "auth_failure",
            AuditAction::Login => "login",
            AuditAction::Logout => "logout",
            AuditAction::RuleChange => "rule_change",
            AuditAction::CredentialChange => "credential_change",
            AuditAction::AccessDenied => "access_denied",
            AuditAction::Recording => "recording",
            AuditAction::ConfigChange => "config_change",
        }
    }

    pub fn parse(s: &str) -> Option<AuditAction> {
        use AuditAction::*;
        [
            Publish,
            Subscribe,
            CallService,
            SendActionGoal,
            CancelActionGoal,
            AdvertiseService,
            AdvertiseAction,
            AuthFailure,
            Login,
            Logout,
            RuleChange,
            CredentialChange,
            AccessDenied,
            Recording,
            ConfigChange,
        ]
        .into_iter()
        .find(|a| a.as_str() == s)
    }
}

/// One audit entry.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct AuditRecord {
    pub at: UnixTime,
    /// `robot:r1`, `user:alice`, `anonymous`, or for failed authentications what was
    /// claimed (`claimed-user:bob`, `claimed-robot:r9`, `unknown`).
    pub principal: String,
    pub client_ip: IpAddr,
    pub action: AuditAction,
    /// Topic/service/action name, or what was changed (`rule #4`, `token #9`).
    pub name: String,
    /// Payload size in bytes, where there is a payload.
    pub size: Option<u64>,
    pub allowed: bool,
    /// Free text: the denial reason, the error, the rule as JSON.
    pub detail: Option<String>,
}

impl AuditRecord {
    /// An operation by an authenticated identity.
    pub fn operation(
        identity: &Identity,
        action: AuditAction,
        name: &str,
        size: Option<u64>,
        allowed: bool,
        now: UnixTime,
    ) -> AuditRecord {
        AuditRecord {
            at: now,
            principal: identity.principal(),
            client_ip: identity.client_ip,
            action,
            name: name.to_owned(),
            size,
            allowed,
            detail: None,
        }
    }

    /// A failed authentication. `claimed` is what the client said it was, if anything.
    pub fn auth_failure(
        client_ip: IpAddr,
        claimed: Option<&str>,
        error: &crate::AuthError,
        now: UnixTime,
    ) -> AuditRecord {
        AuditRecord {
            at: now,
            principal: claimed
                .map_or_else(|| "unknown".to_owned(), |c| c.chars().take(128).collect()),
            client_ip,
            action: AuditAction::AuthFailure,
            name: String::new(),
            size: None,
            allowed: false,
            detail: Some(error.to_string()),
        }
    }

    pub fn with_detail(mut self, detail: impl Into<String>) -> AuditRecord {
        self.detail = Some(detail.into());
        self
    }
}
