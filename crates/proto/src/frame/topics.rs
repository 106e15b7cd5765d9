//! The frames that set up and steer a topic (the messages themselves are in `message`):
//! `ADVERTISE` and `UNADVERTISE` (binding an alias to a topic), `SUBSCRIBE` and
//! `UNSUBSCRIBE`, `DELIVERED` (no-drop delivery confirmed), `INTEREST` and `PULL`
//! (whether and when the agent sends), and `VIA` (the hubs a message passed).

use bytes::BufMut;

use super::shared::read_encoding;
use super::types::{Frame, MAX_VIA};
use crate::error::DecodeError;
use crate::payload::Schema;
use crate::wire::{Reader, put_bytes, put_str, put_varint};

/// Writes the body of a topic frame. The codec sends only topic frames here.
pub(super) fn encode_body(frame: &Frame, b: &mut impl BufMut) {
    match frame {
        Frame::Advertise {
            alias,
            topic,
            schema,
            encoding,
            flags,
        } => {
            put_varint(b, u64::from(*alias));
            put_str(b, topic);
            put_str(b, &schema.type_name);
            put_str(b, &schema.encoding);
            put_bytes(b, schema.text.as_bytes());
            b.put_u8(*encoding as u8);
            b.put_u8(*flags);
        }
        Frame::Unadvertise { alias } => put_varint(b, u64::from(*alias)),
        Frame::Subscribe {
            id,
            pattern,
            flags,
            throttle_ms,
            queue_length,
        } => {
            put_varint(b, u64::from(*id));
            put_str(b, pattern);
            b.put_u8(*flags);
            put_varint(b, u64::from(*throttle_ms));
            put_varint(b, u64::from(*queue_length));
        }
        Frame::Unsubscribe { id } => put_varint(b, u64::from(*id)),
        Frame::Delivered { alias, seq } => {
            put_varint(b, u64::from(*alias));
            put_varint(b, *seq);
        }
        Frame::Interest { alias, wanted } => {
            put_varint(b, u64::from(*alias));
            b.put_u8(u8::from(*wanted));
        }
        Frame::Pull { alias } => put_varint(b, u64::from(*alias)),
        Frame::Via { hubs } => {
            put_varint(b, hubs.len() as u64);
            for h in hubs {
                b.put_u64_le(*h);
            }
        }
        other => unreachable!("{other:?} is not a topic frame"),
    }
}

/// Decodes the body of a topic frame (kinds `0x03`–`0x06`, `0x0f`, `0x18`, `0x19`,
/// `0x1f`).
pub(super) fn decode_body(kind: u8, r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    let frame = match kind {
        0x03 => {
            let alias = r.varint_u32("ADVERTISE.alias")?;
            let topic = r.string("ADVERTISE.topic")?;
            let type_name = r.string("ADVERTISE.type")?;
            let schema_encoding = r.string("ADVERTISE.schema_encoding")?;
            let text = r.string("ADVERTISE.schema_text")?;
            let encoding = read_encoding(r, "ADVERTISE.encoding")?;
            let flags = r.u8("ADVERTISE.flags")?;
            Frame::Advertise {
                alias,
                topic,
                schema: Schema {
                    type_name,
                    encoding: schema_encoding,
                    text,
                },
                encoding,
                flags,
            }
        }
        0x04 => Frame::Unadvertise {
            alias: r.varint_u32("UNADVERTISE.alias")?,
        },
        0x05 => Frame::Subscribe {
            id: r.varint_u32("SUBSCRIBE.id")?,
            pattern: r.string("SUBSCRIBE.pattern")?,
            flags: r.u8("SUBSCRIBE.flags")?,
            throttle_ms: r.varint_u32("SUBSCRIBE.throttle_ms")?,
            queue_length: r.varint_u32("SUBSCRIBE.queue_length")?,
        },
        0x06 => Frame::Unsubscribe {
            id: r.varint_u32("UNSUBSCRIBE.id")?,
        },
        0x0f => Frame::Delivered {
            alias: r.varint_u32("DELIVERED.alias")?,
            seq: r.varint("DELIVERED.seq")?,
        },
        0x18 => Frame::Interest {
            alias: r.varint_u32("INTEREST.alias")?,
            wanted: match r.u8("INTEREST.wanted")? {
                0 => false,
                1 => true,
                v => {
                    return Err(DecodeError::invalid(
                        "INTEREST.wanted",
                        format!("{v} is not 0 or 1"),
                    ));
                }
            },
        },
        0x19 => Frame::Pull {
            alias: r.varint_u32("PULL.alias")?,
        },
        0x1f => {
            let count = r.varint("VIA.count")?;
            if count > MAX_VIA as u64 {
                return Err(DecodeError::invalid(
                    "VIA.count",
                    format!("{count} hubs: a chain of more than {MAX_VIA} hubs"),
                ));
            }
            let hubs = (0..count)
                .map(|_| r.u64_le("VIA.hub"))
                .collect::<Result<_, _>>()?;
            Frame::Via { hubs }
        }
        other => Frame::Unknown { kind: other },
    };
    Ok(frame)
}
