//! The agent as a ROS 2 node, so `ros2 node list` shows it and `ros2 node info` lists
//! its publishers, subscribers and services.
//!
//! ROS 2 tools learn which nodes exist, and which DDS readers and writers belong to
//! which node, from the topic `ros_discovery_info`: each participant keeps one sample of
//! `rmw_dds_common/msg/ParticipantEntitiesInfo` there (reliable, transient local, keep
//! last 1) — its own GID, then per node the namespace, the name, and the GIDs of the
//! node's readers and writers. A GID is an entity's 16-byte DDS GUID. Humble and older
//! distributions pad it to 24 bytes; Iron and newer send 16. The type name is the same
//! in both, so a reader of one layout misreads the other: the bridge writes the layout
//! of the robot's distribution — `ros2.distro`, else `ROS_DISTRO`, else the one that
//! reads the other participants' samples exactly, else 16 bytes (Iron and newer).

use bytes::Bytes;
use rustdds::no_key::{DataReader, DataWriter};
use rustdds::{GUID, RTPSEntity};

use crate::bridge::Bridge;
use crate::raw::{CDR_LE_HEADER, RawAdapter, RawCdr};

pub const TOPIC: &str = "ros_discovery_info";
const DDS_TYPE: &str = "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_";
/// How many participants' samples the reader keeps between two looks.
const PARTICIPANTS: i32 = 64;

/// The GID size of a ROS 2 distribution (by its `ROS_DISTRO` name); `None`: not one the
/// agent knows.
pub fn gid_len(distro: &str) -> Option<usize> {
    match distro.trim().to_ascii_lowercase().as_str() {
        "ardent" | "bouncy" | "crystal" | "dashing" | "eloquent" | "foxy" | "galactic"
        | "humble" => Some(24),
        "iron" | "jazzy" | "kilted" | "lyrical" | "rolling" => Some(16),
        _ => None,
    }
}

/// The bridge's sample on `ros_discovery_info`, rewritten when its endpoints change.
pub(crate) struct NodeInfo {
    writer: DataWriter<RawCdr, RawAdapter>,
    /// The other participants' samples, while the GID size is not known from the
    /// configuration.
    reader: Option<DataReader<RawCdr, RawAdapter>>,
    gid_len: Option<usize>,
    namespace: String,
    name: String,
    written: Option<Vec<u8>>,
}

impl NodeInfo {
    pub(crate) fn new(bridge: &Bridge) -> Result<NodeInfo, String> {
        let qos = crate::qos::writer(true);
        let writer = bridge.untracked_writer(TOPIC, DDS_TYPE, qos.clone())?;
        let distro = bridge.opts.distro.as_deref();
        let fixed = distro.and_then(gid_len);
        if let Some(d) = distro.filter(|_| fixed.is_none()) {
            tracing::warn!(
                "ros2: ROS_DISTRO={d:?} is not a ROS 2 distribution the agent knows; the \
                 layout of ros_discovery_info is taken from the graph (set ros2.distro)"
            );
        }
        // A no-key topic is one instance: a reader of depth 1 would keep only the latest
        // sample of all participants (often the bridge's own), so room for many.
        let reader_qos = crate::qos::reader_for(
            qos.reliability(),
            Some(rustdds::policy::Durability::TransientLocal),
            PARTICIPANTS,
        );
        let reader = match fixed {
            Some(_) => None,
            None => Some(bridge.untracked_reader(TOPIC, DDS_TYPE, reader_qos)?),
        };
        let (namespace, name) = split_node_name(&bridge.opts.node_name);
        Ok(NodeInfo {
            writer,
            reader,
            gid_len: fixed,
            namespace,
            name,
            written: None,
        })
    }

