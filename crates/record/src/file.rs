//! One MCAP file of a recording: created at its first message, channels added as topics
//! appear, chunked, compressed and indexed, finished with a summary and the recording's
//! figures as a metadata record.
//!
//! Each topic is written in its typed form ([`ChannelForm`]): ROS 1 topics as `ros1` with
//! their `ros1msg` definition, ROS 2 topics and every type the hub knows as `cdr` with the
//! `ros2msg` definition (and an `offered_qos_profiles` entry, as rosbag2 writes it), types
//! nobody defined as schemaless `json`. A topic whose schema changes (its definition
//! arrived after its first messages) gets a second channel with the new schema.
//!
//! Chunks are closed before they would pass [`CHUNK_MAX`] bytes of messages, so a reader
//! never needs more than that in memory for one chunk (a single message larger than that
//! is a chunk of its own). Every chunk is written out when closed: a hub that dies loses
//! at most the open chunk, and the file reads up to there.

use std::collections::{BTreeMap, HashMap};
use std::fs::File;
use std::io::{BufWriter, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

use fleetlink_proto::Encoding;
use fleetlink_relay::channel_form::{ChannelForm, wire_name};
use fleetlink_relay::message::TopicMeta;
use fleetlink_relay::{Message, TopicId, Transcoder};
use serde::{Deserialize, Serialize};

use crate::spec::Compression;

/// Most bytes of messages in one chunk.
pub const CHUNK_MAX: usize = 4 << 20;

/// The name of the metadata record with the recording's figures.
pub const METADATA_NAME: &str = "fleetlink.recording";

/// What a finished (or growing) file holds.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct FileFigures {
    /// The file's name in the recording's directory.
    pub name: String,
    pub bytes: u64,
    pub messages: u64,
    /// Receive times at the hub of the first and last message, Unix nanoseconds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_ns: Option<u64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_ns: Option<u64>,
    /// Messages the recorder's queue dropped while this file was open.
    pub dropped: u64,
}

/// A writer that knows how far it has written: the file's size without asking the disk.
/// The end is shared so that the file's owner can read it while mcap's writer holds this.
struct Counting<W> {
    inner: W,
    pos: u64,
    end: Arc<AtomicU64>,
}

impl<W> Counting<W> {
    fn moved_to(&mut self, pos: u64) {
        self.pos = pos;
        if pos > self.end.load(Relaxed) {
            self.end.store(pos, Relaxed);
        }
    }
}

impl<W: Write> Write for Counting<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let n = self.inner.write(buf)?;
        self.moved_to(self.pos + n as u64);
        Ok(n)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.inner.flush()
    }
}

impl<W: Seek> Seek for Counting<W> {
    fn seek(&mut self, to: SeekFrom) -> std::io::Result<u64> {
        let pos = self.inner.seek(to)?;
        self.moved_to(pos);
        Ok(pos)
    }
}

/// A topic's channel in this file.
struct Chan {
    /// The topic's description the channel was made from: a message with the same one
    /// (the same `Arc`) goes to this channel without looking at its schema again.
    meta: Arc<TopicMeta>,
    form: ChannelForm,
    id: u16,
}

/// Figures of the whole recording a file's metadata record carries.
#[derive(Debug, Clone, Default)]
pub struct RecordingNote {
    pub fields: BTreeMap<String, String>,
}

pub struct McapFile {
    path: PathBuf,
    writer: mcap::Writer<Counting<BufWriter<File>>>,
    channels: HashMap<TopicId, Chan>,
    /// Bytes of messages in the open chunk.
    in_chunk: usize,
    /// How far the file has been written.
    len: Arc<AtomicU64>,
    pub figures: FileFigures,
    /// Messages that could not be given in their channel's encoding.
    pub unconvertible: u64,
}

impl McapFile {
    /// Creates `dir/name`. `profile` is the header's (`ros1`, `ros2` or empty).
    pub fn create(
        dir: &Path,
        name: &str,
        profile: &str,
        compression: Compression,
    ) -> std::io::Result<McapFile> {
        let path = dir.join(name);
        let file = File::create(&path)?;
        let len = Arc::new(AtomicU64::new(0));
        let out = Counting {
            inner: BufWriter::with_capacity(1 << 20, file),
            pos: 0,
            end: len.clone(),
        };
        let opts = mcap::WriteOptions::new()
            .profile(profile)
            .library(concat!("fleetlink ", env!("CARGO_PKG_VERSION")))
            .compression(match compression {
                Compression::Zstd => Some(mcap::Compression::Zstd),
                Compression::Lz4 => Some(mcap::Compression::Lz4),
                Compression::None => None,
            })
            // Chunks are closed here (`CHUNK_MAX`), and compressed on this thread: the
            // recorder's CPU is one thread's, whatever the machine has.
            .chunk_size(None)
            .compression_threads(0);
        let writer = opts.create(out).map_err(to_io)?;
        Ok(McapFile {
            path,
            writer,
            channels: HashMap::new(),
            in_chunk: 0,
            len,
            figures: FileFigures {
                name: name.to_owned(),
                ..FileFigures::default()
            },
            unconvertible: 0,
        })
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The header's profile for a file whose first message is `msg`.
    pub fn profile_for(msg: &Message, tc: &dyn Transcoder) -> &'static str {
        match ChannelForm::of(&msg.topic.schema, tc).encoding {
            Encoding::Ros1 => "ros1",
            Encoding::Cdr => "ros2",
            _ => "",
        }
    }

