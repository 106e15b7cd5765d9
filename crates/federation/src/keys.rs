//! How fleetlink names travel in Zenoh key expressions, and the few bytes that travel
//! with each message. Pure functions, no I/O.
//!
//! Key space of one fleet (`<f>` is the fleet name, `<hub>` a hub's Zenoh id):
//!
//! | key | what |
//! |---|---|
//! | `fleetlink/<f>/t/<hub>/<topic>` | a topic's messages, put by hub `<hub>` where it is published; a hub listens only to the hubs that offer the topic |
//! | `fleetlink/<f>/cat/<hub>/<kind>/<flags>/<type>/<name>` | liveliness token: `<hub>` offers a topic (`t`), service (`s`), action (`a`), robot (`r`), wants a topic (`w`), or is itself named `<name>` (`h`) |
//! | `fleetlink/<f>/schema/<hub>/<topic>` | queryable: the topic's full definition on `<hub>` |
//! | `fleetlink/<f>/call/<hub>/<service>` | queryable: a service call or action goal to `<hub>` |
//! | `fleetlink/<f>/cancel/<hub>` | a caller gives up a call it made to `<hub>` |
//! | `fleetlink/<f>/keyframe/<hub>/<from>/<topic>` | hub `<from>` asks `<hub>`, which sends it the video topic, for a keyframe of it (no payload) |
//!
//! A ROS name `/robot1/scan` becomes the chunks `robot1/scan`; a type `pkg/msg/T` the
//! one chunk `pkg:msg:T`. Names that cannot be key expressions (empty chunks, Zenoh's
//! wildcard characters) are not federated; the caller logs them.

use fleetlink_proto::Encoding;

/// Prefix of every key of `fleet`.
pub fn root(fleet: &str) -> String {
    format!("fleetlink/{fleet}")
}

/// The chunks of a ROS name, or `None` if it cannot be part of a key expression.
pub fn name_chunks(name: &str) -> Option<&str> {
    let rest = name.strip_prefix('/')?;
    let ok = !rest.is_empty()
        && rest.split('/').all(|c| !c.is_empty())
        && !rest.contains(['*', '$', '?', '#']);
    ok.then_some(rest)
}

/// A chunk that is safe for a fleet or hub name: `[A-Za-z0-9_.-]`, others as `_`.
pub fn chunk(s: &str) -> String {
    let c: String = s
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.') {
                c
            } else {
                '_'
            }
        })
        .collect();
    if c.is_empty() { "_".to_owned() } else { c }
}

/// What a hub offers, as one liveliness token.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Offer {
    Topic {
        name: String,
        type_name: String,
        latched: bool,
    },
    Service {
        name: String,
        type_name: String,
    },
    Action {
        name: String,
        type_name: String,
    },
    Robot {
        name: String,
    },
    Hub {
        name: String,
    },
    /// Someone on the hub subscribes to the topic: the hubs where it is published send it
    /// there (and subscribe to it on their own router even before a publisher appears, so
    /// that a robot arriving there is asked for it from its first message).
    Want {
        name: String,
    },
}

/// Catalog key of `offer` made by `hub`, or `None` when its name cannot be a key.
pub fn offer_key(fleet: &str, hub: &str, offer: &Offer) -> Option<String> {
    let (kind, flags, type_name, name) = match offer {
        Offer::Topic {
            name,
            type_name,
            latched,
        } => (
            "t",
            u8::from(*latched),
            type_name.as_str(),
            name_chunks(name)?,
        ),
        Offer::Service { name, type_name } => ("s", 0, type_name.as_str(), name_chunks(name)?),
        Offer::Action { name, type_name } => ("a", 0, type_name.as_str(), name_chunks(name)?),
        Offer::Robot { name } => ("r", 0, "", chunk_or_none(name)?),
        Offer::Hub { name } => ("h", 0, "", chunk_or_none(name)?),
        Offer::Want { name } => ("w", 0, "", name_chunks(name)?),
    };
    let type_chunk = if type_name.is_empty() {
        "-".to_owned()
    } else {
        if type_name.contains(['*', '$', '?', '#', ':']) {
            return None;
        }
        type_name.replace('/', ":")
    };
    Some(format!(
        "{}/cat/{hub}/{kind}/{flags}/{type_chunk}/{name}",
        root(fleet)
    ))
}

fn chunk_or_none(s: &str) -> Option<&str> {
    (!s.is_empty() && !s.contains(['/', '*', '$', '?', '#'])).then_some(s)
}

