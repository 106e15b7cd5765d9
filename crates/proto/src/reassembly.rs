//! Reassembly of `CHUNK` frames into whole messages ([`Reassembler`]) and of
//! `CALL_CHUNK` pieces into whole call bodies ([`CallReassembler`]).
//!
//! Pieces of one message arrive in order (one TCP stream, one sender queue per topic),
//! so a partial message is a single growing buffer per alias: no sorting, no gaps to
//! track. The total size is checked against a limit *before* the buffer is reserved, so
//! a forged `total_len` cannot make the receiver allocate gigabytes. Call bodies follow
//! the same rules, keyed by `(call_id, kind)` instead of alias.

use std::collections::{BTreeMap, BTreeSet, HashMap};

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
    #[error(
        "body of call {call_id} (kind {kind:#04x}) of {total_len} bytes exceeds the {limit}-byte limit"
    )]
    CallTooLarge {
        call_id: u64,
        kind: u8,
        total_len: u64,
        limit: usize,
    },
    #[error(
        "piece of call {call_id} (kind {kind:#04x}) starts at offset {offset}, expected {expected}"
    )]
    CallOutOfOrder {
        call_id: u64,
        kind: u8,
        offset: u64,
        expected: u64,
    },
    #[error(
        "body of call {call_id} (kind {kind:#04x}) should be {total_len} bytes, its pieces say {got}"
    )]
    CallLengthMismatch {
        call_id: u64,
        kind: u8,
        total_len: u64,
        got: u64,
    },
    #[error("body of call {call_id} (kind {kind:#04x}) lost pieces refused earlier")]
    CallBodyRefused { call_id: u64, kind: u8 },
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

/// Each partial call body counts this much against `max_total` on top of its length, for
/// its map entry and buffer header: call ids are the peer's to choose, so without it a
/// peer could open millions of empty bodies inside any byte budget.
const BODY_OVERHEAD: usize = 64;

/// How many refused bodies are remembered until their frame arrives (see
/// [`CallReassembler::finish`]). A sender that follows the protocol has at most a few at a
/// time; only a peer that never sends the frames its pieces announce can reach the bound,
/// and past it only that peer's own bodies go unchecked.
const MAX_REFUSED: usize = 1024;

/// Identifies one body in flight: the call and the kind of frame the body belongs to
/// (a goal's `FEEDBACK` bodies and its result `REPLY` may be cut at the same time).
type BodyKey = (u64, u8);

struct PartialBody {
    total_len: u64,
    buf: BytesMut,
}

/// Per-connection reassembly of call bodies cut into `CALL_CHUNK` pieces.
///
/// Pieces arrive first and the frame they belong to last, carrying the final piece
/// ([`crate::frame::split_call_body`]); so [`push`](Self::push) only ever collects and
/// [`finish`](Self::finish), called for every `CALL`/`GOAL`/`REPLY`/`FEEDBACK`, hands out
/// the body. When a piece is refused the body is dropped and its key remembered, so that
/// the frame that follows is refused too instead of passing its last piece off as the
/// whole body.
pub struct CallReassembler {
    /// Ordered by call id so [`forget`](Self::forget) removes a call's bodies of every kind
    /// with one range.
    partial: BTreeMap<BodyKey, PartialBody>,
    refused: BTreeSet<BodyKey>,
    max_body: usize,
    max_total: usize,
    /// Sum of the `total_len` of partial bodies: what their buffers reserve.
    pending: usize,
}

impl CallReassembler {
    /// `max_body` bounds one body; `max_total` bounds all partial bodies of the connection
    /// together (each also counting a small fixed overhead).
    pub fn new(max_body: usize, max_total: usize) -> Self {
        CallReassembler {
            partial: BTreeMap::new(),
            refused: BTreeSet::new(),
            max_body,
            max_total,
            pending: 0,
        }
    }

    /// Bytes reserved by partial bodies right now.
    pub fn pending_bytes(&self) -> usize {
        self.pending
    }

    /// Takes one `CALL_CHUNK` piece. Pieces of a body must come in order, from offset 0,
    /// each starting where the previous one ended. On error the body is dropped and the
    /// frame that ends it will be refused by [`finish`](Self::finish).
    pub fn push(
        &mut self,
        call_id: u64,
        kind: u8,
        total_len: u64,
        offset: u64,
        data: &[u8],
    ) -> Result<(), ReassemblyError> {
        let key = (call_id, kind);
        let result = self.try_push(key, total_len, offset, data);
        if result.is_err() {
            self.refuse(key);
        }
        result
    }

