//! Cutting a slice out of MCAP files: the messages of chosen topics in a time range,
//! copied with their channels and schemas into one new file (zstd, indexed, with a
//! summary). The robot cuts slices from its ring; the hub uses the same cut to leave out
//! the topics a requester may not read.

use std::collections::HashMap;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use sha2::{Digest, Sha256};

use super::FetchReply;
use super::ring::Segment;
use crate::read::{Item, McapReader};

/// The segments that may hold messages received in `from..=to`: a segment runs from its
/// start to the next one's.
pub fn overlapping(segments: &[Segment], from: u64, to: u64) -> Vec<&Segment> {
    segments
        .iter()
        .enumerate()
        .filter(|(i, s)| {
            let next = segments.get(i + 1).map_or(u64::MAX, |n| n.start_ns);
            s.start_ns <= to && next > from
        })
        .map(|(_, s)| s)
        .collect()
}

/// Writes the messages of `inputs` received in `from..=to` on topics `keep` accepts into a
/// new file `out`. An input that ends early (a segment whose writer died) is read up to
/// where it breaks. Returns the slice's figures with its SHA-256.
pub fn cut(
    inputs: &[&Path],
    from: u64,
    to: u64,
    keep: &mut dyn FnMut(&str) -> bool,
    out: &Path,
) -> Result<FetchReply, String> {
    let file = File::create(out).map_err(|e| format!("creating {}: {e}", out.display()))?;
    let mut writer: Option<mcap::Writer<BufWriter<File>>> = None;
    let mut pending_file = Some(file);
    let mut schemas: HashMap<(String, String, Vec<u8>), u16> = HashMap::new();
    let mut channels: HashMap<(String, String, u16), u16> = HashMap::new();
    let mut reply = FetchReply {
        start_ns: u64::MAX,
        ..FetchReply::default()
    };
    let mut topics = std::collections::BTreeSet::new();
    for input in inputs {
        let mut reader = match McapReader::open(input) {
            Ok(r) => r,
            Err(e) => {
                tracing::warn!("black box: reading {}: {e}; skipped", input.display());
                continue;
            }
        };
        // This file's channel ids → the slice's (None: a topic left out).
        let mut map: HashMap<u16, Option<u16>> = HashMap::new();
        let mut declared = Vec::new();
        while let Some(item) = reader.next_item() {
            let item = match item {
                Ok(i) => i,
                Err(e) => {
                    tracing::debug!("black box: {} ends early: {e}", input.display());
                    break;
                }
            };
            match item {
                Item::Channel(c) => {
                    let wanted = keep(&c.topic);
                    map.insert(c.id, None);
                    if wanted {
                        declared.push(c);
                    }
                }
                Item::Message {
                    channel,
                    sequence,
                    log_time,
                    publish_time,
                    data,
                } => {
                    if log_time < from || log_time > to {
                        continue;
                    }
                    if let Some(pos) = declared.iter().position(|c| c.id == channel) {
                        // The first wanted message of a channel declares it in the slice.
                        let c = declared.swap_remove(pos);
                        let w = match &mut writer {
                            Some(w) => w,
                            None => {
                                let profile = match c.message_encoding.as_str() {
                                    "cdr" => "ros2",
                                    "ros1" => "ros1",
                                    _ => "",
                                };
                                let opts = mcap::WriteOptions::new()
                                    .profile(profile)
                                    .library(concat!("fleetlink ", env!("CARGO_PKG_VERSION")))
                                    .compression(Some(mcap::Compression::Zstd))
                                    .compression_threads(0);
                                let f = pending_file.take().expect("created once");
                                writer.insert(
                                    opts.create(BufWriter::with_capacity(1 << 20, f))
                                        .map_err(|e| e.to_string())?,
                                )
                            }
                        };
                        let schema_id = if c.schema_encoding.is_empty() {
                            0
                        } else {
                            let key = (c.schema_name.clone(), c.schema_encoding.clone(), c.schema);
                            match schemas.get(&key) {
                                Some(id) => *id,
                                None => {
                                    let id = w
                                        .add_schema(&key.0, &key.1, &key.2)
                                        .map_err(|e| e.to_string())?;
                                    schemas.insert(key, id);
                                    id
                                }
                            }
                        };
                        let key = (c.topic.clone(), c.message_encoding.clone(), schema_id);
                        let id = match channels.get(&key) {
                            Some(id) => *id,
                            None => {
                                let id = w
                                    .add_channel(
                                        schema_id,
                                        &c.topic,
                                        &c.message_encoding,
                                        &c.metadata,
                                    )
                                    .map_err(|e| e.to_string())?;
                                channels.insert(key, id);
                                topics.insert(c.topic.clone());
                                id
                            }
                        };
                        map.insert(channel, Some(id));
                    }
                    let Some(Some(id)) = map.get(&channel).copied() else {
                        continue;
                    };
                    let header = mcap::records::MessageHeader {
                        channel_id: id,
                        sequence,
                        log_time,
                        publish_time,
                    };
                    writer
                        .as_mut()
                        .expect("a channel was declared")
                        .write_to_known_channel(&header, &data)
                        .map_err(|e| e.to_string())?;
                    reply.messages += 1;
                    reply.start_ns = reply.start_ns.min(log_time);
                    reply.end_ns = reply.end_ns.max(log_time);
                }
            }
        }
    }
    let Some(mut w) = writer else {
        drop(pending_file);
        let _ = std::fs::remove_file(out);
        return Err("no messages of the chosen topics in that time range".into());
    };
    w.finish().map_err(|e| e.to_string())?;
    let mut f = w.into_inner();
    f.flush().map_err(|e| e.to_string())?;
    f.get_ref().sync_data().map_err(|e| e.to_string())?;
    drop(f);
    let (size, sha256) = digest(out)?;
    reply.size = size;
    reply.sha256 = sha256;
    reply.topics = topics.into_iter().collect();
    Ok(reply)
}

/// Size and SHA-256 (hex) of a file.
pub fn digest(path: &Path) -> Result<(u64, String), String> {
    let mut f = File::open(path).map_err(|e| format!("reading {}: {e}", path.display()))?;
    let mut h = Sha256::new();
    let size =
        std::io::copy(&mut f, &mut h).map_err(|e| format!("reading {}: {e}", path.display()))?;
    Ok((size, super::hex(&h.finalize())))
}
