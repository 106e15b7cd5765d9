//! Reassembly of `CHUNK` frames into whole messages.
//!
//! Pieces of one message arrive in order (one TCP stream, one sender queue per topic),
//! so a partial message is a single growing buffer per alias: no sorting, no gaps to
//! track. The total size is checked against a limit *before* the buffer is reserved, so
//! a forged `total_len` cannot make the receiver allocate gigabytes.

use std::collections::HashMap;

use bytes::{Bytes, BytesMut};

/// Why a chunk was refused. The partial message it belonged to is discarded.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ReassemblyError {
    #[error("chunked message of {total_len} bytes on alias {alias} exceeds the {limit}-byte limit")]
    TooLarge {
        alias: u32,
        total_len: u64,
        limit: usize,
    },
    #[error("chunk for alias {alias} seq {seq} starts at offset {offset}, expected {expected}")]
    OutOfOrder {
        alias: u32,
        seq: u64,
        offset: u64,
        expected: u64,
    },
    #[error("reassembly buffers would exceed {limit} bytes in total")]
    BudgetExceeded { limit: usize },
}

/// A message completed by its last chunk.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Reassembled {
    pub alias: u32,
    pub seq: u64,
    pub stamp_ns: u64,
    pub payload: Bytes,
}

struct Partial {
    seq: u64,
    stamp_ns: u64,
    total_len: u64,
    buf: BytesMut,
}

/// Per-connection reassembly state.
pub struct Reassembler {
    partial: HashMap<u32, Partial>,
    max_message: usize,
    max_buffered: usize,
    buffered: usize,
    /// Partial messages given up because a newer one started on the same alias.
    pub abandoned: u64,
}

impl Reassembler {
    /// `max_message` bounds one message; `max_buffered` bounds all partial messages of the
    /// connection together.
    pub fn new(max_message: usize, max_buffered: usize) -> Self {
        Reassembler {
            partial: HashMap::new(),
            max_message,
            max_buffered,
            buffered: 0,
            abandoned: 0,
        }
    }

    /// Bytes reserved by partial messages right now.
    pub fn buffered(&self) -> usize {
        self.buffered
    }

    /// Forgets partial messages of `alias` (its topic went away).
    pub fn forget(&mut self, alias: u32) {
        if let Some(p) = self.partial.remove(&alias) {
            self.buffered -= p.total_len as usize;
        }
    }

    pub fn push(
        &mut self,
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        total_len: u64,
        offset: u64,
        data: &[u8],
    ) -> Result<Option<Reassembled>, ReassemblyError> {
        if total_len > self.max_message as u64 {
            self.forget(alias);
            return Err(ReassemblyError::TooLarge {
                alias,
                total_len,
                limit: self.max_message,
            });
        }
        if offset == 0 {
            if self.partial.contains_key(&alias) {
                self.forget(alias);
                self.abandoned += 1;
            }
            if self.buffered + total_len as usize > self.max_buffered {
                return Err(ReassemblyError::BudgetExceeded {
                    limit: self.max_buffered,
                });
            }
            self.buffered += total_len as usize;
            self.partial.insert(
                alias,
                Partial {
                    seq,
                    stamp_ns,
                    total_len,
                    buf: BytesMut::with_capacity(total_len as usize),
                },
            );
        }
        let Some(p) = self.partial.get_mut(&alias) else {
            return Err(ReassemblyError::OutOfOrder {
                alias,
                seq,
                offset,
                expected: 0,
            });
        };
        let expected = p.buf.len() as u64;
        if p.seq != seq || offset != expected || offset + data.len() as u64 > p.total_len {
            self.forget(alias);
            return Err(ReassemblyError::OutOfOrder {
                alias,
                seq,
                offset,
                expected,
            });
        }
        p.buf.extend_from_slice(data);
        if p.buf.len() as u64 == p.total_len {
            let p = self.partial.remove(&alias).expect("present: just extended");
            self.buffered -= p.total_len as usize;
            return Ok(Some(Reassembled {
                alias,
                seq: p.seq,
                stamp_ns: p.stamp_ns,
                payload: p.buf.freeze(),
            }));
        }
        Ok(None)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_in_order_make_the_message() {
        let mut r = Reassembler::new(1000, 1000);
        assert_eq!(r.push(1, 7, 9, 6, 0, b"abc").unwrap(), None);
        let done = r.push(1, 7, 9, 6, 3, b"def").unwrap().unwrap();
        assert_eq!(&done.payload[..], b"abcdef");
        assert_eq!((done.seq, done.stamp_ns), (7, 9));
        assert_eq!(r.buffered(), 0);
    }

    #[test]
    fn forged_total_len_is_refused_before_allocating() {
        let mut r = Reassembler::new(1 << 20, 1 << 20);
        let err = r.push(1, 1, 0, 1 << 40, 0, b"x").unwrap_err();
        assert!(matches!(err, ReassemblyError::TooLarge { .. }));
    }

    #[test]
    fn a_gap_discards_the_partial_message() {
        let mut r = Reassembler::new(100, 100);
        r.push(1, 1, 0, 10, 0, b"abc").unwrap();
        assert!(r.push(1, 1, 0, 10, 5, b"xyz").is_err());
        assert_eq!(r.buffered(), 0);
    }

    #[test]
    fn interleaved_topics_reassemble_independently() {
        let mut r = Reassembler::new(100, 100);
        r.push(1, 1, 0, 4, 0, b"ab").unwrap();
        r.push(2, 1, 0, 2, 0, b"x").unwrap();
        assert_eq!(
            &r.push(2, 1, 0, 2, 1, b"y").unwrap().unwrap().payload[..],
            b"xy"
        );
        assert_eq!(
            &r.push(1, 1, 0, 4, 2, b"cd").unwrap().unwrap().payload[..],
            b"abcd"
        );
    }
}
