//! Why a connection to the hub failed, and what the robot's operator is told to do about
//! it: transient failures (the robot's link, the hub) are retried with backoff, permanent
//! ones (credentials, certificates, protocol) say what to change.

use super::*;

/// Why a connection attempt failed, which decides how soon to try again.
#[derive(Debug)]
pub(super) enum Failure {
    /// The robot's own network: unreachable, connect timed out.
    Link(String),
    /// No route at all (the interface is down): failed locally, nothing was sent.
    NoRoute(String),
    /// The hub refused, failed or is overloaded; `retry_after` if it said when to return.
    Hub {
        reason: String,
        retry_after: Option<Duration>,
    },
    /// Will not go away by retrying: refused credentials, an untrusted certificate, a
    /// protocol mismatch. `reason` says what to do.
    Permanent(String),
}

impl Failure {
    pub(super) fn hub(reason: String) -> Failure {
        Failure::Hub {
            reason,
            retry_after: None,
        }
    }

    pub(super) fn into_reason(self) -> String {
        match self {
            Failure::Link(r) | Failure::NoRoute(r) | Failure::Permanent(r) => r,
            Failure::Hub { reason, .. } => reason,
        }
    }
}

/// Rate limit of the "hub link down" warning.
#[derive(Default)]
pub(super) struct FailureLog {
    last: Option<(std::time::Instant, String)>,
    pub(super) repeats: u32,
}

impl FailureLog {
    const EVERY: Duration = Duration::from_secs(10);

    /// Whether to log a failure with `reason` now (and remember it as logged).
    pub(super) fn due(&mut self, reason: &str) -> bool {
        let now = std::time::Instant::now();
        // Addresses and counters vary; the part before the first ':' names the failure.
        let kind = reason.split(':').next().unwrap_or(reason);
        let due = match &self.last {
            Some((at, k)) => k != kind || now.duration_since(*at) >= Self::EVERY,
            None => true,
        };
        if due {
            self.last = Some((now, kind.to_owned()));
        }
        due
    }
}

/// The delay a refusal's `Retry-After` header asks for (whole seconds), if any.
pub fn retry_after(headers: &tokio_tungstenite::tungstenite::http::HeaderMap) -> Option<Duration> {
    headers
        .get("Retry-After")
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.trim().parse::<u64>().ok())
        .map(Duration::from_secs)
}

/// Classifies a failed WebSocket/TLS handshake.
pub(super) fn handshake_failure(url: &str, e: tokio_tungstenite::tungstenite::Error) -> Failure {
    use tokio_tungstenite::tungstenite::Error as E;
    match e {
        E::Http(resp) => {
            let retry_after = retry_after(resp.headers());
            Failure::Hub {
                reason: format!("the hub at {url} answered HTTP {}", resp.status()),
                retry_after,
            }
        }
        E::Io(io) => match io.get_ref().and_then(|e| e.downcast_ref::<rustls::Error>()) {
            Some(tls) => Failure::Permanent(tls_advice(url, tls)),
            None => Failure::Link(format!("connection to {url} failed: {io}")),
        },
        other => Failure::hub(format!("handshake with {url} failed: {other}")),
    }
}

/// What the hub's refusal of `HELLO` means and what to do about it. Refused
/// credentials, a bad name or a protocol mismatch do not go away by retrying; a rate
/// limit or an unavailable credential store do.
pub(super) fn refusal(text: &str, url: &str, robot: &str, token: &str) -> Failure {
    let mint = format!(
        "create one on the hub with `fleetlink admin --data-dir <hub data dir> token robot \
         {robot}` and set it as `token:` in this agent's configuration"
    );
    if let Some(secs) = text
        .strip_prefix("too many failed logins; retry in ")
        .and_then(|r| r.trim_end_matches(" s").parse::<u64>().ok())
    {
        return Failure::Hub {
            reason: format!("the hub at {url} is rate-limiting logins from this address"),
            retry_after: Some(Duration::from_secs(secs)),
        };
    }
    match text {
        "authentication unavailable" => Failure::hub(format!(
            "the hub at {url} cannot check credentials right now (its credential store failed)"
        )),
        "authentication required" if token.is_empty() => Failure::Permanent(format!(
            "the hub at {url} requires a robot token and this agent has none: {mint}"
        )),
        "authentication required" | "authentication failed" => Failure::Permanent(format!(
            "the hub at {url} refused the token of robot {robot} ({}): it is unknown, \
                 revoked, expired or issued for another robot; {mint}",
            token_hint(token)
        )),
        other => Failure::Permanent(format!("the hub at {url} refused this agent: {other}")),
    }
}

/// A token's first characters, enough to tell which one was used without revealing it.
fn token_hint(token: &str) -> String {
    let shown: String = token.chars().take(14).collect();
    if shown.len() < token.len() {
        format!("{shown}…")
    } else {
        "a short token".to_owned()
    }
}

