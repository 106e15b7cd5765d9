//! The black box: what the robot and the hub agree on to move a slice of the robot's ring
//! buffer across the link.
//!
//! The robot keeps its ring ([`ring`]) and cuts slices from it ([`slice`]); the hub asks
//! for a slice and stores it beside its recordings ([`fetch`]). Between them:
//!
//! - the agent offers the service [`FETCH_SERVICE`] (`/robot1/fleetlink/blackbox/fetch`
//!   at the hub). A call carries a [`FetchRequest`] as JSON: the slice's id (the hub's
//!   recording id), the time range and topics, and the window of bytes wanted next. The
//!   first call for an id cuts the slice into a file on the robot; every call is answered
//!   with the slice's [`FetchReply`] (size, SHA-256) once the window is queued;
//! - the window goes up as [`Piece`]s on the topic [`DATA_TOPIC`], 32 KiB each, CDR of
//!   [`PIECE_TYPE`]. The uplink sends that topic at a low priority (below every live
//!   topic's default), FIFO, and whether or not anyone at the hub has subscribed it;
//! - the hub appends each piece that starts where its file ends and ignores the rest, asks
//!   for the next window before the current one is used up, and asks again from where its
//!   file ends when pieces stop coming (the link dropped, a queue overflowed). So a
//!   transfer resumes after a blackout from the last byte that arrived, and the finished
//!   file is checked against the slice's SHA-256.

pub mod fetch;
pub mod ring;
pub mod slice;

use serde::{Deserialize, Serialize};

/// The agent's fetch service, by its name on the robot.
pub const FETCH_SERVICE: &str = fleetlink_relay::names::BLACKBOX_FETCH_SERVICE;
/// The topic the pieces go up on, by its name on the robot.
pub const DATA_TOPIC: &str = fleetlink_relay::names::BLACKBOX_DATA_TOPIC;
/// The pieces' message type and its definition.
pub const PIECE_TYPE: &str = "fleetlink_msgs/msg/BlackBoxPiece";
pub const PIECE_DEFINITION: &str = "\
# A piece of a black-box slice (an MCAP file) on its way from a robot to the hub.
string slice
uint64 offset
uint64 size
uint8[] data
";
/// The fetch service's type; requests and replies are JSON ([`FetchRequest`],
/// [`FetchReply`]).
pub const FETCH_TYPE: &str = "fleetlink_msgs/srv/BlackBoxFetch";
/// Bytes of the slice in one piece.
pub const PIECE_BYTES: usize = 32 * 1024;
/// Most bytes one fetch call may ask for (the hub asks for less).
pub const MAX_WINDOW: u64 = 4 << 20;

/// A slice's id: 1 to 64 letters, digits, `-` or `_` (it names a file on the robot).
pub fn check_slice_id(id: &str) -> Result<(), String> {
    if id.is_empty()
        || id.len() > 64
        || !id
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
    {
        return Err(format!(
            "slice: {:?} must be 1 to 64 letters, digits, '-' or '_'",
            id.chars().take(80).collect::<String>()
        ));
    }
    Ok(())
}

/// A call of [`FETCH_SERVICE`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FetchRequest {
    pub slice: String,
    pub range: SliceRange,
    /// The first byte of the window wanted now, and its length.
    #[serde(default)]
    pub offset: u64,
    #[serde(default)]
    pub window: u64,
}

/// Which messages a slice holds: a time range (receive times on the robot) and topics.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct SliceRange {
    /// The last this many seconds before the slice is cut, by the robot's clock. Either
    /// this or `from_ns` (with `to_ns` optional, default now).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub last_s: Option<f64>,
    /// Unix nanoseconds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from_ns: Option<u64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub to_ns: Option<u64>,
    /// Whole-name patterns of the robot's local topic names; empty: every topic the ring
    /// keeps.
    #[serde(default)]
    pub topics: Vec<String>,
}

impl SliceRange {
    /// The range as Unix nanoseconds, resolved against `now_ns`; an error names the field.
    pub fn resolve(&self, now_ns: u64) -> Result<(u64, u64), String> {
        match (self.last_s, self.from_ns) {
            (Some(_), Some(_)) => Err("give either last_s or from_ns, not both".into()),
            (None, None) => Err(
                "give the time range: last_s (seconds before now) or from_ns (Unix nanoseconds)"
                    .into(),
            ),
            (Some(s), None) => {
                if !(s.is_finite() && s > 0.0) {
                    return Err(format!("last_s: must be a number of seconds > 0, got {s}"));
                }
                if self.to_ns.is_some() {
                    return Err("to_ns goes with from_ns, not with last_s".into());
                }
                let span = (s * 1e9).min(u64::MAX as f64) as u64;
                Ok((now_ns.saturating_sub(span), now_ns))
            }
            (None, Some(from)) => {
                let to = self.to_ns.unwrap_or(now_ns);
                if to <= from {
                    return Err(format!("to_ns ({to}) must be after from_ns ({from})"));
                }
                Ok((from, to))
            }
        }
    }

