//! `--check` for `fleetlink hub` and `fleetlink agent`: validate everything that can be
//! validated without starting anything (as `nginx -t` does), print the effective
//! configuration with its defaults, and exit 0 or 1.
//!
//! A check reads what the run would read — files, certificates, message definitions,
//! URLs — and stops there: no socket is bound, no hub or database is connected to, no
//! directory is created.

use std::fmt::Write as _;

use clap::parser::ValueSource;

/// What a check found: each step's outcome, in order.
#[derive(Default)]
pub struct Report {
    lines: Vec<String>,
    problems: usize,
}

impl Report {
    pub fn ok(&mut self, what: impl std::fmt::Display) {
        self.lines.push(format!("  ok: {what}"));
    }

    pub fn note(&mut self, what: impl std::fmt::Display) {
        self.lines.push(format!("  note: {what}"));
    }

    pub fn problem(&mut self, what: impl std::fmt::Display) {
        self.problems += 1;
        self.lines.push(format!("  error: {what}"));
    }

    /// Records `result` as ok (`what`) or as the problem it carries.
    pub fn step<T, E: std::fmt::Display>(
        &mut self,
        what: impl std::fmt::Display,
        result: Result<T, E>,
    ) -> Option<T> {
        match result {
            Ok(v) => {
                self.ok(what);
                Some(v)
            }
            Err(e) => {
                self.problem(format!("{what}: {e}"));
                None
            }
        }
    }

    /// The message definitions a start would load: the bundled ones and `--msg-path`.
    pub fn definitions(&mut self, msg_path: &[std::path::PathBuf]) {
        let mut what = "message definitions: the bundled ones".to_owned();
        if !msg_path.is_empty() {
            let dirs: Vec<String> = msg_path.iter().map(|p| p.display().to_string()).collect();
            let _ = write!(what, " and --msg-path {}", dirs.join(", "));
        }
        self.step(what, crate::transcoder(msg_path));
    }

    /// Prints the steps, then `effective` (the configuration as it would run), then the
    /// verdict; an error when anything was wrong, so the process exits 1.
    pub fn finish(self, program: &str, effective: &str) -> anyhow::Result<()> {
        println!("{program}: checking the configuration (nothing is started or connected)");
        for l in &self.lines {
            println!("{l}");
        }
        if self.problems > 0 {
            anyhow::bail!(
                "{program}: the configuration has {} problem{} (listed above)",
                self.problems,
                if self.problems == 1 { "" } else { "s" }
            );
        }
        println!("effective configuration:");
        print!("{effective}");
        println!("{program}: the configuration is valid");
        Ok(())
    }
}

/// Every option of `command` with the value it takes in `matches`, and where the value
/// came from (the command line, the environment, or the default). Options without a
/// value are listed as not set, so the output shows every knob there is.
pub fn options(command: &clap::Command, matches: &clap::ArgMatches) -> String {
    let mut out = String::new();
    for arg in command.get_arguments() {
        let id = arg.get_id().as_str();
        if matches!(id, "help" | "version" | "check") || arg.get_long().is_none() {
            continue;
        }
        let long = arg.get_long().unwrap_or(id);
        let source = matches.value_source(id);
        let values: Vec<String> = match matches.get_raw(id) {
            Some(raw) => raw.map(|v| v.to_string_lossy().into_owned()).collect(),
            None => Vec::new(),
        };
        let is_flag = !arg.get_action().takes_values();
        let shown = if is_flag {
            match matches.get_flag_checked(id) {
                Some(true) => "true".to_owned(),
                _ => "false".to_owned(),
            }
        } else if values.is_empty() {
            "(not set)".to_owned()
        } else {
            values.join(", ")
        };
        let from = match source {
            Some(ValueSource::CommandLine) => "  # given",
            Some(ValueSource::EnvVariable) => "  # from the environment",
            Some(ValueSource::DefaultValue) => "  # default",
            _ => "",
        };
        let _ = writeln!(out, "  --{long}: {}{from}", redact(long, &shown));
    }
    out
}

/// A value as it may be printed: passwords in database URLs left out.
fn redact(long: &str, value: &str) -> String {
    if long == "database" && value != "(not set)" {
        return fleetlink_postgres::redact(value);
    }
    value.to_owned()
}

trait FlagChecked {
    fn get_flag_checked(&self, id: &str) -> Option<bool>;
}

impl FlagChecked for clap::ArgMatches {
    fn get_flag_checked(&self, id: &str) -> Option<bool> {
        self.try_get_one::<bool>(id).ok().flatten().copied()
    }
}
