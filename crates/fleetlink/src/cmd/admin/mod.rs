//! `fleetlink admin`: credentials, access rules and the audit log, edited directly in a
//! hub's database (`--data-dir`, or `--database` for hubs sharing PostgreSQL). Whoever can
//! write the hub's data directory (or the shared database) administers it; a running hub
//! picks up rule changes within a second and checks tokens against the database, so
//! nothing needs a restart. (The same operations are in the REST API for
//! remote administration.) `admin cert` makes TLS certificates and needs no database.
//!
//! A missing database is created only by commands that add something (a token, a user,
//! imported rules), and they say so; the others refuse, naming the path, so a mistyped
//! `--data-dir` is an error instead of an empty listing.

mod cert;

use std::io::Read;
use std::path::PathBuf;

use anyhow::Context;
use clap::Subcommand;
use fleetlink_auth::{
    AclDefaults, AuthPolicy, ConnInfo, GroupName, Identity, IdentityKind, RobotName, Security,
    Store, UnixTime, UserName,
};

#[derive(clap::Args)]
pub struct Args {
    /// The hub's data directory (its database is DIR/hub.sqlite3).
    #[arg(long, default_value = "./fleetlink-data")]
    pub data_dir: PathBuf,
    /// The PostgreSQL database the hubs share (their --database); replaces --data-dir.
    #[arg(
        long,
        env = "FLEETLINK_DATABASE",
        value_name = "URL",
        hide_env_values = true,
        conflicts_with = "data_dir"
    )]
    pub database: Option<String>,
    #[command(subcommand)]
    pub what: What,
}

#[derive(Subcommand)]
pub enum What {
    /// Mint, list and revoke tokens.
    #[command(subcommand)]
    Token(TokenCmd),
    /// List, import, export and remove access rules.
    #[command(subcommand)]
    Rules(RulesCmd),
    /// Add, list and remove users (password login).
    #[command(subcommand)]
    Users(UsersCmd),
    /// Make TLS certificates: a CA, the hub's certificate, robots' client certificates.
    Cert(cert::Args),
    /// Show the newest audit log entries.
    Audit {
        /// How many entries to show at most (newest first).
        #[arg(long, default_value_t = 50)]
        limit: u32,
        /// Only this principal, e.g. `user:alice` or `robot:r1`.
        #[arg(long)]
        principal: Option<String>,
    },
}

#[derive(Subcommand)]
pub enum TokenCmd {
    /// A token for robot NAME's agent (printed once; only its hash is stored).
    Robot {
        /// The robot's name, as in its agent's `name:` (the rule: docs/config.md, "Robot
        /// names").
        name: RobotName,
        /// Days until the token expires (default: never).
        #[arg(long)]
        expires_days: Option<i64>,
    },
    /// A token for an operator or service, with its groups (`--group admin` for full rights).
    Operator {
        /// Who holds the token: a person or a service (recorded in the audit log).
        name: String,
        /// A group the token belongs to (`admin`, `metrics`, or one of your rules');
        /// repeatable.
        #[arg(long = "group")]
        groups: Vec<String>,
        /// Days until the token expires (default: never).
        #[arg(long)]
        expires_days: Option<i64>,
    },
    /// List tokens: id, kind, holder, state (active, expired, revoked) and groups.
    List,
    /// Revoke a token by its id (from `token list`); clients using it are refused at once.
    Revoke {
        /// The token's id, as `token list` shows it.
        id: i64,
    },
}

#[derive(Subcommand)]
pub enum RulesCmd {
    /// List the rules in force, each with its id.
    List,
    /// Replace every rule with those of a YAML file (`-` for stdin); see docs/security.md.
    Import {
        /// The YAML file of rules, or `-` for stdin.
        file: PathBuf,
    },
    /// Print the rules as YAML.
    Export,
    /// Remove one rule by its id (from `rules list`).
    Remove {
        /// The rule's id, as `rules list` shows it.
        id: i64,
    },
}

#[derive(Subcommand)]
pub enum UsersCmd {
    /// Add a user; the password is read from stdin (one line).
    Add {
        /// The user's login name.
        name: String,
        /// A group the user belongs to; repeatable.
        #[arg(long = "group")]
        groups: Vec<String>,
    },
    /// List users and their groups.
    List,
    /// Remove a user; their password no longer logs in.
    Remove {
        /// The user's login name.
        name: String,
    },
}

/// The identity recorded in the audit log for changes made here.
fn local_admin() -> anyhow::Result<Identity> {
    let ip = std::net::IpAddr::from([127, 0, 0, 1]);
    Ok(Identity {
        kind: IdentityKind::User {
            name: UserName::new("local-admin")?,
            groups: vec![GroupName::new("admin")?],
        },
        source: ConnInfo::new(ip),
        client_ip: ip,
    })
}

fn groups(names: &[String]) -> anyhow::Result<Vec<GroupName>> {
    names
        .iter()
        .map(|g| GroupName::new(g).with_context(|| format!("--group {g}")))
        .collect()
}

fn expiry(days: Option<i64>, now: UnixTime) -> Option<UnixTime> {
    days.map(|d| now.plus_secs(d * 86_400))
}

/// Whether a command adds to the database, and so may create a missing one.
fn creates(what: &What) -> bool {
    matches!(
        what,
        What::Token(TokenCmd::Robot { .. } | TokenCmd::Operator { .. })
            | What::Users(UsersCmd::Add { .. })
            | What::Rules(RulesCmd::Import { .. })
    )
}

