//! `fleetlink admin cert`: a small CA and the certificates a hub and its robots need,
//! made with rcgen (ECDSA P-256 keys), so nobody has to get openssl's extensions right.
//!
//! One directory holds the CA (`ca.pem`, `ca.key`) and what it issued. The first command
//! creates the CA; later ones reuse it, so the hub's certificate and every robot's are
//! signed by the same CA, which agents trust as `tls.ca` and the hub as `--tls-client-ca`.
//! Certificates are issued for a limited time (`--days`); the CA for ten years.

use std::io::Write;
use std::net::IpAddr;
use std::path::{Path, PathBuf};

use anyhow::Context;
use clap::Subcommand;
use rcgen::{
    BasicConstraints, CertificateParams, DnType, ExtendedKeyUsagePurpose, IsCa, Issuer, KeyPair,
    KeyUsagePurpose, SanType,
};

/// Days a CA made here is valid.
const CA_DAYS: i64 = 3650;

#[derive(clap::Args)]
pub struct Args {
    /// Directory of the CA and the certificates (created if missing).
    #[arg(long, default_value = "./fleetlink-tls")]
    pub dir: PathBuf,
    /// Days the new certificate is valid.
    #[arg(long, default_value_t = 825, value_parser = clap::value_parser!(i64).range(1..=3650))]
    pub days: i64,
    #[command(subcommand)]
    pub what: CertCmd,
}

#[derive(Subcommand)]
pub enum CertCmd {
    /// The hub's certificate (hub.pem, hub.key) for the names agents connect to.
    Hub {
        /// A DNS name of the hub (e.g. hub.example.com or localhost); repeatable.
        #[arg(long = "name", value_name = "DNS")]
        names: Vec<String>,
        /// An IP address of the hub; repeatable.
        #[arg(long = "ip", value_name = "IP")]
        ips: Vec<IpAddr>,
    },
    /// A hub's federation certificate (HUB.pem, HUB.key, named HUB@FLEET), signed by the
    /// fleet's own federation CA in DIR/federation-FLEET/ (made on first use): hubs of
    /// the fleet accept each other's links with it and refuse everyone else.
    Federation {
        /// The fleet (the hubs' --fleet).
        #[arg(long)]
        fleet: String,
        /// The hub's name in the federation (letters, digits, '_', '.', '-').
        #[arg(long)]
        hub: String,
        /// A DNS name other hubs connect to this hub by; repeatable.
        #[arg(long = "name", value_name = "DNS")]
        names: Vec<String>,
        /// An IP address other hubs connect to this hub at; repeatable.
        #[arg(long = "ip", value_name = "IP")]
        ips: Vec<IpAddr>,
    },
    /// A client certificate (NAME.pem, NAME.key) naming robot NAME, for mutual TLS.
    Robot {
        /// The robot's name, as in its agent's `name:` (the rule: docs/config.md, "Robot
        /// names"; it also keeps the name a valid DNS label).
        name: fleetlink_auth::RobotName,
    },
}

