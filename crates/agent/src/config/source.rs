//! Where a configuration comes from: reading the file (or the defaults) with the
//! command-line values that replace the file's, and the [`ConfigSource`] that remembers
//! the text, its hash and the flags — what kept changes record they were made against
//! ([`super::runtime::kept`]) and what the effective view marks each field's origin with
//! ([`super::origin`]). Also where the changes made at run time are kept by default.

use std::path::{Path, PathBuf};

use sha2::{Digest, Sha256};

use super::locate::LocationTree;
use super::runtime::kept::MadeAgainst;
use super::{
    AgentConfig, ConfigError, Overrides, field_error, flag_or_field, parse_error, rosgw, validate,
};

/// The text a configuration was read from, and the command-line values that replaced
/// some of its fields.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ConfigSource {
    /// The file; `None`: no file (the defaults, or text made in code such as the demo's).
    pub path: Option<PathBuf>,
    /// The text read; empty without a file.
    pub text: String,
    /// Top-level fields given on the command line, with the flag: `("hub", "--hub")`.
    pub flags: Vec<(&'static str, &'static str)>,
}

impl ConfigSource {
    /// Text that is not a file (the demo's robots), named only by its hash.
    pub fn text(text: impl Into<String>) -> ConfigSource {
        ConfigSource {
            text: text.into(),
            ..ConfigSource::default()
        }
    }

    /// Records that `flag` set the top-level `field`.
    pub fn with_flag(mut self, field: &'static str, flag: &'static str) -> ConfigSource {
        self.flags.retain(|(f, _)| *f != field);
        self.flags.push((field, flag));
        self
    }

    /// The flag that set the top-level `field`, if one did.
    pub fn flag_for(&self, field: &str) -> Option<&'static str> {
        self.flags
            .iter()
            .find(|(f, _)| *f == field)
            .map(|(_, k)| *k)
    }

    /// SHA-256 of the text, in hex.
    pub fn sha256(&self) -> String {
        Sha256::digest(self.text.as_bytes())
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect()
    }

    /// What kept changes made against this configuration record.
    pub fn made_against(&self) -> MadeAgainst {
        MadeAgainst {
            file: self.path.as_ref().map(|p| p.display().to_string()),
            sha256: self.sha256(),
        }
    }

    /// The file's name as messages say it: its path, or what stands for it.
    pub fn name(&self) -> String {
        match &self.path {
            Some(p) => p.display().to_string(),
            None if self.text.is_empty() => "the built-in defaults".to_owned(),
            None => "the configuration the agent was given".to_owned(),
        }
    }

    /// Whether the text is a ROS Gateway JSON file (its fields are not the agent's).
    pub(crate) fn is_rosgw(&self) -> bool {
        rosgw::parse(&self.text).is_some()
    }

    /// The text's document tree, when it is the agent's YAML.
    pub(crate) fn tree(&self) -> Option<LocationTree> {
        if self.text.trim().is_empty() || self.is_rosgw() {
            return None;
        }
        LocationTree::parse(&self.text).ok()
    }
}

impl AgentConfig {
    /// Reads and checks a config file. Errors name the file, line, column and field.
    pub fn load(path: &Path) -> Result<Self, ConfigError> {
        Self::load_with(Some(path), &Overrides::default())
    }

    /// Reads a config file (or starts from the defaults), applies command-line
    /// `overrides`, then checks the result once. A problem with an overridden value names
    /// its flag; others name the file's line and field.
    pub fn load_with(path: Option<&Path>, overrides: &Overrides) -> Result<Self, ConfigError> {
        Self::load_source(path, overrides).map(|(cfg, _)| cfg)
    }

