//! Reading an MCAP file front to back, as `fleetlink play` replays it: channels as they
//! are declared, then each message in file order, without holding more than a chunk in
//! memory.

use std::collections::HashMap;
use std::fs::File;
use std::io::Read;
use std::path::Path;

use mcap::records::Record;
use mcap::sans_io::linear_reader::{LinearReadEvent, LinearReader};

/// A channel of the file with its schema.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Channel {
    pub id: u16,
    pub topic: String,
    /// `cdr`, `ros1`, `json`, ...
    pub message_encoding: String,
    /// The schema's name (the message type); empty without a schema.
    pub schema_name: String,
    /// `ros2msg`, `ros1msg`, `jsonschema`, ...; empty without a schema.
    pub schema_encoding: String,
    pub schema: Vec<u8>,
    /// The channel's metadata (`offered_qos_profiles`, `latching`, ...).
    pub metadata: std::collections::BTreeMap<String, String>,
}

/// What the file says next.
#[derive(Debug)]
pub enum Item {
    Channel(Channel),
    Message {
        channel: u16,
        sequence: u32,
        log_time: u64,
        publish_time: u64,
        data: Vec<u8>,
    },
}

/// The items of one file.
pub struct McapReader {
    file: File,
    reader: LinearReader,
    schemas: HashMap<u16, (String, String, Vec<u8>)>,
    pending: Vec<Channel>,
    done: bool,
}

impl McapReader {
    pub fn open(path: &Path) -> std::io::Result<McapReader> {
        Ok(McapReader {
            file: File::open(path)?,
            reader: LinearReader::new(),
            schemas: HashMap::new(),
            pending: Vec::new(),
            done: false,
        })
    }

    /// The next channel or message; `None` at the end of the file.
    pub fn next_item(&mut self) -> Option<Result<Item, String>> {
        loop {
            if let Some(c) = self.pending.pop() {
                return Some(Ok(Item::Channel(c)));
            }
            if self.done {
                return None;
            }
            let event = match self.reader.next_event()? {
                Ok(e) => e,
                Err(e) => {
                    self.done = true;
                    return Some(Err(describe(e)));
                }
            };
            match event {
                LinearReadEvent::ReadRequest(need) => {
                    match self.file.read(self.reader.insert(need)) {
                        Ok(n) => self.reader.notify_read(n),
                        Err(e) => {
                            self.done = true;
                            return Some(Err(e.to_string()));
                        }
                    }
                }
                LinearReadEvent::Record { opcode, data } => {
                    let record = match mcap::parse_record(opcode, data) {
                        Ok(r) => r,
                        Err(e) => {
                            self.done = true;
                            return Some(Err(describe(e)));
                        }
                    };
                    match record {
                        Record::Schema { header, data } => {
                            self.schemas.insert(
                                header.id,
                                (header.name, header.encoding, data.into_owned()),
                            );
                        }
                        Record::Channel(c) => {
                            let (name, enc, schema) =
                                self.schemas.get(&c.schema_id).cloned().unwrap_or_default();
                            self.pending.push(Channel {
                                id: c.id,
                                topic: c.topic,
                                message_encoding: c.message_encoding,
                                schema_name: name,
                                schema_encoding: enc,
                                schema,
                                metadata: c.metadata,
                            });
                        }
                        Record::Message { header, data } => {
                            return Some(Ok(Item::Message {
                                channel: header.channel_id,
                                sequence: header.sequence,
                                log_time: header.log_time,
                                publish_time: header.publish_time,
                                data: data.into_owned(),
                            }));
                        }
                        // The summary repeats the channels; the messages are over.
                        Record::DataEnd(_) => self.done = true,
                        _ => {}
                    }
                }
            }
        }
    }
}

fn describe(e: mcap::McapError) -> String {
    match e {
        mcap::McapError::UnsupportedCompression(c) => format!(
            "chunks compressed with {c:?}, which fleetlink does not read (zstd, lz4 or none); \
             recompress with `mcap compress --compression zstd`"
        ),
        e => e.to_string(),
    }
}
