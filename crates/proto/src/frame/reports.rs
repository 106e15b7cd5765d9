//! The lists an agent reports to the hub about once a second: `BUDGET` (its data budget
//! and the topics it held back), `TOPIC_DROPS` (what it lost of each topic) and
//! `TOPIC_LOAD` (what each topic offers). Each is a count and then that many entries; the
//! reader checks every count against the bytes left, so a lying count is refused before
//! anything is allocated for it.

use bytes::BufMut;

use super::types::{Frame, TopicLoadEntry};
use crate::error::DecodeError;
use crate::wire::{Reader, put_varint};

/// Writes a `BUDGET` body.
pub(super) fn put_budget(
    b: &mut impl BufMut,
    max_bps: u64,
    day_bytes: u64,
    used_bytes: u64,
    thinned: &[u32],
) {
    put_varint(b, max_bps);
    put_varint(b, day_bytes);
    put_varint(b, used_bytes);
    put_varint(b, thinned.len() as u64);
    for a in thinned {
        put_varint(b, u64::from(*a));
    }
}

/// Writes a `TOPIC_DROPS` body.
pub(super) fn put_topic_drops(b: &mut impl BufMut, topics: &[(u32, Vec<(u8, u64)>)]) {
    put_varint(b, topics.len() as u64);
    for (alias, drops) in topics {
        put_varint(b, u64::from(*alias));
        put_varint(b, drops.len() as u64);
        for (reason, n) in drops {
            b.put_u8(*reason);
            put_varint(b, *n);
        }
    }
}

/// Writes a `TOPIC_LOAD` body.
pub(super) fn put_topic_load(b: &mut impl BufMut, topics: &[TopicLoadEntry]) {
    put_varint(b, topics.len() as u64);
    for t in topics {
        put_varint(b, u64::from(t.alias));
        put_varint(b, t.rate_mhz);
        put_varint(b, t.bytes_per_sec);
        put_varint(b, u64::from(t.priority_milli));
        put_varint(b, u64::from(t.queue));
        b.put_u8(t.flags);
    }
}

/// Reads a `BUDGET` body.
pub(super) fn read_budget(r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    let max_bps = r.varint("BUDGET.max_bps")?;
    let day_bytes = r.varint("BUDGET.day_bytes")?;
    let used_bytes = r.varint("BUDGET.used_bytes")?;
    let count = r.varint("BUDGET.count")?;
    // Every alias takes at least a byte: a count past the body is a lie.
    if count > r.remaining() as u64 {
        return Err(DecodeError::invalid(
            "BUDGET.count",
            format!("{count} aliases in {} bytes", r.remaining()),
        ));
    }
    let thinned = (0..count)
        .map(|_| r.varint_u32("BUDGET.alias"))
        .collect::<Result<_, _>>()?;
    Ok(Frame::Budget {
        max_bps,
        day_bytes,
        used_bytes,
        thinned,
    })
}

/// Reads a `TOPIC_DROPS` body.
pub(super) fn read_topic_drops(r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    // Every entry takes at least two bytes, every pair two: a count past the
    // body is a lie.
    let count = r.varint("TOPIC_DROPS.count")?;
    if count > r.remaining() as u64 / 2 {
        return Err(DecodeError::invalid(
            "TOPIC_DROPS.count",
            format!("{count} topics in {} bytes", r.remaining()),
        ));
    }
    let mut topics = Vec::with_capacity(count as usize);
    for _ in 0..count {
        let alias = r.varint_u32("TOPIC_DROPS.alias")?;
        let n = r.varint("TOPIC_DROPS.n")?;
        if n > r.remaining() as u64 / 2 {
            return Err(DecodeError::invalid(
                "TOPIC_DROPS.n",
                format!("{n} reasons in {} bytes", r.remaining()),
            ));
        }
        let mut drops = Vec::with_capacity(n as usize);
        for _ in 0..n {
            drops.push((
                r.u8("TOPIC_DROPS.reason")?,
                r.varint("TOPIC_DROPS.dropped")?,
            ));
        }
        topics.push((alias, drops));
    }
    Ok(Frame::TopicDrops { topics })
}

/// Reads a `TOPIC_LOAD` body.
pub(super) fn read_topic_load(r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    let count = r.varint("TOPIC_LOAD.count")?;
    // Each entry takes at least six bytes.
    if count > r.remaining() as u64 / 6 {
        return Err(DecodeError::invalid(
            "TOPIC_LOAD.count",
            format!("{count} topics in {} bytes", r.remaining()),
        ));
    }
    let mut topics = Vec::with_capacity(count as usize);
    for _ in 0..count {
        topics.push(TopicLoadEntry {
            alias: r.varint_u32("TOPIC_LOAD.alias")?,
            rate_mhz: r.varint("TOPIC_LOAD.rate_mhz")?,
            bytes_per_sec: r.varint("TOPIC_LOAD.bytes_per_sec")?,
            priority_milli: r.varint_u32("TOPIC_LOAD.priority_milli")?,
            queue: r.varint_u32("TOPIC_LOAD.queue")?,
            flags: r.u8("TOPIC_LOAD.flags")?,
        });
    }
    Ok(Frame::TopicLoad { topics })
}