    /// [`AgentConfig::load_with`], with where the configuration came from.
    pub fn load_source(
        path: Option<&Path>,
        overrides: &Overrides,
    ) -> Result<(Self, ConfigSource), ConfigError> {
        let mut source = ConfigSource::default();
        for (set, field, flag) in [
            (overrides.hub.is_some(), "hub", "--hub"),
            (overrides.name.is_some(), "name", "--name"),
            (overrides.mirror.is_some(), "mirror", "--mirror"),
        ] {
            if set {
                source = source.with_flag(field, flag);
            }
        }
        let Some(path) = path else {
            let mut cfg = Self::default();
            overrides.apply(&mut cfg, false);
            validate::validate(&cfg).map_err(|problem| flag_or_field(problem, overrides))?;
            return Ok((cfg, source));
        };
        let text = std::fs::read_to_string(path).map_err(|source| ConfigError::Read {
            path: path.to_owned(),
            source,
        })?;
        let cfg = Self::parse_with(&text, &path.display().to_string(), overrides)?;
        source.path = Some(path.to_owned());
        source.text = text;
        Ok((cfg, source))
    }

    /// Parses and checks config text; `file_name` is only used in error messages.
    pub fn from_str(text: &str, file_name: &str) -> Result<Self, ConfigError> {
        Self::parse_with(text, file_name, &Overrides::default())
    }

    pub(crate) fn parse_with(
        text: &str,
        file_name: &str,
        overrides: &Overrides,
    ) -> Result<Self, ConfigError> {
        // A ROS Gateway JSON file describes the same agent in rosgw's terms.
        if let Some(converted) = rosgw::parse(text) {
            let mut config = converted.map_err(|p| field_error(p, text, file_name))?;
            overrides.apply(&mut config, false);
            // What the conversion produced is checked like a YAML file's fields; a problem
            // left (say with `--hub`) names the agent's field, as there is no line for it.
            validate::validate(&config).map_err(|p| flag_or_field(p, overrides))?;
            return Ok(config);
        }
        let mut config: Self =
            serde_saphyr::from_str(text).map_err(|e| parse_error(&e, text, file_name))?;
        let name_written = (config.mirror.is_some() || overrides.mirror.is_some())
            && LocationTree::parse(text).is_ok_and(|t| t.has_top_key("name"));
        overrides.apply(&mut config, name_written);
        validate::validate(&config).map_err(|problem| {
            if overrides.flag_for(&problem.path).is_some() {
                return flag_or_field(problem, overrides);
            }
            field_error(problem, text, file_name)
        })?;
        Ok(config)
    }

    /// Where the runtime changes are kept: `runtime_file`, else `<name>/runtime.json` in
    /// the service's state directory (systemd's `StateDirectory=`, `$STATE_DIRECTORY`),
    /// the user's (`$XDG_STATE_HOME/fleetlink`, `~/.local/state/fleetlink`), or
    /// `/var/lib/fleetlink` without a home.
    pub fn runtime_file_path(&self) -> Option<PathBuf> {
        Some(self.runtime_file_from().0)
    }

    /// [`AgentConfig::runtime_file_path`], with the environment variable it was found
    /// by (`None`: written in the file, or `/var/lib/fleetlink`).
    pub fn runtime_file_from(&self) -> (PathBuf, Option<&'static str>) {
        if let Some(f) = &self.runtime_file {
            return (f.clone(), None);
        }
        let var = |k: &'static str| {
            std::env::var_os(k)
                .filter(|d| !d.is_empty())
                .map(|d| (PathBuf::from(d), Some(k)))
        };
        let (dir, from) = var("STATE_DIRECTORY")
            // systemd may list several, separated by colons: the first is the service's.
            .map(|(d, k)| {
                let first = d
                    .to_string_lossy()
                    .split(':')
                    .next()
                    .unwrap_or_default()
                    .to_owned();
                (PathBuf::from(first), k)
            })
            .or_else(|| var("XDG_STATE_HOME").map(|(d, k)| (d.join("fleetlink"), k)))
            .or_else(|| var("HOME").map(|(h, k)| (h.join(".local/state/fleetlink"), k)))
            .unwrap_or_else(|| (PathBuf::from("/var/lib/fleetlink"), None));
        (dir.join(self.name.as_str()).join("runtime.json"), from)
    }
}