/// The hub and offer a catalog key names; `None` for a key that is not one of ours.
pub fn parse_offer(fleet: &str, key: &str) -> Option<(String, Offer)> {
    let rest = key.strip_prefix(&root(fleet))?.strip_prefix("/cat/")?;
    let mut parts = rest.splitn(5, '/');
    let hub = parts.next()?.to_owned();
    let kind = parts.next()?;
    let flags: u8 = parts.next()?.parse().ok()?;
    let type_name = match parts.next()? {
        "-" => String::new(),
        t => t.replace(':', "/"),
    };
    let tail = parts.next()?;
    let name = format!("/{tail}");
    let offer = match kind {
        "t" => Offer::Topic {
            name,
            type_name,
            latched: flags & 1 != 0,
        },
        "s" => Offer::Service { name, type_name },
        "a" => Offer::Action { name, type_name },
        "r" => Offer::Robot {
            name: tail.to_owned(),
        },
        "h" => Offer::Hub {
            name: tail.to_owned(),
        },
        "w" => Offer::Want { name },
        _ => return None,
    };
    Some((hub, offer))
}

/// Key of a topic's messages as hub `hub` puts them.
pub fn topic_key(fleet: &str, hub: &str, name: &str) -> Option<String> {
    Some(format!("{}/t/{hub}/{}", root(fleet), name_chunks(name)?))
}

/// Key on which hub `from` asks hub `to` for a keyframe of the video topic `name`.
pub fn keyframe_key(fleet: &str, to: &str, from: &str, name: &str) -> Option<String> {
    Some(format!(
        "{}/keyframe/{to}/{from}/{}",
        root(fleet),
        name_chunks(name)?
    ))
}

/// The asking hub and the topic of a keyframe ask made to hub `to`; `None` for a key
/// that is not one.
pub fn parse_keyframe_key(fleet: &str, to: &str, key: &str) -> Option<(String, String)> {
    let rest = key
        .strip_prefix(&root(fleet))?
        .strip_prefix("/keyframe/")?
        .strip_prefix(to)?
        .strip_prefix('/')?;
    let (from, tail) = rest.split_once('/')?;
    let name = format!("/{tail}");
    name_chunks(&name)?;
    (!from.is_empty()).then(|| (from.to_owned(), name))
}

/// What travels beside a message's payload (the Zenoh attachment): its encoding, its
/// publisher's numbering and stamp, and for a robot's no-drop stream the stream's epoch,
/// so that a hub hearing the same message from two hubs (its robot moved between them)
/// delivers it once.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MessageHeader {
    pub encoding: Encoding,
    pub seq: u64,
    pub stamp_ns: u64,
    /// `Some(epoch)` for a no-drop stream.
    pub reliable: Option<u64>,
}

/// Version byte of [`MessageHeader`]'s layout.
const HEADER_V1: u8 = 1;

impl MessageHeader {
    /// `[1, encoding, flags, seq u64 LE, stamp u64 LE, (epoch u64 LE if reliable)]`.
    pub fn encode(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(27);
        b.push(HEADER_V1);
        b.push(self.encoding as u8);
        b.push(u8::from(self.reliable.is_some()));
        b.extend_from_slice(&self.seq.to_le_bytes());
        b.extend_from_slice(&self.stamp_ns.to_le_bytes());
        if let Some(e) = self.reliable {
            b.extend_from_slice(&e.to_le_bytes());
        }
        b
    }

    pub fn decode(b: &[u8]) -> Result<MessageHeader, String> {
        let u64_at = |i: usize| -> Result<u64, String> {
            b.get(i..i + 8)
                .map(|s| u64::from_le_bytes(s.try_into().expect("8 bytes")))
                .ok_or_else(|| format!("message header of {} bytes is too short", b.len()))
        };
        match b.first() {
            Some(&HEADER_V1) => {}
            Some(v) => return Err(format!("message header version {v} is not known (1 is)")),
            None => return Err("message without a header".to_owned()),
        }
        let encoding = b
            .get(1)
            .and_then(|e| Encoding::from_u8(*e))
            .ok_or("message header names no known encoding")?;
        let reliable = b.get(2).copied().unwrap_or(0) & 1 != 0;
        Ok(MessageHeader {
            encoding,
            seq: u64_at(3)?,
            stamp_ns: u64_at(11)?,
            reliable: if reliable { Some(u64_at(19)?) } else { None },
        })
    }
}

/// A no-drop stream's messages heard on one hub, to deliver each number once even when it
/// arrives twice (from the hub the robot left, then resent through its new hub).
#[derive(Debug, Default)]
pub struct StreamMark {
    epoch: Option<u64>,
    last: u64,
}

