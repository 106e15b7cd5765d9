//! `fleetlink bench copy-floor`: what moving a stream between two loopback TCP sockets
//! costs with nothing else done — the floor under any bridge's CPU figure.
//!
//! Three threads in this process: a sender writes `--size`-byte messages (with a 4-byte
//! length, as TCPROS frames them) `--rate` times a second to the relay; the relay reads
//! them with blocking 1 MiB reads and writes every byte on to a sink over a second loopback
//! connection; the sink reads and discards. Only the relay thread's CPU (user + system,
//! from `/proc/self/task/<tid>/stat`) is reported: like a bridge, it is charged for
//! copying each byte out of one socket and into another, including the loopback
//! delivery the kernel does on the writer's behalf. No framing, masking, parsing,
//! acknowledgement or scheduling — so a bridge carrying the same stream cannot cost less,
//! and its figure minus this one is what its own work costs. `scripts/bench-ros1.sh`
//! runs it beside the agent and rosbridge, in the same measured window.
//!
//! The sender's thread is measured too: writing the stream from memory into a loopback
//! connection is the least any bridge pays to hand its bytes to a hub, whatever it read
//! them from. `scripts/bench-ros2.sh` adds that to what Cyclone DDS's own threads spend
//! receiving the stream.

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::time::{Duration, Instant};

use anyhow::{Context, bail};
use serde_json::json;

#[derive(clap::Args)]
pub struct Args {
    /// Bytes per message (a ~1 MB PointCloud2 is 1048687 bytes of TCPROS body).
    #[arg(long, default_value_t = 1_048_576)]
    size: usize,
    /// Messages per second.
    #[arg(long, default_value_t = 10.0)]
    rate: f64,
    /// Measured seconds, after a two-second warm-up.
    #[arg(long, default_value_t = 30.0)]
    seconds: f64,
    /// One JSON object instead of the text line.
    #[arg(long)]
    json: bool,
}

const WARMUP: Duration = Duration::from_secs(2);

pub fn run(args: Args) -> anyhow::Result<()> {
    if args.size == 0 || args.rate <= 0.0 || args.seconds <= 0.0 {
        bail!("--size, --rate and --seconds must be positive");
    }
    let sink = TcpListener::bind("127.0.0.1:0").context("binding the sink")?;
    let relay = TcpListener::bind("127.0.0.1:0").context("binding the relay")?;
    let (sink_addr, relay_addr) = (sink.local_addr()?, relay.local_addr()?);
    std::thread::spawn(move || {
        if let Ok((mut c, _)) = sink.accept() {
            let mut buf = vec![0u8; 1 << 20];
            while matches!(c.read(&mut buf), Ok(n) if n > 0) {}
        }
    });
    let (tid_tx, tid_rx) = std::sync::mpsc::channel();
    let relay_thread = std::thread::spawn(move || -> anyhow::Result<()> {
        tid_tx.send(this_thread_id()?)?;
        let mut out = TcpStream::connect(sink_addr).context("connecting to the sink")?;
        out.set_nodelay(true)?;
        let (mut input, _) = relay.accept().context("accepting the sender")?;
        let mut buf = vec![0u8; 1 << 20];
        loop {
            let n = input.read(&mut buf)?;
            if n == 0 {
                return Ok(());
            }
            out.write_all(&buf[..n])?;
        }
    });
    let tid = tid_rx.recv().context("the relay thread did not start")?;
    let sender_tid = this_thread_id()?;
    let mut tx = TcpStream::connect(relay_addr).context("connecting to the relay")?;
    tx.set_nodelay(true)?;
    let mut message = vec![0x5a_u8; 4 + args.size];
    message[..4].copy_from_slice(&u32::try_from(args.size)?.to_le_bytes());
    let period = Duration::from_secs_f64(1.0 / args.rate);
    let start = Instant::now();
    let mut next = start;
    // (start, relay CPU, sender CPU)
    let mut window: Option<(Instant, f64, f64)> = None;
    let mut sent = 0u64;
    loop {
        let now = Instant::now();
        if window.is_none() && now >= start + WARMUP {
            window = Some((
                now,
                thread_cpu_seconds(tid)?,
                thread_cpu_seconds(sender_tid)?,
            ));
            sent = 0;
        }
        if let Some((t0, _, _)) = window
            && now >= t0 + Duration::from_secs_f64(args.seconds)
        {
            break;
        }
        tx.write_all(&message).context("writing to the relay")?;
        sent += 1;
        next += period;
        if let Some(wait) = next.checked_duration_since(Instant::now()) {
            std::thread::sleep(wait);
        }
    }
    let (t0, cpu0, send0) = window.expect("the window opens before it closes");
    let cpu1 = thread_cpu_seconds(tid)?;
    let send1 = thread_cpu_seconds(sender_tid)?;
    let secs = t0.elapsed().as_secs_f64();
    drop(tx);
    relay_thread
        .join()
        .map_err(|_| anyhow::anyhow!("the relay thread panicked"))??;
    let percent = (cpu1 - cpu0) * 100.0 / secs;
    let sender = (send1 - send0) * 100.0 / secs;
    if args.json {
        println!(
            "{}",
            json!({"size": args.size, "rate": args.rate, "seconds": secs, "messages": sent,
                   "relay_cpu_percent": percent, "sender_cpu_percent": sender})
        );
    } else {
        println!(
            "plain TCP relay, {sent} messages of {} bytes in {secs:.1} s: {percent:.2} % of one core; \
             writing them from memory: {sender:.2} %",
            args.size
        );
    }
    Ok(())
}

/// This thread's id, as named under `/proc/self/task`.
fn this_thread_id() -> anyhow::Result<u32> {
    let link = std::fs::read_link("/proc/thread-self").context("reading /proc/thread-self")?;
    link.file_name()
        .and_then(|n| n.to_str())
        .and_then(|n| n.parse().ok())
        .context("/proc/thread-self does not name a thread")
}

/// CPU seconds (user + system) of one thread of this process.
fn thread_cpu_seconds(tid: u32) -> anyhow::Result<f64> {
    let path = format!("/proc/self/task/{tid}/stat");
    super::calls::stat_cpu_seconds(&path)
        .with_context(|| format!("cannot read CPU time from {path}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_measured_thread_is_charged() {
        let (tx, rx) = std::sync::mpsc::channel();
        let (done_tx, done_rx) = std::sync::mpsc::channel::<()>();
        let idle = std::thread::spawn(move || {
            tx.send(this_thread_id().unwrap()).unwrap();
            let _ = done_rx.recv();
        });
        let idle_tid = rx.recv().unwrap();
        let busy_tid = this_thread_id().unwrap();
        assert_ne!(idle_tid, busy_tid);
        let before = thread_cpu_seconds(busy_tid).unwrap();
        let t = Instant::now();
        let mut x = 0u64;
        while thread_cpu_seconds(busy_tid).unwrap() - before < 0.05 {
            assert!(t.elapsed() < Duration::from_secs(20), "no CPU time charged");
            for _ in 0..100_000 {
                x = x.wrapping_mul(6364136223846793005).wrapping_add(1);
            }
        }
        std::hint::black_box(x);
        let busy = thread_cpu_seconds(busy_tid).unwrap() - before;
        let idle_cpu = thread_cpu_seconds(idle_tid).unwrap();
        done_tx.send(()).unwrap();
        idle.join().unwrap();
        assert!(
            idle_cpu < busy,
            "idle thread {idle_cpu} s, busy thread {busy} s"
        );
    }
}
