//! Why a participant's bridging ends and the participant is made again: rustdds' threads
//! stopped, a network address appeared, or a lost peer still announces itself.
//!
//! [`super::run`] acts on each [`End`]. The look at the host's addresses needs no
//! participant, so it is tested here on its own.

/// How often the bridge checks that rustdds' threads still run.
pub(super) const LIVENESS_PERIOD: std::time::Duration = std::time::Duration::from_secs(2);

/// How one participant's bridging ended.
pub(super) enum End {
    Shutdown,
    /// rustdds' own threads have ended: nothing more arrives or leaves.
    ParticipantStopped,
    /// Addresses appeared that the participant does not use (see [`DdsAddresses`]).
    NetworkChanged(Vec<DdsAddress>),
    /// rustdds lost this participant by lease and does not take it back, though it still
    /// announces itself (see [`crate::lost_peers`]).
    StrandedPeer(crate::lost_peers::Prefix),
}

/// One IPv4 address of a multicast-capable interface: where rustdds joins DDS discovery.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct DdsAddress {
    interface: String,
    /// The interface's index: a device removed and added again is a new one (its
    /// multicast memberships went with the old device).
    index: u32,
    pub(super) addr: std::net::Ipv4Addr,
}

impl std::fmt::Display for DdsAddress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {}", self.interface, self.addr)
    }
}

/// The host's addresses as rustdds sees them when a participant starts.
///
/// rustdds joins DDS multicast and picks the unicast addresses it announces once, when a
/// participant is created, from the interfaces then up. An agent started before the robot's
/// network (at boot, before DHCP; a USB Ethernet plugged in later; a Wi-Fi address that
/// changed) would never discover the participants on the new network, nor be discovered by
/// them. The bridge compares the addresses with the last look every [`LIVENESS_PERIOD`]
/// and rejoins the graph when one appeared. One that only went away changes nothing.
#[derive(Debug, Default)]
pub(super) struct DdsAddresses {
    pub(super) seen: std::collections::BTreeSet<DdsAddress>,
}

impl DdsAddresses {
    /// The addresses now; `None` when the system cannot say (nothing is concluded then).
    pub(super) fn now() -> Option<DdsAddresses> {
        use nix::net::if_::InterfaceFlags;
        let mut seen = std::collections::BTreeSet::new();
        // getifaddrs(3): tens of microseconds (netdev, which rustdds uses, also reads
        // each interface's files in /sys: ten times that).
        for a in nix::ifaddrs::getifaddrs().ok()? {
            // As rustdds chooses where to join multicast: the flag, IPv4 only.
            if !a.flags.contains(InterfaceFlags::IFF_MULTICAST) {
                continue;
            }
            let Some(v4) = a.address.as_ref().and_then(|s| s.as_sockaddr_in()) else {
                continue;
            };
            let index = nix::net::if_::if_nametoindex(a.interface_name.as_str()).unwrap_or(0);
            seen.insert(DdsAddress {
                interface: a.interface_name,
                index,
                addr: v4.ip(),
            });
        }
        Some(DdsAddresses { seen })
    }

    /// Takes a new look; returns the addresses that appeared since the last one.
    pub(super) fn appeared(&mut self, now: Option<DdsAddresses>) -> Vec<DdsAddress> {
        let Some(now) = now else {
            return Vec::new();
        };
        let new = now.seen.difference(&self.seen).cloned().collect();
        *self = now;
        new
    }
}

#[cfg(test)]
mod tests {
    use super::{DdsAddress, DdsAddresses};

    fn set(list: &[(&str, u32, [u8; 4])]) -> Option<DdsAddresses> {
        let seen = list
            .iter()
            .map(|(interface, index, a)| DdsAddress {
                interface: (*interface).into(),
                index: *index,
                addr: (*a).into(),
            })
            .collect();
        Some(DdsAddresses { seen })
    }

    #[test]
    fn an_address_that_appears_is_reported_once_and_one_that_goes_is_not() {
        let mut a = DdsAddresses::default();
        let lo = ("lo", 1, [127, 0, 0, 1]);
        let wlan = ("wlan0", 3, [10, 0, 0, 5]);
        assert_eq!(
            a.appeared(set(&[lo])).len(),
            1,
            "the first look after an empty one"
        );
        assert!(a.appeared(set(&[lo])).is_empty());
        let new = a.appeared(set(&[lo, wlan]));
        assert_eq!(new.len(), 1);
        assert_eq!(new[0].to_string(), "wlan0 10.0.0.5");
        assert!(a.appeared(set(&[lo, wlan])).is_empty(), "reported once");
        assert!(a.appeared(set(&[lo])).is_empty(), "gone: nothing to join");
        assert_eq!(a.appeared(set(&[lo, wlan])).len(), 1, "back: joined again");
        let replugged = ("wlan0", 4, [10, 0, 0, 5]);
        assert_eq!(
            a.appeared(set(&[lo, replugged])).len(),
            1,
            "the same address on a new device (its memberships went with the old one)"
        );
        assert!(
            a.appeared(None).is_empty(),
            "no answer from the system: no conclusion"
        );
        assert!(a.appeared(set(&[lo, replugged])).is_empty());
    }
}
