//! Arbitrary bytes as one WebSocket message of `fleetlink.v1` frames: every frame that
//! decodes must encode back to bytes that decode to the same frame, and chunks go through
//! a reassembler whose buffer budget must hold whatever the chunks claim.

#![no_main]

use bytes::Bytes;
use fleetlink_proto::frame::{self, Frame};
use fleetlink_proto::reassembly::Reassembler;
use libfuzzer_sys::fuzz_target;

const MAX_MESSAGE: usize = 1 << 20;
const MAX_BUFFERED: usize = 4 << 20;

fuzz_target!(|data: &[u8]| {
    let buf = Bytes::copy_from_slice(data);
    let mut reassembler = Reassembler::new(MAX_MESSAGE, MAX_BUFFERED);
    for decoded in frame::frames(&buf) {
        let Ok(f) = decoded else { break };
        let again = f.to_bytes();
        let (back, end) = Frame::decode(&again, 0).expect("a decoded frame re-encodes validly");
        assert_eq!(back, f);
        assert_eq!(end, again.len());
        if let Frame::Chunk {
            alias,
            seq,
            stamp_ns,
            total_len,
            offset,
            data,
        } = f
        {
            if let Ok(Some(done)) = reassembler.push(alias, seq, stamp_ns, total_len, offset, &data)
            {
                assert_eq!(done.payload.len() as u64, total_len);
            }
            assert!(reassembler.buffered() <= MAX_BUFFERED);
        }
    }
});