    fn try_push(
        &mut self,
        key: BodyKey,
        total_len: u64,
        offset: u64,
        data: &[u8],
    ) -> Result<(), ReassemblyError> {
        let (call_id, kind) = key;
        if self.refused.contains(&key) {
            return Err(ReassemblyError::CallBodyRefused { call_id, kind });
        }
        if total_len > self.max_body as u64 {
            return Err(ReassemblyError::CallTooLarge {
                call_id,
                kind,
                total_len,
                limit: self.max_body,
            });
        }
        if offset == 0 && !self.partial.contains_key(&key) {
            // Checked before reserving: `total_len` is bounded by `max_body` above, and
            // here by what the connection may hold in total.
            let charged = self.pending + (self.partial.len() + 1) * BODY_OVERHEAD;
            if charged.saturating_add(total_len as usize) > self.max_total {
                return Err(ReassemblyError::BudgetExceeded {
                    limit: self.max_total,
                });
            }
            self.pending += total_len as usize;
            self.partial.insert(
                key,
                PartialBody {
                    total_len,
                    buf: BytesMut::with_capacity(total_len as usize),
                },
            );
        }
        let Some(p) = self.partial.get_mut(&key) else {
            return Err(ReassemblyError::CallOutOfOrder {
                call_id,
                kind,
                offset,
                expected: 0,
            });
        };
        let expected = p.buf.len() as u64;
        if offset != expected {
            return Err(ReassemblyError::CallOutOfOrder {
                call_id,
                kind,
                offset,
                expected,
            });
        }
        // A piece naming another total, or running past it, cannot belong to this body.
        let end = offset + data.len() as u64;
        if p.total_len != total_len || end > p.total_len {
            return Err(ReassemblyError::CallLengthMismatch {
                call_id,
                kind,
                total_len: p.total_len,
                got: end.max(total_len),
            });
        }
        p.buf.extend_from_slice(data);
        Ok(())
    }

    /// Completes the body of the `kind` frame of call `call_id`, whose payload is `last`.
    /// With no pieces pending the body is `last` itself (no copy); otherwise it is the
    /// pieces followed by `last`, which must add up to the announced total length.
    pub fn finish(
        &mut self,
        call_id: u64,
        kind: u8,
        last: Bytes,
    ) -> Result<Bytes, ReassemblyError> {
        let key = (call_id, kind);
        if self.refused.remove(&key) {
            return Err(ReassemblyError::CallBodyRefused { call_id, kind });
        }
        let Some(mut p) = self.partial.remove(&key) else {
            return Ok(last);
        };
        self.pending -= p.total_len as usize;
        let got = p.buf.len() as u64 + last.len() as u64;
        if got != p.total_len {
            return Err(ReassemblyError::CallLengthMismatch {
                call_id,
                kind,
                total_len: p.total_len,
                got,
            });
        }
        p.buf.extend_from_slice(&last);
        Ok(p.buf.freeze())
    }

    /// Drops whatever is pending for call `call_id`, bodies of every kind (the call ended,
    /// or its connection did).
    pub fn forget(&mut self, call_id: u64) {
        let range = (call_id, u8::MIN)..=(call_id, u8::MAX);
        let keys: Vec<BodyKey> = self.partial.range(range.clone()).map(|(k, _)| *k).collect();
        for key in keys {
            if let Some(p) = self.partial.remove(&key) {
                self.pending -= p.total_len as usize;
            }
        }
        let refused: Vec<BodyKey> = self.refused.range(range).copied().collect();
        for key in refused {
            self.refused.remove(&key);
        }
    }

