//! Participants rustdds gave up on while they still announce themselves.
//!
//! rustdds drops a remote participant when its lease runs out, and a short outage of the
//! robot's network does that: a cable, a switch or a Wi-Fi bridge gone for a few seconds
//! loses the participant's announcements for longer than its lease (Cyclone DDS: 10 s,
//! announced every 8 s). The participant itself never noticed anything, since the
//! agent's own announcements reach it again after the outage, so it does not announce
//! itself as new; and rustdds does not take the participant back from the periodic
//! announcements that do arrive (measured with Cyclone: not within minutes). Its topics
//! and services are gone from the bridge for good, though its samples keep arriving.
//!
//! So the bridge listens to DDS discovery announcements itself (the domain's multicast
//! port, bound to the group so no unicast datagram meant for rustdds comes here) and
//! remembers who rustdds lost by lease. A lost participant that still announces itself,
//! and that rustdds has not found again after [`GRACE`], makes the bridge join the graph
//! again with a new participant, which every peer discovers afresh. A participant that
//! crashed announces nothing and changes nothing.

use std::collections::HashMap;
use std::net::{Ipv4Addr, SocketAddr};
use std::time::{Duration, Instant};

use rustdds::{DomainParticipantStatusEvent, LostReason};

/// A participant's GUID prefix: who sent an RTPS message.
pub(crate) type Prefix = [u8; 12];

/// How long rustdds gets to find a lost participant again by itself (it does for peers
/// whose announcements are new samples, such as Fast DDS's).
pub(crate) const GRACE: Duration = Duration::from_secs(3);

/// How long a participant lost by lease is remembered: one that crashed never comes back.
const FORGET: Duration = Duration::from_secs(600);

/// The well-known multicast group of DDS discovery.
const SPDP_GROUP: Ipv4Addr = Ipv4Addr::new(239, 255, 0, 1);

/// Who rustdds lost by lease, and whether each was heard from since.
#[derive(Debug, Default)]
pub(crate) struct LostPeers {
    /// When rustdds lost it, and when it was first heard announcing itself after that.
    lost: HashMap<Prefix, (Instant, Option<Instant>)>,
}

impl LostPeers {
    /// Takes in one of rustdds' participant events.
    pub(crate) fn on_event(&mut self, ev: &DomainParticipantStatusEvent, now: Instant) {
        match ev {
            DomainParticipantStatusEvent::ParticipantLost {
                id,
                reason: LostReason::Timeout { .. },
            } => {
                self.lost
                    .retain(|_, (at, _)| now.duration_since(*at) < FORGET);
                if let Ok(p) = Prefix::try_from(id.as_ref()) {
                    self.lost.insert(p, (now, None));
                }
            }
            // Gone for good (it said so), or found again: nothing to wait for.
            DomainParticipantStatusEvent::ParticipantLost { id, .. } => {
                self.forget(id.as_ref());
            }
            DomainParticipantStatusEvent::ParticipantDiscovered { dpd } => {
                self.forget(dpd.guid.prefix.as_ref());
            }
            _ => {}
        }
    }

    fn forget(&mut self, id: &[u8]) {
        if let Ok(p) = Prefix::try_from(id) {
            self.lost.remove(&p);
        }
    }

    /// `sender` announced itself.
    pub(crate) fn heard(&mut self, sender: Prefix, now: Instant) {
        if let Some((_, heard)) = self.lost.get_mut(&sender) {
            heard.get_or_insert(now);
        }
    }

    /// A participant lost by lease that has been announcing itself for [`GRACE`] without
    /// rustdds finding it again.
    pub(crate) fn stranded(&self, now: Instant) -> Option<Prefix> {
        self.lost
            .iter()
            .find(|(_, (_, heard))| heard.is_some_and(|h| now.duration_since(h) >= GRACE))
            .map(|(p, _)| *p)
    }
}

/// The sender of an RTPS message: the GUID prefix in its header.
pub(crate) fn sender(datagram: &[u8]) -> Option<Prefix> {
    if datagram.get(..4)? != b"RTPS" {
        return None;
    }
    datagram.get(8..20)?.try_into().ok()
}

/// Receives the domain's discovery announcements beside rustdds.
pub(crate) struct Announcements {
    socket: tokio::net::UdpSocket,
    buf: Vec<u8>,
}

