//! What the bridge is told to do (the agent builds this from its `rosbridge:` section).

use std::sync::Arc;
use std::time::Duration;

use fleetlink_relay::TopicName;
pub use fleetlink_relay::names::NameFilter;

#[derive(Debug, Clone)]
pub struct RosbridgeClientOptions {
    /// `ws://HOST:PORT[/path]` or `wss://…` of the robot's rosbridge server.
    pub url: String,
    /// Sent as the `?token=` query parameter when not empty (what fleetlink hubs and
    /// token-checking proxies in front of rosbridge servers read).
    pub token: String,
    /// The server's topics published into the agent's router (and so up to the hub).
    pub publish: NameFilter,
    /// Router topics (hub topics brought down) advertised and published on the server.
    pub subscribe: Vec<TopicName>,
    /// The server's services offered to the fleet.
    pub expose: NameFilter,
    /// Fleet services (as the agent's call table names them) advertised on the server.
    pub offer: NameFilter,
    /// The server's action servers offered to the fleet (goals sent with
    /// `send_action_goal`).
    pub expose_actions: NameFilter,
    /// How often the server's rosapi is asked for new topics, services and actions.
    pub discovery_period: Duration,
    /// How long a call forwarded to the server, or a server program's call of a fleet
    /// service, may take.
    pub call_timeout: Duration,
    /// First delay before connecting again after the link dropped; doubles up to
    /// `reconnect_max`.
    pub reconnect_initial: Duration,
    pub reconnect_max: Duration,
    /// TLS for a `wss://` server; `None` uses the system's roots.
    pub tls: Option<Arc<rustls::ClientConfig>>,
}

impl RosbridgeClientOptions {
    /// Options for `url` with nothing bridged and the documented defaults.
    pub fn new(url: impl Into<String>) -> RosbridgeClientOptions {
        RosbridgeClientOptions {
            url: url.into(),
            token: String::new(),
            publish: NameFilter::default(),
            subscribe: Vec::new(),
            expose: NameFilter::default(),
            offer: NameFilter::default(),
            expose_actions: NameFilter::default(),
            discovery_period: Duration::from_secs(5),
            call_timeout: Duration::from_secs(10),
            reconnect_initial: Duration::from_millis(200),
            reconnect_max: Duration::from_secs(10),
            tls: None,
        }
    }

    /// The URL connected to: `url` with `token=` added to its query when there is one.
    pub fn connect_url(&self) -> Result<String, crate::RosbridgeClientError> {
        check_url(&self.url)?;
        if self.token.is_empty() {
            return Ok(self.url.clone());
        }
        let token: String = self
            .token
            .bytes()
            .map(|b| match b {
                b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'~' => {
                    (b as char).to_string()
                }
                other => format!("%{other:02X}"),
            })
            .collect();
        let (base, fragment) = match self.url.split_once('#') {
            Some((b, f)) => (b, Some(f)),
            None => (self.url.as_str(), None),
        };
        let sep = if base.contains('?') { '&' } else { '?' };
        let mut out = format!("{base}{sep}token={token}");
        if let Some(f) = fragment {
            out.push('#');
            out.push_str(f);
        }
        Ok(out)
    }
}

/// A `ws://` or `wss://` URL that names a host: anything else is a configuration error,
/// reported at start and never retried.
pub fn check_url(url: &str) -> Result<(), crate::RosbridgeClientError> {
    let bad = |why: String| crate::RosbridgeClientError::Url {
        url: url.to_owned(),
        why,
    };
    if !(url.starts_with("ws://") || url.starts_with("wss://")) {
        return Err(bad("must start with ws:// or wss://".into()));
    }
    match url.parse::<tokio_tungstenite::tungstenite::http::Uri>() {
        Ok(uri) if uri.host().is_some_and(|h| !h.is_empty()) => Ok(()),
        Ok(_) => Err(bad("names no host (expected ws://HOST:PORT)".into())),
        Err(e) => Err(bad(format!("is not a valid URL ({e})"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn token_goes_into_the_query() {
        let mut o = RosbridgeClientOptions::new("ws://robot:9090");
        assert_eq!(o.connect_url().unwrap(), "ws://robot:9090");
        o.token = "a b&c".into();
        assert_eq!(o.connect_url().unwrap(), "ws://robot:9090?token=a%20b%26c");
        o.url = "ws://robot:9090/x?y=1".into();
        assert_eq!(
            o.connect_url().unwrap(),
            "ws://robot:9090/x?y=1&token=a%20b%26c"
        );
    }

    #[test]
    fn a_url_that_is_not_websocket_is_an_error() {
        let e = RosbridgeClientOptions::new("http://robot:9090")
            .connect_url()
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "rosbridge: url \"http://robot:9090\" must start with ws:// or wss://"
        );
    }
}
