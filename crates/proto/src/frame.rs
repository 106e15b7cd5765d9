//! `fleetlink.v1` frames: the binary protocol between agents and the hub.
//!
//! A WebSocket binary message carries one or more frames back to back, so a sender can
//! pack many small messages into one write. Every frame is
//!
//! ```text
//! +---------+----------------+--------------------+
//! | kind u8 | body_len varint| body (body_len)    |
//! +---------+----------------+--------------------+
//! ```
//!
//! and a decoder skips frames of unknown kind and ignores bytes after the fields it knows,
//! so later versions can add frames and append fields. Body layouts are drawn per variant
//! of [`Frame`] and in `docs/protocol.md`.
//!
//! This file only names the parts; everything is re-exported here, so callers write
//! `frame::Frame`, `frame::encode_message` and so on:
//!
//! - `types`: the [`Frame`] enum, the kind bytes, flags, `STATUS` codes and call outcomes.
//! - `codec`: a frame to bytes and back ([`Frame::encode`], [`Frame::decode`],
//!   [`frames`]), handing each body to the file of its family:
//! - `link`: `HELLO`, `WELCOME`, `PING`, `PONG`, `ACK`, `STATUS`, `SHARE`, `LINK_REPORT`;
//! - `topics`: `ADVERTISE`, `SUBSCRIBE` and the other frames that steer a topic;
//! - `message`: the one layout of `MESSAGE` and `ZMESSAGE` and the one of `CHUNK` and
//!   `ZCHUNK`, plus the send path's [`encode_message`] and [`encode_chunk`];
//! - `reports`: the agent's once-a-second lists (`BUDGET`, `TOPIC_DROPS`, `TOPIC_LOAD`);
//! - `calls`: the service and action frames (`0x10`–`0x17`) and [`split_call_body`];
//! - `shared`: the few field readers and writers more than one family uses.

mod calls;
mod codec;
mod link;
mod message;
mod reports;
mod shared;
mod topics;
mod types;

pub use calls::split_call_body;
pub use codec::{Frames, frames};
pub use message::{chunk_frames, encode_chunk, encode_message, encode_message_kind};
pub use types::{
    ADVERTISE_LATCHED, ADVERTISE_PULL, ADVERTISE_RELIABLE, CallStatus, DEFAULT_CHUNK_SIZE, Frame,
    FrameKind, Level, MAX_VIA, SERVICE_ACTION, SUBPROTOCOL, SUBSCRIBE_REGEX, SUBSCRIBE_SERVICES,
    TOPIC_LOAD_NO_DROP, TopicLoadEntry, VERSION, WELCOME_COMPRESSION, WELCOME_INTEREST,
    status_code,
};
