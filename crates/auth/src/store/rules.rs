//! ACL rule rows: list, add, remove, replace, and the revision counter.
//!
//! Rules are stored as JSON of [`Rule`], so a new rule field needs no migration; each is
//! re-validated (patterns compiled) when read back.

use rusqlite::{OptionalExtension, params};

use super::{Store, StoreError, corrupt};
use crate::UnixTime;
use crate::acl::{Rule, RuleId, StoredRule};

fn bump_revision(tx: &rusqlite::Transaction<'_>) -> rusqlite::Result<()> {
    tx.execute(
        "UPDATE auth_meta SET value = value + 1 WHERE key = 'rules_revision'",
        [],
    )?;
    Ok(())
}

impl Store {
    pub fn list_rules(&self) -> Result<Vec<StoredRule>, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare("SELECT id, rule_json FROM auth_rules ORDER BY id")?;
            let rows = stmt.query_map([], |r| Ok((r.get::<_, i64>(0)?, r.get::<_, String>(1)?)))?;
            let mut out = Vec::new();
            for row in rows {
                let (id, json) = row?;
                let rule: Rule = serde_json::from_str(&json).map_err(corrupt("ACL rule"))?;
                out.push(StoredRule {
                    id: RuleId(id),
                    rule,
                });
            }
            Ok(out)
        })
    }

    pub fn add_rule(&self, rule: &Rule, now: UnixTime) -> Result<RuleId, StoreError> {
        let json = serde_json::to_string(rule).map_err(corrupt("ACL rule"))?;
        self.with(|c| {
            let tx = c.transaction()?;
            tx.execute(
                "INSERT INTO auth_rules (rule_json, created_at) VALUES (?1, ?2)",
                params![json, now.0],
            )?;
            let id = tx.last_insert_rowid();
            bump_revision(&tx)?;
            tx.commit()?;
            Ok(RuleId(id))
        })
    }

    /// Removes a rule; `false` if there was none with that id.
    pub fn remove_rule(&self, id: RuleId) -> Result<bool, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            let n = tx.execute("DELETE FROM auth_rules WHERE id = ?1", [id.0])?;
            if n > 0 {
                bump_revision(&tx)?;
            }
            tx.commit()?;
            Ok(n > 0)
        })
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
        self.with(|c| {
            let tx = c.transaction()?;
            tx.execute("DELETE FROM auth_rules", [])?;
            let mut out = Vec::with_capacity(rules.len());
            for (rule, json) in rules.iter().zip(&jsons) {
                tx.execute(
                    "INSERT INTO auth_rules (rule_json, created_at) VALUES (?1, ?2)",
                    params![json, now.0],
                )?;
                out.push(StoredRule {
                    id: RuleId(tx.last_insert_rowid()),
                    rule: rule.clone(),
                });
            }
            bump_revision(&tx)?;
            tx.commit()?;
            Ok(out)
        })
    }

    /// Increases on every rule change, by any process using this database file.
    pub fn rules_revision(&self) -> Result<u64, StoreError> {
        self.with(|c| {
            let v: Option<i64> = c
                .query_row(
                    "SELECT value FROM auth_meta WHERE key = 'rules_revision'",
                    [],
                    |r| r.get(0),
                )
                .optional()?;
            Ok(v.unwrap_or(0).max(0) as u64)
        })
    }
}