impl StreamMark {
    /// Whether message `seq` of stream `epoch` is new; advances the mark. A new epoch is
    /// a new stream (the robot's outbox started afresh).
    pub fn admit(&mut self, epoch: u64, seq: u64) -> bool {
        if self.epoch != Some(epoch) {
            self.epoch = Some(epoch);
            self.last = seq;
            return true;
        }
        if seq <= self.last {
            return false;
        }
        self.last = seq;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offers_round_trip_through_keys() {
        let offers = [
            Offer::Topic {
                name: "/robot1/scan".into(),
                type_name: "sensor_msgs/msg/LaserScan".into(),
                latched: true,
            },
            Offer::Service {
                name: "/robot1/reset".into(),
                type_name: "std_srvs/srv/Trigger".into(),
            },
            Offer::Action {
                name: "/robot1/navigate".into(),
                type_name: "nav2_msgs/action/NavigateToPose".into(),
            },
            Offer::Topic {
                name: "/x".into(),
                type_name: String::new(),
                latched: false,
            },
            Offer::Robot {
                name: "robot1".into(),
            },
            Offer::Hub {
                name: "hub-a".into(),
            },
            Offer::Want {
                name: "/robot1/odom".into(),
            },
        ];
        for o in offers {
            let key = offer_key("f", "abc123", &o).unwrap();
            assert_eq!(parse_offer("f", &key), Some(("abc123".to_owned(), o)));
        }
    }

    #[test]
    fn names_that_cannot_be_keys_are_refused() {
        for bad in ["", "/", "relative", "/a//b", "/a/*", "/a/$x", "/a?", "/a#"] {
            assert_eq!(name_chunks(bad), None, "{bad}");
        }
        assert_eq!(name_chunks("/a/b_c/~d"), Some("a/b_c/~d"));
        assert_eq!(
            topic_key("f", "h1", "/a/b").as_deref(),
            Some("fleetlink/f/t/h1/a/b")
        );
        assert_eq!(topic_key("f", "h1", "/a/*"), None);
        assert_eq!(parse_offer("f", "fleetlink/g/cat/h/t/0/-/x"), None);
        assert_eq!(parse_offer("f", "fleetlink/f/cat/h/z/0/-/x"), None);
        assert_eq!(chunk("hub a/1"), "hub_a_1");
    }

    #[test]
    fn keyframe_asks_name_both_hubs_and_the_topic() {
        let key = keyframe_key("f", "hubA", "hubB", "/robot1/camera/video").unwrap();
        assert_eq!(key, "fleetlink/f/keyframe/hubA/hubB/robot1/camera/video");
        assert_eq!(
            parse_keyframe_key("f", "hubA", &key),
            Some(("hubB".to_owned(), "/robot1/camera/video".to_owned()))
        );
        assert_eq!(parse_keyframe_key("f", "hubC", &key), None, "another hub's");
        assert_eq!(
            parse_keyframe_key("f", "hub", &key),
            None,
            "a prefix of the id"
        );
        assert_eq!(
            parse_keyframe_key("g", "hubA", &key),
            None,
            "another fleet's"
        );
        assert_eq!(
            parse_keyframe_key("f", "hubA", "fleetlink/f/keyframe/hubA/hubB"),
            None,
            "no topic"
        );
        assert_eq!(keyframe_key("f", "a", "b", "/a/*"), None);
    }

    #[test]
    fn headers_round_trip_and_bad_ones_are_named() {
        for h in [
            MessageHeader {
                encoding: Encoding::Cdr,
                seq: 7,
                stamp_ns: 1 << 60,
                reliable: None,
            },
            MessageHeader {
                encoding: Encoding::Json,
                seq: u64::MAX,
                stamp_ns: 0,
                reliable: Some(42),
            },
        ] {
            assert_eq!(MessageHeader::decode(&h.encode()), Ok(h));
        }
        assert!(MessageHeader::decode(&[]).unwrap_err().contains("without"));
        assert!(
            MessageHeader::decode(&[9])
                .unwrap_err()
                .contains("version 9")
        );
        assert!(
            MessageHeader::decode(&[1, 200])
                .unwrap_err()
                .contains("encoding")
        );
        assert!(
            MessageHeader::decode(&[1, 0, 0, 1])
                .unwrap_err()
                .contains("short")
        );
    }

    #[test]
    fn a_stream_number_is_admitted_once_per_epoch() {
        let mut m = StreamMark::default();
        assert!(m.admit(1, 5));
        assert!(m.admit(1, 6));
        assert!(!m.admit(1, 6), "the same number again");
        assert!(!m.admit(1, 3), "an older number");
        assert!(m.admit(2, 1), "a new epoch starts afresh");
        assert!(m.admit(2, 2));
    }
}