impl Announcements {
    /// Joins the discovery group on each of `interfaces` (the addresses rustdds joined).
    pub(crate) fn open(
        domain: u16,
        interfaces: impl Iterator<Item = Ipv4Addr>,
    ) -> std::io::Result<Announcements> {
        use socket2::{Domain, Protocol, Socket, Type};
        // The well-known port of DDS discovery's multicast (RTPS 9.6.1.1: 7400 + 250 d).
        let port = 7400 + 250 * domain;
        let s = Socket::new(Domain::IPV4, Type::DGRAM, Some(Protocol::UDP))?;
        // rustdds and every other participant on this host share the port.
        s.set_reuse_address(true)?;
        s.set_reuse_port(true)?;
        s.set_nonblocking(true)?;
        // Bound to the group, not to 0.0.0.0: only datagrams sent to the group arrive
        // here, and unicast ones to this port stay rustdds' alone.
        s.bind(&SocketAddr::from((SPDP_GROUP, port)).into())?;
        let mut joined = false;
        for a in interfaces {
            joined |= s.join_multicast_v4(&SPDP_GROUP, &a).is_ok();
        }
        if !joined {
            return Err(std::io::Error::other(
                "no interface to join DDS discovery on",
            ));
        }
        Ok(Announcements {
            socket: tokio::net::UdpSocket::from_std(s.into())?,
            buf: vec![0; 64 * 1024],
        })
    }

    /// The sender of the next announcement.
    pub(crate) async fn next(&mut self) -> std::io::Result<Prefix> {
        loop {
            let n = self.socket.recv(&mut self.buf).await?;
            if let Some(p) = self.buf.get(..n).and_then(sender) {
                return Ok(p);
            }
        }
    }
}

/// The sender of the next announcement, if listening (else never).
pub(crate) async fn next(a: &mut Option<Announcements>) -> std::io::Result<Prefix> {
    match a {
        Some(a) => a.next().await,
        None => std::future::pending().await,
    }
}

#[cfg(test)]
mod tests {
    use rustdds::{DomainParticipantStatusEvent as Ev, GUID, LostReason};

    use super::*;

    fn lost(p: Prefix, reason: LostReason) -> Ev {
        let mut guid = [0; 16];
        guid[..12].copy_from_slice(&p);
        Ev::ParticipantLost {
            id: GUID::from_bytes(guid).prefix,
            reason,
        }
    }

    fn timeout() -> LostReason {
        LostReason::Timeout {
            lease: rustdds::Duration::from_secs(10),
            elapsed: rustdds::Duration::from_secs(11),
        }
    }

    #[test]
    fn a_participant_lost_by_lease_that_keeps_announcing_is_stranded_after_the_grace() {
        let (a, b) = ([1; 12], [2; 12]);
        let mut peers = LostPeers::default();
        let t0 = Instant::now();
        peers.on_event(&lost(a, timeout()), t0);
        peers.on_event(&lost(b, timeout()), t0);
        assert_eq!(
            peers.stranded(t0 + Duration::from_secs(60)),
            None,
            "nobody heard yet"
        );
        peers.heard(a, t0 + Duration::from_secs(5));
        peers.heard([3; 12], t0 + Duration::from_secs(5)); // never lost: nothing
        assert_eq!(
            peers.stranded(t0 + Duration::from_secs(6)),
            None,
            "within the grace"
        );
        peers.heard(a, t0 + Duration::from_secs(7)); // the first hearing counts
        assert_eq!(peers.stranded(t0 + Duration::from_secs(8)), Some(a));
    }

    #[test]
    fn a_participant_found_again_or_gone_by_its_own_word_is_not_stranded() {
        let (a, b) = ([1; 12], [2; 12]);
        let mut peers = LostPeers::default();
        let t0 = Instant::now();
        peers.on_event(&lost(a, timeout()), t0);
        peers.on_event(&lost(b, timeout()), t0);
        peers.on_event(&lost(b, LostReason::Disposed), t0);
        peers.heard(a, t0);
        peers.heard(b, t0);
        // What the ParticipantDiscovered event of `a` does (its description has a dozen
        // fields of rustdds' own types).
        peers.forget(&a);
        assert_eq!(peers.stranded(t0 + Duration::from_secs(60)), None);
    }

    #[test]
    fn the_sender_is_read_from_the_rtps_header_and_anything_else_is_ignored() {
        let mut d = b"RTPS\x02\x03\x01\x10".to_vec();
        d.extend_from_slice(&[7; 12]);
        d.extend_from_slice(&[0; 8]);
        assert_eq!(sender(&d), Some([7; 12]));
        assert_eq!(sender(&d[..19]), None, "too short");
        d[0] = b'X';
        assert_eq!(sender(&d), None, "not RTPS");
    }
}
