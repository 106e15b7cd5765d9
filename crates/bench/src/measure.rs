//! A bench's summary and the runtime its measurement runs on: shared by the subcommands
//! that measure on a multi-thread runtime and print one summary at the end.

/// A bench's final summary: one JSON object with `--json`, else text.
pub trait Report: serde::Serialize {
    fn text(&self) -> String;
}

/// Runs `measure` on a multi-thread runtime (`threads` workers, default one per core) and
/// prints its summary. Connections still open are dropped with the runtime; nothing
/// waits for the hub to close them.
pub fn run_measurement<R: Report>(
    threads: Option<usize>,
    json: bool,
    measure: impl Future<Output = anyhow::Result<R>>,
) -> anyhow::Result<()> {
    use anyhow::Context;
    let mut rt = tokio::runtime::Builder::new_multi_thread();
    if let Some(n) = threads {
        rt.worker_threads(n.max(1));
    }
    let rt = rt
        .enable_all()
        .build()
        .context("starting the async runtime")?;
    let summary = rt.block_on(measure)?;
    if json {
        println!("{}", serde_json::to_string(&summary)?);
    } else {
        print!("{}", summary.text());
    }
    rt.shutdown_timeout(std::time::Duration::from_millis(200));
    Ok(())
}
