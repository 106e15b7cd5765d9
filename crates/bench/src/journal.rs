//! `fleetlink bench journal`: what the agent's thread feels while its durable outbox
//! compacts a large journal on a slow disk.
//!
//! The agent runs its adapters, its link and its heartbeat on one thread, which is also
//! the thread that hands no-drop messages to the durable outbox. This bench builds that
//! situation on a current-thread runtime: a journal with `--live-mb` of unconfirmed
//! messages in a file four times as large (so the next confirmation compacts it), a
//! heartbeat that wants to run every `--tick-ms`, and an adapter that hands a small
//! no-drop message to the journal every `--publish-ms`. Then the disk is slowed to
//! `--disk-mbps` and a confirmation starts the compaction. It reports how late the
//! heartbeat ran (its jitter) and how long each message took from its due time until the
//! journal had taken it (the adapter's latency), while the compaction runs.
//!
//! The slow disk is the journal's write delay for test builds
//! (`fleetlink_agent::outbox_store::slow_disk`): this bench needs a build with debug
//! assertions (`cargo build --profile ci`).

use std::time::{Duration, Instant};

use anyhow::{Context, bail};
use bytes::Bytes;
use fleetlink_agent::outbox_store::{self, Fsync, OutboxStoreConfig};
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::message::TopicMeta;
use fleetlink_relay::reliable::Journal;
use fleetlink_relay::{TopicId, TopicName};

#[derive(clap::Args)]
pub struct Args {
    /// Directory for the outbox file (a tmpfs keeps the setup fast; the slow disk is
    /// simulated). Must not hold another agent's outbox.
    #[arg(long)]
    dir: std::path::PathBuf,
    /// Unconfirmed data the compaction rewrites, MB.
    #[arg(long, default_value_t = 256)]
    live_mb: u64,
    /// Write speed of the simulated disk during the measurement, MB/s.
    #[arg(long, default_value_t = 20.0)]
    disk_mbps: f64,
    /// The heartbeat's period, ms.
    #[arg(long, default_value_t = 100)]
    tick_ms: u64,
    /// The adapter's period, ms (one 200-byte no-drop message each).
    #[arg(long, default_value_t = 10)]
    publish_ms: u64,
    /// How long to measure, s.
    #[arg(long, default_value_t = 20)]
    seconds: u64,
    /// Print the result as one JSON object.
    #[arg(long)]
    json: bool,
}

fn meta(name: &str, id: u32) -> anyhow::Result<TopicMeta> {
    Ok(TopicMeta::new(
        TopicId(id),
        TopicName::parse(name)?,
        Schema::named("std_msgs/msg/String"),
        false,
    ))
}

/// Percentiles of a set of durations, in ms.
fn summary(mut xs: Vec<Duration>) -> serde_json::Value {
    xs.sort();
    let p = |q: f64| {
        xs.get(((xs.len() as f64 - 1.0) * q).round() as usize)
            .map_or(0.0, |d| d.as_secs_f64() * 1e3)
    };
    serde_json::json!({
        "n": xs.len(),
        "p50_ms": p(0.5),
        "p99_ms": p(0.99),
        "max_ms": p(1.0),
    })
}

pub fn run(a: Args) -> anyhow::Result<()> {
    if !outbox_store::slow_disk::available() {
        bail!(
            "`bench journal` simulates a slow disk, which only test builds have: build with \
             `cargo build --profile ci -p fleetlink` and run target/ci/fleetlink"
        );
    }
    if a.dir.join("outbox.log").exists() {
        bail!(
            "{} already holds an outbox; give an empty directory",
            a.dir.display()
        );
    }
    let cfg = OutboxStoreConfig {
        dir: a.dir.clone(),
        max_bytes: u64::MAX,
        fsync: Fsync::Batch,
    };
    let mut opened = outbox_store::open(&cfg).context("opening the outbox")?;
    let j = &mut opened.journal;
    // The setup, at full speed: the live messages, then three times as much filler, all
    // unconfirmed until the measurement confirms the filler at once: the file is then four
    // times the live data, and that confirmation compacts it.
    let (live_t, filler_t, small_t) =
        (meta("/live", 1)?, meta("/filler", 2)?, meta("/adapter", 3)?);
    // One buffer shared by every record, as the outbox shares a message's payload.
    let chunk = Payload::new(Encoding::Cdr, Bytes::from(vec![7u8; 1 << 20]));
    for i in 0..a.live_mb {
        j.append(&live_t, i + 1, 0, &chunk)?;
    }
    let filler = 3 * a.live_mb + 8;
    for i in 0..filler {
        j.append(&filler_t, i + 1, 0, &chunk)?;
    }
    j.wait_written();
    eprintln!(
        "journal: {} MB live in a file of about {} MB; disk slowed to {} MB/s; the last \
         filler confirmation starts the compaction",
        a.live_mb,
        4 * a.live_mb + 8,
        a.disk_mbps
    );
    outbox_store::slow_disk::set((a.disk_mbps * 1e6) as u64);
    let rt = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()?;
    let (ticks, appends, confirm_took) = rt.block_on(async {
        let start = Instant::now();
        let end = start + Duration::from_secs(a.seconds);
        let tick = Duration::from_millis(a.tick_ms);
        let heartbeat = async {
            let mut late = Vec::new();
            let mut due = Instant::now() + tick;
            while due < end {
                tokio::time::sleep_until(due.into()).await;
                late.push(Instant::now().saturating_duration_since(due));
                due += tick;
            }
            late
        };
        let journal = std::cell::RefCell::new(&mut opened.journal);
        let adapter = async {
            let period = Duration::from_millis(a.publish_ms);
            let body = Payload::new(Encoding::Cdr, Bytes::from(vec![1u8; 200]));
            let mut took = Vec::new();
            let mut due = Instant::now() + period;
            let mut seq = 0;
            while due < end {
                tokio::time::sleep_until(due.into()).await;
                seq += 1;
                let r = journal.borrow_mut().append(&small_t, seq, 0, &body);
                if let Err(e) = r {
                    eprintln!("append: {e}");
                }
                took.push(Instant::now().saturating_duration_since(due));
                due += period;
            }
            took
        };
        let compaction = async {
            // A moment of calm first, so the figures show the before as well.
            tokio::time::sleep(Duration::from_millis(500)).await;
            let t = Instant::now();
            journal.borrow_mut().confirm(&filler_t.name, filler);
            t.elapsed()
        };
        tokio::join!(heartbeat, adapter, compaction)
    });
    let result = serde_json::json!({
        "live_mb": a.live_mb,
        "disk_mbps": a.disk_mbps,
        "heartbeat_lateness": summary(ticks),
        "adapter_latency": summary(appends),
        "confirm_call_ms": confirm_took.as_secs_f64() * 1e3,
    });
    outbox_store::slow_disk::set(0);
    drop(opened);
    let _ = std::fs::remove_file(a.dir.join("outbox.log"));
    if a.json {
        println!("{result}");
    } else {
        let f = |k: &str| {
            let v = &result[k];
            format!(
                "p50 {:.1} ms, p99 {:.1} ms, max {:.1} ms ({} samples)",
                v["p50_ms"].as_f64().unwrap_or(0.0),
                v["p99_ms"].as_f64().unwrap_or(0.0),
                v["max_ms"].as_f64().unwrap_or(0.0),
                v["n"]
            )
        };
        println!("heartbeat lateness: {}", f("heartbeat_lateness"));
        println!("adapter latency:    {}", f("adapter_latency"));
        println!(
            "confirm() call that started the compaction: {:.1} ms",
            confirm_took.as_secs_f64() * 1e3
        );
    }
    Ok(())
}
