//! One module per subcommand, each with an `Args` struct and a `run` function.

pub mod admin;
pub mod agent;
pub mod bench;
pub mod demo;
pub mod hub;
mod log_limit;
pub mod msg;
pub mod qoi_sim;

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
    use tracing_subscriber::layer::{Layer, SubscriberExt};
    use tracing_subscriber::util::SubscriberInitExt;
    // rustdds narrates every socket and match at info, and warns about every datagram
    // over its MTU guess and every long fragment NACK (normal for 1 MB samples): only
    // its other warnings are worth showing.
    let asked = std::env::var("RUST_LOG").ok();
    let filter = tracing_subscriber::EnvFilter::try_from_default_env()
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new(format!(
            "{default},rustdds=warn,rustdds::structure::sequence_number=off,rustdds::network::udp_sender=error"
        )));
    let repeats = asked
        .is_none_or(|v| !v.contains("rustdds"))
        .then(|| log_limit::Repeats::new("rustdds", std::time::Duration::from_secs(60)));
    let _ = tracing_subscriber::registry()
        .with(
            tracing_subscriber::fmt::layer()
                .with_writer(std::io::stderr)
                .with_filter(filter)
                .with_filter(repeats),
        )
        .try_init();
}