    /// Drops the partial body under `key` and remembers that it was refused.
    fn refuse(&mut self, key: BodyKey) {
        if let Some(p) = self.partial.remove(&key) {
            self.pending -= p.total_len as usize;
        }
        if self.refused.len() < MAX_REFUSED {
            self.refused.insert(key);
        }
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

    // ---- call bodies ----------------------------------------------------------------

    use crate::frame::{Frame, FrameKind, split_call_body};

    const REPLY: u8 = FrameKind::Reply as u8;
    const FEEDBACK: u8 = FrameKind::Feedback as u8;

    /// Feeds the pieces of `split_call_body` to `r` and finishes with the last one.
    fn send_through(
        r: &mut CallReassembler,
        call_id: u64,
        body: &Bytes,
        chunk_size: usize,
    ) -> Result<Bytes, ReassemblyError> {
        let (chunks, last) = split_call_body(call_id, FrameKind::Reply, body, chunk_size);
        for f in chunks {
            let Frame::CallChunk {
                call_id,
                kind,
                total_len,
                offset,
                data,
            } = f
            else {
                panic!("not a CALL_CHUNK: {f:?}");
            };
            r.push(call_id, kind, total_len, offset, &data)?;
        }
        r.finish(call_id, REPLY, last)
    }

    #[test]
    fn a_100_kib_body_in_16_kib_pieces_comes_back_whole() {
        let body = Bytes::from(
            (0..100 * 1024u32)
                .map(|i| (i % 251) as u8)
                .collect::<Vec<_>>(),
        );
        let mut r = CallReassembler::new(1 << 20, 1 << 20);
        let (chunks, last) = split_call_body(1, FrameKind::Reply, &body, 16 * 1024);
        assert_eq!((chunks.len(), last.len()), (6, 4 * 1024));
        assert_eq!(send_through(&mut r, 1, &body, 16 * 1024).unwrap(), body);
        assert_eq!(r.pending_bytes(), 0);
    }

    #[test]
    fn finish_without_pieces_returns_the_payload_itself() {
        let mut r = CallReassembler::new(100, 100);
        let last = Bytes::from(vec![5; 40]);
        let body = r.finish(3, REPLY, last.clone()).unwrap();
        assert_eq!((body.as_ptr(), body.len()), (last.as_ptr(), 40));
    }

    #[test]
    fn a_piece_out_of_order_drops_the_body_and_its_frame() {
        let mut r = CallReassembler::new(100, 1000);
        r.push(1, REPLY, 9, 0, b"abc").unwrap();
        let e = r.push(1, REPLY, 9, 6, b"ghi").unwrap_err();
        assert!(matches!(
            e,
            ReassemblyError::CallOutOfOrder {
                offset: 6,
                expected: 3,
                ..
            }
        ));
        assert_eq!(r.pending_bytes(), 0);
        // The frame that ends the body must not pass its last piece off as the body.
        let e = r.finish(1, REPLY, Bytes::from_static(b"ghi")).unwrap_err();
        assert!(matches!(
            e,
            ReassemblyError::CallBodyRefused { call_id: 1, .. }
        ));
        // The next body of that call is unaffected.
        assert_eq!(
            &r.finish(1, REPLY, Bytes::from_static(b"ok")).unwrap()[..],
            b"ok"
        );
    }

    #[test]
    fn a_piece_that_does_not_start_a_body_is_refused() {
        let mut r = CallReassembler::new(100, 1000);
        let e = r.push(1, REPLY, 10, 4, b"xy").unwrap_err();
        assert!(matches!(
            e,
            ReassemblyError::CallOutOfOrder { expected: 0, .. }
        ));
    }

    #[test]
    fn a_body_over_the_limits_is_refused_before_allocating() {
        let mut r = CallReassembler::new(1 << 20, 1 << 20);
        let e = r.push(1, REPLY, 1 << 40, 0, b"x").unwrap_err();
        assert!(
            matches!(e, ReassemblyError::CallTooLarge { total_len, .. } if total_len == 1 << 40)
        );
        assert!(r.finish(1, REPLY, Bytes::new()).is_err());

        let mut r = CallReassembler::new(600, 1000);
        r.push(1, REPLY, 600, 0, b"a").unwrap();
        let e = r.push(2, REPLY, 600, 0, b"b").unwrap_err();
        assert_eq!(e, ReassemblyError::BudgetExceeded { limit: 1000 });
        assert_eq!(r.pending_bytes(), 600);
    }

    #[test]
    fn a_body_shorter_than_announced_is_refused() {
        let mut r = CallReassembler::new(100, 1000);
        r.push(1, REPLY, 10, 0, b"abcd").unwrap();
        let e = r.finish(1, REPLY, Bytes::from_static(b"ef")).unwrap_err();
        assert!(matches!(
            e,
            ReassemblyError::CallLengthMismatch {
                total_len: 10,
                got: 6,
                ..
            }
        ));
        assert_eq!(r.pending_bytes(), 0);
    }

    #[test]
    fn forget_drops_every_kind_of_the_call_only() {
        let mut r = CallReassembler::new(100, 1000);
        r.push(1, REPLY, 50, 0, b"a").unwrap();
        r.push(1, FEEDBACK, 30, 0, b"b").unwrap();
        r.push(2, REPLY, 20, 0, b"c").unwrap();
        assert_eq!(r.pending_bytes(), 100);
        r.forget(1);
        assert_eq!(r.pending_bytes(), 20);
        assert_eq!(
            &r.finish(1, REPLY, Bytes::from_static(b"z")).unwrap()[..],
            b"z"
        );
        r.push(2, REPLY, 20, 1, &[0; 18]).unwrap();
        assert_eq!(
            r.finish(2, REPLY, Bytes::from_static(b"d")).unwrap().len(),
            20
        );
        assert_eq!(r.pending_bytes(), 0);
    }

    #[test]
    fn many_empty_bodies_cannot_outgrow_the_budget() {
        let mut r = CallReassembler::new(100, 64 * 10);
        let accepted = (0..1000u64)
            .filter(|id| r.push(*id, REPLY, 0, 0, b"").is_ok())
            .count();
        assert_eq!(accepted, 10);
    }
}
