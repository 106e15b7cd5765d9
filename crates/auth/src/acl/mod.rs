//! Authorization: the rule model, YAML import/export and the decision API.
//!
//! Design choice: deny by default. A request is allowed when a built-in grant
//! ([`AclDefaults`]: admin group, a robot's own namespace, anonymous read) or an `allow`
//! rule covers it, and no `deny` rule matching the same identity, name and operation
//! forbids it. Rule order is irrelevant, so rules can be added and removed one by one
//! through the API without reasoning about precedence.
//!
//! # YAML format
//!
//! ```yaml
//! rules:
//!   - subject: {group: operators}     # or {user: alice}, {robot: r1}, {cidr: 10.8.0.0/16},
//!     names: "/.*"                     #    any_robot, any_user, anonymous, anyone
//!     ops: [subscribe, call_service]   # or [all]
//!   - subject: {group: operators}
//!     names: "/r[0-9]+/cmd_vel"
//!     ops: [publish]
//!   - subject: any_robot
//!     names: "/fleet/map"
//!     ops: [subscribe]
//!   - subject: {user: intern}
//!     names: "/r1/.*"
//!     ops: [publish]
//!     effect: deny                     # default: allow
//!     comment: "read-only on r1"
//! ```

mod decide;
mod rule;

pub use decide::{Access, AclDefaults, Authorizer, Decision, METRICS, Reason};
pub use rule::{
    Effect, MAX_PATTERN_LEN, NamePattern, OpSet, Operation, PatternError, Rule, RuleId, StoredRule,
    Subject,
};

/// A rule file that could not be imported.
#[derive(Debug, thiserror::Error)]
#[error("invalid ACL YAML: {0}")]
pub struct AclImportError(#[from] serde_saphyr::Error);

/// A rule file failed to serialise.
#[derive(Debug, thiserror::Error)]
#[error("cannot write ACL YAML: {0}")]
pub struct AclExportError(#[from] serde_saphyr::SerializeError);

#[derive(serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
struct RuleFile {
    #[serde(default)]
    rules: Vec<Rule>,
}

/// Parses a rule file (format above). Every pattern is compiled, so a file with one bad
/// regex is rejected as a whole, naming the rule.
pub fn import_yaml(text: &str) -> Result<Vec<Rule>, AclImportError> {
    let file: RuleFile = serde_saphyr::from_str(text)?;
    Ok(file.rules)
}

/// Writes rules in the format [`import_yaml`] reads.
pub fn export_yaml(rules: &[Rule]) -> Result<String, AclExportError> {
    Ok(serde_saphyr::to_string(&RuleFile {
        rules: rules.to_vec(),
    })?)
}
