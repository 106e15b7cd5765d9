//! Assembling an agent: local router, hub link, local listener and simulator.

use std::net::SocketAddr;
use std::sync::Arc;

use fleetlink_relay::Router;
use fleetlink_relay::rosbridge::SessionConfig;
use fleetlink_relay::transcode::Transcoder;
use tokio::net::TcpListener;
use tokio::sync::watch;
use tokio_util::sync::CancellationToken;

use crate::uplink::{LinkState, Uplink, UplinkConfig, UplinkStats};

/// Everything an agent needs to run (the CLI builds it from flags and the YAML file).
#[derive(Debug, Clone)]
pub struct AgentOptions {
    pub uplink: UplinkConfig,
    /// Where local rosbridge clients connect; `None` disables the listener.
    pub local_listen: Option<SocketAddr>,
}

/// A bound agent, ready to run.
pub struct Agent {
    router: Arc<Router>,
    uplink: Uplink,
    local: Option<TcpListener>,
}

#[derive(Debug, thiserror::Error)]
pub enum AgentError {
    #[error("cannot listen for local rosbridge clients on {addr}: {source}")]
    Bind {
        addr: SocketAddr,
        source: std::io::Error,
    },
}

impl Agent {
    pub async fn bind(
        opts: AgentOptions,
        transcoder: Arc<dyn Transcoder>,
    ) -> Result<Agent, AgentError> {
        let local = match opts.local_listen {
            Some(addr) => Some(
                crate::local::bind(addr)
                    .await
                    .map_err(|source| AgentError::Bind { addr, source })?,
            ),
            None => None,
        };
        let router = Arc::new(Router::new(transcoder));
        let uplink = Uplink::new(opts.uplink, router.clone());
        Ok(Agent {
            router,
            uplink,
            local,
        })
    }

    /// The local router (the simulator and tests publish into it).
    pub fn router(&self) -> Arc<Router> {
        self.router.clone()
    }

    pub fn local_addr(&self) -> Option<SocketAddr> {
        self.local.as_ref().and_then(|l| l.local_addr().ok())
    }

    pub fn link_state(&self) -> watch::Receiver<LinkState> {
        self.uplink.watch()
    }

    pub fn uplink_stats(&self) -> Arc<UplinkStats> {
        self.uplink.stats.clone()
    }

    /// Runs until `shutdown` is cancelled.
    pub async fn run(self, shutdown: CancellationToken) {
        let local = self.local.map(|l| {
            let cfg = Arc::new(SessionConfig {
                node_name: "/fleetlink_agent".into(),
                ..SessionConfig::default()
            });
            tokio::spawn(crate::local::serve(
                l,
                self.router.clone(),
                cfg,
                shutdown.clone(),
            ))
        });
        self.uplink.run(shutdown.clone()).await;
        if let Some(l) = local {
            let _ = l.await;
        }
    }
}