    /// Learns the GID size from other participants (unless configured) and writes the
    /// bridge's sample when it changed.
    pub(crate) fn refresh(&mut self, bridge: &Bridge) {
        if let Some(reader) = &mut self.reader {
            while let Ok(Some(sample)) = reader.take_next_sample() {
                if bridge.is_own(sample.sample_info().writer_guid()) {
                    continue;
                }
                let raw = sample.into_value().0;
                let found = detect_gid_len(&raw);
                if found.is_some() && found != self.gid_len {
                    tracing::info!(
                        "ros2: the graph's nodes use {}-byte GIDs in ros_discovery_info",
                        found.unwrap_or_default()
                    );
                    self.gid_len = found;
                }
            }
        }
        let (readers, writers) = bridge.endpoints.list();
        let sample = encode(
            self.gid_len.unwrap_or(16),
            bridge.dp.guid(),
            &self.namespace,
            &self.name,
            &readers,
            &writers,
        );
        if self.written.as_ref() == Some(&sample) {
            return;
        }
        match self.writer.write(RawCdr(Bytes::from(sample.clone())), None) {
            Ok(()) => self.written = Some(sample),
            Err(e) => tracing::debug!("ros2: writing ros_discovery_info: {e:?}"),
        }
    }

    /// The node's full name, as `ros2 node list` shows it.
    pub(crate) fn full_name(&self) -> String {
        match self.namespace.as_str() {
            "/" => format!("/{}", self.name),
            ns => format!("{ns}/{}", self.name),
        }
    }
}

/// `/a/b/node` → (`/a/b`, `node`); `node` → (`/`, `node`).
fn split_node_name(full: &str) -> (String, String) {
    let full = full.trim().trim_end_matches('/');
    match full.rsplit_once('/') {
        Some(("", name)) => ("/".into(), name.into()),
        Some((ns, name)) => (
            if ns.starts_with('/') {
                ns.into()
            } else {
                format!("/{ns}")
            },
            name.into(),
        ),
        None => ("/".into(), full.into()),
    }
}

/// A `ParticipantEntitiesInfo` sample (with its CDR header) of one node.
fn encode(
    gid_len: usize,
    participant: GUID,
    namespace: &str,
    name: &str,
    readers: &[GUID],
    writers: &[GUID],
) -> Vec<u8> {
    let mut c = Cdr(Vec::with_capacity(
        64 + (readers.len() + writers.len()) * gid_len,
    ));
    c.gid(participant, gid_len);
    c.u32(1);
    c.string(namespace);
    c.string(name);
    for list in [readers, writers] {
        c.u32(u32::try_from(list.len()).unwrap_or(u32::MAX));
        for g in list {
            c.gid(*g, gid_len);
        }
    }
    let mut out = Vec::with_capacity(4 + c.0.len());
    out.extend_from_slice(&CDR_LE_HEADER);
    out.extend_from_slice(&c.0);
    out
}

/// Little-endian CDR, aligned from the start of the body.
struct Cdr(Vec<u8>);