pub fn run(args: Args) -> anyhow::Result<()> {
    let what = match args.what {
        What::Cert(cert) => return cert::run(cert),
        what => what,
    };
    let store = match &args.database {
        Some(url) => {
            let db = fleetlink_postgres::Database::connect(url)?;
            Store::postgres(db)
                .with_context(|| format!("opening {}", fleetlink_postgres::redact(url)))?
        }
        None => open_file(&args.data_dir, &what)?,
    };
    let security = Security::new(store, AuthPolicy::default(), AclDefaults::default())?;
    run_on(security, what)
}

/// The hub's SQLite file in `dir`, created only for a command that adds something.
fn open_file(dir: &std::path::Path, what: &What) -> anyhow::Result<Store> {
    let db = dir.join("hub.sqlite3");
    if !db.exists() {
        anyhow::ensure!(
            creates(what),
            "no hub database at {}: check --data-dir (it is the hub's --data-dir; a hub \
             creates its database when it first starts, and so do `admin token` and \
             `admin users add`)",
            db.display()
        );
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        eprintln!("created a new hub database at {}", db.display());
    }
    Store::open(&db).with_context(|| format!("opening {}", db.display()))
}

fn run_on(security: Security, what: What) -> anyhow::Result<()> {
    let me = local_admin()?;
    let now = UnixTime::now();
    match what {
        What::Cert(_) => unreachable!("handled before the database is opened"),
        What::Token(TokenCmd::Robot { name, expires_days }) => {
            let t = security.add_robot_token(&me, &name, expiry(expires_days, now), now)?;
            println!("{}", t.expose());
        }
        What::Token(TokenCmd::Operator {
            name,
            groups: g,
            expires_days,
        }) => {
            let user = UserName::new(&name).with_context(|| format!("operator name {name:?}"))?;
            let t = security.mint_operator_token(
                &me,
                &user,
                &groups(&g)?,
                expiry(expires_days, now),
                now,
            )?;
            println!("{}", t.expose());
        }
        What::Token(TokenCmd::List) => {
            for t in security.store.list_tokens(None)? {
                let state = match (t.revoked_at, t.expires_at) {
                    (Some(_), _) => "revoked",
                    (None, Some(e)) if e <= now => "expired",
                    _ => "active",
                };
                let groups: Vec<&str> = t.groups.iter().map(|g| g.as_str()).collect();
                println!(
                    "{}\t{}\t{}\t{}\t[{}]",
                    t.id.0,
                    t.kind,
                    t.subject,
                    state,
                    groups.join(",")
                );
            }
        }
        What::Token(TokenCmd::Revoke { id }) => {
            if !security.revoke_token(&me, fleetlink_auth::store::TokenId(id), now)? {
                anyhow::bail!("no active token with id {id}");
            }
            println!("revoked token {id}");
        }
        What::Rules(RulesCmd::List) => {
            for r in security.store.list_rules()? {
                println!("{}\t{}", r.id, serde_json::to_string(&r.rule)?);
            }
        }
        What::Rules(RulesCmd::Import { file }) => {
            let text = if file.as_os_str() == "-" {
                let mut s = String::new();
                std::io::stdin().read_to_string(&mut s)?;
                s
            } else {
                std::fs::read_to_string(&file)
                    .with_context(|| format!("reading {}", file.display()))?
            };
            let n = security
                .import_rules_yaml(&me, &text, now)
                .with_context(|| format!("importing {}", file.display()))?;
            println!("{n} rules in force");
        }
        What::Rules(RulesCmd::Export) => {
            let rules: Vec<_> = security
                .store
                .list_rules()?
                .into_iter()
                .map(|r| r.rule)
                .collect();
            print!("{}", fleetlink_auth::acl::export_yaml(&rules)?);
        }
        What::Rules(RulesCmd::Remove { id }) => {
            if !security.remove_rule(&me, fleetlink_auth::RuleId(id), now)? {
                anyhow::bail!("no rule with id {id}");
            }
            println!("removed rule {id}");
        }
        What::Users(UsersCmd::Add { name, groups: g }) => {
            let user = UserName::new(&name).with_context(|| format!("user name {name:?}"))?;
            let mut password = String::new();
            std::io::stdin()
                .read_line(&mut password)
                .context("reading the password from stdin")?;
            let password = password.trim_end_matches(['\r', '\n']);
            anyhow::ensure!(!password.is_empty(), "empty password on stdin");
            security.add_user(&me, &user, password, &groups(&g)?, now)?;
            println!("added user {name}");
        }
        What::Users(UsersCmd::List) => {
            for u in security.store.list_users()? {
                let groups: Vec<&str> = u.groups.iter().map(|g| g.as_str()).collect();
                println!("{}\t[{}]", u.name, groups.join(","));
            }
        }
        What::Users(UsersCmd::Remove { name }) => {
            let user = UserName::new(&name)?;
            if !security.remove_user(&me, &user, now)? {
                anyhow::bail!("no user {name}");
            }
            println!("removed user {name}");
        }
        What::Audit { limit, principal } => {
            let q = fleetlink_auth::audit::AuditQuery {
                principal,
                limit,
                ..Default::default()
            };
            for r in security.store.query_audit(&q)?.records {
                println!("{}", serde_json::to_string(&r)?);
            }
        }
    }
    security.audit.flush();
    Ok(())
}