    /// The topics as one whole-name pattern (`None`: every topic).
    pub fn pattern(&self) -> Result<Option<regex::Regex>, String> {
        if self.topics.is_empty() {
            return Ok(None);
        }
        crate::spec::one_pattern(&self.topics).map(Some)
    }
}

/// The answer to a fetch call: what the slice is.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, Default)]
pub struct FetchReply {
    pub size: u64,
    /// SHA-256 of the whole file, lower-case hex.
    pub sha256: String,
    pub messages: u64,
    /// Receive times of its first and last message, Unix nanoseconds.
    pub start_ns: u64,
    pub end_ns: u64,
    /// The topics it holds.
    pub topics: Vec<String>,
}

/// One piece of a slice.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Piece<'a> {
    pub slice: &'a str,
    pub offset: u64,
    /// The whole slice's size.
    pub size: u64,
    pub data: &'a [u8],
}

impl Piece<'_> {
    /// CDR (little-endian, with its encapsulation header) of [`PIECE_DEFINITION`].
    pub fn encode(&self) -> Vec<u8> {
        let mut out =
            Vec::with_capacity(4 + 4 + self.slice.len() + 1 + 8 + 16 + 4 + self.data.len());
        out.extend_from_slice(&[0, 1, 0, 0]);
        out.extend_from_slice(&(self.slice.len() as u32 + 1).to_le_bytes());
        out.extend_from_slice(self.slice.as_bytes());
        out.push(0);
        // Alignment counts from the end of the encapsulation header.
        while !(out.len() - 4).is_multiple_of(8) {
            out.push(0);
        }
        out.extend_from_slice(&self.offset.to_le_bytes());
        out.extend_from_slice(&self.size.to_le_bytes());
        out.extend_from_slice(&(self.data.len() as u32).to_le_bytes());
        out.extend_from_slice(self.data);
        out
    }

    /// Reads [`Piece::encode`]'s layout; `None` if `b` is not one.
    pub fn decode(b: &[u8]) -> Option<Piece<'_>> {
        if b.get(..2)? != [0, 1] {
            return None;
        }
        let u32_at = |at: usize| -> Option<u32> {
            Some(u32::from_le_bytes(b.get(at..at + 4)?.try_into().ok()?))
        };
        let u64_at = |at: usize| -> Option<u64> {
            Some(u64::from_le_bytes(b.get(at..at + 8)?.try_into().ok()?))
        };
        let n = u32_at(4)? as usize;
        let text = b.get(8..8 + n.checked_sub(1)?)?;
        let slice = std::str::from_utf8(text).ok()?;
        let mut at = 8 + n;
        at += (8 - (at - 4) % 8) % 8;
        let offset = u64_at(at)?;
        let size = u64_at(at + 8)?;
        let len = u32_at(at + 16)? as usize;
        let data = b.get(at + 20..at + 20 + len)?;
        Some(Piece {
            slice,
            offset,
            size,
            data,
        })
    }
}

/// Lower-case hex of `bytes`.
pub(crate) fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_read_back_whatever_the_padding() {
        for id in ["a", "bb-1", "rec-20261128-230501", "x".repeat(64).as_str()] {
            let data: Vec<u8> = (0..1000u32).map(|i| i as u8).collect();
            let p = Piece {
                slice: id,
                offset: 123_456_789,
                size: 987_654_321,
                data: &data,
            };
            let b = p.encode();
            assert_eq!(Piece::decode(&b), Some(p.clone()));
            // The two u64 fields start 8-aligned after the header.
            let at = 8 + id.len() + 1;
            let at = at + (8 - (at - 4) % 8) % 8;
            assert_eq!(&b[at..at + 8], &123_456_789u64.to_le_bytes());
            assert!(Piece::decode(&b[..b.len() - 1]).is_none());
        }
        assert!(Piece::decode(b"\x00\x01\x00\x00").is_none());
        assert!(Piece::decode(b"").is_none());
    }

    #[test]
    fn ranges_resolve_or_name_the_field() {
        let now = 100_000_000_000;
        let last = SliceRange {
            last_s: Some(30.0),
            ..SliceRange::default()
        };
        assert_eq!(last.resolve(now), Ok((70_000_000_000, now)));
        let both = SliceRange {
            last_s: Some(1.0),
            from_ns: Some(1),
            ..SliceRange::default()
        };
        assert!(both.resolve(now).unwrap_err().contains("not both"));
        assert!(
            SliceRange::default()
                .resolve(now)
                .unwrap_err()
                .contains("last_s")
        );
        let backwards = SliceRange {
            from_ns: Some(5),
            to_ns: Some(4),
            ..SliceRange::default()
        };
        assert!(backwards.resolve(now).unwrap_err().contains("to_ns"));
        let negative = SliceRange {
            last_s: Some(-1.0),
            ..SliceRange::default()
        };
        assert!(negative.resolve(now).unwrap_err().starts_with("last_s"));
        assert!(check_slice_id("../etc").is_err());
        assert!(check_slice_id("bb-robot1-20261128-230501").is_ok());
    }
}
