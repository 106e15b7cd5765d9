//! One module per subcommand, each with an `Args` struct and a `run` function.

pub mod admin;
pub mod agent;
pub mod bench;
pub mod check;
pub mod demo;
pub mod federation;
pub mod hub;
mod log_limit;
pub mod msg;
pub mod play;
pub mod qoi_sim;
pub mod record;
pub mod upstream;

/// A running hub as the CLI reaches it (`record`, `play` and `bench record` share it).
pub use fleetlink_remote as remote;

/// Completes on Ctrl-C or SIGTERM.
pub async fn shutdown_signal() {
    {
        let ctrl_c = async {
            let _ = tokio::signal::ctrl_c().await;
        };
        #[cfg(unix)]
        let term = async {
            match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
                Ok(mut s) => {
                    s.recv().await;
                }
                Err(_) => std::future::pending::<()>().await,
            }
        };
        #[cfg(not(unix))]
        let term = std::future::pending::<()>();
        tokio::select! {
            _ = ctrl_c => {}
            _ = term => {}
        }
    }
}

/// Logs to stderr; `RUST_LOG` overrides the default level.
///
/// Each of rustdds' log lines is shown at most once a minute from each place in its code
/// ([`log_limit`]), unless `RUST_LOG` names rustdds (then everything it asks for).
pub fn init_logging(default: &str) {
    use tracing_subscriber::util::SubscriberInitExt;
    let rust_log = std::env::var("RUST_LOG").ok();
    let _ = log_subscriber(default, rust_log.as_deref(), std::io::stderr).try_init();
}

/// What [`init_logging`] installs, given the default level and `RUST_LOG`.
///
/// The level filter is the outermost filter: the most verbose level it lets through is
/// the process's maximum level, which `log` records (rustdds, tungstenite) are checked
/// against before they are made. rustdds and tungstenite write debug and trace records
/// for every fragment and frame; below the maximum they cost one comparison, above it a
/// trip through `tracing-log` and the filters (7 % of an agent bridging 10 MB/s of point
/// clouds when the outer filter left the maximum at trace).
fn log_subscriber<W>(
    default: &str,
    rust_log: Option<&str>,
    writer: W,
) -> impl tracing::Subscriber + Send + Sync
where
    W: for<'w> tracing_subscriber::fmt::MakeWriter<'w> + Send + Sync + 'static,
{
    use tracing_subscriber::layer::{Layer, SubscriberExt};
    // rustdds narrates every socket and match at info, and warns about every datagram
    // over its MTU guess and every long fragment NACK (normal for 1 MB samples): only
    // its other warnings are worth showing. Zenoh (a federated hub) narrates its
    // session's endpoints and links at info: its warnings say what matters.
    let filter = rust_log
        .and_then(|v| tracing_subscriber::EnvFilter::try_new(v).ok())
        .unwrap_or_else(|| tracing_subscriber::EnvFilter::new(format!(
            "{default},zenoh=warn,rustdds=warn,rustdds::structure::sequence_number=off,rustdds::network::udp_sender=error"
        )));
    let repeats = rust_log
        .is_none_or(|v| !v.contains("rustdds"))
        .then(|| log_limit::Repeats::new("rustdds", std::time::Duration::from_secs(60)));
    tracing_subscriber::registry().with(
        tracing_subscriber::fmt::layer()
            .with_writer(writer)
            .with_filter(repeats)
            .with_filter(filter),
    )
}

/// The hard limit on open files, if there is one.
pub fn open_files_limit() -> Option<u64> {
    rustix::process::getrlimit(rustix::process::Resource::Nofile).maximum
}

/// Raises this process's soft limit on open files to at least `want` (up to the hard
/// limit): every connection is a file, and the usual soft limit of 1,024 would cap a hub
/// or a fleet bench far below what it can carry. Above the hard limit it goes as far as
/// that and says so.
pub fn raise_open_files(want: u64) -> anyhow::Result<()> {
    use rustix::process::{Resource, getrlimit, setrlimit};
    let lim = getrlimit(Resource::Nofile);
    if lim.current.is_some_and(|c| c >= want) {
        return Ok(());
    }
    let mut new = lim;
    new.current = Some(lim.maximum.map_or(want, |m| m.min(want)));
    setrlimit(Resource::Nofile, new)
        .map_err(|e| anyhow::anyhow!("raising the open-files limit to {want}: {e}"))?;
    if let Some(m) = lim.maximum.filter(|m| *m < want) {
        anyhow::bail!(
            "this needs {want} open files but the hard limit is {m}; \
             raise it (ulimit -Hn, LimitNOFILE= in a systemd unit) or ask for fewer connections"
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use std::sync::{Arc, Mutex};

    use tracing::level_filters::LevelFilter;

    use super::*;

    /// The lines a test's subscriber wrote.
    #[derive(Clone, Default)]
    struct Lines(Arc<Mutex<Vec<u8>>>);

    impl std::io::Write for Lines {
        fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
            self.0.lock().unwrap().extend_from_slice(b);
            Ok(b.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    impl<'w> tracing_subscriber::fmt::MakeWriter<'w> for Lines {
        type Writer = Lines;
        fn make_writer(&'w self) -> Lines {
            self.clone()
        }
    }

    #[test]
    fn the_level_filter_sets_the_maximum_level_so_debug_records_of_dependencies_stop_at_once() {
        use tracing::Subscriber;
        let hint = |default, rust_log| {
            log_subscriber(default, rust_log, Lines::default()).max_level_hint()
        };
        assert_eq!(hint("info", None), Some(LevelFilter::INFO));
        assert_eq!(hint("warn", None), Some(LevelFilter::WARN));
        assert_eq!(
            hint("info", Some("rustdds=debug,warn")),
            Some(LevelFilter::DEBUG)
        );
        assert_eq!(hint("info", Some("error")), Some(LevelFilter::ERROR));
    }

    #[test]
    fn the_default_filter_shows_ours_and_one_line_of_a_rustdds_flood() {
        let _ = tracing_log::LogTracer::init();
        let out = Lines::default();
        let subscriber = log_subscriber("info", None, out.clone());
        tracing::subscriber::with_default(subscriber, || {
            for i in 0..100 {
                log::warn!(target: "rustdds::rtps::writer", "no locators for reader {i}");
                log::info!(target: "rustdds::rtps::reader", "HeartbeatFrag handling not implemented {i}");
                log::debug!(target: "rustdds::rtps::fragment_assembler", "new_datafrag {i}");
            }
            tracing::info!(target: "fleetlink_ros2::bridge", "ours");
            tracing::debug!(target: "fleetlink_ros2::bridge", "ours, in detail");
        });
        let text = String::from_utf8(out.0.lock().unwrap().clone()).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2, "{text}");
        assert!(lines[0].contains("no locators for reader 0"), "{text}");
        assert!(lines[1].contains("ours"), "{text}");
    }
}