pub fn run(args: Args) -> anyhow::Result<()> {
    if let CertCmd::Federation {
        fleet,
        hub,
        names,
        ips,
    } = &args.what
    {
        return federation(&args.dir, args.days, fleet, hub, names, ips);
    }
    std::fs::create_dir_all(&args.dir)
        .with_context(|| format!("creating {}", args.dir.display()))?;
    let dir = &args.dir;
    let ca = load_or_make_ca(dir, &CaKind::Hub)?;
    let ca_pem = dir.join("ca.pem");
    match args.what {
        CertCmd::Federation { .. } => unreachable!("handled above"),
        CertCmd::Hub { names, ips } => {
            anyhow::ensure!(
                !names.is_empty() || !ips.is_empty(),
                "give the names agents use to reach the hub: --name DNS and/or --ip IP"
            );
            let mut params = leaf_params(args.days)?;
            let first = names.first().cloned().unwrap_or_else(|| ips[0].to_string());
            params.distinguished_name.push(DnType::CommonName, first);
            add_sans(&mut params, &names, &ips)?;
            params.extended_key_usages = vec![ExtendedKeyUsagePurpose::ServerAuth];
            let (cert, key) = (dir.join("hub.pem"), dir.join("hub.key"));
            issue(params, &ca, &cert, &key)?;
            let sans: Vec<String> = names
                .iter()
                .cloned()
                .chain(ips.iter().map(ToString::to_string))
                .collect();
            println!(
                "wrote {} and {} (the hub's certificate for {}, valid {} days)",
                cert.display(),
                key.display(),
                sans.join(", "),
                args.days
            );
            println!();
            println!("run the hub with:");
            println!(
                "  fleetlink hub --tls-cert {} --tls-key {} ...",
                cert.display(),
                key.display()
            );
            println!(
                "and give agents the CA (copy {} to the robot):",
                ca_pem.display()
            );
            println!("  hub: wss://{}:8080", sans[0]);
            println!("  tls:");
            println!("    ca: {}", ca_pem.display());
        }
        CertCmd::Robot { name: robot } => {
            let mut params = leaf_params(args.days)?;
            params
                .distinguished_name
                .push(DnType::CommonName, robot.as_str());
            params.subject_alt_names.push(SanType::DnsName(
                robot
                    .as_str()
                    .try_into()
                    .with_context(|| format!("robot name {robot:?} as a DNS name"))?,
            ));
            params.extended_key_usages = vec![ExtendedKeyUsagePurpose::ClientAuth];
            let cert = dir.join(format!("{robot}.pem"));
            let key = dir.join(format!("{robot}.key"));
            issue(params, &ca, &cert, &key)?;
            println!(
                "wrote {} and {} (robot {robot}'s client certificate, valid {} days)",
                cert.display(),
                key.display(),
                args.days
            );
            println!();
            println!(
                "run the hub with --tls-client-ca {} (add --require-client-cert to refuse \
                 robots without one)",
                ca_pem.display()
            );
            println!("and in robot {robot}'s agent configuration (copy the three files to it):");
            println!("  name: {robot}");
            println!("  tls:");
            println!("    ca: {}", ca_pem.display());
            println!("    cert: {}", cert.display());
            println!("    key: {}", key.display());
        }
    }
    Ok(())
}

/// A hub's federation certificate, from the fleet's federation CA (a CA of its own, so
/// that no robot or web certificate of the hub's other CA can pass for a hub).
fn federation(
    dir: &Path,
    days: i64,
    fleet: &str,
    hub: &str,
    names: &[String],
    ips: &[IpAddr],
) -> anyhow::Result<()> {
    let cn = format!("{hub}@{fleet}");
    fleetlink_auth::tls::federation::HubCertName::parse(&cn)
        .with_context(|| format!("--hub {hub:?} --fleet {fleet:?}"))?;
    anyhow::ensure!(
        !names.is_empty() || !ips.is_empty(),
        "give the names other hubs use to reach this hub (their tls/ endpoints): --name DNS \
         and/or --ip IP"
    );
    let dir = dir.join(format!("federation-{fleet}"));
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let ca = load_or_make_ca(&dir, &CaKind::Federation(fleet.to_owned()))?;
    let mut params = leaf_params(days)?;
    params.distinguished_name.push(DnType::CommonName, &cn);
    add_sans(&mut params, names, ips)?;
    // A hub both accepts links from other hubs and makes them.
    params.extended_key_usages = vec![
        ExtendedKeyUsagePurpose::ServerAuth,
        ExtendedKeyUsagePurpose::ClientAuth,
    ];
    let (cert, key) = (
        dir.join(format!("{hub}.pem")),
        dir.join(format!("{hub}.key")),
    );
    issue(params, &ca, &cert, &key)?;
    let ca_pem = dir.join("ca.pem");
    println!(
        "wrote {} and {} (hub {hub}'s federation certificate, {cn}, valid {days} days)",
        cert.display(),
        key.display()
    );
    println!();
    println!(
        "run the hub with (every hub of fleet {fleet} gets the same CA, and its own certificate):"
    );
    let at = names.first().cloned().unwrap_or_else(|| ips[0].to_string());
    println!(
        "  fleetlink hub --federate zenoh --fleet {fleet} --zenoh-ca {} --zenoh-cert {} \\",
        ca_pem.display(),
        cert.display()
    );
    println!(
        "      --zenoh-key {} --zenoh-listen tls/{}:7447 [--zenoh-connect tls/OTHER-HUB:7447] ...",
        key.display(),
        if at.contains(':') {
            format!("[{at}]")
        } else {
            at.clone()
        }
    );
    Ok(())
}

/// The names a certificate is valid for: each `--name` as a DNS name, each `--ip`.
fn add_sans(
    params: &mut CertificateParams,
    names: &[String],
    ips: &[IpAddr],
) -> anyhow::Result<()> {
    for n in names {
        params.subject_alt_names.push(SanType::DnsName(
            n.as_str()
                .try_into()
                .with_context(|| format!("--name {n:?} is not a DNS name"))?,
        ));
    }
    params
        .subject_alt_names
        .extend(ips.iter().map(|ip| SanType::IpAddress(*ip)));
    Ok(())
}