impl Cdr {
    fn align(&mut self, n: usize) {
        while !self.0.len().is_multiple_of(n) {
            self.0.push(0);
        }
    }
    fn u32(&mut self, v: u32) {
        self.align(4);
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    fn string(&mut self, s: &str) {
        self.u32(u32::try_from(s.len() + 1).unwrap_or(u32::MAX));
        self.0.extend_from_slice(s.as_bytes());
        self.0.push(0);
    }
    fn gid(&mut self, g: GUID, len: usize) {
        let bytes = g.to_bytes();
        self.0.extend_from_slice(&bytes);
        self.0
            .resize(self.0.len() + len.saturating_sub(bytes.len()), 0);
    }
}

/// The GID size that reads `sample` (a `ParticipantEntitiesInfo` with its CDR header)
/// exactly; `None` when neither or both do.
fn detect_gid_len(sample: &[u8]) -> Option<usize> {
    if sample.len() < 4 || sample[1] != 0x01 {
        return None; // not little-endian plain CDR
    }
    let body = &sample[4..];
    match (reads_exactly(body, 16), reads_exactly(body, 24)) {
        (true, false) => Some(16),
        (false, true) => Some(24),
        _ => None,
    }
}

fn reads_exactly(body: &[u8], gid_len: usize) -> bool {
    let mut at = gid_len;
    let u32_at = |at: &mut usize| -> Option<usize> {
        *at = at.next_multiple_of(4);
        let v = body.get(*at..*at + 4)?;
        *at += 4;
        Some(u32::from_le_bytes(v.try_into().ok()?) as usize)
    };
    let mut walk = || -> Option<usize> {
        let nodes = u32_at(&mut at)?;
        for _ in 0..nodes {
            for _ in 0..2 {
                let len = u32_at(&mut at)?;
                if len == 0 || body.get(at + len - 1) != Some(&0) {
                    return None; // a CDR string ends in NUL
                }
                at += len;
            }
            for _ in 0..2 {
                let n = u32_at(&mut at)?;
                at = at.checked_add(n.checked_mul(gid_len)?)?;
                if at > body.len() {
                    return None;
                }
            }
        }
        Some(at)
    };
    // The writer may pad the sample to a multiple of 4.
    walk().is_some_and(|end| end <= body.len() && body.len() - end < 4)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn guid(b: u8) -> GUID {
        GUID::from_bytes([b; 16])
    }

    #[test]
    fn distributions_before_iron_pad_gids_to_24_bytes() {
        assert_eq!(gid_len("humble"), Some(24));
        assert_eq!(gid_len("Foxy"), Some(24));
        assert_eq!(gid_len("jazzy"), Some(16));
        assert_eq!(gid_len("rolling"), Some(16));
        assert_eq!(gid_len("noetic"), None);
    }

    #[test]
    fn a_sample_lays_out_the_node_and_its_endpoints() {
        let s = encode(
            16,
            guid(1),
            "/",
            "fleetlink_r1",
            &[guid(2)],
            &[guid(3), guid(4)],
        );
        assert_eq!(&s[..4], &CDR_LE_HEADER);
        let body = &s[4..];
        assert_eq!(&body[..16], &[1; 16], "the participant's GID");
        assert_eq!(&body[16..20], &1u32.to_le_bytes(), "one node");
        assert_eq!(
            &body[20..24],
            &2u32.to_le_bytes(),
            "namespace \"/\" with its NUL"
        );
        assert_eq!(&body[24..26], b"/\0");
        // The name's length is aligned to 4: two bytes of padding after "/\0".
        assert_eq!(&body[28..32], &13u32.to_le_bytes());
        assert_eq!(&body[32..45], b"fleetlink_r1\0");
        assert_eq!(&body[48..52], &1u32.to_le_bytes(), "one reader");
        assert_eq!(&body[52..68], &[2; 16]);
        assert_eq!(&body[68..72], &2u32.to_le_bytes(), "two writers");
        assert_eq!(body.len(), 72 + 32);
        let humble = encode(24, guid(1), "/", "n", &[guid(2)], &[]);
        assert_eq!(&humble[4 + 16..4 + 24], &[0; 8], "a GID padded with zeros");
    }

    #[test]
    fn the_gid_size_is_the_one_that_reads_a_sample_exactly() {
        for len in [16, 24] {
            let s = encode(
                len,
                guid(1),
                "/robot",
                "camera",
                &[guid(2), guid(3)],
                &[guid(4)],
            );
            assert_eq!(detect_gid_len(&s), Some(len), "{len}-byte GIDs");
            // Up to 3 bytes of padding after the last field change nothing; more is
            // not this layout.
            let mut padded = s.clone();
            padded.extend_from_slice(&[0, 0, 0]);
            assert_eq!(detect_gid_len(&padded), Some(len));
            padded.push(0);
            assert_ne!(detect_gid_len(&padded), Some(len));
        }
        assert_eq!(detect_gid_len(&[0, 1, 0, 0, 1, 2]), None);
        assert_eq!(detect_gid_len(&[]), None);
    }

    #[test]
    fn node_names_split_into_namespace_and_name() {
        assert_eq!(
            split_node_name("/fleetlink_r1"),
            ("/".into(), "fleetlink_r1".into())
        );
        assert_eq!(split_node_name("agent"), ("/".into(), "agent".into()));
        assert_eq!(
            split_node_name("/robot/agent"),
            ("/robot".into(), "agent".into())
        );
        assert_eq!(
            split_node_name("a/b/agent"),
            ("/a/b".into(), "agent".into())
        );
    }
}
