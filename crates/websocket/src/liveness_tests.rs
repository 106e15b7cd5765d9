//! [`Liveness`] on virtual time, against modelled clients: one that answers, one that
//! went silent, one frozen while its kernel still acknowledges, one reading slowly
//! behind a long queue, and one whose link was cut.

use super::*;

const CFG: LivenessConfig = LivenessConfig {
    ping_every: Duration::from_secs(10),
    silence: Duration::from_secs(30),
};

/// A modelled client: what its connection looks like at a time (seconds since the
/// start), and whether and how late it answers a ping sent then.
struct Client {
    /// Seconds after which a ping sent at `t` is answered (`None`: never).
    answers: Box<dyn Fn(f64) -> Option<f64>>,
    /// Its connection at `t` (`None`: cannot be sampled).
    socket: Box<dyn Fn(f64) -> Option<TcpProgress>>,
}

/// Runs `live` against `client` until it is taken as gone or `until` seconds pass;
/// returns when it was taken as gone (seconds since the start) and the pings sent.
fn run(client: &Client, until: f64) -> (Option<f64>, usize) {
    let base = Instant::now();
    let secs = |t: Instant| t.duration_since(base).as_secs_f64();
    let mut live = Liveness::new(CFG, base);
    let mut pongs: Vec<f64> = Vec::new();
    let mut pings = 0;
    loop {
        let next = live.poll_timeout();
        // A pong arriving before the next timer is read first.
        pongs.sort_by(f64::total_cmp);
        if let Some(&p) = pongs.first()
            && p <= secs(next)
        {
            pongs.remove(0);
            live.on_read(base + Duration::from_secs_f64(p));
            continue;
        }
        let t = secs(next);
        if t > until {
            return (None, pings);
        }
        let due = live.handle_timeout(next);
        if due.gone.is_some() {
            return (Some(t), pings);
        }
        if due.ping {
            pings += 1;
            if let Some(late) = (client.answers)(t) {
                pongs.push(t + late);
            }
        }
        if due.sample {
            live.on_sample(next, (client.socket)(t));
        }
    }
}

#[test]
fn a_client_that_answers_is_never_taken_as_gone() {
    let client = Client {
        answers: Box::new(|_| Some(0.005)),
        socket: Box::new(|_| None),
    };
    let (gone, pings) = run(&client, 600.0);
    assert_eq!(gone, None);
    assert_eq!(pings, 60, "a ping every 10 s");
}

#[test]
fn a_silent_client_is_gone_at_the_silence_limit_after_its_last_answer() {
    // Answers until 42 s (the ping at 40 s is its last answered, at 40.005 s).
    let client = Client {
        answers: Box::new(|t| (t < 42.0).then_some(0.005)),
        socket: Box::new(|_| None),
    };
    let (gone, pings) = run(&client, 600.0);
    let gone = gone.expect("taken as gone");
    assert!((gone - 70.005).abs() < 1e-6, "gone at {gone}");
    assert_eq!(pings, 7, "pings at 10..70 s");
}

/// The connection of a client that read at `read_rate` bytes a second until `stop`
/// (then nothing), while its kernel acknowledged `ack_rate` (up to a receive buffer of
/// `rcvbuf` bytes beyond what it read).
fn connection(
    read_rate: f64,
    ack_rate: f64,
    stop: f64,
    rcvbuf: f64,
) -> impl Fn(f64) -> Option<TcpProgress> {
    move |t: f64| {
        let read = read_rate * t.min(stop);
        let acked = (ack_rate * t).min(read + rcvbuf);
        Some(TcpProgress {
            acked: acked as u64,
            window_end: (read + rcvbuf) as u64,
            segments: (acked / 1448.0) as u64,
            window_scale: 7,
        })
    }
}

