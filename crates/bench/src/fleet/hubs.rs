//! The hubs as this machine sees them in /proc: found by process id or by the loopback
//! port they listen on, sampled (CPU seconds, resident memory) at each step of the run,
//! and turned into each hub's figures.

use std::net::Ipv4Addr;

use super::args::Args;
use super::summary::{HubFigures, cpu_pct, round};
use crate::calls::proc_figures;

/// The hubs this bench can see in /proc.
pub struct HubProcs {
    pids: Vec<u32>,
}

/// CPU seconds and resident kB of every measured hub at one moment.
pub type Sample = Vec<Option<(f64, u64)>>;

impl HubProcs {
    pub fn find(urls: &[String], given: &[u32]) -> HubProcs {
        let mut pids: Vec<u32> = given.to_vec();
        if pids.is_empty() {
            pids = urls.iter().filter_map(|u| local_hub_pid(u)).collect();
        }
        pids.dedup();
        HubProcs { pids }
    }

    pub fn sample(&self) -> Sample {
        self.pids.iter().map(|p| proc_figures(*p)).collect()
    }

    pub fn figures(
        &self,
        before: &Sample,
        idle0: &Sample,
        idle1: &Sample,
        loaded: Option<&(Sample, Sample)>,
        args: &Args,
    ) -> Vec<HubFigures> {
        let conns = args.robots + args.subscribers + usize::from(args.wildcard);
        let conns_per_hub = conns as f64 / self.pids.len().max(1) as f64;
        let pct = |a: Option<(f64, u64)>, b: Option<(f64, u64)>, secs: f64| {
            cpu_pct(a.map(|x| x.0), b.map(|x| x.0), secs)
        };
        self.pids
            .iter()
            .enumerate()
            .map(|(i, &pid)| {
                let rss = |s: &Sample| s[i].map(|x| x.1);
                let kb_per_connection = match (rss(before), rss(idle1)) {
                    (Some(a), Some(b)) => Some(round((b as f64 - a as f64) / conns_per_hub, 1)),
                    _ => None,
                };
                HubFigures {
                    pid,
                    rss_before_kb: rss(before),
                    rss_idle_kb: rss(idle1),
                    rss_loaded_kb: loaded.and_then(|l| rss(&l.1)),
                    kb_per_connection,
                    cpu_idle_pct: pct(idle0[i], idle1[i], args.idle),
                    cpu_loaded_pct: loaded.and_then(|l| pct(l.0[i], l.1[i], args.duration)),
                }
            })
            .collect()
    }
}

/// The process listening on a loopback URL's port, from /proc/net/tcp and the processes'
/// open sockets (needs the right to read other processes' fds: the same user, or root).
fn local_hub_pid(url: &str) -> Option<u32> {
    let authority = url.split("://").nth(1)?.split('/').next()?;
    let (host, port) = authority.rsplit_once(':')?;
    let port: u16 = port.parse().ok()?;
    let loopback = host == "localhost"
        || host
            .parse::<Ipv4Addr>()
            .is_ok_and(|a| a.is_loopback() || a.is_unspecified());
    if !loopback {
        return None;
    }
    let mut inodes = Vec::new();
    for table in ["/proc/net/tcp", "/proc/net/tcp6"] {
        let Ok(text) = std::fs::read_to_string(table) else {
            continue;
        };
        for line in text.lines().skip(1) {
            let f: Vec<&str> = line.split_whitespace().collect();
            let (Some(local), Some(state), Some(inode)) = (f.get(1), f.get(3), f.get(9)) else {
                continue;
            };
            let listening = *state == "0A";
            let port_hex = local.rsplit(':').next().unwrap_or_default();
            if listening && u16::from_str_radix(port_hex, 16).ok() == Some(port) {
                inodes.push(format!("socket:[{inode}]"));
            }
        }
    }
    if inodes.is_empty() {
        return None;
    }
    let me = std::process::id();
    for entry in std::fs::read_dir("/proc").ok()?.flatten() {
        let Some(pid) = entry
            .file_name()
            .to_str()
            .and_then(|s| s.parse::<u32>().ok())
        else {
            continue;
        };
        if pid == me {
            continue;
        }
        let Ok(fds) = std::fs::read_dir(entry.path().join("fd")) else {
            continue;
        };
        for fd in fds.flatten() {
            if let Ok(target) = std::fs::read_link(fd.path())
                && inodes.iter().any(|i| target.as_os_str() == i.as_str())
            {
                return Some(pid);
            }
        }
    }
    None
}
