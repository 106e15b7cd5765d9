//! `fleetlink hub`: run the relay.

use std::net::SocketAddr;
use std::path::PathBuf;
use std::time::Duration;

use anyhow::Context;
use fleetlink_hub::{Hub, HubConfig};

#[derive(clap::Args)]
pub struct Args {
    /// Address and port for agents, rosbridge clients and HTTP.
    #[arg(long, default_value = "127.0.0.1:8080")]
    pub listen: SocketAddr,
    /// Where the hub keeps its SQLite database and files.
    #[arg(long, default_value = "./fleetlink-data")]
    pub data_dir: PathBuf,
    /// Heartbeat interval for agents that do not ask for one (milliseconds).
    #[arg(long, default_value_t = 1000)]
    pub heartbeat_ms: u64,
    /// Largest WebSocket message accepted from a client (bytes).
    #[arg(long, default_value_t = 16 << 20)]
    pub max_message_size: usize,
    /// Queue length of subscriptions that do not ask for one.
    #[arg(long, default_value_t = 100)]
    pub queue_length: usize,
}

impl Args {
    pub fn config(&self) -> HubConfig {
        HubConfig {
            listen: self.listen,
            data_dir: self.data_dir.clone(),
            heartbeat: Duration::from_millis(self.heartbeat_ms.max(10)),
            max_message_size: self.max_message_size,
            default_queue: self.queue_length.max(1),
        }
    }
}

pub fn run(args: Args) -> anyhow::Result<()> {
    super::init_logging("info");
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(async {
        let hub = Hub::bind(args.config(), crate::transcoder()).await?;
        let addr = hub.local_addr();
        println!("fleetlink hub listening on {addr}");
        println!("  dashboard:  http://{addr}/");
        println!("  rosbridge:  ws://{addr}/   agents: ws://{addr}/ (subprotocol fleetlink.v1)");
        hub.run(super::shutdown_signal()).await?;
        println!("fleetlink hub stopped");
        Ok::<_, anyhow::Error>(())
    })?;
    Ok(())
}
