//! The frames that open a link and look after it: `HELLO` and `WELCOME` (who is talking,
//! and what each side can do), `PING` and `PONG` (round trips and clocks), `ACK` (what
//! arrived), `STATUS` (what went wrong), `SHARE` and `LINK_REPORT` (how much the link may
//! carry, and what it did carry).

use bytes::BufMut;

use super::types::{Frame, Level};
use crate::error::DecodeError;
use crate::wire::{Reader, put_str, put_varint};

/// Writes the body of a link frame. The codec sends only link frames here.
pub(super) fn encode_body(frame: &Frame, b: &mut impl BufMut) {
    match frame {
        Frame::Hello {
            version,
            robot,
            token,
            heartbeat_ms,
            outbox_epoch,
            mirror,
        } => {
            put_varint(b, u64::from(*version));
            put_str(b, robot);
            put_str(b, token);
            put_varint(b, u64::from(*heartbeat_ms));
            b.put_u64_le(*outbox_epoch);
            if !mirror.is_empty() {
                put_str(b, mirror);
            }
        }
        Frame::Welcome {
            session,
            namespace,
            hub_time_ns,
            heartbeat_ms,
            features,
        } => {
            put_str(b, session);
            put_str(b, namespace);
            b.put_u64_le(*hub_time_ns);
            put_varint(b, u64::from(*heartbeat_ms));
            put_varint(b, *features);
        }
        Frame::Ping { id, sent_ns } => {
            b.put_u64_le(*id);
            b.put_u64_le(*sent_ns);
        }
        Frame::Pong {
            id,
            echo_ns,
            responder_ns,
        } => {
            b.put_u64_le(*id);
            b.put_u64_le(*echo_ns);
            b.put_u64_le(*responder_ns);
        }
        Frame::Ack { frames, bytes } => {
            put_varint(b, u64::from(*frames));
            put_varint(b, *bytes);
        }
        Frame::Status {
            level,
            code,
            alias,
            text,
        } => {
            b.put_u8(*level as u8);
            put_varint(b, u64::from(*code));
            put_varint(b, u64::from(*alias));
            put_str(b, text);
        }
        Frame::Share { bytes_per_sec } => b.put_u64_le(*bytes_per_sec),
        Frame::LinkReport {
            demand_bps,
            rate_bps,
            latency_ns,
            capacity_bps,
            measured_at_ms,
        } => {
            b.put_u64_le(*demand_bps);
            b.put_u64_le(*rate_bps);
            b.put_u64_le(*latency_ns);
            b.put_u64_le(*capacity_bps);
            b.put_u64_le(*measured_at_ms);
        }
        other => unreachable!("{other:?} is not a link frame"),
    }
}

/// Decodes the body of a link frame (kinds `0x01`, `0x02`, `0x09`–`0x0e`).
pub(super) fn decode_body(kind: u8, r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    let frame = match kind {
        0x01 => Frame::Hello {
            version: r.varint_u32("HELLO.version")?,
            robot: r.string("HELLO.robot")?,
            token: r.string("HELLO.token")?,
            heartbeat_ms: r.varint_u32("HELLO.heartbeat_ms")?,
            outbox_epoch: if r.is_empty() {
                0
            } else {
                r.u64_le("HELLO.outbox_epoch")?
            },
            mirror: if r.is_empty() {
                String::new()
            } else {
                r.string("HELLO.mirror")?
            },
        },
        0x02 => Frame::Welcome {
            session: r.string("WELCOME.session")?,
            namespace: r.string("WELCOME.namespace")?,
            hub_time_ns: r.u64_le("WELCOME.hub_time_ns")?,
            heartbeat_ms: r.varint_u32("WELCOME.heartbeat_ms")?,
            features: if r.is_empty() {
                0
            } else {
                r.varint("WELCOME.features")?
            },
        },
        0x09 => Frame::Ping {
            id: r.u64_le("PING.id")?,
            sent_ns: r.u64_le("PING.sent_ns")?,
        },
        0x0a => Frame::Pong {
            id: r.u64_le("PONG.id")?,
            echo_ns: r.u64_le("PONG.echo_ns")?,
            responder_ns: r.u64_le("PONG.responder_ns")?,
        },
        0x0b => Frame::Ack {
            frames: r.varint_u32("ACK.frames")?,
            bytes: if r.is_empty() {
                0
            } else {
                r.varint("ACK.bytes")?
            },
        },
        0x0c => Frame::Status {
            level: Level::from_u8(r.u8("STATUS.level")?),
            code: r.varint_u32("STATUS.code")?,
            alias: r.varint_u32("STATUS.alias")?,
            text: r.string("STATUS.text")?,
        },
        0x0d => Frame::Share {
            bytes_per_sec: r.u64_le("SHARE.bytes_per_sec")?,
        },
        0x0e => Frame::LinkReport {
            demand_bps: r.u64_le("LINK_REPORT.demand_bps")?,
            rate_bps: r.u64_le("LINK_REPORT.rate_bps")?,
            latency_ns: r.u64_le("LINK_REPORT.latency_ns")?,
            capacity_bps: if r.remaining() >= 8 {
                r.u64_le("LINK_REPORT.capacity_bps")?
            } else {
                0
            },
            measured_at_ms: if r.remaining() >= 8 {
                r.u64_le("LINK_REPORT.measured_at_ms")?
            } else {
                0
            },
        },
        other => Frame::Unknown { kind: other },
    };
    Ok(frame)
}
