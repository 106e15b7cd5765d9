//! A message body as it travels, and the schema that travels with its topic.
//!
//! fleetlink keeps a message in the encoding it arrived in ([`Encoding`]) and converts it
//! lazily, at most once per target encoding. The bytes are [`Bytes`]: cloning a payload
//! shares the storage, it never copies it.

use std::fmt;

use bytes::Bytes;

/// How a payload's bytes encode the message.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Encoding {
    /// The message object in rosbridge JSON conventions (UTF-8 JSON text).
    Json = 0,
    /// The message object in rosbridge CBOR conventions.
    Cbor = 1,
    /// ROS 2 CDR, with its 4-byte encapsulation header.
    Cdr = 2,
    /// ROS 1 serialization.
    Ros1 = 3,
}

impl Encoding {
    pub const ALL: [Encoding; 4] = [
        Encoding::Json,
        Encoding::Cbor,
        Encoding::Cdr,
        Encoding::Ros1,
    ];

    pub fn from_u8(v: u8) -> Option<Encoding> {
        Self::ALL.get(v as usize).copied()
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Encoding::Json => "json",
            Encoding::Cbor => "cbor",
            Encoding::Cdr => "cdr",
            Encoding::Ros1 => "ros1",
        }
    }

    /// Raw encodings are the serialized forms ROS itself uses (what `cbor-raw` carries).
    pub fn is_raw(self) -> bool {
        matches!(self, Encoding::Cdr | Encoding::Ros1)
    }
}

impl fmt::Display for Encoding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// One message body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Payload {
    pub encoding: Encoding,
    pub bytes: Bytes,
}

impl Payload {
    pub fn new(encoding: Encoding, bytes: impl Into<Bytes>) -> Self {
        Payload {
            encoding,
            bytes: bytes.into(),
        }
    }

    pub fn json(bytes: impl Into<Bytes>) -> Self {
        Self::new(Encoding::Json, bytes)
    }

    pub fn len(&self) -> usize {
        self.bytes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.bytes.is_empty()
    }
}

/// The definition of a topic's message type, sent once with `advertise`.
///
/// `encoding` names the text format the way MCAP and Foxglove do (`ros1msg`, `ros2msg`);
/// `text` is the full definition including dependencies. An empty `text` means the sender
/// knows only the type name.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Schema {
    pub type_name: String,
    pub encoding: String,
    pub text: String,
}

impl Schema {
    pub fn named(type_name: impl Into<String>) -> Self {
        Schema {
            type_name: type_name.into(),
            encoding: String::new(),
            text: String::new(),
        }
    }
}