/// Which CA a directory holds.
enum CaKind {
    /// The hub's CA: its web certificate and robots' client certificates.
    Hub,
    /// A fleet's federation CA: hub certificates only.
    Federation(String),
}

/// The CA in `dir`, made (and announced) if `ca.pem` does not exist yet.
fn load_or_make_ca(dir: &Path, kind: &CaKind) -> anyhow::Result<Issuer<'static, KeyPair>> {
    let (cert, key) = (dir.join("ca.pem"), dir.join("ca.key"));
    if cert.exists() {
        let key_pem = std::fs::read_to_string(&key)
            .with_context(|| format!("{} exists but its key cannot be read", cert.display()))?;
        let key_pair = KeyPair::from_pem(&key_pem)
            .with_context(|| format!("{}: not a private key", key.display()))?;
        let cert_pem = std::fs::read_to_string(&cert)
            .with_context(|| format!("reading {}", cert.display()))?;
        return Issuer::from_ca_cert_pem(&cert_pem, key_pair)
            .with_context(|| format!("{}: not a CA certificate", cert.display()));
    }
    let key_pair = KeyPair::generate().context("generating the CA key")?;
    let mut params = CertificateParams::default();
    let name = match kind {
        CaKind::Hub => "fleetlink CA".to_owned(),
        CaKind::Federation(fleet) => format!("fleetlink federation CA of fleet {fleet}"),
    };
    params.distinguished_name.push(DnType::CommonName, name);
    params.is_ca = IsCa::Ca(BasicConstraints::Constrained(0));
    params.key_usages = vec![
        KeyUsagePurpose::KeyCertSign,
        KeyUsagePurpose::CrlSign,
        KeyUsagePurpose::DigitalSignature,
    ];
    validity(&mut params, CA_DAYS);
    let ca_cert = params
        .self_signed(&key_pair)
        .context("signing the CA certificate")?;
    write_private(&key, &key_pair.serialize_pem())?;
    std::fs::write(&cert, ca_cert.pem()).with_context(|| format!("writing {}", cert.display()))?;
    match kind {
        CaKind::Hub => println!(
            "wrote {} (a new CA: agents trust it as tls.ca) and {} (its key: keep it private; \
             it signs the hub's and robots' certificates)",
            cert.display(),
            key.display()
        ),
        CaKind::Federation(fleet) => println!(
            "wrote {} (a new federation CA: every hub of fleet {fleet} is given it as \
             --zenoh-ca) and {} (its key: keep it private; it signs the hubs' certificates)",
            cert.display(),
            key.display()
        ),
    }
    Ok(Issuer::new(params, key_pair))
}

fn leaf_params(days: i64) -> anyhow::Result<CertificateParams> {
    let mut params = CertificateParams::default();
    params.is_ca = IsCa::ExplicitNoCa;
    params.key_usages = vec![KeyUsagePurpose::DigitalSignature];
    params.use_authority_key_identifier_extension = true;
    validity(&mut params, days);
    Ok(params)
}

/// From an hour ago (a robot's clock may lag) to `days` from now.
fn validity(params: &mut CertificateParams, days: i64) {
    let now = time::OffsetDateTime::now_utc();
    params.not_before = now - time::Duration::hours(1);
    params.not_after = now + time::Duration::days(days);
}

fn issue(
    params: CertificateParams,
    ca: &Issuer<'static, KeyPair>,
    cert: &Path,
    key: &Path,
) -> anyhow::Result<()> {
    let key_pair = KeyPair::generate().context("generating a key")?;
    let signed = params
        .signed_by(&key_pair, ca)
        .context("signing the certificate")?;
    write_private(key, &key_pair.serialize_pem())?;
    std::fs::write(cert, signed.pem()).with_context(|| format!("writing {}", cert.display()))
}

/// Writes a private key readable by its owner only.
fn write_private(path: &Path, pem: &str) -> anyhow::Result<()> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create(true).truncate(true);
    #[cfg(unix)]
    std::os::unix::fs::OpenOptionsExt::mode(&mut options, 0o600);
    let mut f = options
        .open(path)
        .with_context(|| format!("writing {}", path.display()))?;
    f.write_all(pem.as_bytes())
        .with_context(|| format!("writing {}", path.display()))
}