    /// Writes one message; `Ok(false)` when it cannot be given in its channel's encoding
    /// (counted, not written).
    pub fn write(&mut self, msg: &Message, tc: &dyn Transcoder) -> std::io::Result<bool> {
        let id = self.channel_for(msg, tc)?;
        let encoding = self.channels[&msg.topic.id].form.encoding;
        let payload = match msg.payload_in(encoding, tc) {
            Ok(p) => p,
            Err(_) => {
                self.unconvertible += 1;
                return Ok(false);
            }
        };
        if self.in_chunk > 0 && self.in_chunk + payload.len() > CHUNK_MAX {
            self.writer.flush().map_err(to_io)?;
            self.in_chunk = 0;
        }
        let log_time = msg.received_unix_ns();
        let header = mcap::records::MessageHeader {
            channel_id: id,
            sequence: msg.seq as u32,
            log_time,
            publish_time: if msg.stamp_ns == 0 {
                log_time
            } else {
                msg.stamp_ns
            },
        };
        self.writer
            .write_to_known_channel(&header, &payload)
            .map_err(to_io)?;
        self.in_chunk += payload.len();
        let len = self.writer_len();
        let f = &mut self.figures;
        f.messages += 1;
        f.start_ns = Some(f.start_ns.map_or(log_time, |s| s.min(log_time)));
        f.end_ns = Some(f.end_ns.map_or(log_time, |e| e.max(log_time)));
        f.bytes = len;
        Ok(true)
    }

    /// Closes the open chunk (if any) and writes it out, so that a reader finds every
    /// message written so far even if the process dies before the file is finished.
    pub fn close_chunk(&mut self) -> std::io::Result<()> {
        if self.in_chunk > 0 {
            self.writer.flush().map_err(to_io)?;
            self.in_chunk = 0;
        }
        Ok(())
    }

    /// Bytes written so far (the open chunk not yet among them).
    pub fn writer_len(&self) -> u64 {
        self.len.load(Relaxed)
    }

    fn channel_for(&mut self, msg: &Message, tc: &dyn Transcoder) -> std::io::Result<u16> {
        if let Some(c) = self.channels.get(&msg.topic.id)
            && Arc::ptr_eq(&c.meta, &msg.topic)
        {
            return Ok(c.id);
        }
        let form = ChannelForm::of(&msg.topic.schema, tc);
        if let Some(c) = self.channels.get_mut(&msg.topic.id)
            && c.form == form
            && c.meta.name == msg.topic.name
        {
            c.meta = msg.topic.clone();
            return Ok(c.id);
        }
        let schema_id = match form.schema_encoding {
            Some(enc) => self
                .writer
                .add_schema(&form.schema_name, enc, form.schema.as_bytes())
                .map_err(to_io)?,
            None => 0,
        };
        let mut meta = BTreeMap::new();
        match form.encoding {
            Encoding::Cdr => {
                meta.insert(
                    "offered_qos_profiles".to_owned(),
                    offered_qos(msg.topic.latched),
                );
            }
            Encoding::Ros1 if msg.topic.latched => {
                meta.insert("latching".to_owned(), "1".to_owned());
            }
            _ => {}
        }
        let id = self
            .writer
            .add_channel(
                schema_id,
                msg.topic.name.as_str(),
                wire_name(form.encoding),
                &meta,
            )
            .map_err(to_io)?;
        self.channels.insert(
            msg.topic.id,
            Chan {
                meta: msg.topic.clone(),
                form,
                id,
            },
        );
        Ok(id)
    }

    /// Finishes the file: the open chunk, `note` as a metadata record, the summary and
    /// its indexes. Returns the file's figures.
    pub fn finish(mut self, note: &RecordingNote) -> std::io::Result<FileFigures> {
        self.writer.flush().map_err(to_io)?;
        self.writer
            .write_metadata(&mcap::records::Metadata {
                name: METADATA_NAME.to_owned(),
                metadata: note.fields.clone(),
            })
            .map_err(to_io)?;
        self.writer.finish().map_err(to_io)?;
        let mut out = self.writer.into_inner();
        out.flush()?;
        let mut figures = self.figures;
        figures.bytes = out.end.load(Relaxed);
        out.inner.get_ref().sync_data()?;
        Ok(figures)
    }
}

/// The QoS a ROS 2 channel was offered with, as rosbag2 writes it into MCAP: reliable,
/// volatile (transient local for a latched topic), other policies at the defaults.
fn offered_qos(latched: bool) -> String {
    let forever = "\n    sec: 2147483647\n    nsec: 4294967295";
    format!(
        "- history: 3\n  depth: 0\n  reliability: 1\n  durability: {}\n  deadline:{forever}\n  \
         lifespan:{forever}\n  liveliness: 1\n  liveliness_lease_duration:{forever}\n  \
         avoid_ros_namespace_conventions: false",
        if latched { 1 } else { 2 }
    )
}

fn to_io(e: mcap::McapError) -> std::io::Error {
    match e {
        mcap::McapError::Io(e) => e,
        e => std::io::Error::other(e.to_string()),
    }
}