#[test]
fn a_frozen_client_is_gone_though_its_kernel_still_acknowledges() {
    // Frozen at 35 s: no more answers; its kernel acknowledges 1 MB/s into a 6 MB
    // buffer, which fills only at about 41 s.
    let client = Client {
        answers: Box::new(|t| (t < 35.0).then_some(0.005)),
        socket: Box::new(connection(1e6, 1e6, 35.0, 6e6)),
    };
    let (gone, _) = run(&client, 600.0);
    let gone = gone.expect("taken as gone");
    // Its last answer was to the ping at 30 s.
    assert!((gone - 60.005).abs() < 1e-6, "gone at {gone}");
}

#[test]
fn a_slow_reader_behind_a_long_queue_is_kept_while_it_reads() {
    // Reads 32 KB/s (256 kbit/s); its pongs sit behind 4 MB: two minutes late. It
    // stops reading at 300 s.
    let client = Client {
        answers: Box::new(|t| (t < 300.0 - 125.0).then_some(125.0)),
        socket: Box::new(connection(32e3, 32e3, 300.0, 64e3)),
    };
    let (gone, _) = run(&client, 1000.0);
    let gone = gone.expect("taken as gone once it stopped reading");
    assert!(
        (300.0..=300.0 + 30.0).contains(&gone),
        "gone at {gone}: kept while it read, gone within the silence limit of its last read"
    );
}

#[test]
fn a_cut_link_is_gone_at_the_silence_limit() {
    // Nothing answered or acknowledged after 12 s.
    let client = Client {
        answers: Box::new(|t| (t < 12.0).then_some(0.005)),
        socket: Box::new(connection(1e5, 1e5, 12.0, 0.0)),
    };
    let (gone, _) = run(&client, 600.0);
    assert!((gone.expect("gone") - 40.005).abs() < 1e-6);
}

#[test]
fn a_window_that_creeps_by_rounding_is_not_progress() {
    let at = |acked: u64, window_end: u64, segments: u64| TcpProgress {
        acked,
        window_end,
        segments,
        window_scale: 7,
    };
    let before = at(1_000_000, 7_000_000, 1_000);
    // A receiver that does not read rounds its window up to its unit (128 bytes):
    // bulk data moves the edge by up to 127 bytes a segment...
    let bulk = at(1_500_000, 7_000_000 + 345 * 127, 1_345);
    assert!(!bulk.progressed_since(&before));
    // ... and a ping of 16 bytes by its 16 bytes.
    let ping = at(1_000_016, 7_000_016, 1_001);
    assert!(!ping.progressed_since(&before));
    // An application that reads moves it as far as it acknowledges.
    let read = at(1_500_000, 7_400_000, 1_345);
    assert!(read.progressed_since(&before));
    // A window update with nothing acknowledged (the reader caught up) is progress.
    let update = at(1_000_000, 7_002_896, 1_000);
    assert!(update.progressed_since(&before));
    assert!(!before.progressed_since(&before));
    // A receiver widening its window before it reads, two segments for each one it
    // gets, is taken for a reader: for as long as its buffer lets it, a few seconds at
    // most (see `a_frozen_client_is_gone_though_its_kernel_still_acknowledges`).
    let widening = at(1_014_480, 7_028_960, 1_010);
    assert!(widening.progressed_since(&before));
}

#[test]
fn a_client_is_never_gone_before_the_silence_limit_after_its_last_progress() {
    // Reading stops at many moments between samples: it is taken as gone no sooner than
    // two sample periods before the silence limit after its last read (a read in the
    // last part of a period may not be told from its kernel's acknowledgements), and no
    // later than the limit.
    for tenth in 0..40 {
        let stop = 100.0 + f64::from(tenth) / 10.0;
        let client = Client {
            answers: Box::new(|_| None),
            socket: Box::new(connection(32e3, 32e3, stop, 64e3)),
        };
        let (gone, _) = run(&client, 1000.0);
        let gone = gone.expect("gone");
        assert!(
            gone >= stop + 28.0 && gone <= stop + 30.0,
            "stopped at {stop}, gone at {gone}"
        );
    }
}