/// What a TLS failure with the hub means, in words that say what to do.
fn tls_advice(url: &str, e: &rustls::Error) -> String {
    use fleetlink_auth::tls::HubCertError;
    use rustls::CertificateError as C;
    let host = url
        .split("://")
        .nth(1)
        .and_then(|r| r.split(['/', ':']).next())
        .unwrap_or(url);
    match e {
        rustls::Error::InvalidCertificate(c) => match c {
            C::UnknownIssuer => format!(
                "the certificate of the hub at {url} is not issued by a CA this agent trusts: \
                 give the CA that issued it — or the certificate itself, if it is self-signed — \
                 as `tls.ca` in this agent's configuration"
            ),
            C::NotValidForName | C::NotValidForNameContext { .. } => format!(
                "the certificate of the hub at {url} is not issued for the name {host}: connect \
                 with a name the certificate lists, or reissue it with {host} as a subject \
                 alternative name"
            ),
            C::Expired | C::ExpiredContext { .. } => format!(
                "the certificate of the hub at {url} has expired: renew it on the hub (or check \
                 this robot's clock)"
            ),
            C::NotValidYet | C::NotValidYetContext { .. } => format!(
                "the certificate of the hub at {url} is not valid yet: check this robot's clock"
            ),
            C::Revoked => format!("the certificate of the hub at {url} has been revoked"),
            C::Other(_) if HubCertError::of(e) == Some(&HubCertError::SelfSigned) => format!(
                "the certificate of the hub at {url} is self-signed and this agent does not \
                 trust it: give that certificate (the hub's --tls-cert file) as `tls.ca` in \
                 this agent's configuration (see \"TLS in five minutes\" in docs/tls.md)"
            ),
            C::Other(_) if HubCertError::of(e) == Some(&HubCertError::CaAsServer) => format!(
                "the hub at {url} presents a CA certificate as its own: give the hub a \
                 certificate issued by that CA (`fleetlink admin cert hub`), or give this very \
                 certificate as `tls.ca` to pin it"
            ),
            _ => format!(
                "the certificate of the hub at {url} could not be verified ({}); check `tls.ca`",
                certificate_problem(c)
            ),
        },
        rustls::Error::AlertReceived(alert) => format!(
            "the hub at {url} ended the TLS handshake ({alert:?}): if it requires client \
             certificates, check `tls.cert` and `tls.key`"
        ),
        other => format!("TLS with the hub at {url} failed: {other}"),
    }
}

/// A certificate problem in a few words (rustls' own text is a debug dump of its enum).
fn certificate_problem(c: &rustls::CertificateError) -> &'static str {
    use rustls::CertificateError as C;
    match c {
        C::BadEncoding => "it is not a valid certificate",
        C::BadSignature => "its signature is wrong",
        C::UnsupportedSignatureAlgorithmContext { .. }
        | C::UnsupportedSignatureAlgorithmForPublicKeyContext { .. } => {
            "it is signed with an algorithm this agent does not support"
        }
        C::InvalidPurpose | C::InvalidPurposeContext { .. } => "it is not for TLS servers",
        _ => "see the hub's certificate chain",
    }
}

/// Issue 14: permanent failures are told apart from transient ones and say what to do.
#[cfg(test)]
mod failure_tests {
    use super::*;

    const URL: &str = "wss://hub.example:8080/";

    #[test]
    fn refused_credentials_are_permanent_and_say_how_to_mint_a_token() {
        let Failure::Permanent(m) = refusal("authentication required", URL, "robot4", "") else {
            panic!("no token must be permanent");
        };
        assert!(m.contains("has none"), "{m}");
        assert!(m.contains("fleetlink admin --data-dir"), "{m}");
        assert!(m.contains("token robot robot4"), "{m}");
        let Failure::Permanent(m) = refusal(
            "authentication failed",
            URL,
            "robot4",
            "flk_robot_abcdefghijklmnop",
        ) else {
            panic!("a refused token must be permanent");
        };
        assert!(
            m.contains("flk_robot_abcd…"),
            "the token is named, not shown: {m}"
        );
        assert!(!m.contains("abcdefghijklmnop"), "{m}");
        assert!(
            !m.contains("authentication failed: authentication failed"),
            "{m}"
        );
    }

    #[test]
    fn a_rate_limit_is_transient_with_the_hubs_delay() {
        match refusal("too many failed logins; retry in 30 s", URL, "r", "t") {
            Failure::Hub { retry_after, .. } => {
                assert_eq!(retry_after, Some(Duration::from_secs(30)));
            }
            other => panic!("expected a transient failure, got {other:?}"),
        }
    }

    #[test]
    fn certificate_problems_name_the_setting_to_change() {
        use rustls::CertificateError as C;
        let advice = |c: C| tls_advice(URL, &rustls::Error::InvalidCertificate(c));
        assert!(advice(C::UnknownIssuer).contains("`tls.ca`"));
        assert!(advice(C::NotValidForName).contains("hub.example"));
        assert!(advice(C::Expired).contains("expired"));
        let ours = |h: fleetlink_auth::tls::HubCertError| {
            advice(C::Other(rustls::OtherError(std::sync::Arc::new(h))))
        };
        let selfsigned = ours(fleetlink_auth::tls::HubCertError::SelfSigned);
        assert!(selfsigned.contains("self-signed"), "{selfsigned}");
        assert!(selfsigned.contains("as `tls.ca`"), "{selfsigned}");
        let ca = ours(fleetlink_auth::tls::HubCertError::CaAsServer);
        assert!(ca.contains("CA certificate as its own"), "{ca}");
        for m in [advice(C::BadSignature), advice(C::UnknownIssuer)] {
            assert!(!m.contains("Some(") && !m.contains("OtherError"), "{m}");
        }
    }
}
