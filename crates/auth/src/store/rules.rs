//! ACL rule rows: list, add, remove, replace, and the revision counter.
//!
//! Rules are stored as JSON of [`Rule`], so a new rule field needs no migration; each is
//! re-validated (patterns compiled) when read back. Every change bumps the revision in its
//! transaction (and, on PostgreSQL, notifies the other hubs when it commits); the
//! statements are in each backend's file (`sqlite.rs`, `postgres.rs`).

use super::{Store, StoreError, corrupt};
use crate::UnixTime;
use crate::acl::{Rule, RuleId, StoredRule};

impl Store {
    pub fn list_rules(&self) -> Result<Vec<StoredRule>, StoreError> {
        let rows = self.engine.list_rules()?;
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
        let id = self.engine.add_rule(&json, now)?;
        Ok(RuleId(id))
    }

    /// Removes a rule; `false` if there was none with that id.
    pub fn remove_rule(&self, id: RuleId) -> Result<bool, StoreError> {
        self.engine.remove_rule(id)
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
        let ids = self.engine.replace_rules(&jsons, now)?;
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
        let v = self.engine.rules_revision()?;
        Ok(v.unwrap_or(0).max(0) as u64)
    }
}
