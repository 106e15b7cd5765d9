//! Connecting to the hub over a link that may just be coming back: staggered TCP connects.

use super::*;

/// TCP connect to `host:port` with staggered attempts: the name is resolved once, then a
/// connect starts every [`CONNECT_STAGGER`] (cycling through the addresses) while none has
/// completed, and the first to complete wins; the others are dropped, which closes them.
/// A failed attempt ends the race only when the others would share its failure (refused,
/// no route, with one address) or nothing else is pending and every address was tried;
/// the caller bounds the time.
pub(super) async fn connect_staggered(
    host: &str,
    port: u16,
) -> std::io::Result<tokio::net::TcpStream> {
    use futures_util::stream::FuturesUnordered;
    use std::io::ErrorKind as K;
    let addrs: Vec<std::net::SocketAddr> = tokio::net::lookup_host((host, port)).await?.collect();
    if addrs.is_empty() {
        return Err(std::io::Error::new(
            K::NotFound,
            format!("{host} resolved to no address"),
        ));
    }
    let mut racing = FuturesUnordered::new();
    let mut started = 0usize;
    let mut last_err: Option<std::io::Error> = None;
    let mut next = tokio::time::Instant::now();
    loop {
        if started < CONNECT_RACE && tokio::time::Instant::now() >= next {
            racing.push(tokio::net::TcpStream::connect(addrs[started % addrs.len()]));
            started += 1;
            next = tokio::time::Instant::now() + CONNECT_STAGGER;
        }
        if racing.is_empty() {
            return Err(last_err.unwrap_or_else(|| K::TimedOut.into()));
        }
        let more = started < CONNECT_RACE;
        tokio::select! {
            done = racing.next() => match done {
                Some(Ok(s)) => return Ok(s),
                Some(Err(e)) => {
                    // Refused or unroutable: every attempt to that one address would fail
                    // the same way, so say so now.
                    let shared = matches!(
                        e.kind(),
                        K::ConnectionRefused
                            | K::NetworkUnreachable
                            | K::NetworkDown
                            | K::HostUnreachable
                    );
                    if (shared && addrs.len() == 1)
                        || (racing.is_empty() && started >= addrs.len().min(CONNECT_RACE))
                    {
                        return Err(e);
                    }
                    last_err = Some(e);
                    // The next address now rather than at the next tick.
                    next = tokio::time::Instant::now();
                }
                None => {}
            },
            _ = tokio::time::sleep_until(next), if more => {}
        }
    }
}

#[cfg(test)]
mod connect_tests {
    use super::*;
    use std::time::Instant;

    /// When the path clears, and when a single connect and a staggered one, both started
    /// while SYNs were being dropped, got through.
    struct Race {
        cleared: Duration,
        single: Duration,
        staggered: Duration,
    }

    /// A listener whose accept queue is full drops new SYNs, as a path does in the moments
    /// after it comes back. A single connect and a staggered one start together; 1.1 s in,
    /// just after the single connect's first SYN retransmission, the listener starts
    /// taking connections.
    async fn race() -> Race {
        let sock = socket2::Socket::new(socket2::Domain::IPV4, socket2::Type::STREAM, None)
            .expect("socket");
        let any: std::net::SocketAddr = "127.0.0.1:0".parse().unwrap();
        sock.bind(&any.into()).expect("bind");
        sock.listen(0).expect("listen"); // an accept queue of one
        let listener: std::net::TcpListener = sock.into();
        let port = listener.local_addr().unwrap().port();
        // Fill the queue: from here on the listener drops SYNs.
        let queued = std::net::TcpStream::connect(("127.0.0.1", port)).expect("first connect");

        let start = Instant::now();
        let timed = |f: tokio::task::JoinHandle<std::io::Result<tokio::net::TcpStream>>| async {
            f.await.unwrap().expect("connected");
            start.elapsed()
        };
        let single = tokio::spawn(tokio::net::TcpStream::connect(("127.0.0.1", port)));
        let staggered = tokio::spawn(connect_staggered("127.0.0.1", port));
        tokio::time::sleep(Duration::from_millis(1100)).await;
        assert!(
            !single.is_finished() && !staggered.is_finished(),
            "the test's premise: SYNs to a full accept queue are dropped"
        );
        let cleared = start.elapsed();
        let accepting = std::thread::spawn(move || {
            let mut held = vec![queued];
            while held.len() < 2 + 1 + CONNECT_RACE {
                match listener.accept() {
                    Ok((s, _)) => held.push(s),
                    Err(_) => break,
                }
            }
        });
        let (single, staggered) = tokio::time::timeout(Duration::from_secs(10), async {
            tokio::join!(timed(single), timed(staggered))
        })
        .await
        .expect("both connected within 10 s");
        drop(accepting); // detached; it ends with the test process
        Race {
            cleared,
            single,
            staggered,
        }
    }

    /// The staggered connect gets through at its next fresh SYN (one is due every 250 ms),
    /// well before the single one, which waits for the kernel's next retransmission (the
    /// first few are 1 s apart; later ones back off). A run whose clearing came late (the
    /// test's own sleep overran on a loaded machine) proves nothing and is repeated.
    #[tokio::test(flavor = "current_thread")]
    async fn a_connect_whose_first_syns_are_lost_gets_through_before_a_single_one() {
        let mut runs = Vec::new();
        for _ in 0..3 {
            let r = race().await;
            if r.cleared < Duration::from_millis(1500) {
                assert!(
                    r.staggered + Duration::from_millis(300) < r.single,
                    "path cleared at {:?}; staggered connect at {:?}, single connect at {:?}",
                    r.cleared,
                    r.staggered,
                    r.single
                );
                return;
            }
            runs.push(r.cleared);
        }
        panic!("the test's own 1.1 s sleep overran every time: cleared at {runs:?}");
    }
}
